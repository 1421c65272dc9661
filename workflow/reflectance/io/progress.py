"""Progress of long work on standard error: a tqdm bar with the time left, on a terminal only.

``reflectance render``, ``reflectance bench`` and ``reflectance audit --database`` count their
work through a :class:`Progress` (render: the samples traced and shaded; bench: the pixels of the
sizes; the audit: its blocks of datasets), the phase under way as the bar's description. The bar
is tqdm's (https://tqdm.github.io), whose estimate of the time left is the work still to do at
the recent rate. It is drawn only when the stream is a terminal: written to a file or a pipe (a
Snakemake log, CI) nothing is written, nor with ``--quiet``. Standard output is never touched: it
carries the commands' CSV and JSON.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping, Sequence
from types import TracebackType
from typing import Any, TextIO

__all__ = ["Progress", "WORKER_PROGRESS", "worker_progress", "run_worker", "worker_main"]


class Progress:
    """The work of one long task, a bar on a terminal (:class:`tqdm.tqdm`).

    Parameters
    ----------
    total : int or None
        Units of work of the task (None: not known yet; :meth:`update` may set or grow it).
    label : str
        Who is working, printed first (e.g. ``"reflectance render"``).
    stream : file, optional
        Where to draw (default: standard error when the task starts).
    enabled : bool
        False draws nothing (``--quiet``).
    tty : bool, optional
        Force the bar (True) or nothing (False); default: a bar if ``stream.isatty()`` (tqdm's
        ``disable=None``).
    unit : str
        The units' name, after their count (``" samples"``).
    unit_scale : bool
        Counts with SI prefixes (``1.05M``).

    Examples
    --------
    >>> import io
    >>> log = io.StringIO()  # not a terminal: nothing is written
    >>> progress = Progress(2, "demo", stream=log)
    >>> progress.update(1, "shading"); progress.close()
    >>> log.getvalue()
    ''
    """

    def __init__(self, total: int | None, label: str, stream: TextIO | None = None, enabled: bool = True, tty: bool | None = None, unit: str = " steps",
                 unit_scale: bool = False) -> None:
        from tqdm import tqdm

        self.label = label
        disable = True if not enabled or tty is False else (False if tty else None)
        # mininterval and the rest left to tqdm (and to its TQDM_* environment variables); no
        # prefixes while the total is unknown (a bare 0, not "0.00")
        self._unit_scale = unit_scale
        self._bar = tqdm(total=total, desc=label, file=sys.stderr if stream is None else stream,
                         disable=disable, unit=unit, unit_scale=unit_scale and total is not None,
                         dynamic_ncols=True, leave=True)
        self.enabled = not self._bar.disable  # (tqdm disables a bar when it closes)
        self._closed = False

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None, traceback: TracebackType | None) -> None:
        """Closes the bar if the task did not: stopped (``"interrupted"`` by Ctrl-C, else
        ``"failed"``), before the caller says why on a line of its own."""
        if not self._closed:
            if kind is None:
                self.close()
            else:
                self.close("interrupted" if issubclass(kind, KeyboardInterrupt) else "failed",
                           complete=False)

    @property
    def total(self) -> int | None:
        return self._bar.total

    @total.setter
    def total(self, value: int | None) -> None:
        self._bar.total, self._bar.unit_scale = value, self._unit_scale

    def update(self, done: int | None = None, message: str | None = None, total: int | None = None) -> None:
        """``done`` units of the work are finished (None: as before), ``message`` is under way
        (None: as before) and the work has ``total`` units (None: as before)."""
        bar = self._bar
        if bar.disable:
            return
        if total is not None:
            bar.total, bar.unit_scale = total, self._unit_scale
        if message is not None:
            bar.set_description_str(f"{self.label}: {message}", refresh=False)
        drawn = bar.last_print_t
        if done is not None and done > bar.n:
            bar.update(done - bar.n)  # (tqdm's rate, and so its estimate, follow the counts)
        elif done is not None:
            bar.n = done
        if bar.last_print_t == drawn:  # not drawn by update (at most every mininterval)
            bar.refresh()

    def close(self, message: str = "done", complete: bool = True) -> None:
        """The task is finished (``complete``: all its units) or stopped (a failure: the count
        as it is); the bar's last state stays on its line, the line ended. Once only."""
        if self._closed:
            return
        self._closed = True
        bar = self._bar
        if complete and bar.total is not None:
            bar.update(bar.total - bar.n)
        bar.set_description_str(f"{self.label}: {message}", refresh=False)
        bar.close()


#: a worker's progress lines on its standard output start so (:func:`run_worker`)
WORKER_PROGRESS = "@progress "


def worker_progress(phase: str) -> None:
    """In a worker of :func:`run_worker`: tell the parent that ``phase`` starts."""
    print(WORKER_PROGRESS + phase, flush=True)


def run_worker(module: str, job: Mapping[str, Any], progress: Callable[[str], object] | None = None,
               failure: str = "worker failed") -> Any:  # the worker's JSON: any JSON value
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
        assert proc.stdout is not None  # stdout=PIPE
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
