"""Tracing: what each camera sample sees and which lights each sample sees, band by band.

:func:`trace` runs the two exact passes on a scene, of the whole fine grid or a band of its rows
(:func:`tiles`): camera visibility (:func:`reflectance.render.visibility.visibility`, VTK ID
buffer + exact float64 hits) and each light's shadow mask
(:func:`reflectance.render.shadows.shadow_masks`, light maps of :func:`light_map_size`).
:func:`trace_key` is everything a trace depends on, and :func:`trace_once` keeps a one-band trace
under it in the process's trace memo (:data:`reflectance.io.cache.TRACES`), for scenes that
differ only in what a trace never looks at (materials, spectra, intensities, the ambient term).
"""

from __future__ import annotations

import hashlib
import time
from collections.abc import Callable
from typing import Any, TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.io.cache import TRACES
from reflectance.render.camera import SINGLE_TILE_SAMPLES, TILE_SAMPLES
from reflectance.render.shadows import shadow_masks
from reflectance.render.visibility import visibility

if TYPE_CHECKING:
    from reflectance.render.camera import Camera
    from reflectance.render.idbuffer import IdRenderer
    from reflectance.render.samples import SurfaceSamples
    from reflectance.render.scene import Scene

__all__ = ["tiles", "light_map_size", "trace", "trace_key", "trace_once"]

# SINGLE_TILE_SAMPLES and TILE_SAMPLES come from reflectance.render.camera; tiles() reads them
# as this module's names (which tests patch)


