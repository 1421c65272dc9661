"""`reflectance render` and `bench` outputs: PNG alone, --exposure, the linear RGB EXR, tagged
PNGs, and progress on standard error (a tqdm bar on a terminal; nothing on a file or a pipe, nor
with --quiet)."""

import io
import re
import struct
import zlib

import numpy as np
import pytest

from reflectance.cli import main
from reflectance.io.images import read_exr
from reflectance.io.progress import Progress


def chunks(path):
    data, out, i = path.read_bytes(), {}, 8
    while i < len(data):
        (n,) = struct.unpack(">I", data[i:i + 4])
        out[data[i + 4:i + 8]] = data[i + 8:i + 8 + n]
        i += 12 + n
    return out


def png_codes(path):
    from PIL import Image

    with Image.open(path) as im:
        return np.asarray(im, dtype=np.float64) / 255


@pytest.fixture
def render(root, tmp_path):
    scene = root / "workflow" / "scenes" / "example_spheres.yaml"

    def run(*options):
        return main(["render", str(scene), "--width", "32", "--height", "20", "--spectra-dir",
                     str(root / "spectra"), *[str(o) for o in options]])
    return run


class Terminal(io.StringIO):
    """A stream that says it is a terminal (as a user's standard error)."""

    def isatty(self):
        return True


def test_progress_bar_on_a_terminal_only():
    """tqdm's bar, phase as its description and the time left, on a terminal; nothing on a file
    (a log, a pipe) nor when disabled (--quiet)."""
    term = Terminal()
    p = Progress(4, "job", stream=term)
    p.update(1, "a long phase name"), p.update(2, "b"), p.close()
    text = term.getvalue()
    assert text.endswith("\n") and text.count("\n") == 1  # one line, redrawn in place
    assert "job: a long phase name:  25%|" in text and "| 1/4 [" in text
    assert re.search(r"job: done: 100%\|.*\| 4/4 \[\d\d:\d\d<\d\d:\d\d", text), text
    for stream, options in ((io.StringIO(), {}), (Terminal(), {"enabled": False}),
                            (Terminal(), {"tty": False})):
        p = Progress(2, "job", stream=stream, **options)
        p.update(1, "x"), p.close()
        assert stream.getvalue() == "" and not p.enabled
    forced = io.StringIO()
    p = Progress(2, "job", stream=forced, tty=True)
    p.update(1, "x"), p.close()
    assert p.enabled and "job: done: 100%|" in forced.getvalue()


def test_a_worker_main_answers_run_worker(tmp_path, monkeypatch):
    """The subprocess protocol of the bench and the cross-check: worker_main calls its function
    with the job's keywords and a progress that run_worker passes on, and prints the value."""
    import os
    import textwrap

    from reflectance.io.progress import run_worker

    (tmp_path / "toy_worker.py").write_text(textwrap.dedent("""\
        from reflectance.io.progress import worker_main

        def job(size, name, progress):
            progress(f"phase of {name}")
            print("chatter that is not the answer")
            return {"area": size * size, "name": name}

        if __name__ == "__main__":
            worker_main(job)
        """))
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(tmp_path),
                                                      os.environ.get("PYTHONPATH", "")]))
    seen = []
    assert run_worker("toy_worker", {"size": 3, "name": "x"}, seen.append) == {"area": 9,
                                                                                "name": "x"}
    assert seen == ["phase of x"]
    with pytest.raises(RuntimeError, match="toy failed:(.|\n)*unexpected keyword"):
        run_worker("toy_worker", {"size": 3, "name": "x", "colour": 1}, failure="toy failed")


def test_render_png_alone_prints_nothing_on_a_pipe(render, tmp_path, capsys):
    assert render("--png", tmp_path / "a.png") == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png"]
    assert capsys.readouterr() == ("", "")  # (pytest's capture is not a terminal)
    assert b"sRGB" in chunks(tmp_path / "a.png")  # the scene's display space is sRGB


