"""Microfacet distributions D: the fraction of facets whose normal points along H.

Every distribution is a plain function of ``cos_alpha = N.H`` (the cosine of the angle alpha between
the mean surface normal N and the facet normal H) and of its roughness parameter, vectorised with
numpy broadcasting in float64 (per-pixel cosines, per-pixel roughness). Facets facing away from N
do not exist: D = 0 for N.H < 0; values of N.H above 1 come from round-off and are clipped to 1.
Scalars in give numpy scalars out.

Two conventions, named by the ``convention`` argument:

- ``"paper"``: the equations as printed, used to redraw the papers' figures. Blinn's D1, D2, D3
  peak at D(0) = 1; Cook & Torrance's Beckmann D has no 1/pi and their Gaussian an arbitrary
  constant ``c`` (default 1).
- ``"physical"``: D normalised over the hemisphere of facet normals,
  ``integral D(alpha) cos(alpha) d omega_h = 1``, the form a microfacet BRDF
  ``F D G / (4 (N.L)(N.V))`` needs to conserve energy (Walter et al. 2007, the
  projected-area condition on D).

The factor between them, per distribution (``D_paper = factor * D_physical``):

=======================================  =========================================================
Phong (Blinn D1), ``cos^c1``              ``2 pi / (c1 + 2)``
Torrance-Sparrow Gaussian (Blinn D2)      its hemispherical integral (no closed form; 64-point
                                          Gauss-Legendre, exact to float precision)
Cook & Torrance Gaussian (c = 1)          the same, with ``c2 = 1/m``
Trowbridge-Reitz (Blinn D3)               ``pi c3^2`` (the physical form is GGX with alpha = c3)
Beckmann (Cook & Torrance)                ``pi``
=======================================  =========================================================

For the Beckmann function this makes Cook & Torrance's specular term, ``F D_p G / (pi (N.L)(N.V))``
with ``D_p = pi D_phys``, equal to ``F D_phys G / ((N.L)(N.V))``: four times the normalised
``F D_phys G / (4 (N.L)(N.V))`` (see :mod:`reflectance.optics.brdf`).

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (D1, D2, D3; beta and its inverse from c3;
  texture-modulated C3.)
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24. (Gaussian and Beckmann D, weighted sum of D.)
- Torrance, K. E., & Sparrow, E. M. (1967). Theory for off-specular reflection from roughened
  surfaces. J. Opt. Soc. Am., 57(9), 1105-1114.
- Trowbridge, T. S., & Reitz, K. P. (1975). Average irregularity representation of a roughened
  surface for ray reflection. J. Opt. Soc. Am., 65(5), 531-536.
- Beckmann, P., & Spizzichino, A. (1963). The Scattering of Electromagnetic Waves from Rough
  Surfaces. Pergamon / MacMillan.
- Walter, B., Marschner, S. R., Li, H., & Torrance, K. E. (2007). Microfacet Models for Refraction
  through Rough Surfaces. Eurographics Symposium on Rendering. (Normalisation of D; Beckmann
  with 1/pi; GGX.)
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = [
    "CONVENTIONS",
    "distribution_Phong1975",
    "distribution_TorranceSparrow1967",
    "distribution_TrowbridgeReitz1975",
    "c3_texture_Blinn1977",
    "distribution_TrowbridgeReitz_texture_Blinn1977",
    "distribution_Beckmann1963",
    "distribution_Gaussian_CookTorrance1982",
    "distribution_mixture",
    "beta_to_c1_Blinn1977",
    "c1_to_beta_Blinn1977",
    "beta_to_c2_Blinn1977",
    "beta_to_c3_Blinn1977",
    "C3_MAX_FOR_BETA",
    "c3_to_beta_Blinn1977",
    "DISTRIBUTION_METHODS",
    "ROUGHNESS_PARAMETERS",
    "distribution",
]

CONVENTIONS = ("paper", "physical")
"""Normalisation conventions: equations as printed, or normalised over the hemisphere."""


# --- helpers ------------------------------------------------------------------------------------

def _out(x):
    """Return a numpy scalar for 0-d results, the array otherwise."""
    return x[()] if np.ndim(x) == 0 else x


def _cos(cos_alpha: npt.ArrayLike) -> npt.NDArray[np.float64]:
    # D is defined for facets facing the mean normal only: N.H in [0, 1] (see _facing).
    return np.clip(np.asarray(cos_alpha, dtype=np.float64), 0.0, 1.0)


def _facing(cos_alpha, D):
    """D where N.H >= 0, 0 for facets facing away (NaN propagates)."""
    return np.where(np.asarray(cos_alpha, dtype=np.float64) < 0, 0.0, D)


def _check_convention(convention):
    if convention not in CONVENTIONS:
        raise ValueError(
            f"Unknown convention {convention!r}; known conventions: {', '.join(CONVENTIONS)}."
        )


def _check_positive(name: str, value: npt.ArrayLike,
                    allow_zero: bool = False) -> npt.NDArray[np.float64]:
    value = np.asarray(value, dtype=np.float64)
    # NaN compares False: NaN parameters propagate instead of raising.
    bad = (value < 0) if allow_zero else (value <= 0)
    if np.any(bad) or np.any(np.isinf(value)):
        bound = ">= 0" if allow_zero else "> 0"
        raise ValueError(f"'{name}' must be finite and {bound}, got {value!r}.")
    return value


# 64-point Gauss-Legendre rule on [-1, 1] (numpy.polynomial.legendre.leggauss), used to normalise
# the Gaussians, whose hemispherical integral has no closed form.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(64)


def _gaussian_hemisphere_integral(k):
    """``2 pi integral_0^{pi/2} exp(-(alpha k)^2) cos(alpha) sin(alpha) d alpha`` for any k >= 0.

    The integrand is below 1e-35 beyond ``alpha = 9 / k``; integrating over
    ``[0, min(pi/2, 9/k)]`` with 64 Gauss-Legendre nodes is exact to float precision for every k
    (a smooth Gaussian sampled across its whole width).
    """
    k = np.asarray(k, dtype=np.float64)[..., None]
    b = np.minimum(np.pi / 2, 9.0 / np.maximum(k, 1e-300))
    alpha = 0.5 * b * (_GL_X + 1.0)
    integrand = np.exp(-((alpha * k) ** 2)) * np.cos(alpha) * np.sin(alpha)
    return 2.0 * np.pi * 0.5 * b[..., 0] * np.sum(_GL_W * integrand, axis=-1)


def _gaussian_of_angle(cos_alpha, k):
    """``exp(-(alpha k)^2)`` with ``alpha = arccos(N.H)``: the shape shared by Blinn's D2 and Cook &
    Torrance's Gaussian (k = c2 = 1/m)."""
    alpha = np.arccos(cos_alpha)
    return np.exp(-((alpha * k) ** 2))


