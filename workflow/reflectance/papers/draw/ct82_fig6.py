"""Cook & Torrance 1982, Fig. 6, drawn: the job of rule ``ct82_fig6``, called by its script,
``workflow/scripts/cook_torrance_1982_fig6.py`` (which says what the figure shows). What the job
reads, renders and writes is declared in :mod:`reflectance.papers.figures.ct82_fig6`."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy, tristimulus_weights, white_XYZ
from reflectance.colour.display import display_tag
from reflectance.io.cache import TRACES
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.optics.spectra import load_material
from reflectance.papers.figures import ct82_fig6 as definition
from reflectance.render.composite import appearance, covered_rows
from reflectance.render.pipeline import display_image, render, render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.render.shading import ambient_intensity
from reflectance.io.tables import write_csv
from reflectance.scripting import params_dict

__all__ = ["run"]

TITLES = {"a": "(a) copper-coloured plastic vase", "b": "(b) copper vase"}
#: a display variant's title: how its linear RGB became the PNG's codes (scene display.transfer)
DISPLAYS = {"display": "the linear RGB encoded by the display's transfer function",
            "none": "the linear RGB written as the codes, without gamma correction\n(not the "
                    "paper's pipeline, which corrected for the monitor: a contrast)"}
READINGS = {"intensity": "ambient as printed: I_ia = {f} I_i",
            "irradiance": "ambient = {f} of the lights' irradiance: I_ia = {f} \u03a3 I_i d\u03c9_i / \u03c0",
            "weighted": "ambient = {f} of the lights as they enter the model: I_ia = {f} \u03a3 I_i d\u03c9_i"}


def departure_text(change):
    return ", ".join(f"{k} = {v:g}" for k, v in change.items())


def title_of(item, fig_cfg, printed_name):
    """The panel's title: a departed panel says what it changes, what the paper prints and
    which figure shows the panel as printed (``printed_name``, a variant's file suffix)."""
    part, departure = item.tags["part"], item.tags["departure"]
    if departure is None:
        return TITLES[part]
    printed = {k: fig_cfg["panels"][part][k] for k in departure}
    where = f", fig6_{printed_name}" if printed_name else ""
    return (f"{TITLES[part]}\nnot as printed: {departure_text(departure)}\n"
            f"(printed {departure_text(printed)}{where})")


def variant(snakemake, log, out, reference, published, items):
    """One variant of the figure (its scenes ``items``): panels, table and figure to ``out``."""
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    spectra_dir = str(Path(snakemake.input.spectra[0]).parent)
    printed_name = (published or {}).get("printed_variant")
    renders = [(item.tags["part"], title_of(item, fig_cfg, printed_name), item.tags["panel"],
                item.written, item) for item in items]
    rows, images, covered = [], [], []
    for part, title, panel, written, item in renders:
        scene = scene_from_dict(item.document, source=f"config.yaml figures.cook_torrance_1982.fig6 "
                                                      f"panel {part}")
        result = (render_to_files(scene, out[f"{part}_scene"], out[f"{part}_exr"],
                                  out[f"{part}_png"], components=True, keep_trace=True)
                  if written else render(scene, components=True, keep_trace=True))
        rgb, scale = result.display or display_image(result)  # as written, or not written
        if written:  # a departed panel as printed is in the table, not the figure
            images.append((title, rgb)), covered.append(result.XYZ)
        Y = {name: value[..., 1] for name, value in result.components.items()}
        direct = Y["diffuse"] + Y["specular"]
        I_ia = ambient_intensity(scene.ambient, scene.lights)
        energies = [light.intensity * light.solid_angle for light in scene.lights]
        W = tristimulus_weights(scene.wavelengths, colour_cfg["illuminant"], scene.observer)
        F0 = load_material(panel["material"], scene.wavelengths, spectra_dir).F0 @ W
        rows.append({
            "panel": part, "written": written, "s": panel["s"], "d": panel["d"],
            "ambient_reference": reference, "I_ia": I_ia,
            "ambient_Y": Y["ambient"].max(), "diffuse_Y_max": Y["diffuse"].max(),
            "specular_Y_max": Y["specular"].max(), "direct_Y_max": direct.max(),
            "specular_over_diffuse_peak": (Y["specular"].max() / Y["diffuse"].max()
                                           if Y["diffuse"].max() > 0 else np.nan),
            "ambient_over_direct_max": Y["ambient"].max() / direct.max(),
            # Cook & Torrance 1982: I_ia R_a over R_d I_i (N.L) d omega_i at N.L = 1, R_a = pi R_d
            "ambient_over_headon_diffuse_weakest_light": np.pi * I_ia / min(energies),
            "ambient_over_headon_diffuse_all_lights": np.pi * I_ia / sum(energies),
            "exposure_scale": scale, "F0_X": F0[0], "F0_Y": F0[1], "F0_Z": F0[2],
            **appearance(rgb, result.XYZ, colour_cfg["space"]),
        })
        log.info("panel %s (%s): %s; timings %s", part, title, rows[-1], result.timings)
    pd.DataFrame(rows).pipe(write_csv, out["csv"], float_format="%.6g")

    # drawn at the print width (the renders pixel for pixel at dpi), the empty rows cropped
    crop = covered_rows(covered, margin=8)
    height, width = images[0][1][crop].shape[:2]
    lines = max(label.count("\n") + 1 for label, _ in images)
    # one line; the default figure's reading and exposure are its caption's (issue 28)
    title = "Cook & Torrance 1982, Fig. 6"
    if published and published.get("variant"):
        title += f" \u2014 {DISPLAYS[published['exposure'].get('transfer', 'display')]}"
    if published and published.get("printed"):
        title += " \u2014 the panels as printed"
    if not published:
        reading = READINGS[reference].format(f=f"{fig_cfg['ambient_fraction']:g}")
        title += f" \u2014 {reading}".replace(": I_ia", ":\nI_ia")
    n, margin, head = len(images), 0.1, 0.1 + 0.16 * lines  # inches
    top = 0.1 + 0.19 * (title.count("\n") + 1)
    dpi = n * width / (PRINT_WIDTH_IN - 2 * margin)
    W, H = PRINT_WIDTH_IN, height / dpi + head + top
    fig = new_figure(W, H, facecolor="black")
    for k, (label, rgb) in enumerate(images):
        ax = fig.add_axes(((margin + k * width / dpi) / W, 0.02 / H, width / dpi / W,
                           height / dpi / H))
        ax.imshow(rgb[crop], interpolation="nearest")
        ax.set_axis_off()
        ax.set_title(label, color="white", fontsize=TEXT_SIZE["annotation"], linespacing=1.2,
                     pad=4)
    fig.suptitle(title, color="white", fontsize=TEXT_SIZE["symbol"], y=1 - 0.04 / H, va="top",
                 linespacing=1.3)
    savefig(fig, out["png"], dpi=dpi, tag=display_tag(scene.display.space))


def run(snakemake: Any, log: logging.Logger) -> None:
    """Render both panels of every variant of the figure (the default figure, then each reading
    of the ambient term), write each variant's table and figure, and the captions' values:
    ``snakemake`` is the rule's job (its params, input and output), ``log`` its log."""
    # the variants' panels share vase, camera and lights: traced once (keep_trace)
    # the default figure (if params.published; unprefixed outputs), then each reading
    params = params_dict(snakemake.params)
    variants = definition.variants(params)
    scenes = definition.scenes(params, str(Path(snakemake.input.spectra[0]).parent))
    for prefix, reference, published in variants:
        log.info("variant %s (ambient reference %s)", prefix.rstrip("_") or "published", reference)
        variant(snakemake, log, {key: getattr(snakemake.output, prefix + key) for key in definition.FILES},
                reference, published,
                [item for item in scenes if item.tags["prefix"] == prefix])
    log.info("%d distinct traces for %d variants", len(TRACES), len(variants))


    # the captions' numbers (workflow/report/ct82_fig6_*.rst), from each variant's table as
    # written; per panel its first row is Fig. 6a as printed, its last as the default figure shows it
    values = {}
    colour_cfg = snakemake.params.colour
    for prefix, reference, published in variants:
        if published and published.get("printed"):  # its panels are the default's as printed
            continue
        table = pd.read_csv(getattr(snakemake.output, prefix + "csv"))
        first = table.drop_duplicates("panel").set_index("panel")
        a, b = first.loc["a"], first.loc["b"]
        if published and published.get("variant"):  # the default figure, shown otherwise:
            # (a) as printed and (b) as its PNG shows them: (a)'s body (median L*, C*, hue) and
            # highlight C*, (b)'s highlight C* and hue, its share at or above 20/255 and at 255
            values.update({
                "variant_a_body_C": f"{a.body_chroma:.1f}",
                "variant_a_body_hue": f"{a.body_hue_deg:.1f}", "variant_a_body_L": f"{a.L50:.0f}",
                "variant_a_highlight_C": f"{a.body_chroma * a.highlight_chroma_ratio:.1f}",
                "variant_b_highlight_C": f"{b.body_chroma * b.highlight_chroma_ratio:.1f}",
                "variant_b_hue": f"{b.highlight_hue_deg:.1f}",
                "variant_b_visible": f"{100 * b.visible:.0f}",
                "variant_b_clipped": f"{100 * b.clipped:.1f}"})
        elif published:
            a_shown = table.drop_duplicates("panel", keep="last").set_index("panel").loc["a"]
            white = XYZ_to_xy(white_XYZ(colour_cfg["illuminant"], colour_cfg["observer"]))
            _, F0_a, F0_b = XYZ_to_Lab(b[["F0_X", "F0_Y", "F0_Z"]].to_numpy(float), white)
            values.update({
                "ambient_headon": f"{100 * b.ambient_over_headon_diffuse_all_lights:.1f}",
                "ambient_highlight": f"{100 * b.ambient_over_direct_max:.2f}",
                "b_hue": f"{b.highlight_hue_deg:.1f}",
                "Cu_F0_hue": f"{np.degrees(np.arctan2(F0_b, F0_a)) % 360:.1f}",
                "a_F0": f"{a.F0_Y:.3f}", "a_peak_ratio": f"{a.specular_over_diffuse_peak:.2f}",
                "a_chroma": f"{a.highlight_chroma_ratio:.2f}", "a_body_L": f"{a.L50:.0f}",
                "a_body_C": f"{a.body_chroma:.1f}", "a_body_hue": f"{a.body_hue_deg:.1f}",
                "a_highlight_C": f"{a.body_chroma * a.highlight_chroma_ratio:.1f}",
                "b_highlight_C": f"{b.body_chroma * b.highlight_chroma_ratio:.1f}",
                "a_shown_chroma": f"{a_shown.highlight_chroma_ratio:.2f}",
                "b_clipped": f"{100 * b.clipped:.1f}", "b_visible": f"{100 * b.visible:.0f}"})
        elif reference == "intensity":
            values.update({
                "intensity_ambient": f"{a.ambient_over_headon_diffuse_weakest_light:.0f}",
                "intensity_over_peak": f"{b.ambient_over_direct_max:.1f}"})
        elif reference == "irradiance":
            values.update({"irradiance_b_visible": f"{100 * b.visible:.0f}",
                           "irradiance_a_chroma": f"{a.highlight_chroma_ratio:.2f}"})
    write_caption_values(snakemake.output.values, values)
