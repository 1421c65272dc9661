"""Wikipedia, "Specular highlight": "Specular highlights on a pair of spheres", rendered.

The pair of coloured plastic spheres (pigments recovered from Munsell notations, F of a measured
clear coat) with the article's Cook-Torrance model, one light, a grey floor; beside it, in its own
panel and exposed on its own, the gold sphere of the article's metals.
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
            "values": f"{OUT}/spheres.values.rst", "gold_exr": f"{OUT}/spheres_gold.exr",
            "gold_render": f"{OUT}/spheres_gold_render.png",
            "gold_scene": f"{OUT}/spheres_gold.scene.yaml"}


def scenes(params, spectra_dir):
    """The pair on its floor (written as ``scene``, ``exr``, ``render``), then the gold sphere on
    its own (``gold_scene``, ``gold_exr``, ``gold_render``)."""
    out = outputs(params)
    return [FigureScene(name, _SPHERES, spheres_scene_article(
        params["fig"], params["wavelengths"], params["colour"], spectra_dir, panel),
        out[file], {"panel": panel})
        for name, panel, file in (("spheres", "pair", "scene"), ("spheres_gold", "metal",
                                                                  "gold_scene"))]
