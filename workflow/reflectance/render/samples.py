"""What the camera samples see: the :class:`SurfaceSamples` record of :func:`visibility`."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from reflectance.render.parallel import Tasks, pieces

if TYPE_CHECKING:
    from reflectance.render.primitives import Primitives

__all__ = ["SurfaceSamples"]


@dataclass(frozen=True)
class SurfaceSamples:
    """What each camera sample sees; arrays have one row per sample (N = rows * cols).

    Samples are ordered row-major on the fine grid ``shape`` (rows, cols); use :meth:`image` and
    :meth:`to_pixels` to get back to images. A selection of a band's samples
    (:func:`reflectance.render.visibility.visibility` with ``select``, the adaptive
    refinement's) has shape (N, 1), in the selection's order; ``pixel`` says where each
    belongs. Background samples have ``hit`` False,
    ``object_id`` and ``triangle`` -1, zeros in the geometric arrays and ``depth`` inf; ``view``
    is defined everywhere.

    Attributes
    ----------
    shape : (int, int)
    supersample : int
    hit : (N,) bool
    object_id, triangle : (N,) int32
        Object id of :func:`reflectance.geometry.shapes.compose`; triangle index in the composed mesh
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
    pixel : (N,) int32
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
    # the flat scene, reused
    scene: Primitives | None = field(default=None, repr=False, compare=False)

    def image(self, values: npt.NDArray[Any]) -> npt.NDArray[Any]:
        """Reshape per-sample values (N, ...) to the fine grid (rows, cols, ...)."""
        values = np.asarray(values)
        return values.reshape(tuple(self.shape) + values.shape[1:])

    def to_pixels(self, values: npt.NDArray[Any],
                  threads: int | None = 1) -> npt.NDArray[np.float64]:
        """Average per-sample values over each pixel's samples (box filter): (H, W, ...); with
        several ``threads`` (:mod:`reflectance.render.parallel`), bands of pixel rows at once
        (each pixel's mean as in one call)."""
        values = self.image(values)
        n = self.supersample
        rows, cols = self.shape
        blocks = values.reshape((rows // n, n, cols // n, n) + values.shape[2:])
        if threads == 1:
            return blocks.mean(axis=(1, 3))
        out = np.empty((rows // n, cols // n) + values.shape[2:],  # the dtype one call gives
                       blocks[:0].mean(axis=(1, 3)).dtype)

        def band(p):
            out[p] = blocks[p].mean(axis=(1, 3))

        tasks = Tasks(threads)
        tasks.map(band, pieces(rows // n, tasks.threads, rows // n, least=1))
        return out
