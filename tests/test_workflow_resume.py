"""Interrupted and failing runs, end to end, in a temporary copy of the project.

README promises that a run killed outright resumes with a plain `snakemake --cores 2`, that no
half-written file ever appears at an output's path, and that a failing job never removes a
committed spectrum.
"""

import hashlib
import os
import re
import signal
import subprocess
import sys
import time
from collections import Counter

import pytest
import yaml

from test_workflow import SNAKEMAKE, copy_project, digests, results, snakemake

pytestmark = pytest.mark.workflow

#: the rules that render (reflectance.render.pipeline); the run is killed during one of them
RENDER_RULES = ("ct82_fig6", "ct82_fig7", "ct82_fig8", "blinn77_fig7", "blinn77_fig7_sweep",
                "blinn77_fig8", "article_spheres")


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
    elif name.endswith(".rst"):  # an audit's one-sentence answer, included by its caption
        text = path.read_text(encoding="utf-8")
        assert text.strip() and text.endswith("\n"), path
    else:
        raise AssertionError(f"unexpected output {path}")


def final_files(cwd):
    return {p for p in (cwd / "results").rglob("*") if p.is_file() and not p.name.startswith(".")}


def temporaries(cwd):
    return sorted(str(p) for p in (cwd / "results").rglob(".*") if p.is_file())


def test_kill_9_mid_render_then_a_plain_rerun_completes(root, tmp_path, built):
    """README: a run killed outright resumes with a plain `snakemake --cores 2`, and what it
    builds is byte-identical to an uninterrupted build (the session's `built`, in another
    folder): every CSV, EXR, PNG, PDF and scene file of the archive."""
    cwd = copy_project(root, tmp_path)
    log = open(tmp_path / "first_run.txt", "w")
    run = subprocess.Popen(SNAKEMAKE + ["--cores", "2"], cwd=cwd, stdout=log,
                           stderr=subprocess.STDOUT, start_new_session=True)
    checked, killed_in, seen_running, before = set(), None, None, set()
    try:
        deadline = time.monotonic() + 3600
        while time.monotonic() < deadline and run.poll() is None:
            # Every file that appears at an output's path is whole the moment it is seen.
            for path in final_files(cwd) - checked:
                whole(path)
                checked.add(path)
            text = (tmp_path / "first_run.txt").read_text()
            running = (Counter(re.findall(r"rule (\w+):", text))
                       - Counter(re.findall(r"Finished jobid: \d+ \(Rule: (\w+)\)", text)))
            rendering = [r for r in RENDER_RULES if running[r]]
            written = set((cwd / "results").rglob("*"))
            if rendering and seen_running is None:
                seen_running, before = time.monotonic(), written
            # Mid-render: a render job has begun writing (a scene file or a temporary of its
            # first image), so some of its outputs exist and others are still to come.
            if rendering and (written - before or time.monotonic() - seen_running > 120):
                killed_in = rendering
                break
            time.sleep(0.2)
    finally:
        if run.poll() is None:
            os.killpg(run.pid, signal.SIGKILL)  # the whole group: snakemake and its jobs
        run.wait()
        log.close()
    assert killed_in, "the run ended before a render job could be killed:\n" + (
        tmp_path / "first_run.txt").read_text()[-3000:]
    assert (cwd / ".snakemake" / "locks").is_dir()  # what a killed run leaves behind
    for path in final_files(cwd):
        whole(path)

    spectra_before = {p.name: p.read_bytes() for p in (cwd / "spectra").glob("*.csv")}
    proc = snakemake(cwd, "--cores", "2")  # plain: no --rerun-incomplete, no --unlock
    assert "reflectance: resuming" in proc.stderr
    for path in final_files(cwd):
        whole(path)
    assert temporaries(cwd) == []  # the killed writers' temporaries were removed
    assert {p.name: p.read_bytes() for p in (cwd / "spectra").glob("*.csv")} == spectra_before
    dry = snakemake(cwd, "-n", "--cores", "2")
    assert "Nothing to be done" in dry.stdout + dry.stderr
    files = results(built)
    assert results(cwd) == files
    resumed, clean = digests(cwd, files), digests(built, files)
    assert [p for p in files if resumed[p] != clean[p]] == []


@pytest.mark.parametrize("case", ["bad notation", "failing script"])
def test_a_failing_spectrum_job_keeps_the_committed_file(root, tmp_path, case):
    """Snakemake deletes a job's outputs before it runs and after it fails; the committed spectra
    are flagged update(), so the previous file stays (and is restored after a failure)."""
    cwd = copy_project(root, tmp_path)
    if case == "bad notation":  # not a Munsell colour: the recovery fails inside the job
        config = yaml.safe_load((cwd / "config.yaml").read_text())
        config["materials"]["Rubber"]["notation"] = "N99"
        (cwd / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
    else:  # whatever the reason, a derive job that fails after it started
        script = cwd / "workflow" / "scripts" / "derive_spectrum.py"
        script.write_text(script.read_text() + "\nraise RuntimeError('fails after writing')\n")
    committed = {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
                 for p in (cwd / "spectra").glob("*.csv")}
    proc = snakemake(cwd, "--cores", "1", "--force", "spectra/Rubber.csv", check=False)
    assert proc.returncode != 0
    assert {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in (cwd / "spectra").glob("*.csv")} == committed
    assert not [p for p in (cwd / "spectra").iterdir() if p.name.startswith(".")]
