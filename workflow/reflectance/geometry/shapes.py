"""Scene geometry as triangulated pyvista meshes with exact (analytic) vertex normals and (u, v).

Every builder returns a :class:`pyvista.PolyData` of triangles carrying

- ``point_data["Normals"]``: unit shading normals, computed analytically from the surface's
  smooth definition (never from the facets), float64;
- ``point_data["uv"]``: texture coordinates in [0, 1] (seams carry duplicated vertices so that
  interpolation never wraps from u = 1 back to 0);
- ``cell_data["part"]``: which part of an object a triangle belongs to (see :data:`VASE_PARTS`);
- ``cell_data["sphere_index"]`` with ``field_data["sphere_center"]`` / ``["sphere_radius"]``:
  the analytic sphere a triangle approximates (-1: none), so that visibility can intersect the
  exact sphere instead of its facets.

:func:`compose` merges several objects into one mesh and tags each triangle with an
``object_id``; that composed mesh is what :mod:`reflectance.render.visibility` consumes.

The vase is the object of Cook & Torrance 1982, Figs. 6 and 7; the superellipsoid is one choice of
an object with varied curvature for Blinn 1977, Fig. 7 (the paper does not describe its object).
"""

from __future__ import annotations

import functools
import os
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pyvista as pv

__all__ = [
    "VASE_PARTS",
    "VASE_INTERPOLATION_METHODS",
    "vase",
    "sphere",
    "torus",
    "superellipsoid_Barr1981",
    "plane",
    "MESH_FILE_SUFFIXES",
    "mesh_from_file",
    "place",
    "compose",
    "analytic_spheres",
]

VASE_PARTS = {"outer": 0, "rim": 1, "inner": 2, "floor": 3, "bottom": 4}
"""Codes of ``cell_data["part"]`` for :func:`vase`; other builders use 0 everywhere."""


def _cubic(s, y):
    from scipy.interpolate import CubicSpline  # here: scipy.interpolate costs ~1.5 s to import

    # not-a-knot cubic spline: C2, so normals and curvature vary smoothly along the profile
    return CubicSpline(s, y, bc_type="not-a-knot")


def _pchip(s, y):
    from scipy.interpolate import PchipInterpolator

    # shape-preserving (no overshoot, so a non-negative radius stays non-negative), only C1
    return PchipInterpolator(s, y)


VASE_INTERPOLATION_METHODS = {"cubic": _cubic, "pchip": _pchip}
"""Interpolants of the vase profile (radius and height against chord-length parameter)."""

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(8)


# --------------------------------------------------------------------------------------------
# Grid triangulation shared by every builder
# --------------------------------------------------------------------------------------------

def grid_mesh(points: npt.NDArray[np.float64], normals: npt.NDArray[np.float64],
              uv: npt.NDArray[np.float64], part: int = 0) -> pv.PolyData:
    """Triangulate a (rows, cols) grid of vertices; drop zero-area triangles (poles, axis).

    Each triangle is oriented so that its geometric normal agrees with its vertex normals.
    """
    rows, cols = points.shape[:2]
    if rows < 2 or cols < 2:
        raise ValueError(f"a surface grid needs at least 2 x 2 vertices, got {rows} x {cols}")
    index = np.arange(rows * cols).reshape(rows, cols)
    a, b = index[:-1, :-1].ravel(), index[:-1, 1:].ravel()
    c, d = index[1:, 1:].ravel(), index[1:, :-1].ravel()
    tris = np.concatenate([np.stack([a, b, c], -1), np.stack([a, c, d], -1)])
    return triangle_mesh(points.reshape(-1, 3), normals.reshape(-1, 3), uv.reshape(-1, 2),
                          tris, part)


def triangle_mesh(P: npt.NDArray[np.float64], N: npt.NDArray[np.float64],
                  uv: npt.NDArray[np.float64], tris: npt.NDArray[np.integer],
                  part: int) -> pv.PolyData:
    """Mesh of triangles ``tris``: zero-area ones dropped, each turned to face its normals."""
    cross = np.cross(P[tris[:, 1]] - P[tris[:, 0]], P[tris[:, 2]] - P[tris[:, 0]])
    area2 = np.linalg.norm(cross, axis=-1)
    scale = max(float(np.ptp(P, axis=0).max()), np.finfo(float).tiny)
    keep = area2 > 1e-14 * scale**2
    tris, cross = tris[keep], cross[keep]
    flip = np.einsum("ij,ij->i", cross, N[tris].sum(axis=1)) < 0
    tris[flip] = tris[flip][:, ::-1]
    return _polydata(P, N, uv, tris, np.full(len(tris), part, np.int32))


def _polydata(points, normals, uv, tris, part, sphere_index=None):
    normals = np.asarray(normals, np.float64)
    normals = normals / np.linalg.norm(normals, axis=-1, keepdims=True)
    return _mesh_from_arrays(
        np.asarray(points, np.float64), normals, np.asarray(uv, np.float64), tris,
        np.asarray(part, np.int32),
        np.full(len(tris), -1, np.int32) if sphere_index is None else sphere_index)


def _mesh_from_arrays(points, normals, uv, tris, part, sphere_index):
    """The PolyData of these arrays, taken as they are."""
    faces = np.column_stack([np.full(len(tris), 3, np.int64), tris]).ravel()
    mesh = pv.PolyData(points, faces=faces)
    mesh.point_data["Normals"] = normals
    mesh.point_data["uv"] = uv
    mesh.cell_data["part"] = part
    mesh.cell_data["sphere_index"] = sphere_index
    return mesh


# --------------------------------------------------------------------------------------------
# Built meshes, cached (reflectance.io.cache)
# --------------------------------------------------------------------------------------------

