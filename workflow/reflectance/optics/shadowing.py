"""Shadowing-masking G: the "geometrical attenuation factor" of the microfacet models.

Every function is a plain function of the cosines ``NL = N.L``, ``NV = N.V`` (Blinn's ``N.E``),
``NH = N.H`` and ``VH = V.H = L.H``, in that order, vectorised with numpy broadcasting in float64.
G is 0 where the light or the viewer is at or below the horizon (``NL <= 0`` or ``NV <= 0``).
Scalars in give numpy scalars out.

- V-cavity (Torrance & Sparrow 1967, derived by Blinn 1977, printed again by Cook & Torrance
  1982 and the lecture; one formula, one function):
  ``G = min(1, G_b, G_c)``, ``G_b = 2 (N.H)(N.V) / (V.H)`` (masking of reflected light),
  ``G_c = 2 (N.H)(N.L) / (V.H)`` (shadowing of incident light), each on its own from
  :func:`vcavity_terms_Blinn1977`. :mod:`reflectance.papers.vgroove` checks them against a ray simulation
  of a symmetric V-groove.
- Blinn's division-free ordering of ``G / (N.E)`` (:func:`G_over_NE_Blinn1977`).
- Smith's G for the Beckmann distribution (Walter et al. 2007), the modern option, exact (erf) or
  with Walter's rational approximation.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (Figs. 1-4, G_b, G_c; "Computational considerations".)
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24. (G = min{1, ...}.)
- Torrance, K. E., & Sparrow, E. M. (1967). Theory for off-specular reflection from roughened
  surfaces. J. Opt. Soc. Am., 57(9), 1105-1114.
- Smith, B. G. (1967). Geometrical shadowing of a random rough surface. IEEE Transactions on
  Antennas and Propagation, 15(5), 668-671.
- Walter, B., Marschner, S. R., Li, H., & Torrance, K. E. (2007). Microfacet Models for Refraction
  through Rough Surfaces. Eurographics Symposium on Rendering. (Separable Smith G = G1(L) G1(V);
  Beckmann G1 with erf and its rational approximation.)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = [
    "vcavity_terms_Blinn1977",
    "shadowing_VCavity_Blinn1977",
    "G_over_NE_Blinn1977",
    "G1_Smith_Beckmann_Walter2007",
    "shadowing_Smith_Beckmann_Walter2007",
    "SHADOWING_METHODS",
    "shadowing",
]


def _out(x):
    return x[()] if np.ndim(x) == 0 else x


def _cosines(*cosines: npt.ArrayLike) -> list[npt.NDArray[np.float64]]:
    # Round-off can push a cosine of unit vectors outside [-1, 1].
    return [np.clip(np.asarray(c, dtype=np.float64), -1.0, 1.0) for c in cosines]


def _positive(x):
    """x where x > 0, 1 elsewhere: a denominator that never divides by zero (callers mask)."""
    return np.where(x > 0, x, 1.0)


def vcavity_terms_Blinn1977(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                            VH: npt.ArrayLike
                           ) -> tuple[npt.NDArray[np.float64] | np.float64, npt.NDArray[np.float64] | np.float64]:
    """Blinn's ``G_b = 2 (N.H)(N.E) / (E.H)`` (masking) and ``G_c = 2 (N.H)(N.L) / (E.H)`` (shadowing).

    Unclipped (they exceed 1 when nothing is blocked); :func:`shadowing_VCavity_Blinn1977` is
    ``min(1, G_b, G_c)``. ``V.H`` must be > 0.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.V`` (Blinn's ``N.E``), ``N.H`` and ``V.H`` (``E.H``).

    Returns
    -------
    G_b, G_c : numpy.ndarray or numpy.float64

    Raises
    ------
    ValueError
        If any ``V.H`` is not > 0.

    References
    ----------
    - Blinn 1977, Figs. 1-4, G_b and G_c.

    Examples
    --------
    >>> G_b, G_c = vcavity_terms_Blinn1977(0.1, 0.9, 0.8, 0.5)
    >>> print(f"{G_b:.2f} {G_c:.2f}")  # 2 .8 .9 / .5, 2 .8 .1 / .5
    2.88 0.32
    """
    NL, NV, NH, VH = (np.asarray(x, dtype=np.float64) for x in (NL, NV, NH, VH))
    if np.any(~(VH > 0)):
        raise ValueError(f"'VH' (E.H) must be > 0, got {VH!r}.")
    G_b = 2.0 * NH * NV / VH  # Blinn 1977, G_b = 2 (N.H)(N.E) / (E.H) (masking)
    G_c = 2.0 * NH * NL / VH  # Blinn 1977, G_c = 2 (N.H)(N.L) / (E.H) (shadowing)
    return _out(G_b), _out(G_c)


def shadowing_VCavity_Blinn1977(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                                VH: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """V-cavity geometrical attenuation factor ``G = min(1, G_b, G_c)``.

    ``G_b = 2 (N.H)(N.V) / (V.H)`` is the fraction of a fully lit facet whose reflected light
    escapes the groove (Blinn's case b, masking); ``G_c = 2 (N.H)(N.L) / (V.H)`` the fraction of
    the facet that is lit (case c, shadowing). Cook & Torrance 1982 print the same formula (with
    ``V.H = L.H``), so there is one implementation under Blinn's name; the two terms come from
    :func:`vcavity_terms_Blinn1977`.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.V`` (Blinn's ``N.E``), ``N.H`` and ``V.H``.

    Returns
    -------
    numpy.ndarray or numpy.float64
        G in [0, 1]; 0 where ``NL <= 0``, ``NV <= 0``, ``NH <= 0`` or ``VH <= 0``.

    References
    ----------
    - Blinn 1977, Figs. 1-4, G_b and G_c; "the effective value of G will be the minimum of G_a,
      G_b and G_c".
    - Cook & Torrance 1982, "Directional distribution of the reflected light", G.

    Examples
    --------
    >>> print(f"{shadowing_VCavity_Blinn1977(0.1, 0.9, 0.8, 0.5):.2f}")  # G_c = 2 .8 .1 / .5
    0.32
    """
    NL, NV, NH, VH = _cosines(NL, NV, NH, VH)
    valid = (NL > 0) & (NV > 0) & (NH > 0) & (VH > 0)
    G_b, G_c = vcavity_terms_Blinn1977(NL, NV, NH, _positive(VH))
    G = np.minimum(1.0, np.minimum(G_b, G_c))  # Blinn 1977 / Cook & Torrance 1982, G = min{1, G_b, G_c}
    return _out(np.where(valid, G, 0.0))


def G_over_NE_Blinn1977(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                        VH: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """``G / (N.E)`` by Blinn's division-free ordering: choose the minimum first, divide after.

    As printed (Blinn 1977, "Computational considerations")::

        if (N.E) < (N.L) then
            if 2(N.E)(N.H) < (E.H) then G := 2(N.H)/(E.H)
            else G := 1/(N.E)
        else
            if 2(N.L)(N.H) < (E.H) then G := 2(N.H)(N.L)/(E.H)(N.E)
            else G := 1/(N.E)

    ``G_b`` and ``G_c`` share the factor ``2 (N.H) / (E.H)``, so ``G_b < G_c`` exactly when
    ``N.E < N.L``: the outer test picks the candidate minimum, the inner one compares it with 1.
    The last division reads ``/ ((E.H)(N.E))`` (read left to right, ``/(E.H) * (N.E)``, it would be
    wrong); with that grouping the ordering equals ``min(1, G_b, G_c) / (N.E)`` everywhere (tested)
    and never divides by a vanishing ``N.E``: in the first branch ``G := 1/(N.E)`` is reached only
    when ``N.E >= (E.H) / (2 (N.H))``, and in the second ``N.E >= N.L``.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.E`` (= ``N.V``), ``N.H``, ``E.H`` (= ``V.H``).

    Returns
    -------
    numpy.ndarray or numpy.float64
        ``G / (N.E)``; 0 where ``NL <= 0``, ``NV <= 0``, ``NH <= 0`` or ``VH <= 0``.

    References
    ----------
    - Blinn 1977, "Computational considerations".

    Examples
    --------
    >>> print(f"{G_over_NE_Blinn1977(0.9, 0.1, 0.8, 0.5):.2f}")  # G_b / N.E = 2 N.H / E.H
    3.20
    """
    NL, NE, NH, EH = _cosines(NL, NV, NH, VH)
    valid = (NL > 0) & (NE > 0) & (NH > 0) & (EH > 0)
    EHs, NEs = _positive(EH), _positive(NE)
    masking_first = NE < NL  # Blinn 1977: if (N.E) < (N.L), G_b is the smaller of G_b, G_c
    G = np.where(
        masking_first,
        np.where(2.0 * NE * NH < EH, 2.0 * NH / EHs, 1.0 / NEs),  # G_b/(N.E) or 1/(N.E)
        np.where(2.0 * NL * NH < EH, 2.0 * NH * NL / (EHs * NEs), 1.0 / NEs),  # G_c/(N.E) or 1/(N.E)
    )
    return _out(np.where(valid, G, 0.0))


def G1_Smith_Beckmann_Walter2007(cos_theta: npt.ArrayLike, m: npt.ArrayLike,
                                 form: str = "exact") -> npt.NDArray[np.float64] | np.float64:
    """Smith's masking for one direction over a Beckmann surface of rms slope m.

    With ``a = 1 / (m tan theta) = cos theta / (m sin theta)``:

    - ``"exact"``: ``G1 = 2 / (1 + erf(a) + exp(-a^2) / (a sqrt(pi)))``, evaluated as
      ``2 a sqrt(pi) / (a sqrt(pi) (1 + erf a) + exp(-a^2))`` so that ``a = 0`` (grazing) gives 0.
    - ``"rational"``: Walter et al.'s approximation
      ``(3.535 a + 2.181 a^2) / (1 + 2.276 a + 2.577 a^2)`` for ``a < 1.6``, else 1.

    Parameters
    ----------
    cos_theta : array_like
        ``N.V`` (or ``N.L``); 0 below the horizon.
    m : array_like
        Beckmann rms slope (the ``m`` of Cook & Torrance and ``alpha_b`` of Walter et al.), > 0.
    form : str
        ``"exact"`` or ``"rational"``.

    References
    ----------
    - Smith 1967; Walter et al. 2007, Beckmann G1 (exact and rational approximation).

    Examples
    --------
    >>> print(f"{G1_Smith_Beckmann_Walter2007(1.0, 0.3):.6f}")
    1.000000
    """
    if form not in ("exact", "rational"):
        raise ValueError(f"Unknown Smith G1 form {form!r}; known forms: exact, rational.")
    m = np.asarray(m, dtype=np.float64)
    if np.any(m <= 0):
        raise ValueError(f"'m' (Beckmann rms slope) must be > 0, got {m!r}.")
    (c,) = _cosines(cos_theta)
    c = np.maximum(c, 0.0)
    s = np.sqrt(np.maximum(1.0 - c * c, 0.0))
    # a = cot(theta) / m; beyond 1e6 G1 is 1 to float precision (exp(-a^2) / a underflows), so
    # clamping keeps a finite at normal incidence (sin = 0) without changing the result.
    a = np.minimum(c / np.maximum(m * s, 1e-300), 1e6)
    if form == "exact":
        from scipy.special import erf  # here: scipy.special costs ~0.7 s to import

        root_pi_a = np.sqrt(np.pi) * a
        G1 = 2.0 * root_pi_a / (root_pi_a * (1.0 + erf(a)) + np.exp(-a * a))  # Walter 2007, Beckmann G1
    else:
        G1 = np.where(
            a < 1.6,
            (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a),  # Walter 2007, rational G1
            1.0,
        )
    return _out(np.where(c > 0, G1, 0.0))


def shadowing_Smith_Beckmann_Walter2007(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike,
                                        VH: npt.ArrayLike, m: npt.ArrayLike,
                                        form: str = "exact"
                                       ) -> npt.NDArray[np.float64] | np.float64:
    """Separable Smith shadowing-masking ``G = G1(N.L) G1(N.V)`` for a Beckmann surface.

    The facet-side condition ``chi+((V.H) / (N.V))`` of Walter et al. is applied: G = 0 unless
    ``V.H > 0`` (and ``N.L``, ``N.V`` > 0). ``NH`` is accepted for a common signature with
    :func:`shadowing_VCavity_Blinn1977`; Smith's G does not depend on it.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.V``, ``N.H``, ``V.H``.
    m : array_like
        Beckmann rms slope, > 0 (use the same ``m`` as the distribution).
    form : str
        ``"exact"`` (erf) or ``"rational"`` (Walter et al.'s approximation).

    References
    ----------
    - Smith 1967; Walter et al. 2007, separable G and Beckmann G1.

    Examples
    --------
    >>> print(f"{shadowing_Smith_Beckmann_Walter2007(1.0, 1.0, 1.0, 1.0, 0.3):.6f}")
    1.000000
    """
    NL, NV, NH, VH = _cosines(NL, NV, NH, VH)
    G = G1_Smith_Beckmann_Walter2007(NL, m, form) * G1_Smith_Beckmann_Walter2007(NV, m, form)
    return _out(np.where((VH > 0) & (NL > 0) & (NV > 0), G, 0.0))


SHADOWING_METHODS: dict[str, Callable[..., Any]] = {
    "VCavity_Blinn1977": shadowing_VCavity_Blinn1977,
    "Smith_Beckmann_Walter2007": shadowing_Smith_Beckmann_Walter2007,
}
"""Shadowing-masking methods of :func:`shadowing`, each ``f(NL, NV, NH, VH, ...)``."""


def shadowing(NL: npt.ArrayLike, NV: npt.ArrayLike, NH: npt.ArrayLike, VH: npt.ArrayLike,
              method: str = "VCavity_Blinn1977",
              **kwargs: Any) -> npt.NDArray[np.float64] | np.float64:
    """Geometrical attenuation factor G by one of :data:`SHADOWING_METHODS`.

    Parameters
    ----------
    NL, NV, NH, VH : array_like
        ``N.L``, ``N.V``, ``N.H``, ``V.H``.
    method : str
        ``"VCavity_Blinn1977"`` (Blinn 1977 = Cook & Torrance 1982) or
        ``"Smith_Beckmann_Walter2007"`` (needs ``m``; optional ``form``).
    **kwargs
        The method's parameters.

    Raises
    ------
    ValueError
        For an unknown method (listing the known ones) or wrong parameters.

    Examples
    --------
    >>> print(f"{shadowing(0.9, 0.1, 0.8, 0.5):.2f}")
    0.32
    """
    try:
        function = SHADOWING_METHODS[method]
    except (KeyError, TypeError):
        raise ValueError(
            f"Unknown shadowing method {method!r}; known methods: {', '.join(SHADOWING_METHODS)}."
        ) from None
    try:
        return function(NL, NV, NH, VH, **kwargs)
    except TypeError as error:
        raise ValueError(f"Bad parameters {sorted(kwargs)} for shadowing {method!r}: {error}") from None
