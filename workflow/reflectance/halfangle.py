"""Blinn's half-value angle beta from a distribution's roughness (the inverse of his conversions).

Blinn (1977, "Facet distribution functions") compares D1, D2 and D3 at equal ``beta``, the facet
angle at which each falls to one half, and gives ``c1``, ``c2``, ``c3`` as functions of ``beta``
(:func:`reflectance.microfacet.beta_to_c3_Blinn1977` and its siblings). His material parameters
are printed as ``c3`` (Figs. 7a, 7b), so comparing Phong with Torrance-Sparrow at equal ``beta``
needs the inverse: ``beta`` from ``c3``.

Solving ``c3^2 = (cos^2 beta - 1) / (cos^2 beta - sqrt 2)`` for ``cos^2 beta`` gives
``cos^2 beta = (1 - sqrt(2) c3^2) / (1 - c3^2)``. ``D3`` at ``alpha = 90`` degrees is ``c3^4``,
so ``beta`` exists only while ``c3^4 < 1/2``, i.e. ``c3 < 2^(-1/4)``.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. ("Facet distribution functions": c3(beta).)
"""

from __future__ import annotations

import numpy as np

__all__ = ["C3_MAX_FOR_BETA", "c3_to_beta_Blinn1977"]

C3_MAX_FOR_BETA = 2.0**-0.25
"""Largest ``c3`` whose D3 still falls to one half before ``alpha = 90`` degrees (``c3^4 = 1/2``)."""


def c3_to_beta_Blinn1977(c3):
    """Half-value angle ``beta`` (radians) of Blinn's D3 with eccentricity ``c3``.

    The inverse of ``c3 = ((cos^2 beta - 1) / (cos^2 beta - sqrt 2))^(1/2)``:
    ``beta = arccos(sqrt((1 - sqrt(2) c3^2) / (1 - c3^2)))``.

    Parameters
    ----------
    c3 : array_like
        Eccentricity, ``0 < c3 < 2^(-1/4)`` (about 0.8409).

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
    beta = np.arccos(np.sqrt(np.clip(cos2_beta, 0.0, 1.0)))
    return beta[()] if beta.ndim == 0 else beta
