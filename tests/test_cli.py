"""The `reflectance` command line."""

import io
import json
import shutil
import subprocess
import sys
from pathlib import Path

import colour
import numpy as np
import pandas as pd
import pytest

from reflectance.cli import main


def run_cli(args, capsys):
    main(args)
    return capsys.readouterr().out


def _copper_XYZ(root, cos_theta, fitted=False):
    """Independent: D65 x F(lambda) of copper integrated by colour-science (white Y = 1), F from
    the complex Snell law with the committed n, k (or Cook & Torrance's k = 0 fit to F0)."""
    data = pd.read_csv(root / "spectra" / "Cu.csv")
    wl = np.arange(360, 831, 5.0)
    N = np.interp(wl, data.wavelength_nm, data.n) + 1j * np.interp(wl, data.wavelength_nm, data.k)
    if fitted:
        root_F0 = abs((N - 1) / (N + 1))
        N = (1 + root_F0) / (1 - root_F0) + 0j
    ct = np.sqrt(1 - (1 - cos_theta**2) / N**2 + 0j)
    rs = (cos_theta - N * ct) / (cos_theta + N * ct)
    rp = (N * cos_theta - ct) / (N * cos_theta + ct)
    F = (abs(rs) ** 2 + abs(rp) ** 2) / 2
    sd = colour.SpectralDistribution(dict(zip(wl, F)))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(360, 830, 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    white = colour.sd_to_XYZ(colour.sd_ones(cmfs.shape), cmfs, d65, method="Integration") / 100
    return colour.sd_to_XYZ(sd, cmfs, d65, method="Integration") / 100, colour.XYZ_to_xy(white)


def test_colour_prints_the_table(root, capsys, monkeypatch):
    monkeypatch.chdir(root)
    out = run_cli(["colour", "Cu", "--angle", "0", "80"], capsys)
    t = pd.read_csv(io.StringIO(out))
    assert list(t.columns) == ["angle_deg", "X", "Y", "Z", "x", "y", "dominant_nm", "purity",
                               "R", "G", "B", "dE2000_vs_exact"]
    assert list(t.angle_deg) == [0, 80]
    for i, theta in enumerate((0, 80)):
        XYZ, _ = _copper_XYZ(root, np.cos(np.radians(theta)))
        # the CLI prints 6 significant digits
        np.testing.assert_allclose(t.loc[i, ["X", "Y", "Z"]].to_numpy(float), XYZ, rtol=1e-5)


def test_colour_fitted_differs_near_grazing(root, capsys, monkeypatch):
    """dE2000 of the k = 0 fit against the exact colour, as colour-science computes it."""
    monkeypatch.chdir(root)
    t = pd.read_csv(io.StringIO(run_cli(
        ["colour", "Cu", "--angle", "0", "80", "--fresnel", "fitted"], capsys)))
    for i, theta in enumerate((0, 80)):
        c = np.cos(np.radians(theta))
        (exact, white_xy), (fitted, _) = _copper_XYZ(root, c), _copper_XYZ(root, c, fitted=True)
        dE = colour.delta_E(colour.XYZ_to_Lab(fitted, white_xy), colour.XYZ_to_Lab(exact, white_xy),
                            method="CIE 2000")
        assert t.dE2000_vs_exact[i] == pytest.approx(dE, rel=1e-4, abs=1e-5)
        np.testing.assert_allclose(t.loc[i, ["X", "Y", "Z"]].to_numpy(float), fitted, rtol=1e-5)
    assert t.dE2000_vs_exact[1] > 100 * 1e-5  # at 80 degrees the fit is visibly off


def test_unknown_material_lists_known(root, monkeypatch):
    monkeypatch.chdir(root)
    with pytest.raises(SystemExit) as err:
        main(["colour", "Unobtainium", "--angle", "0"])
    assert "Unobtainium" in str(err.value) and "Cu" in str(err.value)


def test_spectra_lists_materials(root, capsys, monkeypatch):
    monkeypatch.chdir(root)
    t = pd.read_csv(io.StringIO(run_cli(["spectra"], capsys)))
    assert {"Cu", "Au", "Ag"} <= set(t.material)
    assert set(t.kind) <= {"measured", "derived"}


def test_console_script_help():
    out = subprocess.run([sys.executable, "-m", "reflectance.cli", "colour", "--help"],
                         capture_output=True, text=True, check=True).stdout
    for option in ("--angle", "--fresnel", "--illuminant", "--space"):
        assert option in out


def test_colour_and_spectra_work_outside_the_checkout(tmp_path):
    """With no ./spectra, the commands read the spectra that ship with the package."""
    import subprocess
    import sys

    run = [sys.executable, "-m", "reflectance"]
    here = subprocess.run(run + ["colour", "Cu", "--angle", "0"], cwd=tmp_path,
                          capture_output=True, text=True)
    assert here.returncode == 0, here.stderr
    header, row = here.stdout.splitlines()
    values = dict(zip(header.split(","), row.split(",")))
    # copper's normal-incidence colour is reddish: x above D65's 0.3127
    assert float(values["x"]) > 0.33
    listed = subprocess.run(run + ["spectra"], cwd=tmp_path, capture_output=True, text=True)
    assert listed.returncode == 0 and "\nCu," in listed.stdout
    # a --spectra-dir is searched first and hides nothing it does not hold: an empty folder
    # leaves copper the bundled one
    (tmp_path / "empty").mkdir()
    again = subprocess.run(run + ["colour", "Cu", "--angle", "0", "--spectra-dir", "empty"],
                           cwd=tmp_path, capture_output=True, text=True)
    assert again.returncode == 0 and again.stdout == here.stdout, again.stderr


# --- the one lookup of a material name: --spectra-dir folders (in order), then the bundled ----

def flat(folder, name, n):
    """A material of constant index n (k = 0): F0 = ((n - 1)/(n + 1))^2 at every wavelength."""
    folder.mkdir(exist_ok=True)
    (folder / f"{name}.csv").write_text(f"wavelength_nm,n,k\n300,{n},0\n900,{n},0\n")


def colour_Y(args, capsys):
    table = pd.read_csv(io.StringIO(run_cli(["colour", *args, "--angle", "0"], capsys)))
    return float(table.Y[0])


def test_colour_and_brdf_search_the_folders_in_order_then_the_bundled(root, tmp_path, capsys,
                                                                      monkeypatch):
    monkeypatch.chdir(tmp_path)
    flat(tmp_path / "a", "Cu", 1.5)    # hides the bundled copper
    flat(tmp_path / "b", "Cu", 2.0)    # hidden by a
    flat(tmp_path / "b", "Mine", 3.0)
    dirs = ["--spectra-dir", "a", "--spectra-dir", "b"]
    # a flat spectrum at normal incidence: Y = F0 (the white has Y = 1)
    assert colour_Y(["Cu", *dirs], capsys) == pytest.approx(0.04, rel=1e-5)
    assert colour_Y(["Mine", *dirs], capsys) == pytest.approx(0.25, rel=1e-5)
    assert colour_Y(["Cu", "--spectra-dir", "b", "--spectra-dir", "a"], capsys) == \
        pytest.approx(1 / 9, rel=1e-5)
    exact, _ = _copper_XYZ(root, 1.0)  # no folder: the bundled copper, the project's Cu.csv
    assert colour_Y(["Cu"], capsys) == pytest.approx(exact[1], rel=1e-5)
    # Au is in neither folder: the bundled gold, as without them
    assert run_cli(["colour", "Au", "--angle", "0", "60", *dirs], capsys) == \
        run_cli(["colour", "Au", "--angle", "0", "60"], capsys)
    # brdf --material takes the same lookup: Y = total cos(incidence) (its epilog), and a
    # Lambertian of albedo F0 = 0.04 has total = 0.04/pi
    brdf = pd.read_csv(io.StringIO(run_cli(["brdf", "lambert", "--material", "Cu", *dirs,
                                            "--incidence", "0", "--angles", "0"], capsys)))
    assert brdf.total[0] == pytest.approx(0.04 / np.pi, rel=1e-5)


def test_spectra_lists_what_each_name_finds(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    flat(tmp_path / "mine", "Cu", 1.5)
    (tmp_path / "mine" / "Paint.csv").write_text("wavelength_nm,reflectance\n300,0.2\n900,0.4\n")
    t = pd.read_csv(io.StringIO(run_cli(["spectra", "--spectra-dir", "mine"], capsys)),
                    keep_default_na=False)
    rows = t.set_index("material")
    assert list(t.material[:2]) == ["Cu", "Paint"]  # the folder's first, then the bundled
    assert list(t.material).count("Cu") == 1          # the bundled copper is hidden
    assert rows.loc["Cu", "kind"] == "measured" and rows.loc["Paint", "kind"] == "derived"
    assert rows.loc["Cu", "dataset"] == f"file {Path('mine') / 'Cu.csv'}"
    assert {"Au", "Ag"} <= set(t.material) and rows.loc["Au", "reference"] != ""


def test_render_in_a_fresh_folder_and_a_scenes_own_file(root, tmp_path, capsys, monkeypatch):
    """No ./spectra: the names come from the bundled spectra (--spectra-dir adds folders in
    front, hiding none it lacks), a material file from beside the scene file."""
    from reflectance.io.images import read_exr

    monkeypatch.chdir(tmp_path)
    (tmp_path / "scenes" / "mats").mkdir(parents=True)
    shutil.copy(root / "spectra" / "Cu.csv", tmp_path / "scenes" / "mats" / "my_copper.csv")
    flat(tmp_path / "mine", "Other", 1.5)
    images = {}
    for label, material, extra in (("named", {"name": "Cu"}, []),
                                   ("file", {"file": "mats/my_copper.csv"}, []),
                                   ("named, a folder in front", {"name": "Cu"},
                                    ["--spectra-dir", "mine"])):
        scene = tmp_path / "scenes" / "s.yaml"
        scene.write_text(SCENE.format(material=json.dumps({**material, "m": 0.3})))
        out = tmp_path / f"{len(images)}.exr"
        assert main(["render", "scenes/s.yaml", "-o", str(out), "--quiet", *extra]) == 0
        images[label], _ = read_exr(out)
    assert images["named"].max() > 0.05  # the copper sphere is lit
    # the same data by name, by file and with a folder in front: the same image
    np.testing.assert_array_equal(images["file"], images["named"])
    np.testing.assert_array_equal(images["named, a folder in front"], images["named"])


def test_render_refuses_a_bad_material_file_naming_it_and_its_key(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "s.yaml").write_text(SCENE.format(material='{"file": "../x.csv", "m": 0.3}'))
    (tmp_path / "bad.yaml").write_text(SCENE.format(material='{"file": "bad.csv", "m": 0.3}'))
    (tmp_path / "bad.csv").write_text("lambda,n,k\n400,1,1\n500,1,1\n")
    for scene, says in (("s.yaml", "'../x.csv' leaves the scene file's folder"),
                        ("bad.yaml", "bad.csv, line 1 (header)")):
        with pytest.raises(SystemExit) as err:
            main(["render", scene, "-o", "out.exr", "--quiet"])
        assert f"{scene}: objects[0].material.file: " in str(err.value.code)
        assert says in str(err.value.code)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.csv", "bad.yaml", "s.yaml"]


SCENE = """\
camera: {{position: [0, -5, 0], look_at: [0, 0, 0], fov_deg: 30, width: 12, height: 8}}
objects:
  - geometry: {{type: sphere, radius: 1.0}}
    material: {material}
lights: [{{type: directional, direction: [0, -1, 1]}}]
"""


def test_top_level_help_says_which_commands_print_csv(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "Each command prints CSV" not in text
    assert "colour, spectra, brdf and audit print CSV" in text
    assert "render writes images" in text and "bench prints a timing report" in text


def _stdin(monkeypatch, data):
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(data)))


def test_audit_reads_a_spectrum_from_standard_input(root, capsys, monkeypatch, tmp_path):
    """`reflectance audit -`: the same numbers as the same file named, the material 'stdin', and
    -o's metadata naming standard input with the hash of the bytes read."""
    import hashlib

    import yaml

    data = (root / "spectra" / "Cu.csv").read_bytes()
    named = run_cli(["audit", str(root / "spectra" / "Cu.csv"), "--angle", "0", "70"], capsys)
    _stdin(monkeypatch, data)
    piped = run_cli(["audit", "-", "--angle", "0", "70", "-o", str(tmp_path)], capsys)
    assert piped.splitlines()[0] == named.splitlines()[0]
    assert [line.split(",", 1)[1] for line in piped.splitlines()[1:]] == \
        [line.split(",", 1)[1] for line in named.splitlines()[1:]]
    assert all(line.startswith("stdin,") for line in piped.splitlines()[1:])
    source = yaml.safe_load((tmp_path / "audit_metadata.yaml").read_text())["input"]
    assert source["file"] == "- (standard input)"
    assert source["sha256"] == hashlib.sha256(data).hexdigest()
    # bad input on standard input is named as such, in one line
    _stdin(monkeypatch, b"wavelength_nm,reflectance\n400,abc\n500,0.2\n")
    with pytest.raises(SystemExit) as err:
        main(["audit", "-"])
    assert str(err.value.code).startswith("reflectance: <standard input>")


def test_audit_refuses_a_spectrum_on_standard_input_past_the_bound(monkeypatch):
    """A stream that never ends (or a huge one) on standard input: read one byte past the bound
    and refused in one line, not read to the end."""
    from reflectance.optics.spectra import MAX_SPECTRUM_BYTES

    header = b"wavelength_nm,reflectance\n"
    _stdin(monkeypatch, header + b"5" * (MAX_SPECTRUM_BYTES + 1 - len(header)))
    with pytest.raises(SystemExit) as err:
        main(["audit", "-"])
    message = str(err.value.code)
    assert message.startswith("reflectance: <standard input>: larger than ") and "\n" not in message
    assert f"{MAX_SPECTRUM_BYTES:,} bytes" in message


def test_render_exposure_stops_scale_the_automatic_exposure(tmp_path, capsys, monkeypatch):
    """--exposure-stops S is the automatic exposure times 2**S (0: the automatic one itself);
    --exposure is an absolute factor; the two are refused together. The scene read from standard
    input (`render -`) gives the same image as the file."""
    from reflectance.io.images import read_exr

    monkeypatch.chdir(tmp_path)
    scene = tmp_path / "s.yaml"
    scene.write_text(SCENE.format(material=json.dumps({"name": "Cu", "m": 0.3})))
    scales = {}
    for label, extra in (("auto", []), ("0", ["--exposure-stops", "0"]),
                         ("+1", ["--exposure-stops", "1"]), ("-2.5", ["--exposure-stops", "-2.5"]),
                         ("absolute", ["--exposure", "0.75"])):
        out = tmp_path / f"{label}.exr"
        assert main(["render", "s.yaml", "-o", str(out), "--quiet", *extra]) == 0
        XYZ, header = read_exr(out)
        scales[label] = float(header["display_exposure_scale"])
    assert scales["auto"] > 0
    assert scales["0"] == pytest.approx(scales["auto"], rel=1e-12)
    assert scales["+1"] == pytest.approx(2 * scales["auto"], rel=1e-12)
    assert scales["-2.5"] == pytest.approx(scales["auto"] / 2 ** 2.5, rel=1e-12)
    assert scales["absolute"] == 0.75
    with pytest.raises(SystemExit) as err:
        main(["render", "s.yaml", "-o", "x.exr", "--exposure", "1", "--exposure-stops", "1"])
    assert "argument --exposure-stops: not allowed with argument --exposure" in str(err.value.code)
    _stdin(monkeypatch, scene.read_bytes())
    assert main(["render", "-", "-o", str(tmp_path / "stdin.exr"), "--quiet"]) == 0
    np.testing.assert_array_equal(read_exr(tmp_path / "stdin.exr")[0],
                                  read_exr(tmp_path / "auto.exr")[0])
