"""Cook & Torrance 1982, Fig. 6: (a) a copper-coloured plastic vase, (b) a copper vase.

One job writes the default figure (``fig6.published``: the reading that gives the published look,
metered, with Fig. 6a's labelled departure in place of its printed panel), the same with the panels
as printed (``published.printed_variant``), its display variant, and one figure per reading of
the ambient term (``fig6.ambient_readings``), its outputs prefixed ``<reading>_``.
"""

from __future__ import annotations

from reflectance.papers.figures.declaration import FigureScene
from reflectance.papers.scenes import panel_material, vase_scene_CookTorrance1982

RULE = "ct82_fig6"
OUT = "results/cook_torrance_1982"
_FIG6 = "figures.cook_torrance_1982.fig6"
PARAMS = {"fig": _FIG6, "reference": f"{_FIG6}.published.ambient_reference",
          "published": f"{_FIG6}.published", "readings": f"{_FIG6}.ambient_readings",
          "wavelengths": "wavelengths", "colour": "colour"}
#: one variant's files: {output name: file name, "{}" the variant's suffix}
FILES = {"png": "fig6{}.png", "csv": "fig6{}.csv",
         **{f"{panel}_{kind}": f"fig6{panel}{{}}.{ext}" for panel in "ab"
            for kind, ext in (("exr", "exr"), ("png", "png"), ("scene", "scene.yaml"))}}


def variants(params):
    """``[(output prefix, ambient reference, published settings or None), ...]``: the default
    figure first (unprefixed), then, if it departs from the print, the same with the departures
    undone (``printed_variant``, its settings' ``printed`` True), then each of its display
    variants (its exposure replaced, the settings' ``variant`` naming it), each prefixed
    ``<name>_``, then each reading of the ambient term, prefixed ``<reading>_`` (C&T Figs. 6
    and 7 alike)."""
    published = params["published"]
    default = [("", params["reference"], published)] if published else []
    # the default figure with its departures undone: the paper's panels as printed, its display
    if published and published.get("departures") and published.get("printed_variant"):
        default.append((f"{published['printed_variant']}_", params["reference"],
                        {**published, "departures": {}, "printed": True}))
    # the default figure again with another display (fig6.published.display_variant)
    shown = [(f"{v['name']}_", params["reference"],
              {**published, "exposure": v["exposure"], "panel_exposure": v.get("panel_exposure", {}),
               "variant": v["name"]})
             for v in [(published or {}).get("display_variant")] if v]
    return default + shown + [(f"{reading}_", reference, None)
                              for reading, reference in params["readings"].items()]


def panel_exposure(published, part):
    """The default figure's exposure of panel ``part``: its own (``published.panel_exposure``)
    or the shared one; None outside the default figure."""
    if not published:
        return None
    return published.get("panel_exposure", {}).get(part, published["exposure"])


def spectra(params):
    """Fig. 6's materials: each panel's F and R_d spectra (and any a departure names)."""
    panels = params["fig"]["panels"]
    departures = (params["published"] or {}).get("departures", {})
    specs = list(panels.values()) + [{**panels[p], **d} for p, d in departures.items()]
    return sorted({spec[key] for spec in specs for key in ("material", "diffuse_material")
                   if key in spec})


def outputs(params):
    out = {"values": f"{OUT}/fig6.values.rst"}  # the numbers its captions state
    for prefix, _, _ in variants(params):
        suffix = f"_{prefix[:-1]}" if prefix else ""
        out.update({f"{prefix}{key}": f"{OUT}/{name.format(suffix)}"
                    for key, name in FILES.items()})
    return out


def scenes(params, spectra_dir):
    """Per variant and panel: the vase; a departed panel of the default figure is rendered as
    printed too, for its table (only the departure is written, as ``<panel>_*``, and drawn)."""
    fig, files = params["fig"], outputs(params)
    out = []
    for prefix, reference, published in variants(params):
        departures = published.get("departures", {}) if published else {}
        for part, panel in fig["panels"].items():
            exposure = panel_exposure(published, part)
            shown = ([(panel, False, "as printed"), ({**panel, **departures[part]}, True, "")]
                     if part in departures else [(panel, True, "")])
            for spec, written, note in shown:
                document = vase_scene_CookTorrance1982(fig, panel_material(spec), reference,
                                                       params["wavelengths"], params["colour"],
                                                       spectra_dir, exposure=exposure)
                name = f"fig6{part}" + (f"_{prefix[:-1]}" if prefix else "") + (
                    f" {note}" if note else "")
                out.append(FigureScene(name, f"{_FIG6}.panels.{part}", document,
                                       files[f"{prefix}{part}_scene"] if written else None,
                                       {"prefix": prefix, "part": part, "panel": spec,
                                        "reference": reference, "published": published,
                                        "departure": departures.get(part) if written else None}))
    return out