# --- Blinn 1977: D1, D2, D3 -----------------------------------------------------------------------

def distribution_Phong1975(cos_alpha: npt.ArrayLike, c1: npt.ArrayLike,
                           convention: str = "paper") -> npt.NDArray[np.float64] | np.float64:
    """Phong's cosine power as a facet distribution: Blinn's D1 = cos^c1(alpha).

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    c1 : array_like
        Exponent ("measure of shininess", typically 50 or 60 in Blinn 1977), >= 0.
    convention : str
        ``"paper"``: ``cos^c1 alpha`` (D(0) = 1). ``"physical"``: ``(c1 + 2) / (2 pi) cos^c1 alpha``,
        whose ``integral D cos(alpha) d omega`` is 1 since ``2 pi integral_0^1 mu^(c1+1) d mu =
        2 pi / (c1 + 2)``.

    Returns
    -------
    numpy.ndarray or numpy.float64

    References
    ----------
    - Blinn 1977, "Facet distribution functions", D1.
    - Phong, B. T. (1975). Illumination for computer generated pictures. Comm. ACM 18(6), 311-317.

    Examples
    --------
    >>> print(f"{distribution_Phong1975(0.5, 2.0):.4f}")
    0.2500
    """
    _check_convention(convention)
    c1 = _check_positive("c1", c1, allow_zero=True)
    c = _cos(cos_alpha)
    D = c**c1  # Blinn 1977, D1 = cos^c1 alpha
    if convention == "physical":
        D = D * (c1 + 2.0) / (2.0 * np.pi)
    return _out(_facing(cos_alpha, D))


