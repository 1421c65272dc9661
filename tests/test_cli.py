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


def test_colour_prints_the_table(root, capsys, monkeypatch):
    monkeypatch.chdir(root)
    out = run_cli(["colour", "Cu", "--angle", "0", "80"], capsys)
    t = pd.read_csv(io.StringIO(out))
    assert list(t.columns) == ["angle_deg", "X", "Y", "Z", "x", "y", "dominant_nm", "purity",
                               "R", "G", "B", "dE2000_vs_exact"]
    assert list(t.angle_deg) == [0, 80]
    # Independent check of Y at normal incidence: D65-weighted mean of copper's F0 with ybar,
    # F0 = |(N - 1)/(N + 1)|^2 from the committed n, k, integrated by colour-science.
    data = pd.read_csv(root / "spectra" / "Cu.csv")
    wl = np.arange(360, 831, 5.0)
    N = np.interp(wl, data.wavelength_nm, data.n) + 1j * np.interp(wl, data.wavelength_nm, data.k)
    F0 = abs((N - 1) / (N + 1)) ** 2
    sd = colour.SpectralDistribution(dict(zip(wl, F0)))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(360, 830, 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    Y = colour.sd_to_XYZ(sd, cmfs, d65, method="Integration")[1] / 100
    assert t.Y[0] == pytest.approx(Y, rel=1e-5)
    assert t.dE2000_vs_exact.abs().max() < 1e-6  # --fresnel exact against itself


def test_colour_fitted_differs_near_grazing(root, capsys, monkeypatch):
    monkeypatch.chdir(root)
    t = pd.read_csv(io.StringIO(run_cli(
        ["colour", "Cu", "--angle", "0", "80", "--fresnel", "fitted"], capsys)))
    assert t.dE2000_vs_exact[0] < 1e-4 and t.dE2000_vs_exact[1] > 0.01


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