_MESH_FORMAT = 1
"""Version of the cached meshes' layout; part of every file name."""

_MESH_ARRAYS = {"points": (np.float64, 3), "normals": (np.float64, 3), "uv": (np.float64, 2),
                "tris": (np.int64, 3), "part": (np.int32, None), "sphere_index": (np.int32, None)}
"""The arrays of a cached mesh: dtype and columns (None: one value per triangle)."""


MESH_CACHE_STALE_DAYS = 7
"""A folder of meshes for another code or library version is removed once it has gone this
many days without a new mesh (another checkout in use keeps its own)."""


@functools.lru_cache(maxsize=1)
def _mesh_cache_name():
    """The cached meshes' folder name (of the form
    :data:`reflectance.io.cache.DISK_FOLDERS` gives): this module's source and the numpy, scipy
    and pyvista that built them, so that a change of any builds them again."""
    from reflectance.io.cache import distribution_version, source_digest

    return (f"meshes-{source_digest(__file__)}-numpy-{distribution_version('numpy', 'numpy')}"
            f"-scipy-{distribution_version('scipy', 'scipy')}"
            f"-pyvista-{distribution_version('pyvista', 'pyvista')}")


def _mesh_cache_directory():
    from reflectance.io.cache import cache_root

    return cache_root() / _mesh_cache_name()


def _json_value(value):
    if isinstance(value, (np.ndarray, np.generic)):
        return value.tolist()
    raise TypeError(f"not a plain value: {type(value).__name__}")


def _cached_mesh(kind, build, *args):
    """``build(*args)``, built once per arguments, code and numpy, scipy and pyvista versions
    (:func:`_mesh_cache_name`), then read back from the cache: the very arrays the build gave,
    bit for bit, without the build's imports (the vase's splines import scipy.interpolate, about
    0.5 s). Arguments that are not plain values, or a cache that cannot be located, read or
    written, just build."""
    import zipfile

    import io

    from reflectance.io.cache import DISK_FOLDERS, file_name, load, prune, store

    try:
        path = _mesh_cache_directory() / file_name(_MESH_FORMAT, kind, args, ".npz",
                                                   default=_json_value)
    except (TypeError, ValueError, OSError, RuntimeError):  # not plain values; no home folder
        return build(*args)
    try:
        with np.load(io.BytesIO(load(path)), allow_pickle=False) as data:  # checked: issue 25
            arrays = {name: data[name] for name in _MESH_ARRAYS}
        n_points, n_tris = len(arrays["points"]), len(arrays["tris"])
        for name, (dtype, columns) in _MESH_ARRAYS.items():
            shape = (n_points if name in ("points", "normals", "uv") else n_tris,
                     *(() if columns is None else (columns,)))
            if arrays[name].dtype != dtype or arrays[name].shape != shape:
                raise ValueError(f"{path}: {name} is not {dtype.__name__} {shape}")
        if n_tris and not 0 <= arrays["tris"].min() <= arrays["tris"].max() < n_points:
            raise ValueError(f"{path}: a triangle's vertex is out of range")
        if not all(np.isfinite(arrays[name]).all() for name in ("points", "normals", "uv")):
            raise ValueError(f"{path}: a vertex that is not finite")
        return _mesh_from_arrays(**arrays)
    except (OSError, ValueError, EOFError, KeyError, TypeError, AttributeError,
            zipfile.BadZipFile):  # (an .npy there: np.load gives an array, not an archive)
        pass
    mesh = build(*args)
    if (set(mesh.point_data.keys()) == {"Normals", "uv"}
            and set(mesh.cell_data.keys()) == {"part", "sphere_index"}
            and not mesh.field_data.keys()):
        arrays = {"points": np.asarray(mesh.points, np.float64),
                  "normals": np.asarray(mesh.point_data["Normals"]),
                  "uv": np.asarray(mesh.point_data["uv"]), "tris": _triangles(mesh),
                  "part": np.asarray(mesh.cell_data["part"]),
                  "sphere_index": np.asarray(mesh.cell_data["sphere_index"])}
        if not path.parent.exists():  # a new code or library version: drop the stale meshes
            # (only folders of the meshes' name: DISK_FOLDERS, which _mesh_cache_name follows)
            prune(path.parent, DISK_FOLDERS["meshes"], MESH_CACHE_STALE_DAYS)
        store(path, lambda file: np.savez(file, **arrays))
    return mesh


def merge_meshes(meshes: Sequence[pv.PolyData]) -> pv.PolyData:
    """Concatenate meshes without welding points (parts keep their own normals and uv)."""
    points, normals, uv, tris, part, sidx = [], [], [], [], [], []
    offset = 0
    for mesh in meshes:
        points.append(np.asarray(mesh.points, np.float64))
        normals.append(mesh.point_data["Normals"])
        uv.append(mesh.point_data["uv"])
        tris.append(_triangles(mesh) + offset)
        part.append(mesh.cell_data["part"])
        sidx.append(mesh.cell_data["sphere_index"])
        offset += mesh.n_points
    return _polydata(
        np.concatenate(points), np.concatenate(normals), np.concatenate(uv),
        np.concatenate(tris), np.concatenate(part), np.concatenate(sidx),
    )


def _triangles(mesh):
    """(n, 3) vertex indices of an all-triangle PolyData."""
    if mesh.n_cells == 0:
        return np.zeros((0, 3), np.int64)
    if not mesh.is_all_triangles:
        raise ValueError("mesh must consist of triangles only (use mesh.triangulate())")
    return np.asarray(mesh.faces, np.int64).reshape(-1, 4)[:, 1:]