#: `reflectance render` in a process of its own, its image in bands of 4 pixel rows (so that the
#: bar has several steps to estimate the time left from)
BANDED_RENDER = ("import sys\n"
                 "import reflectance.render.tracing as tracing\n"
                 "tracing.SINGLE_TILE_SAMPLES, tracing.TILE_SAMPLES = 0, 64 * 2 * 2 * 4\n"
                 "from reflectance.cli import main\n"
                 "sys.exit(main(['render', *sys.argv[1:]]))\n")


def banded_render(root, tmp_path, terminal, *options, scene=None):
    import os
    import sys

    from terminal import stderr_of

    scene = scene or root / "workflow" / "scenes" / "example_spheres.yaml"
    return stderr_of([sys.executable, "-c", BANDED_RENDER, str(scene),
                      "--width", "64", "--height", "48", "--spectra-dir", str(root / "spectra"),
                      *map(str, options)], terminal, cwd=tmp_path,
                     env=dict(os.environ, PYTHONPATH=str(root / "workflow")))


def test_render_on_a_terminal_shows_a_bar_with_the_time_left(root, tmp_path):
    """On a terminal: tqdm's bar of the samples (12288: 64 x 48 pixels of 2 x 2), each band's
    phase as its description, the time left once a band is done (elapsed<left), one line
    redrawn in place, then the summary."""
    proc, text = banded_render(root, tmp_path, True, "--png", tmp_path / "a.png")
    assert proc.returncode == 0, text
    frames = re.split(r"[\r\n]+", text.strip())
    middle = [f for f in frames if re.search(r": +([1-9]|[1-9]\d)%\|", f)]  # 1 % to 99 %
    assert middle, text
    assert any(re.search(r"\| [\d.]+k/12\.3k \[\d\d:\d\d<\d\d:\d\d, [\d.]+[kM]? samples/s\]$", f)
               for f in middle), text
    assert any(f.startswith("reflectance render: rows 24-28: shadows: ") for f in frames), text
    assert re.search(r"reflectance render: done: 100%\|.*\| 12\.3k/12\.3k ", frames[-2]), text
    assert frames[-1].startswith(f"{tmp_path / 'a.png'}: 64 x 48 pixels"), text
    assert text.count("\n") == 2  # the bar's line and the summary's
    proc, text = banded_render(root, tmp_path, True, "--png", tmp_path / "b.png", "--quiet")
    assert (proc.returncode, text) == (0, "")


def test_render_on_a_pipe_prints_nothing_but_errors(root, tmp_path):
    """Standard error to a pipe (a Snakemake log, CI): no bar, no phases, no summary; a failure
    is its one line, on a pipe and on a terminal (after the bar's line)."""
    proc, text = banded_render(root, tmp_path, False, "--png", tmp_path / "a.png")
    assert (proc.returncode, text) == (0, ""), text
    assert (tmp_path / "a.png").is_file()
    # a material no spectra folder has: refused when the scene is read, the bar begun
    bad = tmp_path / "bad.yaml"
    bad.write_text(X_SCENE.replace("{model: Lambert, albedo: 0.5}", "{name: Unobtainium, m: 0.3}"))
    proc, text = banded_render(root, tmp_path, False, "--png", tmp_path / "c.png", scene=bad)
    assert proc.returncode == 1 and len(text.splitlines()) == 1, text
    assert text.startswith("reflectance: ") and "Unobtainium" in text, text
    proc, text = banded_render(root, tmp_path, True, "--png", tmp_path / "c.png", scene=bad)
    lines = text.replace("\r\n", "\n").rstrip("\n").split("\n")  # (a redraw is "\r")
    assert proc.returncode == 1 and len(lines) == 2, text
    assert lines[0].split("\r")[-1].startswith("reflectance render: failed: "), text
    assert lines[1].startswith("reflectance: ") and "Unobtainium" in lines[1], text
    assert not (tmp_path / "c.png").exists()


def test_render_quiet_prints_nothing(render, tmp_path, capsys):
    assert render("--png", tmp_path / "a.png", "--quiet") == 0
    assert capsys.readouterr() == ("", "")


def test_render_needs_an_output(render, tmp_path):
    with pytest.raises(SystemExit, match="at least one output"):
        render()
    with pytest.raises(SystemExit, match="different files"):
        render("-o", tmp_path / "a.exr", "--rgb-exr", tmp_path / "a.exr")
    assert list(tmp_path.iterdir()) == []


