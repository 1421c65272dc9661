"""Gamut mapping of the rendered figures against the unclipped colour (audit 3).

A rendered figure's EXR holds its linear scene XYZ and, in its header, the scene (display space,
white, exposure key, highlight knee) and the exposure scale its PNG used. :func:`exr_display_RGB`
repeats the display pipeline of :func:`reflectance.render.pipeline.display_image` up to the gamut
clip: the linear display RGB each pixel asks for. :func:`clip_differences` then brings the
out-of-gamut pixels into the display by each method of
:data:`reflectance.colour.display.GAMUT_CLIP_METHODS` (Cook & Torrance's constant dominant
wavelength, per-channel clipping, CSS Color 4's OKLCh chroma reduction) and measures what each
costs: CIEDE2000 and the CAM16 hue angle shift against the unclipped colour.

References
----------
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM TOG 1(1),
  "Determining the RGB values".
- W3C, CSS Color Module Level 4, §13.2 "CSS Gamut Mapping to an RGB Destination".
- Li, C., et al. (2017). Comprehensive color solutions: CAM16, CAT16, and CAM16-UCS. Color Res.
  Appl. 42(6), 703-718 (hue angle h). CIE 142-2001 (CIEDE2000).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = ["GAMUT_TOLERANCE", "exr_colorimetry", "exr_display_RGB", "out_of_gamut", "hue_difference_deg", "clip_differences"]


def exr_colorimetry(header: Mapping[str, Any]) -> dict[str, Any]:  # names (str), a grid (dict)
    """``{"illuminant", "observer", "wavelengths"}`` an EXR of the render pipeline was computed
    with, from the scene in its header: the display white (display.illuminant, else the first
    light's spectrum, as :func:`reflectance.render.scene.load_scene` reads it), the observer and
    the wavelength grid (start_nm, end_nm, step_nm)."""
    scene = json.loads(header["scene"])
    lights = scene.get("lights") or []
    illuminant = scene["display"].get("illuminant", lights[0]["spectrum"] if lights else "D65")
    return {"illuminant": illuminant, "observer": scene["observer"],
            "wavelengths": dict(scene["wavelengths"])}


def exr_display_RGB(XYZ: npt.ArrayLike,
                    header: Mapping[str, Any]
                   ) -> tuple[npt.NDArray[np.float64], str, npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """Linear display RGB before the gamut clip of an EXR written by the render pipeline.

    Parameters
    ----------
    XYZ : array_like, shape (H, W, 3)
        The EXR's scene XYZ (:func:`reflectance.io.images.read_exr`).
    header : dict
        Its header: ``scene`` (JSON) and ``display_exposure_scale``.

    Returns
    -------
    tuple
        ``(RGB, space, white, lit)``: linear RGB (H, W, 3) exposed (and highlight-compressed) as
        the PNG was, the display space name, the scene white XYZ (Y = 1) on the render grid, and
        the mask of object pixels (scene Y > 0).
    """
    from reflectance.colour.colorimetry import white_XYZ
    from reflectance.colour.display import XYZ_to_linear_RGB, compress_highlights
    from reflectance.optics.spectra import wavelength_grid

    scene = json.loads(header["scene"])
    d, seen = scene["display"], exr_colorimetry(header)
    w = seen["wavelengths"]
    grid = wavelength_grid(w["start_nm"], w["end_nm"], w["step_nm"])
    white = white_XYZ(seen["illuminant"], seen["observer"], grid)
    XYZ = np.asarray(XYZ, dtype=np.float64)
    scale = float(header["display_exposure_scale"])
    RGB = XYZ_to_linear_RGB(XYZ * scale, d["space"], illuminant=white)
    if d.get("highlight_knee") is not None:
        RGB = compress_highlights(RGB, d["highlight_knee"], d.get("highlight_rolloff", "tanh"))
    return RGB, d["space"], white, XYZ[..., 1] > 0


#: how far outside [0, 1] a channel must lie to count as out of gamut: an exposure that puts the
#: brightest colour's largest channel at exactly 1 (Cook & Torrance's), applied to the EXR's
#: float32 XYZ (relative rounding 6e-8), is not
GAMUT_TOLERANCE = 1e-6


def out_of_gamut(RGB: npt.NDArray[np.float64],
                 tolerance: float = GAMUT_TOLERANCE) -> npt.NDArray[np.bool_]:
    """True where a linear RGB colour has a channel outside [-tolerance, 1 + tolerance]."""
    RGB = np.asarray(RGB, dtype=np.float64)
    return np.any((RGB < -tolerance) | (RGB > 1.0 + tolerance), axis=-1)


def hue_difference_deg(h: npt.ArrayLike, h_reference: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """``h - h_reference`` in degrees, wrapped into [-180, 180).

    Examples
    --------
    >>> hue_difference_deg([350.0, 10.0], [10.0, 350.0]).tolist()
    [-20.0, 20.0]
    """
    return (np.asarray(h, dtype=np.float64) - np.asarray(h_reference, dtype=np.float64)
            + 180.0) % 360.0 - 180.0


def clip_differences(RGB: npt.ArrayLike, space: str, white: npt.ArrayLike, methods: Sequence[str],
                     viewing: Mapping[str, Any]) -> dict[str, dict[str, Any]]:
    """What each gamut clip does to colours, against the unclipped colour.

    Parameters
    ----------
    RGB : array_like, shape (n, 3)
        Linear display RGB (typically the out-of-gamut pixels).
    space : str
        Display space.
    white : array_like, shape (3,)
        The scene white XYZ (Y = 1): RGB (1, 1, 1).
    methods : sequence of str
        Keys of :data:`reflectance.colour.display.GAMUT_CLIP_METHODS`.
    viewing : dict
        CAM16 viewing conditions ``L_A``, ``Y_b``, ``surround`` (a name of
        ``colour.VIEWING_CONDITIONS_CAM16``); the adopted white is ``white``.

    Returns
    -------
    dict
        ``"reference"``: ``{"XYZ", "C", "h"}`` of the unclipped colours (CAM16 chroma and hue
        angle); per method ``{"RGB", "XYZ", "dE2000", "dh_CAM16"}`` (hue shift in degrees,
        wrapped).
    """
    import colour

    from reflectance.colour.colorimetry import XYZ_to_Lab
    from reflectance.colour.difference import delta_E_CIE2000
    from reflectance.colour.display import gamut_clip, linear_RGB_to_XYZ

    RGB = np.asarray(RGB, dtype=np.float64).reshape(-1, 3)
    white = np.asarray(white, dtype=np.float64)
    xy = white[:2] / white.sum()
    conditions = dict(XYZ_w=100.0 * white, L_A=viewing["L_A"], Y_b=viewing["Y_b"],
                      surround=colour.VIEWING_CONDITIONS_CAM16[viewing["surround"]])

    def describe(rgb):
        XYZ = linear_RGB_to_XYZ(rgb, space, illuminant=white)
        with np.errstate(invalid="ignore", divide="ignore"):
            cam = colour.XYZ_to_CAM16(100.0 * XYZ, **conditions)
        return XYZ, XYZ_to_Lab(XYZ, xy), np.asarray(cam.C), np.asarray(cam.h)

    XYZ_ref, lab_ref, C_ref, h_ref = describe(RGB)
    out = {"reference": {"XYZ": XYZ_ref, "C": C_ref, "h": h_ref}}
    for method in methods:
        clipped = gamut_clip(RGB, method, space)
        XYZ, lab, _, h = describe(clipped)
        out[method] = {"RGB": clipped, "XYZ": XYZ, "dE2000": delta_E_CIE2000(lab, lab_ref),
                       "dh_CAM16": hue_difference_deg(h, h_ref)}
    return out
