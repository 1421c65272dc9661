"""Wikipedia, "Specular highlight": the pair of spheres, drawn: the job of rule
``article_spheres``, called by its script, ``workflow/scripts/article_spheres.py`` (which says
what the figure shows). What the job reads, renders and writes is declared in
:mod:`reflectance.papers.figures.article_spheres`."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy, tristimulus_weights, white_XYZ
from reflectance.colour.display import display_tag
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, new_figure, savefig
from reflectance.render.composite import appearance
from reflectance.render.pipeline import render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.figures import article_spheres as definition
from reflectance.scripting import params_dict
from reflectance.optics.spectra import DEFAULT_RECOVERY, load_material, wavelength_grid
from reflectance.io.tables import write_csv

__all__ = ["run"]


def run(snakemake: Any, log: logging.Logger) -> None:
    """Render the pair of spheres and the gold sphere, tabulate each sphere's material, draw the
    figure and write the caption's values: ``snakemake`` is the rule's job (its params, input
    and output), ``log`` its log."""
    cfg, out, colour = snakemake.params.fig, snakemake.output, snakemake.params.colour
    pigments, w = snakemake.params.pigments, snakemake.params.wavelengths
    grid = wavelength_grid(w["start_nm"], w["end_nm"], w["step_nm"])
    folder = Path(snakemake.input.spectra[0]).parent  # spectra/: the clear coat and the pigments
    pair, gold = definition.scenes(params_dict(snakemake.params), str(folder))  # as checked
    metal = cfg["metal_sphere"]  # the article: "on metallic materials such as gold ..."
    results = {}
    for part, files in ((pair, (out.scene, out.exr, out.render)),
                        (gold, (out.gold_scene, out.gold_exr, out.gold_render))):
        scene = scene_from_dict(part.document, source=f"config.yaml {part.source}")
        results[part.tags["panel"]] = render_to_files(scene, *files)
        log.info("%s: timings %s; exposure scale %.6g", part.name,
                 results[part.tags["panel"]].timings, results[part.tags["panel"]].display[1])
    image, scale = results["pair"].display
    gold_image, gold_scale = results["metal"].display

    W = tristimulus_weights(grid, cfg["light"]["spectrum"], colour["observer"])
    F0_Y = load_material(cfg["material"], grid, folder).F0 @ W[:, 1] / W[:, 1].sum()
    rows = []
    for s in cfg["spheres"]:
        rho = load_material(s["diffuse_material"], grid, folder).F0  # the pigment reflectance
        X, Y, Z = rho @ W
        pigment = pigments[s["diffuse_material"]]
        rows.append({"sphere": s["name"], "munsell": pigment["notation"],
                     "recovery": pigment.get("recovery", DEFAULT_RECOVERY),
                     "albedo_Y": Y, "albedo_x": X / (X + Y + Z), "albedo_y": Y / (X + Y + Z),
                     "clear_coat": cfg["material"], "clear_coat_F0_Y": F0_Y, "m": cfg["m"],
                     "s": cfg["s"], "d": cfg["d"], "exposure_scale": scale})
    F0 = load_material(metal["material"], grid, folder).F0
    X, Y, Z = F0 @ W
    rows.append({"sphere": metal["name"], "munsell": "", "recovery": "", "albedo_Y": 0.0,
                 "albedo_x": float("nan"), "albedo_y": float("nan"), "clear_coat": metal["material"],
                 "clear_coat_F0_Y": Y / W[:, 1].sum(), "F0_x": X / (X + Y + Z), "F0_y": Y / (X + Y + Z),
                 "m": metal["m"], "s": 1.0, "d": 0.0, "exposure_scale": gold_scale})
    pd.DataFrame(rows).pipe(write_csv, out.csv, float_format="%.6g")

    # each sphere's highlight: the pixel of greatest luminance in its half of the pair's render
    # (the spheres lie either side of the camera's axis, x = look_at x: the config check's scene)
    Y = results["pair"].XYZ[..., 1]
    mid = Y.shape[1] // 2
    order = sorted(range(len(cfg["spheres"])), key=lambda i: cfg["spheres"][i]["center"][0])
    peaks = {}
    for i, cols in zip(order, (slice(0, mid), slice(mid, None))):
        half = Y[:, cols]
        r, c = np.unravel_index(np.argmax(half), half.shape)
        peaks[cfg["spheres"][i]["name"]] = tuple(int(round(255 * v)) for v in image[:, cols][r, c])

    # the spheres' pixels: the floor is spectrally flat under a D65 light and the sky black, so
    # theirs are the pixels with chroma (8/255 between channels); the gold sphere's highlight is
    # its pixels above half its peak luminance, its body the rest, as the caption measures them
    def chromatic(img):
        return (np.asarray(img).max(-1) - np.asarray(img).min(-1)) > 8 / 255

    sphere, Yg = chromatic(gold_image), results["metal"].XYZ[..., 1]
    bright = sphere & (Yg > 0.5 * Yg[sphere].max())
    body = np.percentile(Yg[sphere & ~bright], [10, 50])
    clipped = float(np.mean(np.round(255 * gold_image[sphere]).max(-1) >= 255))
    # how gold reads: its F0 in CIELAB under the light (L* of the F0 luminance, a white of Y = 1),
    # against the gold sphere as the PNG shows it (its pixels alone: the floor's XYZ set to 0)
    white = XYZ_to_xy(white_XYZ(cfg["light"]["spectrum"], colour["observer"]))
    F0_Lab = XYZ_to_Lab(F0 @ W / W[:, 1].sum(), white)
    shown = appearance(gold_image, np.where(sphere[..., None], results["metal"].XYZ, 0.0),
                       colour["space"])
    # the floor the gold sphere mirrors (reflectance.papers.scenes.ground_lights): the radiance
    # of its ground lights, the one nearest the horizon and the one nearest straight below
    ground = sorted((light["direction"][2], light["intensity"])
                    for light in gold.document["lights"] if not light.get("shadows", True))

    # the rows above the highest sphere cropped (floor or sky), leaving the gap between the panels
    gap_px = max(1, round(0.02 * image.shape[1]))
    rows = np.flatnonzero(chromatic(image).any(1) | sphere.any(1))
    top = max(0, int(rows[0]) - gap_px) if len(rows) else 0
    image, gold_image = image[top:], gold_image[top:]

    # drawn at the printed width, both renders pixel for pixel at one scale (dpi = pixels per
    # printed inch; the panels share the camera's height and field of view)
    h_px = image.shape[0]
    w_px = image.shape[1] + gap_px + gold_image.shape[1]
    title_in, label_in, margin_in = 0.26, 0.22, 0.04
    width_in = PRINT_WIDTH_IN
    image_h_in = width_in * h_px / w_px
    height_in = image_h_in + title_in + label_in + margin_in
    fig = new_figure(width_in, height_in)
    left = 0.0
    for img, label in ((image, "a pair of plastic spheres: clear coat over a pigment"),
                       (gold_image, f"{metal['name']}: the highlight takes the metal's colour")):
        w = img.shape[1] / w_px
        ax = fig.add_axes((left, margin_in / height_in, w, image_h_in / height_in))
        ax.imshow(img, interpolation="nearest")
        ax.set_axis_off()
        ax.set_title(label, size=STYLE["font.size"], pad=3)
        left += w + gap_px / w_px
    fig.suptitle("Wikipedia, \u201cSpecular highlight\u201d: a pair of spheres, rendered, and the "
                 "article's gold",
                 size=STYLE["axes.titlesize"], y=1 - 0.03 / height_in, va="top")
    savefig(fig, out.png, dpi=w_px / width_in, tight=False, tag=display_tag(results["pair"].scene.display.space))

    # the caption's numbers (workflow/report/article_spheres.rst), from the table as written
    written = pd.read_csv(out.csv).set_index("sphere")
    write_caption_values(out.values, {
        "metal_F0": f"{written.clear_coat_F0_Y[metal['name']]:.2f}",
        "coat_F0": f"{written.clear_coat_F0_Y[cfg['spheres'][0]['name']]:.3f}",
        "pair_scale": f"{scale:.3g}", "gold_scale": f"{gold_scale:.3g}",
        "gold_clipped": f"{100 * clipped:.1f}", "gold_body_spread": f"{body[1] / body[0]:.1f}",
        "cropped_rows": f"{top}",
        "gold_F0_L": f"{F0_Lab[0]:.0f}", "gold_F0_C": f"{np.hypot(*F0_Lab[1:]):.0f}",
        "gold_F0_hue": f"{np.degrees(np.arctan2(F0_Lab[2], F0_Lab[1])) % 360:.0f}",
        "gold_body_L": f"{shown['L50']:.0f}", "gold_body_C": f"{shown['body_chroma']:.0f}",
        "gold_body_hue": f"{shown['body_hue_deg']:.0f}",
        "gold_highlight_C": f"{shown['body_chroma'] * shown['highlight_chroma_ratio']:.0f}",
        "ground_radiance": f"{ground[-1][1]:.2g}" if ground else "none",
        "ground_contact": f"{ground[0][1]:.2g}" if ground else "none",
        "pair_peaks": "; ".join("({}, {}, {}) ".format(*rgb) + f"({name})"
                                for name, rgb in peaks.items())})
