"""Wikipedia, "Specular highlight": the image "Specular highlights on a pair of spheres", rendered.
Two coloured plastic spheres (pigment reflectances recovered from Munsell notations; F of a
measured clear coat, so the highlights are white) with the article's Cook-Torrance model, one
directional light, a grey floor; C&T exposure (the brightest colour at the display maximum)."""

from pathlib import Path

import pandas as pd

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import display_tag
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, new_figure, savefig
from reflectance.render.pipeline import render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.figures import article_spheres as definition
from reflectance.scripting import params_dict, script_log
from reflectance.optics.spectra import DEFAULT_RECOVERY, load_material, wavelength_grid
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg, out, colour = snakemake.params.fig, snakemake.output, snakemake.params.colour
    pigments, w = snakemake.params.pigments, snakemake.params.wavelengths
    grid = wavelength_grid(w["start_nm"], w["end_nm"], w["step_nm"])
    folder = Path(snakemake.input.spectra[0]).parent  # spectra/: the clear coat and the pigments
    spheres, = definition.scenes(params_dict(snakemake.params), str(folder))  # as checked
    metal = cfg["metal_sphere"]  # the article: "on metallic materials such as gold ..."
    scene = scene_from_dict(spheres.document, source=f"config.yaml {spheres.source}")
    result = render_to_files(scene, out.scene, out.exr, out.render)
    image, scale = result.display  # Cook & Torrance exposure over all three spheres
    log.info("timings %s; exposure scale %.6g", result.timings, scale)

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
                 "m": metal["m"], "s": 1.0, "d": 0.0, "exposure_scale": scale})
    pd.DataFrame(rows).pipe(write_csv, out.csv, float_format="%.6g")

    # drawn at the printed width, the render pixel for pixel (dpi = pixels per printed inch)
    h_px, w_px = image.shape[:2]
    title_in, margin_in = 0.62, 0.04
    width_in = PRINT_WIDTH_IN
    image_h_in = width_in * h_px / w_px
    height_in = image_h_in + title_in + margin_in
    fig = new_figure(width_in, height_in)
    ax = fig.add_axes((0.0, margin_in / height_in, 1.0, image_h_in / height_in))
    ax.imshow(image, interpolation="nearest")
    ax.set_axis_off()
    names = ", ".join(pigments[s["diffuse_material"]]["notation"] for s in cfg["spheres"])
    fig.suptitle(f"Wikipedia, \u201cSpecular highlight\u201d: the article's pair of plastic spheres, "
                 f"a {metal['name']} one between them\n"
                 f"Cook\u2013Torrance D F G / (4 (V\u00b7N)(N\u00b7L)), Beckmann m = {cfg['m']:g}; "
                 f"clear coat F of {cfg['material']}\n"
                 f"pigments Munsell {names}; middle: {metal['material']}, exact F, "
                 f"m = {metal['m']:g} (s = 1, d = 0)",
                 size=STYLE["axes.titlesize"], y=1 - 0.03 / height_in, va="top", linespacing=1.3)
    savefig(fig, out.png, dpi=w_px / width_in, tight=False, tag=display_tag(scene.display.space))

    # the caption's numbers (workflow/report/article_spheres.rst), from the table as written
    written = pd.read_csv(out.csv).set_index("sphere")
    write_caption_values(out.values, {
        "metal_F0": f"{written.clear_coat_F0_Y[metal['name']]:.2f}",
        "coat_F0": f"{written.clear_coat_F0_Y[cfg['spheres'][0]['name']]:.3f}"})
