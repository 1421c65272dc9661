"""`snakemake --archive`: the tarball of a fresh clone rebuilds byte-identical outputs.

Fast by design: one small target (Cook & Torrance 1982, Fig. 4, and the spectrum it needs), built
in the clone and in the unpacked archive, with the archive's own library (PYTHONPATH), compared
byte for byte."""

import hashlib
import shutil
import subprocess
import sys
import tarfile

import pytest

pytestmark = pytest.mark.workflow

TARGETS = ["results/cook_torrance_1982/fig4.csv", "results/cook_torrance_1982/fig4.png",
           "results/cook_torrance_1982/fig4.pdf"]


def start(runs, cwd, *args):
    env = dict(runs.environ, PYTHONPATH=str(cwd / "workflow"))  # this copy's library
    return runs.popen([sys.executable, "-m", "snakemake", "--cores", "1", *args], cwd=cwd,
                      env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def finish(proc):
    out, _ = proc.communicate()
    assert proc.returncode == 0, f"{' '.join(proc.args[3:])}:\n{out[-3000:]}"


def digests(cwd):
    return {t: hashlib.sha256((cwd / t).read_bytes()).hexdigest() for t in TARGETS}


def start_with_session(runs, root, tmp_path_factory, items):
    """Start the archive's runs on the session's pool (tests/conftest.py's ``early`` calls this
    when the session starts): they need nothing of the session's build, and are all waiting on
    subprocesses, so they overlap the other tests; the test takes their result (or failure)."""
    _start_archive(runs, root, tmp_path_factory)


def _start_archive(runs, root, tmp_path_factory):
    if runs.started("archive"):
        return
    if shutil.which("git") is None or subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=root, capture_output=True).returncode != 0:
        runs.start("archive", pytest.skip,
                   "the project is not a git checkout (snakemake --archive needs one)")
        return
    runs.start("archive", _archive_runs, runs, root, tmp_path_factory.mktemp("archive"))


def _archive_runs(runs, root, tmp_path):
    """A fresh clone of ``root``, its ``--archive`` tarball of TARGETS, unpacked, and TARGETS
    built in both: (clone, unpacked, the tarball's names)."""
    clone = tmp_path / "clone"
    git = runs.popen(["git", "clone", "-q", str(root), str(clone)], stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True)
    out, _ = git.communicate()
    assert git.returncode == 0, out
    tarball = tmp_path / "archive.tar.gz"
    finish(start(runs, clone, "--archive", str(tarball), *TARGETS))
    with tarfile.open(tarball) as tar:
        names = set(tar.getnames())
        unpacked = tmp_path / "unpacked"
        tar.extractall(unpacked, filter="tar")
    # both builds at once (one core each); with mtime triggers only, the committed spectra of
    # each copy are used as they are (tests/test_workflow.py checks that a fresh export equals
    # them) and only the figure is built
    builds = [start(runs, cwd, *TARGETS, "--rerun-triggers", "mtime") for cwd in (unpacked, clone)]
    for proc in builds:
        finish(proc)
    return clone, unpacked, names


def test_archive_of_a_fresh_clone_rebuilds_byte_identical(early, root, tmp_path_factory):
    """The runs (``_archive_runs``) start with the session, on its pool; taken here."""
    _start_archive(early, root, tmp_path_factory)  # (``early`` did, unless run without it)
    clone, unpacked, names = early.result("archive")
    assert {"Snakefile", "config.yaml", "pyproject.toml", "workflow/envs/constraints.txt",
            "workflow/reflectance/io/images.py", "spectra/Cu.csv"} <= names
    assert not any(n.startswith(("results/", ".git/")) and n != "results/README.md"
                   for n in names)
    assert digests(unpacked) == digests(clone)
