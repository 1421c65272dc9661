"""`reflectance audit`: every Fresnel shortcut against exact, for a bundled name or a CSV file.

The numbers are checked against an independent computation: the Fresnel equations written here in
their textbook s/p form (complex Snell's law), colour-science's own ``sd_to_XYZ`` (not the project's
tristimulus weights), ``XYZ_to_Lab`` and ``delta_E``.
"""

import csv
import io
import shutil
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
    return {k: (v if k in ("material", "kind", "method") else float(v or "nan"))
            for k, v in row.items()}


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
        assert [row["L"], row["a"], row["b"]] == pytest.approx(lab, abs=1e-5)
        dE = colour.delta_E(lab, lab_exact, method="CIE 2000")
        assert row["dE2000_vs_exact"] == pytest.approx(dE, abs=1e-5)
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
        assert rows[0]["material"] == path.stem and rows[0]["kind"] == "nk"
        for a, b in zip(bundled, rows):
            assert float(a["X"]) == pytest.approx(float(b["X"]), rel=1e-7)
            assert float(a["dE2000_vs_exact"]) == pytest.approx(float(b["dE2000_vs_exact"]),
                                                               abs=1e-6)


def test_reflectance_spectrum_is_audited_with_k_zero(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "grey.csv"
    path.write_text("wavelength_nm,reflectance\n300,0.5\n900,0.5\n")
    rows = audit([str(path), "--angle", "0", "70", "--methods", "exact", "fitted"], capsys)
    assert {r["kind"] for r in rows} == {"reflectance_k0"}
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
    assert sorted(p.name for p in out.iterdir()) == ["audit.csv", "audit.pdf", "audit.png"]


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


def start_with_session(runs, root, tmp_path_factory, items):
    """The wheel's build, install and run start with the session, on its pool
    (tests/conftest.py's ``early`` calls this), if the test is selected: they need nothing of the
    session's build, and so overlap the other tests; the test takes their result."""
    if any(item.originalname == "test_installed_package_works_in_any_folder" for item in items):
        _start_installed(runs, root, tmp_path_factory)


def _start_installed(runs, root, tmp_path_factory):
    if not runs.started("installed"):
        runs.start("installed", _installed, runs, root, tmp_path_factory.mktemp("installed"))


def _run(runs, args, timeout, **kwargs):
    """``args`` as a process of the pool: the finished process (its output captured)."""
    return runs.run(args, timeout=timeout, **kwargs)


def _installed(runs, root, tmp_path):
    """A wheel built from a copy of the project, installed alone (--target), its command run in
    an empty folder: (the install folder, the command's finished process)."""
    src = tmp_path / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(root / name, src / name)
    shutil.copytree(root / "spectra", src / "spectra")
    shutil.copytree(root / "workflow" / "reflectance", src / "workflow" / "reflectance",
                    symlinks=True, ignore=shutil.ignore_patterns("__pycache__"))
    wheels = tmp_path / "wheels"
    built = _run(runs, [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w",
                        str(wheels), str(src)], timeout=600)
    if built.returncode != 0:
        pytest.skip(f"cannot build a wheel here: {built.stderr.strip().splitlines()[-1:]}")
    site = tmp_path / "site"
    installed = _run(runs, [sys.executable, "-m", "pip", "install", "--no-deps", "-q", "--target",
                            str(site), *map(str, wheels.glob("*.whl"))], timeout=600)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = dict(runs.environ, PYTHONPATH=str(site))
    result = _run(runs, [sys.executable, "-c", "import sys, reflectance, reflectance.cli as c; "
                         "print(reflectance.__file__, file=sys.stderr); sys.exit(c.main())",
                         "audit", "Cu", "--angle", "0"], timeout=300, cwd=elsewhere, env=env)
    return site, result


def test_installed_package_works_in_any_folder(root, early, tmp_path_factory):
    """Build a wheel from a copy of the project, install it alone (dependencies from this
    environment) and run the command in an empty folder: the spectra come with the package.
    The build, install and run (``_installed``) start with the session; taken here."""
    _start_installed(early, root, tmp_path_factory)  # (``early`` did, unless run without it)
    site, result = early.result("installed")
    assert result.returncode == 0, result.stderr
    assert str(site) in result.stderr  # the installed copy, not the checkout
    assert not (site / "reflectance" / "data" / "spectra").is_symlink()
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    assert rows[0]["material"] == "Cu" and float(rows[0]["Y"]) > 0.5
