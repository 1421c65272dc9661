"""Threads for the renderer's per-sample work.

numpy releases the GIL inside its array loops (gathers, ufuncs, einsum, sorts) and VTK releases
it while it draws, so independent pieces of one render's per-sample work run side by side on
several cores in one process. Each piece computes its samples exactly as the one-thread path does
(the same operations on the same values, elementwise), and results are put together in a fixed
order, so an image is the same, bit for bit, at any thread count.

The thread count is :func:`render_threads`: the ``threads`` argument of
:func:`reflectance.render.pipeline.render`, else the environment variable
:data:`THREADS_VARIABLE`, else ``OMP_NUM_THREADS`` (what a job scheduler grants: Snakemake sets
it to a rule's ``threads``, 1 in this workflow), else the cores this process may run on. One
thread is the serial path (no pool at all).
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Iterable
from concurrent.futures import Future, ThreadPoolExecutor
from typing import Any, TypeVar

_Item = TypeVar("_Item")
_Result = TypeVar("_Result")

__all__ = ["THREADS_VARIABLE", "render_threads", "Tasks", "pieces"]

THREADS_VARIABLE = "REFLECTANCE_RENDER_THREADS"
"""Environment variable overriding the renderer's default thread count (a positive integer)."""

_pools: dict[int, ThreadPoolExecutor] = {}
_pools_lock = threading.Lock()


def render_threads(threads: int | None = None) -> int:
    """The thread count of a render: ``threads`` if given, else :data:`THREADS_VARIABLE`, else
    ``OMP_NUM_THREADS``, else the number of cores this process may run on
    (``os.sched_getaffinity``)."""
    where = "threads"
    if threads is None:
        threads, where = os.environ.get(THREADS_VARIABLE) or None, THREADS_VARIABLE
    if threads is None:  # OpenMP's variable may be a list per nesting level ("4,2"): its first
        # level; a value OpenMP's own syntax would not take is left to OpenMP, not refused here
        first = (os.environ.get("OMP_NUM_THREADS") or "").split(",")[0].strip()
        if first.isdigit() and int(first) >= 1:
            return int(first)
        try:
            return max(1, len(os.sched_getaffinity(0)))
        except AttributeError:  # pragma: no cover - not Linux
            return max(1, os.cpu_count() or 1)
    try:
        value = int(threads)
    except (TypeError, ValueError):
        value = 0
    if isinstance(threads, bool) or value < 1 or str(value) != str(threads).strip():
        raise ValueError(f"{where}: the renderer's thread count must be a positive integer, "
                         f"got {threads!r}")
    return value


def _forget_pools():
    """In a forked child: the parent's pools have no threads there (a task would wait forever)."""
    global _pools_lock
    _pools.clear()
    _pools_lock = threading.Lock()


os.register_at_fork(after_in_child=_forget_pools)


def _pool(threads):
    """A process-wide pool of ``threads`` workers (made once per count, kept)."""
    with _pools_lock:
        if threads not in _pools:
            _pools[threads] = ThreadPoolExecutor(threads, thread_name_prefix="reflectance-render")
        return _pools[threads]


class Tasks:
    """Calls run on ``threads`` worker threads (or, for one thread, at once in the caller).

    :meth:`submit` queues a call; :meth:`results` waits for every call queued so far and returns
    their results in the order they were queued (the first exception is raised). Only the
    thread that made the object may submit (pieces never submit pieces: no pool waits on itself).
    """

    def __init__(self, threads: int | None = 1) -> None:
        self.threads = render_threads(threads)
        self._futures: list[Future[Any]] = []  # calls of any kind: each its own result

    def submit(self, fn: Callable[..., object], *args: Any) -> None:
        if self.threads == 1:
            done: Future[object] = Future()  # the call made at once, as a finished future
            done.set_result(fn(*args))
            self._futures.append(done)
        else:
            self._futures.append(_pool(self.threads).submit(fn, *args))

    def results(self) -> list[Any]:  # what the calls queued return, each of its own type
        futures, self._futures = self._futures, []
        for future in futures:  # every piece ends (or fails) before the caller goes on
            future.exception()
        return [future.result() for future in futures]

    def map(self, fn: Callable[[_Item], _Result], items: Iterable[_Item]) -> list[_Result]:
        """``[fn(item) for item in items]``, the calls on the workers."""
        for item in items:
            self.submit(fn, item)
        return self.results()


def pieces(n: int, threads: int, most: int, least: int = 1 << 12) -> list[slice]:
    """Slices of ``range(n)`` in order: chunks of ``most`` items for one thread (the serial
    path's), else equal pieces of at most ``most``, at least two per thread (so that uneven
    pieces balance) unless that makes pieces of fewer than ``least`` items."""
    size = most
    if threads > 1 and n:
        size = -(-n // max(-(-n // most), min(2 * threads, n // least)))
    return [slice(start, min(n, start + size)) for start in range(0, n, size)]
