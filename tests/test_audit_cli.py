"""`reflectance audit`: every Fresnel shortcut against exact, for a bundled name or a CSV file.

The numbers are checked against an independent computation: the Fresnel equations written here in
their textbook s/p form (complex Snell's law), colour-science's own ``sd_to_XYZ`` (not the project's
tristimulus weights), ``XYZ_to_Lab`` and ``delta_E``.
"""

import csv
import functools
import io
import json
import os
import shutil
import site
import subprocess
import sys
from pathlib import Path

import colour
import numpy as np
import pytest

from reflectance.cli import main

GRID = np.arange(360, 831, 5.0)
CMFS = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
    colour.SpectralShape(360, 830, 5))
D65 = colour.SDS_ILLUMINANTS["D65"].copy().align(CMFS.shape)


def audit(args, capsys):
    main(["audit", *args])
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    return rows


def pick(rows, method, angle):
    (row,) = [r for r in rows if r["method"] == method and float(r["angle_deg"]) == angle]
    return {k: (v if k in TEXT_COLUMNS else float(v or "nan")) for k, v in row.items()}


#: the columns of text; the others are numbers
TEXT_COLUMNS = ("material", "kind", "illuminant", "observer", "method")
#: half a unit of the last decimal printed (CIELAB and the differences: 4 decimals), and a margin
PRINTED_4 = 0.5e-4 + 1e-9


def read_nk(path):
    with open(path) as f:
        data = np.array([[float(v) for v in row] for row in list(csv.reader(f))[1:]])
    return data[:, 0], data[:, 1], data[:, 2]


def fresnel_textbook(theta, N):
    """Unpolarised reflectance from air onto index N = n + ik (Hecht, Optics, 4.4 and 4.6)."""
    ci, si = np.cos(theta), np.sin(theta)
    ct = np.sqrt(1 - (si / N) ** 2)   # complex Snell's law
    rs = (ci - N * ct) / (ci + N * ct)
    rp = (N * ci - ct) / (N * ci + ct)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def XYZ_colour_science(F):
    sd = colour.SpectralDistribution(dict(zip(GRID, F)))
    return colour.sd_to_XYZ(sd, CMFS, D65, method="Integration") / 100


@pytest.fixture(scope="module")
def copper(root):
    wl, n, k = read_nk(root / "spectra" / "Cu.csv")
    return np.interp(GRID, wl, n) + 1j * np.interp(GRID, wl, k)