def test_exposure_override_and_the_linear_rgb_exr(render, tmp_path):
    import colour

    from reflectance.colour.display import encode

    assert render("-o", tmp_path / "auto.exr", "--png", tmp_path / "auto.png", "--rgb-exr",
                  tmp_path / "auto_rgb.exr", "--quiet") == 0
    XYZ, header = read_exr(tmp_path / "auto.exr")
    scale = float(header["display_exposure_scale"])
    # the automatic scale given explicitly reproduces the automatic PNG, byte for byte
    assert render("--png", tmp_path / "same.png", "--exposure", repr(scale), "--quiet") == 0
    assert (tmp_path / "same.png").read_bytes() == (tmp_path / "auto.png").read_bytes()
    # a quarter of it: a darker picture, and the header records the factor used
    assert render("-o", tmp_path / "dark.exr", "--png", tmp_path / "dark.png", "--exposure",
                  repr(scale / 4), "--quiet") == 0
    assert float(read_exr(tmp_path / "dark.exr")[1]["display_exposure_scale"]) == scale / 4
    assert png_codes(tmp_path / "dark.png").mean() < png_codes(tmp_path / "auto.png").mean()
    # the RGB EXR: linear display light; encoded it is the PNG (to 8-bit quantisation)
    RGB, rgb_header = read_exr(tmp_path / "auto_rgb.exr", channels="RGB")
    assert RGB.min() >= 0 and RGB.max() <= 1
    np.testing.assert_allclose(encode(RGB.astype(np.float64), "sRGB"),
                               png_codes(tmp_path / "auto.png"), atol=0.5 / 255 + 1e-6)
    cs = colour.RGB_COLOURSPACES["sRGB"]
    chroma = np.array(rgb_header["chromaticities"])
    np.testing.assert_allclose(chroma, [*cs.primaries.ravel(), *cs.whitepoint], atol=1e-6)
    # and in the display's primaries, it is the XYZ image converted (where nothing was clipped)
    lit = (RGB.max(axis=-1) < 0.99) & (RGB.min(axis=-1) > 1e-3)
    assert lit.sum() > 20
    XYZ_from_RGB = colour.RGB_to_XYZ(RGB[lit].astype(np.float64), cs, cs.whitepoint,
                                     chromatic_adaptation_transform=None) / scale
    np.testing.assert_allclose(XYZ_from_RGB, XYZ[lit], rtol=1e-3, atol=1e-6)


@pytest.mark.parametrize("exposure", ["0", "-1", "nan"])
def test_bad_exposure_is_refused(render, tmp_path, exposure):
    with pytest.raises(SystemExit, match="--exposure"):
        render("--png", tmp_path / "a.png", "--exposure", exposure)
    assert list(tmp_path.iterdir()) == []


def test_bench_reports_each_size_and_phase(root, monkeypatch, capsys):
    # one size (each runs in its own process, ~15 s); its pixels are the bar's total
    term = Terminal()
    monkeypatch.setattr("sys.stderr", term)
    assert main(["bench", "--sizes", "8", "--runs", "2", "--brute-force-runs", "0",
                 "--grids", "--spectra-dir", str(root / "spectra")]) == 0
    out = capsys.readouterr().out
    assert "size" in out.splitlines()[1]  # the report itself, on stdout
    frames = re.split(r"[\r\n]+", term.getvalue().strip())
    where = "reflectance bench: size 8 (1/1)"
    assert any(f.startswith(f"{where}:   0%|") for f in frames), frames
    for phase in ("scene", "run 1/2: visibility", "run 1/2: shadows", "run 1/2: shading",
                  "run 2/2: shading"):
        assert any(f.startswith(f"{where}: {phase}:   0%|") for f in frames), phase
    assert re.match(r"reflectance bench: done: 100%\|.*\| 64\.0/64\.0 \[", frames[-1]), frames


#: a scene for the bench commands below (the bench reads and checks it before its sizes run)
X_SCENE = ("camera: {position: [0, -5, 0], look_at: [0, 0, 0], fov_deg: 30, width: 8, height: 6}\n"
           "objects: [{geometry: {type: sphere, radius: 1.0},\n"
           "           material: {model: Lambert, albedo: 0.5}}]\n"
           "lights: [{type: directional, direction: [0, -1, 1]}]\n")


