"""Audit 8, figure 2: does a shortcut's error follow the colour of F0 or the absorption? Each
audited dataset's largest CIEDE2000 (over the angles) against the chroma of its F0 and its mean
k, per method of figures.error, drawn in its own F0 colour."""

import numpy as np
from matplotlib.lines import Line2D

from reflectance.audit.database import read_table
from reflectance.colour.display import display_tag
from reflectance.io.atomic import write_text
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log

MARKERS = {"metal-like": "o", "absorbing": "^", "transparent": "s"}  # one shape per kind

with script_log(snakemake) as log:
    cfg, p = snakemake.params.figure, snakemake.params
    table = read_table(snakemake.input.csv)
    rows = table[table.status == "audited"]
    floor = cfg["k_floor"]
    k = np.maximum(rows.mean_k.to_numpy(), floor)  # k below the floor (and a missing k) drawn at it
    fig = new_figure(PRINT_WIDTH_IN, 1.0 + 2.1 * len(cfg["methods"]))
    axes = fig.subplots(len(cfg["methods"]), 2, sharex="col", sharey=True, squeeze=False,
                        gridspec_kw={"hspace": 0.12, "wspace": 0.06, "top": 0.93})
    top = max(float(rows[f"{m}_max_dE2000"].max()) for m in cfg["methods"])
    for (left, right), method in zip(axes, cfg["methods"]):
        dE = rows[f"{method}_max_dE2000"].to_numpy()
        for kind, marker in MARKERS.items():
            mine = (rows.kind == kind).to_numpy()
            for ax, x in ((left, rows.F0_C.to_numpy()), (right, k)):
                ax.scatter(x[mine], dE[mine], s=9, marker=marker, c=list(rows.F0_sRGB[mine]),
                           edgecolors="0.35", linewidths=0.3)
        for level in p.levels:
            for ax in (left, right):
                ax.axhline(level, color="0.55", linewidth=0.6, linestyle=":")
        for threshold in (p.absorbing_k, p.metal_mean_k):  # the kinds' bounds
            right.axvline(threshold, color="0.4", linewidth=0.8)
        for ax in (left, right):
            ax.set_yscale("symlog", linthresh=1.0, linscale=0.5)
            ax.margins(x=0.02)
            ax.grid(True)
        left.set_ylabel(f"{method}\nlargest \u0394E00")
    ticks = [t for t in (0, 0.5, 1, 2, 5, 10, 20, 50, 100, 200) if t <= top or t <= 10]
    axes[0, 0].set_yticks(ticks, [f"{t:g}" for t in ticks])
    axes[0, 0].set_ylim(0, 1.3 * top)
    axes[-1, 0].set_xlabel("chroma C*ab of F0 (CIELAB)")
    axes[-1, 1].set_xscale("log")
    low = f"{floor:g}".replace("e-0", "e-")
    axes[-1, 1].set_xlabel(f"mean k (\u2264 {low} or missing: at {low})")
    axes[0, 1].legend(handles=[Line2D([], [], marker=m, linestyle="", color="0.6",
                                      markeredgecolor="0.35", label=kind)
                               for kind, m in MARKERS.items()],
                      loc="upper left", fontsize=TEXT_SIZE["annotation"])
    axes[0, 0].set_title(f"Largest colour error over 0-90\u00b0 of {len(rows)} datasets, each "
                         f"dot in its F0 colour ({p.space})", loc="left")
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(p.space))

    coloured = rows[rows.kind != "transparent"]
    parts = []
    for method in cfg["methods"]:
        dE = coloured[f"{method}_max_dE2000"]
        worst = rows.loc[rows[f"{method}_max_dE2000"].idxmax()]
        parts.append(f"{method}: Spearman {dE.corr(coloured.F0_C, method='spearman'):.2f} with "
                     f"chroma, {dE.corr(coloured.mean_k, method='spearman'):.2f} with k "
                     f"(largest {worst[f'{method}_max_dE2000']:.2f}, {worst.dataset})")
    answer = (f"**Answer:** over the {len(coloured)} absorbing and metal-like datasets, the rank "
              f"correlation of each method's largest error with F0's chroma and with the mean k "
              f"is " + "; ".join(parts) + f". {int((rows.mean_k < floor).sum())} datasets have a "
              f"mean k below {floor:g} or none and are drawn at {floor:g}.\n")
    write_text(snakemake.output.answer, answer)
    log.info("%s", answer.strip())
