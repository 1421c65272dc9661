"""Visibility and cast shadows: VTK finds the surface, float64 numpy computes where exactly.

VTK rasterises an *ID buffer* off-screen: every triangle of the scene is drawn flat, unlit,
without anti-aliasing or multisampling, in a colour that encodes its index in 24 bits (0 is the
background). The buffer is only used to *choose* which triangle a sample sees; the sample's
position, normal and (u, v) then come from intersecting its exact camera ray with that triangle
(Moller-Trumbore, float64), or with the exact sphere when the triangle belongs to an analytic
sphere (:func:`reflectance.geometry.sphere`). No 8-bit quantity limits the shading.

Where the raster and the exact ray disagree (silhouettes, shared edges), the triangles of the
3 x 3 neighbouring ID pixels are tested and the nearest exact hit wins; a sample whose ray meets
none of them is background. :attr:`SurfaceSamples.stats` reports how often this happens.

Shadows use the same idea from each light's point of view: an ID map (orthographic for a
directional light, perspective or a six-face cube for a point light) proposes, for each surface
sample, the primitives seen in the 3 x 3 map pixels around the sample's projection, and an
exact float64 ray from the sample to the light is tested against each of them. Every point of
that ray projects onto the same spot of the light's map, so the surface the light meets first
there is seen at or next to those pixels; when the ray misses a proposed triangle but crosses
its plane within reach, the test walks across the edge beyond which the crossing lies (point
location on the occluding mesh), which recovers triangles hidden in a vertex's fan or thinner
than a map pixel. A reported shadow is always a real occluder; a missed one needs an occluder
that the map shows nowhere near the sample's projection (smaller than a map pixel and farther
than the walk reaches).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pyvista as pv
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers VTK's OpenGL backend)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)

from reflectance.geometry import analytic_spheres, compose

__all__ = [
    "Camera",
    "DirectionalLight",
    "PointLight",
    "LIGHT_TYPES",
    "as_light",
    "light_vectors",
    "SurfaceSamples",
    "encode_ids",
    "decode_ids",
    "id_buffer",
    "ray_triangle_MollerTrumbore1997",
    "ray_sphere",
    "visibility",
    "shadow_mask",
    "shadow_masks",
]

MAX_TRIANGLES = 2**24 - 1
"""The ID buffer holds 24 bits per pixel (RGB, 8 bits each); id 0 is the background."""

MAX_BUFFER_SIDE = 16384
"""Largest ID-buffer side in pixels (OpenGL renderbuffers are commonly limited to this)."""


def _unit(v, name):
    v = np.asarray(v, dtype=np.float64)
    norm = np.linalg.norm(v)
    if v.shape != (3,) or not np.isfinite(norm) or norm == 0:
        raise ValueError(f"{name} must be a non-zero finite 3-vector, got {v!r}")
    return v / norm


def _normalize(v):
    norm = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(norm > 0, norm, 1.0)


def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


# --------------------------------------------------------------------------------------------
# Views: one projection, used both for VTK and for the float64 rays
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _View:
    """A pinhole (perspective) or orthographic view on a width x height pixel grid.

    Image coordinates (x, y) are in pixels, x from the left edge and y from the top edge; pixel
    (row, col) covers [col, col + 1) x [row, row + 1), its centre at (col + 1/2, row + 1/2).
    ``half`` is tan(vertical half angle) for perspective views and the half height in world
    units for orthographic ones (VTK's view angle and parallel scale).
    """

    eye: np.ndarray
    right: np.ndarray
    up: np.ndarray
    forward: np.ndarray
    width: int
    height: int
    perspective: bool
    half: float

    @classmethod
    def look(cls, eye, forward, up, width, height, perspective, half):
        f = _unit(forward, "view direction")
        r = np.cross(f, _unit(up, "view up"))
        if np.linalg.norm(r) < 1e-12:
            raise ValueError("view up must not be parallel to the view direction")
        r /= np.linalg.norm(r)
        u = np.cross(r, f)  # as VTK orthogonalises the view up
        return cls(np.asarray(eye, np.float64), r, u, f, int(width), int(height),
                   bool(perspective), float(half))

    def ndc(self, x, y):
        return 2.0 * x / self.width - 1.0, 1.0 - 2.0 * y / self.height

    def rays(self, x, y):
        """Ray origins and unit directions through image points, components first.

        Returns origins of shape (3, 1) (perspective: the eye) or (3, N) (orthographic) and
        directions of shape (3, N).
        """
        sx, sy = self.ndc(np.asarray(x, np.float64), np.asarray(y, np.float64))
        a = sx * (self.half * self.width / self.height)
        b = sy * self.half
        offset = self.right[:, None] * a + self.up[:, None] * b
        if self.perspective:
            d = self.forward[:, None] + offset
            return self.eye[:, None], d / np.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2)
        return self.eye[:, None] + offset, np.repeat(self.forward[:, None], len(a), axis=1)

    def project(self, points):
        """Image coordinates (x, y) and depth along the view of points given as (3, ...).

        Points behind a perspective eye have no image: their x, y are NaN.
        """
        q = [np.asarray(points[k], np.float64) - self.eye[k] for k in range(3)]
        along = lambda e: q[0] * e[0] + q[1] * e[1] + q[2] * e[2]  # noqa: E731
        depth = along(self.forward)
        scale = self.half * np.where(depth > 0, depth, np.nan) if self.perspective else self.half
        sx = along(self.right) / (scale * (self.width / self.height))
        sy = along(self.up) / scale
        return (sx + 1.0) * 0.5 * self.width, (1.0 - sy) * 0.5 * self.height, depth

    def clipping_range(self, points):
        """Tight (near, far) for VTK's depth buffer, from the depths of the scene's points."""
        depth = (np.asarray(points, np.float64) - self.eye) @ self.forward
        far = float(depth.max())
        if far <= 0:
            far = 1.0
        span = max(far - float(depth.min()), 1e-12 * far)
        if self.perspective:
            ahead = depth[depth > 0]
            near = max(float(ahead.min()) - 1e-3 * span if len(ahead) else 0.0, 1e-4 * far)
        else:
            near = float(depth.min()) - 1e-3 * span
        return near, far + 1e-3 * span

    def to_vtk(self, camera, clipping_range):
        camera.SetPosition(*self.eye)
        camera.SetFocalPoint(*(self.eye + self.forward))
        camera.SetViewUp(*self.up)
        camera.SetWindowCenter(0.0, 0.0)
        camera.SetUseHorizontalViewAngle(False)
        if self.perspective:
            camera.SetParallelProjection(False)
            camera.SetViewAngle(float(np.degrees(2.0 * np.arctan(self.half))))
        else:
            camera.SetParallelProjection(True)
            camera.SetParallelScale(self.half)
        camera.SetClippingRange(*clipping_range)


@dataclass(frozen=True)
class Camera:
    """Perspective camera matching VTK's: position, focal point, view up, vertical view angle.

    The image has ``height`` rows and ``width`` columns; each pixel holds ``supersample`` x
    ``supersample`` samples at the centres of a regular grid of sub-pixels (stratified,
    deterministic). Samples are ordered row-major on the fine grid of shape :attr:`shape`.

    Parameters
    ----------
    position, look_at, up : array_like, shape (3,)
    fov_deg : float
        Vertical field of view in degrees (VTK's ``view_angle``), in (0, 180).
    width, height : int
    supersample : int, optional
    """

    position: tuple
    look_at: tuple
    up: tuple
    fov_deg: float
    width: int
    height: int
    supersample: int = 1

    def __post_init__(self):
        for name in ("position", "look_at", "up"):
            v = np.asarray(getattr(self, name), dtype=np.float64)
            if v.shape != (3,) or not np.all(np.isfinite(v)):
                raise ValueError(f"camera {name} must be 3 finite numbers, "
                                 f"got {getattr(self, name)!r}")
            object.__setattr__(self, name, tuple(float(x) for x in v))
        if not (0.0 < float(self.fov_deg) < 180.0):
            raise ValueError(f"camera fov_deg must be in (0, 180), got {self.fov_deg!r}")
        for name in ("width", "height", "supersample"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
                raise ValueError(f"camera {name} must be an integer >= 1, got {value!r}")
            object.__setattr__(self, name, int(value))
        object.__setattr__(self, "fov_deg", float(self.fov_deg))
        if np.allclose(self.position, self.look_at, rtol=0, atol=0):
            raise ValueError("camera position and look_at must differ")
        self.view()  # validates up against the view direction

    @property
    def shape(self):
        """(rows, cols) of the sample grid: (height * supersample, width * supersample)."""
        return self.height * self.supersample, self.width * self.supersample

    def view(self):
        """The view on the fine (supersampled) grid."""
        rows, cols = self.shape
        forward = np.subtract(self.look_at, self.position)
        return _View.look(self.position, forward, self.up, cols, rows, True,
                          np.tan(np.radians(self.fov_deg) / 2.0))

    def sample_coordinates(self):
        """Image coordinates (x, y) of every sample, in pixels of the final image.

        Pixel (row, col) covers [col, col + 1) x [row, row + 1); its samples sit at
        (col + (j + 1/2) / n, row + (i + 1/2) / n) for i, j in 0 .. n - 1, n = supersample.
        """
        rows, cols = self.shape
        n = self.supersample
        y, x = np.meshgrid((np.arange(rows) + 0.5) / n, (np.arange(cols) + 0.5) / n,
                           indexing="ij")
        return x.ravel(), y.ravel()

    def rays(self):
        """Camera position (3,) and unit ray directions (N, 3), float64, one per sample."""
        x, y = self.sample_coordinates()
        eye, d = self.view().rays(x * self.supersample, y * self.supersample)
        return eye[:, 0].copy(), np.ascontiguousarray(d.T)

    def project(self, points):
        """Image coordinates (x, y) in final-image pixels and depth of world points (..., 3).

        Points behind the camera have no image: their x, y are NaN.
        """
        x, y, depth = self.view().project(np.moveaxis(np.asarray(points, np.float64), -1, 0))
        return x / self.supersample, y / self.supersample, depth


# --------------------------------------------------------------------------------------------
# Lights (geometry only: where the light comes from)
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class DirectionalLight:
    """A light at infinity; ``direction`` points from the scene toward the light."""

    direction: tuple

    def __post_init__(self):
        object.__setattr__(self, "direction",
                           tuple(float(x) for x in _unit(self.direction, "light direction")))


@dataclass(frozen=True)
class PointLight:
    """A point light at ``position``."""

    position: tuple

    def __post_init__(self):
        p = np.asarray(self.position, np.float64)
        if p.shape != (3,) or not np.all(np.isfinite(p)):
            raise ValueError(f"light position must be 3 finite numbers, got {self.position!r}")
        object.__setattr__(self, "position", tuple(float(x) for x in p))


LIGHT_TYPES = {"directional": (DirectionalLight, "direction"), "point": (PointLight, "position")}
"""Light types of a light mapping ``{type: ..., <key>: [x, y, z]}`` and their vector key."""


def as_light(light):
    """A :class:`DirectionalLight` or :class:`PointLight` from itself or a mapping.

    Examples
    --------
    >>> as_light({"type": "directional", "direction": [0, 0, 2]})
    DirectionalLight(direction=(0.0, 0.0, 1.0))
    """
    if isinstance(light, (DirectionalLight, PointLight)):
        return light
    if not hasattr(light, "get"):
        raise ValueError(f"a light must be a light object or a mapping, got {light!r}")
    kind = light.get("type")
    if kind not in LIGHT_TYPES:
        raise ValueError(f"unknown light type {kind!r}; known: {sorted(LIGHT_TYPES)}")
    cls, key = LIGHT_TYPES[kind]
    if key not in light:
        raise ValueError(f"a {kind} light needs the key {key!r}")
    return cls(light[key])


def light_vectors(light, positions):
    """Unit vectors L from each position toward the light and the distance to it.

    Parameters
    ----------
    light : DirectionalLight, PointLight or mapping
    positions : array_like, shape (..., 3)

    Returns
    -------
    L : ndarray, shape (..., 3)
    distance : ndarray, shape (...)
        ``inf`` for a directional light.
    """
    light = as_light(light)
    positions = np.asarray(positions, np.float64)
    if isinstance(light, DirectionalLight):
        L = np.broadcast_to(np.asarray(light.direction), positions.shape).copy()
        return L, np.full(positions.shape[:-1], np.inf)
    d = np.asarray(light.position) - positions
    distance = np.linalg.norm(d, axis=-1)
    return _normalize(d), distance


# --------------------------------------------------------------------------------------------
# Exact ray tests (kernels on component-first arrays: x[0], x[1], x[2] are contiguous)
# --------------------------------------------------------------------------------------------

def _moller_trumbore(o, d, a, e1, e2, t_min, t_max, tolerance):
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


def _sphere(o, d, c, r, t_min, t_max):
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


def _components(*arrays):
    """Broadcast (..., 3) arrays and return each as (3, ...) views."""
    arrays = np.broadcast_arrays(*(np.asarray(x, np.float64) for x in arrays))
    if arrays[0].shape[-1:] != (3,):
        raise ValueError("points and directions must have 3 components on the last axis")
    return [np.moveaxis(x, -1, 0) for x in arrays]


def ray_triangle_MollerTrumbore1997(origins, directions, v0, v1, v2, t_min=0.0, t_max=np.inf,
                                    tolerance=0.0):
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
    o, d, a, b, c = _components(origins, directions, v0, v1, v2)
    t, b1, b2, hit = _moller_trumbore(o, d, a, b - a, c - a, t_min, t_max, tolerance)
    return np.where(hit, t, np.inf), np.where(hit, b1, 0.0), np.where(hit, b2, 0.0), hit


def ray_sphere(origins, directions, centers, radii, t_min=0.0, t_max=np.inf):
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
    o, d, c = _components(origins, directions, centers)
    return _sphere(o, d, c, np.asarray(radii, np.float64), t_min, t_max)


# --------------------------------------------------------------------------------------------
# The scene as flat float64 arrays
# --------------------------------------------------------------------------------------------

class _Scene:
    """Flat arrays of a composed scene; a triangle's *key* names what to intersect exactly.

    key = triangle index for mesh triangles, n_triangles + sphere index for sphere proxies (all
    proxy triangles of one sphere share one exact test). Vertex data are kept components
    first, (3, n_points), so that gathers give contiguous component rows.
    """

    def __init__(self, meshes):
        if isinstance(meshes, pv.PolyData) and "object_id" in meshes.cell_data:
            mesh = meshes
        elif isinstance(meshes, pv.DataSet):
            mesh = compose([(meshes, 0)])
        else:
            mesh = compose(meshes)
        self.mesh = mesh
        self._source = (meshes, meshes.GetMTime()) if isinstance(meshes, pv.DataSet) else None
        self.points = np.asarray(mesh.points, np.float64)
        self.P = np.ascontiguousarray(self.points.T)
        self.N = np.ascontiguousarray(np.asarray(mesh.point_data["Normals"], np.float64).T)
        self.UV = np.ascontiguousarray(np.asarray(mesh.point_data["uv"], np.float64).T)
        self.tris = np.asarray(mesh.faces, np.int64).reshape(-1, 4)[:, 1:]
        self.T = np.ascontiguousarray(self.tris.T)
        P0, P1, P2 = (self.points[self.tris[:, j]] for j in range(3))
        # (9, n): first corner and the two edges from it, gathered with one np.take per test
        self.table = np.ascontiguousarray(np.concatenate([P0, P1 - P0, P2 - P0], axis=1).T)
        self.n = len(self.tris)
        if self.n == 0:
            raise ValueError("the scene has no triangles")
        if self.n > MAX_TRIANGLES:
            raise ValueError(f"the scene has {self.n} triangles; the 24-bit ID buffer holds at "
                             f"most {MAX_TRIANGLES}")
        self.object_id = np.asarray(mesh.cell_data["object_id"], np.int64)
        sphere_index = np.asarray(mesh.cell_data["sphere_index"], np.int64)
        centers, self.radii = analytic_spheres(mesh)
        self.C = np.ascontiguousarray(centers.T)
        # int32 (n <= 2**24 - 1): halves the memory traffic of the key images
        self.key = np.where(sphere_index >= 0, self.n + sphere_index,
                            np.arange(self.n)).astype(np.int32)
        order = np.argsort(self.key, kind="stable")
        self.first_triangle = order[np.searchsorted(self.key[order],
                                                    self.n + np.arange(len(self.radii)))]
        self.face_normal = _normalize(np.cross(P1 - P0, P2 - P0))
        lo, hi = self.points.min(axis=0), self.points.max(axis=0)
        self.center = 0.5 * (lo + hi)
        self.radius = max(float(np.linalg.norm(self.points - self.center, axis=1).max()),
                          1e-300)

    @property
    def neighbours(self):
        """(n, 3) triangle across the edge opposite each corner (-1: none), on welded vertices.

        Coincident vertices (seams, joints between parts) are welded at 1e-9 of the scene size.
        """
        if getattr(self, "_neighbours", None) is None:
            grid = np.round((self.points - self.center) / (1e-9 * self.radius)).astype(np.int64)
            order = np.lexsort(grid.T)
            new = np.ones(len(grid), bool)
            new[1:] = np.any(grid[order[1:]] != grid[order[:-1]], axis=1)
            weld = np.empty(len(grid), np.int64)
            weld[order] = np.cumsum(new) - 1
            w = weld[self.tris]
            a, b = w[:, [1, 2, 0]], w[:, [2, 0, 1]]
            code = (np.minimum(a, b) * (int(weld.max()) + 1) + np.maximum(a, b)).ravel()
            order = np.argsort(code, kind="stable")
            pair = np.nonzero(code[order][1:] == code[order][:-1])[0]
            across = np.full(3 * self.n, -1, np.int64)
            across[order[pair]] = order[pair + 1] // 3
            across[order[pair + 1]] = order[pair] // 3
            self._neighbours = across.reshape(self.n, 3)
        return self._neighbours

    def made_from(self, meshes):
        """Whether ``meshes`` is the very mesh this scene was built from, unmodified since."""
        return (self._source is not None and meshes is self._source[0]
                and meshes.GetMTime() == self._source[1])

    def intersect(self, o, d, keys, t_min, t_max, tolerance=1e-10):
        """Exact test of rays (components first) against primitives ``keys``: t, b1, b2, hit.

        ``o`` and ``d`` are (3, 1) when shared by all rays, else (3, n); ``t_min``, ``t_max``
        scalars or (n,).
        """
        m = len(keys)
        if m and keys.max() < self.n:  # only triangles: no masking copies
            tri = np.take(self.table, keys, axis=1)
            return _moller_trumbore(o, d, tri[0:3], tri[3:6], tri[6:9], t_min, t_max,
                                    tolerance)
        t, b1, b2 = np.full(m, np.inf), np.zeros(m), np.zeros(m)
        hit = np.zeros(m, bool)
        tmin, tmax = np.broadcast_to(t_min, (m,)), np.broadcast_to(t_max, (m,))
        for is_triangle in (True, False):
            sel = np.nonzero((keys < self.n) == is_triangle)[0]
            if len(sel) == 0:
                continue
            om = o if o.shape[1] == 1 else np.take(o, sel, axis=1)
            dm = d if d.shape[1] == 1 else np.take(d, sel, axis=1)
            if is_triangle:
                tri = np.take(self.table, keys[sel], axis=1)
                t[sel], b1[sel], b2[sel], hit[sel] = _moller_trumbore(
                    om, dm, tri[0:3], tri[3:6], tri[6:9], tmin[sel], tmax[sel], tolerance)
            else:
                k = keys[sel] - self.n
                t[sel], hit[sel] = _sphere(om, dm, np.take(self.C, k, axis=1),
                                           self.radii[k], tmin[sel], tmax[sel])
        return t, b1, b2, hit

    def light_planes(self, light):
        """(4, n) planes (a, b, c, e) of the triangles, signed so that a x + b y + c z + e > 0
        on the light's side. A ray from x to the light can cross a triangle only if the value
        at x is negative; a triangle whose plane holds the light gets (0, 0, 0, 1): never."""
        offset = -np.einsum("ij,ij->i", self.face_normal, self.table[0:3].T)
        if isinstance(light, DirectionalLight):
            side = np.sign(self.face_normal @ np.asarray(light.direction))
        else:
            side = np.sign(self.face_normal @ np.asarray(light.position) + offset)
        planes = np.column_stack([self.face_normal, offset]) * side[:, None]
        planes[side == 0] = (0.0, 0.0, 0.0, 1.0)
        return np.ascontiguousarray(planes.T)


# --------------------------------------------------------------------------------------------
# The ID buffer
# --------------------------------------------------------------------------------------------

def encode_ids(ids):
    """24-bit ids (1 .. 2**24 - 1) as RGB uint8 triples, red the most significant byte."""
    ids = np.asarray(ids, np.int64)
    if np.any((ids < 0) | (ids > MAX_TRIANGLES)):
        raise ValueError(f"ids must be in 0 .. {MAX_TRIANGLES}")
    return np.stack([(ids >> 16) & 255, (ids >> 8) & 255, ids & 255], axis=-1).astype(np.uint8)


def decode_ids(rgb):
    """Inverse of :func:`encode_ids` for an (..., 3) uint8 image."""
    rgb = np.asarray(rgb)
    if rgb.dtype != np.uint8 or rgb.shape[-1] != 3:
        raise ValueError("an ID image must be uint8 with 3 channels")
    red, green, blue = (rgb[..., k].astype(np.int64) for k in range(3))
    return (red << 16) | (green << 8) | blue


class _IdRenderer:
    """One off-screen VTK window drawing the scene's triangles in their id colours."""

    def __init__(self, scene):
        # plain VTK objects rather than a pyvista Plotter: every setting that could blend
        # colours (multisampling, FXAA, smoothing, lighting, lookup tables) is set here, and a
        # window opens in ~10 ms instead of a Plotter's ~1 s
        try:  # EGL directly: no attempt (and warning) to reach an X server
            from vtkmodules.vtkRenderingOpenGL2 import vtkEGLRenderWindow
            window = vtkEGLRenderWindow()
        except ImportError:  # pragma: no cover - VTK built without EGL
            window = vtkRenderWindow()
        self.scene = scene
        poly = pv.PolyData(scene.points, faces=np.asarray(scene.mesh.faces))
        poly.cell_data["id_rgb"] = encode_ids(np.arange(1, scene.n + 1))
        poly.cell_data.active_scalars_name = "id_rgb"
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(poly)
        mapper.SetScalarModeToUseCellData()
        mapper.SetColorModeToDirectScalars()  # the uint8 colours go to the screen unmapped
        mapper.ScalarVisibilityOn()
        mapper.SetInterpolateScalarsBeforeMapping(False)
        actor = vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        prop.LightingOff()
        prop.SetInterpolationToFlat()
        prop.SetRepresentationToSurface()
        prop.BackfaceCullingOff()
        prop.FrontfaceCullingOff()
        renderer = vtkRenderer()
        renderer.SetBackground(0.0, 0.0, 0.0)
        renderer.SetUseFXAA(False)
        renderer.SetUseDepthPeeling(False)
        renderer.AutomaticLightCreationOff()
        renderer.AddActor(actor)
        window.SetOffScreenRendering(True)
        window.SetMultiSamples(0)
        window.SetPointSmoothing(False)
        window.SetLineSmoothing(False)
        window.SetPolygonSmoothing(False)
        window.AddRenderer(renderer)
        self.window, self.renderer, self._poly = window, renderer, poly

    def render(self, view):
        """(height, width) int64 array: 0 background, k the triangle k - 1."""
        if max(view.width, view.height) > MAX_BUFFER_SIDE:
            raise ValueError(f"an ID buffer of {view.width} x {view.height} pixels exceeds "
                             f"{MAX_BUFFER_SIDE} per side: lower the resolution or supersample")
        self.window.SetSize(view.width, view.height)
        view.to_vtk(self.renderer.GetActiveCamera(), view.clipping_range(self.scene.points))
        self.window.Render()
        pixels = vtkUnsignedCharArray()
        self.window.GetPixelData(0, 0, view.width - 1, view.height - 1, 0, pixels, 0)
        image = vtk_to_numpy(pixels).reshape(view.height, view.width, 3)[::-1]
        ids = decode_ids(image)
        if ids.max() > self.scene.n:
            raise RuntimeError("the ID buffer decoded to ids beyond the triangle count: colours "
                               "were blended (anti-aliasing or colour management is active)")
        return ids

    def close(self):
        self.window.Finalize()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def id_buffer(meshes, camera):
    """The ID buffer of a camera's fine grid: (rows, cols) int64, 0 background, k triangle k - 1.

    Parameters
    ----------
    meshes : pyvista.PolyData or sequence of (mesh, object_id)
        A scene from :func:`reflectance.geometry.compose`, or the pairs to compose.
    camera : Camera

    Returns
    -------
    ndarray
    """
    with _IdRenderer(_Scene(meshes)) as renderer:
        return renderer.render(camera.view())


# --------------------------------------------------------------------------------------------
# Visibility
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class SurfaceSamples:
    """What each camera sample sees; arrays have one row per sample (N = rows * cols).

    Samples are ordered row-major on the fine grid ``shape`` (rows, cols); use :meth:`image` and
    :meth:`to_pixels` to get back to images. Background samples have ``hit`` False,
    ``object_id`` and ``triangle`` -1, zeros in the geometric arrays and ``depth`` inf; ``view``
    is defined everywhere.

    Attributes
    ----------
    shape : (int, int)
    supersample : int
    hit : (N,) bool
    object_id, triangle : (N,) int64
        Object id of :func:`reflectance.geometry.compose`; triangle index in the composed mesh
        (for a sphere, the first triangle of its proxy).
    barycentric : (N, 2)
        Weights (b1, b2) of the triangle's 2nd and 3rd vertices (0 for spheres).
    position : (N, 3)
    normal : (N, 3)
        Unit shading normal: interpolated vertex normals, or the exact sphere normal.
    geometric_normal : (N, 3)
        Unit facet normal (the exact normal for spheres).
    flipped : (N,) bool
        The surface was seen from its back and both normals were turned toward the camera.
    uv : (N, 2)
    view : (N, 3)
        Unit vector V from the surface toward the camera (minus the ray direction).
    depth : (N,)
        Distance from the camera along the ray.
    pixel : (N,) int64
        Index of the final-image pixel (row * width + col) the sample belongs to.
    stats : dict
        Fractions of all samples: ``raster_miss`` (ID buffer named a triangle its exact ray
        misses), ``recovered`` (such samples, or background ones beside a surface, hit by a
        neighbour's triangle), ``dropped`` (ID buffer named a triangle, no candidate hit: now
        background).
    """

    shape: tuple
    supersample: int
    hit: np.ndarray
    object_id: np.ndarray
    triangle: np.ndarray
    barycentric: np.ndarray
    position: np.ndarray
    normal: np.ndarray
    geometric_normal: np.ndarray
    flipped: np.ndarray
    uv: np.ndarray
    view: np.ndarray
    depth: np.ndarray
    pixel: np.ndarray
    stats: dict = field(default_factory=dict)
    scene: object = field(default=None, repr=False, compare=False)  # the flat scene, reused

    def image(self, values):
        """Reshape per-sample values (N, ...) to the fine grid (rows, cols, ...)."""
        values = np.asarray(values)
        return values.reshape(tuple(self.shape) + values.shape[1:])

    def to_pixels(self, values):
        """Average per-sample values over each pixel's samples (box filter): (H, W, ...)."""
        values = self.image(values)
        n = self.supersample
        rows, cols = self.shape
        return values.reshape((rows // n, n, cols // n, n) + values.shape[2:]).mean(axis=(1, 3))


def _key_image(scene, ids):
    """Primitive keys of an ID image (-1 for the background)."""
    return np.where(ids > 0, np.take(scene.key, np.maximum(ids - 1, 0)), np.int32(-1))


def _dilate(mask):
    """3 x 3 binary dilation of a 2-D mask."""
    out = mask.copy()
    out[1:] |= mask[:-1]
    out[:-1] |= mask[1:]
    rows = out.copy()
    out[:, 1:] |= rows[:, :-1]
    out[:, :-1] |= rows[:, 1:]
    return out


def _neighbours(image, rows, cols):
    """(n, 9) values of ``image`` at the 3 x 3 pixels around (rows, cols); -1 off the image."""
    width = image.shape[1] + 2
    padded = np.pad(image, 1, constant_values=-1).ravel()
    offsets = (np.arange(-1, 2)[:, None] * width + np.arange(-1, 2)[None, :]).ravel()
    return np.take(padded, ((rows + 1) * width + cols + 1)[:, None] + offsets)


def _distinct(keys, exclude):
    """Rows of candidate keys with repeats and the row's ``exclude`` key set to -1."""
    keys = np.where(keys == exclude[:, None], np.int32(-1), keys)
    keys.sort(axis=1)
    keys[:, 1:][keys[:, 1:] == keys[:, :-1]] = -1
    return keys


def visibility(meshes, camera):
    """Which surface each camera sample sees, with exact float64 position, normal and (u, v).

    Parameters
    ----------
    meshes : pyvista.PolyData or sequence of (mesh, object_id)
        A scene from :func:`reflectance.geometry.compose`, or the pairs to compose.
    camera : Camera

    Returns
    -------
    SurfaceSamples

    Examples
    --------
    >>> from reflectance.geometry import sphere
    >>> cam = Camera((0, 0, 5), (0, 0, 0), (0, 1, 0), 30.0, 8, 8)
    >>> s = visibility([(sphere((0, 0, 0), 1.0, 32, 16), 1)], cam)
    >>> bool(s.hit[s.pixel == 3 * 8 + 4][0]), bool(s.hit[0])
    (True, False)
    """
    if not isinstance(camera, Camera):
        raise ValueError(f"camera must be a Camera, got {type(camera).__name__}")
    scene = _Scene(meshes)
    view = camera.view()
    with _IdRenderer(scene) as renderer:
        keys = _key_image(scene, renderer.render(view))
    rows, cols = camera.shape
    N = rows * cols
    eye, d = view.rays(np.tile(np.arange(cols) + 0.5, rows),
                       np.repeat(np.arange(rows) + 0.5, cols))
    raster = keys.ravel()
    best_t, best_key = np.full(N, np.inf), np.full(N, -1, np.int32)
    best_b1, best_b2 = np.zeros(N), np.zeros(N)

    def offer(sel, k):  # each sample at most once per call
        t, b1, b2, hit = scene.intersect(eye, np.take(d, sel, axis=1), k, 0.0, np.inf)
        better = hit & (t < best_t[sel])
        s = sel[better]
        best_t[s], best_key[s], best_b1[s], best_b2[s] = (t[better], k[better], b1[better],
                                                          b2[better])

    surface = np.nonzero(raster >= 0)[0]
    offer(surface, raster[surface])
    missed = surface[best_key[surface] < 0]
    # where raster and exact rays disagree: retry with the neighbouring pixels' primitives
    near = np.nonzero((raster < 0) & _dilate(keys >= 0).ravel())[0]
    retry = np.concatenate([missed, near])
    candidates = _distinct(_neighbours(keys, retry // cols, retry % cols), raster[retry])
    for j in range(candidates.shape[1]):
        m = candidates[:, j] >= 0
        if m.any():
            offer(retry[m], candidates[m, j])
    # Last resort, still exact: a sample the raster covers whose ray meets none of the nearby
    # primitives (its true triangle is smaller than a pixel and never reached the ID buffer) is
    # tested against every primitive whose projected bounding box contains it.
    lost = missed[best_key[missed] < 0]
    if len(lost):
        _search_projected_boxes(scene, view, eye, d, lost, cols, best_t, best_key, best_b1,
                                best_b2)
    hit = best_key >= 0
    stats = {
        "raster_miss": len(missed) / N,
        "recovered": float(np.count_nonzero(hit[retry])) / N,
        "searched": len(lost) / N,
        "dropped": float(np.count_nonzero(~hit[missed])) / N,
    }
    return _samples(scene, camera, eye, d, hit, best_t, best_key, best_b1, best_b2, stats)


def _search_projected_boxes(scene, view, eye, d, samples, cols, best_t, best_key, best_b1,
                            best_b2):
    """Exact nearest hit of each sample's ray among the primitives whose screen-space bounding
    box holds the sample (updates the ``best_*`` arrays in place)."""
    x, y, _ = view.project(scene.P)
    tx, ty = x[scene.T], y[scene.T]  # (3, n) corners of every triangle on the fine grid
    x0, x1, y0, y1 = tx.min(axis=0), tx.max(axis=0), ty.min(axis=0), ty.max(axis=0)
    for s in samples:
        px, py = s % cols + 0.5, s // cols + 0.5
        near = np.nonzero((x0 <= px) & (px <= x1) & (y0 <= py) & (py <= y1))[0]
        keys = np.unique(scene.key[near])
        if not len(keys):
            continue
        t, b1, b2, h = scene.intersect(eye, np.repeat(d[:, s:s + 1], len(keys), axis=1), keys,
                                       0.0, np.inf)
        if h.any():
            j = int(np.argmin(np.where(h, t, np.inf)))
            best_t[s], best_key[s], best_b1[s], best_b2[s] = t[j], keys[j], b1[j], b2[j]


def _samples(scene, camera, eye, d, hit, t, key, b1, b2, stats):
    N = len(hit)
    position, normal, geometric = np.zeros((N, 3)), np.zeros((N, 3)), np.zeros((N, 3))
    uv = np.zeros((N, 2))
    triangle = np.full(N, -1, np.int64)

    m = np.nonzero(hit & (key < scene.n))[0]  # mesh triangles: barycentric interpolation
    if len(m):
        tri = key[m]
        triangle[m] = tri
        corner = np.take(scene.T, tri, axis=1)
        w = (1.0 - b1[m] - b2[m], b1[m], b2[m])

        def blend(A):  # barycentric interpolation of a vertex attribute, components first
            return sum(w[j] * np.take(A, corner[j], axis=1) for j in range(3))

        for k, value in enumerate(blend(scene.P)):
            position[m, k] = value
        for k, value in enumerate(blend(scene.UV)):
            uv[m, k] = value
        n = blend(scene.N)
        length = np.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        good = length > 1e-6
        inv = 1.0 / np.where(good, length, 1.0)
        g = scene.face_normal[tri]
        geometric[m] = g
        for k in range(3):
            normal[m, k] = np.where(good, n[k] * inv, g[:, k])

    s = np.nonzero(hit & (key >= scene.n))[0]  # analytic spheres: exact
    if len(s):
        sphere = key[s] - scene.n
        triangle[s] = scene.first_triangle[sphere]
        p = eye + t[s] * d[:, s]
        position[s] = p.T
        n = _normalize((p - scene.C[:, sphere]).T)
        normal[s] = geometric[s] = n
        uv[s, 0] = np.mod(np.arctan2(n[:, 1], n[:, 0]) / (2.0 * np.pi), 1.0)
        uv[s, 1] = np.arccos(np.clip(-n[:, 2], -1.0, 1.0)) / np.pi

    view = np.ascontiguousarray(-d.T)
    flipped = hit & (_dot(geometric, view) < 0)  # seen from the back: two-sided surface
    normal[flipped] *= -1.0
    geometric[flipped] *= -1.0
    rows, cols = camera.shape
    n_ss = camera.supersample
    r_idx, c_idx = np.divmod(np.arange(N), cols)
    return SurfaceSamples(
        shape=(rows, cols), supersample=n_ss, hit=hit,
        object_id=np.where(hit, scene.object_id[np.maximum(triangle, 0)], -1),
        triangle=triangle, barycentric=np.column_stack([b1, b2]) * hit[:, None],
        position=position, normal=normal, geometric_normal=geometric, flipped=flipped, uv=uv,
        view=view, depth=np.where(hit, t, np.inf),
        pixel=(r_idx // n_ss) * camera.width + c_idx // n_ss, stats=stats, scene=scene,
    )


# --------------------------------------------------------------------------------------------
# Shadows
# --------------------------------------------------------------------------------------------

def _any_up(forward):
    """A view-up not parallel to ``forward``: the world axis least aligned with it."""
    return np.eye(3)[int(np.argmin(np.abs(forward)))]


def _light_views(light, points, scene, size):
    """[(view, member indices)] of light views covering the light's rays to ``points`` (n, 3)."""
    margin = 4.0 / size  # keeps every 3 x 3 neighbourhood inside the map
    if isinstance(light, DirectionalLight):
        forward = -np.asarray(light.direction)
        probe = _View.look(np.zeros(3), forward, _any_up(forward), size, size, False, 1.0)
        a, b = points @ probe.right, points @ probe.up
        ca, cb = 0.5 * (a.min() + a.max()), 0.5 * (b.min() + b.max())
        half = 0.5 * max(np.ptp(a), np.ptp(b), 1e-9 * scene.radius) * (1.0 + 2 * margin)
        centre = (scene.center + (ca - scene.center @ probe.right) * probe.right
                  + (cb - scene.center @ probe.up) * probe.up)
        eye = centre - 2.0 * scene.radius * forward
        return [(_View.look(eye, forward, probe.up, size, size, False, half),
                 np.arange(len(points)))]
    origin = np.asarray(light.position)
    d = _normalize(points - origin)
    axis = d.mean(axis=0)
    if np.linalg.norm(axis) > 1e-6:
        axis = axis / np.linalg.norm(axis)
        if (d @ axis).min() > np.cos(np.radians(60.0)):  # one perspective map suffices
            probe = _View.look(origin, axis, _any_up(axis), size, size, True, 1.0)
            spread = np.maximum(np.abs(d @ probe.right), np.abs(d @ probe.up)) / (d @ axis)
            half = float(spread.max()) * (1.0 + 2 * margin) + 1e-12
            return [(_View.look(origin, axis, probe.up, size, size, True, half),
                     np.arange(len(points)))]
    views = []  # a cube map: each sample on the face of its dominant axis
    dominant = np.argmax(np.abs(d), axis=1)
    for k in range(3):
        for sign in (1.0, -1.0):
            members = np.nonzero((dominant == k) & (np.sign(d[np.arange(len(d)), k]) == sign))[0]
            if len(members):
                views.append((_View.look(origin, sign * np.eye(3)[k], np.eye(3)[(k + 1) % 3],
                                         size, size, True, 1.0 + 2 * margin), members))
    return views


def _terminator_offset(scene, samples, idx, P):
    """Lift shadow-ray origins P (3, n) of smooth-shaded triangles off the facets.

    Hanika 2021: a point below the tangent plane of a vertex (plane through the vertex, normal
    its shading normal) is moved up to it, weighted by the barycentric weight of that vertex, so
    the facets around a point do not shadow what the smooth surface would have lit. Sphere
    samples already lie on the exact surface.
    """
    tri = samples.triangle[idx]
    sub = np.nonzero(scene.key[tri] < scene.n)[0]
    if len(sub) == 0:
        return P
    corner = np.take(scene.T, tri[sub], axis=1)
    b = samples.barycentric[idx[sub]]
    w = (1.0 - b[:, 0] - b[:, 1], b[:, 0], b[:, 1])
    sign = np.where(samples.flipped[idx[sub]], -1.0, 1.0)
    Q = P[:, sub]
    lift = np.zeros_like(Q)
    for j in range(3):
        V, Nv = np.take(scene.P, corner[j], axis=1), np.take(scene.N, corner[j], axis=1) * sign
        below = np.minimum(((Q - V) * Nv).sum(axis=0), 0.0)  # Hanika 2021, Listing 1
        lift -= w[j] * below * Nv
    P = P.copy()
    P[:, sub] += lift
    return P


_CHUNK = 1 << 19  # ray-primitive pairs tested at once (bounds the memory of the temporaries)
_WALK_STEPS = 8  # edges crossed from a missed candidate toward the shadow ray's crossing


def _block(scene, r, k, lifted, L, t_max, eps, planes, own, blocked):
    """Set ``blocked[r]`` where the shadow ray of sample r meets primitive k (or a triangle
    reached from k by walking); L is (3, 1) for a directional light, else one per sample."""
    o = np.take(lifted, r, axis=1)
    # cheap necessary condition first: origin and light on opposite sides of the triangle's
    # plane (spheres always go on to the exact test)
    pl = np.take(planes, np.minimum(k, scene.n - 1), axis=1)
    sel = np.nonzero((pl[0] * o[0] + pl[1] * o[1] + pl[2] * o[2] + pl[3] < 0)
                     | (k >= scene.n))[0]
    r, k, o = r[sel], k[sel], np.take(o, sel, axis=1)
    d = L if L.shape[1] == 1 else np.take(L, r, axis=1)
    tm = t_max if np.ndim(t_max) == 0 else np.take(t_max, r)
    t, b1, b2, hit = scene.intersect(o, d, k, eps, tm)
    blocked[r[hit]] = True
    # a missed triangle whose plane the ray crosses within reach: walk across the edge beyond
    # which the crossing lies (point location on the occluder); this finds the triangles hidden
    # in a vertex's fan or thinner than a map pixel
    for _ in range(_WALK_STEPS):
        go = np.nonzero(~hit & ~blocked[r] & (k < scene.n) & (t > eps) & (t < tm))[0]
        if len(go) == 0:
            break
        edge = np.argmin(np.stack([1.0 - b1[go] - b2[go], b1[go], b2[go]]), axis=0)
        nk = scene.neighbours[k[go], edge]
        ok = nk >= 0
        ok[ok] = (np.take(scene.key, nk[ok]) == nk[ok]) & (nk[ok] != own[r[go[ok]]])
        go, k = go[ok], nk[ok].astype(np.int32)
        r, o = r[go], np.take(o, go, axis=1)
        d = d if d.shape[1] == 1 else np.take(d, go, axis=1)
        tm = tm if np.ndim(tm) == 0 else np.take(tm, go)
        t, b1, b2, hit = scene.intersect(o, d, k, eps, tm)
        blocked[r[hit]] = True


def shadow_masks(samples, meshes, lights, map_size=None):
    """True where a surface sample does not see a light (cast shadow or facing away).

    Samples whose shading normal faces away from the light (N.L <= 0) are in shadow without a
    test. For the others an exact float64 ray from the sample toward the light (lifted off the
    facets, Hanika 2021, and offset by 1e-9 of the scene size along the normal) is tested
    against every primitive the light's ID map shows in the 3 x 3 pixels around the sample's
    projection, except the sample's own triangle or sphere, which cannot occlude it; any hit
    closer than the light shadows the sample. Background samples are False. All lights share
    one scene and one VTK window.

    Parameters
    ----------
    samples : SurfaceSamples
        From :func:`visibility` on the same scene.
    meshes : pyvista.PolyData or sequence of (mesh, object_id)
    lights : sequence of DirectionalLight, PointLight or mapping
        ``{"type": "directional", "direction": [...]}`` (toward the light) or
        ``{"type": "point", "position": [...]}``.
    map_size : int, optional
        Side of each light's ID map in pixels; default the larger side of the sample grid,
        clipped to [256, 4096].

    Returns
    -------
    ndarray of bool, shape (n_lights, N)

    References
    ----------
    Hanika, J. (2021). Hacking the shadow terminator. In Ray Tracing Gems II (pp. 65-76).
    Apress.
    """
    lights = [as_light(light) for light in lights]
    if not isinstance(samples, SurfaceSamples):
        raise ValueError(f"samples must be SurfaceSamples, got {type(samples).__name__}")
    scene = samples.scene
    if scene is None or not scene.made_from(meshes):
        scene = _Scene(meshes)
    if map_size is None:
        map_size = int(np.clip(max(samples.shape), 256, 4096))
    elif isinstance(map_size, bool) or not isinstance(map_size, (int, np.integer)) \
            or map_size < 16:
        raise ValueError(f"map_size must be an integer >= 16, got {map_size!r}")
    shadow = np.zeros((len(lights), len(samples.hit)), bool)
    surface = np.nonzero(samples.hit)[0]
    if len(surface) == 0 or not lights:
        return shadow
    if samples.triangle[surface].max() >= scene.n:
        raise ValueError("samples do not belong to this scene (triangle index out of range)")
    eps = 1e-9 * scene.radius
    position = samples.position[surface]
    normal = samples.normal[surface]
    lifted = _terminator_offset(scene, samples, surface,
                                np.ascontiguousarray(position.T)) + eps * normal.T
    own = scene.key[samples.triangle[surface]]
    with _IdRenderer(scene) as renderer:
        for i, light in enumerate(lights):
            L, distance = light_vectors(light, position)
            facing = np.nonzero(_dot(normal, L) > 0)[0]
            blocked = np.ones(len(surface), bool)
            blocked[facing] = False
            if isinstance(light, DirectionalLight):
                Ld, t_max = np.asarray(light.direction)[:, None], np.inf  # one for all rays
            else:
                Ld, t_max = np.ascontiguousarray(L.T), distance * (1.0 - 1e-12) - eps
            planes = scene.light_planes(light)
            for view, members in _light_views(light, position[facing], scene, int(map_size)):
                members = facing[members]
                keys = _key_image(scene, renderer.render(view))
                x, y, _ = view.project(np.take(position, members, axis=0).T)
                col = np.clip(np.floor(x), 0, view.width - 1).astype(np.int64)
                row = np.clip(np.floor(y), 0, view.height - 1).astype(np.int64)
                candidates = _distinct(_neighbours(keys, row, col), own[members])
                local, j = np.nonzero(candidates >= 0)
                ray, prim = members[local], candidates[local, j]
                for start in range(0, len(ray), _CHUNK):
                    chunk = slice(start, start + _CHUNK)
                    _block(scene, ray[chunk], prim[chunk], lifted, Ld, t_max, eps, planes,
                           own, blocked)
            shadow[i, surface[blocked]] = True
    return shadow


def shadow_mask(samples, meshes, light, map_size=None):
    """:func:`shadow_masks` for one light: (N,) bool, True where the light is not seen."""
    return shadow_masks(samples, meshes, [light], map_size)[0]