def _positive_int(value, name, minimum=1):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return int(value)


def _vector3(value, name):
    v = np.asarray(value, dtype=np.float64)
    if v.shape != (3,) or not np.all(np.isfinite(v)):
        raise ValueError(f"{name} must be 3 finite numbers, got {value!r}")
    return v


def check_positive(value: float, name: str) -> float:
    v = float(value)
    if not np.isfinite(v) or v <= 0:
        raise ValueError(f"{name} must be a positive finite number, got {value!r}")
    return v


# --------------------------------------------------------------------------------------------
# Surface of revolution: the vase
# --------------------------------------------------------------------------------------------

def _revolve(r, z, nr, nz, v, n_theta, part):
    """Revolve a sampled profile (r, z) with unit profile normals (nr, nz) about the z axis."""
    theta = np.linspace(0.0, 2.0 * np.pi, n_theta + 1)  # seam column duplicated (u = 0 and 1)
    ct, st = np.cos(theta), np.sin(theta)
    ct[-1], st[-1] = 1.0, 0.0  # the seam closes exactly
    points = np.stack(np.broadcast_arrays(r[:, None] * ct, r[:, None] * st, z[:, None]), -1)
    normals = np.stack(np.broadcast_arrays(nr[:, None] * ct, nr[:, None] * st, nz[:, None]), -1)
    uv = np.stack(np.broadcast_arrays(theta[None, :] / (2.0 * np.pi), v[:, None]), -1)
    return grid_mesh(points, normals, uv, part)


def _disc(radius, z, normal_z, n_theta, spacing, part):
    """Flat disc at height z with normal (0, 0, normal_z), its rim on the n_theta wall angles.

    Rings about ``spacing`` apart; going inwards, a ring's segment count halves wherever its
    segments have become much shorter than the ring spacing, so the triangles keep a bounded
    shape down to the centre (no fan of slivers there). u = angle / 2 pi, v = r / radius.
    """
    n_rings = max(1, int(np.ceil(radius / spacing)))
    r = np.linspace(0.0, radius, n_rings + 1)
    counts = [n_theta]
    for i in range(n_rings - 1, 0, -1):  # ring i from the outside in
        c = counts[-1]
        if c % 2 == 0 and c >= 12 and 2 * np.pi * r[i] / c < 0.5 * (r[1] - r[0]):
            c //= 2
        counts.append(c)
    counts = counts[::-1]  # counts[i - 1] segments on ring i = 1 .. n_rings
    points, uv, start = [], [], []
    size = 0
    inner = counts[0]
    for j in range(inner):  # one centre vertex per wedge, so that u stays continuous
        points.append([0.0, 0.0, z])
        uv.append([(j + 0.5) / inner, 0.0])
    size = inner
    for i, c in enumerate(counts, start=1):
        theta = np.linspace(0.0, 2 * np.pi, c + 1)
        ct, st = np.cos(theta), np.sin(theta)
        ct[-1], st[-1] = 1.0, 0.0
        start.append(size)
        points.extend(np.column_stack([r[i] * ct, r[i] * st, np.full(c + 1, z)]))
        uv.extend(np.column_stack([theta / (2 * np.pi), np.full(c + 1, r[i] / radius)]))
        size += c + 1
    j = np.arange(inner)
    tris = [np.column_stack([j, start[0] + j, start[0] + j + 1])]
    for i in range(len(counts) - 1):
        ci, co, a, b = counts[i], counts[i + 1], start[i], start[i + 1]
        j = np.arange(ci)
        if co == ci:
            tris += [np.column_stack([a + j, b + j, b + j + 1]),
                     np.column_stack([a + j, b + j + 1, a + j + 1])]
        else:  # co == 2 ci: three triangles per inner segment
            tris += [np.column_stack([a + j, b + 2 * j, b + 2 * j + 1]),
                     np.column_stack([a + j, b + 2 * j + 1, a + j + 1]),
                     np.column_stack([a + j + 1, b + 2 * j + 1, b + 2 * j + 2])]
    points = np.asarray(points, np.float64)
    normals = np.tile([0.0, 0.0, normal_z], (len(points), 1))
    return triangle_mesh(points, normals, np.asarray(uv, np.float64),
                          np.concatenate(tris).astype(np.int64), part)


def _arc_length(speed, s):
    """Cumulative arc length at parameters s (8-point Gauss-Legendre per interval)."""
    lo, hi = s[:-1, None], s[1:, None]
    x = 0.5 * (hi - lo) * _GAUSS_X[None, :] + 0.5 * (hi + lo)
    pieces = 0.5 * (hi[:, 0] - lo[:, 0]) * (speed(x) @ _GAUSS_W)
    return np.concatenate([[0.0], np.cumsum(pieces)])


def _fraction(length):
    return length / length[-1] if length[-1] > 0 else np.zeros_like(length)


