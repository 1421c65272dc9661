"""Blinn 1977, Fig. 8, drawn: the job of rule ``blinn77_fig8``, called by its script,
``workflow/scripts/blinn_1977_fig8.py`` (which says what the figure shows). What the job reads,
renders and writes is declared in :mod:`reflectance.papers.figures.blinn77_fig8`."""

from __future__ import annotations

import json
import logging
from typing import Any

import numpy as np
import pandas as pd

from reflectance.colour.display import compress_highlights, display_tag, encode
from reflectance.io.captions import write_caption_values
from reflectance.optics.microfacet import c3_texture_Blinn1977, c3_to_beta_Blinn1977
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.render.pipeline import render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.figures import blinn77_fig8 as definition
from reflectance.scripting import params_dict
from reflectance.geometry.texture import texture
from reflectance.io.tables import write_csv

__all__ = ["run"]


def run(snakemake: Any, log: logging.Logger) -> None:
    """Render the object once per texture pattern, tabulate each C3 map and render, draw the
    figure and write the caption's values: ``snakemake`` is the rule's job (its params and
    output), ``log`` its log."""
    params = params_dict(snakemake.params)
    cfg, fig7, out = params["fig"], params["fig7"], snakemake.output
    u, v = np.meshgrid(np.linspace(0, 1, 721), np.linspace(0, 1, 201))
    images, maps, rows = {}, {}, []
    # both patterns on one object, camera and light: traced once (keep_trace)
    for item in definition.scenes(params):  # the scenes the config check validated
        part = item.tags["pattern"]
        pattern = cfg["patterns"][part]
        scene = scene_from_dict(item.document,
                                source=f"config.yaml figures.blinn_1977.fig8 pattern {part}")
        result = render_to_files(scene, out[f"{part}_scene"], out[f"{part}_exr"],
                                 out[f"{part}_png"], keep_trace=True)
        images[part] = result.XYZ[..., 1]
        # Blinn 1977, C3 = C_min + (1 - C_min) t(u, v)
        maps[part] = c3_texture_Blinn1977(texture(u, v, pattern["method"], **pattern["parameters"]),
                                          cfg["c_min"])
        Y = result.XYZ[..., 1]
        rows.append({"pattern": part, "method": pattern["method"],
                     "parameters": json.dumps(pattern["parameters"], sort_keys=True),
                     "c_min": cfg["c_min"], "C3_min_on_map": maps[part].min(),
                     "C3_max_on_map": maps[part].max(), "max_i": Y.max(), "mean_i": Y[Y > 0].mean()})
        log.info("pattern %s: %s; timings %s", part, rows[-1], result.timings)
    # one exposure for both renders: white = their brightest i, compressed above fig8.highlight_knee
    white = max(Y.max() for Y in images.values())
    images = {part: encode(compress_highlights(np.repeat(Y[..., None], 3, -1) / white,
                                               cfg["highlight_knee"]), scene.display.space)
              for part, Y in images.items()}
    for row in rows:
        row["white_i"] = white
    pd.DataFrame(rows).pipe(write_csv, out.csv, float_format="%.6g")

    # drawn at the print width (the renders pixel for pixel at DPI): its text prints at its size
    left, gap, T = 0.45, 0.3, TEXT_SIZE
    DPI = 2 * images["a"].shape[1] / (PRINT_WIDTH_IN - left - gap - 0.15)
    h, w = (n / DPI for n in images["a"].shape[:2])  # inches
    mh, top = w / 3.6, 0.95
    W, H = left + 2 * w + gap + 0.15, top + h + mh + 0.85
    fig = new_figure(W, H)
    for k, part in enumerate(("a", "b")):
        pattern, x = cfg["patterns"][part], left + k * (w + gap)
        ax = fig.add_axes((x / W, (mh + 0.85) / H, w / W, h / H))
        ax.imshow(images[part], interpolation="nearest")
        ax.set_xticks([]), ax.set_yticks([])
        # the reader's words (config title), not the texture function's keyword names
        ax.set_title(f"({part}) " + pattern["title"].format(**pattern["parameters"]),
                     fontsize=T["annotation"], pad=3)
        ax = fig.add_axes((x / W, 0.4 / H, w / W, mh / H))
        ax.imshow(maps[part], cmap="gray", vmin=cfg["c_min"], vmax=1, origin="lower", extent=(0, 1, 0, 1),
                  aspect="auto", interpolation="antialiased")
        ax.set(xticks=[0, 0.5, 1], yticks=[0, 1])
        ax.set_xlabel("u (around the ring)", fontsize=T["annotation"], labelpad=1)
        ax.set_ylabel("v (tube)", fontsize=T["annotation"], labelpad=1)
        ax.set_title(f"C3(u, v): {cfg['c_min']:g} (black, shiny) to 1 (white, dull)",
                     fontsize=T["annotation"], pad=2)
    fig.suptitle(f"Blinn 1977, Fig. 8 \u2014 surface shininess varying with two texture patterns\n"
                 f"Torrance-Sparrow, D3 with C3 = C_min + (1 \u2212 C_min) t(u, v), C_min = {cfg['c_min']:g}\n"
                 f"p_s = {cfg['p_s']:g}, p_d = {cfg['p_d']:g}, n = {snakemake.params.n:g}, "
                 f"p_a = {fig7['p_a']:g}; light {cfg['light']['angle_deg']:g}\u00b0 from the eye; "
                 f"white i = {white:.2f}, knee {cfg['highlight_knee']:g}",
                 fontsize=T["symbol"], y=1 - 0.05 / H, va="top", linespacing=1.3)
    savefig(fig, out.png, dpi=DPI, tight=False, tag=display_tag(scene.display.space))

    # the caption's numbers (workflow/report/blinn77_fig8.rst): the shiny parts' half-value angle
    # (C3 = C_min, the table's least C3)
    written = pd.read_csv(out.csv)
    write_caption_values(out.values, {
        "shiny_beta": f"{np.degrees(c3_to_beta_Blinn1977(written.C3_min_on_map.min())):.1f}",
        "white_i": f"{written.white_i.iloc[0]:.2f}"})
