"""Cook & Torrance 1982, Fig. 6: (a) a copper-coloured plastic vase, (b) a copper vase, rendered
spectrally (reflectance.render.pipeline) with the paper's parameters; the ambient term read as printed or as
1 % of the lights' irradiance (wildcard ``reading``). Also tabulates how large the ambient term is
against the direct light."""

from pathlib import Path

import numpy as np
import pandas as pd

from reflectance.io.figures import new_figure, savefig
from reflectance.render.pipeline import display_image, render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.papers.scenes import panel_material, vase_scene_CookTorrance1982
from reflectance.scripting import script_log
from reflectance.render.shading import ambient_intensity
from reflectance.io.tables import write_csv

TITLES = {"a": "(a) copper-coloured plastic vase", "b": "(b) copper vase"}
READINGS = {"intensity": "ambient as printed: I_ia = {f} I_i",
            "irradiance": "ambient = {f} of the lights' irradiance: I_ia = {f} \u03a3 I_i d\u03c9_i / \u03c0"}


with script_log(snakemake) as log:
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    reference, out = snakemake.params.reference, snakemake.output
    spectra_dir = str(Path(snakemake.input.spectra[0]).parent)
    rows, images = [], {}
    for part in ("a", "b"):
        document = vase_scene_CookTorrance1982(fig_cfg, panel_material(fig_cfg["panels"][part]),
                                               reference, snakemake.params.wavelengths,
                                               colour_cfg, spectra_dir)
        scene = scene_from_dict(document, source=f"config.yaml figures.cook_torrance_1982.fig6 "
                                                 f"panel {part}")
        result = render_to_files(scene, out[f"{part}_scene"], out[f"{part}_exr"],
                                 out[f"{part}_png"], components=True)
        images[part], scale = display_image(result)
        Y = {name: value[..., 1] for name, value in result.components.items()}
        direct = Y["diffuse"] + Y["specular"]
        I_ia = ambient_intensity(scene.ambient, scene.lights)
        energies = [light.intensity * light.solid_angle for light in scene.lights]
        rows.append({
            "panel": part, "ambient_reading": reference, "I_ia": I_ia,
            "ambient_Y": Y["ambient"].max(), "diffuse_Y_max": Y["diffuse"].max(),
            "specular_Y_max": Y["specular"].max(), "direct_Y_max": direct.max(),
            "ambient_over_direct_max": Y["ambient"].max() / direct.max(),
            # Cook & Torrance 1982: I_ia R_a over R_d I_i (N.L) d omega_i at N.L = 1, R_a = pi R_d
            "ambient_over_headon_diffuse_weakest_light": np.pi * I_ia / min(energies),
            "ambient_over_headon_diffuse_all_lights": np.pi * I_ia / sum(energies),
            "exposure_scale": scale,
        })
        log.info("panel %s (%s): %s; timings %s", part, reference, rows[-1], result.timings)
    pd.DataFrame(rows).pipe(write_csv, out.csv, float_format="%.6g")

    height, width = images["a"].shape[:2]
    fig = new_figure(2 * width / 100 + 0.4, height / 100 + 0.9, facecolor="black")
    for k, part in enumerate(("a", "b")):
        ax = fig.add_axes((0.02 + 0.49 * k, 0.02, 0.47, 0.84))
        ax.imshow(images[part], interpolation="nearest")
        ax.set_axis_off()
        ax.set_title(TITLES[part], color="white", fontsize=10)
    reading = READINGS[reference].format(f=f"{fig_cfg['ambient_fraction']:g}")
    fig.suptitle(f"Cook & Torrance 1982, Fig. 6 \u2014 {reading}", color="white", fontsize=11)
    savefig(fig, out.png, dpi=100)
