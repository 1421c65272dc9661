"""Errata of the four texts: every place where they disagree with each other or with arithmetic: the
text of workflow/report/errata.yaml (read as text only) with the consequence computed by each
row's function in reflectance.papers.errata, and the test that shows it."""

import textwrap

import numpy as np

from reflectance.papers.errata import errata_table


def render(table, png, pdf):
    from reflectance.io.figures import new_figure, savefig

    widths = {"text": 16, "location": 34, "printed": 48, "correct": 60, "consequence": 60,
              "test": 52}
    xs = np.cumsum([0.004] + [0.00345 * (w + 2) for w in list(widths.values())[:-1]])
    short = table.assign(text=table.text.str.split(" (", regex=False).str[0],
                         test=table.test.str.replace("::", ":: "))
    cells = [[textwrap.wrap(str(r[c]), w, break_long_words=False) or [""]
              for c, w in widths.items()] for _, r in short.iterrows()]
    heights = [max(len(c) for c in row) for row in cells]
    fig = new_figure(24, 0.9 + 0.155 * (sum(heights) + 0.6 * len(heights)))
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.55 / fig.get_figheight()))
    ax.set_axis_off()
    total = sum(heights) + 0.6 * len(heights)
    ax.set_xlim(0, 1)
    ax.set_ylim(total + 1.6, -1.6)
    for x, title in zip(xs, ("Text", "Location", "As printed", "Correct / other text",
                             "Consequence (computed)", "Test that shows it")):
        ax.text(x, -0.8, title, fontsize=9, fontweight="bold", va="center")
    y = 0.0
    for i, (row, h) in enumerate(zip(cells, heights)):
        if i % 2 == 0:
            ax.axhspan(y - 0.3, y + h + 0.3 - 0.6 + 0.3, color="0.93", lw=0)
        for j, (x, lines) in enumerate(zip(xs, row)):
            ax.text(x, y, "\n".join(lines), fontsize=7.5, va="top", linespacing=1.25,
                    family="monospace" if j == len(xs) - 1 else None)
        y += h + 0.6
    sources = sorted(set(table.text[table.text.str.contains(" (", regex=False)]))
    ax.text(0.004, total + 0.9, "; ".join(sources), fontsize=8, color="0.3", va="bottom")
    fig.suptitle("Errata: where Blinn 1977, Cook & Torrance 1982, the lecture and the article "
                 "disagree with each other or with arithmetic", fontsize=11, y=0.995, va="top")
    savefig(fig, png, pdf)


if "snakemake" in globals():
    from reflectance.io.tables import write_csv
    from reflectance.scripting import script_log

    with script_log(snakemake) as log:
        settings = {k: v for k, v in snakemake.params.errata.items() if k != "rows"}
        table = errata_table(snakemake.input.rows, settings)
        table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
        render(table, snakemake.output.png, snakemake.output.pdf)
        for r in table.itertuples():
            log.info("%s | %s | %s", r.text, r.location, r.consequence)
