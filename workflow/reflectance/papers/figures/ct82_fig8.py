"""Cook & Torrance 1982, Fig. 8: "A watch", rendered spectrally under a single light.

Its parts' materials (``fig8.parts``, Table I rows by name), Fig. 6's renderer settings and
ambient fraction, and red LEDs of the dominant wavelength the text gives.
"""

from __future__ import annotations

from reflectance.papers.figures.declaration import FigureScene
from reflectance.papers.scenes import watch_scene_CookTorrance1982

RULE = "ct82_fig8"
OUT = "results/cook_torrance_1982"
_CT = "figures.cook_torrance_1982"
PARAMS = {"fig": f"{_CT}.fig8",
          "fig6": tuple(f"{_CT}.fig6.{key}" for key in (
              "distribution", "convention", "fresnel", "shadowing", "spectral",
              "ambient_fraction", "ambient_readings", "published.ambient_reference")),
          "table1": f"{_CT}.table1.rows", "wavelengths": "wavelengths", "colour": "colour"}


def spectra(params):
    """Each part's material (a Table I row names its material)."""
    rows = {row["material"]: row for row in params["table1"]}
    return sorted({spec.get("material", rows.get(spec.get("table1"), {}).get("material"))
                   for spec in params["fig"]["parts"].values()} - {None})


def outputs(params):
    return {"png": f"{OUT}/fig8.png", "csv": f"{OUT}/fig8.csv", "exr": f"{OUT}/fig8.exr",
            "render_png": f"{OUT}/fig8_render.png", "scene": f"{OUT}/fig8.scene.yaml",
            "values": f"{OUT}/fig8.values.rst"}


def scenes(params, spectra_dir):
    """The watch (written as ``scene``, ``exr``, ``render_png``)."""
    return [FigureScene("fig8", f"{_CT}.fig8", watch_scene_CookTorrance1982(
        params["fig"], params["fig6"], params["table1"], params["wavelengths"], params["colour"],
        spectra_dir), outputs(params)["scene"])]