def tiles(camera: Camera, single: int | None = None,
          tile: int | None = None) -> list[tuple[int, int]]:
    """Bands ``(start, stop)`` of rows of the camera's fine grid that
    :func:`reflectance.render.pipeline.render` traces one at a time: the whole grid if it has at
    most ``single`` samples (default :data:`~reflectance.render.camera.SINGLE_TILE_SAMPLES`), else
    bands of whole pixel rows of at most ``tile`` samples (default
    :data:`~reflectance.render.camera.TILE_SAMPLES`; at least one pixel row)."""
    single = SINGLE_TILE_SAMPLES if single is None else int(single)
    tile = TILE_SAMPLES if tile is None else int(tile)
    rows, cols = camera.shape
    if rows * cols <= single:
        return [(0, rows)]
    n = camera.supersample
    step = max(n, tile // cols // n * n)
    return [(start, min(start + step, rows)) for start in range(0, rows, step)]


def light_map_size(camera: Camera, rows: tuple[int, int] | None = None) -> int:
    """Light-map side: what :func:`shadow_masks` picks for the whole grid, and for a band of
    ``rows`` that side scaled by twice the square root of the band's share of the samples (the
    band's samples cover about that share of the whole map; twice as fine again, as a margin),
    at least 256 and at most the whole grid's."""
    whole = int(np.clip(max(camera.shape), 256, 4096))
    if rows is None or (rows[0], rows[1]) == (0, camera.shape[0]):
        return whole
    share = (rows[1] - rows[0]) / camera.shape[0]
    return int(np.clip(round(2.0 * whole * np.sqrt(share)), 256, whole))


def _silent(phase):
    pass


def trace(scene: Scene, rows: tuple[int, int] | None = None, primitives: Any = None,
          progress: Callable[[str], None] | None = None, select: Any = None,
          map_size: int | None = None, renderer: IdRenderer | None = None,
          threads: int | None = 1
         ) -> tuple[SurfaceSamples, npt.NDArray[np.bool_], dict[str, float]]:
    """(samples, shadowed, timings): camera visibility and each light's shadow mask, of the
    whole image or of the band ``rows`` of the fine grid (:func:`tiles`); ``primitives``
    (:class:`reflectance.render.primitives.Primitives` of ``scene.mesh``) are reused if given.

    ``select`` traces only those samples of the band (``visibility``'s); ``map_size`` sets the
    light maps' side (default: :func:`light_map_size` of the band). ``progress``, if given, is
    called with the name of each phase as it starts. ``renderer``, an open
    :class:`reflectance.render.idbuffer.IdRenderer` of ``primitives``, draws the camera's and the
    lights' ID buffers (one window, the scene uploaded once); default one per phase.
    ``threads``: of the per-sample work (:mod:`reflectance.render.parallel`; the same result at
    any count)."""
    progress = progress or _silent
    t0 = time.perf_counter()
    progress("visibility")
    samples = visibility(scene.mesh if primitives is None else primitives, scene.camera, rows,
                         select, renderer, threads)
    t1 = time.perf_counter()
    progress("shadows")
    shadowed = np.zeros((len(scene.lights), len(samples.hit)), bool)
    casting = [i for i, light in enumerate(scene.lights) if light.shadows] if scene.shadows else []
    if casting:  # (a light with shadows: false is a fill light nothing blocks; N.L clips it)
        shadowed[casting] = shadow_masks(samples, scene.mesh,
                                         [scene.lights[i].source for i in casting],
                                         map_size or light_map_size(scene.camera, rows),
                                         renderer, threads)
    t2 = time.perf_counter()
    return samples, shadowed, {"visibility": t1 - t0, "shadows": t2 - t1}


def trace_key(scene: Scene, rows: tuple[int, int] | None = None) -> str:
    """What :func:`trace` depends on, as a SHA-256 hex digest: the composed mesh (points, faces,
    every point and cell array), the camera, the lights' directions or positions and whether
    each is shadowed, whether the scene casts shadows, and the band of rows (None: the whole
    grid, the same trace as its one band). Two scenes with the same key are traced identically
    (the trace never looks at materials, spectra, intensities or the ambient term)."""
    rows = (0, scene.camera.shape[0]) if rows is None else (int(rows[0]), int(rows[1]))
    digest = hashlib.sha256()
    mesh = scene.mesh
    arrays = [("points", mesh.points), ("faces", mesh.faces)]
    arrays += [(f"point_data.{name}", mesh.point_data[name]) for name in sorted(mesh.point_data)]
    arrays += [(f"cell_data.{name}", mesh.cell_data[name]) for name in sorted(mesh.cell_data)]
    for name, array in arrays:
        array = np.ascontiguousarray(array)
        digest.update(f"{name} {array.dtype.str} {array.shape}\n".encode())
        digest.update(array.tobytes())
    digest.update(repr((scene.camera, [(light.source, light.shadows) for light in scene.lights],
                        bool(scene.shadows), rows)).encode())
    return digest.hexdigest()


def trace_once(scene: Scene, keep: bool = True, rows: tuple[int, int] | None = None,
               tools: Callable[[], tuple[Any, IdRenderer]] | None = None,
               progress: Callable[[str], None] | None = None,
               threads: int | None = 1) -> tuple[Any, ...]:
    """:func:`trace` of ``scene`` (the band ``rows``; None: the whole grid), or, with ``keep``,
    the one the process's trace memo (:data:`reflectance.io.cache.TRACES`) keeps under its
    :func:`trace_key`, for scenes that differ only in what the trace does not look at (a new
    trace is kept there). Images of several bands (:func:`tiles`) are not kept (memory).
    ``tools``, if given, is called only when a trace is needed and returns ``(primitives,
    renderer)`` for :func:`trace`. Returns ``(samples, shadowed, timings)``, zero timings for a
    kept trace; ``threads`` as for :func:`trace`."""
    timings = {"visibility": 0.0, "shadows": 0.0}

    def traced():
        primitives, renderer = tools() if tools is not None else (None, None)
        samples, shadowed, t = trace(scene, rows, primitives, progress, renderer=renderer,
                                     threads=threads)
        timings.update(t)
        return samples, shadowed

    if keep and len(tiles(scene.camera)) == 1:
        samples, shadowed = TRACES.get(trace_key(scene, rows), traced)
    else:
        samples, shadowed = traced()
    return samples, shadowed, timings
