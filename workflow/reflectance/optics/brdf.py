"""Reflectance models of the four texts, as BRDFs assembled from D, G and F.

Every model is a plain function of cosines (``NL = N.L``, ``NV = N.V``, ``NH = N.H``,
``VH = V.H``, and for some models ``R.V``, ``H.X``, ``H.Y``, ``L.T``, ``V.T``, ``L.V``), vectorised
with numpy broadcasting in float64, so a renderer can call it on arrays of per-pixel cosines;
:func:`brdf` computes those cosines from unit vectors (arrays ``(..., 3)``) and calls one of
:data:`BRDF_METHODS`.

What each model returns is a BRDF ``f(L, V)``: reflected intensity per unit incident energy
``E_i = I_i (N.L) d omega_i`` (Cook & Torrance's bidirectional reflectance R). A renderer shades
with :func:`intensity_CookTorrance1982`,
``I_r = I_ia R_a + sum_l I_il (N.L_l) d omega_il f_l``. Models that the texts print as intensities
(Blinn's ``i = p_a + d p_d + s p_s`` with ``d = N.L``; the article's Heidrich-Seidel ``k_diff``,
``k_spec``) are written in this form by dividing their light-dependent part by ``N.L``, so that
``(N.L) f`` is exactly the printed expression; Blinn's ``p_a`` is then ``I_ia R_a`` with
``I_ia = 1``. Every f is 0 where the light or the viewer is at or below the horizon (the article's
"(A.B) means max(0, A.B)"; Blinn: "If this dot product is negative ... set to zero").

Conventions (``convention=``), for the models with a microfacet D:

- ``"paper"``: as printed. Cook & Torrance: ``R_s = F D G / (pi (N.L)(N.V))`` with their
  Beckmann D (no 1/pi).
- ``"physical"``: ``R_s = F D G / (4 (N.L)(N.V))`` with D normalised over the hemisphere
  (:mod:`reflectance.optics.microfacet`), the form of Walter et al. 2007 and of the article's
  Cook-Torrance ``k_spec``.
- ``"lecture"`` (Cook-Torrance only): as the lecture's slides print it, ``BRDF = s R_s + d R_d``
  with ``R_s = D G F / (N.V)`` and the slide's Beckmann ``D = exp(-(tan d / m)^2) / (4 m^2 cos^4 d)``
  (Cook & Torrance's printed D over 4). Against ``"physical"`` its specular term is
  ``pi (N.L)`` times larger.

For the Beckmann function ``D_paper = pi D_phys``, so ``R_s(paper) = F D_phys G / ((N.L)(N.V))
= 4 R_s(physical)``: with F = 1 the paper's directional albedo is four times the physical one.

Spectral use: F (and ``R_d``) may carry a trailing wavelength axis; give the cosines a matching
trailing axis (``NL[..., None]``), or let :func:`brdf` do it when it evaluates F from ``n, k``.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198.
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24.
- Russin, B. Advanced Reflection Models (lecture, Module 3B, 605.767 Applied Computer Graphics,
  Johns Hopkins Engineering for Professionals); Akenine-Moller, T., Haines, E., & Hoffman, N.
  (2008). Real-Time Rendering (3rd ed.), Sec. 7.6 (normalised Blinn-Phong).
- Wikipedia, "Specular highlight", oldid 793299363 (31 July 2017): Ward and Heidrich-Seidel.
- Ward, G. J. (1992). Measuring and Modeling Anisotropic Reflection. Computer Graphics
  (SIGGRAPH '92), 26(2), 265-272.
- Heidrich, W., & Seidel, H.-P. (1998). Efficient Rendering of Anisotropic Surfaces Using Computer
  Graphics Hardware. Proc. Image and Multi-dimensional Digital Signal Processing Workshop.
- Walter, B., Marschner, S. R., Li, H., & Torrance, K. E. (2007). Microfacet Models for Refraction
  through Rough Surfaces. Eurographics Symposium on Rendering.
- Hapke, B. (1981). Bidirectional reflectance spectroscopy 1. Theory. Journal of Geophysical
  Research 86(B4), 3039-3054; Hapke, B. (1986). Bidirectional reflectance spectroscopy 4. The
  extinction coefficient and the opposition effect. Icarus 67, 264-280 (the lunar lobe).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt

from reflectance.optics.microfacet import CONVENTIONS, distribution
from reflectance.optics.shadowing import G_over_NE_Blinn1977, shadowing

__all__ = [
    "brdf_Lambert",
    "brdf_Phong1975",
    "brdf_BlinnPhong1977",
    "brdf_BlinnPhong_AkenineMoller2008",
    "brdf_TorranceSparrow_Blinn1977",
    "brdf_CookTorrance1982",
    "brdf_Ward1992",
    "brdf_HeidrichSeidel1998",
    "brdf_LommelSeeliger",
    "brdf_Hapke1981",
    "ambient_reflectance_CookTorrance1982",
    "intensity_CookTorrance1982",
    "BRDF_METHODS",
    "COOK_TORRANCE_CONVENTIONS",
    "brdf",
    "directional_albedo",
]


# --- helpers ------------------------------------------------------------------------------------

def _out(x):
    x = np.asarray(x, dtype=np.float64)
    return x[()] if x.ndim == 0 else x


def _cosines(*cosines: npt.ArrayLike) -> list[npt.NDArray[np.float64]]:
    # Round-off can push a cosine of unit vectors outside [-1, 1].
    return [np.clip(np.asarray(c, dtype=np.float64), -1.0, 1.0) for c in cosines]


def _lit_and_seen(NL, NV):
    return (NL > 0) & (NV > 0)


def _positive(x):
    """A safe denominator: x where x > 0 (floored at 1e-150, so that dividing by two cosines stays
    below ~1e300; the renderer's product f (N.L) is unaffected for N.L >= 1e-150), and 1 where
    x <= 0, where the callers mask the result to 0."""
    return np.where(x > 0, np.maximum(x, 1e-150), 1.0)


#: Cook-Torrance's conventions: the microfacet ones and the lecture's printed form
COOK_TORRANCE_CONVENTIONS = (*CONVENTIONS, "lecture")


def _check_convention(convention, known=CONVENTIONS):
    if convention not in known:
        raise ValueError(
            f"Unknown convention {convention!r}; known conventions: {', '.join(known)}."
        )


def _fresnel_values(F: npt.ArrayLike | Callable[[npt.NDArray[np.float64]], npt.ArrayLike] | None,
                    VH: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """F given as values (broadcasting against the cosines) or as a function of ``cos_theta``."""
    if F is None:
        raise ValueError("This model needs the Fresnel term 'F' (values or a function of V.H).")
    return np.asarray(F(VH) if callable(F) else F, dtype=np.float64)


def _distribution_values(NH, method, convention, parameters):
    if method == "TrowbridgeReitz_texture_Blinn1977":
        if convention != "paper":
            raise ValueError(
                "The texture-modulated D3 of Blinn 1977 exists only as printed (convention='paper')."
            )
        return distribution(NH, method, **parameters)
    return distribution(NH, method, convention=convention, **parameters)


# --- diffuse and empirical models -----------------------------------------------------------------

def brdf_Lambert(NL: npt.ArrayLike, NV: npt.ArrayLike, rho_d: npt.ArrayLike = 1.0,
                 convention: str = "physical") -> npt.NDArray[np.float64] | np.float64:
    """Lambertian diffuse reflection.

    ``"paper"``: ``f = p_d`` (Blinn 1977: ``i = p_a + d p_d`` with ``d = max(0, N.L)``).
    ``"physical"``: ``f = rho_d / pi`` for a diffuse albedo ``rho_d``.

    Parameters
    ----------
    NL, NV : array_like
        ``N.L`` and ``N.V``.
    rho_d : array_like
        ``p_d`` (paper) or the albedo (physical); may be spectral.
    convention : str
        ``"paper"`` or ``"physical"``.

    References
    ----------
    - Blinn 1977, "Introduction" (Lambert's law with ambient); Cook & Torrance 1982, R_d.

    Examples
    --------
    >>> print(f"{brdf_Lambert(0.5, 0.5, 0.8) * 3.141592653589793:.6f}")
    0.800000
    """
    _check_convention(convention)
    NL, NV = _cosines(NL, NV)
    rho_d = np.asarray(rho_d, dtype=np.float64)
    f = rho_d if convention == "paper" else rho_d / np.pi  # Blinn 1977, i = p_a + d p_d
    return _out(np.where(_lit_and_seen(NL, NV), f, 0.0))


def brdf_Phong1975(NL: npt.ArrayLike, NV: npt.ArrayLike, RV: npt.ArrayLike,
                   p_d: npt.ArrayLike = 0.0, p_s: npt.ArrayLike = 1.0,
                   c1: npt.ArrayLike = 50.0) -> npt.NDArray[np.float64] | np.float64:
    """Phong's model with the mirror direction, ``i = p_a + d p_d + s p_s``, ``s = (R.V)^c1``.

    ``R = 2 (N.L) N - L`` is the mirror reflection of L, so ``R.V = 2 (N.L)(N.V) - L.V``. As a
    BRDF, ``f = p_d + p_s max(0, R.V)^c1 / (N.L)``. Not reciprocal (the specular term lacks the
    ``N.L`` that the diffuse term has), and unbounded as ``N.L -> 0`` although ``(N.L) f`` is not.

    Parameters
    ----------
    NL, NV, RV : array_like
        ``N.L``, ``N.V``, ``R.V``.
    p_d, p_s : array_like
        Proportions of diffuse and specular reflection.
    c1 : array_like
        Exponent ("typically 50 or 60").

    References
    ----------
    - Phong, B. T. (1975). Illumination for computer generated pictures. Comm. ACM 18(6), 311-317.
    - Wikipedia, "Specular highlight", "Phong distribution" (``(R.V)^n``).

    Examples
    --------
    >>> print(f"{brdf_Phong1975(0.5, 0.5, 1.0, p_d=0.0, p_s=1.0, c1=10) * 0.5:.3f}")
    1.000
    """
    NL, NV, RV = _cosines(NL, NV, RV)
    s = np.maximum(RV, 0.0) ** np.asarray(c1, dtype=np.float64)  # Phong 1975, s = (R.V)^c1
    f = p_d + p_s * s / _positive(NL)  # i = p_a + d p_d + s p_s, divided by d = N.L
    return _out(np.where(_lit_and_seen(NL, NV), f, 0.0))


def brdf_BlinnPhong1977(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                        p_d: npt.ArrayLike = 0.0, p_s: npt.ArrayLike = 1.0,
                        c1: npt.ArrayLike = 50.0) -> npt.NDArray[np.float64] | np.float64:
    """Phong's model as Blinn writes it, with the half vector: ``s = (N.H)^c1``.

    ``i = p_a + d p_d + s p_s`` with ``d = max(0, N.L)``; as a BRDF ``f = p_d + p_s (N.H)^c1 / (N.L)``.
    Not reciprocal, like :func:`brdf_Phong1975`; the lecture's normalised form
    (:func:`brdf_BlinnPhong_AkenineMoller2008`) is.

    Parameters
    ----------
    NL, NV, NH : array_like
        ``N.L``, ``N.V``, ``N.H``.
    p_d, p_s : array_like
        Proportions of diffuse and specular reflection.
    c1 : array_like
        Exponent.

    References
    ----------
    - Blinn 1977, "Simple hilight models": ``s = (N.H)^c1``, ``i = p_a + d p_d + s p_s``.
    - Lecture, "Shading equation": Blinn-Phong ``L_o = (cos theta_i c_diff + cos^m theta_h c_spec) B_L``.

    Examples
    --------
    >>> print(f"{brdf_BlinnPhong1977(1.0, 1.0, 1.0, p_d=0.6, p_s=0.4):.3f}")
    1.000
    """
    NL, NV, NH = _cosines(NL, NV, NH)
    s = np.maximum(NH, 0.0) ** np.asarray(c1, dtype=np.float64)  # Blinn 1977, s = (N.H)^c1
    f = p_d + p_s * s / _positive(NL)  # Blinn 1977, i = p_a + d p_d + s p_s, divided by d = N.L
    return _out(np.where(_lit_and_seen(NL, NV), f, 0.0))


def brdf_BlinnPhong_AkenineMoller2008(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                                      c_diff: npt.ArrayLike = 0.0, c_spec: npt.ArrayLike = 1.0,
                                      m: npt.ArrayLike = 50.0
                                     ) -> npt.NDArray[np.float64] | np.float64:
    """The lecture's normalised Blinn-Phong: ``f = c_diff / pi + (m + 8) / (8 pi) cos^m theta_h c_spec``.

    From ``L_o(v) = (c_diff / pi + (m + 8)/(8 pi) cos^m theta_h c_spec) E_L cos theta_i``. The
    factor ``(m + 8) / (8 pi)`` approximately normalises the lobe (its directional albedo at normal
    incidence is within 8 % of 1, above 1 for small m). Against the lecture's Blinn-Phong
    ``(cos theta_i c_diff + cos^m theta_h c_spec) E_L / pi`` the specular term gains
    ``(m + 8)/8 cos theta_i``; the lecture's remark that Blinn-Phong "lacks the ``(m+8)/m``
    factor" misprints ``(m + 8)/8``.

    Parameters
    ----------
    NL, NV, NH : array_like
        ``N.L``, ``N.V`` and ``cos theta_h = N.H``.
    c_diff, c_spec : array_like
        Diffuse and specular colours (may be spectral).
    m : array_like
        Smoothness exponent.

    References
    ----------
    - Lecture, "Shading equation"; Akenine-Moller, Haines & Hoffman 2008 (Real-Time Rendering, 3rd
      ed.), as cited by the lecture.

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{brdf_BlinnPhong_AkenineMoller2008(1.0, 1.0, 1.0, 0.0, 1.0, 8.0) * np.pi:.3f}")
    2.000
    """
    NL, NV, NH = _cosines(NL, NV, NH)
    m = np.asarray(m, dtype=np.float64)
    # Lecture, shading equation: c_diff/pi + (m+8)/(8 pi) cos^m(theta_h) c_spec
    f = np.asarray(c_diff) / np.pi + (m + 8.0) / (8.0 * np.pi) * np.maximum(NH, 0.0) ** m * np.asarray(c_spec)
    return _out(np.where(_lit_and_seen(NL, NV), f, 0.0))


# --- microfacet models ----------------------------------------------------------------------------

def brdf_TorranceSparrow_Blinn1977(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                                   VH: npt.ArrayLike,
                                   F: npt.ArrayLike | Callable[[npt.NDArray[np.float64]], npt.ArrayLike] | None = None,
                                   p_d: npt.ArrayLike = 0.0, p_s: npt.ArrayLike = 1.0,
                                   distribution: str = "TrowbridgeReitz1975",
                                   **distribution_parameters: Any
                                  ) -> npt.NDArray[np.float64] | np.float64:
    """Blinn's Torrance-Sparrow highlight ``s = D G F / (N.E)`` in ``i = p_a + d p_d + s p_s``.

    As a BRDF, ``f = p_d + p_s D F [G / (N.E)] / (N.L)``, with ``G / (N.E)`` by Blinn's
    division-free ordering (:func:`reflectance.optics.shadowing.G_over_NE_Blinn1977`); since
    ``G <= G_c = 2 (N.H)(N.L) / (E.H)`` the division by ``N.L`` stays bounded at grazing light.
    Defined only as printed: D with D(0) = 1 (Blinn's D1, D2, D3). For the normalised form use
    :func:`brdf_CookTorrance1982` with ``convention="physical"``.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.E``, ``N.H``, ``E.H``.
    F : array_like or callable
        Fresnel reflectance at ``E.H`` (values, possibly spectral), or a function of ``E.H``.
        Blinn's printed Fresnel lacks the factor 1/2 (Cook & Torrance 1982, "Spectral composition"); see
        :mod:`reflectance.optics.fresnel`.
    p_d, p_s : array_like
        Proportions of diffuse and specular reflection (Blinn Fig. 7a: 0.6, 0.4).
    distribution : str
        A method of :data:`reflectance.optics.microfacet.DISTRIBUTION_METHODS` (Blinn chooses D3).
    **distribution_parameters
        Its parameters, e.g. ``c3=0.5`` (Blinn Fig. 7a, aluminium, with ``n = 200``).

    References
    ----------
    - Blinn 1977, "Torrance-Sparrow model" (s = DGF/(N.E)) and "Computational considerations".

    Examples
    --------
    >>> print(f"{brdf_TorranceSparrow_Blinn1977(1.0, 1.0, 1.0, 1.0, 1.0, c3=0.5):.3f}")
    1.000
    """
    NL, NV, NH, VH = _cosines(NL, NV, NH, VH)
    D = _distribution_values(NH, distribution, "paper", distribution_parameters)
    F = _fresnel_values(F, VH)
    # Blinn 1977, s = D G F / (N.E), with G/(N.E) computed division-free; f = p_d + p_s s / (N.L)
    s_over_NL = D * F * G_over_NE_Blinn1977(NL, NV, NH, VH) / _positive(NL)
    f = p_d + p_s * s_over_NL
    return _out(np.where(_lit_and_seen(NL, NV), f, 0.0))


def brdf_CookTorrance1982(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                          VH: npt.ArrayLike,
                          F: npt.ArrayLike | Callable[[npt.NDArray[np.float64]], npt.ArrayLike] | None = None,
                          s: npt.ArrayLike = 1.0, d: npt.ArrayLike = 0.0, R_d: npt.ArrayLike = 0.0,
                          distribution: str = "Beckmann1963",
                          shadowing_method: str = "VCavity_Blinn1977", convention: str = "paper",
                          **distribution_parameters: Any) -> npt.NDArray[np.float64] | np.float64:
    """Cook & Torrance's bidirectional reflectance ``R = s R_s + d R_d``, ``s + d = 1``.

    ``"paper"``: ``R_s = (F / pi) D G / ((N.L)(N.V))`` with D as printed (Beckmann without 1/pi).
    ``"physical"``: ``R_s = F D G / (4 (N.L)(N.V))`` with D normalised. For Beckmann, paper = 4 x
    physical.
    ``"lecture"``: the lecture's slides, ``R_s = D G F / (N.V)`` with the slide's Beckmann
    ``D = exp(-(tan d / m)^2) / (4 m^2 cos^4 d)`` (Beckmann only): ``pi (N.L)`` x physical. The slide
    calls ``s R_s + d R_d`` the BRDF; its ``R_s`` is Blinn's ``s = D G F / (N.E)`` (an intensity
    factor), not divided by ``N.L`` here, so that the lecture's printed expression is what is drawn.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.V``, ``N.H``, ``V.H``.
    F : array_like or callable
        Fresnel reflectance at ``V.H`` (values, possibly spectral), or a function of ``V.H``.
    s, d : array_like
        Fractions of specular and diffuse reflectance; ``s + d = 1``.
    R_d : array_like
        Diffuse bidirectional reflectance (1/sr), e.g. ``F0 / pi`` (Cook & Torrance Fig. 7).
    distribution : str
        A method of :data:`reflectance.optics.microfacet.DISTRIBUTION_METHODS`; ``"mixture"`` with
        ``lobes=[(w1, m1), (w2, m2)]`` for several roughness scales (Fig. 6b copper vase).
    shadowing_method : str
        ``"VCavity_Blinn1977"`` (as printed) or ``"Smith_Beckmann_Walter2007"`` (needs a Beckmann
        ``m``).
    convention : str
        ``"paper"``, ``"physical"`` or ``"lecture"``.
    **distribution_parameters
        The distribution's parameters (``m=0.15`` ...).

    References
    ----------
    - Cook & Torrance 1982, "The reflectance model" (R = sR_s + dR_d) and "Directional distribution
      of the reflected light" (R_s, G, D).
    - Walter et al. 2007 (normalised microfacet BRDF, 1/4 Jacobian).
    - Lecture, "Cook and Torrance Reflection Model (1982)" (R_s = DGF/(N.V), BRDF = sR_s + dR_d)
      and "Distribution of Microfacet Orientations" (its Beckmann D with 4 m^2).

    Examples
    --------
    >>> import numpy as np
    >>> paper = brdf_CookTorrance1982(0.8, 0.7, 0.95, 0.9, 0.5, m=0.3)
    >>> physical = brdf_CookTorrance1982(0.8, 0.7, 0.95, 0.9, 0.5, m=0.3, convention="physical")
    >>> print(f"{paper / physical:.6f}")
    4.000000
    >>> lecture = brdf_CookTorrance1982(0.8, 0.7, 0.95, 0.9, 0.5, m=0.3, convention="lecture")
    >>> print(f"{lecture / physical / (np.pi * 0.8):.6f}")  # pi (N.L) x physical
    1.000000
    """
    _check_convention(convention, COOK_TORRANCE_CONVENTIONS)
    s, d = np.asarray(s, dtype=np.float64), np.asarray(d, dtype=np.float64)
    if np.any(np.abs(s + d - 1.0) > 1e-9):
        raise ValueError(f"Cook & Torrance 1982 require s + d = 1, got s = {s!r}, d = {d!r}.")
    NL, NV, NH, VH = _cosines(NL, NV, NH, VH)
    if convention == "lecture":
        if distribution != "Beckmann1963":
            raise ValueError("convention='lecture' is the slides' form, with their Beckmann D only: "
                             f"it needs distribution='Beckmann1963', got {distribution!r}.")
        # Lecture, "Distribution of microfacet orientations": e^{-(tan d/m)^2} / (4 m^2 cos^4 d)
        D = _distribution_values(NH, distribution, "paper", distribution_parameters) / 4.0
    else:
        D = _distribution_values(NH, distribution, convention, distribution_parameters)
    shadowing_parameters = {}
    if shadowing_method == "Smith_Beckmann_Walter2007":
        if distribution != "Beckmann1963":
            raise ValueError(
                "shadowing_method='Smith_Beckmann_Walter2007' is the Smith G of a Beckmann surface; "
                f"it needs distribution='Beckmann1963', got {distribution!r}."
            )
        shadowing_parameters["m"] = distribution_parameters["m"]
    G = shadowing(NL, NV, NH, VH, method=shadowing_method, **shadowing_parameters)
    F = _fresnel_values(F, VH)
    # G vanishes at least as fast as N.L and N.V (G <= G_b, G_c for the V-cavity; G1 ~ cot for
    # Smith), so dividing one cosine at a time stays bounded at grazing angles.
    G_over_NL_NV = G / _positive(NL) / _positive(NV)
    if convention == "lecture":
        R_s = D * G * F / _positive(NV)  # Lecture, "Cook and Torrance": R_s = DGF/(N.V)
    elif convention == "paper":
        R_s = F / np.pi * D * G_over_NL_NV  # Cook & Torrance 1982, R_s = (F/pi) D G / ((N.L)(N.V))
    else:
        R_s = F * D * G_over_NL_NV / 4.0  # Walter et al. 2007, F D G / (4 (N.L)(N.V))
    R = s * R_s + d * np.asarray(R_d, dtype=np.float64)  # Cook & Torrance 1982, R = s R_s + d R_d
    return _out(np.where(_lit_and_seen(NL, NV), R, 0.0))


def ambient_reflectance_CookTorrance1982(R_d: npt.ArrayLike
                                        ) -> npt.NDArray[np.float64] | np.float64:
    """Ambient reflectance as Cook & Torrance set it for their vases: ``R_a = pi R_d``.

    References
    ----------
    - Cook & Torrance 1982, "Applications" (Figs. 6a, 6b: ``R_a = pi R_d``).

    Examples
    --------
    >>> print(f"{ambient_reflectance_CookTorrance1982(1 / 3.141592653589793):.6f}")
    1.000000
    """
    return _out(np.pi * np.asarray(R_d, dtype=np.float64))  # Cook & Torrance 1982, R_a = pi R_d


def intensity_CookTorrance1982(R: npt.ArrayLike, NL: npt.ArrayLike, I_l: npt.ArrayLike,
                               domega_l: npt.ArrayLike, I_ia: npt.ArrayLike = 0.0,
                               R_a: npt.ArrayLike = 0.0,
                               unblocked_fraction: npt.ArrayLike = 1.0
                              ) -> npt.NDArray[np.float64] | np.float64:
    """Reflected intensity ``I_r = I_ia R_a f + sum_l I_il (N.L_l) d omega_il R_l``.

    Parameters
    ----------
    R : array_like
        BRDF of each light, lights along axis 0: shape ``(n_lights, ...)``.
    NL : array_like
        ``N.L_l``, same leading axis (clamped at 0).
    I_l, domega_l : array_like
        Intensity and solid angle of each light, broadcasting against ``R`` (lights on axis 0).
    I_ia, R_a : array_like
        Ambient intensity and ambient reflectance.
    unblocked_fraction : array_like
        ``f``, the unblocked fraction of the hemisphere (1 in the paper's images).

    Returns
    -------
    numpy.ndarray or numpy.float64

    Notes
    -----
    Blinn's ``i = p_a + d p_d + s p_s`` is the case ``I_ia = 1``, ``R_a = p_a``, ``I_l = 1``,
    ``d omega_l = 1`` with ``R`` from :func:`brdf_BlinnPhong1977` or
    :func:`brdf_TorranceSparrow_Blinn1977`.

    References
    ----------
    - Cook & Torrance 1982, "The reflectance model": ``I_ra = R_a I_ia f`` and
      ``I_r = I_ia R_a + sum_l I_il (N.L_l) d omega_il (s R_s + d R_d)``.

    Examples
    --------
    >>> print(f"{intensity_CookTorrance1982([2.0, 1.0], [0.5, 1.0], 1.0, [0.0001, 0.0002]):.6f}")
    0.000300
    """
    R = np.asarray(R, dtype=np.float64)
    NL = np.maximum(np.asarray(NL, dtype=np.float64), 0.0)
    terms = np.asarray(I_l) * NL * np.asarray(domega_l) * R  # I_il (N.L_l) d omega_il R_l
    # Cook & Torrance 1982: I_r = I_ia R_a (f) + sum over lights
    return _out(np.asarray(I_ia) * np.asarray(R_a) * unblocked_fraction + np.sum(terms, axis=0))


# --- anisotropic models of the article ------------------------------------------------------------

def brdf_Ward1992(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike, HX: npt.ArrayLike,
                  HY: npt.ArrayLike, rho_s: npt.ArrayLike = 1.0, alpha_x: npt.ArrayLike = 0.1,
                  alpha_y: npt.ArrayLike = 0.1,
                  rho_d: npt.ArrayLike = 0.0) -> npt.NDArray[np.float64] | np.float64:
    """Ward's anisotropic Gaussian, as the article writes its specular term.

    The article: ``k_spec = rho_s / sqrt((N.L)(N.V)) (N.L) / (4 pi alpha_x alpha_y)
    exp[-2 ((H.X / alpha_x)^2 + (H.Y / alpha_y)^2) / (1 + H.N)]``. Its ``k_spec`` includes the
    factor ``N.L``; the BRDF is ``f = rho_d / pi + k_spec / (N.L)``, which is reciprocal. (The
    exponent ``2 (...) / (1 + H.N)`` is the approximation Ward gives for his
    ``-tan^2(delta) (cos^2 phi / alpha_x^2 + sin^2 phi / alpha_y^2)``; for isotropic alpha it is
    ``2 (1 - cos delta)`` against ``tan^2 delta``, equal to second order in delta.)

    Parameters
    ----------
    NL, NV, NH : array_like
        ``N.L``, ``N.V``, ``H.N``.
    HX, HY : array_like
        ``H.X`` and ``H.Y`` for the orthogonal tangents X, Y of the anisotropy.
    rho_s, rho_d : array_like
        Specular and diffuse reflectances (may be spectral).
    alpha_x, alpha_y : array_like
        Roughness along X and Y, > 0.

    References
    ----------
    - Wikipedia, "Specular highlight", "Ward anisotropic distribution"; Ward 1992.

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{brdf_Ward1992(1.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.1, 0.1) * 4 * np.pi * 0.01:.6f}")
    1.000000
    """
    NL, NV, NH, HX, HY = _cosines(NL, NV, NH, HX, HY)
    alpha_x, alpha_y = np.asarray(alpha_x, dtype=np.float64), np.asarray(alpha_y, dtype=np.float64)
    if np.any(alpha_x <= 0) or np.any(alpha_y <= 0):
        raise ValueError(f"'alpha_x', 'alpha_y' must be > 0, got {alpha_x!r}, {alpha_y!r}.")
    lit = _lit_and_seen(NL, NV)
    # article, Ward exponent; H.N > 0 wherever L and V are above the surface (elsewhere masked)
    exponent = -2.0 * ((HX / alpha_x) ** 2 + (HY / alpha_y) ** 2) / (1.0 + np.maximum(NH, 0.0))
    # sqrt of each cosine separately: their product can underflow to 0 at grazing angles
    spec = np.asarray(rho_s) / (4.0 * np.pi * alpha_x * alpha_y * np.sqrt(_positive(NL)) * np.sqrt(_positive(NV)))
    f = np.asarray(rho_d) / np.pi + spec * np.exp(exponent)  # article's k_spec / (N.L)
    return _out(np.where(lit, f, 0.0))


def brdf_HeidrichSeidel1998(NL: npt.ArrayLike, NV: npt.ArrayLike, LT: npt.ArrayLike,
                            VT: npt.ArrayLike, LV: npt.ArrayLike, s: npt.ArrayLike = 50.0,
                            k_d: npt.ArrayLike = 0.0, k_s: npt.ArrayLike = 1.0,
                            form: str = "HeidrichSeidel1998"
                           ) -> npt.NDArray[np.float64] | np.float64:
    """Heidrich & Seidel's anisotropic model for fibres of direction T, as a BRDF.

    ``k_diff = L.P = sqrt(1 - (L.T)^2)`` (P: the fibre normal in the plane of L and T) and
    ``k_spec = (V.R)^s``; the BRDF is ``f = (k_d k_diff + k_s k_spec) / (N.L)``.

    ``form="HeidrichSeidel1998"`` (default): ``V.R = sqrt(1 - (L.T)^2) sqrt(1 - (V.T)^2) - (L.T)(V.T)``,
    the article's "optimised" second line, which is the best-reflecting fibre normal of Heidrich &
    Seidel (1 on the cone of mirror directions, ``V.T = -L.T``); zero unless N.L, N.V and V.R are > 0.

    ``form="as_printed"``: the article's "Final calculation" with its
    ``R = (-L + 2 (L.T) T) / |...|`` (so ``V.R = 2 (L.T)(V.T) - L.V``) and its three conditions
    ``0 < N.V``, ``0 < P.V``, ``0 < R.V``, else zero. That R is the reflection of -L in the plane
    normal to T, not in a fibre normal; it differs from the optimised line (at the mirror
    direction it gives ``V.R = -1``), and the article's last step
    ``(-cos(a + b))^s = cos^s(a + b)`` drops a sign. See the tests for the discrepancies.

    Parameters
    ----------
    NL, NV : array_like
        ``N.L``, ``N.V`` (N: the real surface normal).
    LT, VT, LV : array_like
        ``L.T``, ``V.T``, ``L.V`` with T the fibre direction projected into the surface plane.
    s : array_like
        Shininess exponent.
    k_d, k_s : array_like
        Diffuse and specular weights (may be spectral).
    form : str
        ``"HeidrichSeidel1998"`` or ``"as_printed"``.

    References
    ----------
    - Wikipedia, "Specular highlight", "Heidrich-Seidel anisotropic distribution"; Heidrich &
      Seidel 1998.

    Examples
    --------
    >>> import numpy as np
    >>> a = 0.6  # L at angle a from T, V on the mirror cone (V.T = -L.T)
    >>> print(f"{brdf_HeidrichSeidel1998(0.5, 0.5, np.cos(a), -np.cos(a), 0.0) * 0.5:.6f}")
    1.000000
    """
    if form not in ("HeidrichSeidel1998", "as_printed"):
        raise ValueError(f"Unknown Heidrich-Seidel form {form!r}; known forms: HeidrichSeidel1998, as_printed.")
    NL, NV, LT, VT, LV = _cosines(NL, NV, LT, VT, LV)
    s = np.asarray(s, dtype=np.float64)
    sin_L = np.sqrt(np.maximum(1.0 - LT * LT, 0.0))
    sin_V = np.sqrt(np.maximum(1.0 - VT * VT, 0.0))
    k_diff = sin_L  # article: k_diff = L.P = sqrt(1 - (L.T)^2)
    if form == "HeidrichSeidel1998":
        VR = sin_L * sin_V - LT * VT  # article, optimised specular, 2nd line
        valid = _lit_and_seen(NL, NV) & (VR > 0)
        k_spec = np.maximum(VR, 0.0) ** s
        f = (np.asarray(k_d) * k_diff + np.asarray(k_s) * np.where(valid, k_spec, 0.0)) / _positive(NL)
        return _out(np.where(_lit_and_seen(NL, NV), f, 0.0))
    VR = 2.0 * LT * VT - LV  # article: R = -L + 2 (L.T) T (unit already), V.R
    PV = (LV - LT * VT) / np.where(sin_L > 0, sin_L, 1.0)  # article: P = L - (L.T) T, normalised
    valid = (NV > 0) & (PV > 0) & (VR > 0) & (NL > 0)  # article's conditions (and a lit surface)
    f = (np.asarray(k_d) * k_diff + np.asarray(k_s) * np.maximum(VR, 0.0) ** s) / _positive(NL)
    return _out(np.where(valid, f, 0.0))


def brdf_LommelSeeliger(NL: npt.ArrayLike, NV: npt.ArrayLike,
                        albedo: npt.ArrayLike = 1.0) -> npt.NDArray[np.float64] | np.float64:
    """The Lommel-Seeliger law of a dusty, lunar-like surface: ``f = w / (4 pi (N.L + N.V))``.

    Single scattering by isotropic particles in a semi-infinite layer of single-scattering albedo
    ``w`` (Hapke 1981, eq. 2 with p(g) = 1 and no opposition effect): the reflected radiance is
    proportional to ``(N.L) / (N.L + N.V)``, so a full Moon is evenly bright to its limb; the
    lobe grows towards grazing views and is reciprocal.

    Parameters
    ----------
    NL, NV : array_like
        ``N.L`` and ``N.V``.
    albedo : array_like
        Single-scattering albedo ``w`` in [0, 1].

    References
    ----------
    - Hapke, B. (1981). Bidirectional reflectance spectroscopy 1. Theory. Journal of Geophysical
      Research 86(B4), 3039-3054. (Lommel-Seeliger as its single-scattering, isotropic limit.)

    Examples
    --------
    >>> import numpy as np
    >>> print(f"{brdf_LommelSeeliger(1.0, 1.0, 1.0) * 8 * np.pi:.6f}")
    1.000000
    """
    NL, NV = _cosines(NL, NV)
    lit = _lit_and_seen(NL, NV)
    # Hapke 1981, single isotropic scattering: f = w / (4 pi (mu_0 + mu))
    f = np.asarray(albedo) / (4.0 * np.pi * _positive(NL + NV))
    return _out(np.where(lit, f, 0.0))


def brdf_Hapke1981(NL: npt.ArrayLike, NV: npt.ArrayLike, LV: npt.ArrayLike,
                   albedo: npt.ArrayLike = 1.0, B0: npt.ArrayLike = 1.0, h: npt.ArrayLike = 0.06,
                   xi: npt.ArrayLike = 0.0,
                   multiple_scattering: bool = True) -> npt.NDArray[np.float64] | np.float64:
    """Hapke's bidirectional reflectance of a particulate (lunar) surface, with its opposition effect.

    Hapke 1981: ``r(i, e, g) = (w / 4 pi) mu_0 / (mu_0 + mu) {[1 + B(g)] p(g) + H(mu_0) H(mu) - 1}``,
    a radiance factor per unit incident irradiance; the BRDF is ``f = r / mu_0``::

        f = w / (4 pi (mu_0 + mu)) {[1 + B(g)] p(g) + H(mu_0) H(mu) - 1}

    with ``mu_0 = N.L``, ``mu = N.V`` and the phase angle ``g`` between L and V (``cos g = L.V``,
    0 when the viewer looks along the light). Its parts:

    - ``B(g) = B0 / (1 + tan(g / 2) / h)``: the shadow-hiding opposition effect in the form of
      Hapke 1986 (amplitude ``B0``, angular width ``h``): at ``g = 0`` a particle's own shadow is
      hidden behind it, so the surface is up to ``1 + B0`` times brighter back towards the light.
    - ``p(g) = (1 - xi^2) / (1 + 2 xi cos g + xi^2)^(3/2)``: the Henyey-Greenstein (1941) phase
      function of one particle written in the phase angle (``xi < 0`` scatters back towards the
      light, ``xi = 0`` is isotropic).
    - ``H(x) = (1 + 2 x) / (1 + 2 x sqrt(1 - w))``: Hapke 1981's approximation to Chandrasekhar's
      H function (isotropic multiple scattering); ``multiple_scattering=False`` sets ``H = 1``.

    With ``B0 = 0``, ``xi = 0`` and no multiple scattering it is the Lommel-Seeliger law
    :func:`brdf_LommelSeeliger`, which has no back-scatter. The model is reciprocal (``g``, the sum
    ``mu_0 + mu`` and the product of H's are symmetric in L and V).

    Parameters
    ----------
    NL, NV, LV : array_like
        ``N.L``, ``N.V`` and ``L.V`` (the cosine of the phase angle).
    albedo : array_like
        Single-scattering albedo ``w`` in [0, 1].
    B0, h : array_like
        Amplitude (>= 0) and angular width (> 0) of the opposition effect.
    xi : array_like
        Henyey-Greenstein asymmetry in (-1, 1); negative: back-scattering particles.
    multiple_scattering : bool
        Include ``H(mu_0) H(mu) - 1``.

    References
    ----------
    - Hapke 1981 (r(i, e, g) and its H function); Hapke 1986 (B(g)).
    - Henyey, L. G., & Greenstein, J. L. (1941). Diffuse radiation in the Galaxy. Astrophysical
      Journal 93, 70-83.

    Examples
    --------
    >>> import numpy as np
    >>> # looking back along the light (L.V = 1): 1 + B0 times the Lommel-Seeliger value
    >>> print(f"{brdf_Hapke1981(0.6, 0.6, 1.0, 0.8, B0=1.0, multiple_scattering=False) / brdf_LommelSeeliger(0.6, 0.6, 0.8):.6f}")
    2.000000
    """
    NL, NV, LV = _cosines(NL, NV, LV)
    w, B0, h, xi = (np.asarray(a, dtype=np.float64) for a in (albedo, B0, h, xi))
    if np.any(h <= 0) or np.any(B0 < 0) or np.any(np.abs(xi) >= 1):
        raise ValueError(f"Hapke needs h > 0, B0 >= 0 and |xi| < 1, got h = {h!r}, B0 = {B0!r}, xi = {xi!r}.")
    lit = _lit_and_seen(NL, NV)
    # tan(g/2) = sqrt((1 - cos g) / (1 + cos g)); g = pi (L = -V) cannot be lit and seen
    tan_half = np.sqrt(np.maximum(1.0 - LV, 0.0) / _positive(1.0 + LV))
    B = B0 / (1.0 + tan_half / h)  # Hapke 1986, shadow-hiding opposition effect
    p = (1.0 - xi * xi) / (1.0 + 2.0 * xi * LV + xi * xi) ** 1.5  # Henyey & Greenstein 1941, in g
    multiple: npt.NDArray[np.float64] | float
    if multiple_scattering:
        gamma = np.sqrt(np.maximum(1.0 - w, 0.0))
        H0 = (1.0 + 2.0 * NL) / (1.0 + 2.0 * gamma * NL)  # Hapke 1981, approximate H function
        H = (1.0 + 2.0 * NV) / (1.0 + 2.0 * gamma * NV)
        multiple = H0 * H - 1.0
    else:
        multiple = 0.0
    # Hapke 1981: r = (w / 4 pi) mu_0 / (mu_0 + mu) {[1 + B] p + H H - 1}; f = r / mu_0
    f = w / (4.0 * np.pi * _positive(NL + NV)) * ((1.0 + B) * p + multiple)
    return _out(np.where(lit, f, 0.0))


# --- registry, vector-level dispatcher, albedo ----------------------------------------------------

BRDF_METHODS: dict[str, Callable[..., Any]] = {
    "Lambert": brdf_Lambert,
    "Phong1975": brdf_Phong1975,
    "BlinnPhong1977": brdf_BlinnPhong1977,
    "BlinnPhong_AkenineMoller2008": brdf_BlinnPhong_AkenineMoller2008,
    "TorranceSparrow_Blinn1977": brdf_TorranceSparrow_Blinn1977,
    "CookTorrance1982": brdf_CookTorrance1982,
    "Ward1992": brdf_Ward1992,
    "HeidrichSeidel1998": brdf_HeidrichSeidel1998,
    "LommelSeeliger": brdf_LommelSeeliger,
    "Hapke1981": brdf_Hapke1981,
}
"""BRDF models of :func:`brdf`, each a function of cosines (see the module docstring)."""

_COSINE_NAMES = ("NL", "NV", "NH", "VH", "RV", "HX", "HY", "LT", "VT", "LV")


def _unit_vectors(v: npt.ArrayLike, name: str) -> npt.NDArray[np.float64]:
    v = np.asarray(v, dtype=np.float64)
    if v.shape[-1:] != (3,):
        raise ValueError(f"'{name}' must have shape (..., 3), got {v.shape}.")
    norm = np.linalg.norm(v, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError(f"'{name}' contains zero vectors; directions must be non-zero.")
    return v / norm


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def brdf(L: npt.ArrayLike, V: npt.ArrayLike, N: npt.ArrayLike, method: str = "CookTorrance1982",
         X: npt.ArrayLike | None = None, Y: npt.ArrayLike | None = None,
         T: npt.ArrayLike | None = None, n: npt.ArrayLike | None = None,
         k: npt.ArrayLike | None = None, fresnel_method: str = "exact",
         **parameters: Any) -> npt.NDArray[np.float64] | np.float64:
    """Evaluate a model of :data:`BRDF_METHODS` on direction vectors.

    Parameters
    ----------
    L, V, N : array_like
        Directions towards the light and the viewer, and the surface normal, shape ``(..., 3)``
        (normalised here; broadcasting).
    method : str
        A key of :data:`BRDF_METHODS`.
    X, Y : array_like, optional
        Orthogonal tangents of the anisotropy (``"Ward1992"``); for ``alpha_x == alpha_y`` they
        may be omitted.
    T : array_like, optional
        Fibre (thread) direction D of ``"HeidrichSeidel1998"``; projected into the surface plane,
        ``T = (D - (D.N) N) / |D - (D.N) N|``.
    n, k : array_like, optional
        Refractive index and extinction coefficient: when ``F`` is not given, the microfacet models
        evaluate ``F = reflectance.optics.fresnel.fresnel(V.H, n, k, fresnel_method)``. Spectral ``n``
        (shape ``(n_wl,)``) gives a result of shape ``(..., n_wl)``.
    fresnel_method : str
        Passed to :func:`reflectance.optics.fresnel.fresnel`.
    **parameters
        The model's parameters (``m``, ``c3``, ``s``, ``d``, ``R_d``, ``convention``, ``F`` ...).

    Returns
    -------
    numpy.ndarray or numpy.float64

    Raises
    ------
    ValueError
        For an unknown method (listing the known ones), missing vectors or wrong parameters.

    Examples
    --------
    >>> import numpy as np
    >>> L = np.array([0.0, 0.6, 0.8]); V = np.array([0.0, -0.6, 0.8]); N = np.array([0.0, 0.0, 1.0])
    >>> print(f"{brdf(L, V, N, 'Lambert', rho_d=np.pi):.3f}")
    1.000
    """
    try:
        function = BRDF_METHODS[method]
    except (KeyError, TypeError):
        raise ValueError(f"Unknown BRDF method {method!r}; known methods: {', '.join(BRDF_METHODS)}.") from None
    L, V, N = _unit_vectors(L, "L"), _unit_vectors(V, "V"), _unit_vectors(N, "N")
    half = L + V
    norm = np.linalg.norm(half, axis=-1, keepdims=True)
    # L = -V: no half vector, and the two cannot both be above the surface (f = 0 anyway).
    H = np.where(norm > 0, half / np.where(norm > 0, norm, 1.0), N)
    NL, NV, NH, VH, LV = _dot(N, L), _dot(N, V), _dot(N, H), _dot(V, H), _dot(L, V)
    cosines = {"NL": NL, "NV": NV, "NH": NH, "VH": VH, "LV": LV, "RV": 2.0 * NL * NV - LV}
    accepted = inspect.signature(function).parameters
    if "HX" in accepted:
        if X is None or Y is None:
            if np.all(parameters.get("alpha_x") == parameters.get("alpha_y", np.nan)):
                # Isotropic: only (H.X)^2 + (H.Y)^2 = 1 - (N.H)^2 matters.
                cosines["HX"], cosines["HY"] = np.sqrt(np.maximum(1.0 - NH * NH, 0.0)), np.zeros_like(NH)
            else:
                raise ValueError(f"{method!r} with alpha_x != alpha_y needs the tangents X and Y.")
        else:
            cosines["HX"], cosines["HY"] = _dot(H, _unit_vectors(X, "X")), _dot(H, _unit_vectors(Y, "Y"))
    if "LT" in accepted:
        if T is None:
            raise ValueError(f"{method!r} needs the fibre direction T.")
        D = np.asarray(T, dtype=np.float64)
        T = _unit_vectors(D - _dot(D, N)[..., None] * N, "T projected into the surface plane")
        cosines["LT"], cosines["VT"] = _dot(L, T), _dot(V, T)
    if (n is not None or k is not None) and "F" not in accepted:
        raise ValueError(f"{method!r} has no Fresnel term: 'n' and 'k' apply to the microfacet models only.")
    if "F" in accepted and "F" not in parameters and n is not None:
        from reflectance.optics.fresnel import fresnel  # imported here: fresnel is an optional companion

        spectral = np.ndim(n) > 0 or (k is not None and np.ndim(k) > 0)
        if spectral:
            cosines = {name: c[..., None] for name, c in cosines.items()}
        parameters["F"] = fresnel(cosines["VH"], n, 0.0 if k is None else k, method=fresnel_method)
    arguments = {name: cosines[name] for name in _COSINE_NAMES if name in accepted}
    try:
        return function(**arguments, **parameters)
    except TypeError as error:
        raise ValueError(f"Bad parameters {sorted(parameters)} for BRDF {method!r}: {error}") from None


# Gauss-Legendre rule on [0, 1] graded towards 0, where microfacet lobes concentrate in theta_h:
# intervals [2^-(j+1), 2^-j], j = 0..11, and [0, 2^-12], 24 nodes each.
def _graded_unit_rule(levels=12, nodes=24):
    x, w = np.polynomial.legendre.leggauss(nodes)
    edges = np.concatenate([[0.0], 2.0 ** -np.arange(levels, -1, -1)])
    a, b = edges[:-1, None], edges[1:, None]
    return ((b - a) / 2 * x + (a + b) / 2).ravel(), ((b - a) / 2 * w).ravel()


def directional_albedo(L: npt.ArrayLike, method: str = "CookTorrance1982",
                       N: npt.ArrayLike = (0.0, 0.0, 1.0), n_phi: int = 128,
                       **parameters: Any) -> npt.NDArray[np.float64] | np.float64:
    """Directional albedo ``integral f(L, V) (N.V) d omega_V`` over the viewing hemisphere.

    Integrated over half vectors H (``V = 2 (L.H) H - L``, ``d omega_V = 4 (V.H) d omega_H``): for
    each of ``n_phi`` equally spaced azimuths ``phi_h`` (measured from the plane of N and L),
    ``theta_h`` runs from 0 to the horizon of V, ``theta_max = (pi - atan2(cos theta_i,
    sin theta_i cos phi_h)) / 2`` (where ``N.V = 2 (L.H)(N.H) - N.L = 0``), with a composite
    Gauss-Legendre rule graded towards the normal. The integrand is then smooth and periodic in
    ``phi_h``, and lobes down to about 1e-3 rad wide are resolved. With ``F = 1`` this is the
    white-furnace test of a microfacet BRDF (<= 1 for an energy-conserving model).

    Parameters
    ----------
    L : array_like
        Direction towards the light, shape (3,), above the surface.
    method : str
        A key of :data:`BRDF_METHODS`.
    N : array_like
        Surface normal.
    n_phi : int
        Azimuthal steps.
    **parameters
        Passed to :func:`brdf` (with ``X, Y, T, n, k`` as there).

    Returns
    -------
    numpy.ndarray or numpy.float64
        The albedo (trailing spectral axis if the BRDF has one).

    Examples
    --------
    >>> import numpy as np
    >>> L = np.array([np.sin(0.5), 0.0, np.cos(0.5)])
    >>> print(f"{directional_albedo(L, 'Lambert', rho_d=0.7):.6f}")
    0.700000
    """
    N = _unit_vectors(N, "N")
    L = _unit_vectors(L, "L")
    cos_i = float(L @ N)
    if not cos_i > 0:
        raise ValueError(f"L must be above the surface, got N.L = {cos_i!r}.")
    tangent = L - cos_i * N
    if np.linalg.norm(tangent) < 1e-12:  # normal incidence: any tangent
        tangent = np.eye(3)[np.argmin(np.abs(N))]
        tangent = tangent - (tangent @ N) * N
    t1 = tangent / np.linalg.norm(tangent)
    t2 = np.cross(N, t1)
    sin_i = np.sqrt(max(1.0 - cos_i * cos_i, 0.0))
    phi = (np.arange(n_phi) + 0.5) * 2.0 * np.pi / n_phi
    theta_max = (np.pi - np.arctan2(cos_i, sin_i * np.cos(phi))) / 2.0  # N.V = 0 on this curve
    x, w = _graded_unit_rule()
    theta = x[:, None] * theta_max[None, :]
    w_theta = w[:, None] * theta_max[None, :]
    st, ct = np.sin(theta)[..., None], np.cos(theta)[..., None]
    H = st * np.cos(phi)[None, :, None] * t1 + st * np.sin(phi)[None, :, None] * t2 + ct * N
    LH = _dot(H, L)
    V = 2.0 * LH[..., None] * H - L
    f = brdf(L, V, N, method, **parameters)
    weight = 4.0 * LH * np.maximum(_dot(V, N), 0.0) * np.sin(theta) * w_theta * (2.0 * np.pi / n_phi)
    if np.ndim(f) > np.ndim(weight):
        weight = weight[..., None]
    return _out(np.sum(f * weight, axis=(0, 1)))