@pytest.mark.parametrize("angle", [0.0, 60.0, 85.0])
def test_audit_matches_colour_science(copper, angle, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # the bundled spectra, not ./spectra
    rows = audit(["Cu", "--angle", str(angle), "--methods", "exact", "fitted", "schlick"], capsys)
    theta = np.radians(angle)
    F0 = abs((copper - 1) / (copper + 1)) ** 2
    n_fit = (1 + np.sqrt(F0)) / (1 - np.sqrt(F0))    # Cook & Torrance's k = 0 fit
    spectra = {"exact": fresnel_textbook(theta, copper),
               "fitted": fresnel_textbook(theta, n_fit + 0j),
               "schlick": F0 + (1 - F0) * (1 - np.cos(theta)) ** 5}
    white = XYZ_colour_science(np.ones_like(GRID))
    white_xy = colour.XYZ_to_xy(white)
    lab_exact = colour.XYZ_to_Lab(XYZ_colour_science(spectra["exact"]), white_xy)
    for method, F in spectra.items():
        row = pick(rows, method, angle)
        XYZ = XYZ_colour_science(F)
        assert [row["X"], row["Y"], row["Z"]] == pytest.approx(XYZ, rel=1e-6, abs=1e-9)
        lab = colour.XYZ_to_Lab(XYZ, white_xy)
        assert [row["L"], row["a"], row["b"]] == pytest.approx(lab, abs=PRINTED_4 + 1e-5)
        dE = colour.delta_E(lab, lab_exact, method="CIE 2000")
        assert row["dE2000_vs_exact"] == pytest.approx(dE, abs=PRINTED_4 + 1e-5)
        assert (row["illuminant"], row["observer"]) == ("D65", "CIE 1931 2 Degree Standard "
                                                                "Observer")
    if angle == 85.0:  # the fit drifts at grazing: a colour difference anyone sees
        assert pick(rows, "fitted", angle)["dE2000_vs_exact"] > 2


def test_every_method_and_the_default_angles(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    rows = audit(["Au"], capsys)
    methods = list(dict.fromkeys(r["method"] for r in rows))
    assert methods == ["exact", "approximation", "fitted", "schlick", "f82", "gulbrandsen", "rgb"]
    angles = [float(r["angle_deg"]) for r in rows if r["method"] == "exact"]
    assert angles[0] == 0 and angles[-1] == 89 and np.all(np.diff(angles) > 0)
    assert np.diff(angles)[-1] == 1 < np.diff(angles)[0]  # finer near grazing
    for column in ("method", "angle_deg", "X", "Y", "Z", "x", "y", "L", "a", "b", "dominant_nm",
                   "dE2000_vs_exact", "dE_CAM16UCS_vs_exact"):
        assert column in rows[0]
    for angle in angles:  # every method is exact at normal incidence, apart from rgb's clipping
        for method in methods[:-1]:
            assert pick(rows, method, 0)["dE2000_vs_exact"] < 1e-6
    # Schlick is linear in F0, so per-channel Schlick equals spectral Schlick once F0's colour
    # is inside the gamut; gold's F0 is not (in sRGB), and the clip shows at 0 degrees.
    assert pick(rows, "rgb", 0)["dE2000_vs_exact"] > 0.5
    # F82 pins F at cos = 1/7 (81.8 degrees): closer to exact than Schlick there
    assert pick(rows, "f82", 82)["dE2000_vs_exact"] < pick(rows, "schlick", 82)["dE2000_vs_exact"]


def test_rgb_equals_schlick_inside_the_gamut(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    rows = audit(["Ag", "--angle", "30", "70", "--methods", "schlick", "rgb"], capsys)
    for angle in (30, 70):
        a, b = pick(rows, "schlick", angle), pick(rows, "rgb", angle)
        assert [a["X"], a["Y"], a["Z"]] == pytest.approx([b["X"], b["Y"], b["Z"]], rel=1e-6)


def write_um_forms(root, tmp_path):
    wl, n, k = read_nk(root / "spectra" / "Cu.csv")
    one = tmp_path / "cu_refractiveindex.csv"
    one.write_text("wl,n,k\n" + "".join(f"{w / 1000:.9g},{a},{b}\n" for w, a, b in zip(wl, n, k)))
    two = tmp_path / "cu_two_blocks.csv"
    two.write_text("wl,n\n" + "".join(f"{w / 1000:.9g},{a}\n" for w, a in zip(wl, n))
                   + "wl,k\n" + "".join(f"{w / 1000:.9g},{b}\n" for w, b in zip(wl, k)))
    return one, two


def test_refractiveindex_info_files_in_micrometres(root, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    bundled = audit(["Cu", "--angle", "0", "80", "--methods", "exact", "fitted"], capsys)
    for path in write_um_forms(root, tmp_path):
        rows = audit([str(path), "--angle", "0", "80", "--methods", "exact", "fitted"], capsys)
        assert rows[0]["material"] == path.stem and rows[0]["kind"] == "measured"
        for a, b in zip(bundled, rows):
            assert float(a["X"]) == pytest.approx(float(b["X"]), rel=1e-7)
            assert float(a["dE2000_vs_exact"]) == pytest.approx(float(b["dE2000_vs_exact"]),
                                                               abs=1e-6)


def test_reflectance_spectrum_is_audited_with_k_zero(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "grey.csv"
    path.write_text("wavelength_nm,reflectance\n300,0.5\n900,0.5\n")
    rows = audit([str(path), "--angle", "0", "70", "--methods", "exact", "fitted"], capsys)
    assert {r["kind"] for r in rows} == {"derived"}  # as Material.kind and sources.csv say
    assert pick(rows, "exact", 0)["Y"] == pytest.approx(0.5, abs=1e-8)  # flat: Y = F0
    # k = 0 and n from F0: exact is the fit itself
    assert pick(rows, "fitted", 70)["dE2000_vs_exact"] == pytest.approx(0, abs=1e-9)
    # n = (1 + sqrt .5)/(1 - sqrt .5), textbook Fresnel at 70 degrees, flat spectrum: Y = F
    n = (1 + np.sqrt(0.5)) / (1 - np.sqrt(0.5))
    assert pick(rows, "exact", 70)["Y"] == pytest.approx(
        fresnel_textbook(np.radians(70), n + 0j), rel=1e-7)


def test_illuminant_file_and_observer(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    spd = tmp_path / "a.csv"
    A = colour.SDS_ILLUMINANTS["A"].copy().align(CMFS.shape)
    spd.write_text("wavelength_nm,power\n" + "".join(
        f"{w:g},{v!r}\n" for w, v in zip(A.wavelengths, A.values)))
    by_name = audit(["Cu", "--angle", "60", "--illuminant", "A"], capsys)
    by_file = audit(["Cu", "--angle", "60", "--illuminant", str(spd)], capsys)
    assert [r["X"] for r in by_name] == [r["X"] for r in by_file]
    ten = audit(["Cu", "--angle", "60", "--observer", "10"], capsys)
    two = audit(["Cu", "--angle", "60", "--observer", "2"], capsys)
    assert ten[0]["x"] != two[0]["x"]


def test_spectra_dir_adds_materials(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "Mine.csv").write_text("wavelength_nm,n,k\n300,1.5,0\n900,1.5,0\n")
    rows = audit(["Mine", "--angle", "0", "--spectra-dir", str(tmp_path / "mine")], capsys)
    assert float(rows[0]["Y"]) == pytest.approx(0.04, abs=1e-9)  # ((1.5 - 1)/(1.5 + 1))^2
    rows = audit(["Cu", "--angle", "0", "--spectra-dir", str(tmp_path / "mine")], capsys)
    assert rows[0]["material"] == "Cu"  # the bundled ones stay available
    bundled_Y = float(rows[0]["Y"])
    # a folder's own Cu hides the bundled one; repeated, the folders are searched in order
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "Cu.csv").write_text("wavelength_nm,n,k\n300,3,0\n900,3,0\n")
    (tmp_path / "other" / "Mine.csv").write_text("wavelength_nm,n,k\n300,2,0\n900,2,0\n")
    for folders, material, Y in ((["mine", "other"], "Cu", 0.25), (["mine", "other"], "Mine", 0.04),
                                 (["other", "mine"], "Mine", 1 / 9)):
        dirs = [a for folder in folders for a in ("--spectra-dir", str(tmp_path / folder))]
        rows = audit([material, "--angle", "0", "--methods", "exact", *dirs], capsys)
        assert float(rows[0]["Y"]) == pytest.approx(Y, rel=1e-7)  # (8 significant digits)
    assert bundled_Y != pytest.approx(0.25, abs=0.01)


def test_output_folder_gets_csv_and_figure(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "out" / "cu"
    main(["audit", "Cu", "--angle", "0", "45", "85", "-o", str(out)])
    printed = capsys.readouterr().out
    assert (out / "audit.csv").read_text() == printed
    assert (out / "audit.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in out.iterdir()) == ["audit.csv", "audit.pdf", "audit.png",
                                                     "audit_metadata.yaml"]


BAD = "bad.csv"


@pytest.mark.parametrize("args, files, says", [
    (["Unobtainium"], {}, ["unknown material 'Unobtainium'", "Cu", "Au"]),
    (["nothing.csv"], {}, ["nothing.csv", "no such file"]),
    ([BAD], {BAD: "lambda,n,k\n400,1,1\n500,1,1\n"},
     [BAD, "line 1 (header)", "'wavelength_nm,n,k'", "'wl,n,k'"]),
    ([BAD], {BAD: "wavelength_nm,n,k\n400,1,1\n500,one,1\n"},
     [BAD, "data row 2 (line 3)", "'one' is not a number"]),
    ([BAD], {BAD: "wl,n,k\n400,1,1\n500,1,1\n"}, [BAD, "micrometres", "wavelength_nm"]),
    ([BAD], {BAD: b"\xff\xfe\x00garbage"}, [BAD, "not a UTF-8 text file"]),
    ([BAD], {BAD: "wavelength_nm,n,k\n400,1,1\n700,1,1\n"},
     [BAD, "360-830 nm leaves the data range 400-700 nm"]),
    (["Cu", "--methods", "exact", "phong"], {}, ["unknown method(s) phong", "schlick, f82"]),
    (["Cu", "--illuminant", "D66"], {}, ["unknown illuminant 'D66'", "D65", "FL2"]),
    (["Cu", "--illuminant", "spd.csv"], {"spd.csv": "wavelength_nm,power\n400,1\n700,1\n"},
     ["spd.csv", "covers 400-700 nm"]),
    (["Cu", "--observer", "5"], {}, ["unknown observer '5'", "2, 10"]),
    (["Cu", "--angle", "95"], {}, ["--angle", "[0, 90]"]),
    (["Cu", "--space", "P3"], {}, ["unknown display space 'P3'", "sRGB"]),
    (["Cu", "--spectra-dir", "nope"], {}, ["--spectra-dir: no such folder 'nope'"]),
])
def test_bad_input_one_line_nothing_written(args, files, says, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for name, text in files.items():
        (tmp_path / name).write_bytes(text if isinstance(text, bytes) else text.encode())
    with pytest.raises(SystemExit) as err:
        main(["audit", *args, "-o", "out"])
    message = str(err.value.code)
    assert message.startswith("reflectance: ") and "\n" not in message
    for part in says:
        assert part in message, message
    assert not (tmp_path / "out").exists()
    assert capsys.readouterr().out == ""


def test_bad_input_exits_1_from_the_shell(tmp_path):
    result = subprocess.run([sys.executable, "-m", "reflectance.cli", "audit", "Unobtainium"],
                            cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "known: " in result.stderr


# --- the installed wheel: every command that needs no workflow, in any folder -----------------

#: the tests that take the installed wheel's runs (``start_with_session`` starts them if any is
#: selected)
INSTALLED_TESTS = ("test_installed_package_works_in_any_folder",
                   "test_installed_render_and_bench_work_in_any_folder",
                   "test_installed_readme_blocks_run_in_any_folder")

#: each command run from the installed wheel, in an empty folder of its own: name -> its
#: arguments after `reflectance` (render and bench as small and short as their options allow)
INSTALLED_COMMANDS = {
    "audit": ["audit", "Cu", "--angle", "0"],
    "colour": ["colour", "Cu", "--angle", "0", "60"],
    "brdf": ["brdf", "cook-torrance", "--material", "Cu", "--m", "0.3", "--incidence", "30",
             "--angles", "-30", "0", "30"],
    "spectra": ["spectra"],
    "render": ["render", "scenes/example_spheres.yaml", "-o", "spheres.exr", "--png",
               "spheres.png", "--width", "32", "--height", "20", "--quiet"],
    "bench": ["bench", "--sizes", "16", "--runs", "1", "--brute-force-runs", "0", "--grids",
              "--reference-supersample", "0", "--crosscheck-size", "0", "--json", "--quiet"],
}


def start_with_session(runs, root, tmp_path_factory, items):
    """The wheel's build, install and runs start with the session, on its pool
    (tests/conftest.py's ``early`` calls this), if one of :data:`INSTALLED_TESTS` is selected:
    they need nothing of the session's build, and so overlap the other tests; the tests take
    their results."""
    if any(item.originalname in INSTALLED_TESTS for item in items):
        _start_installed(runs, root, tmp_path_factory)


def _start_installed(runs, root, tmp_path_factory):
    if not runs.started("installed"):
        runs.start("installed", _installed, runs, root, tmp_path_factory.mktemp("installed"))
        # once installed, each command (and the guides' blocks) on the pool, side by side
        for name in (*INSTALLED_COMMANDS, "readme"):
            runs.after("installed", f"installed {name}", _installed_run, runs, name, root)


def _run(runs, args, timeout, **kwargs):
    """``args`` as a process of the pool: the finished process (its output captured)."""
    return runs.run(args, timeout=timeout, **kwargs)


def _installed(runs, root, tmp_path):
    """A wheel built from a copy of the project and installed into a fresh venv, which gets
    this environment's packages (not its editable reflectance) from a .pth file: the venv's
    paths, the environment its commands run in, and an empty folder outside the checkout."""
    src = tmp_path / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md", "config.yaml"):
        shutil.copy(root / name, src / name)
    shutil.copytree(root / "spectra", src / "spectra")
    shutil.copytree(root / "workflow" / "reflectance", src / "workflow" / "reflectance",
                    symlinks=True, ignore=shutil.ignore_patterns("__pycache__"))
    wheels = tmp_path / "wheels"
    built = _run(runs, [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w",
                        str(wheels), str(src)], timeout=600)
    if built.returncode != 0:
        pytest.skip(f"cannot build a wheel here: {built.stderr.strip().splitlines()[-1:]}")
    venv = tmp_path / "venv"
    made = _run(runs, [sys.executable, "-m", "venv", "--without-pip", str(venv)], timeout=300)
    assert made.returncode == 0, made.stdout + made.stderr
    python = venv / "bin" / "python"
    # the wheel alone first (pip then sees no other reflectance), from this environment's pip
    installed = _run(runs, [sys.executable, "-m", "pip", "--python", str(python), "install",
                            "--no-deps", "--no-index", "-q", *map(str, wheels.glob("*.whl"))],
                     timeout=600)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    asked = _run(runs, [str(python), "-c",
                        "import sysconfig; print(sysconfig.get_path('purelib'))"], timeout=300)
    assert asked.returncode == 0, asked.stderr
    site_dir = Path(asked.stdout.strip())
    # this environment's dependencies as plain path lines: site does not run the .pth files of
    # a folder named so, so the editable reflectance's (which points at the checkout) stays out
    (site_dir / "test-environment.pth").write_text(
        "".join(f"{folder}\n" for folder in site.getsitepackages()))
    ours = str(Path(sys.executable).parent)  # this environment's scripts: not on the venv's PATH
    path = [venv / "bin", *(p for p in runs.environ.get("PATH", "").split(os.pathsep)
                            if p and p != ours)]
    env = {k: v for k, v in runs.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env.update(PATH=os.pathsep.join(map(str, path)), VIRTUAL_ENV=str(venv))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    return {"venv": venv, "site": site_dir, "env": env, "elsewhere": elsewhere}


def _installed_run(installed, runs, name, root):
    """Command ``name`` of :data:`INSTALLED_COMMANDS` (the venv's `reflectance` script), or
    the guides' blocks that README's quick start moved to (``"readme"``: workflow/docs/guides/
    python.rst and rendering.rst), in an empty folder of its own outside the checkout."""
    from test_readme import QUICK_START, RENDER_GUIDE, quick_start, shell_commands

    folder = installed["elsewhere"] / name
    folder.mkdir()
    run = functools.partial(_run, runs, timeout=600, env=installed["env"])
    if name == "readme":
        paths, command = quick_start(root / QUICK_START, folder,
                                     str(installed["venv"] / "bin" / "python"))
        quick = paths, run(command, cwd=folder)
        return quick, [(block, run(command, cwd=block))
                       for block, command in shell_commands(root / RENDER_GUIDE, folder)]
    if name == "render":  # a scene file of the checkout, copied: the folder is not the checkout
        (folder / "scenes").mkdir()
        shutil.copy(root / "workflow" / "scenes" / "example_spheres.yaml", folder / "scenes")
    where = run([str(installed["venv"] / "bin" / "python"), "-c",
                 "import reflectance; print(reflectance.__file__)"], cwd=folder)
    command = [str(installed["venv"] / "bin" / "reflectance"), *INSTALLED_COMMANDS[name]]
    return folder, where.stdout.strip(), run(command, cwd=folder)


def _installed_result(early, root, tmp_path_factory, name):
    """(folder, where reflectance was imported from, finished process) of ``name``, run from
    the installed wheel (``_installed_run``)."""
    _start_installed(early, root, tmp_path_factory)  # (``early`` did, unless run without it)
    installed = early.result("installed")
    folder, where, proc = early.result(f"installed {name}")
    assert proc.returncode == 0, proc.stderr
    # the installed copy, not the checkout, in a folder outside it
    assert Path(where).is_relative_to(installed["site"]), where
    assert not folder.is_relative_to(root)
    return folder, proc


def csv_rows(proc):
    return list(csv.DictReader(io.StringIO(proc.stdout)))


def test_installed_package_works_in_any_folder(root, early, tmp_path_factory):
    """Build a wheel from a copy of the project, install it into a fresh venv (dependencies
    from this environment) and run each command in an empty folder: the spectra, the scene
    schema and the config come with the package, as files, not links. The build, install and
    runs (``_installed``, ``_installed_run``) start with the session; taken here."""
    _, audit = _installed_result(early, root, tmp_path_factory, "audit")
    site_dir = early.result("installed")["site"]
    data = site_dir / "reflectance" / "data"
    for path in (data / "spectra", data / "spectra" / "Cu.csv", data / "scene.schema.yaml",
                 data / "config.yaml"):
        assert path.exists() and not path.is_symlink(), path
    assert (data / "config.yaml").read_bytes() == (root / "config.yaml").read_bytes()
    # PEP 561: a type checker reads the installed package's annotations
    assert (site_dir / "reflectance" / "py.typed").is_file()
    rows = csv_rows(audit)
    assert rows[0]["material"] == "Cu" and float(rows[0]["Y"]) > 0.5
    _, colour_ = _installed_result(early, root, tmp_path_factory, "colour")
    rows = csv_rows(colour_)
    assert [float(r["angle_deg"]) for r in rows] == [0, 60]
    assert float(rows[0]["x"]) > 0.33 and float(rows[0]["Y"]) == pytest.approx(
        float(csv_rows(audit)[0]["Y"]), rel=1e-5)  # copper's reddish normal colour, as audit's
    _, brdf = _installed_result(early, root, tmp_path_factory, "brdf")
    total = [float(r["total"]) for r in csv_rows(brdf)]
    assert len(total) == 3 and max(range(3), key=total.__getitem__) == 2  # the mirror: +30
    _, spectra = _installed_result(early, root, tmp_path_factory, "spectra")
    listed = {r["material"]: r for r in csv_rows(spectra)}
    assert {"Cu", "Au", "Ag"} <= set(listed) and listed["Cu"]["kind"] == "measured"


def test_installed_render_and_bench_work_in_any_folder(root, early, tmp_path_factory):
    """`reflectance render` of a scene file (its schema from the package, its materials the
    bundled spectra) and `reflectance bench` (its default scene from the package's config.yaml:
    the Fig. 6b vase), from the installed wheel."""
    from PIL import Image

    from reflectance.io.images import read_exr

    folder, _ = _installed_result(early, root, tmp_path_factory, "render")
    with Image.open(folder / "spheres.png") as im:
        assert im.size == (32, 20)
    XYZ, _ = read_exr(folder / "spheres.exr")
    assert XYZ.shape == (20, 32, 3) and XYZ[..., 1].max() > 0.05
    _, bench = _installed_result(early, root, tmp_path_factory, "bench")
    (result,) = json.loads(bench.stdout)
    assert result["size"] == 16 and result["lights"] == 2 and result["wavelengths"] == 95
    assert result["triangles"] > 100_000  # the vase (221,408 triangles at config.yaml's sampling)
    assert result["hit_samples"] > 0 and result["total_s"] > 0


def test_installed_readme_blocks_run_in_any_folder(root, early, tmp_path_factory):
    """The guides' quick-start blocks (Python) and render block (bash) run as written from the
    installed wheel, each in an empty folder outside the checkout, with what the prose says."""
    from test_readme import check_quick_start, check_render_block

    _start_installed(early, root, tmp_path_factory)
    (paths, quick), shells = early.result("installed readme")
    assert not paths[0].is_relative_to(root)
    check_quick_start(paths, quick)
    assert shells, "the rendering guide has no block marked to run"
    for block, proc in shells:
        check_render_block(block, proc)