def vase(profile: npt.ArrayLike, n_theta: int, n_profile_samples: int, wall_thickness: float,
         n_rim_samples: int = 9, interpolation: str = "cubic") -> pv.PolyData:
    """Thin-walled vase: a smooth profile revolved about the z axis, open at the top.

    The outer wall is the profile interpolated smoothly (chord-length parameter s); the inner
    wall is its offset curve at distance ``wall_thickness`` along the inward profile normal (an
    offset curve shares the normals of its base curve, so both walls have exact normals); the
    rim is a half circle of diameter ``wall_thickness`` joining them with continuous normals. If
    the profile starts off the axis, a flat bottom closes the outside and a flat floor the
    inside, at ``wall_thickness`` above the bottom; their rings thin out toward the centre so
    that no fan of sliver triangles forms there. The shell is closed, so a point inside the
    vase can only see a light outside through the opening, never through the wall.

    Parameters
    ----------
    profile : array_like, shape (n, 2)
        (radius, height) points from the bottom up (Cook & Torrance 1982, Figs. 6-7); radius >= 0,
        at least 3 points, consecutive points distinct.
    n_theta : int
        Segments around the axis.
    n_profile_samples : int
        Samples along the outer profile (the inner wall gets as many).
    wall_thickness : float
        Wall thickness, smaller than the profile's radius of curvature on the inner side.
    n_rim_samples : int, optional
        Samples across the rim's half circle.
    interpolation : str, optional
        A key of :data:`VASE_INTERPOLATION_METHODS`.

    Returns
    -------
    pyvista.PolyData
        Triangles with ``Normals``, ``uv`` (u = angle / 2 pi, v = arc-length fraction along the
        part's own profile, from the bottom up; from outside to inside on the rim; from the axis
        outwards on the bottom and the floor) and ``part`` (:data:`VASE_PARTS`).

    References
    ----------
    Cook, R. L., & Torrance, K. E. (1982). A reflectance model for computer graphics. ACM
    Transactions on Graphics, 1(1), 7-24 (Figs. 6, 7: the vases).

    Examples
    --------
    >>> mesh = vase([(0.5, 0.0), (0.8, 0.5), (0.4, 1.0)], 16, 8, 0.05)
    >>> mesh.is_all_triangles, np.unique(mesh.cell_data["part"]).tolist()
    (True, [0, 1, 2, 3, 4])
    """
    return _cached_mesh("vase", _vase, profile, n_theta, n_profile_samples, wall_thickness,
                        n_rim_samples, interpolation)


def _vase(profile, n_theta, n_profile_samples, wall_thickness, n_rim_samples, interpolation):
    """:func:`vase`, built (no cache)."""
    if interpolation not in VASE_INTERPOLATION_METHODS:
        raise ValueError(
            f"unknown vase interpolation {interpolation!r}; "
            f"known: {sorted(VASE_INTERPOLATION_METHODS)}"
        )
    n_theta = _positive_int(n_theta, "n_theta", 3)
    n_samples = _positive_int(n_profile_samples, "n_profile_samples", 2)
    n_rim = _positive_int(n_rim_samples, "n_rim_samples", 2)
    t = check_positive(wall_thickness, "wall_thickness")
    P = np.asarray(profile, dtype=np.float64)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 3:
        raise ValueError(f"profile must be at least 3 (radius, height) points, got shape {P.shape}")
    if not np.all(np.isfinite(P)):
        raise ValueError("profile contains non-finite values")
    if np.any(P[:, 0] < 0):
        raise ValueError(f"profile radius must be >= 0; row {int(np.argmax(P[:, 0] < 0))} is not")
    chord = np.linalg.norm(np.diff(P, axis=0), axis=1)
    if np.any(chord == 0):
        raise ValueError(f"profile rows {int(np.argmin(chord))} and {int(np.argmin(chord)) + 1} "
                         "are the same point")
    s_knots = np.concatenate([[0.0], np.cumsum(chord)]) / chord.sum()
    fit = VASE_INTERPOLATION_METHODS[interpolation]
    R, Z = fit(s_knots, P[:, 0]), fit(s_knots, P[:, 1])
    dR, dZ, d2R, d2Z = R.derivative(1), Z.derivative(1), R.derivative(2), Z.derivative(2)

    def frame(s):
        r1, z1 = dR(s), dZ(s)
        speed = np.hypot(r1, z1)
        return speed, r1 / speed, z1 / speed  # unit tangent; outward normal is (tz, -tr)

    dense = np.linspace(0.0, 1.0, 64 * n_samples + 1)
    speed = np.hypot(dR(dense), dZ(dense))
    if np.any(speed <= 0):
        raise ValueError("profile interpolation has a cusp (zero tangent)")
    r_dense = R(dense)
    if np.any(r_dense < 0):
        raise ValueError(f"{interpolation} interpolation of the profile crosses the axis "
                         "(negative radius); add points or use interpolation='pchip'")
    # offset curve P - t n turns back on itself where t * curvature >= 1 on the inner side
    curvature = (dR(dense) * d2Z(dense) - dZ(dense) * d2R(dense)) / speed**3
    if np.any(t * curvature >= 1.0):
        raise ValueError(f"wall_thickness {t} exceeds the profile's inner radius of curvature "
                         f"{1.0 / curvature.max():.6g}")

    def outer(s):
        return R(s), Z(s)

    def outer_speed(s):
        return np.hypot(dR(s), dZ(s))

    def inner(s):
        _, a, b = frame(s)
        return R(s) - t * b, Z(s) + t * a  # P - t n with n = (tz, -tr)

    def inner_speed(s):
        r1, z1 = dR(s), dZ(s)
        speed = np.hypot(r1, z1)
        k = (r1 * d2Z(s) - z1 * d2R(s)) / speed**3
        return speed * np.abs(1.0 - t * k)  # |d/ds (P - t n)| = |P'| |1 - t k|

    def revolve_profile(s, curve, curve_speed, part):
        rr, zz = curve(s)
        _, a, b = frame(s)
        sign = 1.0 if part == VASE_PARTS["outer"] else -1.0  # inner wall faces the axis
        v = _fraction(_arc_length(curve_speed, s))
        return _revolve(rr, zz, sign * b, -sign * a, v, n_theta, part)

    parts = []
    s_outer = np.linspace(0.0, 1.0, n_samples)
    parts.append(revolve_profile(s_outer, outer, outer_speed, VASE_PARTS["outer"]))

    # rim: half circle from the outer top point to the inner top point, normal turning from
    # n through the tangent to -n
    r1, z1 = R(1.0), Z(1.0)
    _, a1, b1 = frame(1.0)
    n1 = np.array([b1, -a1])
    t1 = np.array([a1, b1])
    phi = np.linspace(0.0, np.pi, n_rim)
    normal2d = np.cos(phi)[:, None] * n1 + np.sin(phi)[:, None] * t1
    centre = np.array([r1, z1]) - 0.5 * t * n1
    rim = centre + 0.5 * t * normal2d
    if np.any(rim[:, 0] <= 0):
        raise ValueError("the rim reaches the axis: wall_thickness is too large for the opening")
    parts.append(_revolve(rim[:, 0], rim[:, 1], normal2d[:, 0], normal2d[:, 1],
                          phi / np.pi, n_theta, VASE_PARTS["rim"]))

    # where the inner wall starts: above the floor (flat bottom) or at the axis
    r0, z0 = P[0]
    ri_dense, zi_dense = inner(dense)
    if r0 > 0:
        z_floor = z0 + t
        gap = zi_dense - z_floor
    else:
        gap = ri_dense
    if gap[0] >= 0:
        s_start = 0.0
    else:
        above = np.nonzero(gap >= 0)[0]
        if len(above) == 0:
            raise ValueError("the inner wall never clears the bottom: wall_thickness too large")
        k = above[0]
        fn = (lambda s: inner(s)[1] - z_floor) if r0 > 0 else (lambda s: inner(s)[0])
        from scipy.optimize import brentq

        s_start = brentq(fn, dense[k - 1], dense[k], xtol=1e-15, rtol=4 * np.finfo(float).eps)
    if np.any(ri_dense[dense >= s_start] < -1e-12):
        raise ValueError("the inner wall crosses the axis: wall_thickness too large")
    s_inner = np.linspace(s_start, 1.0, n_samples)
    parts.append(revolve_profile(s_inner, inner, inner_speed, VASE_PARTS["inner"]))

    # flat floor inside (normal +z) and flat bottom outside (normal -z)
    rf, zf = inner(s_start)
    spacing = _arc_length(outer_speed, np.array([0.0, 1.0]))[-1] / (n_samples - 1)
    if rf > 1e-12:
        parts.append(_disc(rf, zf, 1.0, n_theta, spacing, VASE_PARTS["floor"]))
    if r0 > 0:
        parts.append(_disc(r0, z0, -1.0, n_theta, spacing, VASE_PARTS["bottom"]))
    return merge_meshes(parts)


