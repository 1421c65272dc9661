"""Audit 8, figure 3: which materials does each shortcut get most wrong? Per method, its worst
materials of the kinds of figures.worst (one dataset each: the material's worst), ranked by the
largest CIEDE2000 over the angles, with the exact and the method's colour at that angle."""

import textwrap

import numpy as np
from matplotlib.patches import Rectangle

from reflectance.audit.database import read_table
from reflectance.colour.display import display_tag
from reflectance.io.atomic import write_text
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    cfg, space = snakemake.params.figure, snakemake.params.space
    methods, count = cfg["methods"], cfg["count"]
    table = read_table(snakemake.input.csv)
    rows = table[(table.status == "audited") & table.kind.isin(cfg["kinds"])]
    # one dataset per material, its worst; none that the figure would print as 0.0
    worst = {m: rows[rows[f"{m}_max_dE2000"] >= 0.05]
             .sort_values([f"{m}_max_dE2000", "dataset"], ascending=[False, True])
             .drop_duplicates(["shelf", "material"]).head(count) for m in methods}

    fig = new_figure(PRINT_WIDTH_IN, 0.45 + 0.95 * len(methods))
    ax = fig.add_axes((0.11, 0.0, 0.89, 0.94))
    ax.set_xlim(0, count)
    ax.set_ylim(len(methods), 0)
    ax.axis("off")
    small = TEXT_SIZE["table"]
    for r, method in enumerate(methods):
        ax.text(-0.05, r + 0.5, method, ha="right", va="center", fontsize=TEXT_SIZE["annotation"])
        if len(worst[method]) < count:
            ax.text(len(worst[method]) + 0.1, r + 0.3, "no other material above 0.0",
                    ha="left", va="center", fontsize=small, color="0.4")
        for c, (_, row) in enumerate(worst[method].iterrows()):
            for side, colour in ((0, row[f"{method}_exact_sRGB_at_max"]),
                                 (1, row[f"{method}_sRGB_at_max"])):
                ax.add_patch(Rectangle((c + 0.06 + 0.44 * side, r + 0.06), 0.44, 0.36,
                                       facecolor=colour, edgecolor="0.6", linewidth=0.4))
            name = textwrap.shorten(f"{row.material} ({row.page})", 34, placeholder="\u2026")
            ax.text(c + 0.5, r + 0.47, "\n".join(textwrap.wrap(name, 19)[:2]), ha="center",
                    va="top", fontsize=small, linespacing=1.1)
            ax.text(c + 0.5, r + 0.86, f"{row[f'{method}_max_dE2000']:.1f} at "
                    f"{row[f'{method}_max_dE2000_deg']:g}\u00b0", ha="center", va="center",
                    fontsize=small, color="0.25")
    for c in range(count):
        ax.text(c + 0.5, -0.06, f"{c + 1}", ha="center", va="bottom",
                fontsize=TEXT_SIZE["annotation"], color="0.3")
    fig.suptitle(f"Worst {' and '.join(cfg['kinds'])} materials per shortcut (swatches: exact | "
                 f"method at its worst angle; CIEDE2000 at that angle; {space})",
                 fontsize=TEXT_SIZE["annotation"] + 1, y=1.0, va="bottom")
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(space))

    parts = []
    for method in methods:
        top = worst[method].iloc[0]
        parts.append(f"{method} {top[f'{method}_max_dE2000']:.2f} ({top.dataset}, at "
                     f"{top[f'{method}_max_dE2000_deg']:g}\u00b0)")
    everything = table[table.status == "audited"]
    others = everything[~everything.kind.isin(cfg["kinds"])]
    outside = {m: others.loc[others[f"{m}_max_dE2000"].idxmax()] for m in methods}
    beyond = [f"{m} {row[f'{m}_max_dE2000']:.2f} ({row.dataset}, {row.kind}, mean n "
              f"{row.mean_n:.6g})" for m, row in outside.items()
              if row[f"{m}_max_dE2000"] > worst[m].iloc[0][f"{m}_max_dE2000"]]
    answer = (f"**Answer:** among the {len(rows)} {' and '.join(cfg['kinds'])} datasets, each "
              f"method's worst material and its largest CIEDE2000: " + "; ".join(parts) + "."
              + (f" Datasets of the other kinds fare worse still: {'; '.join(beyond)}."
                 if beyond else "") + "\n")
    write_text(snakemake.output.answer, answer)
    log.info("%s", answer.strip())
