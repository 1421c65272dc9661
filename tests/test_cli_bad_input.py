"""Bad command-line input: each is refused with one line naming the option (or the file), exit
status 1, no traceback, and no file written. Issue 12, "Command line"."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

from reflectance.cli import main

SCENE = """\
camera: {position: [0, -5, 0], look_at: [0, 0, 0], fov_deg: 30, width: 8, height: 6}
objects:
  - geometry: {type: sphere, radius: 1.0}
    material: {name: Cu, m: 0.3}
lights: [{type: directional, direction: [0, -1, 1]}]
"""

CT = ["cook-torrance", "--m", "0.3", "--incidence", "30", "--angles", "0"]
PHONG = ["phong", "--incidence", "30", "--angles", "0"]

# (arguments, what the message must name)
BAD = [
    # reflectance colour
    (["colour", "Cu", "--angle", "nan"], "--angle"),
    (["colour", "Cu", "--angle", "inf"], "--angle"),
    (["colour", "Cu", "--angle", "-1"], "--angle"),
    (["colour", "Cu", "--angle", "91"], "--angle"),
    (["colour", "Cu", "--angle", "ten"], "--angle"),
    (["colour", "Cu", "--angle", "0", "--average-range", "nan", "780"], "--average-range"),
    (["colour", "Cu", "--angle", "0", "--average-range", "700", "400"], "--average-range"),
    (["colour", "Cu", "--angle", "0", "--average-range", "-5", "780"], "--average-range"),
    (["colour", "../x/Cu", "--angle", "0"], "material '../x/Cu' is not a name"),
    (["colour", "/etc/passwd", "--angle", "0"], "material '/etc/passwd' is not a name"),
    (["colour", "..", "--angle", "0"], "material '..' is not a name"),
    (["colour", "sub\\Cu", "--angle", "0"], "is not a name"),
    # reflectance brdf
    (["brdf", *CT, "--n", "nan"], "--n"),
    (["brdf", *CT, "--n", "1e160"], "--n"),
    (["brdf", *CT, "--n", "0"], "--n"),
    (["brdf", *CT, "--n", "-1.5"], "--n"),
    (["brdf", *CT, "--n", "1.5", "--k", "nan"], "--k"),
    (["brdf", *CT, "--n", "1.5", "--k", "-1"], "--k"),
    (["brdf", *CT, "--n", "1.5", "--s", "1.5"], "--s"),
    (["brdf", *CT, "--n", "1.5", "--s", "-0.1"], "--s"),
    (["brdf", *CT, "--n", "1.5", "--s", "nan"], "--s"),
    (["brdf", *CT, "--n", "1.5", "--d", "2"], "--d"),
    (["brdf", "cook-torrance", "--n", "1.5", "--m", "nan", "--incidence", "30", "--angles", "0"], "--m"),
    (["brdf", "cook-torrance", "--n", "1.5", "--m", "0", "--incidence", "30", "--angles", "0"], "--m"),
    (["brdf", "cook-torrance", "--n", "1.5", "--m", "1e300", "--incidence", "30", "--angles", "0"], "--m"),
    (["brdf", "cook-torrance", "--n", "1.5", "--c3", "0", "--incidence", "30", "--angles", "0"], "--c3"),
    (["brdf", "cook-torrance", "--n", "1.5", "--c3", "1.5", "--incidence", "30", "--angles", "0"], "--c3"),
    (["brdf", *PHONG, "--c1", "-5"], "--c1"),
    (["brdf", *PHONG, "--c1", "nan"], "--c1"),
    (["brdf", *PHONG, "--c1", "inf"], "--c1"),
    (["brdf", *PHONG, "--beta", "0"], "--beta"),
    (["brdf", *PHONG, "--beta", "90"], "--beta"),
    (["brdf", *PHONG, "--beta", "-inf"], "--beta"),
    (["brdf", "lambert", "--incidence", "nan", "--angles", "0"], "--incidence"),
    (["brdf", "lambert", "--incidence", "90", "--angles", "0"], "--incidence"),
    (["brdf", "lambert", "--incidence", "30", "--angles", "0", "nan"], "--angles"),
    (["brdf", "lambert", "--incidence", "30", "--angles", "95"], "--angles"),
    (["brdf", *PHONG, "--azimuth", "inf"], "--azimuth"),
    (["brdf", "heidrich-seidel", "--incidence", "30", "--angles", "0", "--fibre-azimuth", "nan"],
     "--fibre-azimuth"),
    (["brdf", "lambert", "--incidence", "30", "--angles", "0", "--material", "../spectra/Cu"],
     "is not a name"),
    # reflectance render (numbers; output paths below)
    (["render", "s.yaml", "-o", "out.exr", "--width", "0"], "--width"),
    (["render", "s.yaml", "-o", "out.exr", "--height", "-1"], "--height"),
    (["render", "s.yaml", "-o", "out.exr", "--width", "2.5"], "--width"),
    (["render", "s.yaml", "-o", "out.exr", "--supersample", "0"], "--supersample"),
    (["render", "s.yaml", "-o", "out.exr", "--supersample", "100"], "--supersample"),
    (["render", "s.yaml", "-o", "afile/out.exr"], "-o afile/out.exr: afile is a file"),
    (["render", "s.yaml", "-o", "out.exr", "--png", "afile/out.png"], "--png afile/out.png"),
    (["render", "s.yaml", "-o", "out.exr", "--png", "s.yaml/sub/out.png"], "--png"),
    (["render", "s.yaml", "-o", "folder.exr"], "is a folder"),
    # reflectance bench
    (["bench", "--sizes", "0"], "--sizes"),
    (["bench", "--sizes", "64", "nan"], "--sizes"),
    (["bench", "--runs", "0"], "--runs"),
    (["bench", "--supersample", "-2"], "--supersample"),
    (["bench", "--brute-force-runs", "-1"], "--brute-force-runs"),
    (["bench", "--grids", "0"], "--grids"),
    (["bench", "--grids", "nan"], "--grids"),
    (["bench", "--grid-size", "0"], "--grid-size"),
    # issue 25: sizes counted before anything is made, one line naming the option
    (["audit", "Cu", "--wavelengths", "360", "830", "1e-7"], "--wavelengths: 1e-07 nm from 360 to 830 nm makes"),
    (["audit", "Cu", "--angle", "0", "10", "--wavelengths", "400", "700", "1e-8"], "--wavelengths: 1e-08 nm"),
    (["bench", "--grids", "5", "1e-6"], "--grids: 1e-06 nm at --grid-size 512 makes"),
    (["bench", "--sizes", "64", "16384"], "--sizes 16384, --supersample 2: the ID buffer would be"),
    # --spectra-dir, a folder that does not exist, in every command that looks a material up
    *[(args + ["--spectra-dir", "nope"], "--spectra-dir: no such folder 'nope'")
      for args in (["colour", "Cu", "--angle", "0"], ["spectra"],
                   ["brdf", "lambert", "--material", "Cu", "--incidence", "0", "--angles", "0"],
                   ["render", "s.yaml", "-o", "out.exr"], ["bench", "--sizes", "8"],
                   ["audit", "Cu", "--angle", "0"])],
]

# --config files: (file content, what the message must name besides the file)
BAD_CONFIGS = [
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 0}\n", "wavelengths.step_nm"),
    ("wavelengths: {start_nm: 360, end_nm: 830}\n", "step_nm"),
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: five}\n", "wavelengths.step_nm"),
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: .nan}\n", "wavelengths.step_nm"),
    ("wavelengths: {start_nm: 830, end_nm: 360, step_nm: 5}\n", "start_nm"),
    ("wavelengths: [360, 830, 5]\n", "wavelengths"),
    ("colour: {space: sRGB}\n", "wavelengths"),
    ("- just\n- a list\n", "wavelengths"),
    ("wavelengths: {start_nm: 360\n", "not valid YAML"),
    # issue 25: a grid too fine to make; YAML that grows when read; a key given twice
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 1.0e-8}\n", "wavelengths.step_nm: 1e-08 nm"),
    ('x0: &a ["lol"]\n' + "".join(f"x{i}: &{chr(97 + i)} [{', '.join([f'*{chr(96 + i)}'] * 9)}]\n"
                                   for i in range(1, 9))
     + "wavelengths: {start_nm: 360, end_nm: 830, step_nm: 5}\n", "its aliases expand it"),
    ("x: " + "[" * 3000 + "]" * 3000 + "\nwavelengths: {start_nm: 360, end_nm: 830, step_nm: 5}\n",
     "nested more than 64 levels deep"),
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 5}\nwavelengths: {start_nm: 400}\n",
     "key 'wavelengths' given twice"),
]


@pytest.fixture
def workdir(tmp_path, monkeypatch, root):
    """A folder holding a scene, a regular file 'afile' and a folder 'folder.exr'; the spectra
    are the project's (by --spectra-dir)."""
    (tmp_path / "s.yaml").write_text(SCENE)
    (tmp_path / "afile").write_text("x")
    (tmp_path / "folder.exr").mkdir()
    monkeypatch.chdir(tmp_path)
    return tmp_path


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def refused(args, root):
    """Run the command in-process; return its message. A traceback would fail the test here."""
    with_spectra = args + (["--spectra-dir", str(root / "spectra")] if args[0] != "bench" else [])
    with pytest.raises(SystemExit) as info:
        main(with_spectra)
    code = info.value.code
    assert isinstance(code, str), f"exit code {code!r}: a refusal exits with status 1 and a message"
    return code


