"""The `reflectance` command line."""

import io
import subprocess
import sys

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
    # an explicit --spectra-dir is honoured (an empty folder knows no materials)
    (tmp_path / "empty").mkdir()
    none = subprocess.run(run + ["colour", "Cu", "--angle", "0", "--spectra-dir", "empty"],
                          cwd=tmp_path, capture_output=True, text=True)
    assert none.returncode == 1 and "unknown material 'Cu'" in none.stderr
