"""From scene XYZ to display RGB: exposure, linear RGB, gamut clipping, transfer function.

Cook & Torrance 1982 ("Determining the RGB values") convert XYZ to the linear RGB of a monitor by a
matrix, scale all XYZ of a scene equally so that the colour of greatest luminance sits at the
maximum luminance of its chromaticity, desaturate the colours that are still out of gamut at
constant dominant wavelength, and finally apply the monitor's nonlinearity. This module does those
steps in that order (:func:`XYZ_to_display`), with two alternative gamut clips for comparison.

Conventions
-----------
*   Scene XYZ are relative to the scene illuminant's white with Y = 1 (what
    :func:`reflectance.colour.colorimetry.tristimulus_weights` gives for S = 1).
*   Linear display RGB has the display white at (1, 1, 1), whose luminance is 1.
*   Each display space's RGB <-> XYZ matrix is derived from colour-science's primaries and
    whitepoint (``colour.normalised_primary_matrix``, computed once by colour-science and cached by
    :mod:`reflectance.colour.tables`, so that this module needs numpy only except for css-oklch). For 'sRGB' this is deliberately not
    colour-science's stored ``matrix_XYZ_to_RGB``, which is the 4-decimal rounded matrix printed in
    IEC 61966-2-1:1999 and maps D65 to (1, 1, 1) only to ~2e-4; the derived matrix does so to float
    precision and differs from the rounded one by < 3e-4 over the RGB cube.
*   The scene white is always brought onto the display white with the von Kries CAT02 transform
    (CIE 159:2004; colour-science's default in ``XYZ_to_RGB``), also when both are "D65": the D65
    white summed from its SPD on a grid (x, y = 0.31271, 0.32901 on 5 nm) is not exactly the
    display's nominal (0.3127, 0.3290), and adapting one onto the other is what makes the scene
    white land on RGB (1, 1, 1) * Y to float precision. For a D65 scene the adaptation changes
    colours by ~1e-4; for another illuminant (A, C, ...) it is an ordinary chromatic adaptation.

References
----------
-   Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM TOG 1(1),
    7-24, section "Determining the RGB values".
-   IEC 61966-2-1:1999, sRGB. SMPTE RP 145 (SMPTE C primaries). ITU-R BT.1886 (2011), reference
    EOTF. CIE 159:2004 (CIECAM02, CAT02). CIE 15:2004 §9.1 (dominant wavelength).
-   W3C CSS Color Module Level 4, §13.2 "CSS Gamut Mapping to an RGB Destination" (binary search
    with local MINDE, deltaEOK, JND 0.02).
-   Schlick, C. (1994). An Inexpensive BRDF Model for Physically-based Rendering. CGF 13(3)
    (an RGB renderer's F per display channel: :func:`fresnel_XYZ_rgb` with it passed in).
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.colour import tables
from reflectance.colour.colorimetry import OBSERVER_DEFAULT, white_XYZ

if TYPE_CHECKING:
    from reflectance.io.images import ColourTag

__all__ = [
    "DISPLAY_SPACES",
    "CHROMATIC_ADAPTATION_TRANSFORM",
    "DisplaySpace",
    "display_space",
    "XYZ_to_linear_RGB",
    "linear_RGB_to_XYZ",
    "expose_CookTorrance1982",
    "expose_key",
    "compress_highlights",
    "HIGHLIGHT_ROLLOFFS",
    "gamut_clip_CookTorrance1982",
    "gamut_clip_channels",
    "gamut_clip_CSSColor4",
    "GAMUT_CLIP_METHODS",
    "gamut_clip",
    "TRANSFERS",
    "encode",
    "decode_8bit",
    "XYZ_to_display",
    "fresnel_XYZ_rgb",
    "display_tag",
]

CHROMATIC_ADAPTATION_TRANSFORM = "CAT02"
"""von Kries transform used to bring the scene white onto the display white (CIE 159:2004)."""

DISPLAY_SPACES = {
    # name: (colour-science RGB_COLOURSPACES key, transfer function description)
    "sRGB": ("sRGB", "IEC 61966-2-1 sRGB inverse EOTF (piecewise, 12.92 / 1.055 x^(1/2.4))"),
    "SMPTE-C": ("SMPTE C", "inverse of the ITU-R BT.1886 reference EOTF, L_W = 1, L_B = 0"),
}
"""Display spaces by name: colour-science's colourspace and the transfer function of :func:`encode`.

