"""Cook & Torrance 1982, Fig. 8, drawn: the job of rule ``ct82_fig8``, called by its script,
``workflow/scripts/cook_torrance_1982_fig8.py`` (which says what the figure shows). What the job
reads, renders and writes is declared in :mod:`reflectance.papers.figures.ct82_fig8`."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import display_tag
from reflectance.render.composite import part_pixels
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import new_figure, savefig
from reflectance.render.pipeline import render_to_files
from reflectance.render.tracing import trace_once
from reflectance.render.scene import scene_from_dict
from reflectance.papers.figures import ct82_fig8 as definition
from reflectance.scripting import params_dict
from reflectance.optics.spectra import load_material
from reflectance.geometry.watch import WATCH_PARTS
from reflectance.io.tables import write_csv

__all__ = ["run"]


def run(snakemake: Any, log: logging.Logger) -> None:
    """Render the watch, tabulate what each part is and shows, draw the figure and write the
    caption's values: ``snakemake`` is the rule's job (its params, input and output), ``log``
    its log."""
    p, out = snakemake.params, snakemake.output
    colour_cfg = p.colour
    spectra_dir = str(Path(snakemake.input.spectra[0]).parent)
    watch, = definition.scenes(params_dict(p), spectra_dir)  # the scene the check validated
    scene = scene_from_dict(watch.document, source=f"config.yaml {watch.source}")
    # the render's camera samples, reused below (keep_trace)
    result = render_to_files(scene, out.scene, out.exr, out.render_png, keep_trace=True)
    rgb, scale = result.display
    log.info("render %s, exposure scale %.6g", result.timings, scale)

    # what each pixel shows: the fraction of its samples on each part; the colour it is shown in
    display = dict(illuminant=colour_cfg["illuminant"], observer=scene.observer,
                   wavelengths=scene.wavelengths)
    # every camera sample of the image: the render's own trace, or, for an image of several
    # bands (which keeps none), traced whole here
    samples, _, _ = trace_once(scene)
    stats = part_pixels(samples, scene.mesh.cell_data["part"],
                        result.XYZ, scale, colour_cfg["space"], colour_cfg["gamut_clip"], display)
    W = tristimulus_weights(scene.wavelengths, colour_cfg["illuminant"], scene.observer)
    rows = []
    for part, number in WATCH_PARTS.items():
        spec = watch.document["objects"][0]["parts"][part]
        F0 = load_material(spec["name"], scene.wavelengths, spectra_dir).F0 @ W \
            if "name" in spec else np.full(3, np.nan)
        emission = spec.get("emission", {})
        pixels = stats(number)
        rows.append({"part": part, "material": spec.get("name", ""),
                     "model": spec.get("model", "CookTorrance1982"), "s": spec.get("s", 0.0),
                     "d": spec.get("d", 1.0), "m": spec.get("m", np.nan),
                     "F0_x": F0[0] / F0.sum(), "F0_y": F0[1] / F0.sum(), "F0_Y": F0[1],
                     "emission_Y": emission.get("luminance", 0.0),
                     "emission_dominant_wavelength_nm": emission.get("dominant_wavelength_nm",
                                                                     np.nan),
                     **pixels, "exposure_scale": scale})
        log.info("%s", rows[-1])
    pd.DataFrame(rows).pipe(write_csv, out.csv, float_format="%.6g")

    height, width = rgb.shape[:2]
    fig = new_figure(width / 100, height / 100 + 0.45, facecolor="black")
    ax = fig.add_axes((0, 0, 1, height / (height + 45)))
    ax.imshow(rgb, interpolation="nearest")
    ax.set_axis_off()
    fig.suptitle(f"Cook & Torrance 1982, Fig. 8 \u2014 a watch: gold, stainless steel, "
                 f"{p.fig['led']['dominant_wavelength_nm']:g} nm LEDs",
                 color="white", fontsize=10, y=1 - 0.12 / (height / 100 + 0.45))
    savefig(fig, out.png, dpi=100, tag=display_tag(scene.display.space))

    # the caption's numbers (workflow/report/ct82_fig8.rst), from the table as written
    parts = pd.read_csv(out.csv).set_index("part")
    Y = parts.mean_Y
    write_caption_values(out.values, {
        "led_nm": f"{parts.dominant_wavelength_shown_nm.led:.0f}",
        "led_purity": f"{parts.purity_shown.led:.2f}",
        "case_nm": f"{parts.dominant_wavelength_shown_nm.case:.0f}",
        "case_purity": f"{parts.purity_shown.case:.2f}",
        "steel_purity": f"{parts.purity_shown.band_inner:.2f}",
        "border_over_inset": f"{Y.band_outer_border / Y.band_outer_interior:.2f}"})
