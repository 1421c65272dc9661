"""The workflow runs unchanged through Snakemake's generic-cluster executor (local submit script)."""

import hashlib
import re
import shutil
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.workflow

TARGETS = ["results/cook_torrance_1982/fig4.csv", "results/cook_torrance_1982/fig5bc.csv"]


def after_build(runs, built, tmp_path_factory, items):
    """tests/conftest.py's ``early`` calls this when the session's build is done: the cluster
    run starts then, beside the other runs that read the build (``items``: its selected test)."""
    cwd = tmp_path_factory.mktemp("cluster")
    root = Path(__file__).resolve().parents[1]
    for name in ("Snakefile", "config.yaml"):
        shutil.copy(root / name, cwd / name)
    shutil.copytree(root / "workflow", cwd / "workflow",
                    ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    shutil.copytree(built / "spectra", cwd / "spectra", copy_function=shutil.copy)
    return [(10, "generic cluster", _cluster_run, (runs, cwd))]


def _cluster_run(runs, cwd):
    # Status checks every second, not Snakemake's default 10 s: a test has no scheduler to spare.
    proc = runs.run([sys.executable, "-m", "snakemake", "--profile",
                     "workflow/profiles/cluster-generic", "--seconds-between-status-checks",
                     "1", *TARGETS], cwd=cwd, timeout=1800)  # a loaded 2-core machine
    return cwd, proc


def test_generic_cluster_profile_gives_the_local_result(built, after_build):
    """Two figures through workflow/profiles/cluster-generic, byte-identical to the same files of
    the session's local build (`built`), made from the same inputs: this checkout's workflow and
    config, and the spectra that build exported (fresh times, so none is made again). The run
    starts when the build ends (``after_build``)."""
    cwd, proc = after_build("generic cluster")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    # The executor's own report for every job, with the id that submit.sh printed (local-<pid>):
    # the jobs really went through the submit command, not the local executor.
    submitted = re.findall(r"Submitted job (\d+) with external jobid 'local-\d+'",
                           proc.stdout + proc.stderr)
    assert len(submitted) >= len(TARGETS), proc.stdout + proc.stderr
    digest = {t: [hashlib.sha256((d / t).read_bytes()).hexdigest() for d in (cwd, built)]
              for t in TARGETS}
    assert all(cluster == local for cluster, local in digest.values()), digest
