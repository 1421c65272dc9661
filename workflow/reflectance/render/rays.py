"""Exact float64 ray tests: Moller-Trumbore triangles and precise spheres, vectorised.

The private kernels work on component-first arrays (x[0], x[1], x[2] contiguous rows), which
is how :mod:`reflectance.render.primitives` stores the scene; the public functions take (..., 3)
arrays and broadcast them. The kernels are public for the scene's primitives
(:mod:`reflectance.render.primitives`); the vector helpers come from
:mod:`reflectance.geometry.vectors`.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from reflectance.geometry.vectors import dot, normalize, unit_vector

__all__ = ["ray_triangle_MollerTrumbore1997", "ray_sphere"]


def triangle_hits(o, d, a, e1, e2, t_min, t_max, tolerance):
    """Moller-Trumbore on component-first arrays; the triangle is (a, a + e1, a + e2)."""
    s = (o[0] - a[0], o[1] - a[1], o[2] - a[2])
    # Moller & Trumbore 1997, Eq. 5: Cramer's rule with P = D x E2, Q = T x E1
    p = (d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0])
    q = (s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0])
    det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2]
    # det = 0: the ray is parallel to the triangle's plane; the NaN / inf it makes compare False
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        b1 = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv
        b2 = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) * inv
        t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv
        hit = ((b1 >= -tolerance) & (b2 >= -tolerance) & (b1 + b2 <= 1.0 + tolerance)
               & (t > t_min) & (t < t_max))
    return t, b1, b2, hit  # raw: for a miss, where the ray's line meets the plane


def sphere_hits(o, d, c, r, t_min, t_max):
    f = (o[0] - c[0], o[1] - c[1], o[2] - c[2])
    a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
    b = -(f[0] * d[0] + f[1] * d[1] + f[2] * d[2])
    # Haines et al. 2019, Eq. 7.5: the discriminant from the ray's closest approach
    k = b / a
    g = (f[0] + k * d[0], f[1] + k * d[1], f[2] + k * d[2])
    disc = r * r - (g[0] * g[0] + g[1] * g[1] + g[2] * g[2])
    real = disc >= 0
    root = np.sqrt(np.where(real, a * disc, 0.0))
    qq = b + np.where(b >= 0, root, -root)  # Haines et al. 2019, Eq. 7.6: no cancellation
    cc = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - r * r
    t1 = np.asarray(qq / a)
    t0 = np.divide(cc, qq, out=t1.copy(), where=qq != 0)  # qq = 0: a double root at t1
    lo, hi = np.minimum(t0, t1), np.maximum(t0, t1)
    first = (lo > t_min) & (lo < t_max)
    hit = real & (first | ((hi > t_min) & (hi < t_max)))
    return np.where(hit, np.where(first, lo, hi), np.inf), hit


def components_first(*arrays):
    """Broadcast (..., 3) arrays and return each as (3, ...) views."""
    arrays = np.broadcast_arrays(*(np.asarray(x, np.float64) for x in arrays))
    if arrays[0].shape[-1:] != (3,):
        raise ValueError("points and directions must have 3 components on the last axis")
    return [np.moveaxis(x, -1, 0) for x in arrays]


def ray_triangle_MollerTrumbore1997(origins: npt.ArrayLike, directions: npt.ArrayLike,
                                    v0: npt.ArrayLike, v1: npt.ArrayLike, v2: npt.ArrayLike,
                                    t_min: npt.ArrayLike = 0.0, t_max: npt.ArrayLike = np.inf,
                                    tolerance: float = 0.0
                                   ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """Ray-triangle intersection, two-sided, vectorised, float64.

    Parameters
    ----------
    origins, directions, v0, v1, v2 : array_like, shape (..., 3)
        Broadcast against each other. Directions need not be unit (t is then in their units).
    t_min, t_max : float or array_like
        Open interval of accepted ray parameters.
    tolerance : float, optional
        Barycentric slack: accept b1, b2 >= -tolerance and b1 + b2 <= 1 + tolerance, so that a
        ray through a shared edge never falls between its two triangles.

    Returns
    -------
    t, b1, b2 : ndarray
        Ray parameter and barycentric weights of v1, v2 (v0 has 1 - b1 - b2); ``inf`` and 0
        where there is no hit.
    hit : ndarray of bool

    References
    ----------
    Moller, T., & Trumbore, B. (1997). Fast, minimum storage ray-triangle intersection. Journal
    of Graphics Tools, 2(1), 21-28.

    Examples
    --------
    >>> t, b1, b2, hit = ray_triangle_MollerTrumbore1997(
    ...     [0.25, 0.25, 1.0], [0, 0, -1], [0, 0, 0], [1, 0, 0], [0, 1, 0])
    >>> float(t), float(b1), float(b2), bool(hit)
    (1.0, 0.25, 0.25, True)
    """
    o, d, a, b, c = components_first(origins, directions, v0, v1, v2)
    t, b1, b2, hit = triangle_hits(o, d, a, b - a, c - a, t_min, t_max, tolerance)
    return np.where(hit, t, np.inf), np.where(hit, b1, 0.0), np.where(hit, b2, 0.0), hit


def ray_sphere(origins: npt.ArrayLike, directions: npt.ArrayLike, centers: npt.ArrayLike,
               radii: npt.ArrayLike, t_min: npt.ArrayLike = 0.0,
               t_max: npt.ArrayLike = np.inf
              ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """Nearest intersection of rays with spheres in (t_min, t_max), vectorised, float64.

    The discriminant is formed from the ray's closest approach to the centre and the roots
    without cancellation, which keeps the precision for small or distant spheres.

    Parameters
    ----------
    origins, directions, centers : array_like, shape (..., 3)
    radii : array_like, shape (...)
    t_min, t_max : float or array_like

    Returns
    -------
    t : ndarray
        ``inf`` where there is no hit.
    hit : ndarray of bool

    References
    ----------
    Haines, E., Gunther, J., & Akenine-Moller, T. (2019). Precision improvements for ray/sphere
    intersection. In Ray Tracing Gems (pp. 87-94). Apress.

    Examples
    --------
    >>> t, hit = ray_sphere([0, 0, 5.0], [0, 0, -1.0], [0, 0, 0], 1.0)
    >>> float(t), bool(hit)
    (4.0, True)
    """
    o, d, c = components_first(origins, directions, centers)
    return sphere_hits(o, d, c, np.asarray(radii, np.float64), t_min, t_max)
