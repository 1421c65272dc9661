"""Independent subprocesses of one test module, run side by side (test helper).

A `snakemake -n` that fails at parse time, or a `python -X importtime` start, is one process
busy on one core for several seconds while pytest waits. When a module has several such runs
that do not depend on one another, a module-scoped fixture starts them all at once on a small
pool (one per core this process may use, at most four: each holds a few hundred MB), and each
test then takes its own run's result and makes its own assertions on it. What each test checks
is unchanged; only the waiting overlaps.

The same pool serves the session (tests/conftest.py, fixture ``early``): runs that only wait on
subprocesses (the session's build, the SLURM runs) start when the session does, in background
threads, and the tests that need them take their results when they come to them. Such runs start
their processes with ``popen`` (each in its own session), so that closing the pool early (a
failure with ``-x``, Ctrl-C) kills what is still running, children included, instead of waiting
for it; ``callback`` registers what must happen once the runs are over (stopping daemons).
"""

import os
import signal
import subprocess
import threading
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import ExitStack


def workers():
    """How many runs at once: the cores this process may use, 1 to 4."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        cores = os.cpu_count() or 1
    return max(1, min(4, cores))


class Closed(Exception):
    """A run asked for a process after the pool was closed."""


class SideBySide:
    """``start(key, function, *args)`` in a thread pool; ``result(key)`` waits for that one
    (and raises what it raised)."""

    def __init__(self, n=None):
        self._pool = ThreadPoolExecutor(n or workers())
        self._runs = {}
        self._lock = threading.Lock()
        self._processes = []
        self._cleanup = ExitStack()
        self.closing = threading.Event()
        # the environment as it is now (the session's start, for tests/conftest.py's pool): a
        # run started later must not take what a test running meanwhile has patched
        self.environ = os.environ.copy()

    def start(self, key, function, *args, **kwargs):
        assert key not in self._runs, key
        self._runs[key] = self._pool.submit(function, *args, **kwargs)

    def start_once(self, key, function, *args, **kwargs):
        """``start`` unless ``key`` was started already."""
        if key not in self._runs:
            self.start(key, function, *args, **kwargs)

    def after(self, key, then, function, *args, **kwargs):
        """Start ``then``, ``function(result of key, *args, **kwargs)``, on the pool once run
        ``key`` has ended, without holding a thread while it waits; if ``key`` raised (or the
        pool closed first), ``result(then)`` raises the same."""
        assert then not in self._runs, then
        outer = self._runs[then] = Future()

        def copy(inner):
            if inner.cancelled():
                outer.set_exception(Closed(then))
            elif inner.exception() is not None:
                outer.set_exception(inner.exception())
            else:
                outer.set_result(inner.result())

        def chain(done):
            if done.cancelled() or done.exception() is not None:
                return copy(done)
            try:
                inner = self._pool.submit(function, done.result(), *args, **kwargs)
            except RuntimeError:  # the pool is shut down: the session is ending
                return outer.set_exception(Closed(then))
            inner.add_done_callback(copy)

        self._runs[key].add_done_callback(chain)

    def started(self, key):
        return key in self._runs

    def result(self, key):
        return self._runs[key].result()

    def popen(self, *args, **kwargs):
        """``subprocess.Popen`` in a session of its own (by default in the environment the pool
        was made in), killed with its children if it is still running when the pool closes."""
        with self._lock:
            if self.closing.is_set():
                raise Closed(args)
            kwargs.setdefault("env", self.environ)
            proc = subprocess.Popen(*args, start_new_session=True, **kwargs)
            self._processes.append(proc)
        return proc

    def run(self, args, timeout=None, **kwargs):
        """``args`` run to its end as :meth:`popen` starts it, output captured as text: the
        ``subprocess.CompletedProcess``. On ``timeout`` (seconds) its whole session is killed
        and waited for, then ``subprocess.TimeoutExpired`` is raised with all the output it
        had written (its ``stdout`` and ``stderr``, text)."""
        proc = self.popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          **kwargs)
        try:
            stdout, stderr = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            stdout, stderr = proc.communicate()
            raise subprocess.TimeoutExpired(proc.args, timeout, stdout, stderr) from None
        return subprocess.CompletedProcess(proc.args, proc.returncode, stdout, stderr)

    def callback(self, function, *args, **kwargs):
        """Call ``function`` when the pool closes, after its runs are over (last in, first
        out; each one called even if another raised)."""
        self._cleanup.callback(function, *args, **kwargs)

    def close(self):
        with self._lock:
            self.closing.set()
            for proc in self._processes:
                if proc.poll() is None:
                    try:
                        os.killpg(proc.pid, signal.SIGKILL)
                    except ProcessLookupError:
                        pass
        try:
            self._pool.shutdown(wait=True, cancel_futures=True)
        finally:
            self._cleanup.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