# --------------------------------------------------------------------------------------------
# Analytic solids
# --------------------------------------------------------------------------------------------

def sphere(center: npt.ArrayLike, radius: float, n_theta: int, n_phi: int) -> pv.PolyData:
    """Sphere: a faceted proxy for rasterisation plus the exact centre and radius.

    The proxy is a longitude-latitude polyhedron scaled so that it encloses the sphere (every
    face plane at distance >= ``radius`` from the centre): every camera ray that meets the
    exact sphere meets the proxy, and :mod:`reflectance.render.visibility` then intersects the exact
    sphere, so positions, normals and (u, v) of sphere samples do not depend on the facets.

    Parameters
    ----------
    center : array_like, shape (3,)
    radius : float
    n_theta : int
        Segments around the z axis (>= 3).
    n_phi : int
        Segments from the south pole (-z) to the north pole (>= 2).

    Returns
    -------
    pyvista.PolyData
        With ``uv`` = (azimuth / 2 pi, polar angle from -z / pi), the exact unit normals
        (directions from the centre) at the proxy vertices, ``sphere_index`` 0 on every cell and
        ``field_data["sphere_center"]``, ``["sphere_radius"]``.

    Examples
    --------
    >>> s = sphere((0, 0, 0), 2.0, 32, 16)
    >>> float(s.field_data["sphere_radius"][0])
    2.0
    """
    c = _vector3(center, "center")
    r = check_positive(radius, "radius")
    n_theta = _positive_int(n_theta, "n_theta", 3)
    n_phi = _positive_int(n_phi, "n_phi", 2)
    theta = np.linspace(0.0, 2.0 * np.pi, n_theta + 1)
    polar = np.linspace(0.0, np.pi, n_phi + 1)
    st, ct = np.sin(theta), np.cos(theta)
    st[-1], ct[-1] = 0.0, 1.0
    sp, cp = np.sin(polar), np.cos(polar)
    sp[[0, -1]] = 0.0
    e = np.stack(np.broadcast_arrays(sp[:, None] * ct, sp[:, None] * st, -cp[:, None]), -1)
    uv = np.stack(np.broadcast_arrays(theta[None, :] / (2 * np.pi), polar[:, None] / np.pi), -1)
    mesh = grid_mesh(e, e, uv)  # unit sphere first
    tris = _triangles(mesh)
    V = np.asarray(mesh.points)
    n = np.cross(V[tris[:, 1]] - V[tris[:, 0]], V[tris[:, 2]] - V[tris[:, 0]])
    plane_distance = np.abs(np.einsum("ij,ij->i", n, V[tris[:, 0]])) / np.linalg.norm(n, axis=1)
    enlarge = (1.0 + 1e-9) / plane_distance.min()  # the scaled polyhedron contains the ball
    mesh.points = c + (r * enlarge) * V
    mesh.cell_data["sphere_index"] = np.zeros(mesh.n_cells, np.int32)
    mesh.field_data["sphere_center"] = c[None, :]
    mesh.field_data["sphere_radius"] = np.array([r])
    return mesh


