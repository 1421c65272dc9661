"""Interrupted and failing runs, end to end, in a temporary copy of the project.

The building guide (workflow/docs/guides/building.rst, "Resuming an interrupted run")
promises that a run killed outright resumes with a plain `snakemake --cores 2`, that no
half-written file ever appears at an output's path, and that a failing job never removes a
committed spectrum.
"""

import hashlib
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

import pytest
import yaml

from test_workflow import SNAKEMAKE, copy_project, digests, results

pytestmark = pytest.mark.workflow

#: The render the run is killed in: Cook & Torrance's Fig. 6, the one job of the figure's family,
#: which writes the default figure's panel a (scene, EXR, PNG), then panel b, then the figure and
#: its table, then each reading's likewise, each file in one rename; the gamut-mapping audit,
#: README's strip and the provenance manifest read its files.
KILLED_RULE = "ct82_fig6"
READINGS = yaml.safe_load((Path(__file__).resolve().parents[1] / "config.yaml").read_text())[
    "figures"]["cook_torrance_1982"]["fig6"]["ambient_readings"]
KILLED_OUTPUTS = ["results/cook_torrance_1982/fig6.values.rst"] + [
    f"results/cook_torrance_1982/{name}"
    for suffix in [""] + [f"_{reading}" for reading in READINGS]
    for name in [f"fig6{suffix}.png", f"fig6{suffix}.csv"]
    + [f"fig6{panel}{suffix}.{ext}" for panel in "ab" for ext in ("exr", "png", "scene.yaml")]]


def whole(path):
    """Raise unless ``path`` is a complete file of its kind (decodes to the end)."""
    import numpy as np
    import pandas as pd
    from PIL import Image

    from reflectance.io.images import read_exr

    name = path.name
    if name.endswith((".png", ".gif")):
        with Image.open(path) as im:
            for frame in range(getattr(im, "n_frames", 1)):
                im.seek(frame)
                im.load()
    elif name.endswith(".exr"):
        XYZ, _ = read_exr(path)
        assert np.all(np.isfinite(XYZ)), path
    elif name.endswith(".csv"):
        assert len(pd.read_csv(path).columns) >= 2, path
    elif name.endswith(".yaml"):
        assert isinstance(yaml.safe_load(path.read_text()), dict), path
    elif name.endswith(".pdf"):
        data = path.read_bytes()
        assert data.startswith(b"%PDF") and data.rstrip().endswith(b"%%EOF"), path
    elif name.endswith(".rst"):  # an audit's answer or a figure's values, included by its caption
        text = path.read_text(encoding="utf-8")
        assert text.strip() and text.endswith("\n"), path
    else:
        raise AssertionError(f"unexpected output {path}")


def final_files(cwd):
    """{path: its inode and modification time} of every file at an output's path under results/
    (a writer replaces a file in one rename: a new inode is a new file)."""
    return {p: (p.stat().st_ino, p.stat().st_mtime_ns) for p in (cwd / "results").rglob("*")
            if p.is_file() and not p.name.startswith(".")}


def temporaries(cwd):
    return sorted(str(p) for p in (cwd / "results").rglob(".*") if p.is_file())


def after_build(runs, built, tmp_path_factory, items):
    """tests/conftest.py's ``early`` calls this when the session's build is done: if the kill -9
    test is selected, its copy of the build is made here and its runs start then."""
    if not any(item.originalname == "test_kill_9_mid_render_then_a_plain_rerun_completes"
               for item in items):
        return []
    tmp = tmp_path_factory.mktemp("kill-9")
    cwd = tmp / "copy"
    shutil.copytree(built, cwd, symlinks=True, ignore=shutil.ignore_patterns("locks"))
    return [(25, "kill -9", _kill_9_and_resume, (runs, built, cwd, tmp))]


