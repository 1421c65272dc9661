"""Directions by their angles from the normal, and the intensity reflected in the plane of incidence.

- :func:`direction_from_angles`: the unit vector at angle ``theta`` from N = +z and azimuth ``phi``
  from +x, for any broadcasting shape (Blinn's Fig. 1 cases, Cook & Torrance's Fig. 2, the
  outgoing hemisphere of the lecture's 3-D lobes).
- :func:`plane_of_incidence_vectors`: L, E and N in the plane of incidence, the one convention of
  every plane-of-incidence figure (Blinn Figs. 5 and 6, the lecture's and the article's lobes).
- :func:`intensity_in_plane_of_incidence`: the polar plots of Blinn 1977, Figs. 5 and 6.
- :func:`lobe_peak`: a lobe's largest value up to an angle from N, the one scale of the lecture's
  2-D and 3-D lobes (so the two figures print the same maximum).
- :func:`turned_about_normal`: directions turned about N = +z (the lecture's anisotropic lobe
  with its light turned across the grain).

Blinn draws "the amount of light reflected from a surface as a result of an incident ray at 30
[70] degrees from the surface normal" as a curve whose distance from the centre, in each direction
of the plane of incidence, is the intensity his models print: ``i = p_a + d p_d + s p_s``. The BRDFs
of :mod:`reflectance.optics.brdf` are written so that ``(N.L) f`` is that printed intensity (with
``p_a = 0``), so the curve is ``(N.L) f(L, E)`` for E sweeping the plane.

Convention of the plane of incidence: N = +z and the plane is x-z; the light lies on the -x side,
``L = (-sin theta_i, 0, cos theta_i)``; a signed viewing angle ``theta_r`` is measured from N towards
the mirror side, ``E = (sin theta_r, 0, cos theta_r)``, so the mirror direction is
``theta_r = theta_i`` and negative angles lie on the light's side. Drawn with ``x = r sin theta_r``
(as on matplotlib's polar axes with angles clockwise from the top) the light comes from the left,
as in the lecture. Blinn's figures show the light "from the right": the same plane seen from
behind, drawn with ``x = -r sin theta_r``; their models are isotropic about N, so the side
changes no value.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (Figs. 1, 5 and 6.)
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24. (Fig. 2.)
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from reflectance.optics.brdf import brdf

__all__ = ["direction_from_angles", "plane_of_incidence_vectors", "intensity_in_plane_of_incidence",
           "plane_angles", "lobe_peak", "turned_about_normal"]


def direction_from_angles(theta: npt.ArrayLike, phi: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Unit vectors at angle ``theta`` from N = +z and azimuth ``phi`` from +x (radians).

    ``(sin theta cos phi, sin theta sin phi, cos theta)``, shape ``broadcast(theta, phi).shape + (3,)``.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(direction_from_angles(np.pi / 2, np.pi / 2), 12).tolist()
    [0.0, 1.0, 0.0]
    """
    theta, phi = np.broadcast_arrays(np.asarray(theta, dtype=np.float64),
                                     np.asarray(phi, dtype=np.float64))
    return np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], axis=-1)


