"""Cook & Torrance 1982, Fig. 7: "A variety of vases", rendered one at a time under Fig. 6's light.

The six metals with Fig. 6b's s, d and lobes, Table I's nonmetals, then labelled variants; the
default figure (each vase metered by its row's exposure) and one grid per reading of the ambient
term, its outputs prefixed ``<reading>_``.
"""

from __future__ import annotations

from reflectance.papers.figures.declaration import FigureScene
from reflectance.papers.figures import ct82_fig6
from reflectance.papers.scenes import (fig7_exposure_CookTorrance1982,
                                       fig7_vases_CookTorrance1982, vase_scene_CookTorrance1982)

RULE = "ct82_fig7"
OUT = "results/cook_torrance_1982"
_CT = "figures.cook_torrance_1982"
#: what of Fig. 6 a vase of Fig. 7 is rendered with ("the same parameters used for Figure 6b")
FIG6_RENDERING = tuple(f"{_CT}.fig6.{key}" for key in (
    "distribution", "convention", "fresnel", "shadowing", "spectral", "camera", "vase", "lights",
    "ambient_fraction", "panels.b"))
PARAMS = {"fig": f"{_CT}.fig7", "fig6": FIG6_RENDERING, "table1": f"{_CT}.table1.rows",
          "reference": f"{_CT}.fig6.published.ambient_reference",
          "published": (f"{_CT}.fig6.published.ambient_reference",),
          "readings": f"{_CT}.fig6.ambient_readings",
          "visible_nm": f"{_CT}.table1.average_F0_range_nm",
          "wavelengths": "wavelengths", "colour": "colour"}

#: the params of the RGB-rendering audit (audits.rgb_rendering), which renders Fig. 7's metal
#: vases as the default figure does (workflow/rules/audits.smk)
RGB_AUDIT_PARAMS = {"audit": "audits.rgb_rendering", "fig7": f"{_CT}.fig7",
                    "table1": f"{_CT}.table1.rows",
                    "fig6": FIG6_RENDERING + (f"{_CT}.fig6.published.ambient_reference",
                                              f"{_CT}.fig6.published.exposure"),
                    "wavelengths": "wavelengths", "colour": "colour"}


def variants(params):
    """Fig. 6's variants (the default figure, then each ambient reading), without Fig. 6's
    display and printed variants (``fig6.published.display_variant``, ``printed_variant``:
    Fig. 6's alone)."""
    return [v for v in ct82_fig6.variants(params)
            if not (v[2] or {}).get("variant") and not (v[2] or {}).get("printed")]


def vases(params):
    """The vases' ids, in the grid's order."""
    return [vase for vase, _, _ in fig7_vases_CookTorrance1982(params["fig"], params["fig6"],
                                                               params["table1"])]


def spectra(params):
    """Every vase's spectrum (a Table I row's own, or fig7.table1_spectra's) and sources.csv's
    labels are read; the materials here."""
    return sorted({material["name"] for _, _, material in fig7_vases_CookTorrance1982(
        params["fig"], params["fig6"], params["table1"])})


def outputs(params):
    out = {"values": f"{OUT}/fig7.values.rst"}  # the numbers its captions state
    for prefix, _, published in variants(params):
        stem = f"fig7_{prefix[:-1]}" if prefix else "fig7"
        out.update({f"{prefix}png": f"{OUT}/{stem}.png", f"{prefix}csv": f"{OUT}/{stem}.csv",
                    f"{prefix}exrs": [f"{OUT}/{stem}/{v}.exr" for v in vases(params)],
                    f"{prefix}scenes": [f"{OUT}/{stem}/{v}.scene.yaml" for v in vases(params)]})
        if published:  # the default figure alone writes each vase's PNG, and its variants
            out["pngs"] = [f"{OUT}/{stem}/{v}.png" for v in vases(params)]
            if params["fig"]["extras"]:  # apart from the paper's grid (issue 28)
                out["variants_png"] = f"{OUT}/{stem}_variants.png"
    return out


def scenes(params, spectra_dir):
    """Per variant, every vase (written as its ``<prefix>scenes``/``exrs`` entry)."""
    fig, files = params["fig"], outputs(params)
    out = []
    for prefix, reference, published in variants(params):
        for k, (vase, group, material) in enumerate(fig7_vases_CookTorrance1982(
                fig, params["fig6"], params["table1"])):
            exposure = fig7_exposure_CookTorrance1982(fig, vase, group) if published else None
            document = vase_scene_CookTorrance1982(params["fig6"], material, reference,
                                                   params["wavelengths"], params["colour"],
                                                   spectra_dir, fig["vase_image"],
                                                   exposure=exposure)
            stem = f"fig7_{prefix[:-1]}" if prefix else "fig7"
            out.append(FigureScene(f"{stem}/{vase}", f"{_CT}.fig7", document,
                                   files[f"{prefix}scenes"][k],
                                   {"prefix": prefix, "index": k, "vase": vase, "group": group,
                                    "material": material}))
    return out
