"""The workflow runs unchanged through Snakemake's generic-cluster executor (local submit script)."""

import hashlib
import re
import shutil
import subprocess
import sys

import pytest

pytestmark = pytest.mark.workflow

TARGETS = ["results/cook_torrance_1982/fig4.csv", "results/cook_torrance_1982/fig5bc.csv"]


def build(root, cwd, *extra):
    for name in ("Snakefile", "config.yaml"):
        shutil.copy(root / name, cwd / name)
    for name in ("workflow", "spectra"):
        shutil.copytree(root / name, cwd / name, ignore=shutil.ignore_patterns("__pycache__"))
    proc = subprocess.run([sys.executable, "-m", "snakemake", *extra, *TARGETS], cwd=cwd,
                          capture_output=True, text=True, timeout=1800)  # a loaded 2-core machine
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return {t: hashlib.sha256((cwd / t).read_bytes()).hexdigest() for t in TARGETS}, proc


def test_generic_cluster_profile_gives_the_local_result(root, tmp_path):
    (tmp_path / "local").mkdir()
    (tmp_path / "cluster").mkdir()
    local, _ = build(root, tmp_path / "local", "--cores", "2")
    cluster, proc = build(root, tmp_path / "cluster", "--profile",
                          "workflow/profiles/cluster-generic")
    # The executor's own report for every job, with the id that submit.sh printed (local-<pid>):
    # the jobs really went through the submit command, not the local executor.
    submitted = re.findall(r"Submitted job (\d+) with external jobid 'local-\d+'",
                           proc.stdout + proc.stderr)
    assert len(submitted) >= len(TARGETS), proc.stdout + proc.stderr
    assert cluster == local