def distribution_TorranceSparrow1967(cos_alpha: npt.ArrayLike, c2: npt.ArrayLike,
                                     convention: str = "paper"
                                    ) -> npt.NDArray[np.float64] | np.float64:
    """Torrance & Sparrow's Gaussian in the facet angle, as Blinn writes it: D2 = exp(-(alpha c2)^2).

    Note that ``c2`` is an *inverse* width: large ``c2`` gives a narrow lobe (a shiny surface). Blinn
    calls it "the standard deviation" and says "large values yield dull surfaces"; with his
    formula the opposite holds (``c2 = 1 / (sqrt(2) sigma)`` for a Gaussian of standard deviation
    sigma in alpha). Cook & Torrance's Gaussian is the same shape with ``c2 = 1/m``.

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``; ``alpha = arccos(N.H)`` in radians.
    c2 : array_like
        Inverse angular width, >= 0 (1/radian).
    convention : str
        ``"paper"`` (D(0) = 1) or ``"physical"`` (divided by its hemispherical integral, computed
        by Gauss-Legendre quadrature).

    References
    ----------
    - Blinn 1977, "Torrance-Sparrow model" and "Facet distribution functions", D2.
    - Torrance & Sparrow 1967.

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{distribution_TorranceSparrow1967(np.cos(0.1), 10.0):.6f}")  # exp(-1)
    0.367879
    """
    _check_convention(convention)
    c2 = _check_positive("c2", c2, allow_zero=True)
    D = _gaussian_of_angle(_cos(cos_alpha), c2)  # Blinn 1977, D2 = exp(-(alpha c2)^2)
    if convention == "physical":
        D = D / _gaussian_hemisphere_integral(c2)
    return _out(_facing(cos_alpha, D))


def distribution_TrowbridgeReitz1975(cos_alpha: npt.ArrayLike, c3: npt.ArrayLike,
                                     convention: str = "paper"
                                    ) -> npt.NDArray[np.float64] | np.float64:
    """Trowbridge & Reitz's ellipsoid distribution in Blinn's normalisation, D3.

    ``D3 = (c3^2 / (cos^2 alpha (c3^2 - 1) + 1))^2``. Blinn multiplies Trowbridge & Reitz's
    original by ``c3^2`` so that D3(0) = 1. The normalised (``"physical"``) form is
    ``D3 / (pi c3^2)``, which is the GGX distribution of Walter et al. 2007 with roughness
    ``alpha_g = c3``.

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    c3 : array_like
        Eccentricity of the ellipsoids, > 0: 0 for very shiny, 1 for very diffuse (D3 = 1).
    convention : str
        ``"paper"`` or ``"physical"``.

    References
    ----------
    - Blinn 1977, "Facet distribution functions", D3; "Computational considerations" (k1, k2).
    - Trowbridge & Reitz 1975.
    - Walter et al. 2007, GGX distribution.

    Examples
    --------
    >>> print(f"{distribution_TrowbridgeReitz1975(1.0, 0.5):.4f}")
    1.0000
    """
    _check_convention(convention)
    c3 = _check_positive("c3", c3)
    c = _cos(cos_alpha)
    c3_2 = c3 * c3
    D = (c3_2 / (c * c * (c3_2 - 1.0) + 1.0)) ** 2  # Blinn 1977, D3
    if convention == "physical":
        D = D / (np.pi * c3_2)
    return _out(_facing(cos_alpha, D))