def test_kill_9_mid_render_then_a_plain_rerun_completes(after_build):
    """The building guide: a run killed outright resumes with a plain `snakemake --cores 2`, and what it
    builds is byte-identical to an uninterrupted build.

    The session's whole build (`built`) is copied with Snakemake's records, and one render's
    outputs are removed, as if that render had never run: the run in the copy starts it (and,
    after it, the jobs that read its files) and is killed with SIGKILL, Snakemake and its jobs,
    once the render has begun writing. The plain rerun must render again and end with every file
    of results/ byte-identical to the uninterrupted build's: the CSVs, EXRs, PNGs, PDFs and scene
    files the render and the jobs after it write anew, and everything else untouched. The runs
    start when the build ends (``after_build``); ``_kill_9_and_resume`` checks as it goes, and
    what fails there fails here."""
    after_build("kill -9")


def _kill_9_and_resume(runs, built, cwd, tmp_path):
    for name in KILLED_OUTPUTS:
        (cwd / name).unlink()
    copied = final_files(cwd)  # the build's own files (test_workflow reads them)
    log = open(tmp_path / "first_run.txt", "w")
    run = runs.popen(SNAKEMAKE + ["--cores", "2"], cwd=cwd, stdout=log, stderr=subprocess.STDOUT)
    checked = dict(copied)
    killed, started, before = False, None, set()
    try:
        deadline = time.monotonic() + 1800
        while time.monotonic() < deadline and run.poll() is None:
            # Every file that appears at an output's path is whole the moment it is seen.
            for path, key in final_files(cwd).items():
                if checked.get(path) != key:
                    whole(path)
                    checked[path] = key
            text = (tmp_path / "first_run.txt").read_text()
            rendering = (f"rule {KILLED_RULE}:" in text
                         and f"(Rule: {KILLED_RULE})" not in text)
            written = set((cwd / "results").rglob("*"))
            if rendering and started is None:
                started, before = time.monotonic(), written
            # Mid-render: the job has begun writing (a scene file or a temporary of its first
            # image), so some of its outputs exist and others are still to come.
            if rendering and (written - before or time.monotonic() - started > 120):
                killed = True
                break
            time.sleep(0.2)
    finally:
        if run.poll() is None:
            os.killpg(run.pid, signal.SIGKILL)  # the whole group: snakemake and its jobs
        run.wait()
        log.close()
    first_run = (tmp_path / "first_run.txt").read_text()
    assert killed, "the run ended before the render could be killed:\n" + first_run[-3000:]
    assert (cwd / ".snakemake" / "locks").is_dir()  # what a killed run leaves behind
    missing = [name for name in KILLED_OUTPUTS if not (cwd / name).exists()]
    assert missing, "the render had finished when it was killed"
    for path, key in final_files(cwd).items():  # what the killed run wrote
        if checked.get(path) != key:
            whole(path)

    spectra_before = {p.name: p.read_bytes() for p in (cwd / "spectra").glob("*.csv")}
    # plain: no --rerun-incomplete, no --unlock
    proc = runs.run(SNAKEMAKE + ["--cores", "2"], cwd=cwd)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "reflectance: resuming" in proc.stderr
    assert f"rule {KILLED_RULE}:" in proc.stdout + proc.stderr  # rendered again
    for path, key in final_files(cwd).items():  # what the rerun wrote (the rest: compared below)
        if copied.get(path) != key:
            whole(path)
    assert temporaries(cwd) == []  # the killed writers' temporaries were removed
    assert {p.name: p.read_bytes() for p in (cwd / "spectra").glob("*.csv")} == spectra_before
    dry = runs.run(SNAKEMAKE + ["-n", "--cores", "2"], cwd=cwd)
    assert dry.returncode == 0, dry.stdout + dry.stderr
    assert "Nothing to be done" in dry.stdout + dry.stderr
    files = results(built)
    assert results(cwd) == files
    resumed, clean = digests(cwd, files), digests(built, files)
    assert [p for p in files if resumed[p] != clean[p]] == []
    # the render's files are new ones, not the copies of the build's
    assert all(os.path.getmtime(cwd / name) > os.path.getmtime(built / name)
               for name in KILLED_OUTPUTS)


FAILING_CASES = ["bad notation", "failing script", "one material fails"]


def _spectra_digests(cwd):
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in (cwd / "spectra").glob("*.csv")}


def _spectra_inodes(cwd):
    return {p.name: p.stat().st_ino for p in (cwd / "spectra").glob("*.csv")}