def torus(major_radius: float, minor_radius: float, n_u: int, n_v: int,
          center: npt.ArrayLike = (0.0, 0.0, 0.0)) -> pv.PolyData:
    """Ring torus about the z axis with exact normals; u around the axis, v around the tube.

    Parameters
    ----------
    major_radius, minor_radius : float
        Distance of the tube centre from the axis, tube radius (``minor < major``).
    n_u, n_v : int
        Segments around the axis and around the tube.
    center : array_like, shape (3,), optional

    Returns
    -------
    pyvista.PolyData

    Examples
    --------
    >>> torus(1.0, 0.25, 24, 12).is_all_triangles
    True
    """
    R = check_positive(major_radius, "major_radius")
    r = check_positive(minor_radius, "minor_radius")
    if r >= R:
        raise ValueError(f"minor_radius {r} must be smaller than major_radius {R} (ring torus)")
    c = _vector3(center, "center")
    n_u = _positive_int(n_u, "n_u", 3)
    n_v = _positive_int(n_v, "n_v", 3)
    u = np.linspace(0.0, 2 * np.pi, n_u + 1)
    v = np.linspace(0.0, 2 * np.pi, n_v + 1)
    cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
    cu[-1], su[-1], cv[-1], sv[-1] = 1.0, 0.0, 1.0, 0.0
    normal = np.stack(np.broadcast_arrays(cv[:, None] * cu, cv[:, None] * su, sv[:, None]), -1)
    ring = np.stack(np.broadcast_arrays(cu, su, 0.0 * cu), -1)[None, :, :]
    points = c + R * ring + r * normal
    uv = np.stack(np.broadcast_arrays(u[None, :] / (2 * np.pi), v[:, None] / (2 * np.pi)), -1)
    return grid_mesh(points, normal, uv)


def _signed_power(x, exponent):
    return np.sign(x) * np.abs(x) ** exponent


def superellipsoid_Barr1981(radii: npt.ArrayLike, exponents: npt.ArrayLike, n_u: int, n_v: int,
                            center: npt.ArrayLike = (0.0, 0.0, 0.0)) -> pv.PolyData:
    """Superellipsoid (superquadric ellipsoid) with exact normals: an object of varied curvature.

    Points ``(a1 C(eta)^e1 C(w)^e2, a2 C(eta)^e1 S(w)^e2, a3 S(eta)^e1)`` and normals
    ``(C(eta)^(2-e1) C(w)^(2-e2) / a1, C(eta)^(2-e1) S(w)^(2-e2) / a2, S(eta)^(2-e1) / a3)``
    (normalised), with signed powers, for eta in [-pi/2, pi/2] and w in [-pi, pi]. Exponents near
    0 give a rounded box (flat faces, tight edges), 1 an ellipsoid.

    Parameters
    ----------
    radii : array_like, shape (3,)
        Semi-axes (a1, a2, a3).
    exponents : array_like, shape (2,)
        (e1, e2), the north-south and east-west squareness, each in (0, 2).
    n_u, n_v : int
        Segments in w (around z) and in eta (pole to pole).
    center : array_like, shape (3,), optional

    Returns
    -------
    pyvista.PolyData
        ``uv`` = ((w + pi) / 2 pi, (eta + pi / 2) / pi).

    References
    ----------
    Barr, A. H. (1981). Superquadrics and angle-preserving transformations. IEEE Computer
    Graphics and Applications, 1(1), 11-23 (superellipsoid and its normal vector).

    Examples
    --------
    >>> superellipsoid_Barr1981((1, 1, 1), (0.5, 0.5), 32, 16).is_all_triangles
    True
    """
    a = np.asarray(radii, dtype=np.float64)
    if a.shape != (3,) or not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError(f"radii must be 3 positive numbers, got {radii!r}")
    e = np.asarray(exponents, dtype=np.float64)
    if e.shape != (2,) or not np.all((e > 0) & (e < 2)):
        raise ValueError(f"exponents must be 2 numbers in (0, 2), got {exponents!r}")
    c = _vector3(center, "center")
    n_u = _positive_int(n_u, "n_u", 3)
    n_v = _positive_int(n_v, "n_v", 2)
    eta = np.linspace(-np.pi / 2, np.pi / 2, n_v + 1)
    w = np.linspace(-np.pi, np.pi, n_u + 1)

    def trig(angle):
        cos, sin = np.cos(angle), np.sin(angle)
        cos[np.abs(cos) < 1e-15] = 0.0  # exact zeros at multiples of pi/2 (x^e of 6e-17 is not 0)
        sin[np.abs(sin) < 1e-15] = 0.0
        return cos, sin

    ce, se = trig(eta)
    cw, sw = trig(w)
    # Barr 1981, superellipsoid surface vector
    points = c + np.stack(np.broadcast_arrays(
        a[0] * _signed_power(ce, e[0])[:, None] * _signed_power(cw, e[1]),
        a[1] * _signed_power(ce, e[0])[:, None] * _signed_power(sw, e[1]),
        a[2] * _signed_power(se, e[0])[:, None]), -1)
    # Barr 1981, superellipsoid normal vector
    normal = np.stack(np.broadcast_arrays(
        _signed_power(ce, 2 - e[0])[:, None] * _signed_power(cw, 2 - e[1]) / a[0],
        _signed_power(ce, 2 - e[0])[:, None] * _signed_power(sw, 2 - e[1]) / a[1],
        _signed_power(se, 2 - e[0])[:, None] / a[2]), -1)
    uv = np.stack(np.broadcast_arrays((w[None, :] + np.pi) / (2 * np.pi),
                                      (eta[:, None] + np.pi / 2) / np.pi), -1)
    return grid_mesh(points, normal, uv)


