"""`snakemake --archive`: the tarball of a fresh clone rebuilds byte-identical outputs.

Fast by design: one small target (Cook & Torrance 1982, Fig. 4, and the spectrum it needs), built
in the clone and in the unpacked archive, with the archive's own library (PYTHONPATH), compared
byte for byte."""

import hashlib
import os
import shutil
import subprocess
import sys
import tarfile

import pytest

pytestmark = pytest.mark.workflow

TARGETS = ["results/cook_torrance_1982/fig4.csv", "results/cook_torrance_1982/fig4.png",
           "results/cook_torrance_1982/fig4.pdf"]


def start(cwd, *args):
    env = dict(os.environ, PYTHONPATH=str(cwd / "workflow"))  # this copy's library
    return subprocess.Popen([sys.executable, "-m", "snakemake", "--cores", "1", *args], cwd=cwd,
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def finish(proc):
    out, _ = proc.communicate()
    assert proc.returncode == 0, f"{' '.join(proc.args[3:])}:\n{out[-3000:]}"


def snakemake(cwd, *args):
    finish(start(cwd, *args))


def digests(cwd):
    return {t: hashlib.sha256((cwd / t).read_bytes()).hexdigest() for t in TARGETS}


def test_archive_of_a_fresh_clone_rebuilds_byte_identical(root, tmp_path):
    if shutil.which("git") is None or subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=root, capture_output=True).returncode != 0:
        pytest.skip("the project is not a git checkout (snakemake --archive needs one)")
    clone = tmp_path / "clone"
    subprocess.run(["git", "clone", "-q", str(root), str(clone)], check=True)
    tarball = tmp_path / "archive.tar.gz"
    snakemake(clone, "--archive", str(tarball), *TARGETS)
    with tarfile.open(tarball) as tar:
        names = set(tar.getnames())
        assert {"Snakefile", "config.yaml", "pyproject.toml", "workflow/envs/constraints.txt",
                "workflow/reflectance/io/images.py", "spectra/Cu.csv"} <= names
        assert not any(n.startswith(("results/", ".git/")) and n != "results/README.md"
                       for n in names)
        unpacked = tmp_path / "unpacked"
        tar.extractall(unpacked, filter="tar")
    # both builds at once (one core each); with mtime triggers only, the committed spectra of
    # each copy are used as they are (tests/test_workflow.py checks that a fresh export equals
    # them) and only the figure is built
    builds = [start(cwd, *TARGETS, "--rerun-triggers", "mtime") for cwd in (unpacked, clone)]
    for proc in builds:
        finish(proc)
    assert digests(unpacked) == digests(clone)