def test_bench_progress_on_a_terminal_only(monkeypatch, capsys, tmp_path):
    import reflectance.bench.run as bench

    monkeypatch.chdir(tmp_path)
    (tmp_path / "x.yaml").write_text(X_SCENE)

    def fake_run_bench(*args, progress=None, **kwargs):
        progress.update(0, "size 8 (1/2)")
        progress.update(64, "size 16 (2/2)")
        progress.close()
        return []
    monkeypatch.setattr(bench, "run_bench", fake_run_bench)
    assert main(["bench", "--sizes", "8", "16", "--scene", "x.yaml", "--quiet"]) == 0
    assert capsys.readouterr().err == ""
    assert main(["bench", "--sizes", "8", "16", "--scene", "x.yaml"]) == 0
    assert capsys.readouterr().err == ""  # not a terminal
    term = Terminal()
    for quiet in (["--quiet"], []):
        with monkeypatch.context() as patch:
            patch.setattr("sys.stderr", term)
            assert main(["bench", "--sizes", "8", "16", "--scene", "x.yaml", *quiet]) == 0
        if quiet:
            assert term.getvalue() == ""
    # the bar counts the sizes' pixels (8 x 8 + 16 x 16), the size under way its description
    assert "reflectance bench: size 16 (2/2):  20%|" in term.getvalue()
    assert re.search(r"reflectance bench: done: 100%\|.*\| 320/320 \[", term.getvalue())


def test_bench_command_defaults_are_the_librarys(monkeypatch, tmp_path):
    """`reflectance bench` without options passes run_bench its own defaults for the references
    and the cross-check (the parser reads them from reflectance.bench.measure)."""
    import inspect

    import reflectance.bench.run as bench

    monkeypatch.chdir(tmp_path)
    (tmp_path / "x.yaml").write_text(X_SCENE)

    real = inspect.signature(bench.run_bench)
    passed = {}
    monkeypatch.setattr(bench, "run_bench", lambda *a, **k: passed.update(
        real.bind(*a, **k).arguments) or [])
    assert main(["bench", "--scene", "x.yaml", "--quiet"]) == 0
    for name in ("reference_supersample", "crosscheck_size", "crosscheck_spp",
                 "crosscheck_supersamples"):
        assert passed[name] == real.parameters[name].default, name


def test_linear_rgb_exr_from_a_rendered_xyz_exr_matches_the_direct_one(root, tmp_path):
    """The workflow's rule (colour.linear_rgb_exr) converts a render's XYZ EXR with its scene
    file; the result is the RGB EXR the render writes itself, to float32 rounding."""
    import yaml

    from reflectance.render.pipeline import write_linear_RGB_from_XYZ

    doc = yaml.safe_load((root / "workflow" / "scenes" / "example_spheres.yaml").read_text())
    doc["camera"].update(width=24, height=16)
    doc["spectra_dir"] = str(root / "spectra")
    scene = tmp_path / "s.scene.yaml"
    scene.write_text(yaml.safe_dump(doc))
    assert main(["render", str(scene), "-o", str(tmp_path / "s.exr"), "--rgb-exr",
                 str(tmp_path / "direct.exr"), "--quiet"]) == 0
    write_linear_RGB_from_XYZ(tmp_path / "s.exr", scene, tmp_path / "s.rgb.exr")
    direct, _ = read_exr(tmp_path / "direct.exr", channels="RGB")
    converted, header = read_exr(tmp_path / "s.rgb.exr", channels="RGB")
    assert direct.max() > 0.1
    np.testing.assert_allclose(converted, direct, rtol=1e-5, atol=1e-7)
    with pytest.raises(ValueError, match="not an EXR written by a render"):
        from reflectance.io.images import write_exr_XYZ

        write_exr_XYZ(tmp_path / "plain.exr", np.ones((16, 24, 3)))
        write_linear_RGB_from_XYZ(tmp_path / "plain.exr", scene, tmp_path / "bad.rgb.exr")
    assert not (tmp_path / "bad.rgb.exr").exists()