def plane(center: npt.ArrayLike, normal: npt.ArrayLike, size: Sequence[float],
          resolution: Sequence[int], u_direction: npt.ArrayLike | None = None) -> pv.PolyData:
    """Flat rectangle of triangles, normal constant, uv in [0, 1]^2.

    Parameters
    ----------
    center, normal : array_like, shape (3,)
    size : (float, float)
        Extent along the u and v directions.
    resolution : (int, int)
        Segments along u and v.
    u_direction : array_like, shape (3,), optional
        In-plane u axis (projected onto the plane); default: the direction of the world axis
        least aligned with ``normal``, made orthogonal to it.

    Returns
    -------
    pyvista.PolyData

    Examples
    --------
    >>> plane((0, 0, 0), (0, 0, 1), (2, 2), (4, 4)).n_cells
    32
    """
    c = _vector3(center, "center")
    n = _vector3(normal, "normal")
    if np.linalg.norm(n) == 0:
        raise ValueError("normal must not be zero")
    n = n / np.linalg.norm(n)
    if u_direction is None:
        helper = np.eye(3)[int(np.argmin(np.abs(n)))]
    else:
        helper = _vector3(u_direction, "u_direction")
    e1 = helper - np.dot(helper, n) * n
    if np.linalg.norm(e1) < 1e-12:
        raise ValueError("u_direction must not be parallel to normal")
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    su, sv = (check_positive(x, "size") for x in size)
    nu, nv = (_positive_int(k, "resolution") for k in resolution)
    u = np.linspace(0.0, 1.0, nu + 1)
    v = np.linspace(0.0, 1.0, nv + 1)
    points = (c + ((u[None, :, None] - 0.5) * su) * e1 + ((v[:, None, None] - 0.5) * sv) * e2)
    normals = np.broadcast_to(n, points.shape)
    uv = np.stack(np.broadcast_arrays(u[None, :], v[:, None]), -1)
    return grid_mesh(points, normals, uv)


# --------------------------------------------------------------------------------------------
# Meshes from files, placement and composition
# --------------------------------------------------------------------------------------------

MESH_FILE_SUFFIXES = (".obj", ".ply", ".stl", ".vtk", ".vtp")


def _with_attributes(mesh, feature_angle, source):
    """Triangulated copy of ``mesh`` with Normals, uv, part and sphere_index."""
    if isinstance(mesh, pv.MultiBlock):
        mesh = mesh.combine()
    if not isinstance(mesh, pv.PolyData):
        mesh = mesh.extract_surface()
    mesh = mesh.triangulate()
    if mesh.n_cells == 0:
        raise ValueError(f"{source}: mesh has no surface triangles")
    normals = mesh.point_data.get("Normals")
    if normals is None or np.shape(normals) != (mesh.n_points, 3):
        # smooth vertex normals; vertices on edges sharper than feature_angle are split
        mesh = mesh.compute_normals(cell_normals=False, point_normals=True, split_vertices=True,
                                    feature_angle=feature_angle, consistent_normals=True,
                                    auto_orient_normals=False)
    normals = np.asarray(mesh.point_data["Normals"], np.float64)
    length = np.linalg.norm(normals, axis=1)
    if not np.all(np.isfinite(normals)) or np.any(length == 0):
        raise ValueError(f"{source}: vertex normals contain zeros or non-finite values")
    uv = mesh.point_data.get("uv")
    if uv is None:
        uv = mesh.active_texture_coordinates
    if uv is None or np.shape(uv) != (mesh.n_points, 2):
        # no texture coordinates: spherical mapping about the bounding-box centre
        d = np.asarray(mesh.points, np.float64) - np.asarray(mesh.center)
        rho = np.linalg.norm(d, axis=1)
        u = np.mod(np.arctan2(d[:, 1], d[:, 0]) / (2 * np.pi), 1.0)
        v = np.arccos(np.clip(-d[:, 2] / np.where(rho > 0, rho, 1.0), -1.0, 1.0)) / np.pi
        uv = np.column_stack([u, v])
    part = mesh.cell_data.get("part")
    sidx = mesh.cell_data.get("sphere_index")
    out = _polydata(mesh.points, normals, np.asarray(uv, np.float64), _triangles(mesh),
                    np.zeros(mesh.n_cells, np.int32) if part is None else part,
                    None if sidx is None else np.asarray(sidx, np.int32))
    for key in ("sphere_center", "sphere_radius"):
        if key in mesh.field_data:
            out.field_data[key] = mesh.field_data[key]
    return out


def mesh_from_file(path: str | os.PathLike[str], feature_angle: float = 30.0) -> pv.PolyData:
    """Read a triangle mesh (OBJ, PLY, STL, VTK, VTP) with pyvista.

    Normals stored in the file are used; otherwise smooth vertex normals are computed, split
    along edges sharper than ``feature_angle``. Texture coordinates stored in the file are used;
    otherwise a spherical mapping about the bounding-box centre stands in.

    Parameters
    ----------
    path : str or Path
    feature_angle : float, optional
        Degrees.

    Returns
    -------
    pyvista.PolyData
    """
    path = Path(path)
    if path.suffix.lower() not in MESH_FILE_SUFFIXES:
        raise ValueError(f"{path}: unsupported mesh format {path.suffix!r}; "
                         f"known: {list(MESH_FILE_SUFFIXES)}")
    if not path.is_file():
        raise ValueError(f"{path}: mesh file not found")
    from reflectance.geometry.mesh_files import check_mesh_file, check_read_mesh

    check_mesh_file(path)  # what would crash VTK's reader, or exhaust memory, is refused first
    from pyvista.core.utilities import VtkErrorCatcher

    try:
        with VtkErrorCatcher(raise_errors=True, send_to_logging=False):
            mesh = pv.read(path)
    except RuntimeError as err:
        first = str(err).strip().splitlines()[0] if str(err).strip() else "an error"
        raise ValueError(f"{path}: VTK cannot read it ({first[:200]})") from None
    check_read_mesh(mesh, path)  # (the formats whose payload VTK alone decodes)
    return _with_attributes(mesh, float(feature_angle), str(path))


