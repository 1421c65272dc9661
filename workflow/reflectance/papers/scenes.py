"""Scenes built from config.yaml's figure sections (the scene format of ``scene.schema.yaml``).

Every rendered figure turns a section of ``config.yaml`` into a scene mapping and writes it beside
its outputs (so that ``reflectance render`` re-renders it alone). The shared parts live here:

- :func:`scene_document`: camera, objects, lights, ambient and display -> a scene mapping;
  :func:`display_from_colour` the ``display`` of config ``colour``;
- :func:`vase_scene_CookTorrance1982`: one vase as Cook & Torrance 1982 Fig. 6 renders it (also
  Fig. 7's vases); :func:`fig6_scene_CookTorrance1982` a Fig. 6 panel straight from config.yaml
  (the default scene of ``reflectance bench``);
- :func:`light_direction`, :func:`materials_Blinn1977` and :func:`blinn_scene_Blinn1977`:
  Blinn 1977 Figs. 7 and 8;
- the per-figure pieces :func:`fig7_vases_CookTorrance1982`, :func:`watch_scene_CookTorrance1982`,
  :func:`texture_material_Blinn1977`, :func:`sweep_camera_Blinn1977` and
  :func:`spheres_scene_article`, from which the figure modules of :mod:`reflectance.papers.figures`
  build every scene of every rendered figure (what :mod:`reflectance.config` validates when the
  workflow is parsed, and what the jobs render).

Blinn's models are scalar: ``i = p_a + d p_d + s p_s`` with ``d = N.L``, Phong's ``s = (N.H)^c1``
or the Torrance-Sparrow ``s = D3 G F / (N.E)``, F the dielectric Fresnel reflectance of one index
``n`` (n = 200 for his aluminium, 1.8 for magnesium oxide): scene materials with
``index: {n: ..., k: 0}``. F is then the exact dielectric Fresnel reflectance, with the factor 1/2
that Blinn's printing lacks, at every wavelength; with a spectrally flat diffuse albedo of 1 a
white light gives a grey image whose luminance Y is Blinn's intensity i (a light of intensity 1
and solid angle 1 has Y = 1). How large Phong's specular proportion is has two readings
(:data:`PHONG_SPECULAR_READINGS`): Blinn prints one ``p_s`` for both models, but his
Torrance-Sparrow highlight carries F, which for MgO is 0.08 at normal incidence, and yet he calls
the front-lit images of both models "essentially same".

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (Figs. 7a, 7b, 8; D3; c1, c3 of beta.)
- Cook, R. L., & Torrance, K. E. (1982). A reflectance model for computer graphics. ACM
  Transactions on Graphics, 1(1), 7-24. (Figs. 6, 7.)
"""

from __future__ import annotations

import copy
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982
from reflectance.optics.microfacet import beta_to_c1_Blinn1977, c3_to_beta_Blinn1977
from reflectance.geometry.vectors import unit_vector
from reflectance.io.paths import package_data

__all__ = [
    "sky_dome_lights",
    "ground_lights",
    "CONFIG_PATH",
    "PHONG_SPECULAR_READINGS",
    "display_from_colour",
    "scene_document",
    "panel_material",
    "vase_scene_CookTorrance1982",
    "fig6_scene_CookTorrance1982",
    "light_direction",
    "materials_Blinn1977",
    "mirror_highlight_Blinn1977",
    "highlight_crossover_Blinn1977",
    "blinn_scene_Blinn1977",
    "rim_camera_Blinn1977",
    "table1_material",
    "fig7_vases_CookTorrance1982",
    "fig7_exposure_CookTorrance1982",
    "watch_part_material",
    "watch_scene_CookTorrance1982",
    "texture_material_Blinn1977",
    "sweep_camera_Blinn1977",
    "spheres_scene_article",
]

CONFIG_PATH = package_data("config.yaml")
"""The project's config.yaml as the package ships it (package data; in a source checkout a link to
the project's own), so that :func:`fig6_scene_CookTorrance1982` (``reflectance bench``'s scene)
works from an installed wheel; the spectra beside it are the bundled ones."""

PHONG_SPECULAR_READINGS = {
    "as_printed": "Phong's s p_s with Blinn's p_s: the highlight of a white mirror (F = 1)",
    "matched": "Phong's p_s times F(n) at normal incidence, so that both models agree for a "
               "light at the eye (Blinn's 'both models essentially same', front lit)",
}
"""How large Phong's specular proportion is against Blinn's Torrance-Sparrow model."""


