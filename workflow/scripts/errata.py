"""Errata of the four texts: every place where they disagree with each other or with arithmetic: the
text of workflow/report/errata.yaml (read as text only) with the consequence computed by each
row's function in reflectance.papers.errata, and the test that shows it (in the CSV; the figures,
for a paper's reader, leave the test paths out)."""

import textwrap
from pathlib import Path

from reflectance.papers.errata import errata_table


def wrap(text, width):
    """Lines of at most ``width`` characters with no orphan: a last line of a word or two (``1/2``,
    ``(N.E)``, ``4)``) is avoided by wrapping narrower until it carries at least a third of a line."""
    lines = textwrap.wrap(text, width, break_long_words=False) or [""]
    for narrower in range(width, int(0.75 * width), -1):
        candidate = textwrap.wrap(text, narrower, break_long_words=False)
        if len(candidate) == 1 or len(candidate[-1]) >= width / 3:
            return candidate
    return lines


def render(table, title, png, pdf, elsewhere):
    """The rows as a figure at print width, under one heading per kind: per row, where it is
    (left) and what it is (right), and under them the line ``elsewhere`` (where the other rows
    are). The test that shows each row is in the CSV, not the figure."""
    from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, TEXT_SIZE, new_figure, savefig

    x_where, x_label, x_text = 0.005, 0.215, 0.335  # column edges, fractions of the width
    width = {"where": 25, "text": 82}                # characters per line
    fields = (("printed", "As printed"), ("correct", "Correct / other"), ("consequence", "Computed"))
    blocks = []  # (heading or None, where lines, what lines, height)
    for kind, rows in table.groupby("kind", sort=False):
        if table.kind.nunique() > 1:
            blocks.append((kind[0].upper() + kind[1:], [], [], 1.2))
        for _, r in rows.iterrows():
            where = [(str(r.text).split(" (")[0], "bold")] + [
                (line, "normal") for line in wrap(str(r.location), width["where"])]
            what = [(label if i == 0 else "", line) for key, label in fields
                    for i, line in enumerate(wrap(str(r[key]).replace("::", ":: "), width["text"]))]
            blocks.append((None, where, what, max(len(where), len(what))))
    gap = 0.7  # lines between rows
    total = sum(h for *_, h in blocks) + gap * len(blocks)
    line_in = 1.4 * TEXT_SIZE["table"] / 72
    fig = new_figure(PRINT_WIDTH_IN, (total + 4.5) * line_in + 0.3)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.3 / fig.get_figheight()))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(total + 2.5, -2.4)
    ax.text(x_where, -1.2, "Text, location", fontsize=TEXT_SIZE["annotation"], fontweight="bold", va="center")
    ax.text(x_label, -1.2, "What the text prints, what it should, what follows (computed)",
            fontsize=TEXT_SIZE["annotation"], fontweight="bold", va="center")
    ax.axhline(-0.55, color="0.2", lw=0.8)
    y, shade = 0.0, 0
    for heading, where, what, h in blocks:
        if heading:
            ax.text(x_where, y + 0.1, heading, fontsize=TEXT_SIZE["annotation"], fontweight="bold",
                    fontstyle="italic", color="#a0522d", va="center")
            y += h + gap
            continue
        if shade % 2 == 0:
            ax.axhspan(y - 0.5 - gap / 2, y + h - 0.5 + gap / 2, color="0.94", lw=0)
        shade += 1
        for j, (line, weight) in enumerate(where):
            ax.text(x_where, y + j, line, fontsize=TEXT_SIZE["table"], va="center", fontweight=weight)
        for j, (label, line) in enumerate(what):
            ax.text(x_label, y + j, label, fontsize=TEXT_SIZE["table"], va="center", color="0.35")
            ax.text(x_text, y + j, line, fontsize=TEXT_SIZE["table"], va="center")
        y += h + gap
    sources = sorted(set(table.text[table.text.str.contains(" (", regex=False)]))
    ax.text(x_where, total + 0.6, "; ".join(sources), fontsize=TEXT_SIZE["table"], color="0.3", va="center")
    ax.text(x_where, total + 1.6, elsewhere, fontsize=TEXT_SIZE["table"], color="0.3", va="center",
            fontstyle="italic")
    fig.suptitle(title, size=STYLE["axes.titlesize"], y=0.998, va="top")
    savefig(fig, png, pdf)


if "snakemake" in globals():
    from reflectance.io.tables import write_csv
    from reflectance.scripting import script_log

    with script_log(snakemake) as log:
        settings = {k: v for k, v in snakemake.params.errata.items() if k != "rows"}
        table = errata_table(snakemake.input.rows, settings)
        table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
        # errata.png: the errata; errata_other.png: the rows of other kinds (naming, convention
        # mismatch, possible transcription artefacts), each under its own heading
        is_erratum = table.kind == "erratum"

        def rows_of(part):  # "naming (1), convention mismatch (1)", in the table's order
            return ", ".join(f"{kind} ({n})" for kind, n in part.kind.value_counts(sort=False).items())

        other_png, png = Path(snakemake.output.other_png).name, Path(snakemake.output.png).name
        render(table[is_erratum], "Errata: where Blinn 1977, Cook & Torrance 1982, the lecture and the article\n"
               "disagree with each other or with arithmetic", snakemake.output.png, snakemake.output.pdf,
               f"Rows of other kinds, in {other_png}: {rows_of(table[~is_erratum])}.")
        render(table[~is_erratum], "Not errata: naming, a convention mismatch and possible transcription\n"
               "artefacts in the four texts", snakemake.output.other_png, snakemake.output.other_pdf,
               f"The {int(is_erratum.sum())} errata: {png}.")
        for r in table.itertuples():
            log.info("%s | %s | %s", r.text, r.location, r.consequence)
