"""Support for the workflow's scripts: each logs to its rule's ``log:`` file."""

from __future__ import annotations

import contextlib
import logging
import sys
import traceback
from pathlib import Path

__all__ = ["script_log"]


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
        finally:
            sys.stdout, sys.stderr = old_out, old_err
            logger.removeHandler(handler)
