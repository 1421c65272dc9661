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
from reflectance.io.figures import new_figure, savefig
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

NAMES = {"D1": "D1 = cos^c1 \u03b1 (Phong)", "D2": "D2 = exp(\u2212(\u03b1 c2)\u00b2) (Torrance-Sparrow)",
         "D3": "D3 (Trowbridge-Reitz)"}
COLOURS = {"D1": "#0072b2", "D2": "#e69f00", "D3": "#009e73"}

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    betas = cfg["beta_deg"]
    alpha_deg = np.linspace(0.0, 90.0, int(round(90.0 / cfg["alpha_step_deg"])) + 1)
    fig = new_figure(4.8 * len(betas), 8.2)
    axes = fig.subplots(2, len(betas), squeeze=False)
    curves, summary = [], []
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
            lines.append(f"max |{a} \u2212 {b}| = {diff[i]:.4f} at \u03b1 = {alpha_deg[i]:.2f}\u00b0")
        summary.append(row)
        curves.append(pd.DataFrame({"beta_deg": beta_deg, "alpha_deg": alpha_deg, **D}))
        for axis in (ax, ax_log):
            for k in D:
                axis.plot(alpha_deg, D[k], color=COLOURS[k], lw=1.5, label=NAMES[k],
                          ls={"D1": "-", "D2": "--", "D3": ":"}[k])
            axis.axvline(beta_deg, color="0.5", lw=0.8, ls="-.")
            axis.axhline(0.5, color="0.5", lw=0.8, ls="-.")
            axis.plot(beta_deg, 0.5, "o", color="k", ms=5, zorder=5)
        ax.set(xlim=(0, min(90.0, 4 * beta_deg)), ylim=(0, 1.04), xlabel="\u03b1 (degrees)", ylabel="D",
               title=f"\u03b2 = {beta_deg:g}\u00b0: c1 = {c1:.3f}, c2 = {c2:.3f}, c3 = {c3:.4f}")
        ax.annotate("half value at \u03b2", (beta_deg, 0.5), xytext=(8, 8), textcoords="offset points",
                    fontsize=8.5)
        ax.text(0.98, 0.97, "\n".join(lines), transform=ax.transAxes, ha="right", va="top", fontsize=8.5,
                bbox=dict(facecolor="white", edgecolor="0.8", pad=3))
        ax_log.set(xlim=(0, 90), ylim=(1e-6, 2), yscale="log", xlabel="\u03b1 (degrees)",
                   ylabel="D (log scale)")
        log.info("beta %g: %s", beta_deg, "; ".join(lines))
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=10,
               frameon=False)
    fig.suptitle("Blinn 1977, \u201cFacet distribution functions\u201d \u2014 D1, D2, D3 with c1, c2, c3 from the "
                 "same half-value angle \u03b2 (each falls to 1/2 at \u03b1 = \u03b2)", fontsize=12)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    pd.concat(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    pd.DataFrame(summary).pipe(write_csv, snakemake.output.summary, float_format="%.6g")
