"""Cook & Torrance 1982 Fig. 5: colour of copper vs angle, exact and approximated."""

import colour
import numpy as np
import pytest

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.audit.colour_shift import (
    colour_interpolation_CookTorrance1982,
    colour_table,
    colour_XYZ,
)
from reflectance.optics.spectra import load_material


@pytest.fixture(scope="module")
def copper(root, grid):
    return load_material("Cu", grid, spectra_dir=root / "spectra")


@pytest.fixture(scope="module")
def W(grid):
    return tristimulus_weights(grid, "D65", "CIE 1931 2 Degree Standard Observer")


def _brute_force_XYZ(copper, theta_deg):
    """Independent: colour's own integration of D65 x F(lambda) with F from complex Snell."""
    N = copper.n + 1j * copper.k
    ci = np.cos(np.radians(theta_deg))
    si2 = 1 - ci**2
    ct = np.sqrt(1 - si2 / N**2 + 0j)
    rs = (ci - N * ct) / (ci + N * ct)
    rp = (N * ci - ct) / (N * ci + ct)
    F = (abs(rs) ** 2 + abs(rp) ** 2) / 2
    sd = colour.SpectralDistribution(dict(zip(copper.wavelengths, F)))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(copper.wavelengths[0], copper.wavelengths[-1], 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    return colour.sd_to_XYZ(sd, cmfs, d65, method="Integration") / 100


@pytest.mark.parametrize("theta", [0.0, 45.0, 80.0, 89.0])
def test_exact_colour_matches_colour_science_integration(copper, W, theta):
    got = colour_XYZ(copper, np.cos(np.radians(theta)), W, "exact")
    np.testing.assert_allclose(got, _brute_force_XYZ(copper, theta), rtol=1e-9, atol=1e-12)


def test_grazing_colour_is_the_light(copper, W):
    for method in ("exact", "approximation", "fitted", "schlick", "f82"):
        np.testing.assert_allclose(colour_XYZ(copper, 0.0, W, method), W.sum(axis=0), atol=1e-12)


def test_normal_incidence_of_every_shortcut_is_exact(copper, W):
    exact = colour_XYZ(copper, 1.0, W, "exact")
    for method in ("approximation", "fitted", "schlick", "f82"):
        np.testing.assert_allclose(colour_XYZ(copper, 1.0, W, method), exact, rtol=1e-12)


def test_interpolation_formula_per_component():
    # C&T 1982 p. 13 written out for a red component by hand.
    red0, red90, F0, Ft = 0.7, 1.0, 0.3, 0.65
    got = colour_interpolation_CookTorrance1982([red0, 0, 0], [red90, 0, 0], Ft, F0)
    assert got[0] == pytest.approx(red0 + (red90 - red0) * (Ft - F0) / (1 - F0))
    # max(0, .): F below F0 leaves the normal-incidence colour.
    assert colour_interpolation_CookTorrance1982([red0, 0, 0], [1, 0, 0], 0.1, F0)[0] == red0


def test_table_columns_and_dE(copper, W):
    t = colour_table(copper, [0, 60, 85, 90], W, methods=("exact", "fitted", "approximation"))
    assert list(t.columns) == ["method", "angle_deg", "X", "Y", "Z", "x", "y", "dominant_nm",
                               "purity", "R", "G", "B", "dE2000_vs_exact"]
    assert np.all(t[t.method == "exact"].dE2000_vs_exact.abs() < 1e-9)
    # shortcuts are exact at 0 and 90 degrees and differ in between
    for m in ("fitted", "approximation"):
        part = t[t.method == m].set_index("angle_deg")
        assert part.loc[0.0, "dE2000_vs_exact"] < 1e-6
        assert part.loc[90.0, "dE2000_vs_exact"] < 1e-6
        assert part.loc[85.0, "dE2000_vs_exact"] > 0.01
    assert t[["R", "G", "B"]].to_numpy().min() >= 0 and t[["R", "G", "B"]].to_numpy().max() <= 1
    # copper is orange-red at normal incidence: dominant wavelength between 580 and 610 nm
    assert 580 < t[(t.method == "exact") & (t.angle_deg == 0)].dominant_nm.iloc[0] < 610


def test_bad_angles_are_refused(copper, W):
    with pytest.raises(ValueError, match="angles"):
        colour_table(copper, [0, 95], W)