def c3_texture_Blinn1977(t: npt.ArrayLike,
                         c_min: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Texture-modulated roughness: ``C3 = C_min + (1 - C_min) t(u, v)``.

    References
    ----------
    - Blinn 1977, "Varying surface shininess".

    Examples
    --------
    >>> print(f"{c3_texture_Blinn1977(0.5, 0.2):.2f}")
    0.60
    """
    c_min = _check_positive("c_min", c_min)
    t = np.asarray(t, dtype=np.float64)
    return _out(c_min + (1.0 - c_min) * t)  # Blinn 1977, C3 = C_min + (1 - C_min) t(u, v)


def distribution_TrowbridgeReitz_texture_Blinn1977(cos_alpha: npt.ArrayLike, c3: npt.ArrayLike,
                                                   c_min: npt.ArrayLike
                                                  ) -> npt.NDArray[np.float64] | np.float64:
    """D3 for a roughness C3 varying over the surface, normalised by its minimum C_min.

    ``D3 = [C_min C3 / (cos^2 alpha (C3^2 - 1) + 1)]^2``, equal to
    :func:`distribution_TrowbridgeReitz1975` where ``C3 = C_min`` (t = 0). Defined only as
    printed (a "physical" D for a per-point roughness is the GGX of the local ``c3``).

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    c3 : array_like
        Local C3 (see :func:`c3_texture_Blinn1977`), > 0.
    c_min : array_like
        Minimum of C3 over the surface, > 0.

    References
    ----------
    - Blinn 1977, "Varying surface shininess".

    Examples
    --------
    >>> print(f"{distribution_TrowbridgeReitz_texture_Blinn1977(1.0, 0.5, 0.25):.4f}")
    0.2500
    """
    c3 = _check_positive("c3", c3)
    c_min = _check_positive("c_min", c_min)
    c = _cos(cos_alpha)
    D = (c_min * c3 / (c * c * (c3 * c3 - 1.0) + 1.0)) ** 2  # Blinn 1977, texture-modulated D3
    return _out(_facing(cos_alpha, D))


# --- Cook & Torrance 1982 -------------------------------------------------------------------------

def distribution_Beckmann1963(cos_alpha: npt.ArrayLike, m: npt.ArrayLike,
                              convention: str = "paper") -> npt.NDArray[np.float64] | np.float64:
    """Beckmann distribution, as Cook & Torrance print it or normalised.

    ``"paper"``: ``D = exp(-(tan alpha / m)^2) / (m^2 cos^4 alpha)`` (no 1/pi).
    ``"physical"``: the same divided by pi, whose ``integral D cos(alpha) d omega`` is 1.

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    m : array_like
        Root mean square slope of the facets, > 0.
    convention : str
        ``"paper"`` or ``"physical"``.

    References
    ----------
    - Cook & Torrance 1982, "Directional distribution of the reflected light", Beckmann D.
    - Beckmann & Spizzichino 1963.
    - Walter et al. 2007, Beckmann distribution (with 1/pi).

    Examples
    --------
    >>> import numpy as np
    >>> m = 0.5
    >>> c = 1 / np.sqrt(1 + m * m)  # tan(alpha) = m
    >>> print(f"{distribution_Beckmann1963(c, m):.6f}", f"{np.exp(-1) * (1 + m * m) ** 2 / (m * m):.6f}")
    2.299247 2.299247
    """
    _check_convention(convention)
    m = _check_positive("m", m)
    c = _cos(cos_alpha)
    # Below cos = 1e-100 the exponent is < -1e200 / m^2 and D is 0 (its limit); substituting
    # c = 1 there keeps every intermediate finite, and the result is then replaced by 0.
    tiny = c <= 1e-100
    cs = np.where(tiny, 1.0, c)
    c2 = cs * cs
    tan2 = (1.0 - c2) / c2
    m2 = m * m
    D = np.exp(-tan2 / m2) / m2 / c2 / c2  # Cook & Torrance 1982, Beckmann D
    D = np.where(tiny, 0.0, D)
    if convention == "physical":
        D = D / np.pi  # Walter et al. 2007, normalised Beckmann
    return _out(_facing(cos_alpha, D))


def distribution_Gaussian_CookTorrance1982(cos_alpha: npt.ArrayLike, m: npt.ArrayLike,
                                           c: npt.ArrayLike | None = None,
                                           convention: str = "paper"
                                          ) -> npt.NDArray[np.float64] | np.float64:
    """Cook & Torrance's Gaussian model ``D = c exp(-(alpha/m)^2)``.

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    m : array_like
        Width, > 0 (radians; Cook & Torrance call it the rms slope).
    c : array_like, optional
        "An arbitrary constant": 1 by default with ``convention="paper"``. With
        ``convention="physical"`` c is the normalising constant and must not be given.
    convention : str
        ``"paper"`` or ``"physical"``.

    References
    ----------
    - Cook & Torrance 1982, "Directional distribution of the reflected light", Gaussian D.
    - Torrance & Sparrow 1967.

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{distribution_Gaussian_CookTorrance1982(np.cos(0.2), 0.2):.6f}")  # exp(-1)
    0.367879
    """
    _check_convention(convention)
    m = _check_positive("m", m)
    if convention == "physical" and c is not None:
        raise ValueError(
            "'c' is set by the normalisation with convention='physical'; pass c only with "
            "convention='paper'."
        )
    D = _gaussian_of_angle(_cos(cos_alpha), 1.0 / m)  # Cook & Torrance 1982, D = c exp(-(alpha/m)^2)
    if convention == "physical":
        return _out(_facing(cos_alpha, D / _gaussian_hemisphere_integral(1.0 / m)))
    return _out(_facing(cos_alpha, (1.0 if c is None else np.asarray(c, dtype=np.float64)) * D))


# --- Blinn's half-angle beta ----------------------------------------------------------------------

def _check_beta(beta: npt.ArrayLike) -> npt.NDArray[np.float64]:
    beta = np.asarray(beta, dtype=np.float64)
    if np.any((beta <= 0) | (beta >= np.pi / 2)):
        raise ValueError(f"'beta' (radians) must lie in (0, pi/2), got {beta!r}.")
    return beta


def beta_to_c1_Blinn1977(beta: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Exponent c1 of D1 that falls to 1/2 at alpha = beta: ``c1 = -ln 2 / ln cos beta``.

    References
    ----------
    - Blinn 1977, "Facet distribution functions".

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{beta_to_c1_Blinn1977(np.pi / 3):.4f}")  # cos = 1/2
    1.0000
    """
    beta = _check_beta(beta)
    return _out(-np.log(2.0) / np.log(np.cos(beta)))  # Blinn 1977, c1(beta)


def c1_to_beta_Blinn1977(c1: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Half-value angle beta of D1 = cos^c1(alpha), the inverse of :func:`beta_to_c1_Blinn1977`:
    ``beta = arccos(2^(-1/c1))``.

    References
    ----------
    - Blinn 1977, "Facet distribution functions".

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{np.degrees(c1_to_beta_Blinn1977(1.0)):.4f}")  # cos beta = 1/2
    60.0000
    >>> print(f"{beta_to_c1_Blinn1977(c1_to_beta_Blinn1977(50.0)):.6f}")
    50.000000
    """
    c1 = np.asarray(c1, dtype=np.float64)
    if not np.all(np.isfinite(c1) & (c1 > 0)):
        raise ValueError(f"c1 must be positive and finite, got {c1!r}")
    return _out(np.arccos(0.5 ** (1.0 / c1)))  # Blinn 1977, D1(beta) = 1/2


def beta_to_c2_Blinn1977(beta: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Inverse width c2 of D2 that falls to 1/2 at alpha = beta: ``c2 = sqrt(ln 2) / beta``.

    References
    ----------
    - Blinn 1977, "Facet distribution functions".

    Examples
    --------
    >>> print(f"{beta_to_c2_Blinn1977(0.5):.6f}")
    1.665109
    """
    beta = _check_beta(beta)
    return _out(np.sqrt(np.log(2.0)) / beta)  # Blinn 1977, c2(beta)


def beta_to_c3_Blinn1977(beta: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Eccentricity c3 of D3 that falls to 1/2 at alpha = beta:
    ``c3 = ((cos^2 beta - 1) / (cos^2 beta - sqrt 2))^(1/2)``.

    References
    ----------
    - Blinn 1977, "Facet distribution functions".

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{beta_to_c3_Blinn1977(np.pi / 4):.6f}")  # sqrt(0.5 / (sqrt(2) - 0.5))
    0.739539
    """
    beta = _check_beta(beta)
    c2 = np.cos(beta) ** 2
    return _out(np.sqrt((c2 - 1.0) / (c2 - np.sqrt(2.0))))  # Blinn 1977, c3(beta)


C3_MAX_FOR_BETA = 2.0**-0.25
"""Largest ``c3`` whose D3 still falls to one half before ``alpha = 90`` degrees (``c3^4 = 1/2``)."""


def c3_to_beta_Blinn1977(c3: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Half-value angle ``beta`` (radians) of Blinn's D3 with eccentricity ``c3``: the inverse of
    :func:`beta_to_c3_Blinn1977`.

    Blinn compares D1, D2 and D3 at equal ``beta`` but prints his material parameters as ``c3``
    (Figs. 7a, 7b), so comparing Phong with Torrance-Sparrow at equal ``beta`` needs ``beta`` from
    ``c3``. Solving ``c3^2 = (cos^2 beta - 1) / (cos^2 beta - sqrt 2)`` for ``cos^2 beta`` gives
    ``beta = arccos(sqrt((1 - sqrt(2) c3^2) / (1 - c3^2)))``. D3 at ``alpha = 90`` degrees is
    ``c3^4``, so ``beta`` exists only while ``c3^4 < 1/2``, i.e. ``c3 < 2^(-1/4)``.

    Parameters
    ----------
    c3 : array_like
        Eccentricity, ``0 < c3 < 2^(-1/4)`` (about 0.8409, :data:`C3_MAX_FOR_BETA`).

    Returns
    -------
    numpy.ndarray or numpy.float64
        ``beta`` in radians, in ``(0, pi/2)``.

    Raises
    ------
    ValueError
        If ``c3`` is outside ``(0, 2^(-1/4))``: for larger ``c3``, D3 never falls to one half.

    References
    ----------
    - Blinn 1977, "Facet distribution functions", c3(beta).

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{np.degrees(c3_to_beta_Blinn1977(0.35)):.4f}")  # Blinn Fig. 7b, MgO
    13.9141
    """
    c3 = np.asarray(c3, dtype=np.float64)
    if np.any(~((c3 > 0) & (c3 < C3_MAX_FOR_BETA))):
        raise ValueError(
            f"'c3' must lie in (0, 2^(-1/4) = {C3_MAX_FOR_BETA:.6f}) for D3 to fall to one half, "
            f"got {c3!r}."
        )
    c3_2 = c3 * c3
    cos2_beta = (1.0 - np.sqrt(2.0) * c3_2) / (1.0 - c3_2)  # Blinn 1977, c3(beta) solved for cos^2 beta
    return _out(np.arccos(np.sqrt(np.clip(cos2_beta, 0.0, 1.0))))


# --- mixture and dispatcher -----------------------------------------------------------------------

DISTRIBUTION_METHODS = {
    "Phong1975": distribution_Phong1975,
    "TorranceSparrow1967": distribution_TorranceSparrow1967,
    "TrowbridgeReitz1975": distribution_TrowbridgeReitz1975,
    "TrowbridgeReitz_texture_Blinn1977": distribution_TrowbridgeReitz_texture_Blinn1977,
    "Beckmann1963": distribution_Beckmann1963,
    "Gaussian_CookTorrance1982": distribution_Gaussian_CookTorrance1982,
}
"""Facet distributions of :func:`distribution`, each ``f(cos_alpha, <roughness>, ...)``
(``"mixture"`` is added below)."""

ROUGHNESS_PARAMETERS = {
    "Phong1975": "c1",
    "TorranceSparrow1967": "c2",
    "TrowbridgeReitz1975": "c3",
    "TrowbridgeReitz_texture_Blinn1977": "c3",
    "Beckmann1963": "m",
    "Gaussian_CookTorrance1982": "m",
}
"""Name of each distribution's roughness argument (what a bare number in a mixture lobe sets)."""


def _method(method):
    try:
        return DISTRIBUTION_METHODS[method]
    except (KeyError, TypeError):
        raise ValueError(
            f"Unknown distribution method {method!r}; known methods: "
            f"{', '.join(DISTRIBUTION_METHODS)}."
        ) from None


def distribution_mixture(cos_alpha: npt.ArrayLike,
                         lobes: Iterable[tuple[float, float | Mapping[str, Any]]],
                         base: str = "Beckmann1963",
                         convention: str = "paper") -> npt.NDArray[np.float64] | np.float64:
    """Weighted sum of distributions of one kind: ``D = sum_j w_j D(m_j)``, ``sum_j w_j = 1``.

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    lobes : sequence of (weight, roughness)
        ``roughness`` is a number (the base distribution's roughness argument, see
        :data:`ROUGHNESS_PARAMETERS`) or a dict of its keyword arguments. Weights are >= 0 and
        sum to 1 (to 1e-9).
    base : str
        A method of :data:`DISTRIBUTION_METHODS` other than the mixture itself.
    convention : str
        Passed to every lobe that has one (a weighted sum of normalised lobes is normalised).

    References
    ----------
    - Cook & Torrance 1982, "Directional distribution of the reflected light", D = sum w_j D(m_j)
      (copper vase of Fig. 6b: m1 = 0.4, w1 = 0.4, m2 = 0.2, w2 = 0.6).
    - Wikipedia, "Specular highlight" (oldid 793299363), "Using multiple distributions".

    Examples
    --------
    >>> import numpy as np
    >>> d = distribution_mixture(0.9, [(0.4, 0.4), (0.6, 0.2)])
    >>> lobes = 0.4 * distribution_Beckmann1963(0.9, 0.4) + 0.6 * distribution_Beckmann1963(0.9, 0.2)
    >>> bool(np.isclose(d, lobes))
    True
    """
    function = _method(base)
    try:
        pairs = [(float(w), r) for w, r in lobes]
    except (TypeError, ValueError):
        raise ValueError(
            f"'lobes' must be a sequence of (weight, roughness) pairs, got {lobes!r}."
        ) from None
    if not pairs:
        raise ValueError("'lobes' is empty; give at least one (weight, roughness) pair.")
    weights = np.array([w for w, _ in pairs])
    if np.any(weights < 0) or abs(weights.sum() - 1.0) > 1e-9:
        raise ValueError(
            f"Mixture weights must be >= 0 and sum to 1 (Cook & Torrance 1982), got {weights.tolist()}."
        )
    extra = {} if base == "TrowbridgeReitz_texture_Blinn1977" else {"convention": convention}
    total = 0.0
    for w, roughness in pairs:
        kwargs = dict(roughness) if isinstance(roughness, dict) else {ROUGHNESS_PARAMETERS[base]: roughness}
        total = total + w * function(cos_alpha, **kwargs, **extra)  # Cook & Torrance 1982, sum w_j D(m_j)
    return _out(np.asarray(total, dtype=np.float64))


DISTRIBUTION_METHODS["mixture"] = distribution_mixture


def distribution(cos_alpha: npt.ArrayLike, method: str = "Beckmann1963",
                 **kwargs: Any) -> npt.NDArray[np.float64] | np.float64:
    """Facet distribution D by one of :data:`DISTRIBUTION_METHODS`.

    Parameters
    ----------
    cos_alpha : array_like
        ``N.H``.
    method : str
        ``"Phong1975"`` (Blinn D1, ``c1``), ``"TorranceSparrow1967"`` (Blinn D2, ``c2``),
        ``"TrowbridgeReitz1975"`` (Blinn D3, ``c3``), ``"TrowbridgeReitz_texture_Blinn1977"``
        (``c3, c_min``), ``"Beckmann1963"`` (``m``), ``"Gaussian_CookTorrance1982"`` (``m, c``) or
        ``"mixture"`` (``lobes, base``).
    **kwargs
        The method's parameters, and ``convention`` (``"paper"`` or ``"physical"``) where it has one.

    Raises
    ------
    ValueError
        For an unknown method (listing the known ones) or wrong parameters (naming them).

    Examples
    --------
    >>> print(f"{distribution(1.0, 'Beckmann1963', m=0.5, convention='physical'):.6f}")  # 1/(pi m^2)
    1.273240
    """
    function = _method(method)
    try:
        return function(cos_alpha, **kwargs)
    except TypeError as error:
        raise ValueError(f"Bad parameters {sorted(kwargs)} for distribution {method!r}: {error}") from None