def plane_of_incidence_vectors(theta_i: float,
                               theta_r: npt.ArrayLike
                              ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """L, E (shape ``theta_r.shape + (3,)``) and N for light at ``theta_i`` and views ``theta_r``.

    ``L = (-sin theta_i, 0, cos theta_i)`` (the light on the -x side), ``E = (sin theta_r, 0,
    cos theta_r)``, ``N = (0, 0, 1)``: see the module docstring.

    Parameters
    ----------
    theta_i : float
        Angle of incidence from the normal (radians), in ``[0, pi/2)``.
    theta_r : array_like
        Signed viewing angles from the normal (radians), positive towards the mirror side (+x).

    Examples
    --------
    >>> import numpy as np
    >>> L, E, N = plane_of_incidence_vectors(np.pi / 6, np.pi / 6)
    >>> np.round(L + E, 8).tolist()  # mirror direction: L + E along N
    [0.0, 0.0, 1.73205081]
    """
    theta_i = float(theta_i)
    if not 0.0 <= theta_i < np.pi / 2:
        raise ValueError(f"'theta_i' must lie in [0, pi/2) radians, got {theta_i!r}.")
    theta_r = np.asarray(theta_r, dtype=np.float64)
    # Built from sin and cos directly (not from direction_from_angles(theta, pi)), so that the
    # y components are exactly 0.
    L = np.array([-np.sin(theta_i), 0.0, np.cos(theta_i)])
    E = np.stack([np.sin(theta_r), np.zeros_like(theta_r), np.cos(theta_r)], axis=-1)
    return L, E, np.array([0.0, 0.0, 1.0])


def intensity_in_plane_of_incidence(theta_i: float, theta_r: npt.ArrayLike, method: str,
                                    **parameters: Any) -> npt.NDArray[np.float64] | np.float64:
    """Blinn's printed intensity ``i = (N.L) f(L, E)`` (``p_a = 0``) over the plane of incidence.

    Parameters
    ----------
    theta_i : float
        Angle of incidence (radians), light from the -x side.
    theta_r : array_like
        Signed viewing angles (radians), positive towards the mirror side; ``|theta_r| >= pi/2``
        (at or below the horizon) gives 0.
    method : str
        A key of :data:`reflectance.optics.brdf.BRDF_METHODS`, e.g. ``"BlinnPhong1977"`` or
        ``"TorranceSparrow_Blinn1977"``.
    **parameters
        The model's parameters (``p_d``, ``p_s``, ``c1``, ``F``, ``c3``, ...).

    Returns
    -------
    numpy.ndarray
        Intensity per viewing angle (shape of ``theta_r``).

    References
    ----------
    - Blinn 1977, Figs. 5 and 6; "Simple hilight models" (``i = p_a + d p_d + s p_s``).

    Examples
    --------
    >>> import numpy as np
    >>> i = intensity_in_plane_of_incidence(np.pi / 3, [0.0, np.pi / 3], "BlinnPhong1977",
    ...                                     p_d=0.5, p_s=0.5, c1=10.0)
    >>> np.round(i, 6).tolist()  # 0.5 cos 60 + 0.5 cos^10(30 deg); at the mirror: + p_s
    [0.368652, 0.75]
    """
    L, E, N = plane_of_incidence_vectors(theta_i, theta_r)
    # Blinn 1977, i = p_a + d p_d + s p_s with p_a = 0: the BRDF times d = N.L
    i = float(L @ N) * np.asarray(brdf(L, E, N, method, **parameters), dtype=np.float64)
    # cos(pi/2) rounds to 6e-17 > 0: the horizon itself is decided on the angle, not on N.E.
    i = np.where(np.abs(np.asarray(theta_r, dtype=np.float64)) < np.pi / 2, i, 0.0)
    return i[()] if i.ndim == 0 else i


def plane_angles(step_deg: float) -> npt.NDArray[np.float64]:
    """Signed angles from N (radians) across the plane of incidence, -90 to 90 degrees inclusive
    every ``step_deg``: the lecture's 2-D lobes, and the 3-D figure's in-plane check of them.

    Examples
    --------
    >>> np.degrees(plane_angles(45.0)).tolist()
    [-90.0, -45.0, 0.0, 45.0, 90.0]
    """
    return np.radians(np.arange(-90.0, 90.0 + 1e-9, step_deg))


def lobe_peak(f: npt.ArrayLike, theta: npt.ArrayLike, limit_deg: float) -> tuple[float, int]:
    """The largest ``f`` over the directions at most ``limit_deg`` from N, and its flat index.

    ``theta`` holds the (signed, or polar) angles from N in radians, broadcasting against ``f``.
    The lecture's lobes are scaled by this value, in 2-D (the plane of incidence) and in 3-D (the
    outgoing hemisphere): Ward's ``1 / sqrt(N.L N.V)`` grows without bound at the horizon, so a
    lobe's maximum is taken short of it, the same way in both figures.

    Examples
    --------
    >>> import numpy as np
    >>> theta = np.radians([-90.0, -30.0, 0.0, 60.0, 89.0])
    >>> lobe_peak(np.array([9.0, 2.0, 1.0, 3.0, 7.0]), theta, 85.0)
    (3.0, 3)
    """
    f, theta = np.broadcast_arrays(np.asarray(f, dtype=np.float64), np.asarray(theta, dtype=np.float64))
    inside = np.abs(theta) <= np.radians(limit_deg) * (1 + 1e-12)
    if not inside.any():
        raise ValueError(f"no direction within {limit_deg!r} degrees of N")
    index = int(np.argmax(np.where(inside, f, -np.inf)))
    return float(f.flat[index]), index


def turned_about_normal(vectors: npt.ArrayLike, phi: float) -> npt.NDArray[np.float64]:
    """``vectors`` (shape ``(..., 3)``) turned by the azimuth ``phi`` (radians) about N = +z.

    Examples
    --------
    >>> np.round(turned_about_normal([1.0, 0.0, 0.5], np.pi / 2), 12).tolist()
    [0.0, 1.0, 0.5]
    """
    v = np.asarray(vectors, dtype=np.float64)
    c, s = np.cos(phi), np.sin(phi)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1], v[..., 2]], axis=-1)