def display_from_colour(colour: Mapping[str, Any], illuminant: bool = True) -> dict[str, Any]:
    """The scene ``display`` of config ``colour`` (space, gamut clip, white, PNG bit depth).

    With ``illuminant=False`` the display white is left to the scene's default (the first
    light's spectrum).
    """
    out = {"space": colour["space"], "gamut_clip": colour["gamut_clip"]}
    if illuminant:
        out["illuminant"] = colour["illuminant"]
    out["png_bit_depth"] = colour["png_bit_depth"]
    return out


def scene_document(camera: Mapping[str, Any], objects: Sequence[Mapping[str, Any]],
                   lights: Sequence[Mapping[str, Any]], wavelengths: Mapping[str, Any],
                   spectra_dir: str | None = None, observer: str | None = None,
                   spectral: str | None = None, ambient: Mapping[str, Any] | None = None,
                   display: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """A scene mapping (reflectance/data/scene.schema.yaml); keys left None take the defaults.

    Parameters
    ----------
    camera : dict
    objects : list of dict
    lights : list of dict
        Lights without a ``type`` are directional.
    wavelengths : dict
        ``{start_nm, end_nm, step_nm}`` (config ``wavelengths``).
    spectra_dir, observer, spectral : str, optional
    ambient, display : dict, optional
    """
    doc: dict[str, Any] = {"wavelengths": dict(wavelengths)}
    for key, value in (("observer", observer), ("spectra_dir", spectra_dir),
                       ("spectral", spectral)):
        if value is not None:
            doc[key] = str(value)
    doc.update(camera=dict(camera), objects=list(objects),
               lights=[dict(light) if "type" in light else {"type": "directional", **light}
                       for light in lights])
    if ambient is not None:
        doc["ambient"] = dict(ambient)
    if display is not None:
        doc["display"] = dict(display)
    return doc


def panel_material(panel: Mapping[str, Any]) -> dict[str, Any]:
    """A config material entry (``material`` names the spectrum of F) as a scene material."""
    return {**{k: v for k, v in panel.items() if k != "material"}, "name": panel["material"]}


def vase_scene_CookTorrance1982(fig6: Mapping[str, Any], material: Mapping[str, Any],
                                reference: str, wavelengths: Mapping[str, Any],
                                colour: Mapping[str, Any], spectra_dir: str | None,
                                image: Mapping[str, Any] | None = None,
                                exposure: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """One vase alone as Cook & Torrance 1982 Fig. 6 renders it (Fig. 7: every vase).

    Parameters
    ----------
    fig6 : dict
        Config ``figures.cook_torrance_1982.fig6`` (vase, camera, lights, ambient fraction and
        the renderer settings).
    material : dict
        The scene material; fig6's distribution, convention, fresnel and shadowing unless given.
    reference : str
        The ambient reading (scene ``ambient.reference``).
    wavelengths, colour : dict
        Config ``wavelengths`` and ``colour``.
    spectra_dir : str
    image : dict, optional
        Overrides of the camera (``width``, ``height``, ``supersample``).
    exposure : dict, optional
        Scene ``display`` keys ``key`` and ``highlight_knee`` (default: Cook & Torrance's exposure,
        the brightest colour at the display maximum).
    """
    material = {"distribution": fig6["distribution"], "convention": fig6["convention"],
                "fresnel": fig6["fresnel"], "shadowing": fig6["shadowing"], **material}
    return scene_document(
        {**fig6["camera"], **(image or {})},
        [{"name": "vase", "geometry": {"type": "vase", **fig6["vase"]}, "material": material}],
        fig6["lights"], wavelengths, spectra_dir, observer=colour["observer"],
        spectral=fig6["spectral"],
        ambient={"fraction": fig6["ambient_fraction"], "reference": reference},
        display={**display_from_colour(colour), **(exposure or {})})


def fig6_scene_CookTorrance1982(panel: str = "b", reading: str = "irradiance",
                                config: dict[str, Any] | str | os.PathLike[str] | None = None,
                                spectra_dir: str | None = None) -> dict[str, Any]:
    """The scene of Cook & Torrance 1982 Fig. 6 ``panel`` from config.yaml.

    Parameters
    ----------
    panel : str
        A key of ``figures.cook_torrance_1982.fig6.panels`` (``"b"``: the copper vase).
    reading : str
        A key of ``fig6.ambient_readings``.
    config : dict or str or Path, optional
        The configuration or its file (default :data:`CONFIG_PATH`, the package's).
    spectra_dir : str, optional
        Default: ``spectra`` beside the config file (for the package's own, the bundled
        spectra); for a dict, ``spectra``.
    """
    if not isinstance(config, dict):
        path = Path(config or CONFIG_PATH)  # type: ignore[arg-type]  # the package's file
        from reflectance.io.yamlfile import read_yaml

        config, spectra_default = read_yaml(path), path.parent / "spectra"
    else:
        spectra_default = Path("spectra")
    fig6 = config["figures"]["cook_torrance_1982"]["fig6"]
    for key, value, known in (("panels", panel, fig6["panels"]),
                              ("ambient_readings", reading, fig6["ambient_readings"])):
        if value not in known:
            raise ValueError(f"config.yaml figures.cook_torrance_1982.fig6.{key}: no "
                             f"{value!r}; known: {', '.join(known)}")
    return vase_scene_CookTorrance1982(fig6, panel_material(fig6["panels"][panel]),
                                       fig6["ambient_readings"][reading],
                                       config["wavelengths"], config["colour"],
                                       str(spectra_dir or spectra_default))


def light_direction(position: npt.ArrayLike, look_at: npt.ArrayLike, up: npt.ArrayLike,
                    angle_deg: float, azimuth_deg: float) -> npt.NDArray[np.float64]:
    """Unit vector toward a directional light at ``angle_deg`` from the direction to the viewer.

    ``L = cos(a) E + sin(a) (cos(b) X + sin(b) Y)`` with E the unit vector from ``look_at`` toward
    the camera ``position``, X the image's right and Y its up (``up`` made orthogonal to E), a the
    angle and b the azimuth in the image plane (0: from the right, 90: from above). 0 is a light
    at the eye ("front lit"), angles towards 180 light the object from behind ("edge lit").

    Parameters
    ----------
    position, look_at, up : array_like, shape (3,)
        The camera (as in the scene's ``camera``).
    angle_deg : float
        Angle between L and E, in [0, 180]: 0 front lit, near 180 lit from behind.
    azimuth_deg : float

    Returns
    -------
    numpy.ndarray, shape (3,)

    Examples
    --------
    >>> (light_direction((0, -5, 0), (0, 0, 0), (0, 0, 1), 90, 0).round(12) + 0.0).tolist()
    [1.0, 0.0, 0.0]
    """
    E = unit_vector(np.subtract(position, look_at), "position - look_at")
    Y = np.asarray(up, dtype=np.float64) - np.dot(up, E) * E
    Y = unit_vector(Y, "up (orthogonal to the view direction)")
    X = np.cross(Y, E)  # the image's right: (right, up, toward the viewer) is right-handed
    if not 0.0 <= float(angle_deg) <= 180.0:
        raise ValueError(f"angle_deg must lie in [0, 180], got {angle_deg!r}")
    a, b = np.radians(float(angle_deg)), np.radians(float(azimuth_deg))
    return np.cos(a) * E + np.sin(a) * (np.cos(b) * X + np.sin(b) * Y)


def materials_Blinn1977(p_s: float, p_d: float, c3: float, n: float,
                        phong_specular: str = "as_printed") -> dict[str, Any]:
    """Scene materials of Blinn's Phong and Torrance-Sparrow models at equal beta.

    Both have a flat diffuse albedo 1 (so ``d p_d`` is the diffuse intensity). The
    Torrance-Sparrow material takes F from the constant index ``n`` (scene key ``index``, k = 0)
    and Blinn's D3 with ``c3``; the Phong material has ``c1 = -ln 2 / ln cos(beta)`` with beta
    the half-value angle of that D3.

    Parameters
    ----------
    p_s, p_d : float
        Blinn's specular and diffuse proportions (Fig. 7a: 0.4, 0.6; Fig. 7b: 0.667, 0.333).
    c3 : float
        D3 eccentricity, in (0, 2^(-1/4)).
    n : float
        Blinn's index of refraction (Fig. 7a: 200, Fig. 7b: 1.8).
    phong_specular : str
        A key of :data:`PHONG_SPECULAR_READINGS`.

    Returns
    -------
    dict
        ``{"phong": material, "torrance_sparrow": material}`` (scene-file mappings) and
        ``"c1"``, ``"beta_deg"``, ``"phong_s"``.

    References
    ----------
    - Blinn 1977, "Comparison with Phong shading", Fig. 7; "Facet distribution functions".

    Examples
    --------
    >>> m = materials_Blinn1977(0.667, 0.333, 0.35, 1.8, "matched")
    >>> print(f"{m['beta_deg']:.4f} {m['c1']:.4f} {m['phong_s']:.5f}")
    13.9141 23.2741 0.05445
    """
    if phong_specular not in PHONG_SPECULAR_READINGS:
        raise ValueError(f"unknown phong_specular reading {phong_specular!r}; known: "
                         f"{', '.join(PHONG_SPECULAR_READINGS)}")
    beta = c3_to_beta_Blinn1977(c3)
    c1 = float(beta_to_c1_Blinn1977(beta))  # Blinn 1977, equal beta: D1 and D3 halve together
    phong_s = float(p_s)
    if phong_specular == "matched":
        # Blinn 1977, s = D G F / (N.E) at a light at the eye: D = G = N.E = 1 at the highlight
        phong_s *= float(fresnel_dielectric_CookTorrance1982(1.0, n))
    return {
        "phong": {"model": "BlinnPhong1977", "c1": c1, "s": phong_s, "d": float(p_d),
                  "albedo": 1.0},  # Blinn 1977, s = (N.H)^c1
        "torrance_sparrow": {"index": {"n": float(n), "k": 0.0},
                             "model": "TorranceSparrow_Blinn1977",
                             "distribution": "TrowbridgeReitz1975", "c3": float(c3),
                             "s": float(p_s), "d": float(p_d), "albedo": 1.0,
                             "fresnel": "exact", "convention": "paper"},  # s = D G F / (N.E)
        "c1": c1, "beta_deg": float(np.degrees(beta)), "phong_s": phong_s,
    }


def mirror_highlight_Blinn1977(p_s: float, n: float,
                               angle_deg: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Blinn's Torrance-Sparrow specular intensity ``p_s s`` where the surface normal is H.

    For a light at ``angle_deg`` from the direction to the eye, a facet with N = H has
    N.H = 1, E.H = N.E = N.L = cos(angle/2), D3 = 1 and G = 1 (G_b = G_c = 2), so
    ``s = D3 G F / (N.E) = F(cos(angle/2)) / cos(angle/2)``: the specular value at the mirror
    point of a curved object that shows one. It is not the object's brightest: beyond the mirror
    point, towards the silhouette, D3 falls slowly while N.E falls faster and G stays 1 (as long
    as neither masking nor shadowing sets in), so ``D3 G / (N.E)`` and with it ``s`` grow past
    this value there (fig7.csv sets it beside the renders' brightest i).

    Parameters
    ----------
    p_s : float
    n : float
        Blinn's index of refraction (F with the factor 1/2, k = 0).
    angle_deg : array_like
        Angle between L and E, in [0, 180).

    Examples
    --------
    >>> print(f"{mirror_highlight_Blinn1977(0.667, 1.8, 0.0):.5f}")  # p_s ((n - 1)/(n + 1))^2
    0.05445
    """
    c = np.cos(np.radians(np.asarray(angle_deg, dtype=np.float64)) / 2)
    # Blinn 1977, s = D3 G F / (N.E) with D3 = G = 1 and N.E = E.H = c
    return float(p_s) * fresnel_dielectric_CookTorrance1982(c, float(n)) / c


def highlight_crossover_Blinn1977(first: Mapping[str, float], second: Mapping[str, float],
                                  bracket_deg: Sequence[float] = (90.0, 179.9)) -> float | None:
    """The light angle at which two of Blinn's materials have equal mirror highlights.

    ``first`` and ``second`` are ``{p_s, n}`` mappings (config ``fig7.panels``); the result is the
    angle (degrees from the eye direction) where :func:`mirror_highlight_Blinn1977` of ``second``
    equals that of ``first``, found by bisection (``scipy.optimize.brentq``) in ``bracket_deg``;
    ``None`` if they do not cross there. Blinn 1977: magnesium oxide is "very specular (even more
    so than the aluminum) for light hitting it almost tangentially".

    Examples
    --------
    >>> a = {"p_s": 0.4, "n": 200.0}; b = {"p_s": 0.667, "n": 1.8}
    >>> print(f"{highlight_crossover_Blinn1977(a, b):.2f}")
    166.87
    """
    from scipy.optimize import brentq

    def difference(angle):
        return float(mirror_highlight_Blinn1977(second["p_s"], second["n"], angle)
                     - mirror_highlight_Blinn1977(first["p_s"], first["n"], angle))

    lo, hi = (float(x) for x in bracket_deg)
    if difference(lo) * difference(hi) > 0:
        return None
    return float(brentq(difference, lo, hi, xtol=1e-10))


def blinn_scene_Blinn1977(fig7: Mapping[str, Any], material: Mapping[str, Any],
                          light: dict[str, Any] | list[dict[str, Any]],
                          wavelengths: Mapping[str, Any],
                          camera: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """One render of Blinn 1977 Fig. 7's object (also Fig. 8 and the sweep).

    Parameters
    ----------
    fig7 : dict
        Config ``figures.blinn_1977.fig7`` (object, camera, p_a).
    material : dict
        Scene material (:func:`materials_Blinn1977`).
    light : dict or list of dict
        ``{angle_deg, azimuth_deg}`` from the eye (:func:`light_direction`), or several.
    wavelengths : dict
    camera : dict, optional
        Default: fig7's camera.
    """
    cam = dict(camera or fig7["camera"])
    lights = [{"type": "directional", "direction": [float(x) for x in light_direction(
                   cam["position"], cam["look_at"], cam["up"], one["angle_deg"],
                   one["azimuth_deg"])],
               "spectrum": "D65", "intensity": 1.0, "solid_angle": 1.0}
              for one in ([light] if isinstance(light, dict) else light)]
    # Blinn's p_a: I_ia R_a with I_ia = p_a (a fraction of the light's intensity 1), R_a = 1
    return scene_document(cam, [{"name": "object", "geometry": dict(fig7["object"]),
                                 "material": material}], lights, wavelengths,
                          ambient={"fraction": fig7["p_a"], "reference": "intensity"},
                          display={"expose": False})


def rim_camera_Blinn1977(fig7: Mapping[str, Any], light: Mapping[str, float]) -> dict[str, Any]:
    """A close-up of Blinn 1977 Fig. 7's edge-lit highlight: fig7's camera position, aimed at the
    point of the torus whose normal is ``H = (L + E) / |L + E|`` (where Blinn's D3 peaks), with
    ``fig7.rim_closeup``'s field of view and size.

    For a light at angle a from the eye the lit and visible normals lie within 180 - a degrees of
    the silhouette, so at the full view the highlight is a rim about a pixel wide; the close-up
    magnifies it by the ratio of the fields of view. The torus is the one of config ``object``
    (about the z axis through its ``center``); the mirror point of normal n is
    ``center + R (n_x, n_y, 0) / |(n_x, n_y)| + r n``.
    """
    obj, cam = fig7["object"], dict(fig7["camera"])
    if obj["type"] != "torus":
        raise ValueError("config.yaml figures.blinn_1977.fig7.rim_closeup: needs object.type "
                         f"torus, got {obj['type']!r}")
    L = light_direction(cam["position"], cam["look_at"], cam["up"], light["angle_deg"],
                        light["azimuth_deg"])
    E = unit_vector(np.subtract(cam["position"], cam["look_at"]), "position - look_at")
    H = unit_vector(L + E, "L + E")
    ring = unit_vector(np.array([H[0], H[1], 0.0]), "H projected on the ring's plane")
    point = (np.asarray(obj.get("center", (0.0, 0.0, 0.0)), dtype=np.float64)
             + obj["major_radius"] * ring + obj["minor_radius"] * H)
    cam.update(look_at=[float(x) for x in point],
               **{k: v for k, v in fig7["rim_closeup"].items() if k != "light"})
    return cam


# --------------------------------------------------------------------------------------------
# The pieces of the rendered figures' scenes (reflectance.papers.figures assembles them)
# --------------------------------------------------------------------------------------------
# (config sections and scene documents are YAML mappings of mixed values: Mapping[str, Any])

def table1_material(row: Mapping[str, Any], material: str | None = None) -> dict[str, Any]:
    """A Cook & Torrance 1982 Table I row as a scene material of ``material``'s spectrum (default
    the row's own; R_d = F0/pi of it: the scene default); Table I's m "Not used" (s = 0) leaves the
    key out."""
    return {"name": material or row["material"], "s": row["s"], "d": row["d"],
            **({} if row["m"] is None else {"m": row["m"]})}


def fig7_vases_CookTorrance1982(fig7: Mapping[str, Any], fig6: Mapping[str, Any],
                                table1: Sequence[Mapping[str, Any]]
                                ) -> list[tuple[str, str, dict[str, Any]]]:
    """(id, group, scene material) of every vase of Cook & Torrance 1982 Fig. 7: the metals with
    Fig. 6b's s, d and lobes ("the same parameters used for Figure 6b"), Table I's nonmetals (with
    the reflectance of ``fig7.table1_spectra`` where a row's n, k do not give its colour), then the
    labelled variants (a Table I row's s, d, m with another material's spectrum)."""
    b = fig6["panels"]["b"]
    out = [(e["material"], "metal", {"name": e["material"], "s": b["s"], "d": b["d"],
                                     "lobes": b["lobes"]}) for e in fig7["metals"]]
    spectra = fig7.get("table1_spectra", {})
    for row in table1:
        name = spectra.get(row["material"], row["material"])
        out.append((name, "nonmetal", table1_material(row, name)))
    rows = {row["material"]: row for row in table1}
    for i, extra in enumerate(fig7["extras"]):
        if extra["table1"] not in rows:
            raise ValueError(f"config.yaml figures.cook_torrance_1982.fig7.extras[{i}].table1: "
                             f"{extra['table1']!r} is not a table1 row; known: {', '.join(rows)}")
        out.append((f"{extra['table1']}_{extra['material']}", "extra",
                    table1_material(rows[extra["table1"]], extra["material"])))
    return out


def fig7_exposure_CookTorrance1982(fig7: Mapping[str, Any], vase: str,
                                   group: str) -> dict[str, Any]:
    """The default Fig. 7's scene display keys of one vase: its row's exposure (config
    ``fig7.exposure[group]``) with the metered luminance (white card or key) times the vase's
    ``fig7.vase_exposure`` factor (default 1), a labelled departure from one exposure per row."""
    exposure = copy.deepcopy(fig7["exposure"][group])
    factor = fig7.get("vase_exposure", {}).get(vase, 1.0)
    for key in ("white", "key"):
        if key in exposure:
            exposure[key]["luminance"] *= factor
    return exposure


def watch_part_material(name: str, spec: Mapping[str, Any], fig6: Mapping[str, Any],
                        table1: Sequence[Mapping[str, Any]]) -> dict[str, Any]:
    """A part of config ``fig8.parts`` as a scene material; ``table1: X`` takes Table I's row X."""
    if "table1" in spec:
        rows = {row["material"]: row for row in table1}
        if spec["table1"] not in rows:
            raise ValueError(f"config.yaml figures.cook_torrance_1982.fig8.parts.{name}.table1: "
                             f"{spec['table1']!r} is not a table1 row; known: {', '.join(rows)}")
        row = rows[spec["table1"]]
        spec = {"material": row["material"], "s": row["s"], "d": row["d"], "m": row["m"]}
    return {**panel_material(spec), "distribution": fig6["distribution"],
            "convention": fig6["convention"], "fresnel": fig6["fresnel"],
            "shadowing": fig6["shadowing"]}


def watch_scene_CookTorrance1982(fig8: Mapping[str, Any], fig6: Mapping[str, Any],
                                 table1: Sequence[Mapping[str, Any]],
                                 wavelengths: Mapping[str, Any], colour: Mapping[str, Any],
                                 spectra_dir: str | None) -> dict[str, Any]:
    """The watch of Cook & Torrance 1982 Fig. 8 as a scene (config ``fig8``, with fig6's
    renderer settings and ambient fraction)."""
    light, led = fig8["light"], fig8["led"]
    parts = {name: watch_part_material(name, spec, fig6, table1)
             for name, spec in fig8["parts"].items()}
    # C&T 1982 Fig. 8: the LEDs' "color was approximated by using a color with the same dominant
    # wavelength"; luminance relative to a white Lambertian card facing the light (I d omega / pi)
    parts["led"] = {"model": "Lambert", "convention": "physical", "albedo": 0.0, "emission": {
        "dominant_wavelength_nm": led["dominant_wavelength_nm"], "purity": led["purity"],
        "luminance": led["luminance_factor"] * light["intensity"] * light["solid_angle"] / np.pi,
        "white": colour["illuminant"]}}
    return scene_document(
        fig8["camera"], [{"name": "watch", "geometry": {"type": "watch",
                                                        "parameters": fig8["watch"]},
                          "material": parts["case"], "parts": parts}], [light], wavelengths,
        spectra_dir, observer=colour["observer"], spectral=fig6["spectral"],
        ambient={"fraction": fig6["ambient_fraction"],
                 "reference": watch_ambient_reference(fig8, fig6)},
        display={**display_from_colour(colour), **fig8.get("exposure", {})})


def watch_ambient_reference(fig8, fig6):
    """The scene ambient reference of ``fig8.ambient_reading``: a key of fig6.ambient_readings, or
    ``published`` (the default figures' reading, fig6.published.ambient_reference)."""
    if fig8["ambient_reading"] == "published":
        return fig6["published"]["ambient_reference"]
    return fig6["ambient_readings"][fig8["ambient_reading"]]


def texture_material_Blinn1977(fig8: Mapping[str, Any], pattern: Mapping[str, Any],
                               n: float) -> dict[str, Any]:
    """Blinn 1977 Fig. 8's material: Torrance-Sparrow with D3 whose C3 = C_min + (1 - C_min) t
    follows a texture ``pattern`` (config ``fig8.patterns.*``), F from the index ``n``."""
    return {"index": {"n": float(n), "k": 0.0}, "model": "TorranceSparrow_Blinn1977",
            "distribution": "TrowbridgeReitz1975", "convention": "paper", "fresnel": "exact",
            "s": fig8["p_s"], "d": fig8["p_d"], "albedo": 1.0,
            "roughness_texture": {"method": pattern["method"],
                                  "parameters": dict(pattern["parameters"]),
                                  "min": fig8["c_min"], "max": 1.0}}


def sweep_camera_Blinn1977(fig7: Mapping[str, Any], sweep: Mapping[str, Any]) -> dict[str, Any]:
    """The camera of Blinn 1977 Fig. 7's light sweep: fig7's, ``size`` wide, same aspect."""
    cam = dict(fig7["camera"])
    cam.update(width=sweep["size"], height=round(sweep["size"] * cam["height"] / cam["width"]),
               supersample=sweep["supersample"])
    return cam


def sky_dome_lights(environment: Mapping[str, Any], spectrum: str) -> list[dict[str, Any]]:
    """A gradient sky as ``environment["lights"]`` directional lights over the upper hemisphere.

    The directions are a Fibonacci lattice on the hemisphere: light ``i`` at height
    ``z_i = (i + 1/2) / N`` and azimuth ``i`` times the golden angle. Equal steps in z cut a
    sphere into zones of equal area (Archimedes' hat-box theorem), so each light stands for the
    solid angle ``2 pi / N``. The sky's radiance falls from ``zenith`` overhead to ``horizon``
    linearly in z, the sine of the elevation (both in units of the key light's irradiance per
    steradian; a choice: the article prints no environment). A light's intensity is that
    radiance, its ``solid_angle`` ``2 pi / N``: the lights sum to the sky's irradiance.

    Examples
    --------
    >>> dome = sky_dome_lights({"lights": 64, "zenith": 0.3, "horizon": 0.1}, "D65")
    >>> z = np.array([d["direction"][2] for d in dome])
    >>> print(len(dome), f"{z.min():.4f} {z.max():.4f}", f"{sum(d['solid_angle'] for d in dome):.4f}")
    64 0.0078 0.9922 6.2832
    """
    directions = _hemisphere_lattice(int(environment["lights"]))
    z = directions[:, 2]
    radiance = environment["horizon"] + (environment["zenith"] - environment["horizon"]) * z
    return [{"direction": [float(x) for x in d], "spectrum": spectrum,
             "intensity": float(L), "solid_angle": float(2.0 * np.pi / len(z))}
            for d, L in zip(directions, radiance)]


def _hemisphere_lattice(n: int) -> npt.NDArray[np.float64]:
    """(n, 3) unit vectors of a Fibonacci lattice on the upper hemisphere: ``z_i = (i + 1/2) / n``,
    azimuth ``i`` golden angles; each stands for the solid angle ``2 pi / n`` (equal zones)."""
    z = (np.arange(n) + 0.5) / n
    phi = np.arange(n) * np.pi * (3.0 - np.sqrt(5.0))  # the golden angle
    r = np.sqrt(1.0 - z**2)
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)


def ground_lights(n: int, albedo: float, lights: Sequence[Mapping[str, Any]], spectrum: str,
                  sphere: tuple[Sequence[float], float] | None = None) -> list[dict[str, Any]]:
    """A grey Lambertian floor (the plane z = 0, ``albedo``) as ``n`` directional lights over the
    lower hemisphere: what a sphere above it mirrors below its horizon.

    Ground light ``j`` (the lattice of :func:`sky_dome_lights` mirrored below the horizon, each
    ``2 pi / n`` sr) has the radiance of the floor point it meets from the sphere's centre,
    ``albedo / pi * sum_l I_l d omega_l max(0, L_l . z)`` over the directional ``lights`` that
    reach that point (Lambert: L = rho E / pi); ``sphere`` = (centre, radius) blocks those whose
    ray from the point meets it (its shadow on the floor and the sky it hides), None: nothing
    does. The lights cast no shadow (``shadows: false``): the floor they stand for would block
    them, and a convex object above it shades itself through N.L alone. (A choice: one bounce,
    the floor seen from the centre, not from each point of the sphere.)

    Examples
    --------
    >>> sky = sky_dome_lights({"lights": 256, "zenith": 1.0, "horizon": 1.0}, "D65")
    >>> [g] = ground_lights(1, 0.5, sky, "D65")  # a uniform sky of radiance 1: E = pi
    >>> print(f"{g['intensity']:.4f}", g["direction"][2], g["shadows"])
    0.5000 -0.5 False

    A unit sphere resting on the floor hides the sky's cap of half-angle asin(1 / D) from a floor
    point at distance ``a`` from where it rests (D^2 = 1 + a^2), the cap's irradiance
    ``pi sin^3`` of that angle (a sphere's form factor; the cap touches the horizon): the
    ground light nearest straight below sees the floor at 0.5 (1 - D^-3), up to the sky's
    256 lights:

    >>> under = ground_lights(64, 0.5, sky, "D65", sphere=([0, 0, 1], 1.0))
    >>> a = np.hypot(*under[-1]["direction"][:2]) / -under[-1]["direction"][2]
    >>> print(f"{under[-1]['intensity']:.3f} {0.5 * (1 - (1 + a * a) ** -1.5):.3f}")
    0.012 0.012
    """
    directions = _hemisphere_lattice(int(n)) * np.array([1.0, 1.0, -1.0])
    toward = np.array([unit_vector(light["direction"], "light direction") for light in lights])
    energy = np.array([light["intensity"] * light["solid_angle"] for light in lights])
    reach = np.ones((len(directions), len(lights)), bool)
    if sphere is not None:
        centre, radius = np.asarray(sphere[0], np.float64), float(sphere[1])
        # the floor point each direction meets from the centre: centre + t d, t = c_z / -d_z
        point = centre + (centre[2] / -directions[:, 2])[:, None] * directions
        offset = point - centre  # a ray point + s L meets the sphere where s solves
        b = offset @ toward.T  # s^2 + 2 b s + c = 0, c = |offset|^2 - r^2: a root s > 0
        c = np.einsum("ij,ij->i", offset, offset)[:, None] - radius**2
        reach = ~((b < 0) & (b * b > c))
    irradiance = (reach * energy * np.maximum(toward[:, 2], 0.0)).sum(axis=1)
    radiance = albedo * irradiance / np.pi
    return [{"direction": [float(x) for x in d], "spectrum": spectrum, "intensity": float(L),
             "solid_angle": float(2.0 * np.pi / len(directions)), "shadows": False}
            for d, L in zip(directions, radiance)]


def spheres_scene_article(spheres: Mapping[str, Any], wavelengths: Mapping[str, Any],
                          colour: Mapping[str, Any], spectra_dir: str | None,
                          panel: str = "pair") -> dict[str, Any]:
    """One panel of the article's spheres (config ``figures.article.spheres``) on a grey floor:
    ``panel`` "pair" is the article's pair of plastic spheres, "metal" the gold sphere alone
    (camera ``metal_sphere.image`` over the figure's, so both panels share one scale). Each panel
    is exposed on its own, by its scene display keys ``exposure[panel]`` ({}: Cook & Torrance's
    exposure over the panel)."""
    cfg = spheres
    if panel not in ("pair", "metal"):
        raise ValueError(f"panel: 'pair' or 'metal', got {panel!r}")
    camera = dict(cfg["camera"])
    lights = [{**cfg["light"], "intensity": 1.0, "solid_angle": 1.0}]
    ambient = {"fraction": cfg["ambient_fraction"], "reference": "irradiance"}
    if panel == "pair":
        objects = [{"name": s["name"], "geometry": {"type": "sphere", "center": s["center"],
                                                     "radius": s["radius"]},
                    "material": {"name": cfg["material"], "diffuse_material": s["diffuse_material"],
                                 "model": "CookTorrance1982", "distribution": cfg["distribution"],
                                 "convention": cfg["convention"], "m": cfg["m"], "s": cfg["s"],
                                 "d": cfg["d"], "fresnel": "exact", "shadowing": "v-cavity"}}
                   for s in cfg["spheres"]]
    else:  # the article: "on metallic materials such as gold ..."; C&T's metals: s = 1, d = 0
        metal = cfg["metal_sphere"]
        camera.update(metal["image"])
        objects = [{"name": metal["name"],
                    "geometry": {"type": "sphere", "center": metal["center"],
                                 "radius": metal["radius"]},
                    "material": {"name": metal["material"], "model": "CookTorrance1982",
                                 "distribution": cfg["distribution"],
                                 "convention": cfg["convention"], "m": metal["m"], "s": 1.0,
                                 "d": 0.0, "fresnel": "exact", "shadowing": "v-cavity"}}]
        if "environment" in metal:  # a sky the metal mirrors: it stands in for the ambient term
            environment = metal["environment"]
            lights += sky_dome_lights(environment, cfg["light"]["spectrum"])
            if environment.get("ground_lights", 0):  # and the lit floor below its horizon
                lights += ground_lights(environment["ground_lights"], cfg["floor_albedo"],
                                        lights, cfg["light"]["spectrum"],
                                        (metal["center"], metal["radius"]))
            ambient = {"fraction": 0.0, "reference": "irradiance"}
    objects.append({"name": "floor", "geometry": {"type": "plane", "center": [0, 0, 0],
                                                   "normal": [0, 0, 1], "size": [cfg["floor_size"]] * 2,
                                                   "resolution": [32, 32]},
                    "material": {"model": "Lambert", "convention": "physical",
                                 "albedo": cfg["floor_albedo"]}})
    return scene_document(camera, objects, lights, wavelengths, spectra_dir,
                          observer=colour["observer"], ambient=ambient,
                          display={**display_from_colour(colour, illuminant=False),
                                   **copy.deepcopy(cfg["exposure"][panel])})
