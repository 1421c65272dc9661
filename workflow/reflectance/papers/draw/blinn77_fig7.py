"""Blinn 1977, Fig. 7, drawn: the job of rule ``blinn77_fig7``, called by its script,
``workflow/scripts/blinn_1977_fig7.py`` (which says what the figure shows). What the job reads,
renders and writes is declared in :mod:`reflectance.papers.figures.blinn77_fig7`."""

from __future__ import annotations

import logging
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

from reflectance.colour.display import compress_highlights, display_tag, encode
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import OKABE_ITO, TEXT_SIZE, new_figure, savefig, text_colour
from reflectance.render.pipeline import render, render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.figures import blinn77_fig7 as definition
from reflectance.papers.scenes import (highlight_crossover_Blinn1977, materials_Blinn1977,
                                       mirror_highlight_Blinn1977)
from reflectance.scripting import params_dict
from reflectance.io.tables import write_csv

__all__ = ["run"]

TITLES = {"a": "Figure 7a  Simulation of aluminium surface",
          "b": "Figure 7b  Simulation of magnesium oxide surface"}
MODELS = {"phong": "Phong", "torrance_sparrow": "Torrance-Sparrow"}  # definition.MODELS, titled


def _rim_profile(renders: Iterable[npt.NDArray[np.floating]]
                ) -> tuple[int, npt.NDArray[np.intp]]:
    """The column through the brightest pixel of ``renders`` (images of i of one size), and the
    rows of it that show the object in any of them (i >= p_a > 0 there, 0 off it): where the
    figure draws i down the lit rim and face of each render on one axis."""
    stack = np.stack(list(renders))
    column = int(np.unravel_index(np.argmax(stack), stack.shape)[2])
    rows = np.flatnonzero((stack[:, :, column] > 0).any(axis=0))
    return column, np.arange(rows[0], rows[-1] + 1)