@pytest.mark.parametrize("args, named", BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_option_is_refused_naming_it(args, named, workdir, root):
    before = listing(workdir)
    message = refused(args, root)
    assert named in message
    assert "\n" not in message.strip()
    assert listing(workdir) == before  # nothing written


@pytest.mark.parametrize("content, named", BAD_CONFIGS, ids=[c[:60] for c, _ in BAD_CONFIGS])
def test_bad_config_is_refused_naming_file_and_key(content, named, workdir, root):
    (workdir / "bad.yaml").write_text(content)
    before = listing(workdir)
    message = refused(["colour", "Cu", "--angle", "0", "--config", "bad.yaml"], root)
    assert "--config bad.yaml" in message and named in message
    assert "\n" not in message.strip()
    assert listing(workdir) == before


def test_missing_and_binary_config_files(workdir, root):
    assert "no such file" in refused(["colour", "Cu", "--angle", "0", "--config", "nope.yaml"], root)
    (workdir / "bin.yaml").write_bytes(b"\xff\xfe\x00\x81binary")
    message = refused(["colour", "Cu", "--angle", "0", "--config", "bin.yaml"], root)
    assert "--config bin.yaml" in message and "\n" not in message.strip()


def test_the_checks_do_not_refuse_good_values(workdir, root, capsys):
    """The ranges' ends that are allowed give finite numbers (the types are not too strict)."""
    import io

    import numpy as np
    import pandas as pd

    for args in (["brdf", "cook-torrance", "--n", "1000", "--k", "1000", "--m", "0.001",
                  "--incidence", "0", "--angles", "-90", "0", "90"],
                 ["brdf", "cook-torrance", "--n", "1.5", "--c3", "0.001", "--incidence", "89.9",
                  "--angles", "-90", "0", "90"],
                 ["brdf", "torrance-sparrow", "--n", "1.5", "--beta", "0.1", "--incidence", "30",
                  "--angles", "-90", "30", "90"],
                 ["brdf", "phong", "--beta", "0.1", "--incidence", "30", "--angles", "30"],
                 ["brdf", "phong", "--c1", "10000", "--s", "0", "--d", "1", "--incidence", "30",
                  "--angles", "30"]):
        assert main(args) in (0, None)
        table = pd.read_csv(io.StringIO(capsys.readouterr().out))
        assert np.isfinite(table.drop(columns="theta_out_deg").to_numpy()).all(), args


def test_failed_png_leaves_no_exr(workdir, root, monkeypatch):
    """A PNG that cannot be written: one line naming the file, and neither image is left (nor an
    earlier EXR replaced)."""
    import reflectance.render.pipeline as pipeline

    def fail(path, *args, **kwargs):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(pipeline, "write_png", fail)
    (workdir / "old.exr").write_bytes(b"earlier")
    before = listing(workdir)
    for exr in ("out.exr", "old.exr"):
        message = refused(["render", "s.yaml", "-o", exr, "--png", "out.png", "--quiet"], root)
        assert "cannot write" in message and "--png out.png" in message and "nothing written" in message
        assert listing(workdir) == before
    assert (workdir / "old.exr").read_bytes() == b"earlier"


#: the command line, in a process that first makes sure it is not root (root may write anywhere)
AS_A_USER = ("import os, sys\n"
             "assert os.geteuid() != 0, 'still root: the refusal would not be tested'\n"
             "from reflectance.cli import main\n"
             "sys.exit(main())\n")


def unprivileged(command):
    """``command`` as an unprivileged user runs it: unchanged unless the tests run as root (CI
    does), else under setpriv (util-linux) as the user nobody, with no supplementary groups."""
    if os.geteuid() != 0:
        return command
    import pwd
    import shutil

    setpriv = shutil.which("setpriv")
    if setpriv is None:
        if os.environ.get("CI"):  # as tests/conftest.py reads it: CI must not skip this quietly
            pytest.fail("the tests run as root, and setpriv (util-linux), which runs the check "
                        "as the user nobody, is not installed")
        pytest.skip("root may write into any folder, and setpriv is not installed")
    nobody = pwd.getpwnam("nobody")
    return [setpriv, f"--reuid={nobody.pw_uid}", f"--regid={nobody.pw_gid}", "--clear-groups",
            *command]


def test_unwritable_folder_is_refused_before_rendering():
    """An output in a folder the user may not write into is refused, naming the option and the
    folder, before the scene is read: one line, exit status 1, no progress (nothing rendered),
    nothing written. An unprivileged process of its own (as root: the user nobody), in a folder
    outside pytest's (which only root may enter)."""
    import shutil
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix="reflectance-unwritable-"))
    try:
        folder.chmod(0o755)  # nobody may enter it and read the scene, not write
        (folder / "s.yaml").write_text(SCENE)
        (folder / "ro").mkdir()
        (folder / "ro").chmod(0o555)
        proc = subprocess.run(unprivileged([sys.executable, "-c", AS_A_USER, "render", "s.yaml",
                                            "-o", "ro/out.exr"]),
                              cwd=folder, capture_output=True, text=True, timeout=300,
                              env=dict(os.environ, HOME=str(folder)))
        assert proc.returncode == 1, proc.stderr
        # the refusal itself: not the failed write that rendering first would end in
        assert proc.stderr == "reflectance: -o ro/out.exr: cannot write in folder ro\n"
        assert proc.stdout == "" and listing(folder / "ro") == []
    finally:
        if (folder / "ro").exists():
            (folder / "ro").chmod(0o755)  # (a folder of its own user may be removed only so)
        shutil.rmtree(folder)


