"""Blinn 1977, "Facet distribution functions": D1 (Phong), D2 (Torrance-Sparrow Gaussian) and D3
(Trowbridge-Reitz) with c1, c2, c3 from the same half-value angle beta, "very similar in shape".
Top row linear (where they are similar), bottom row logarithmic (where their tails differ)."""

import itertools

import numpy as np
import pandas as pd

from reflectance.optics.microfacet import (beta_to_c1_Blinn1977, beta_to_c2_Blinn1977,
                                    beta_to_c3_Blinn1977, distribution_Phong1975,
                                    distribution_TorranceSparrow1967,
                                    distribution_TrowbridgeReitz1975)
from matplotlib.ticker import MaxNLocator

from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

NAMES = {"D1": "$D_1 = \\cos^{c_1}\\alpha$ (Phong)", "D2": "$D_2 = e^{-(\\alpha c_2)^2}$ (Torrance-Sparrow)",
         "D3": "$D_3$ (Trowbridge-Reitz)"}
COLOURS = {"D1": OKABE_ITO[0], "D2": OKABE_ITO[4], "D3": OKABE_ITO[2]}
SUB = {"D1": "$D_1$", "D2": "$D_2$", "D3": "$D_3$"}

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    betas = cfg["beta_deg"]
    alpha_deg = np.linspace(0.0, 90.0, int(round(90.0 / cfg["alpha_step_deg"])) + 1)
    fig = new_figure(PRINT_WIDTH_IN, 0.78 * PRINT_WIDTH_IN)
    axes = fig.subplots(2, len(betas), squeeze=False)
    curves, summary, notes = [], [], []
    for (ax, ax_log), beta_deg in zip(axes.T, betas):
        beta = np.radians(beta_deg)
        c1, c2, c3 = beta_to_c1_Blinn1977(beta), beta_to_c2_Blinn1977(beta), beta_to_c3_Blinn1977(beta)
        functions = {"D1": lambda c: distribution_Phong1975(c, c1),  # Blinn 1977, D1, D2, D3
                     "D2": lambda c: distribution_TorranceSparrow1967(c, c2),
                     "D3": lambda c: distribution_TrowbridgeReitz1975(c, c3)}
        D = {k: f(np.cos(np.radians(alpha_deg))) for k, f in functions.items()}
        row = {"beta_deg": beta_deg, "c1": c1, "c2": c2, "c3": c3,
               **{f"{k}_at_beta": float(f(np.cos(beta))) for k, f in functions.items()},
               **{f"{k}_at_2beta": float(f(np.cos(min(2 * beta, np.pi / 2)))) for k, f in functions.items()}}
        lines = []
        for a, b in itertools.combinations(D, 2):
            diff = np.abs(D[a] - D[b])
            i = int(np.argmax(diff))
            row[f"max_abs_{a}_{b}"], row[f"alpha_deg_at_max_{a}_{b}"] = diff[i], alpha_deg[i]
            lines.append(f"max |{SUB[a]} \u2212 {SUB[b]}| = {diff[i]:.4f} at {alpha_deg[i]:.1f}\u00b0")
        summary.append(row)
        curves.append(pd.DataFrame({"beta_deg": beta_deg, "alpha_deg": alpha_deg, **D}))
        for axis in (ax, ax_log):
            for k in D:
                axis.plot(alpha_deg, D[k], color=COLOURS[k], label=NAMES[k],
                          ls={"D1": "-", "D2": "--", "D3": ":"}[k])
            axis.axvline(beta_deg, color="0.6", lw=0.6, ls="-.", zorder=0)
            axis.plot(beta_deg, 0.5, "o", color="k", ms=3.5, zorder=5)
        ax.set(xlim=(0, min(90.0, 4 * beta_deg)), ylim=(0, 1.04), ylabel="D", title=f"\u03b2 = {beta_deg:g}\u00b0")
        ax.annotate("all \u00bd at \u03b2", (beta_deg, 0.5), xytext=(5, 4), textcoords="offset points",
                    ha="left", va="bottom", fontsize=TEXT_SIZE["annotation"])
        notes.append(f"$c_1$ = {c1:.4g}, $c_2$ = {c2:.4g}, $c_3$ = {c3:.4g}\n" + "\n".join(lines))
        ax_log.set(xlim=(0, 90), ylim=(1e-6, 2), yscale="log", xlabel="\u03b1 (\u00b0)", ylabel="D (log scale)")
        for axis in (ax, ax_log):
            axis.xaxis.set_major_locator(MaxNLocator(6, steps=[1, 1.5, 3, 5, 10]))
        log.info("beta %g: %s", beta_deg, "; ".join(lines))
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="lower center", ncol=3, bbox_to_anchor=(0.5, -0.01))
    fig.suptitle("Blinn 1977, \u201cFacet distribution functions\u201d \u2014 $c_1$, $c_2$, $c_3$ from one "
                 "half-value angle \u03b2")
    fig.tight_layout(rect=(0, 0.185, 1, 1), h_pad=0.6, w_pad=0.8)
    for ax, note in zip(axes[1], notes):  # under each column: its c's and how far the D's differ
        box = ax.get_position()
        fig.text((box.x0 + box.x1) / 2, 0.165, note, ha="center", va="top", fontsize=TEXT_SIZE["table"],
                 linespacing=1.35)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    pd.concat(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    pd.DataFrame(summary).pipe(write_csv, snakemake.output.summary, float_format="%.6g")
