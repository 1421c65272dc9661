"""What one render holds while it runs: :class:`RenderSession`.

A render traces its image band by band, and, with adaptive supersampling, the refined pixels
band by band again; every one of those traces draws with the same resources. The session makes
them on the first trace that needs them (none for a trace the process keeps) and releases them
when it closes, whatever happened in between.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from typing import Any, TYPE_CHECKING

from reflectance.render.idbuffer import IdRenderer
from reflectance.render.parallel import Tasks
from reflectance.render.primitives import Primitives
from reflectance.render.tracing import trace, trace_once

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    from reflectance.render.idbuffer import IdRenderer
    from reflectance.render.samples import SurfaceSamples
    from reflectance.render.scene import Scene

__all__ = ["RenderSession"]


class RenderSession:
    """The traces of one render, their resources and their progress (a context manager).

    Parameters
    ----------
    scene : reflectance.render.scene.Scene
    threads : int
        Of the per-sample work (:mod:`reflectance.render.parallel`).
    progress : callable, optional
        Told each phase as it starts, after where it is (``"rows 0-31: visibility"``).
    keep_trace : bool
        The first pass's trace of an image of one band is looked up in, and kept in, the
        process's trace memo (:func:`reflectance.render.tracing.trace_once`).
    tally : callable, optional
        Told ``(done, total)``, the samples traced and shaded so far and the samples planned
        (:meth:`plan`, :meth:`finished`): the work a progress bar counts.

    Notes
    -----
    The resources: the scene's :class:`reflectance.render.primitives.Primitives` and one
    ID-buffer window (:class:`reflectance.render.idbuffer.IdRenderer`, the scene uploaded once)
    for the camera's and the light maps' ID buffers of every band; with several threads and cast
    shadows, the shadow walks' edge table, made on a worker while the camera's rays are traced
    and awaited (its error raised) when the session closes, after the window.
    """

    def __init__(self, scene: Scene, threads: int = 1,
                 progress: Callable[[str], None] | None = None, keep_trace: bool = False,
                 tally: Callable[[int, int], None] | None = None) -> None:
        self.scene, self.threads, self.keep_trace = scene, threads, keep_trace
        self._progress, self._tally = progress, tally
        self.done = self.total = 0  # samples traced and shaded, and planned
        self._stack = contextlib.ExitStack()
        self._tools: tuple[Any, IdRenderer] | None = None

    def __enter__(self):
        self._stack.__enter__()
        return self

    def __exit__(self, *exc):
        return self._stack.__exit__(*exc)

    def tools(self) -> tuple[Any, IdRenderer]:
        """``(primitives, renderer)`` of the scene, made on the first call."""
        if self._tools is None:
            primitives = Primitives(self.scene.mesh)
            if self.threads > 1 and self.scene.shadows and any(
                    light.shadows for light in self.scene.lights):
                edges = Tasks(self.threads)
                edges.submit(lambda: primitives.neighbours)
                self._stack.callback(edges.results)
            self._tools = primitives, self._stack.enter_context(IdRenderer(primitives))
        return self._tools

    def tell(self, phase: str) -> None:
        """Tell the progress callback, if any, that ``phase`` starts."""
        if self._progress is not None:
            self._progress(phase)

    def plan(self, samples: int) -> None:
        """``samples`` more are to be traced and shaded (the first pass's, the refinement's)."""
        self.total += int(samples)
        self._count()

    def finished(self, samples: int) -> None:
        """``samples`` of the planned ones are traced and shaded."""
        self.done += int(samples)
        self._count()

    def _count(self):
        if self._tally is not None:
            self._tally(self.done, self.total)

    def _at(self, where):
        """The progress callback of the phases of a trace at ``where`` (None without one)."""
        progress = self._progress
        return None if progress is None else (lambda phase: progress(where + phase))

    def trace(self, rows: tuple[int, int], where: str = "") -> tuple[Any, ...]:
        """``(samples, shadowed, timings)`` of the band ``rows`` of the scene's first pass
        (:func:`reflectance.render.tracing.trace_once`, kept with ``keep_trace``)."""
        return trace_once(self.scene, self.keep_trace, rows, self.tools, self._at(where),
                          self.threads)

    def trace_selected(self, scene: Scene, rows: tuple[int, int], select: Any, map_size: int | None,
                       where: str = ""
                      ) -> tuple[SurfaceSamples, npt.NDArray[np.bool_], dict[str, float]]:
        """``(samples, shadowed, timings)`` of the samples ``select`` of the band ``rows`` of
        ``scene`` (the session's scene on a finer grid: the adaptive refinement's), with the
        light maps' side ``map_size`` (:func:`reflectance.render.tracing.trace`)."""
        primitives, renderer = self.tools()
        return trace(scene, rows, primitives, self._at(where), select, map_size, renderer,
                     self.threads)
