"""Progress of long work on standard error: a bar on a terminal, plain lines in a log.

``reflectance render`` and ``reflectance bench`` report each phase (and each image size) through a
:class:`Progress`. On a terminal one line is redrawn in place (carriage return); written to a file
or a pipe (a Snakemake log, CI) each step is one line of its own, so a log reads as a history.
Disabled (``--quiet``), it writes nothing. Standard output is never touched: it carries the
commands' CSV and JSON.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from typing import Any, TextIO

__all__ = ["Progress", "WORKER_PROGRESS", "worker_progress", "run_worker", "worker_main"]


class Progress:
    """Steps of one long task, reported on a stream.

    Parameters
    ----------
    total : int
        Number of steps of the task (the bar is full at ``total``).
    label : str
        Who is working, printed first (e.g. ``"reflectance render"``).
    stream : file, optional
        Where to write (default: standard error, looked up when writing).
    enabled : bool
        False writes nothing (``--quiet``).
    tty : bool, optional
        Force the terminal (True) or the plain-line (False) form; default: ``stream.isatty()``.

    Examples
    --------
    >>> import io
    >>> log = io.StringIO()
    >>> progress = Progress(2, "demo", stream=log)
    >>> progress.update(0, "visibility"); progress.update(1, "shading"); progress.close()
    >>> print(log.getvalue(), end="")
    demo: [0/2] visibility
    demo: [1/2] shading
    demo: [2/2] done
    """

    WIDTH = 24  # characters of the bar

    def __init__(self, total: int, label: str, stream: TextIO | None = None, enabled: bool = True,
                 tty: bool | None = None) -> None:
        self.total = max(int(total), 1)
        self.label = label
        self._stream = stream
        self.enabled = bool(enabled)
        self._tty = tty
        self._drawn = 0  # length of the line drawn on a terminal (0: none)

    @property
    def stream(self) -> TextIO:
        return sys.stderr if self._stream is None else self._stream

    @property
    def tty(self) -> bool:
        if self._tty is not None:
            return self._tty
        isatty = getattr(self.stream, "isatty", None)
        return bool(isatty and isatty())

    def update(self, done: int, message: str) -> None:
        """Report that ``done`` of the steps are finished and ``message`` is under way."""
        if not self.enabled:
            return
        done = min(max(int(done), 0), self.total)
        if self.tty:
            filled = round(self.WIDTH * done / self.total)
            line = (f"{self.label} [{'#' * filled}{'.' * (self.WIDTH - filled)}] "
                    f"{done}/{self.total} {message}")
            pad = max(self._drawn - len(line), 0)
            self.stream.write("\r" + line + " " * pad)
            self._drawn = len(line)
        else:
            self.stream.write(f"{self.label}: [{done}/{self.total}] {message}\n")
        self.stream.flush()

    def close(self, message: str = "done", done: int | None = None) -> None:
        """The task is finished (or stopped at step ``done``, for a failure): a last step and
        the end of the terminal's line."""
        if not self.enabled:
            return
        self.update(self.total if done is None else done, message)
        if self.tty:
            self.stream.write("\n")
            self.stream.flush()
            self._drawn = 0


#: a worker's progress lines on its standard output start so (:func:`run_worker`)
WORKER_PROGRESS = "@progress "


def worker_progress(phase):
    """In a worker of :func:`run_worker`: tell the parent that ``phase`` starts."""
    print(WORKER_PROGRESS + phase, flush=True)


def run_worker(module, job, progress=None, failure="worker failed"):
    """Run ``python -m module --worker JSON(job)`` in a fresh process and return the JSON value of
    its last line on standard output.

    Its :func:`worker_progress` lines are passed to ``progress(phase)`` as they come; standard
    error goes to a file, so that a chatty worker cannot block on a full pipe. If it fails,
    RuntimeError carries ``failure`` and the worker's standard error."""
    import json
    import subprocess
    import tempfile

    with tempfile.TemporaryFile("w+") as errors:
        proc = subprocess.Popen([sys.executable, "-m", module, "--worker", json.dumps(job)],
                                stdout=subprocess.PIPE, stderr=errors, text=True)
        lines = []
        for line in proc.stdout:
            if line.startswith(WORKER_PROGRESS):
                if progress is not None:
                    progress(line[len(WORKER_PROGRESS):].strip())
            else:
                lines.append(line)
        proc.wait()
        if proc.returncode != 0:
            errors.seek(0)
            raise RuntimeError(f"{failure}:\n{errors.read()}")
    return json.loads("".join(lines).strip().splitlines()[-1])


def worker_main(function: Callable[..., Any], argv: Sequence[str] | None = None) -> None:
    """The main of a module that :func:`run_worker` runs: ``function(**job,
    progress=worker_progress)`` for the job given as ``--worker JSON``, its value printed as
    JSON on the last line of standard output. ``argv``: the arguments (default: the process's).
    """
    import argparse
    import json

    parser = argparse.ArgumentParser()
    parser.add_argument("--worker", required=True, metavar="JSON")
    job = json.loads(parser.parse_args(argv).worker)
    print(json.dumps(function(**job, progress=worker_progress)))
