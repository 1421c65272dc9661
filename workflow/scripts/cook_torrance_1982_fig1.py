"""Cook & Torrance 1982, Fig. 1 (summary of symbols): each symbol beside its meaning and the name
that holds it in this project (a function, or an argument shown as ``function(argument)``)."""

import textwrap

import pandas as pd

from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

PACKAGE = "reflectance."  # every code name starts with it: printed once, in the column's heading
COLUMNS = {"symbol": 0.005, "meaning": 0.075, "code": 0.42}  # left edges, fractions of the width
WRAP = {"meaning": 44, "note": 70}  # characters per line (the note goes under the code names)

with script_log(snakemake) as log:
    table = pd.read_csv(snakemake.input.symbols, dtype=str, keep_default_na=False)
    table.pipe(write_csv, snakemake.output.csv)

    codes = [[c.strip().removeprefix(PACKAGE) for c in row.split(";")] for row in table.code]
    notes = [textwrap.wrap(n, WRAP["note"]) for n in table.note]
    meanings = [textwrap.wrap(m, WRAP["meaning"]) for m in table.meaning]
    heights = [max(len(c) + len(n), len(m)) for c, n, m in zip(codes, notes, meanings)]
    n_lines = sum(heights)
    line_in = 1.45 * TEXT_SIZE["table"] / 72  # one table line, in inches
    fig = new_figure(PRINT_WIDTH_IN, (n_lines + 2.2) * line_in + 0.3)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.3 / fig.get_figheight()))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(n_lines - 0.4, -2.2)
    for key, title in (("symbol", "Symbol"), ("meaning", "Meaning (C&T 1982, Fig. 1)"),
                       ("code", f"Code name in {PACKAGE[:-1]} (note in italics)")):
        ax.text(COLUMNS[key], -1.3, title, fontsize=TEXT_SIZE["annotation"], fontweight="bold", va="center")
    ax.axhline(-0.6, color="0.2", lw=0.8)
    y = 0
    for i, (row, code, note, meaning, h) in enumerate(zip(table.itertuples(), codes, notes, meanings, heights)):
        if i % 2:
            ax.axhspan(y - 0.5, y + h - 0.5, color="0.93", lw=0)
        ax.text(COLUMNS["symbol"] + 0.015, y, row.mathtext, fontsize=TEXT_SIZE["symbol"], va="center")
        for j, line in enumerate(meaning):
            ax.text(COLUMNS["meaning"], y + j, line, fontsize=TEXT_SIZE["table"], va="center")
        for j, name in enumerate(code):
            ax.text(COLUMNS["code"], y + j, name, fontsize=TEXT_SIZE["table"], va="center", family="monospace")
        for j, line in enumerate(note, start=len(code)):
            ax.text(COLUMNS["code"], y + j, line, fontsize=TEXT_SIZE["table"], va="center", color="0.3",
                    style="italic")
        y += h
    fig.suptitle("Cook & Torrance 1982, Fig. 1 \u2014 summary of symbols, with the code that holds each",
                 size=STYLE["axes.titlesize"], y=0.998, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("%d symbols, %d code names", len(table), sum(len(c) for c in codes))
