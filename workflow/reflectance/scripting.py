"""Support for the workflow's scripts: each logs to its rule's ``log:`` file."""

from __future__ import annotations

import contextlib
import errno
import logging
import sys
import traceback
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from types import SimpleNamespace
from typing import Any

__all__ = ["script_log", "run_job", "peak_memory", "params_dict", "command_line_job",
           "write_audit_metadata"]


def peak_memory() -> str | None:
    """This process's peak resident memory, as ``'612 MB'`` (None where the system does not say).

    The kernel's high-water mark (``VmHWM`` in /proc/self/status) counts this program only;
    ``getrusage``'s ``ru_maxrss`` would also count the Snakemake process it was forked from.
    The rules' ``resources: mem_mb`` are set from these lines of their logs (workflow/docs/guides/
    cluster.rst), which see short peaks that ``benchmark:``'s sampling may miss.
    """
    try:
        status = Path("/proc/self/status").read_text()
    except OSError:
        return None
    for line in status.splitlines():
        if line.startswith("VmHWM:"):
            return f"{int(line.split()[1]) / 1024:.0f} MB"  # the kernel gives kB
    return None


def command_line_job(rule: str, argv: Sequence[str] | None = None) -> SimpleNamespace:
    """A stand-in for Snakemake's ``snakemake`` object, for a script a rule runs with ``shell:``
    (workflow/rules/spectra.smk says why): ``--log LOG --params JSON OUTPUT...``."""
    import argparse
    import json
    from types import SimpleNamespace

    parser = argparse.ArgumentParser(description=f"the job of rule {rule}")
    parser.add_argument("--log", required=True)
    parser.add_argument("--params", required=True, help="the rule's params, a JSON mapping")
    parser.add_argument("output", nargs="+")
    args = parser.parse_args(argv)
    return SimpleNamespace(rule=rule, log=[args.log], output=list(args.output), input=[],
                           params=SimpleNamespace(**json.loads(args.params)))


_WRITE_ERRORS = {errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EROFS, errno.EIO}
"""The errors of a write that the disk refused."""


@contextlib.contextmanager
def script_log(snakemake: Any) -> Iterator[logging.Logger]:
    """Send a script's output and any traceback to ``snakemake.log[0]``; yield a logger."""
    log_path = Path(snakemake.log[0]) if len(snakemake.log) else None
    logger = logging.getLogger(f"reflectance.{getattr(snakemake, 'rule', 'script')}")
    logger.setLevel(logging.INFO)
    if log_path is None:
        yield logger
        return
    log_path.parent.mkdir(parents=True, exist_ok=True)
    with open(log_path, "w") as stream:
        handler = logging.StreamHandler(stream)
        handler.setFormatter(logging.Formatter("%(levelname)s %(message)s"))
        logger.addHandler(handler)
        old_out, old_err = sys.stdout, sys.stderr
        sys.stdout = sys.stderr = stream
        try:
            yield logger
        except OSError as err:
            if err.filename is None:
                traceback.print_exc(file=stream)
                raise
            # a file that cannot be written or read (a full disk, a lost folder): one line naming
            # it, no traceback (issue 25); the job fails
            logger.error("cannot %s %s: %s", "write" if err.errno in _WRITE_ERRORS else "use",
                         err.filename, err.strerror or err)
            raise SystemExit(1) from None
        except BaseException:
            traceback.print_exc(file=stream)
            raise
        else:
            if (peak := peak_memory()) is not None:
                logger.info("peak resident memory: %s", peak)
        finally:
            sys.stdout, sys.stderr = old_out, old_err
            logger.removeHandler(handler)


def run_job(snakemake: Any, run: Callable[[Any, logging.Logger], None]) -> None:
    """Run a rule's job as ``run(snakemake, log)``, its output and any traceback in its log
    (:func:`script_log`).

    A rendered figure's script is this one call with its drawing,
    ``reflectance.papers.draw.<figure>.run``: the drawing lives in the library, where it is
    imported by name (never by the config check or the Snakefile's parse), and its rule's params
    carry the SHA-256 of its file, so that an edit of it reruns that figure (Snakemake's code
    trigger watches the script alone).

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> run_job(SimpleNamespace(log=[], rule="demo"), lambda job, log: print(job.rule, log.name))
    demo reflectance.demo
    """
    with script_log(snakemake) as log:
        run(snakemake, log)


def params_dict(params: Any) -> dict[str, Any]:
    """A job's params as a plain dict: Snakemake's ``Params`` (named items), a mapping, or a
    namespace (the tests' stand-in for Snakemake's object).

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> params_dict(SimpleNamespace(fig={"k": 1}, colour="sRGB"))
    {'fig': {'k': 1}, 'colour': 'sRGB'}
    """
    return dict(params.items()) if hasattr(params, "items") else dict(vars(params))


def _grid_nm(grid):
    """config.yaml's ``wavelengths`` (start_nm, end_nm, step_nm) as the metadata files write a grid
    (start, end, step); anything else as it is."""
    keys = ("start_nm", "end_nm", "step_nm")
    if isinstance(grid, dict) and set(grid) == set(keys):
        return {key[:-3]: float(grid[key]) for key in keys}
    return grid


def write_audit_metadata(snakemake: Any, what: str, *, illuminant: str, observer: str,
                         wavelengths_nm: Any, units: Mapping[str, str], **settings: Any) -> None:
    """Write the metadata file beside a workflow audit's tables (``snakemake.output.metadata``,
    :func:`reflectance.io.provenance.write_metadata`), as ``reflectance audit -o`` writes one
    beside its audit.csv: what the audit computes, the rule that ran it, the package's and its
    chief dependencies' versions, the illuminant, the observer and the wavelength grid(s), the
    SHA-256 of every input file, any further ``settings``, and the unit of every column of every
    CSV among the outputs; the tables' own SHA-256 at the end.

    Parameters
    ----------
    units : mapping of str to str
        Column name, or a shell-style pattern of names (``dE2000_*``), to its unit ("1": a pure
        number; "text": not a quantity). Every column of every table must match one: a column
        added to a table without its unit stops the job.
    """
    import csv
    import fnmatch
    from importlib.metadata import PackageNotFoundError, version

    from reflectance import __version__
    from reflectance.io.provenance import sha256_file, write_metadata

    def unit(table, column):
        for pattern, value in units.items():
            if column == pattern or fnmatch.fnmatchcase(column, pattern):
                return value
        raise ValueError(f"{snakemake.rule}: {table}: column {column!r} has no unit "
                         f"(write_audit_metadata's units: {', '.join(units)})")

    def package(name):
        try:
            return version(name)
        except PackageNotFoundError:
            return None

    tables = sorted(str(path) for path in snakemake.output if str(path).endswith(".csv"))
    columns = {}
    for path in tables:
        with open(path, newline="", encoding="utf-8") as stream:
            header = next(csv.reader(stream))
        columns[Path(path).name] = {name: {"unit": unit(Path(path).name, name)}
                                    for name in header}
    inputs = sorted({str(path) for path in snakemake.input})
    document = {
        "what": what,
        "command": f"snakemake rule {snakemake.rule}",
        "reflectance": __version__,
        "packages": {name: package(name) for name in ("numpy", "colour-science")},
        "illuminant": illuminant,
        "observer": observer,
        "wavelengths_nm": _grid_nm(wavelengths_nm),
        "inputs": {path: sha256_file(path) for path in inputs},
        **settings,
        "columns": columns,
    }
    write_metadata(snakemake.output.metadata, document, tables=tables)
