"""Blinn 1977, Fig. 7 as a movie: the light swept from the eye to behind the object.

Blinn: the effects "are apparent only during movie sequences". Fig. 7's object, camera, ambient
and panels, one scene per panel and model holding every frame's light.
"""

from __future__ import annotations

import numpy as np

from reflectance.papers.figures.declaration import FigureScene
from reflectance.papers.scenes import (blinn_scene_Blinn1977, materials_Blinn1977,
                                       sweep_camera_Blinn1977)

RULE = "blinn77_fig7_sweep"
OUT = "results/blinn_1977"
_FIG7 = "figures.blinn_1977.fig7"
PARAMS = {"sweep": "figures.blinn_1977.fig7_sweep",
          "fig7": tuple(f"{_FIG7}.{key}" for key in ("object", "camera", "p_a", "panels", "grazing")),
          "wavelengths": "wavelengths"}
MODELS = ("phong", "torrance_sparrow")


def spectra(params):
    """Blinn's materials are indices and constants: no spectrum file."""
    return []


def outputs(params):
    return {name: f"{OUT}/fig7_sweep.{ext}"
            for name, ext in (("gif", "gif"), ("contact", "png"), ("csv", "csv"),
                              ("values", "values.rst"))}


def frame_lights(sweep):
    """One directional light per frame, from ``angles_deg[0]`` to ``angles_deg[1]``."""
    angles = np.linspace(*sweep["angles_deg"], sweep["n_frames"])
    return [{"angle_deg": float(a), "azimuth_deg": sweep["azimuth_deg"]} for a in angles]


def seen(params):
    """fig7 with the object and eye the sweep shows (``fig7_sweep.view``): fig7's own (the torus)
    or ``fig7.grazing``'s (the default figure's flat bar, seen along its top face)."""
    fig7 = params["fig7"]
    if params["sweep"]["view"] == "grazing":
        return {**fig7, "object": fig7["grazing"]["object"], "camera": fig7["grazing"]["camera"]}
    return fig7


def scenes(params, spectra_dir=None):
    """One scene per panel and model; its lights are the frames' (rendered, not written)."""
    sweep, fig7, w = params["sweep"], seen(params), params["wavelengths"]
    camera, lights = sweep_camera_Blinn1977(fig7, sweep), frame_lights(sweep)
    out = []
    for key in sweep["panels"]:
        p = fig7["panels"][key]
        m = materials_Blinn1977(p["p_s"], p["p_d"], p["c3"], p["n"], sweep["phong_specular"])
        for model in MODELS:
            out.append(FigureScene(f"fig7_sweep (panel {key}, {model})",
                                   "figures.blinn_1977.fig7_sweep",
                                   blinn_scene_Blinn1977(fig7, m[model], lights, w, camera),
                                   None, {"panel": key, "model": model}))
    return out