@pytest.mark.parametrize("move, warning", [
    ("position: [0, -0.2, 0]", "probably inside it"),  # inside the unit sphere
    ("look_at: [0, -10, 0]", "sees no object"),        # looking away from it
])
def test_camera_inside_an_object_or_empty_view_warns(workdir, root, capsys, move, warning):
    key = move.split(":")[0]
    original = "position: [0, -5, 0]" if key == "position" else "look_at: [0, 0, 0]"
    (workdir / "odd.yaml").write_text(SCENE.replace(original, move))
    assert main(["render", "odd.yaml", "-o", "odd.exr", "--quiet", "--spectra-dir",
                 str(root / "spectra")]) == 0
    err = capsys.readouterr().err
    assert warning in err and "camera at position" in err and "odd.yaml" in err
    assert main(["render", "s.yaml", "-o", "ok.exr", "--quiet", "--spectra-dir",
                 str(root / "spectra")]) == 0
    assert "warning" not in capsys.readouterr().err  # the ordinary view does not warn


@pytest.mark.parametrize("args, named", [
    (["colour", "Cu", "--angle", "nan"], "--angle"),
    (["colour", "../x/Cu", "--angle", "0"], "is not a name"),
    (["brdf", *PHONG, "--c1", "-5"], "--c1"),
    (["render", "s.yaml", "-o", "afile/out.exr"], "-o afile/out.exr"),
])
def test_as_a_process_exit_status_1_and_one_line(args, named, workdir, root):
    proc = subprocess.run([sys.executable, "-m", "reflectance.cli", *args, "--spectra-dir",
                           str(root / "spectra")], capture_output=True, text=True, cwd=workdir,
                          env=dict(os.environ, PYTHONPATH=str(root / "workflow")))
    assert proc.returncode == 1
    assert named in proc.stderr and "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and proc.stdout == ""


def test_implicit_config_yaml(workdir, root, capsys):
    """./config.yaml is used when present: someone else's file without ``wavelengths`` falls back
    to the built-in grid (as documented), a broken grid in it is refused naming it."""
    (workdir / "config.yaml").write_text("other: 1\n")
    assert main(["colour", "Cu", "--angle", "0", "--spectra-dir", str(root / "spectra")]) in (0, None)
    assert capsys.readouterr().out.startswith("angle_deg,")
    (workdir / "config.yaml").write_text("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 0}\n")
    message = refused(["colour", "Cu", "--angle", "0"], root)
    assert "--config config.yaml: wavelengths.step_nm" in message
