"""A whole image on a display: its exposure scale, and its display RGB computed band by band.

A display's settings (``display``) are what a scene file's ``display`` holds
(:class:`reflectance.render.scene.Display`): ``space``, ``gamut_clip``, ``expose``,
``illuminant``, ``key`` (the metered ``(percentile, luminance)``, :func:`expose_key`),
``highlight_knee`` (:func:`compress_highlights`), ``transfer`` (:func:`encode`) and ``white`` (the display luminance of a white
card facing the lights). The automatic exposure is the white card's when ``white`` is set, else
the metered key's, else Cook & Torrance's (:func:`expose_CookTorrance1982`); a large image's
scale is found from the few pixels that decide it, so that it is the whole image's without
converting the whole image at once. Pixel by pixel the conversion then runs in bands of rows:
the temporaries stay small at any image size, and the numbers are those of one call.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from reflectance.colour.colorimetry import OBSERVER_DEFAULT
from reflectance.colour.display import (XYZ_to_linear_RGB, compress_highlights, display_space,
                                        encode, expose_CookTorrance1982, expose_key, gamut_clip)

__all__ = ["exposure_scale", "image_display_RGB"]

_BAND_PIXELS = 1 << 20  # pixels converted to display RGB at once


def _band_rows(XYZ):
    return max(1, _BAND_PIXELS // max(1, XYZ.shape[1]))


def _colour(display, observer, wavelengths):
    """The colour conversion's keywords of a display."""
    return {"illuminant": display.illuminant, "observer": observer, "wavelengths": wavelengths}


def exposure_scale(XYZ: npt.NDArray[np.float64], display: Any, observer: str = OBSERVER_DEFAULT,
                   wavelengths: npt.ArrayLike | None = None,
                   white_card: float | None = None) -> float:
    """The exposure factor :func:`image_display_RGB` applies to the image ``XYZ`` (its automatic
    exposure; 1 without).

    Parameters
    ----------
    XYZ : ndarray, shape (height, width, 3)
    display
        The display's settings (see the module docstring).
    observer, wavelengths
        As for :func:`reflectance.colour.display.XYZ_to_linear_RGB`.
    white_card : float, optional
        The display luminance of a white card facing the lights (needed when ``display.white``
        is set; :func:`reflectance.render.shading.white_card_luminance`).
    """
    d = display
    if not d.expose:
        return 1.0
    if d.white is not None:
        return d.white / white_card
    return _large_image_scale(XYZ, d, _band_rows(XYZ), _colour(d, observer, wavelengths))


def image_display_RGB(XYZ: npt.NDArray[np.float64], display: Any, observer: str = OBSERVER_DEFAULT,
                      wavelengths: npt.ArrayLike | None = None, white_card: float | None = None,
                      exposure: float | None = None,
                      encoded: bool = False) -> tuple[npt.NDArray[np.float64], float]:
    """(linear display RGB in [0, 1] of shape (H, W, 3), exposure scale) of the image ``XYZ``:
    exposed, highlights compressed, gamut clipped; the light the display emits, before the
    transfer function.

    ``display``, ``observer``, ``wavelengths`` and ``white_card`` as for :func:`exposure_scale`.
    ``exposure`` (a positive factor on XYZ) replaces the automatic exposure of the display
    settings; None keeps it. ``encoded`` applies the display's transfer function too.
    """
    d = display
    kwargs = _colour(d, observer, wavelengths)
    scale, factor = 1.0, 1.0
    rows = _band_rows(XYZ)
    # a fixed factor (given, or from the white card) is applied band by band below
    if exposure is not None:
        if isinstance(exposure, bool) or not np.isfinite(exposure) or exposure <= 0:
            raise ValueError(f"exposure: must be a positive finite factor, got {exposure!r}")
        scale = factor = float(exposure)
    elif d.expose and d.white is not None:  # metered on a white card facing the lights
        scale = factor = d.white / white_card
    elif XYZ.shape[0] > rows:  # a large image: the scale from a few pixels
        scale = factor = _large_image_scale(XYZ, d, rows, kwargs)
    elif d.expose and d.key is not None:
        XYZ, scale = expose_key(XYZ, *d.key)  # the object metered, highlights compressed
    elif d.expose:
        # Cook & Torrance 1982: all XYZ of the scene scaled equally, the most luminous colour
        # at the maximum luminance of its chromaticity
        XYZ, scale = expose_CookTorrance1982(XYZ, d.space, **kwargs)
    # pixel by pixel from here on: in bands of rows, so that the conversion's temporaries stay
    # small at any image size (the same numbers as in one call)
    out = np.empty(XYZ.shape)
    for start in range(0, XYZ.shape[0], rows):
        band = XYZ[start:start + rows]
        RGB = XYZ_to_linear_RGB(band * factor if factor != 1.0 else band, d.space, **kwargs)
        if d.highlight_knee is not None:
            RGB = compress_highlights(RGB, d.highlight_knee, d.highlight_rolloff)
        RGB = gamut_clip(RGB, d.gamut_clip, d.space)
        out[start:start + rows] = encode(RGB, d.space, d.transfer) if encoded else RGB
    return out, scale


def _large_image_scale(XYZ, d, rows, kwargs):
    """The exposure scale of a large image, from the pixels that decide it: for the metered key,
    the luminances of the lit pixels (their percentile is the scale); for Cook & Torrance, the
    pixels of each band within 1e-9 of that band's greatest display luminance (the most
    luminous colour is among them). The exposure functions themselves then pick the scale."""
    if not d.expose:
        return 1.0
    if d.key is not None:
        Y = XYZ[..., 1]
        lit = Y[np.isfinite(Y) & (Y > 0)]
        probe = np.zeros((len(lit), 3))
        probe[:, 1] = lit
        return expose_key(probe, *d.key)[1]
    luminance = display_space(d.space).matrix_RGB_to_XYZ[1]
    candidates = []
    for start in range(0, XYZ.shape[0], rows):
        band = XYZ[start:start + rows].reshape(-1, 3)
        RGB = XYZ_to_linear_RGB(band, d.space, **kwargs)
        Y = np.where(np.all(np.isfinite(RGB), axis=-1), RGB @ luminance, -np.inf)
        top = Y.max()
        if top > 0:
            candidates.append(band[Y >= top * (1.0 - 1e-9)])
    if not candidates:
        return 1.0
    return expose_CookTorrance1982(np.concatenate(candidates), d.space, **kwargs)[1]
