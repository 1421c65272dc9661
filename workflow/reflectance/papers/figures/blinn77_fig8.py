"""Blinn 1977, Fig. 8: "surface shininess varying as a function of two different texture patterns".

Fig. 7's object, camera and ambient; Blinn's Torrance-Sparrow model with D3 whose C3 follows each
pattern of ``fig8.patterns``; F from the index of the Fig. 7 panel ``fig8.panel`` names.
"""

from __future__ import annotations

from reflectance.papers.figures.declaration import FigureScene, config_value
from reflectance.papers.scenes import blinn_scene_Blinn1977, texture_material_Blinn1977

RULE = "blinn77_fig8"
OUT = "results/blinn_1977"
_FIG7 = "figures.blinn_1977.fig7"


def PARAMS(config):
    """Fig. 8, Fig. 7's object, camera and p_a, and the index n of the panel Fig. 8 names."""
    panel = config_value(config, "figures.blinn_1977.fig8.panel")
    return {"fig": "figures.blinn_1977.fig8",
            "fig7": tuple(f"{_FIG7}.{key}" for key in ("object", "camera", "p_a")),
            "n": f"{_FIG7}.panels.{panel}.n", "wavelengths": "wavelengths"}


def spectra(params):
    """Blinn's material is an index and constants: no spectrum file."""
    return []


def outputs(params):
    out = {"png": f"{OUT}/fig8.png", "csv": f"{OUT}/fig8.csv", "values": f"{OUT}/fig8.values.rst"}
    for part in params["fig"]["patterns"]:
        out.update({f"{part}_{kind}": f"{OUT}/fig8{part}.{ext}"
                    for kind, ext in (("exr", "exr"), ("png", "png"), ("scene", "scene.yaml"))})
    return out


def scenes(params, spectra_dir=None):
    """One written scene per pattern (its outputs ``<pattern>_scene``, ``_exr``, ``_png``)."""
    fig, n, files = params["fig"], params["n"], outputs(params)
    cam = params["fig7"]["camera"]  # fig7's camera, fig8.width pixels across at its aspect
    camera = dict(cam, width=fig["width"], height=round(fig["width"] * cam["height"] / cam["width"]))
    return [FigureScene(f"fig8{part}", f"figures.blinn_1977.fig8.patterns.{part}",
                        blinn_scene_Blinn1977(params["fig7"],
                                              texture_material_Blinn1977(fig, pattern, n),
                                              fig["light"], params["wavelengths"], camera),
                        files[f"{part}_scene"], {"pattern": part})
            for part, pattern in fig["patterns"].items()]