def start_with_session(runs, root, tmp_path_factory, items):
    """Start the failing cases' runs on the session's pool if any of ``items`` (this module's
    selected tests) needs them: tests/conftest.py's ``early`` calls this when the session starts.
    They need nothing of the session's build, so they run while other tests do."""
    if any("failing_runs" in getattr(item, "fixturenames", ()) for item in items):
        _start_failing(runs, root, tmp_path_factory)


def _start_failing(runs, root, tmp_path_factory):
    for case in FAILING_CASES:
        if not runs.started(("failing", case)):  # (not start_once: no folder made for nothing)
            runs.start(("failing", case), _failing_run, runs, root,
                       tmp_path_factory.mktemp("failing"), case)


def _failing_run(runs, root, cwd, case):
    """One case's run in its own copy of the project: (copy, digests and inodes of its spectra
    before, finished process)."""
    copy_project(root, cwd)
    script = cwd / "workflow" / "scripts" / "derive_spectra.py"
    if case == "bad notation":  # not a Munsell colour: refused before any job starts
        config = yaml.safe_load((cwd / "config.yaml").read_text())
        config["materials"]["Rubber"]["notation"] = "N99"
        (cwd / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
    elif case == "failing script":  # whatever the reason, a derive job that fails after it wrote
        # (a stand-in derive: the case is about the job failing after it wrote, not about the
        # Meng fits, ~21 CPU-s for nothing)
        _stand_in_derive(script, failing="")
        script.write_text(script.read_text() + "\nraise RuntimeError('fails after writing')\n")
    else:  # one material fails: Rubber; the others (a stand-in) do not
        _stand_in_derive(script, failing="N2.5")
    committed, inodes = _spectra_digests(cwd), _spectra_inodes(cwd)
    proc = runs.popen(SNAKEMAKE + ["--cores", "1", "--force", "spectra/Rubber.csv"], cwd=cwd,
                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    proc.communicate()
    return cwd, committed, inodes, proc


def _stand_in_derive(script, failing):
    """derive_spectra.py's ``derive`` replaced by a stand-in: a flat spectrum for every material,
    a ValueError for the one whose notation is ``failing`` (none if it is "")."""
    text = script.read_text()
    assert "def derive(entry):\n" in text
    script.write_text(text.replace("def derive(entry):\n", f"""def derive(entry):
    if entry["notation"] == {failing!r}:
        raise ValueError("stand-in failure")
    return {{"wavelength_nm": [400.0, 700.0], "reflectance": [0.5, 0.5]}}
"""))


@pytest.fixture(scope="module")
def failing_runs(early, root, tmp_path_factory):
    """The cases' runs, each in its own copy of the project, side by side on the session's pool
    (tests/side_by_side.py), started with the session (``start_with_session``):
    case -> (copy, digests and inodes of its spectra before, finished process), each case's
    failure raised by its own test."""
    _start_failing(early, root, tmp_path_factory)
    return lambda case: early.result(("failing", case))


@pytest.mark.parametrize("case", FAILING_CASES)
def test_a_failing_spectrum_job_keeps_the_committed_file(failing_runs, case):
    """Snakemake deletes a job's outputs before it runs and after it fails; the committed spectra
    are flagged update(), so the previous file stays (and is restored after a failure). The job
    that derives every Munsell spectrum makes them all before it writes any: one material that
    fails is named in its log, and no file is replaced (each keeps its inode; Snakemake's
    restore copies into the file at the path, an atomic write would have left a new one)."""
    cwd, committed, inodes, proc = failing_runs(case)
    assert proc.returncode != 0
    assert _spectra_digests(cwd) == committed
    assert not [p for p in (cwd / "spectra").iterdir() if p.name.startswith(".")]
    after = _spectra_inodes(cwd)
    if case == "failing script":  # written, then restored: the inode check below can tell
        assert after["Rubber.csv"] != inodes["Rubber.csv"]
    if case == "one material fails":
        config = yaml.safe_load((cwd / "config.yaml").read_text())
        derived = sum(m["source"] == "munsell" for m in config["materials"].values())
        log = (cwd / "logs" / "spectra" / "_munsell.log").read_text()
        assert f"1 of {derived} spectra failed, none written" in log
        assert "materials.Rubber: ValueError: stand-in failure" in log
        assert after == inodes
