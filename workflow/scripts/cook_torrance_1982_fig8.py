"""Cook & Torrance 1982, Fig. 8: "A watch" (reflectance.watch), rendered spectrally under a single
light: gold case, bezel and outer band (links with a rougher interior than border), stainless-steel
inner band, a dark face and red LEDs of dominant wavelength 640 nm. Also tabulates each part's
material and what the image shows of it."""

from pathlib import Path

import numpy as np
import pandas as pd
import yaml

from reflectance.colorimetry import dominant_wavelength, tristimulus_weights
from reflectance.display import XYZ_to_linear_RGB, gamut_clip, linear_RGB_to_XYZ
from reflectance.io import atomic_write
from reflectance.plotting import new_figure, savefig
from reflectance.render import display_image, render, write_render
from reflectance.scene import scene_from_dict
from reflectance.scripting import script_log
from reflectance.spectra import load_material
from reflectance.visibility import visibility
from reflectance.watch import WATCH_PARTS


def over_pixels(values, statistic=np.nanmedian):
    """The statistic of a part's fully covered pixels (NaN if it covers none)."""
    return statistic(values) if np.size(values) else np.nan


def part_material(name, spec, fig6, table1):
    """A part of config fig8.parts as a scene material; ``table1: X`` takes Table I's row X."""
    if "table1" in spec:
        rows = {row["material"]: row for row in table1}
        if spec["table1"] not in rows:
            raise ValueError(f"config.yaml figures.cook_torrance_1982.fig8.parts.{name}.table1: "
                             f"{spec['table1']!r} is not a table1 row; known: {', '.join(rows)}")
        row = rows[spec["table1"]]
        spec = {"material": row["material"], "s": row["s"], "d": row["d"], "m": row["m"]}
    return {"name": spec["material"], "s": spec["s"], "d": spec["d"], "m": spec["m"],
            "distribution": fig6["distribution"], "convention": fig6["convention"],
            "fresnel": fig6["fresnel"], "shadowing": fig6["shadowing"]}


def scene_document(fig, fig6, table1, wavelengths, colour, spectra_dir):
    """The watch scene (workflow/schemas/scene.schema.yaml)."""
    light = fig["light"]
    led = fig["led"]
    parts = {name: part_material(name, spec, fig6, table1) for name, spec in fig["parts"].items()}
    # C&T 1982 Fig. 8: the LEDs' "color was approximated by using a color with the same dominant
    # wavelength"; luminance relative to a white Lambertian card facing the light (I d omega / pi)
    parts["led"] = {"model": "Lambert", "convention": "physical", "albedo": 0.0, "emission": {
        "dominant_wavelength_nm": led["dominant_wavelength_nm"], "purity": led["purity"],
        "luminance": led["luminance_factor"] * light["intensity"] * light["solid_angle"] / np.pi,
        "white": colour["illuminant"]}}
    return {"wavelengths": dict(wavelengths), "observer": colour["observer"],
            "spectra_dir": spectra_dir, "spectral": fig6["spectral"], "camera": dict(fig["camera"]),
            "objects": [{"name": "watch", "geometry": {"type": "watch", "parameters": fig["watch"]},
                         "material": parts["case"], "parts": parts}],
            "lights": [{"type": "directional", **light}],
            "ambient": {"fraction": fig6["ambient_fraction"],
                        "reference": fig6["ambient_readings"][fig["ambient_reading"]]},
            "display": {"space": colour["space"], "gamut_clip": colour["gamut_clip"],
                        "illuminant": colour["illuminant"],
                        "png_bit_depth": colour["png_bit_depth"]}}


with script_log(snakemake) as log:
    p, out = snakemake.params, snakemake.output
    colour_cfg = p.colour
    spectra_dir = str(Path(snakemake.input.spectra[0]).parent)
    document = scene_document(p.fig, p.fig6, p.table1, p.wavelengths, colour_cfg, spectra_dir)
    scene = scene_from_dict(document, source="config.yaml figures.cook_torrance_1982.fig8")
    with atomic_write(out.scene) as tmp:
        Path(tmp).write_text(yaml.safe_dump(scene.document, sort_keys=False))
    result = render(scene)
    write_render(result, out.exr, out.render_png)
    rgb, scale = display_image(result)
    log.info("render %s, exposure scale %.6g", result.timings, scale)

    # what each pixel shows: the fraction of its samples on each part; the colour it is shown in
    samples = visibility(scene.mesh, scene.camera)
    code = np.where(samples.hit, scene.mesh.cell_data["part"][np.maximum(samples.triangle, 0)], -1)
    display = dict(illuminant=colour_cfg["illuminant"], observer=scene.observer,
                   wavelengths=scene.wavelengths)
    shown = linear_RGB_to_XYZ(gamut_clip(XYZ_to_linear_RGB(result.XYZ * scale, colour_cfg["space"],
                                                           **display),
                                         colour_cfg["gamut_clip"], colour_cfg["space"]),
                              colour_cfg["space"], **display)
    W = tristimulus_weights(scene.wavelengths, colour_cfg["illuminant"], scene.observer)
    rows = []
    for part, number in WATCH_PARTS.items():
        spec = document["objects"][0]["parts"][part]
        full = samples.to_pixels((code == number).astype(float)) == 1.0
        F0 = load_material(spec["name"], scene.wavelengths, spectra_dir).F0 @ W \
            if "name" in spec else np.full(3, np.nan)
        wl_scene = dominant_wavelength(result.XYZ[full], **display)[0]
        wl_shown, purity = dominant_wavelength(shown[full], **display)
        rows.append({"part": part, "material": spec.get("name", ""), "model": spec.get(
                         "model", "CookTorrance1982"), "s": spec.get("s", 0.0),
                     "d": spec.get("d", 1.0), "m": spec.get("m", np.nan),
                     "F0_x": F0[0] / F0.sum(), "F0_y": F0[1] / F0.sum(), "F0_Y": F0[1],
                     "emission_Y": spec.get("emission", {}).get("luminance", 0.0),
                     "emission_dominant_wavelength_nm": spec.get("emission", {}).get(
                         "dominant_wavelength_nm", np.nan),
                     "pixels": samples.to_pixels((code == number).astype(float)).sum(),
                     "full_pixels": int(full.sum()),
                     "mean_Y": over_pixels(result.XYZ[full][:, 1], np.mean),
                     "dominant_wavelength_scene_nm": over_pixels(wl_scene),
                     "dominant_wavelength_shown_nm": over_pixels(wl_shown),
                     "purity_shown": over_pixels(purity),
                     "exposure_scale": scale})
        log.info("%s", rows[-1])
    pd.DataFrame(rows).to_csv(out.csv, index=False, float_format="%.6g", lineterminator="\n")

    height, width = rgb.shape[:2]
    fig = new_figure(width / 100, height / 100 + 0.45, facecolor="black")
    ax = fig.add_axes((0, 0, 1, height / (height + 45)))
    ax.imshow(rgb, interpolation="nearest")
    ax.set_axis_off()
    fig.suptitle(f"Cook & Torrance 1982, Fig. 8 \u2014 a watch: gold, stainless steel, "
                 f"{p.fig['led']['dominant_wavelength_nm']:g} nm LEDs",
                 color="white", fontsize=10, y=1 - 0.12 / (height / 100 + 0.45))
    savefig(fig, out.png, dpi=100)
