"""Blinn 1977, Fig. 7: an object rendered with Phong's and the Torrance-Sparrow highlight, edge lit
and front lit, (a) aluminium and (b) magnesium oxide with Blinn's measured parameters; Phong's c1
from the beta of c3. Grey images whose Y is Blinn's intensity i = p_a + d p_d + s p_s (no exposure:
i = 1 is display white). One figure per reading of Phong's p_s; a table of the differences."""

import numpy as np
import pandas as pd

from reflectance.io.figures import new_figure, savefig
from reflectance.render.pipeline import display_image, render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.scenes import blinn_scene_Blinn1977, materials_Blinn1977
from reflectance.scripting import script_log

TITLES = {"a": "Figure 7a  Simulation of aluminium surface",
          "b": "Figure 7b  Simulation of magnesium oxide surface"}
MODELS = {"phong": "Phong", "torrance_sparrow": "Torrance-Sparrow"}


with script_log(snakemake) as log:
    fig_cfg, stems, out = snakemake.params.fig, snakemake.params.stems, snakemake.output
    w = snakemake.params.wavelengths
    images, Y, rows = {}, {}, []
    for panel in ("a", "b"):
        p = fig_cfg["panels"][panel]
        for reading in fig_cfg["phong_specular_readings"]:
            m = materials_Blinn1977(p["p_s"], p["p_d"], p["c3"], p["n"], reading)
            for light in ("edge", "front"):
                for model in MODELS:
                    key = (f"{panel}_torrance_sparrow_{light}" if model == "torrance_sparrow"
                           else f"{panel}_phong_{light}_{reading}")
                    if key in images:
                        continue  # the Torrance-Sparrow renders do not depend on the reading
                    doc = blinn_scene_Blinn1977(fig_cfg, m[model], fig_cfg["lights"][light], w)
                    scene = scene_from_dict(doc, source=f"config.yaml figures.blinn_1977.fig7 {key}")
                    result = render_to_files(scene, f"{stems[key]}.scene.yaml",
                                             f"{stems[key]}.exr", f"{stems[key]}.png")
                    images[key], Y[key] = display_image(result)[0], result.XYZ[..., 1]
                    log.info("%s: max i = %.4f; timings %s", key, Y[key].max(), result.timings)
                ph, ts = Y[f"{panel}_phong_{light}_{reading}"], Y[f"{panel}_torrance_sparrow_{light}"]
                diff, lit = np.abs(ph - ts), (ph > 0) | (ts > 0)
                rows.append({"panel": panel, "label": p["label"], "phong_specular": reading,
                             "light": light, **fig_cfg["lights"][light], "p_a": fig_cfg["p_a"],
                             "p_s": p["p_s"], "p_d": p["p_d"], "n": p["n"], "c3": p["c3"],
                             "beta_deg": m["beta_deg"], "c1": m["c1"], "phong_s": m["phong_s"],
                             "phong_max": ph.max(), "torrance_sparrow_max": ts.max(),
                             "max_abs_difference": diff.max(), "mean_abs_difference": diff[lit].mean()})
    table = pd.DataFrame(rows)
    table.to_csv(out.csv, index=False, float_format="%.6g", lineterminator="\n")

    h, wd = (n / 100 for n in images["a_torrance_sparrow_edge"].shape[:2])  # inches at 100 dpi
    gap, block, top, row_h = 0.05, 0.35, 0.7, h + 0.5  # row: title, image, difference line
    W, H = 4 * wd + 3 * gap + block + 0.1, top + 2 * row_h + 0.05
    for reading, png in zip(fig_cfg["phong_specular_readings"], out.figures):
        fig = new_figure(W, H)
        for k, panel in enumerate(("a", "b")):
            x0 = 0.05 + k * (2 * wd + gap + block)
            for j, light in enumerate(("edge", "front")):
                y0 = H - top - (j + 1) * row_h + 0.3  # bottom of the image
                for i, model in enumerate(MODELS):
                    key = (f"{panel}_{model}_{light}" + (f"_{reading}" if model == "phong" else ""))
                    ax = fig.add_axes(((x0 + i * (wd + gap)) / W, y0 / H, wd / W, h / H))
                    ax.imshow(images[key], interpolation="nearest")
                    ax.set_xticks([]), ax.set_yticks([])
                    ax.set_title(f"{MODELS[model]}, {light} lit", fontsize=9, pad=3)
                row = table[(table.panel == panel) & (table.phong_specular == reading)
                            & (table.light == light)].iloc[0]
                fig.text((x0 + wd + gap / 2) / W, (y0 - 0.06) / H,
                         f"max |i_Phong \u2212 i_T-S| = {row.max_abs_difference:.3f}   (max i: Phong "
                         f"{row.phong_max:.2f}, Torrance-Sparrow {row.torrance_sparrow_max:.2f})",
                         ha="center", va="top", fontsize=8.5)
            p = fig_cfg["panels"][panel]
            fig.text((x0 + wd + gap / 2) / W, (H - 0.3) / H,
                     f"{TITLES[panel]}\np_s = {p['p_s']:g}, p_d = {p['p_d']:g}, n = {p['n']:g}, "
                     f"c3 = {p['c3']:g} (\u03b2 = {row.beta_deg:.2f}\u00b0); Phong c1 = {row.c1:.2f}, "
                     f"its p_s = {row.phong_s:.4g}", ha="center", va="top", fontsize=9.5)
        fig.suptitle(f"Blinn 1977, Fig. 7 \u2014 Phong's p_s {reading.replace('_', ' ')}; "
                     f"p_a = {fig_cfg['p_a']:g}; intensity i = Y, i = 1 is white", fontsize=11,
                     y=1 - 0.04 / H, va="top")
        savefig(fig, png, dpi=100, tight=False)