def run(snakemake: Any, log: logging.Logger) -> None:
    """Render every panel, model, light and reading of Phong's p_s from one trace per camera and
    light, tabulate their differences, draw one figure per reading and light and write the
    caption's values: ``snakemake`` is the rule's job (its params and output), ``log`` its log."""
    params = params_dict(snakemake.params)
    fig_cfg, out = params["fig"], snakemake.output
    folder = str(Path(out.csv).parent)  # the rule's outputs' folder
    stems, lights = definition.stems(params, folder), definition.lights(fig_cfg)
    closeup = definition.rim_light(fig_cfg)
    images, Y, rows, rims = {}, {}, [], {}
    # the renders share the object: one trace per camera and light (keep_trace)
    for item in definition.scenes(params, folder=folder):  # the scenes the check validated
        key = item.tags["key"]
        scene = scene_from_dict(item.document, source=f"config.yaml figures.blinn_1977.fig7 {key}")
        if item.written:
            stem = stems[key]
            result = render_to_files(scene, item.file, f"{stem}.exr", f"{stem}.png",
                                     keep_trace=True)
            images[key], Y[key] = result.display[0], result.XYZ[..., 1]
            log.info("%s: max i = %.4f; timings %s", key, Y[key].max(), result.timings)
        else:  # the highlight close up (fig7.rim_closeup), for the inset
            rims[key] = render(scene, keep_trace=True).XYZ[..., 1]
            log.info("%s close up: max i = %.4f", key, rims[key].max())
    for panel, p in fig_cfg["panels"].items():
        for reading in fig_cfg["phong_specular_readings"]:
            m = materials_Blinn1977(p["p_s"], p["p_d"], p["c3"], p["n"], reading)
            for light in lights:
                ph = Y[definition.render_key(panel, "phong", light, reading)]
                ts = Y[definition.render_key(panel, "torrance_sparrow", light, reading)]
                diff, lit = np.abs(ph - ts), (ph > 0) | (ts > 0)
                rows.append({"panel": panel, "label": p["label"], "phong_specular": reading,
                             "light": light, **lights[light], "p_a": fig_cfg["p_a"],
                             "p_s": p["p_s"], "p_d": p["p_d"], "n": p["n"], "c3": p["c3"],
                             "beta_deg": m["beta_deg"], "c1": m["c1"], "phong_s": m["phong_s"],
                             "phong_max": ph.max(), "torrance_sparrow_max": ts.max(),
                             "max_abs_difference": diff.max(), "mean_abs_difference": diff[lit].mean(),
                             "mirror_highlight": float(mirror_highlight_Blinn1977(
                                 p["p_s"], p["n"], lights[light]["angle_deg"]))})
    table = pd.DataFrame(rows)
    # Blinn: MgO "even more [specular] than the aluminum" edge lit: from which light angle on
    crossover = highlight_crossover_Blinn1977(fig_cfg["panels"]["a"], fig_cfg["panels"]["b"])
    table["crossover_deg"] = np.nan if crossover is None else crossover
    log.info("mirror highlights of MgO and aluminium cross at %s degrees", crossover)
    table.pipe(write_csv, out.csv, float_format="%.6g")

    # Near grazing light (beyond the crossover) the highlight is a rim a few pixels thick (N.E =
    # cos(angle/2) at the mirror point) and brighter than i = 1: each image under the close-up's
    # light gets an inset of the rim, magnified, on one scale for all (white = the brightest i).
    zoom = fig_cfg["camera"]["fov_deg"] / fig_cfg["rim_closeup"]["fov_deg"]
    rim_scale = max(rim.max() for rim in rims.values())  # one grey scale for every close-up
    # the default figure's (the grazing view's) four edge-lit images share one exposure: white =
    # the brightest Torrance-Sparrow i of them, compressed above fig7.grazing.highlight_knee
    grazing = definition.GRAZING + "edge"
    if grazing in lights:
        white = max(Y[definition.render_key(p, "torrance_sparrow", grazing, None)].max()
                    for p in fig_cfg["panels"])
        knee = fig_cfg["grazing"]["highlight_knee"]
        shared = {key: encode(compress_highlights(np.repeat(Y[key][..., None], 3, -1) / white,
                                                  knee)) for key in Y if grazing in key}

    # Blinn's layout, drawn at the print width (PRINT_WIDTH_IN, its text at the figures' sizes):
    # per panel Phong and Torrance-Sparrow under the figure's light side by side, under them one
    # front-lit image ("Both Models Essentially Same"; Torrance-Sparrow, the difference printed),
    # pixel for pixel at DPI; the light-angle plot at the bottom.
    T = TEXT_SIZE
    DPI = 230
    h, wd = (n / DPI for n in next(iter(images.values())).shape[:2])  # inches
    gap, block = 0.05, 0.2  # between the two models of a panel; between the panels
    W = 4 * wd + 2 * gap + block + 0.12
    # the figure's two-line title and each panel's three-line heading; column names; the two
    # lines under each row (inches)
    top, heads, foot = 1.0, 0.28, 0.45
    plot_h, plot_foot = 1.75, 0.5
    H = top + heads + 2 * (h + foot) + 0.45 + plot_h + plot_foot
    sweep = np.linspace(90.0, 178.0, 881)
    COLOURS = {"a": OKABE_ITO[0], "b": OKABE_ITO[1]}  # aluminium, MgO: image marks and plots
    profile_peaks = {}  # per light and panel: the brightest i of the profile (for the caption)

    def image(ax, key, text):
        ax.imshow(shared[key] if grazing in key else images[key], interpolation="nearest")
        ax.set_xticks([]), ax.set_yticks([])
        ax.text(0.03, 0.95, text, transform=ax.transAxes, color="white", fontsize=T["annotation"],
                va="top")

    for (reading, light), png in definition.figures(fig_cfg, folder).items():
        front = definition.figure_front(fig_cfg, light)
        name = {light: light.removeprefix(definition.GRAZING),
                front: front.removeprefix(definition.GRAZING)}
        edge_white = white if light == grazing else 1.0  # the edge-lit images' white (an i)
        ts_edge = {p: Y[definition.render_key(p, "torrance_sparrow", light, None)]
                   for p in ("a", "b")}
        column, down = _rim_profile(ts_edge.values())
        fig = new_figure(W, H)
        for k, panel in enumerate(("a", "b")):
            x0 = 0.06 + k * (2 * wd + gap + block)
            y0 = H - top - heads - h  # the bottom of the edge-lit row
            for i, model in enumerate(MODELS):
                key = definition.render_key(panel, model, light, reading)
                ax = fig.add_axes(((x0 + i * (wd + gap)) / W, y0 / H, wd / W, h / H))
                image(ax, key, f"{name[light]} lit, {lights[light]['angle_deg']:g}\u00b0")
                ax.set_title(MODELS[model], fontsize=T["symbol"], pad=3)
                if model == "torrance_sparrow":  # the profile's column, marked at both edges
                    limits = ax.get_xlim(), ax.get_ylim()
                    for y, mark in ((0.97, "v"), (0.03, "^")):
                        ax.plot(column, y, mark, color=COLOURS[panel], ms=5,
                                transform=ax.get_xaxis_transform())
                    ax.set(xlim=limits[0], ylim=limits[1])
                if light == closeup:
                    grey = encode(np.clip(rims[key] / rim_scale, 0, 1))
                    rh, rw = rims[key].shape
                    iw = 0.9  # the close-up across 90 % of the image, its aspect kept
                    inset = ax.inset_axes((0.05, 0.04, iw, iw * rh / rw * wd / h))
                    inset.imshow(grey, cmap="gray", vmin=0, vmax=1, interpolation="antialiased")
                    inset.set_xticks([]), inset.set_yticks([])
                    for side in inset.spines.values():
                        side.set(color="#e69f00", lw=0.8, visible=True)
                    inset.text(0.02, 0.05, f"rim \u00d7{zoom:.0f}, white: i = {rim_scale:.1f}",
                               transform=inset.transAxes, color="#e69f00",
                               fontsize=T["annotation"], va="bottom")
            rows_of = table[(table.panel == panel) & (table.phong_specular == reading)]
            row = rows_of[rows_of.light == light].iloc[0]
            fig.text((x0 + wd + gap / 2) / W, (y0 - 0.04) / H,
                     f"max i: Phong {row.phong_max:.2f}, Torrance-Sparrow "
                     f"{row.torrance_sparrow_max:.2f}\nwhite: i = {edge_white:.3g}"
                     + (", one exposure for the four edge-lit images" if light == grazing
                        else "; brighter clips"),
                     ha="center", va="top", fontsize=T["annotation"], linespacing=1.3)
            yf = y0 - foot - h  # the front-lit image, centred under the pair
            ax = fig.add_axes(((x0 + wd / 2 + gap / 2) / W, yf / H, wd / W, h / H))
            image(ax, definition.render_key(panel, "torrance_sparrow", front, reading),
                  f"{name[front]} lit, {lights[front]['angle_deg']:g}\u00b0")
            both = rows_of[rows_of.light == front].iloc[0]
            fig.text((x0 + wd + gap / 2) / W, (yf - 0.04) / H,
                     "Both Models Essentially Same (Blinn)\n"  # his label under the image
                     f"max |i_Phong \u2212 i_T-S| = {both.max_abs_difference:.3f}; white: i = 1",
                     ha="center", va="top", fontsize=T["annotation"], linespacing=1.3)
            p = fig_cfg["panels"][panel]
            fig.text((x0 + wd + gap / 2) / W, (H - top + 0.02) / H,
                     f"{TITLES[panel]}\np_s = {p['p_s']:g}, p_d = {p['p_d']:g}, n = {p['n']:g}, "
                     f"c3 = {p['c3']:g}\nPhong c1 = {row.c1:.2f}, its p_s = {row.phong_s:.4g}",
                     ha="center", va="bottom", fontsize=T["annotation"], linespacing=1.3)

        # left: the Torrance-Sparrow edge-lit i down the marked column, both materials on one axis
        ax = fig.add_axes((0.62 / W, plot_foot / H, (W / 2 - 1.07) / W, plot_h / H))
        for panel in ("a", "b"):
            i = ts_edge[panel][down, column]
            ax.plot(down - down[0], i, color=COLOURS[panel], lw=1.2, drawstyle="steps-mid",
                    label=fig_cfg["panels"][panel]["label"])
            peak = int(np.argmax(i))
            profile_peaks[light, panel] = float(i[peak])
            ax.annotate(f"{i[peak]:.2f}", (peak, i[peak]), xytext=(5, -2),  # under the white line
                        textcoords="offset points", color=text_colour(COLOURS[panel]),
                        fontsize=T["annotation"], va="top")
        ax.axhline(edge_white, color="0.4", lw=0.8, ls=(0, (3, 2)))
        ax.text(0.98, edge_white, "white of the edge-lit images", ha="right", va="bottom",
                fontsize=T["annotation"], color="0.3", transform=ax.get_yaxis_transform())
        ax.set(xlim=(-2, down[-1] - down[0] + 2), ylim=(0, None),
               xlabel="pixels below the object's top edge", ylabel="i, edge lit")
        ax.set_title("Torrance-Sparrow down the marked column (\u25bc)", fontsize=T["symbol"])
        ax.legend(loc="center right", bbox_to_anchor=(1.0, 0.6))
        ax.grid(True)

        # right: the highlight where N = H against the light's angle
        ax = fig.add_axes(((W / 2 + 0.47) / W, plot_foot / H, (W / 2 - 0.62) / W, plot_h / H))
        for panel in ("a", "b"):
            p = fig_cfg["panels"][panel]
            ax.plot(sweep, mirror_highlight_Blinn1977(p["p_s"], p["n"], sweep),
                    color=COLOURS[panel], label=f"{p['label']}, n = {p['n']:g}")
            at = table[(table.panel == panel) & (table.light == light)].iloc[0]
            ax.plot(lights[light]["angle_deg"], at.mirror_highlight, "o", mfc="none",
                    color=COLOURS[panel], ms=6)
            # the renders' brightest i: G stays 1 while N.E > E.H / 2, so past N = H, s grows
            ax.plot(lights[light]["angle_deg"], at.torrance_sparrow_max, "v", color=COLOURS[panel],
                    ms=5)
        ax.plot([], [], "o", mfc="none", color="0.3", ms=6, label="N = H at this light")
        ax.plot([], [], "v", color="0.3", ms=5, label="renders' brightest i")
        if crossover is not None:  # (panels of other parameters may not cross at all)
            ax.axvline(crossover, color="0.4", lw=0.8, ls=(0, (3, 2)))
            ax.text(crossover - 1.5, 0.03, f"crossover\n{crossover:.1f}\u00b0", ha="right",
                    va="bottom", fontsize=T["annotation"], color="0.3",
                    transform=ax.get_xaxis_transform())
        ax.set(yscale="log", xlim=(90, 178), xticks=np.arange(90, 179, 15),
               xlabel="light angle from the eye (\u00b0)", ylabel="p_s D\u2083 G F / (N\u00b7E)")
        ax.set_title("Torrance-Sparrow highlight where N = H", fontsize=T["symbol"])
        ax.grid(True, which="major")
        ax.legend(loc="upper left", fontsize=T["annotation"])
        brighter = (table[(table.panel == "b") & (table.light == light)].mirror_highlight.iloc[0]
                    > table[(table.panel == "a") & (table.light == light)].mirror_highlight.iloc[0])
        verdict = "MgO brighter than aluminium" if brighter else "MgO dimmer than aluminium"
        # two lines, each a phrase: the claim, then the object and the reading
        fig.suptitle(f"Blinn 1977, Fig. 7 \u2014 edge lit at {lights[light]['angle_deg']:g}\u00b0 "
                     f"from the eye: {verdict}\n"
                     + (fig_cfg["grazing"]["label"] if light == grazing
                        else f"variant: a {fig_cfg['object']['type']}")
                     + f"; Phong's p_s {reading.replace('_', ' ')}",
                     y=1 - 0.04 / H, va="top", linespacing=1.3)
        savefig(fig, png, dpi=DPI, tight=False, tag=display_tag(scene.display.space))

    # the caption's numbers (workflow/report/blinn77_fig7.rst), from the table as written
    written = pd.read_csv(out.csv).set_index(["panel", "phong_specular", "light"])
    at = {(panel, light): written.loc[(panel, "matched", light)]
          for panel in ("a", "b") for light in lights}

    def ratio(light):  # MgO's mirror-point highlight over aluminium's, under ``light``
        return f"{at['b', light].mirror_highlight / at['a', light].mirror_highlight:.2f}"

    # the lights the caption names (config.yaml's fig7.lights): the default figure's, the
    # variant's and the front light; each name written out, so that a reader finds it
    values = {"b_F0": f"{at['b', front].phong_s / at['b', front].p_s:.2f}",
              "crossover": f"{written.crossover_deg.iloc[0]:.1f}",
              "tangential_ratio": ratio("tangential"), "edge_ratio": ratio("edge"),
              "front_ratio": ratio(front),
              "a_ts_tangential": f"{at['a', 'tangential'].torrance_sparrow_max:.2f}",
              "b_ts_tangential": f"{at['b', 'tangential'].torrance_sparrow_max:.2f}",
              "a_ts_edge": f"{at['a', 'edge'].torrance_sparrow_max:.2f}",
              "b_ts_edge": f"{at['b', 'edge'].torrance_sparrow_max:.2f}",
              "phong_edge": f"{written.xs('edge', level='light').phong_max.max():.2f}",
              "difference_front": f"{max(at[p, front].max_abs_difference for p in 'ab'):.3f}"}
    if grazing in lights:  # the default figure: the grazing view's renders
        ts = {p: at[p, grazing].torrance_sparrow_max for p in "ab"}
        over = {p: ts[p] / at[p, grazing].mirror_highlight for p in "ab"}
        front_difference = max(at[p, definition.GRAZING + "front"].max_abs_difference for p in "ab")
        values.update({"a_ts_grazing": f"{ts['a']:.2f}", "b_ts_grazing": f"{ts['b']:.2f}",
                       "a_ts_grazing_over_mirror": f"{over['a']:.2f}",
                       "b_ts_grazing_over_mirror": f"{over['b']:.2f}",
                       "grazing_ratio": f"{ts['b'] / ts['a']:.2f}",
                       "grazing_verdict": "holds" if ts["b"] > ts["a"] else "does not hold",
                       "grazing_white": f"{white:.1f}",
                       "a_profile_peak": f"{profile_peaks[grazing, 'a']:.2f}",
                       "b_profile_peak": f"{profile_peaks[grazing, 'b']:.2f}",
                       "phong_grazing": f"{max(at[p, grazing].phong_max for p in 'ab'):.2f}",
                       "difference_grazing_front": f"{front_difference:.3f}"})
    write_caption_values(out.values, values)
