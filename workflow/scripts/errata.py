"""Errata of the four texts: every place where they disagree with each other or with arithmetic: the
text of workflow/report/errata.yaml (read as text only) with the consequence computed by each
row's function in reflectance.papers.errata, and the test that shows it."""

import textwrap

from reflectance.papers.errata import errata_table


def render(table, png, pdf):
    """The table as a figure at print width: per erratum, where it is (left) and what it is (right)."""
    from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, TEXT_SIZE, new_figure, savefig

    x_where, x_label, x_text = 0.005, 0.215, 0.335  # column edges, fractions of the width
    wrap = {"where": 25, "text": 82, "test": 62}     # characters per line (the test in monospace)
    fields = (("printed", "As printed"), ("correct", "Correct / other"), ("consequence", "Computed"),
              ("test", "Test"))
    blocks = []
    for _, r in table.iterrows():
        where = [(str(r.text).split(" (")[0], "bold")] + [
            (line, "normal") for line in textwrap.wrap(str(r.location), wrap["where"])] + [
            (line, "italic") for line in textwrap.wrap(f"({r.kind})", wrap["where"])] * (r.kind != "erratum")
        what = [(label if i == 0 else "", line, key) for key, label in fields
                for i, line in enumerate(textwrap.wrap(str(r[key]).replace("::", ":: "), wrap.get(key, wrap["text"]),
                                                       break_long_words=False) or [""])]
        blocks.append((where, what, max(len(where), len(what))))
    gap = 0.7  # lines between errata
    total = sum(h for *_, h in blocks) + gap * len(blocks)
    line_in = 1.4 * TEXT_SIZE["table"] / 72
    fig = new_figure(PRINT_WIDTH_IN, (total + 3.5) * line_in + 0.3)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.3 / fig.get_figheight()))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(total + 1.5, -2.4)
    ax.text(x_where, -1.2, "Text, location", fontsize=TEXT_SIZE["annotation"], fontweight="bold", va="center")
    ax.text(x_label, -1.2, "What the text prints, what it should, what follows (computed), and the test",
            fontsize=TEXT_SIZE["annotation"], fontweight="bold", va="center")
    ax.axhline(-0.55, color="0.2", lw=0.8)
    y = 0.0
    for i, (where, what, h) in enumerate(blocks):
        if i % 2 == 0:
            ax.axhspan(y - 0.5 - gap / 2, y + h - 0.5 + gap / 2, color="0.94", lw=0)
        for j, (line, weight) in enumerate(where):
            ax.text(x_where, y + j, line, fontsize=TEXT_SIZE["table"], va="center",
                    fontweight="bold" if weight == "bold" else "normal",
                    fontstyle="italic" if weight == "italic" else "normal",
                    color="#a0522d" if weight == "italic" else None)  # the row's kind, when not an erratum
        for j, (label, line, key) in enumerate(what):
            ax.text(x_label, y + j, label, fontsize=TEXT_SIZE["table"], va="center", color="0.35")
            ax.text(x_text, y + j, line, fontsize=TEXT_SIZE["table"], va="center",
                    family="monospace" if key == "test" else None)
        y += h + gap
    sources = sorted(set(table.text[table.text.str.contains(" (", regex=False)]))
    ax.text(x_where, total + 0.6, "; ".join(sources), fontsize=TEXT_SIZE["table"], color="0.3", va="center")
    fig.suptitle("Errata: where Blinn 1977, Cook & Torrance 1982, the lecture and the article disagree\n"
                 "with each other or with arithmetic (kind in italics where it is not an erratum)", size=STYLE["axes.titlesize"], y=0.998, va="top")
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
