"""ID buffers: VTK rasterises every triangle flat in a colour that encodes its index.

The buffer is drawn off-screen without lighting, anti-aliasing or multisampling, in 24-bit
colours (0 is the background); it only *chooses* which primitive a pixel sees. The exact
geometry then comes from float64 rays (:mod:`reflectance.render.primitives`). The helpers at the end
read primitive keys and 3 x 3 neighbourhoods out of an ID image.
"""

from __future__ import annotations

import contextlib
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
import pyvista as pv
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers VTK's OpenGL backend)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)

from reflectance.render.camera import MAX_BUFFER_SIDE
from reflectance.render.primitives import Primitives

if TYPE_CHECKING:
    import pyvista as pv

    from reflectance.render.camera import Camera

__all__ = ["MAX_TRIANGLES", "encode_ids", "decode_ids", "id_buffer",
           "renderer_for"]

MAX_TRIANGLES = 2**24 - 1
"""The ID buffer holds 24 bits per pixel (RGB, 8 bits each); id 0 is the background."""


def encode_ids(ids: npt.NDArray[np.integer]) -> npt.NDArray[np.uint8]:
    """24-bit ids (1 .. 2**24 - 1) as RGB uint8 triples, red the most significant byte."""
    ids = np.asarray(ids, np.int64)
    if np.any((ids < 0) | (ids > MAX_TRIANGLES)):
        raise ValueError(f"ids must be in 0 .. {MAX_TRIANGLES}")
    return np.stack([(ids >> 16) & 255, (ids >> 8) & 255, ids & 255], axis=-1).astype(np.uint8)


def decode_ids(rgb: npt.NDArray[np.uint8]) -> npt.NDArray[np.int32]:
    """Inverse of :func:`encode_ids` for an (..., 3) uint8 image (int32: 24 bits fit)."""
    rgb = np.asarray(rgb)
    if rgb.dtype != np.uint8 or rgb.shape[-1] != 3:
        raise ValueError("an ID image must be uint8 with 3 channels")
    ids = rgb[..., 0].astype(np.int32)  # built in place: one int32 array of the image's size
    ids <<= 8
    ids |= rgb[..., 1]
    ids <<= 8
    ids |= rgb[..., 2]
    return ids


class IdRenderer:
    """One off-screen VTK window drawing the scene's triangles in their id colours."""

    def __init__(self, scene):
        # plain VTK objects rather than a pyvista Plotter: every setting that could blend
        # colours (multisampling, FXAA, smoothing, lighting, lookup tables) is set here, and a
        # window opens in ~10 ms instead of a Plotter's ~1 s
        if scene.n > MAX_TRIANGLES:
            raise ValueError(f"the scene has {scene.n} triangles; the 24-bit ID buffer holds at "
                             f"most {MAX_TRIANGLES}")
        try:  # EGL directly: no attempt (and warning) to reach an X server
            from vtkmodules.vtkRenderingOpenGL2 import vtkEGLRenderWindow
            window = vtkEGLRenderWindow()
        except ImportError:  # pragma: no cover - VTK built without EGL
            window = vtkRenderWindow()
        self.scene = scene
        # the triangles "exploded": three vertices of their own each, carrying the triangle's
        # id colour as point scalars: the same rasterised triangles in the same order (the same
        # ID images), but VTK passes point colours through as vertex attributes, while it looks
        # cell colours up per fragment in a buffer of cell values (measured on the 221,408-
        # triangle bench vase at 512 px: 0.082 CPU s per Render() against 0.095 s)
        poly = pv.PolyData.from_regular_faces(
            scene.points[scene.tris.ravel()], np.arange(3 * scene.n).reshape(-1, 3))
        poly.point_data["id_rgb"] = np.repeat(encode_ids(np.arange(1, scene.n + 1)), 3, axis=0)
        poly.point_data.active_scalars_name = "id_rgb"
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(poly)
        mapper.SetScalarModeToUsePointData()
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
        """(height, width) int32 array: 0 background, k the triangle k - 1."""
        if max(view.width, view.height) > MAX_BUFFER_SIDE:
            raise ValueError(f"an ID buffer of {view.width} x {view.height} pixels exceeds "
                             f"{MAX_BUFFER_SIDE} per side: lower the resolution or supersample")
        self.window.SetSize(view.width, view.height)
        clipping = view.clipping_range(self.scene.points, self.scene.tris)
        view.to_vtk(self.renderer.GetActiveCamera(), clipping)
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


