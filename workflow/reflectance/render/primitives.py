"""A composed scene as flat float64 arrays, with exact intersection of its primitives.

Mesh triangles are tested by Moller-Trumbore; the proxy triangles of an analytic sphere
(:func:`reflectance.geometry.shapes.sphere`) share one exact sphere test. Used by the ID buffer, the
visibility and the shadows alike.
"""

from __future__ import annotations

import threading

import numpy as np
import pyvista as pv

from reflectance.geometry.shapes import analytic_spheres, compose
from reflectance.render.lights import DirectionalLight
from reflectance.geometry.vectors import normalize
from reflectance.render.rays import sphere_hits, triangle_hits

__all__ = []


class Primitives:
    """Flat arrays of a composed scene; a triangle's *key* names what to intersect exactly.

    key = triangle index for mesh triangles, n_triangles + sphere index for sphere proxies (all
    proxy triangles of one sphere share one exact test). Vertex data are kept components
    first, (3, n_points), so that gathers give contiguous component rows.
    """

    def __init__(self, meshes):
        self._neighbours_lock = threading.Lock()  # the shadow pass's threads share one table
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
        # vertex normals and (u, v) both ways: components first for the ray code, vertex rows
        # for the per-sample interpolation (:mod:`reflectance.render.visibility`)
        self.normal_rows = np.ascontiguousarray(mesh.point_data["Normals"], np.float64)
        self.uv_rows = np.ascontiguousarray(mesh.point_data["uv"], np.float64)
        self.N = np.ascontiguousarray(self.normal_rows.T)
        self.UV = np.ascontiguousarray(self.uv_rows.T)
        self.tris = np.asarray(mesh.faces, np.int64).reshape(-1, 4)[:, 1:]
        self.T = np.ascontiguousarray(self.tris.T)
        # (9, n): first corner and the two edges from it, gathered with one np.take per test;
        # built in place, components first (no transposed copy of an (n, 9) array)
        self.n = len(self.tris)
        self.table = np.empty((9, self.n))
        P0 = np.take(self.P, self.T[0], axis=1, out=self.table[0:3])
        np.subtract(np.take(self.P, self.T[1], axis=1), P0, out=self.table[3:6])
        np.subtract(np.take(self.P, self.T[2], axis=1), P0, out=self.table[6:9])
        if self.n == 0:
            raise ValueError("the scene has no triangles")
        self.object_id = np.asarray(mesh.cell_data["object_id"], np.int64)
        sphere_index = np.asarray(mesh.cell_data["sphere_index"], np.int64)
        centers, self.radii = analytic_spheres(mesh)
        self.C = np.ascontiguousarray(centers.T)
        # int32 (n <= 2**24 - 1): halves the memory traffic of the key images
        self.key = np.where(sphere_index >= 0, self.n + sphere_index,
                            np.arange(self.n)).astype(np.int32)
        # the key of each ID-buffer value: id 0 is the background (-1), id k the triangle k - 1
        self.key_of_id = np.concatenate([np.array([-1], np.int32), self.key])
        order = np.argsort(self.key, kind="stable")
        self.first_triangle = order[np.searchsorted(self.key[order],
                                                    self.n + np.arange(len(self.radii)))]
        self.face_normal = normalize(np.cross(self.table[3:6].T, self.table[6:9].T))
        lo, hi = self.points.min(axis=0), self.points.max(axis=0)
        self.center = 0.5 * (lo + hi)
        self.radius = max(float(np.linalg.norm(self.points - self.center, axis=1).max()),
                          1e-300)

    @property
    def neighbours(self):
        """(n, 3) triangle across the edge opposite each corner (-1: none), on welded vertices.

        Coincident vertices (seams, joints between parts) are welded at 1e-9 of the scene size.
        Made once, on first use (threads asking meanwhile wait for it).
        """
        with self._neighbours_lock:
            return self._find_neighbours()

    def _find_neighbours(self):
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
            return triangle_hits(o, d, tri[0:3], tri[3:6], tri[6:9], t_min, t_max,
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
                t[sel], b1[sel], b2[sel], hit[sel] = triangle_hits(
                    om, dm, tri[0:3], tri[3:6], tri[6:9], tmin[sel], tmax[sel], tolerance)
            else:
                k = keys[sel] - self.n
                t[sel], hit[sel] = sphere_hits(om, dm, np.take(self.C, k, axis=1),
                                           self.radii[k], tmin[sel], tmax[sel])
        return t, b1, b2, hit

    def light_planes(self, light):
        """(4, n) planes (a, b, c, e) of the triangles, signed so that a x + b y + c z + e > 0
        on the light's side. A ray from x to the light can cross a triangle only if the value
        at x is negative; a triangle whose plane holds the light gets (0, 0, 0, 1): never."""
        if getattr(self, "_planes", None) is None:  # (4, n) unsigned planes, made once
            offset = -np.einsum("ij,ij->i", self.face_normal, self.table[0:3].T)
            self._planes = np.ascontiguousarray(np.column_stack([self.face_normal, offset]).T)
        if isinstance(light, DirectionalLight):
            side = np.sign(self.face_normal @ np.asarray(light.direction))
        else:
            side = np.sign(self.face_normal @ np.asarray(light.position) + self._planes[3])
        planes = self._planes * side
        planes[:, side == 0] = ((0.0,), (0.0,), (0.0,), (1.0,))
        return planes
