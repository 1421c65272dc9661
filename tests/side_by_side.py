"""Independent subprocesses of one test module, run side by side (test helper).

A `snakemake -n` that fails at parse time, or a `python -X importtime` start, is one process
busy on one core for several seconds while pytest waits. When a module has several such runs
that do not depend on one another, a module-scoped fixture starts them all at once on a small
pool (one per core this process may use, at most four: each holds a few hundred MB), and each
test then takes its own run's result and makes its own assertions on it. What each test checks
is unchanged; only the waiting overlaps.
"""

import os
from concurrent.futures import ThreadPoolExecutor


def workers():
    """How many runs at once: the cores this process may use, 1 to 4."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        cores = os.cpu_count() or 1
    return max(1, min(4, cores))


class SideBySide:
    """``start(key, function, *args)`` in a thread pool; ``result(key)`` waits for that one
    (and raises what it raised)."""

    def __init__(self, n=None):
        self._pool = ThreadPoolExecutor(n or workers())
        self._runs = {}

    def start(self, key, function, *args, **kwargs):
        assert key not in self._runs, key
        self._runs[key] = self._pool.submit(function, *args, **kwargs)

    def start_once(self, key, function, *args, **kwargs):
        """``start`` unless ``key`` was started already."""
        if key not in self._runs:
            self.start(key, function, *args, **kwargs)

    def result(self, key):
        return self._runs[key].result()

    def close(self):
        self._pool.shutdown(wait=True, cancel_futures=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
