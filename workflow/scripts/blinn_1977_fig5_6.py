"""Blinn 1977, Figs. 5 and 6: Phong vs Torrance-Sparrow reflection in the plane of incidence as
polar plots (distance from the centre = intensity reflected in that direction), light from the
right at the configured angle; one row per parameter set, both models on the same scale."""

import numpy as np
import pandas as pd
from matplotlib.ticker import MaxNLocator

from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982
from reflectance.optics.microfacet import beta_to_c1_Blinn1977, c3_to_beta_Blinn1977
from reflectance.io.figures import new_figure, savefig
from reflectance.papers.polar import intensity_in_plane_of_incidence
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg, number = snakemake.params.fig, snakemake.params.figure_number
    theta_i = np.radians(float(snakemake.params.incidence_deg))
    # n_directions from -90 to 90 degrees inclusive; the two horizon samples (i = 0) are dropped
    theta_r = np.radians(np.linspace(-90.0, 90.0, cfg["n_directions"])[1:-1])
    sets = cfg["parameter_sets"]
    fig = new_figure(12, 0.9 + 3.5 * len(sets))
    axes = np.atleast_2d(fig.subplots(len(sets), 2))
    curves, summary = [], []
    for row_axes, s in zip(axes, sets):
        beta = c3_to_beta_Blinn1977(s["c3"])
        c1 = beta_to_c1_Blinn1977(beta)  # Blinn's equal-beta rule: D1 and D3 halve at the same angle
        models = {
            "phong": ("BlinnPhong1977", dict(c1=c1)),
            "torrance_sparrow": ("TorranceSparrow_Blinn1977", dict(
                F=lambda c, n=s["n"]: fresnel_dielectric_CookTorrance1982(c, n),
                distribution="TrowbridgeReitz1975", c3=s["c3"])),
        }
        values, row = {}, {"parameter_set": s["label"], **{k: s[k] for k in ("p_s", "p_d", "n", "c3")},
                           "beta_deg": np.degrees(beta), "c1": c1, "theta_i_deg": np.degrees(theta_i)}
        for key, (method, extra) in models.items():
            kwargs = dict(p_d=s["p_d"], p_s=s["p_s"], **extra)
            values[key] = intensity_in_plane_of_incidence(theta_i, theta_r, method, **kwargs)
            peak = int(np.argmax(values[key]))
            row.update({f"{key}_max": values[key][peak], f"{key}_max_deg": np.degrees(theta_r[peak]),
                        f"{key}_mirror": float(intensity_in_plane_of_incidence(
                            theta_i, theta_i, method, **kwargs))})
        summary.append(row)
        curves.append(pd.DataFrame({"parameter_set": s["label"], "theta_r_deg": np.degrees(theta_r),
                                    **values}))
        R = 1.1 * max(v.max() for v in values.values())  # the same scale for both models
        ticks = [t for t in MaxNLocator(4).tick_values(0, R) if 0 < t < R]
        titles = {"phong": f"Phong: p_d (N\u00b7L) + p_s (N\u00b7H)^c1,  c1 = {c1:.2f}",
                  "torrance_sparrow": f"Torrance-Sparrow: p_d (N\u00b7L) + p_s D3 G F / (N\u00b7E),  "
                                      f"c3 = {s['c3']:g}"}
        for ax, key in zip(row_axes, ("phong", "torrance_sparrow")):
            r = values[key]
            ax.fill_between([-R, R], -0.12 * R, 0, color="0.9", lw=0)
            ax.axhline(0, color="k", lw=1.2)
            for t in ticks:
                arc = np.linspace(0, np.pi, 181)
                ax.plot(t * np.cos(arc), t * np.sin(arc), color="0.85", lw=0.6, zorder=0)
                for x in (-t, t):
                    ax.text(x, -0.02 * R, f"{t:g}", ha="center", va="top", fontsize=7, color="0.4")
            # Blinn's light comes from the right: reflectance.papers.polar's plane seen from behind (x -> -x)
            ax.plot(-r * np.sin(theta_r), r * np.cos(theta_r), color="#0072b2", lw=1.6)
            light = 0.97 * R * np.array([np.sin(theta_i), np.cos(theta_i)])
            ax.annotate("", xy=0.04 * light, xytext=light,
                        arrowprops=dict(arrowstyle="-|>", color="#e69f00", lw=1.5))
            ax.annotate("", xy=light * [-1, 1], xytext=(0, 0),
                        arrowprops=dict(arrowstyle="-|>", color="0.45", lw=1.0, ls="--"))
            ax.text(*(light * [-1, 1] * 1.03), "mirror\ndirection", ha="center", va="bottom",
                    fontsize=8, color="0.35")
            peak_deg = row[f"{key}_max_deg"]
            peak = row[f"{key}_max"] * np.array([-np.sin(np.radians(peak_deg)), np.cos(np.radians(peak_deg))])
            ax.plot(*peak, "o", color="#d55e00", ms=4)
            ax.text(0.99, 0.97, f"max {row[f'{key}_max']:.3f} at \u03b8 = {peak_deg:.2f}\u00b0\n"
                    f"at the mirror direction: {row[f'{key}_mirror']:.3f}", transform=ax.transAxes,
                    ha="right", va="top", fontsize=8.5)
            ax.set(xlim=(-R, R), ylim=(-0.12 * R, 1.02 * R), aspect="equal", xticks=[], yticks=[])
            ax.set_title(titles[key], fontsize=9.5)
            for side in ax.spines.values():
                side.set_visible(False)
        row_axes[0].text(-0.07, 0.5, f"{s['label']}\np_s = {s['p_s']:g}, p_d = {s['p_d']:g}\n"
                         f"n = {s['n']:g}, c3 = {s['c3']:g}\n\u03b2 = {np.degrees(beta):.2f}\u00b0",
                         transform=row_axes[0].transAxes, ha="right", va="center", fontsize=9)
        log.info("%s: %s", s["label"], ", ".join(f"{k} = {v:.6g}" for k, v in row.items()
                                                   if not isinstance(v, str)))
    fig.suptitle(f"Blinn 1977, Fig. {number} \u2014 Phong vs Torrance-Sparrow, light at "
                 f"{np.degrees(theta_i):g}\u00b0 from the normal, from the right (same scale in each "
                 f"row; F: dielectric Fresnel with the 1/2)", fontsize=11)
    fig.subplots_adjust(left=0.19, right=0.99, top=0.9, bottom=0.02, wspace=0.05, hspace=0.25)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    pd.concat(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    pd.DataFrame(summary).pipe(write_csv, snakemake.output.summary, float_format="%.6g")
