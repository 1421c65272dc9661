"""Blinn 1977, Fig. 7: an object with Phong's and the Torrance-Sparrow highlight under each light.

Panels (a) aluminium and (b) magnesium oxide with Blinn's measured parameters; one figure per
reading of Phong's p_s; one row of renders per light of ``fig7.lights`` (Blinn: edge lit and
front lit), and a close-up of the highlight of ``fig7.rim_closeup.light``'s renders. The default
figure shows ``fig7.grazing``'s object and eye instead: a face seen and lit at grazing angles,
under ``grazing.light`` and the front light (render lights ``grazing_edge``, ``grazing_front``).
"""

from __future__ import annotations

from reflectance.papers.figures.declaration import FigureScene
from reflectance.papers.scenes import blinn_scene_Blinn1977, materials_Blinn1977, rim_camera_Blinn1977

RULE = "blinn77_fig7"
OUT = "results/blinn_1977"
PARAMS = {"fig": "figures.blinn_1977.fig7", "wavelengths": "wavelengths"}
MODELS = ("phong", "torrance_sparrow")
GRAZING = "grazing_"  # the grazing view's render lights' prefix (config light names have no _)


def spectra(params):
    """Blinn's materials are indices and constants: no spectrum file."""
    return []


def render_key(panel, model, light, reading):
    """The key of one written render; Torrance-Sparrow's do not depend on Phong's reading."""
    if model == "torrance_sparrow":
        return f"{panel}_torrance_sparrow_{light}"
    return f"{panel}_phong_{light}_{reading}"


def lights(fig):
    """{render light: {angle_deg, azimuth_deg}}: ``fig7.lights`` (the torus's), then, with
    ``fig7.grazing``, its light and the front light on the grazing view (``grazing_edge``,
    ``grazing_front``)."""
    out = dict(fig["lights"])
    if "grazing" in fig:
        out.update({f"{GRAZING}edge": fig["grazing"]["light"],
                    f"{GRAZING}front": fig["lights"][front_light(fig)]})
    return out


def view(fig, light):
    """fig7 with the object and camera the render under ``light`` sees: ``fig7.grazing``'s for the
    grazing view's lights, else fig7's own (the torus)."""
    if light.startswith(GRAZING):
        return {**fig, "object": fig["grazing"]["object"], "camera": fig["grazing"]["camera"]}
    return fig


def stems(params, folder=OUT):
    """{render key: output stem} of every written render (in ``folder``: the job's, the rule's
    outputs' folder)."""
    fig = params["fig"]
    return {key: f"{folder}/fig7{key}" for key in dict.fromkeys(
        render_key(panel, model, light, reading)
        for panel in fig["panels"] for light in lights(fig)
        for model in reversed(MODELS) for reading in fig["phong_specular_readings"])}


def front_light(fig):
    """The light drawn as one image (``front_lit``; Blinn: "Both Models Essentially Same")."""
    name = fig["front_lit"]
    if name not in fig["lights"]:
        raise ValueError(f"config.yaml figures.blinn_1977.fig7.front_lit: {name!r} is not a "
                         f"light; known: {', '.join(fig['lights'])}")
    return name


def figures(fig, folder=OUT):
    """{(reading, light): PNG} of every figure: Blinn's layout (Phong and Torrance-Sparrow under
    ``light``, one image under the front light) per reading of Phong's p_s and edge light. The
    default figure ``fig7_<reading>.png`` is the grazing view's (``grazing_edge``; without
    ``fig7.grazing``, the first light of ``fig7.lights`` but the front light); each other light of
    ``fig7.lights`` but the front light gives the variant ``fig7_<reading>_<light>.png``."""
    front = front_light(fig)
    edges = [name for name in fig["lights"] if name != front]
    if "grazing" in fig:
        edges.insert(0, f"{GRAZING}edge")
    return {(r, light): f"{folder}/fig7_{r}{'' if k == 0 else '_' + light}.png"
            for r in fig["phong_specular_readings"] for k, light in enumerate(edges)}


def figure_front(fig, light):
    """The front light drawn under the figure of edge light ``light``: the same view's."""
    return f"{GRAZING}front" if light.startswith(GRAZING) else front_light(fig)


def outputs(params):
    fig = params["fig"]
    return {"figures": list(figures(fig).values()),
            "csv": f"{OUT}/fig7.csv", "values": f"{OUT}/fig7.values.rst",
            "renders": [f"{stem}.{ext}" for stem in stems(params).values()
                        for ext in ("exr", "png", "scene.yaml")]}


def rim_light(fig):
    """The name of the light whose highlight the close-up shows (``rim_closeup.light``)."""
    name = fig["rim_closeup"].get("light", "edge")
    if name not in fig["lights"]:
        raise ValueError(f"config.yaml figures.blinn_1977.fig7.rim_closeup.light: {name!r} is "
                         f"not a light; known: {', '.join(fig['lights'])}")
    return name


def scenes(params, spectra_dir=None, folder=OUT):
    """Every render: per panel, reading, light and model (written once per key, in ``folder``),
    and the close-up of each model's highlight under the close-up's light (rendered, not
    written)."""
    fig, w = params["fig"], params["wavelengths"]
    closeup = rim_light(fig)
    camera = rim_camera_Blinn1977(fig, fig["lights"][closeup])
    files = {key: f"{stem}.scene.yaml" for key, stem in stems(params, folder).items()}
    out, seen = [], set()
    for panel, p in fig["panels"].items():
        for reading in fig["phong_specular_readings"]:
            m = materials_Blinn1977(p["p_s"], p["p_d"], p["c3"], p["n"], reading)
            for light, direction in lights(fig).items():
                for model in MODELS:
                    key = render_key(panel, model, light, reading)
                    tags = {"key": key, "panel": panel, "reading": reading, "light": light,
                            "model": model}
                    if key not in seen:
                        seen.add(key)
                        out.append(FigureScene(f"fig7{key}", f"figures.blinn_1977.fig7.panels.{panel}",
                                               blinn_scene_Blinn1977(view(fig, light), m[model],
                                                                     direction, w),
                                               files[key], tags))
                    if light == closeup and f"fig7{key} close-up" not in seen:
                        seen.add(f"fig7{key} close-up")
                        out.append(FigureScene(f"fig7{key} close-up",
                                               "figures.blinn_1977.fig7.rim_closeup",
                                               blinn_scene_Blinn1977(fig, m[model],
                                                                     fig["lights"][light], w,
                                                                     camera),
                                               None, tags))
    return out
