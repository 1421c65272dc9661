"""Wikipedia, "Specular highlight": "Specular highlights on a pair of spheres", rendered.

Coloured plastic spheres (pigments recovered from Munsell notations, F of a measured clear coat)
with the article's Cook-Torrance model, the gold sphere of its metals, one light, a grey floor.
"""

from __future__ import annotations

from reflectance.papers.figures.declaration import FigureScene, config_value
from reflectance.papers.scenes import spheres_scene_article

RULE = "article_spheres"
OUT = "results/article"
_SPHERES = "figures.article.spheres"


def PARAMS(config):
    """The figure, and the materials entries (Munsell notation, recovery) of its pigments."""
    pigments = [s["diffuse_material"] for s in config_value(config, f"{_SPHERES}.spheres")]
    return {"fig": _SPHERES, "pigments": tuple(f"materials.{name}" for name in pigments),
            "wavelengths": "wavelengths", "colour": "colour"}


def spectra(params):
    fig = params["fig"]
    return [fig["material"], fig["metal_sphere"]["material"]] + [
        s["diffuse_material"] for s in fig["spheres"]]


def outputs(params):
    return {"png": f"{OUT}/spheres.png", "csv": f"{OUT}/spheres.csv", "exr": f"{OUT}/spheres.exr",
            "render": f"{OUT}/spheres_render.png", "scene": f"{OUT}/spheres.scene.yaml",
            "values": f"{OUT}/spheres.values.rst"}


def scenes(params, spectra_dir):
    """The spheres on their floor (written as ``scene``, ``exr``, ``render``)."""
    return [FigureScene("spheres", _SPHERES, spheres_scene_article(
        params["fig"], params["wavelengths"], params["colour"], spectra_dir),
        outputs(params)["scene"])]