def renderer_for(scene: Primitives, renderer: IdRenderer | None = None
                 ) -> contextlib.AbstractContextManager[IdRenderer]:
    """A context giving an :class:`IdRenderer` of ``scene``: ``renderer`` itself (left open) if
    it draws that very scene, else a new one closed on exit. One window then serves the camera
    and every light map of a render (the scene is uploaded to it once)."""
    if renderer is not None and renderer.scene is scene:
        return contextlib.nullcontext(renderer)
    return IdRenderer(scene)


def id_buffer(meshes: pv.PolyData | Sequence[tuple[pv.PolyData, int]],
              camera: Camera) -> npt.NDArray[np.int32]:
    """The ID buffer of a camera's fine grid: (rows, cols) int32, 0 background, k triangle k - 1.

    Parameters
    ----------
    meshes : pyvista.PolyData or sequence of (mesh, object_id)
        A scene from :func:`reflectance.geometry.shapes.compose`, or the pairs to compose.
    camera : Camera

    Returns
    -------
    ndarray
    """
    with IdRenderer(Primitives(meshes)) as renderer:
        return renderer.render(camera.view())


def key_image(scene, ids):
    """Primitive keys of an ID image (-1 for the background): one gather from the keys of ids
    0 (background) .. n."""
    return np.take(scene.key_of_id, ids, out=np.empty_like(ids, np.int32))  # ids' layout


def dilate(mask):
    """3 x 3 binary dilation of a 2-D mask."""
    out = mask.copy()
    out[1:] |= mask[:-1]
    out[:-1] |= mask[1:]
    rows = out.copy()
    out[:, 1:] |= rows[:, :-1]
    out[:, :-1] |= rows[:, 1:]
    return out


def neighbour_keys(image, rows, cols, fill=-1):
    """(n, 9) values of ``image`` at the 3 x 3 pixels around (rows, cols); ``fill`` off the
    image. Stored column by column (the transpose of a contiguous (9, n) array), the layout
    :func:`distinct_keys` sorts in."""
    width = image.shape[1] + 2
    padded = np.pad(image, 1, constant_values=fill).ravel()
    offsets = (np.arange(-1, 2)[:, None] * width + np.arange(-1, 2)[None, :]).ravel()
    return np.take(padded, offsets[:, None] + ((rows + 1) * width + cols + 1)[None, :]).T


#: a sorting network of 9 inputs (25 compare-exchanges; sorts every 0-1 input, hence every input)
_SORT9 = ((0, 1), (3, 4), (6, 7), (1, 2), (4, 5), (7, 8), (0, 1), (3, 4), (6, 7), (0, 3), (3, 6),
          (0, 3), (1, 4), (4, 7), (1, 4), (2, 5), (5, 8), (2, 5), (1, 3), (5, 7), (2, 6), (4, 6),
          (2, 4), (2, 3), (5, 6))


def distinct_keys(keys, exclude):
    """Rows of candidate keys, sorted, with repeats and the row's ``exclude`` key set to -1.

    The (n, 9) rows of :func:`neighbour_keys` are sorted column-wise by a sorting network (whole
    columns at once rather than row by row); other widths by ``np.sort``."""
    keys = np.where(keys == exclude[:, None], np.int32(-1), keys)
    if keys.shape[1] != 9:
        keys.sort(axis=1)
        keys[:, 1:][keys[:, 1:] == keys[:, :-1]] = -1
        return keys
    columns = np.ascontiguousarray(keys.T)  # (9, n): contiguous columns (no copy when the
    # keys come from neighbour_keys)
    low = np.empty_like(columns[0])
    for i, j in _SORT9:
        np.minimum(columns[i], columns[j], out=low)
        np.maximum(columns[i], columns[j], out=columns[j])
        columns[i] = low
    columns[1:][columns[1:] == columns[:-1]] = -1
    return columns.T