def place(mesh: pv.PolyData, offset: npt.ArrayLike = (0.0, 0.0, 0.0), scale: float = 1.0,
          rotation: npt.ArrayLike | None = None) -> pv.PolyData:
    """Copy of ``mesh`` moved by ``x -> scale * rotation @ x + offset``.

    Normals turn with the rotation; analytic spheres move and scale with the mesh.

    Parameters
    ----------
    mesh : pyvista.PolyData
        As returned by the builders of this module.
    offset : array_like, shape (3,), optional
    scale : float, optional
        Uniform, positive.
    rotation : array_like, shape (3, 3), optional
        Proper rotation matrix.

    Returns
    -------
    pyvista.PolyData
    """
    t = _vector3(offset, "offset")
    k = check_positive(scale, "scale")
    Rm = np.eye(3) if rotation is None else np.asarray(rotation, dtype=np.float64)
    if Rm.shape != (3, 3) or not np.allclose(Rm @ Rm.T, np.eye(3), atol=1e-9) \
            or np.linalg.det(Rm) <= 0:
        raise ValueError("rotation must be a proper 3 x 3 rotation matrix")
    out = mesh.copy(deep=True)
    out.points = k * np.asarray(mesh.points, np.float64) @ Rm.T + t
    out.point_data["Normals"] = np.asarray(mesh.point_data["Normals"], np.float64) @ Rm.T
    if "sphere_center" in mesh.field_data:
        out.field_data["sphere_center"] = (
            k * np.asarray(mesh.field_data["sphere_center"], np.float64).reshape(-1, 3) @ Rm.T + t
        )
        out.field_data["sphere_radius"] = k * np.asarray(mesh.field_data["sphere_radius"])
    return out


def analytic_spheres(mesh: pv.PolyData) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """(centres (S, 3), radii (S,)) of the analytic spheres a mesh carries (S may be 0)."""
    if "sphere_center" not in mesh.field_data:
        return np.zeros((0, 3)), np.zeros(0)
    return (np.asarray(mesh.field_data["sphere_center"], np.float64).reshape(-1, 3),
            np.asarray(mesh.field_data["sphere_radius"], np.float64).reshape(-1))


def compose(objects: Iterable[tuple[pv.PolyData, int]]) -> pv.PolyData:
    """Merge objects into one triangle mesh tagged with ``cell_data["object_id"]``.

    Parameters
    ----------
    objects : sequence of (pyvista.PolyData, int)
        Each mesh with the object id (>= 0) that all its triangles get. Meshes not made by this
        module get smooth normals and a spherical (u, v) as in :func:`mesh_from_file`.

    Returns
    -------
    pyvista.PolyData
        ``Normals``, ``uv``, ``object_id``, ``part``, ``sphere_index`` (renumbered across the
        scene) and the field data ``sphere_center`` / ``sphere_radius`` of all spheres.

    Examples
    --------
    >>> scene = compose([(sphere((0, 0, 0), 1, 16, 8), 3), (plane((0, 0, -1), (0, 0, 1),
    ...                  (4, 4), (2, 2)), 7)])
    >>> np.unique(scene.cell_data["object_id"]).tolist(), analytic_spheres(scene)[1].tolist()
    ([3, 7], [1.0])
    """
    objects = list(objects)
    if not objects:
        raise ValueError("compose needs at least one (mesh, object_id) pair")
    meshes: list[pv.PolyData] = []
    ids: list[npt.NDArray[np.int32]] = []
    centers: Any = []  # the spheres' centres and radii of each object, then all of them
    radii: Any = []
    for k, item in enumerate(objects):
        if not (isinstance(item, (tuple, list)) and len(item) == 2):
            raise ValueError(f"objects[{k}] must be a (mesh, object_id) pair")
        mesh, object_id = item
        if isinstance(object_id, bool) or not isinstance(object_id, (int, np.integer)) \
                or object_id < 0:
            raise ValueError(f"objects[{k}]: object_id must be an integer >= 0, got {object_id!r}")
        if not isinstance(mesh, pv.DataSet | pv.MultiBlock):
            raise ValueError(f"objects[{k}]: expected a pyvista mesh, got {type(mesh).__name__}")
        mesh = _with_attributes(mesh, 30.0, f"objects[{k}]")
        c, r = analytic_spheres(mesh)
        sidx = np.asarray(mesh.cell_data["sphere_index"], np.int32).copy()
        if len(c) == 0 and np.any(sidx >= 0):
            raise ValueError(f"objects[{k}]: sphere_index set without sphere_center/radius")
        sidx[sidx >= 0] += sum(len(x) for x in centers)
        mesh.cell_data["sphere_index"] = sidx
        centers.append(c)
        radii.append(r)
        meshes.append(mesh)
        ids.append(np.full(mesh.n_cells, int(object_id), np.int32))
    scene = merge_meshes(meshes)
    scene.cell_data["object_id"] = np.concatenate(ids)
    centers, radii = np.concatenate(centers), np.concatenate(radii)
    if len(radii):
        scene.field_data["sphere_center"] = centers
        scene.field_data["sphere_radius"] = radii
    return scene