'SMPTE-C' stands for a studio CRT of the papers' era (SMPTE RP 145 phosphors, D65 white). RP 145
gives no display nonlinearity; ITU-R BT.1886 is the standard written to describe exactly those CRTs
("reference EOTF", gamma 2.4 with L_B = 0), so it is used here. colour-science's own 'SMPTE C'
colourspace instead carries a pure 1/2.2 gamma.
"""

# CSS Color Module Level 4, §13.2: just noticeable difference in deltaEOK and search tolerance.
_CSS_JND = 0.02
_CSS_EPSILON = 0.0001


@dataclasses.dataclass(frozen=True)
class DisplaySpace:
    """A display RGB space: derived primary matrices and its white (Y = 1)."""

    name: str
    colourspace: str
    transfer: str
    matrix_RGB_to_XYZ: np.ndarray
    matrix_XYZ_to_RGB: np.ndarray
    whitepoint_XYZ: np.ndarray


@functools.lru_cache(maxsize=None)
def _display_space(name):
    colourspace_name, transfer = DISPLAY_SPACES[name]
    # Normalised primary matrix from colour's primaries and whitepoint (SMPTE RP 177 derivation),
    # not the rounded IEC 61966-2-1 matrix stored for 'sRGB'.
    M, white = tables.rgb_colourspace_matrix(colourspace_name)
    M_inv = np.linalg.inv(M)
    for array in (M, M_inv, white):
        array.setflags(write=False)
    return DisplaySpace(name, colourspace_name, transfer, M, M_inv, white)


def display_space(space: str = "sRGB") -> DisplaySpace:
    """The :class:`DisplaySpace` called ``space`` (one of :data:`DISPLAY_SPACES`).

    Examples
    --------
    >>> display_space("sRGB").matrix_RGB_to_XYZ[1].round(4).tolist()
    [0.2126, 0.7152, 0.0722]
    """
    if not isinstance(space, str) or space not in DISPLAY_SPACES:
        raise ValueError(
            f"space: unknown display space {space!r}; known: {', '.join(DISPLAY_SPACES)}"
        )
    return _display_space(space)


def _scene_white(illuminant, observer, wavelengths):
    """Scene white XYZ with Y = 1, from an illuminant name or an XYZ triple."""
    if isinstance(illuminant, str):
        XYZ_w = white_XYZ(illuminant, observer, wavelengths)
    else:
        XYZ_w = np.asarray(illuminant, dtype=np.float64)
        if XYZ_w.shape != (3,) or not np.all(np.isfinite(XYZ_w)) or not np.all(XYZ_w > 0):
            raise ValueError(
                f"illuminant: expected an illuminant name or a positive finite XYZ white, got "
                f"{illuminant!r}"
            )
    # Only the white's chromaticity matters: scene XYZ are relative to the white at Y = 1.
    return XYZ_w / XYZ_w[1]


def _matrix_chromatic_adaptation_VonKries(XYZ_w, XYZ_wr, transform):
    """von Kries adaptation matrix from white ``XYZ_w`` to white ``XYZ_wr`` in ``transform``'s space.

    ``M^-1 diag(M XYZ_wr / M XYZ_w) M`` with ``M`` colour-science's matrix of ``transform`` (CAT02,
    CIE 159:2004), in the order of operations of colour-science's
    ``colour.adaptation.matrix_chromatic_adaptation_VonKries``, which it reproduces to the bit.
    """
    M = tables.chromatic_adaptation_matrix(transform)
    RGB_w = np.matmul(M, XYZ_w[..., None]).squeeze(-1)
    RGB_wr = np.matmul(M, XYZ_wr[..., None]).squeeze(-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        D = np.nan_to_num(RGB_wr / RGB_w, nan=0.0, posinf=0.0, neginf=0.0)
    D = np.eye(D.shape[-1]) * np.expand_dims(D, -2)
    return np.matmul(np.matmul(np.linalg.inv(M), D), M)


def _XYZ_to_RGB_matrix(space: str, illuminant: str | npt.ArrayLike, observer: str,
                       wavelengths: npt.ArrayLike | None) -> npt.NDArray[np.float64]:
    ds = display_space(space)
    XYZ_w = _scene_white(illuminant, observer, wavelengths)
    M_cat = _matrix_chromatic_adaptation_VonKries(
        XYZ_w, ds.whitepoint_XYZ, CHROMATIC_ADAPTATION_TRANSFORM
    )
    return ds.matrix_XYZ_to_RGB @ M_cat


def _as_triplets(array: npt.ArrayLike, name: str) -> npt.NDArray[np.float64]:
    array = np.asarray(array, dtype=np.float64)
    if array.ndim == 0 or array.shape[-1] != 3:
        raise ValueError(f"{name}: expected shape (..., 3), got {array.shape}")
    return array


def XYZ_to_linear_RGB(XYZ: npt.ArrayLike, space: str = "sRGB",
                      illuminant: str | npt.ArrayLike = "D65", observer: str = OBSERVER_DEFAULT,
                      wavelengths: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
    """Scene XYZ (relative to the illuminant's white, Y = 1) to linear display RGB.

    The illuminant's white maps to RGB (1, 1, 1) * Y to float precision: the scene white is adapted
    onto the display white with CAT02 (see the module notes), then the derived primary matrix is
    applied. Equals ``colour.XYZ_to_RGB(XYZ, space, illuminant=xy_w,
    chromatic_adaptation_transform="CAT02")`` with colour's derived (not rounded) matrix.

    Parameters
    ----------
    XYZ : array_like
        Shape ``(..., 3)``.
    space : str
        One of :data:`DISPLAY_SPACES`.
    illuminant : str or array_like
        Name of the scene illuminant (its white is computed from the SPD and ``observer`` by
        :func:`reflectance.colour.colorimetry.white_XYZ`) or its white XYZ directly, e.g. ``W.sum(0)`` for
        the weights ``W`` the scene was integrated with.
    observer : str
        Observer of the white (used only with an illuminant name).
    wavelengths : array_like or None
        Grid of the white (used only with an illuminant name). Pass the render grid for an exact
        white; ``None`` uses the observer's 1 nm tabulation.

    Returns
    -------
    numpy.ndarray
        Linear RGB, same shape; out-of-gamut colours have channels outside [0, 1].

    Examples
    --------
    >>> from reflectance.colour.colorimetry import white_XYZ
    >>> XYZ_to_linear_RGB(0.5 * white_XYZ("A"), "sRGB", "A").round(12).tolist()
    [0.5, 0.5, 0.5]
    """
    XYZ = _as_triplets(XYZ, "XYZ")
    return XYZ @ _XYZ_to_RGB_matrix(space, illuminant, observer, wavelengths).T


def linear_RGB_to_XYZ(RGB: npt.ArrayLike, space: str = "sRGB",
                      illuminant: str | npt.ArrayLike = "D65", observer: str = OBSERVER_DEFAULT,
                      wavelengths: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
    """Inverse of :func:`XYZ_to_linear_RGB` (same arguments).

    Examples
    --------
    >>> linear_RGB_to_XYZ([1.0, 1.0, 1.0], "sRGB", [0.9, 1.0, 1.1]).round(12).tolist()
    [0.9, 1.0, 1.1]
    """
    RGB = _as_triplets(RGB, "RGB")
    M = _XYZ_to_RGB_matrix(space, illuminant, observer, wavelengths)
    return RGB @ np.linalg.inv(M).T


def expose_CookTorrance1982(XYZ: npt.ArrayLike, space: str = "sRGB",
                            illuminant: str | npt.ArrayLike = "D65",
                            observer: str = OBSERVER_DEFAULT,
                            wavelengths: npt.ArrayLike | None = None
                           ) -> tuple[npt.NDArray[np.float64], float]:
    """Scale all XYZ of a scene equally so its most luminous colour peaks at the display maximum.

    Cook & Torrance 1982, "Determining the RGB values": "all XYZ values in the scene are scaled
    equally so that they all lie inside the monitor gamut and usually so that the color with the
    greatest luminance is reproduced on the monitor at the maximum luminance possible for its
    chromaticity". Precisely: let ``c*`` be the colour of greatest display luminance ``Y`` (the Y
    of its adapted XYZ, i.e. the luminance row of the primary matrix times its RGB); among ties the
    one with the largest channel. Then ``scale = 1 / max(RGB(c*))``: at that scale ``c*`` has its
    largest channel at 1, which for an in-gamut chromaticity is the brightest the monitor can show
    it.

    Because Y is a convex combination of R, G, B (the luminance row is positive and sums to 1),
    ``Y <= max(RGB)``, so after scaling every colour has ``Y <= 1`` and can be desaturated into
    gamut at constant luminance by :func:`gamut_clip_CookTorrance1982`. Less luminous but more
    saturated colours may still have a channel above 1: that is the gamut clip's job, as in the
    paper. If ``c*`` itself is out of gamut (a negative channel), its chromaticity cannot be shown
    at any luminance; the same rule (largest channel at 1) still applies, continuously, and the
    gamut clip then desaturates it at that luminance.

    Non-finite pixels are ignored for the scale (and stay non-finite). If no pixel has a positive
    luminance the scene is returned unscaled (scale 1).

    Parameters
    ----------
    XYZ : array_like
        Scene XYZ, shape ``(..., 3)`` (a single colour, a list, an image).
    space, illuminant, observer, wavelengths
        As for :func:`XYZ_to_linear_RGB`.

    Returns
    -------
    tuple
        ``(XYZ * scale, scale)`` with ``scale`` a float.

    References
    ----------
    Cook & Torrance 1982, "Determining the RGB values", paragraph on monitor luminance.

    Examples
    --------
    >>> from reflectance.colour.colorimetry import white_XYZ
    >>> XYZ = np.array([4.0, 2.0]).reshape(2, 1) * white_XYZ("D65")
    >>> _, scale = expose_CookTorrance1982(XYZ, "sRGB", "D65")
    >>> round(scale, 12)
    0.25
    """
    XYZ = _as_triplets(XYZ, "XYZ")
    RGB = XYZ_to_linear_RGB(XYZ, space, illuminant, observer, wavelengths).reshape(-1, 3)
    finite = np.all(np.isfinite(RGB), axis=-1)
    if not np.any(finite):
        return XYZ.copy(), 1.0
    RGB = RGB[finite]
    Y = RGB @ display_space(space).matrix_RGB_to_XYZ[1]
    Y_max = Y.max()
    if not Y_max > 0:
        return XYZ.copy(), 1.0
    peak = RGB[Y == Y_max].max()
    scale = float(1.0 / peak)
    return XYZ * scale, scale


def expose_key(XYZ: npt.NDArray[np.float64], percentile: float = 50.0,
               luminance: float = 0.18) -> tuple[npt.NDArray[np.float64], float]:
    """Scale a scene so that a percentile of its object's luminance lands at a display luminance.

    A photographer's reflected-light metering of the object instead of Cook & Torrance's "usually"
    (their most luminous colour at the display maximum): the ``percentile`` of ``Y`` over the
    pixels with ``Y > 0`` (the object; the background is black) becomes ``luminance`` (0.18: the
    photographic middle grey). Brighter colours may then exceed the display; see
    :func:`compress_highlights`. If no pixel has ``Y > 0`` the scene is returned unscaled.

    Parameters
    ----------
    XYZ : array_like
        Scene XYZ, shape ``(..., 3)``.
    percentile : float
        In [0, 100].
    luminance : float
        Display luminance (white = 1) that percentile is shown at.

    Returns
    -------
    tuple
        ``(XYZ * scale, scale)``.

    Examples
    --------
    >>> XYZ = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, 1.0], [2.0, 4.0, 2.0]])
    >>> round(expose_key(XYZ, 0, 0.5)[1], 12)
    0.25
    """
    XYZ = _as_triplets(XYZ, "XYZ")
    if not 0.0 <= float(percentile) <= 100.0:
        raise ValueError(f"percentile must lie in [0, 100], got {percentile!r}")
    if not float(luminance) > 0.0:
        raise ValueError(f"luminance must be > 0, got {luminance!r}")
    Y = XYZ[..., 1]
    on = np.isfinite(Y) & (Y > 0)
    if not on.any():
        return XYZ.copy(), 1.0
    scale = float(luminance) / float(np.percentile(Y[on], percentile))
    return XYZ * scale, scale


#: The curves :func:`compress_highlights` bends a pixel's largest channel ``M`` above the knee
#: ``k`` with, in ``x = (M - k) / (1 - k)``: each has slope 1 at the knee and tends to 1.
#: ``tanh`` reaches 1 - 1e-3 at x = 3.8 (a highlight 3.8 (1 - k) above the knee is white);
#: ``Reinhard2002``, x / (1 + x) (Reinhard et al. 2002, "Photographic tone reproduction for
#: digital images", eq. 3, L / (1 + L)), only at x = 999: a bright highlight keeps a gradient.
HIGHLIGHT_ROLLOFFS: dict[str, Callable[[npt.NDArray[np.float64]], npt.NDArray[np.float64]]] = {
    "tanh": np.tanh,
    "Reinhard2002": lambda x: x / (1.0 + x),
}


def compress_highlights(RGB_linear: npt.ArrayLike, knee: float,
                        rolloff: str = "tanh") -> npt.NDArray[np.float64]:
    """Bring colours above ``knee`` smoothly below the display maximum at constant chromaticity.

    Each pixel's linear RGB is multiplied by ``g(M) / M`` with ``M`` its largest channel and
    ``g(M) = M`` up to the knee, ``g(M) = k + (1 - k) f((M - k) / (1 - k))`` above it, ``f`` the
    ``rolloff`` of :data:`HIGHLIGHT_ROLLOFFS` (slope 1 at the knee, tending to 1). Scaling all
    three channels by one factor keeps the chromaticity, so the dominant wavelength and purity
    (and, where CIELAB is a cube root, the CIELAB hue) of a highlight stay those of the scene: a
    copper highlight stays copper instead of being clipped to white. Colours with a negative
    channel keep it (the gamut clip handles them).

    Examples
    --------
    >>> compress_highlights([[0.4, 0.2, 0.1], [1.0, 0.5, 0.25]], 0.8).round(4)
    array([[ 0.4   ,  0.2   ,  0.1   ],
           [ 0.9523,  0.4762,  0.2381]])
    >>> compress_highlights([[1.0, 0.5, 0.25]], 0.5, "Reinhard2002").round(4)
    array([[ 0.75  ,  0.375 ,  0.1875]])
    """
    RGB = _as_triplets(RGB_linear, "RGB_linear")
    k = float(knee)
    if not 0.0 < k < 1.0:
        raise ValueError(f"highlight knee must lie in (0, 1), got {knee!r}")
    if not isinstance(rolloff, str) or rolloff not in HIGHLIGHT_ROLLOFFS:
        raise ValueError(f"highlight rolloff: unknown {rolloff!r}; known: "
                         f"{', '.join(HIGHLIGHT_ROLLOFFS)}")
    M = RGB.max(axis=-1, keepdims=True)
    above = np.isfinite(M) & (M > k)
    safe = np.where(above, M, 1.0)
    g = k + (1.0 - k) * HIGHLIGHT_ROLLOFFS[rolloff]((safe - k) / (1.0 - k))
    return np.where(above, RGB * (g / safe), RGB)


def _finite_rows(RGB):
    finite = np.all(np.isfinite(RGB), axis=-1)
    return finite, np.where(finite[..., None], RGB, 0.0)


def _in_gamut(RGB):
    return np.all((RGB >= 0) & (RGB <= 1), axis=-1)


def gamut_clip_CookTorrance1982(RGB_linear: npt.ArrayLike,
                                space: str = "sRGB") -> npt.NDArray[np.float64]:
    """Desaturate toward the white of equal luminance, keeping dominant wavelength (C&T 1982).

    Cook & Torrance 1982, "Determining the RGB values": "The purity is then reduced while the
    dominant wavelength (and thus roughly the hue) is held constant until the color lies inside the
    monitor gamut." Mixing a colour with the display white of the same luminance ``Y`` keeps ``Y``
    and moves its chromaticity along the straight line to the white point, so its dominant
    wavelength (or, for purples, complementary wavelength) is unchanged and only the excitation
    purity drops. In linear RGB (white = (1, 1, 1), luminance 1) the mixture is linear in the
    retained fraction ``a``::

        RGB(a) = Y + a (RGB - Y),   Y = luminance row . RGB,   0 <= a <= 1.

    Channel i stays in [0, 1] iff ``a <= (1 - Y) / d_i`` when ``d_i = RGB_i - Y > 0`` and
    ``a <= Y / (Y - RGB_i)`` when ``d_i < 0``; the largest admissible
    ``a = min(1, min_i bound_i)`` is the closed form used here, for all pixels at once.

    Edge cases (documented choices):

    *   In-gamut colours are returned bit-identical.
    *   ``Y > 1`` (too bright for any chromaticity; does not happen after
        :func:`expose_CookTorrance1982`): ``Y`` is clamped to 1 first, which leaves only the
        display white (1, 1, 1): luminance is what the paper keeps, as closely as possible.
    *   ``Y <= 0``: black (0, 0, 0). (A colour with ``Y <= 0`` and any non-zero channel has a
        negative channel, and the bound ``Y / (Y - RGB_i)`` is 0.)
    *   Non-finite input rows give NaN rows.
    *   The result is clipped to [0, 1] to remove float rounding (~1e-16) at the active channel.

    Parameters
    ----------
    RGB_linear : array_like
        Linear display RGB, shape ``(..., 3)``.
    space : str
        One of :data:`DISPLAY_SPACES` (its luminance row defines ``Y``).

    Returns
    -------
    numpy.ndarray
        RGB in [0, 1], same shape.

    References
    ----------
    Cook & Torrance 1982, "Determining the RGB values"; CIE 15:2004 §9.1 (dominant wavelength and
    excitation purity along the line through the white point).

    Examples
    --------
    >>> gamut_clip_CookTorrance1982([1.2, 0.5, -0.1], "sRGB").round(4).tolist()
    [1.0, 0.5355, 0.1374]
    """
    RGB = _as_triplets(RGB_linear, "RGB_linear")
    finite, safe = _finite_rows(RGB)
    Y = np.clip(safe @ display_space(space).matrix_RGB_to_XYZ[1], 0.0, 1.0)[..., None]
    d = safe - Y
    # Per channel a <= numerator / |d| with numerator 1 - Y (d > 0) or Y (d < 0); only ratios
    # below 1 can bind, so divide only there (no overflow for tiny |d|).
    numerator = np.where(d > 0, 1.0 - Y, Y)
    binding = np.abs(d) > numerator
    ratio = numerator / np.where(binding, np.abs(d), 1.0)
    a = np.where(binding, ratio, 1.0).min(axis=-1, keepdims=True)
    # Cook & Torrance 1982: reduce purity at constant dominant wavelength (and luminance).
    clipped = np.clip(Y + a * d, 0.0, 1.0)
    out = np.where(_in_gamut(safe)[..., None], safe, clipped)
    return np.where(finite[..., None], out, np.nan)


def gamut_clip_channels(RGB_linear: npt.ArrayLike, space: str = "sRGB") -> npt.NDArray[np.float64]:
    """Clip each channel to [0, 1] independently (changes hue and luminance; for comparison).

    Non-finite input rows give NaN rows, as for the other methods.

    Examples
    --------
    >>> gamut_clip_channels([1.2, 0.5, -0.1]).tolist()
    [1.0, 0.5, 0.0]
    """
    display_space(space)
    finite, safe = _finite_rows(_as_triplets(RGB_linear, "RGB_linear"))
    return np.where(finite[..., None], np.clip(safe, 0.0, 1.0), np.nan)


def _oklab(RGB, ds):
    import colour  # only the css-oklch clip needs colour-science (its Oklab)

    return colour.XYZ_to_Oklab(RGB @ ds.matrix_RGB_to_XYZ.T)


def _oklab_to_RGB(Lab, ds):
    import colour

    return colour.Oklab_to_XYZ(Lab) @ ds.matrix_XYZ_to_RGB.T


def gamut_clip_CSSColor4(RGB_linear: npt.ArrayLike, space: str = "sRGB") -> npt.NDArray[np.float64]:
    """CSS Color 4 gamut mapping: binary search on OKLCh chroma with local MINDE (deltaEOK 0.02).

    Follows the CSS Color Module Level 4 algorithm "CSS gamut map" (§13.2) step by step, for all
    pixels at once: in-gamut colours are returned unchanged; OKLCh lightness >= 1 gives white and
    <= 0 black; if plain clipping is already within the JND (deltaEOK < 0.02) of the colour, the
    clipped colour is returned; otherwise chroma is bisected between 0 and the original chroma at
    constant L and h until ``max - min <= 0.0001``, accepting a clipped candidate within the JND
    (the "local MINDE"), and the last clipped candidate is returned. ``clip`` and ``inGamut`` act
    on the destination RGB, here linear RGB: equivalent to the spec's encoded RGB, since the
    transfer function maps [0, 1] monotonically onto [0, 1]. Oklab is colour-science's
    ``XYZ_to_Oklab`` of the display XYZ (Ottosson 2020, D65 white).

    Parameters
    ----------
    RGB_linear : array_like
        Linear display RGB, shape ``(..., 3)``.
    space : str
        One of :data:`DISPLAY_SPACES`.

    Returns
    -------
    numpy.ndarray
        RGB in [0, 1] (NaN rows for non-finite input).

    References
    ----------
    W3C, CSS Color Module Level 4, §13.2 "CSS Gamut Mapping to an RGB Destination" and
    its "binary search gamut mapping with local MINDE" pseudocode; deltaEOK (Euclidean distance in
    Oklab). Ottosson, B. (2020). A perceptual color space for image processing (Oklab).

    Examples
    --------
    >>> gamut_clip_CSSColor4([1.2, 0.5, -0.1], "sRGB").round(3).tolist()
    [1.0, 0.526, 0.0]
    """
    ds = display_space(space)
    RGB = _as_triplets(RGB_linear, "RGB_linear")
    shape = RGB.shape
    finite, safe = _finite_rows(RGB.reshape(-1, 3))
    out = safe.copy()
    todo = np.flatnonzero(finite & ~_in_gamut(safe))

    lab = _oklab(safe[todo], ds)
    L = lab[:, 0]
    chroma_origin = np.hypot(lab[:, 1], lab[:, 2])
    hue = np.arctan2(lab[:, 2], lab[:, 1])
    # CSS Color 4 §13.2 steps 3-4: lightness out of [0, 1] maps to white / black.
    out[todo[L >= 1]] = 1.0
    out[todo[L <= 0]] = 0.0
    search = (L > 0) & (L < 1)
    todo, L, chroma_origin, hue, lab = (
        todo[search], L[search], chroma_origin[search], hue[search], lab[search]
    )

    def delta_EOK(RGB_clipped, current_lab):
        return np.linalg.norm(_oklab(RGB_clipped, ds) - current_lab, axis=-1)

    # Steps 11-14: clip the origin; done if within the JND.
    clipped = np.clip(_oklab_to_RGB(lab, ds), 0.0, 1.0)
    active = delta_EOK(clipped, lab) >= _CSS_JND
    # Steps 15-17.
    low = np.zeros_like(L)
    high = chroma_origin.copy()
    min_in_gamut = np.ones_like(L, dtype=bool)
    # Step 18: bisection, all active pixels at once.
    while True:
        active &= high - low > _CSS_EPSILON
        i = np.flatnonzero(active)
        if i.size == 0:
            break
        chroma = 0.5 * (low[i] + high[i])
        current = np.stack([L[i], chroma * np.cos(hue[i]), chroma * np.sin(hue[i])], axis=-1)
        RGB_current = _oklab_to_RGB(current, ds)
        inside = min_in_gamut[i] & _in_gamut(RGB_current)
        low[i[inside]] = chroma[inside]
        j, RGB_j, current_j = i[~inside], RGB_current[~inside], current[~inside]
        clipped[j] = np.clip(RGB_j, 0.0, 1.0)
        E = delta_EOK(clipped[j], current_j)
        below = E < _CSS_JND
        close = below & (_CSS_JND - E < _CSS_EPSILON)
        active[j[close]] = False
        accept = below & ~close
        min_in_gamut[j[accept]] = False
        low[j[accept]] = chroma[~inside][accept]
        high[j[~below]] = chroma[~inside][~below]
    # Step 19: the last clipped candidate is the gamut-mapped colour.
    out[todo] = clipped
    out[~finite] = np.nan
    return out.reshape(shape)


GAMUT_CLIP_METHODS = {
    "dominant-wavelength": gamut_clip_CookTorrance1982,
    "clip": gamut_clip_channels,
    "css-oklch": gamut_clip_CSSColor4,
}
"""Gamut clipping methods: Cook & Torrance 1982 (constant dominant wavelength and luminance),
per-channel clipping, and CSS Color 4 (OKLCh chroma reduction)."""


def _validate_clip_method(method):
    if not isinstance(method, str) or method not in GAMUT_CLIP_METHODS:
        raise ValueError(
            f"method: unknown gamut clip method {method!r}; known: {', '.join(GAMUT_CLIP_METHODS)}"
        )


def gamut_clip(RGB_linear: npt.ArrayLike, method: str = "dominant-wavelength",
               space: str = "sRGB") -> npt.NDArray[np.float64]:
    """Bring linear display RGB into [0, 1] with one of :data:`GAMUT_CLIP_METHODS`.

    Examples
    --------
    >>> gamut_clip([0.2, 0.3, 0.4], "css-oklch").tolist()
    [0.2, 0.3, 0.4]
    """
    _validate_clip_method(method)
    return GAMUT_CLIP_METHODS[method](RGB_linear, space)


TRANSFERS = {
    "display": "the display space's transfer function (DISPLAY_SPACES)",
    "none": "none: the linear RGB written as the signal, without gamma correction (the "
            "monitor's power law then darkens the colours and raises their channel ratios to "
            "its power)",
}
"""What :func:`encode` applies: the space's transfer function, or none (a choice of a scene's
``display.transfer``)."""


def encode(RGB_linear: npt.ArrayLike, space: str = "sRGB",
           transfer: str = "display") -> npt.NDArray[np.float64]:
    """Apply the display's transfer function (linear light -> signal) to RGB in [0, 1].

    ``transfer`` 'none' (:data:`TRANSFERS`) writes the linear RGB as the signal instead: clipped
    to [0, 1], nothing else; the display shown those values applies its own EOTF to them.

    'sRGB': the IEC 61966-2-1 inverse EOTF (equals ``colour.cctf_encoding(..., function="sRGB")``).
    'SMPTE-C': the inverse of the ITU-R BT.1886 reference EOTF with L_W = 1 and L_B = 0, i.e.
    ``V = L^(1/2.4)`` (``colour.models.eotf_inverse_BT1886``); see :data:`DISPLAY_SPACES`. Both are
    defined on [0, 1] only, so input is clipped to [0, 1] first (after a gamut clip this changes
    nothing). NaN stays NaN.

    References
    ----------
    IEC 61966-2-1:1999; ITU-R BT.1886 (2011) Annex 1.

    Examples
    --------
    >>> encode([0.0, 0.0031308, 1.0], "sRGB").round(6).tolist()
    [0.0, 0.04045, 1.0]
    """
    display_space(space)
    if transfer not in TRANSFERS:
        raise ValueError(f"transfer: unknown {transfer!r}; known: {', '.join(TRANSFERS)}")
    RGB = np.clip(np.asarray(RGB_linear, dtype=np.float64), 0.0, 1.0)
    if transfer == "none":
        return RGB
    if space == "sRGB":
        return _eotf_inverse_sRGB(RGB)
    return _eotf_inverse_BT1886(RGB, L_B=0.0, L_W=1.0)


def decode_8bit(codes: npt.ArrayLike, space: str = "sRGB") -> npt.NDArray[np.float64]:
    """The linear light of 8-bit display codes (integers 0-255, any shape): the display's EOTF,
    the inverse of :func:`encode`, read from colour-science's values for the 256 codes
    (:func:`reflectance.colour.tables.transfer_decoding_8bit`: ``colour.cctf_decoding(codes / 255,
    function="sRGB")``, or ``colour.models.eotf_BT1886(codes / 255, L_B=0, L_W=1)`` for
    'SMPTE-C'), so without importing colour-science.

    Examples
    --------
    >>> decode_8bit([0, 255], "sRGB").tolist()
    [0.0, 1.0]
    """
    display_space(space)
    table = tables.transfer_decoding_8bit("sRGB" if space == "sRGB" else "BT.1886")
    codes = np.asarray(codes)
    index = codes.astype(np.intp)
    if np.any(index != codes) or np.any((index < 0) | (index > 255)):
        raise ValueError("codes: expected integers 0-255")
    return table[index]


def _spow(a, p):
    """Sign-preserving power ``sign(a) |a|^p`` (colour-science's ``spow``)."""
    return np.sign(a) * np.abs(a) ** p


def _eotf_inverse_sRGB(L):
    """IEC 61966-2-1:1999 inverse EOTF, as ``colour.models.eotf_inverse_sRGB`` (to the bit)."""
    # IEC 61966-2-1:1999 §5.2, equation (5): 12.92 L below 0.0031308, else 1.055 L^(1/2.4) - 0.055.
    return np.where(L <= 0.0031308, L * 12.92, 1.055 * _spow(L, 1 / 2.4) - 0.055)


def _eotf_inverse_BT1886(L, L_B=0.0, L_W=1.0):
    """ITU-R BT.1886 inverse reference EOTF, as ``colour.models.eotf_inverse_BT1886`` (to the bit)."""
    # ITU-R BT.1886 Annex 1: L = a max(V + b, 0)^2.4, a = (L_W^(1/2.4) - L_B^(1/2.4))^2.4,
    # b = L_B^(1/2.4) / (L_W^(1/2.4) - L_B^(1/2.4)); inverted for V.
    gamma = 2.40
    gamma_d = 1 / gamma
    n = L_W**gamma_d - L_B**gamma_d
    a = n**gamma
    b = L_B**gamma_d / n
    return _spow(L / a, gamma_d) - b


def XYZ_to_display(
    XYZ: npt.ArrayLike,
    space: str = "sRGB",
    clip: str = "dominant-wavelength",
    expose: bool = True,
    illuminant: str | npt.ArrayLike = "D65",
    observer: str = OBSERVER_DEFAULT,
    wavelengths: npt.ArrayLike | None = None,
    highlight_knee: float | None = None,
    highlight_rolloff: str = "tanh",
) -> npt.NDArray[np.float64]:
    """Scene XYZ to encoded display RGB in [0, 1]: expose, linear RGB, gamut clip, encode.

    Parameters
    ----------
    XYZ : array_like
        Scene XYZ, shape ``(..., 3)``, relative to the illuminant's white (Y = 1).
    space : str
        One of :data:`DISPLAY_SPACES`.
    clip : str
        One of :data:`GAMUT_CLIP_METHODS`.
    expose : bool
        Apply :func:`expose_CookTorrance1982` to the whole array first.
    illuminant, observer, wavelengths
        As for :func:`XYZ_to_linear_RGB`.
    highlight_knee : float, optional
        Compress colours above this linear level at constant chromaticity
        (:func:`compress_highlights`) before the gamut clip.
    highlight_rolloff : str
        The curve above the knee, one of :data:`HIGHLIGHT_ROLLOFFS`.

    Returns
    -------
    numpy.ndarray
        float64, same shape, in [0, 1] (NaN where the input was not finite).

    References
    ----------
    Cook & Torrance 1982, "Determining the RGB values".

    Examples
    --------
    >>> from reflectance.colour.colorimetry import white_XYZ
    >>> XYZ_to_display(3.0 * white_XYZ("D65")).round(12).tolist()
    [1.0, 1.0, 1.0]
    """
    display_space(space)
    _validate_clip_method(clip)
    if expose:
        XYZ, _scale = expose_CookTorrance1982(XYZ, space, illuminant, observer, wavelengths)
    RGB = XYZ_to_linear_RGB(XYZ, space, illuminant, observer, wavelengths)
    if highlight_knee is not None:
        RGB = compress_highlights(RGB, highlight_knee, highlight_rolloff)
    return encode(gamut_clip(RGB, clip, space), space)


def fresnel_XYZ_rgb(F0_XYZ: npt.ArrayLike, cos_theta: npt.ArrayLike, white: npt.ArrayLike,
                    space: str = "sRGB", *,
                    fresnel: Callable[[npt.NDArray[np.float64], npt.NDArray[np.float64]], npt.ArrayLike]
                   ) -> npt.NDArray[np.float64]:
    """XYZ of F by a three-channel RGB renderer: F0 per display channel, ``fresnel`` per channel.

    What a renderer that stores a metal as an RGB "specular colour" does: the colour of the normal
    reflectance ``F0_XYZ`` in the linear display space ``space`` with the light's ``white`` at RGB
    (1, 1, 1), clipped to [0, 1] per channel (as a base-colour texture is); then
    ``fresnel(cos_theta, F0_c)`` per channel, and back to XYZ. The renderer's table and the
    shortcut audit's ``rgb`` method pass Schlick 1994
    (:func:`reflectance.optics.fresnel.fresnel_Schlick1994`, ``F0_c + (1 - F0_c)(1 - c)^5``),
    which is linear in F0, so a spectrally flat material gives exactly the spectral Schlick
    colour. (The function is passed in because colour may not import optics: the layering of
    tests/test_architecture.py.)

    Parameters
    ----------
    F0_XYZ : array_like, shape (3,) or (..., 3)
        One material's F0 colour, or several materials' (the database audit).
    cos_theta : array_like
        Cosines of the angle of incidence.
    white : array_like, shape (3,)
        XYZ of the light (RGB (1, 1, 1)).
    space : str
    fresnel : callable
        ``fresnel(cos_theta, F0)`` -> F, broadcasting a column of cosines against the channels.

    Returns
    -------
    ndarray, shape (..., len(cos_theta), 3)
    """
    c = np.asarray(cos_theta, dtype=np.float64).reshape(-1, 1)
    F0 = np.clip(XYZ_to_linear_RGB(F0_XYZ, space, illuminant=white), 0.0, 1.0)[..., None, :]
    return linear_RGB_to_XYZ(np.asarray(fresnel(c, F0)), space, illuminant=white)


#: The transfer of :func:`encode` as a PNG tag says it: sRGB's own chunk, or the power of the
#: ITU-R BT.1886 reference EOTF with L_B = 0 (an ICC profile with that curve).
_TAG_TRANSFER = {"sRGB": "sRGB", "SMPTE-C": 2.4}


def display_tag(space: str = "sRGB") -> ColourTag:
    """The :class:`reflectance.io.images.ColourTag` of a display space, for
    :func:`reflectance.io.images.write_png`: colour-science's primaries and whitepoint of the
    space (the xy of the normalised primary matrix's columns and of its white) and the transfer of
    :func:`encode`.

    Examples
    --------
    >>> tag = display_tag("SMPTE-C")
    >>> [round(v, 3) for v in tag.primaries[0]], tag.transfer
    ([0.63, 0.34], 2.4)
    """
    from reflectance.io.images import ColourTag

    ds = display_space(space)
    columns = np.column_stack([ds.matrix_RGB_to_XYZ, ds.whitepoint_XYZ])
    xy = (columns[:2] / columns.sum(axis=0)).T
    return ColourTag(space, tuple(tuple(float(v) for v in p) for p in xy[:3]),
                     tuple(float(v) for v in xy[3]), _TAG_TRANSFER[space])
