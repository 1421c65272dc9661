"""The pinhole camera and the views (projections) shared by VTK and the float64 rays.

A :class:`View` is one projection used twice: to set VTK's camera for an ID buffer and to
generate or project the exact rays, so the raster and the rays agree to the pixel.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from reflectance.geometry.vectors import unit_vector

__all__ = ["Camera", "MAX_BUFFER_SIDE", "SINGLE_TILE_SAMPLES", "TILE_SAMPLES"]

MAX_BUFFER_SIDE = 16384
"""Largest ID-buffer side in pixels (OpenGL renderbuffers are commonly limited to this); here,
not in :mod:`reflectance.render.idbuffer`, so the config check reads it without loading VTK."""

SINGLE_TILE_SAMPLES = 1 << 21
"""Images of at most this many samples are traced in one pass (every figure of the workflow is);
:func:`reflectance.render.tracing.tiles` reads it (here, so that the config check's memory
estimate reads it without loading VTK)."""

TILE_SAMPLES = 1 << 19
"""Samples per band of a larger image (bounds the per-sample arrays of visibility, shadows and
shading to a few hundred MiB whatever the image size)."""


@dataclass(frozen=True)
class View:
    """A pinhole (perspective) or orthographic view on a width x height pixel grid.

    Image coordinates (x, y) are in pixels, x from the left edge and y from the top edge; pixel
    (row, col) covers [col, col + 1) x [row, row + 1), its centre at (col + 1/2, row + 1/2).
    ``half`` is tan(vertical half angle) for perspective views and the half height in world
    units for orthographic ones (VTK's view angle and parallel scale). ``shift`` moves the
    window vertically by that many half heights (VTK's window centre): :meth:`band` uses it to
    draw a band of rows of a larger view with the larger view's projection.
    """

    eye: np.ndarray
    right: np.ndarray
    up: np.ndarray
    forward: np.ndarray
    width: int
    height: int
    perspective: bool
    half: float
    shift: float = 0.0

    @classmethod
    def look(cls, eye, forward, up, width, height, perspective, half):
        f = unit_vector(forward, "view direction")
        r = np.cross(f, unit_vector(up, "view up"))
        if np.linalg.norm(r) < 1e-12:
            raise ValueError("view up must not be parallel to the view direction")
        r /= np.linalg.norm(r)
        u = np.cross(r, f)  # as VTK orthogonalises the view up
        return cls(np.asarray(eye, np.float64), r, u, f, int(width), int(height),
                   bool(perspective), float(half))

    def ndc(self, x, y):
        if self.shift:
            return 2.0 * x / self.width - 1.0, 1.0 - 2.0 * y / self.height + self.shift
        return 2.0 * x / self.width - 1.0, 1.0 - 2.0 * y / self.height

    def band(self, start, stop):
        """The view of rows ``start .. stop - 1`` alone: the same rays through the same pixels,
        on a (stop - start) x width grid (a tile of an ID buffer too large to draw at once)."""
        if self.shift or not 0 <= start < stop <= self.height:
            raise ValueError(f"rows {start}..{stop} are not a band of a {self.height}-row view")
        h = stop - start
        # the band's window spans rows start..stop of the full one: its half height is h / H of
        # the full one, its centre (H - 2 start - h) / h of its own half heights above the axis
        return View(self.eye, self.right, self.up, self.forward, self.width, h,
                    self.perspective, self.half * h / self.height,
                    (self.height - 2.0 * start - h) / h)

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

    def pixel_rays(self, start=0, stop=None):
        """Perspective rays through every pixel centre, row-major: eye (3, 1), unit d (3, N).

        The same numbers as :meth:`rays` at the pixel centres, built from one row and one
        column of offsets, so that no temporaries of the image's size are made besides the
        result and its norm. ``start`` and ``stop`` select a band of rows (the same numbers
        as those rows of the whole image).
        """
        if not self.perspective:
            raise ValueError("pixel_rays needs a perspective view")
        stop = self.height if stop is None else stop
        sx, _ = self.ndc(np.arange(self.width) + 0.5, 0.0)
        _, sy = self.ndc(0.0, np.arange(start, stop) + 0.5)
        a = sx * (self.half * self.width / self.height)
        b = (sy * self.half)[:, None]
        d = np.empty((3, stop - start, self.width))
        for k in range(3):
            np.add(self.right[k] * a, self.up[k] * b, out=d[k])
            d[k] += self.forward[k]
        d /= np.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2)
        return self.eye[:, None], d.reshape(3, -1)

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
        if self.shift:
            sy = sy - self.shift
        return (sx + 1.0) * 0.5 * self.width, (1.0 - sy) * 0.5 * self.height, depth

    def clipping_range(self, points, triangles=None):
        """(near, far) for VTK's depth buffer that clips nothing in view, as tight as that allows.

        Depth is linear on a triangle, so ``far`` comes from the deepest point and, for a
        triangle wholly ahead of a perspective eye, the nearest point is a vertex. A triangle
        that reaches behind the eye (a large floor under the camera) can come nearer than any
        vertex ahead; only its part inside the view matters, whose depth is at least its
        distance from the eye times the cosine of the view's corner half-angle, and that
        distance is at least the distance to the triangle's plane and to its bounding sphere.
        ``triangles`` (n, 3) vertex indices enable that bound.
        """
        points = np.asarray(points, np.float64)
        depth = (points - self.eye) @ self.forward
        far = float(depth.max())
        if far <= 0:
            far = 1.0
        span = max(far - float(depth.min()), 1e-12 * far)
        if self.perspective:
            ahead = depth[depth > 0]
            near = max(float(ahead.min()) - 1e-3 * span if len(ahead) else 0.0, 1e-4 * far)
            if triangles is not None and depth.min() <= 0:  # else no triangle reaches behind
                near = min(near, self._near_behind(points, np.asarray(triangles), depth, far))
        else:
            near = float(depth.min()) - 1e-3 * span
        return near, far + 1e-3 * span

    def _near_behind(self, points, triangles, depth, far):
        """Lower bound of the depth in view of the triangles reaching behind the eye."""
        d = depth[triangles]
        behind = triangles[(d.max(axis=1) > 0) & (d.min(axis=1) <= 0)]
        if len(behind) == 0:
            return np.inf
        P = points[behind] - self.eye  # (m, 3 corners, 3)
        normal = np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0])
        length = np.linalg.norm(normal, axis=1)
        to_plane = np.abs(np.einsum("ij,ij->i", normal, P[:, 0])) / np.where(length > 0,
                                                                              length, np.inf)
        centre = P.mean(axis=1)
        to_ball = (np.linalg.norm(centre, axis=1)
                   - np.linalg.norm(P - centre[:, None], axis=2).max(axis=1))
        distance = float(np.maximum(np.maximum(to_plane, to_ball), 0.0).min())
        aspect = self.width / self.height
        cos_corner = 1.0 / np.sqrt(1.0 + self.half**2 * ((1.0 + abs(self.shift))**2 + aspect**2)
                                   if self.shift else
                                   1.0 + self.half**2 * (1.0 + aspect**2))  # farthest corner
        near = distance * cos_corner * (1.0 - 1e-3)
        # the eye on a triangle's plane, inside its bounding sphere: that triangle is seen
        # edge-on; any near > 0 keeps the rest
        return near if near > 0 else 1e-6 * far

    def to_vtk(self, camera, clipping_range):
        camera.SetPosition(*self.eye)
        camera.SetFocalPoint(*(self.eye + self.forward))
        camera.SetViewUp(*self.up)
        camera.SetWindowCenter(0.0, self.shift)
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
    def shape(self) -> tuple[int, int]:
        """(rows, cols) of the sample grid: (height * supersample, width * supersample)."""
        return self.height * self.supersample, self.width * self.supersample

    def view(self) -> View:
        """The view on the fine (supersampled) grid."""
        rows, cols = self.shape
        forward = np.subtract(self.look_at, self.position)
        return View.look(self.position, forward, self.up, cols, rows, True,
                          np.tan(np.radians(self.fov_deg) / 2.0))

    def sample_coordinates(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Image coordinates (x, y) of every sample, in pixels of the final image.

        Pixel (row, col) covers [col, col + 1) x [row, row + 1); its samples sit at
        (col + (j + 1/2) / n, row + (i + 1/2) / n) for i, j in 0 .. n - 1, n = supersample.
        """
        rows, cols = self.shape
        n = self.supersample
        y, x = np.meshgrid((np.arange(rows) + 0.5) / n, (np.arange(cols) + 0.5) / n,
                           indexing="ij")
        return x.ravel(), y.ravel()

    def rays(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Camera position (3,) and unit ray directions (N, 3), float64, one per sample."""
        x, y = self.sample_coordinates()
        eye, d = self.view().rays(x * self.supersample, y * self.supersample)
        return eye[:, 0].copy(), np.ascontiguousarray(d.T)

    def project(self,
                points: npt.ArrayLike
               ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Image coordinates (x, y) in final-image pixels and depth of world points (..., 3).

        Points behind the camera have no image: their x, y are NaN.
        """
        x, y, depth = self.view().project(np.moveaxis(np.asarray(points, np.float64), -1, 0))
        return x / self.supersample, y / self.supersample, depth
