"""Cook & Torrance 1982, Fig. 1 (summary of symbols): each symbol beside its meaning and the name
that holds it in this project (a function, or an argument shown as ``function(argument)``)."""

import pandas as pd

from reflectance.io.figures import new_figure, savefig
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    table = pd.read_csv(snakemake.input.symbols, dtype=str, keep_default_na=False)
    table.pipe(write_csv, snakemake.output.csv)

    codes = [[c.strip() for c in row.split(";")] for row in table.code]
    n_lines = sum(len(c) for c in codes)
    fig = new_figure(14.5, 1.1 + 0.215 * n_lines)
    ax = fig.add_axes((0.01, 0.01, 0.98, 0.985 - 0.4 / fig.get_figheight()))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(n_lines, -1.5)
    for x, title in ((0.01, "Symbol"), (0.06, "Meaning (C&T 1982, Fig. 1)"),
                     (0.30, "Code name in this project"), (0.77, "Note")):
        ax.text(x, -1.0, title, fontsize=10, fontweight="bold", va="center")
    ax.axhline(-0.55, color="0.2", lw=0.8)
    y = 0
    for i, (row, code) in enumerate(zip(table.itertuples(), codes)):
        if i % 2:
            ax.axhspan(y - 0.5, y + len(code) - 0.5, color="0.93", lw=0)
        ax.text(0.02, y, row.mathtext, fontsize=11, va="center")
        ax.text(0.06, y, row.meaning, fontsize=9, va="center")
        ax.text(0.77, y, row.note, fontsize=8.5, va="center", color="0.3", style="italic")
        for j, name in enumerate(code):
            ax.text(0.30, y + j, name, fontsize=8.5, va="center", family="monospace")
        y += len(code)
    fig.suptitle("Cook & Torrance 1982, Fig. 1 \u2014 summary of symbols, with the code that "
                 "holds each", fontsize=11, y=0.995, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("%d symbols, %d code names", len(table), n_lines)
