"""Support for the workflow's scripts: each logs to its rule's ``log:`` file."""

from __future__ import annotations

import contextlib
import logging
import sys
import traceback
from pathlib import Path

__all__ = ["script_log", "peak_memory", "params_dict", "command_line_job"]


def peak_memory():
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


def command_line_job(rule, argv=None):
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


@contextlib.contextmanager
def script_log(snakemake):
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
        except BaseException:
            traceback.print_exc(file=stream)
            raise
        else:
            if (peak := peak_memory()) is not None:
                logger.info("peak resident memory: %s", peak)
        finally:
            sys.stdout, sys.stderr = old_out, old_err
            logger.removeHandler(handler)


def params_dict(params):
    """A job's params as a plain dict: Snakemake's ``Params`` (named items), a mapping, or a
    namespace (the tests' stand-in for Snakemake's object).

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> params_dict(SimpleNamespace(fig={"k": 1}, colour="sRGB"))
    {'fig': {'k': 1}, 'colour': 'sRGB'}
    """
    return dict(params.items()) if hasattr(params, "items") else dict(vars(params))
