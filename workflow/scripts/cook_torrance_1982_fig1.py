"""Cook & Torrance 1982, Fig. 1 (summary of symbols): each symbol beside its meaning, in the paper's
order, in two blocks side by side. The code name that holds each symbol is not the paper's: it stays
in the CSV (and the caption says where), not on the figure."""

import textwrap

import pandas as pd

from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

BLOCKS = (0.01, 0.51)              # left edges of the two blocks, fractions of the width
MEANING_AT = 0.085                 # the meaning column, from a block's left edge
WRAP = 46                          # characters per line of a meaning

with script_log(snakemake) as log:
    table = pd.read_csv(snakemake.input.symbols, dtype=str, keep_default_na=False)
    table.pipe(write_csv, snakemake.output.csv)

    meanings = [textwrap.wrap(m, WRAP) for m in table.meaning]
    heights = [len(m) for m in meanings]
    half = (len(table) + 1) // 2   # the first block takes the first half, in the paper's order
    n_lines = max(sum(heights[:half]), sum(heights[half:]))
    line_in = 1.5 * TEXT_SIZE["table"] / 72  # one table line, in inches
    fig = new_figure(PRINT_WIDTH_IN, (n_lines + 2.2) * line_in + 0.3)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.3 / fig.get_figheight()))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(n_lines - 0.4, -2.2)
    for b, rows in enumerate((range(half), range(half, len(table)))):
        x0 = BLOCKS[b]
        for dx, title in ((0.0, "Symbol"), (MEANING_AT, "Meaning")):
            ax.text(x0 + dx, -1.3, title, fontsize=TEXT_SIZE["annotation"], fontweight="bold", va="center")
        ax.plot([x0, x0 + 0.48], [-0.6, -0.6], color="0.2", lw=0.8)
        y = 0
        for k, i in enumerate(rows):
            if k % 2:
                ax.fill_between([x0, x0 + 0.48], y - 0.5, y + heights[i] - 0.5, color="0.93", lw=0)
            ax.text(x0 + 0.015, y, table.mathtext[i], fontsize=TEXT_SIZE["symbol"], va="center")
            for j, line in enumerate(meanings[i]):
                ax.text(x0 + MEANING_AT, y + j, line, fontsize=TEXT_SIZE["table"], va="center")
            y += heights[i]
    fig.suptitle("Cook & Torrance 1982, Fig. 1 \u2014 summary of symbols",
                 size=STYLE["axes.titlesize"], y=0.998, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("%d symbols in two blocks of %d and %d", len(table), half, len(table) - half)
