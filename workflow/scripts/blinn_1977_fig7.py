"""Blinn 1977, Fig. 7: an object rendered with Phong's and the Torrance-Sparrow highlight, edge lit
and front lit, (a) aluminium and (b) magnesium oxide with Blinn's measured parameters; Phong's c1
from the beta of c3. Grey images whose Y is Blinn's intensity i = p_a + d p_d + s p_s (no exposure:
i = 1 is display white). One figure per reading of Phong's p_s; a table of the differences."""

import numpy as np
import pandas as pd
from reflectance.colour.display import display_tag, encode

from reflectance.io.figures import new_figure, savefig
from reflectance.render.pipeline import display_image, render, render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.scenes import (blinn_scene_Blinn1977, highlight_crossover_Blinn1977,
                                       materials_Blinn1977, mirror_highlight_Blinn1977,
                                       rim_camera_Blinn1977)
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

TITLES = {"a": "Figure 7a  Simulation of aluminium surface",
          "b": "Figure 7b  Simulation of magnesium oxide surface"}
MODELS = {"phong": "Phong", "torrance_sparrow": "Torrance-Sparrow"}


with script_log(snakemake) as log:
    fig_cfg, stems, out = snakemake.params.fig, snakemake.params.stems, snakemake.output
    w = snakemake.params.wavelengths
    images, Y, rows, rims = {}, {}, [], {}
    traced = {}  # the renders share the object: one trace per camera and light (pipeline.render)
    rim_camera = rim_camera_Blinn1977(fig_cfg, fig_cfg["lights"]["edge"])
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
                                             f"{stems[key]}.exr", f"{stems[key]}.png", traced=traced)
                    images[key], Y[key] = display_image(result)[0], result.XYZ[..., 1]
                    log.info("%s: max i = %.4f; timings %s", key, Y[key].max(), result.timings)
                    if light == "edge":  # the highlight close up (fig7.rim_closeup), for the inset
                        rims[key] = render(scene_from_dict(blinn_scene_Blinn1977(
                            fig_cfg, m[model], fig_cfg["lights"]["edge"], w, rim_camera)),
                                           traced=traced).XYZ[..., 1]
                        log.info("%s close up: max i = %.4f", key, rims[key].max())
                ph, ts = Y[f"{panel}_phong_{light}_{reading}"], Y[f"{panel}_torrance_sparrow_{light}"]
                diff, lit = np.abs(ph - ts), (ph > 0) | (ts > 0)
                rows.append({"panel": panel, "label": p["label"], "phong_specular": reading,
                             "light": light, **fig_cfg["lights"][light], "p_a": fig_cfg["p_a"],
                             "p_s": p["p_s"], "p_d": p["p_d"], "n": p["n"], "c3": p["c3"],
                             "beta_deg": m["beta_deg"], "c1": m["c1"], "phong_s": m["phong_s"],
                             "phong_max": ph.max(), "torrance_sparrow_max": ts.max(),
                             "max_abs_difference": diff.max(), "mean_abs_difference": diff[lit].mean(),
                             "mirror_highlight": float(mirror_highlight_Blinn1977(
                                 p["p_s"], p["n"], fig_cfg["lights"][light]["angle_deg"]))})
    table = pd.DataFrame(rows)
    # Blinn: MgO "even more [specular] than the aluminum" edge lit: from which light angle on
    crossover = highlight_crossover_Blinn1977(fig_cfg["panels"]["a"], fig_cfg["panels"]["b"])
    table["crossover_deg"] = np.nan if crossover is None else crossover
    log.info("mirror highlights of MgO and aluminium cross at %s degrees", crossover)
    table.pipe(write_csv, out.csv, float_format="%.6g")

    # Edge lit beyond the crossover the highlight is a rim a few pixels thick (N.E = cos(angle/2)
    # at the mirror point) and brighter than i = 1: each edge-lit image gets an inset of the rim,
    # magnified, on one scale for all (white = the brightest edge-lit i), so the two materials compare.
    zoom = fig_cfg["camera"]["fov_deg"] / fig_cfg["rim_closeup"]["fov_deg"]
    rim_scale = max(rim.max() for rim in rims.values())  # one grey scale for every close-up

    h, wd = (n / 100 for n in images["a_torrance_sparrow_edge"].shape[:2])  # inches at 100 dpi
    gap, block, top, row_h = 0.05, 0.35, 0.7, h + 0.5  # row: title, image, difference line
    plot_w = 3.3  # the mirror-point highlight against the light angle, beside the renders
    W, H = 4 * wd + 3 * gap + block + 0.1 + plot_w + 0.75, top + 2 * row_h + 0.05
    sweep = np.linspace(90.0, 178.0, 881)
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
                    if light == "edge":
                        grey = encode(np.clip(rims[key] / rim_scale, 0, 1))
                        rh, rw = rims[key].shape
                        iw = 0.9  # the close-up across 90 % of the image, its aspect kept
                        inset = ax.inset_axes((0.05, 0.04, iw, iw * rh / rw * wd / h))
                        inset.imshow(grey, cmap="gray", vmin=0, vmax=1, interpolation="antialiased")
                        inset.set_xticks([]), inset.set_yticks([])
                        for side in inset.spines.values():
                            side.set(color="#e69f00", lw=0.8, visible=True)
                        inset.text(0.01, 0.03, f"rim close up \u00d7{zoom:.0f}, white = i "
                                   f"{rim_scale:.1f}",
                                   transform=inset.transAxes, color="#e69f00", fontsize=7.5,
                                   va="bottom")
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
        lights = fig_cfg["lights"]
        ax = fig.add_axes(((W - plot_w - 0.1) / W, (row_h + 0.3) / H, plot_w / W,
                           (row_h - 0.05) / H))
        for panel, colour in (("a", "#0072b2"), ("b", "#d55e00")):
            p = fig_cfg["panels"][panel]
            ax.plot(sweep, mirror_highlight_Blinn1977(p["p_s"], p["n"], sweep), color=colour,
                    label=f"{p['label']} (p_s = {p['p_s']:g}, n = {p['n']:g})")
            edge = table[(table.panel == panel) & (table.light == "edge")].iloc[0]
            ax.plot(lights["edge"]["angle_deg"], edge.torrance_sparrow_max, "o", mfc="none",
                    color=colour, ms=6)
        ax.axvline(crossover, color="0.4", lw=0.8, ls=(0, (3, 2)))
        ax.text(crossover - 1.5, 0.3, f"crossover\n{crossover:.1f}\u00b0", ha="right", va="top",
                fontsize=8, color="0.3", transform=ax.get_xaxis_transform())
        ax.set(yscale="log", xlim=(90, 178), xticks=np.arange(90, 179, 15),
               xlabel="light angle from the eye (\u00b0)", ylabel="p_s D\u2083 G F / (N\u00b7E) where N = H")
        ax.grid(True, which="major")
        ax.legend(loc="upper left", fontsize=7.5)
        ax.set_title("Torrance-Sparrow highlight where N = H\n(line; circles: brightest rendered i, edge lit)",
                     fontsize=8.5)
        fig.suptitle(f"Blinn 1977, Fig. 7 \u2014 Phong's p_s {reading.replace('_', ' ')}; light "
                     f"{lights['edge']['angle_deg']:g}\u00b0 (edge) and {lights['front']['angle_deg']:g}"
                     f"\u00b0 (front) from the eye; MgO's highlight passes aluminium's beyond "
                     f"{crossover:.1f}\u00b0; p_a = {fig_cfg['p_a']:g}, i = 1 is white", fontsize=11,
                     y=1 - 0.04 / H, va="top")
        savefig(fig, png, dpi=100, tight=False, tag=display_tag(scene.display.space))
