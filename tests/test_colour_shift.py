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


def _integrate(wavelengths, F):
    """colour-science's own integration of D65 x F(lambda), scaled so that D65 itself has Y = 1."""
    sd = colour.SpectralDistribution(dict(zip(wavelengths, F)))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(wavelengths[0], wavelengths[-1], 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    return colour.sd_to_XYZ(sd, cmfs, d65, method="Integration") / 100


def _fresnel_complex_snell(N, ci):
    """Unpolarised Fresnel reflectance from the complex Snell law (not the paper's form)."""
    ct = np.sqrt(1 - (1 - ci**2) / N**2 + 0j)
    rs = (ci - N * ct) / (ci + N * ct)
    rp = (N * ci - ct) / (N * ci + ct)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def _fresnel_dielectric_as_printed(n, c):
    """Cook & Torrance 1982, "Spectral composition", written out again for the test:
    F = 1/2 (g - c)^2 / (g + c)^2 {1 + [c (g + c) - 1]^2 / [c (g - c) + 1]^2}, g^2 = n^2 + c^2 - 1."""
    g = np.sqrt(n**2 + c**2 - 1)
    return 0.5 * (g - c) ** 2 / (g + c) ** 2 * (1 + (c * (g + c) - 1) ** 2 / (c * (g - c) + 1) ** 2)


def _brute_force_XYZ(copper, theta_deg):
    """Independent: colour's own integration of D65 x F(lambda) with F from complex Snell."""
    N = copper.n + 1j * copper.k
    return _integrate(copper.wavelengths, _fresnel_complex_snell(N, np.cos(np.radians(theta_deg))))


def _F0(copper):
    return abs((copper.n + 1j * copper.k - 1) / (copper.n + 1j * copper.k + 1)) ** 2


def _approximation_XYZ(copper, theta_deg, F=_fresnel_dielectric_as_printed, range_nm=(380, 780)):
    """Fig. 5c from the paper's text alone: F of the index that matches the average normal
    reflectance over 380-780 nm (k = 0), interpolating each component between the colour at
    normal incidence and the light's colour: C_0 + (C_90 - C_0) max(0, F_theta - F_0)/(1 - F_0)."""
    wl, F0 = copper.wavelengths, _F0(copper)
    F0_mean = F0[(wl >= range_nm[0]) & (wl <= range_nm[1])].mean()
    n = (1 + np.sqrt(F0_mean)) / (1 - np.sqrt(F0_mean))
    C_0, C_90 = _integrate(wl, F0), _integrate(wl, np.ones_like(wl))
    t = max(0.0, F(n, np.cos(np.radians(theta_deg))) - F0_mean) / (1 - F0_mean)
    return C_0 + (C_90 - C_0) * t


def _fitted_XYZ(copper, theta_deg):
    """The k = 0 fit per wavelength, n = (1 + sqrt F0)/(1 - sqrt F0), through complex Snell."""
    F0 = _F0(copper)
    n = (1 + np.sqrt(F0)) / (1 - np.sqrt(F0))
    return _integrate(copper.wavelengths, _fresnel_complex_snell(n + 0j, np.cos(np.radians(theta_deg))))


def _dE2000(XYZ, XYZ_reference, copper):
    white_xy = colour.XYZ_to_xy(_integrate(copper.wavelengths, np.ones_like(copper.wavelengths)))
    return colour.delta_E(colour.XYZ_to_Lab(XYZ, white_xy), colour.XYZ_to_Lab(XYZ_reference, white_xy),
                          method="CIE 2000")


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


ANGLES_5C = [30, 40, 50, 60, 70, 75, 80, 85]


@pytest.mark.parametrize("theta", ANGLES_5C)
def test_fig5c_approximation_matches_the_papers_formula(copper, W, theta):
    got = colour_XYZ(copper, np.cos(np.radians(theta)), W, "approximation", (380, 780))
    np.testing.assert_allclose(got, _approximation_XYZ(copper, theta), rtol=1e-9, atol=1e-12)


def test_fig5c_check_tells_the_papers_fresnel_from_schlicks(copper):
    """The comparison above fails if the dielectric F is replaced by Schlick's approximation."""
    def schlick(n, c):
        return ((n - 1) / (n + 1)) ** 2 + (1 - ((n - 1) / (n + 1)) ** 2) * (1 - c) ** 5

    for theta in ANGLES_5C:
        paper, other = _approximation_XYZ(copper, theta), _approximation_XYZ(copper, theta, schlick)
        assert np.max(abs(paper - other) / abs(paper)) > 1e-6, theta  # 1000x the tolerance


def test_table_columns_and_dE(copper, W):
    angles = [0, *ANGLES_5C, 90]
    t = colour_table(copper, angles, W, methods=("exact", "fitted", "approximation"))
    assert list(t.columns) == ["method", "angle_deg", "X", "Y", "Z", "x", "y", "dominant_nm",
                               "purity", "R", "G", "B", "dE2000_vs_exact"]
    independent = {"exact": _brute_force_XYZ, "fitted": _fitted_XYZ,
                   "approximation": _approximation_XYZ}
    for m, XYZ_of in independent.items():
        part = t[t.method == m].set_index("angle_deg")
        for theta in angles:
            XYZ = XYZ_of(copper, theta)
            np.testing.assert_allclose(part.loc[theta, ["X", "Y", "Z"]].to_numpy(float), XYZ,
                                       rtol=1e-8, atol=1e-12)
            expected = _dE2000(XYZ, _brute_force_XYZ(copper, theta), copper)
            assert part.loc[theta, "dE2000_vs_exact"] == pytest.approx(expected, rel=1e-6, abs=1e-9)
    assert t[["R", "G", "B"]].to_numpy().min() >= 0 and t[["R", "G", "B"]].to_numpy().max() <= 1
    # copper is orange-red at normal incidence: dominant wavelength between 580 and 610 nm
    assert 580 < t[(t.method == "exact") & (t.angle_deg == 0)].dominant_nm.iloc[0] < 610


def test_bad_angles_are_refused(copper, W):
    with pytest.raises(ValueError, match="angles"):
        colour_table(copper, [0, 95], W)


# --- Fig. 5c: why the approximation keeps copper's colour until near grazing ---------------------

def _fresnel_sin_tan(theta, n):
    """The unpolarised dielectric Fresnel reflectance, sin/tan form (Blinn 1977; C&T 1982 eq.)."""
    theta = np.asarray(theta, dtype=float)
    t = np.arcsin(np.sin(theta) / n)
    with np.errstate(invalid="ignore", divide="ignore"):
        F = 0.5 * (np.sin(theta - t) ** 2 / np.sin(theta + t) ** 2
                   + np.tan(theta - t) ** 2 / np.tan(theta + t) ** 2)
    return np.where(theta == 0, ((n - 1) / (n + 1)) ** 2, F)


def test_fig5c_onset_by_hand(root, tmp_path):
    """Run the Fig. 5b/5c script; its onset numbers and strip against an independent recomputation."""
    import runpy
    from types import SimpleNamespace

    import pandas as pd
    import yaml
    from scipy.optimize import brentq

    config = yaml.safe_load((root / "config.yaml").read_text())
    fig = config["figures"]["cook_torrance_1982"]["fig5"]
    from pathlib import Path

    from reflectance.papers.figures import figure, params_of

    # every output the rule declares, by the figure's own definition, in tmp_path
    declared = figure("ct82_fig5bc").outputs(params_of(figure("ct82_fig5bc"), config))
    out = {k: str(tmp_path / f"{k}{Path(v).suffix}") for k, v in declared.items()}
    snakemake = SimpleNamespace(
        params=SimpleNamespace(fig=fig, colour=config["colour"], wavelengths=config["wavelengths"]),
        input=SimpleNamespace(spectrum=str(root / "spectra" / f"{fig['material']}.csv")),
        output=SimpleNamespace(**out), log=[str(tmp_path / "log.txt")], rule="ct82_fig5bc")
    runpy.run_path(str(root / "workflow" / "scripts" / "cook_torrance_1982_fig5bc.py"),
                   init_globals={"snakemake": snakemake})
    row = pd.read_csv(out["approximation"]).iloc[0]

    # By hand: copper's normal reflectance from its n, k on the config grid, averaged over the range.
    from reflectance.optics.spectra import wavelength_grid

    grid = wavelength_grid(**config["wavelengths"])
    cu = load_material(fig["material"], grid, spectra_dir=root / "spectra")
    lo, hi = fig["average_F0_range_nm"]
    inside = (grid >= lo) & (grid <= hi)
    F0 = np.mean(((cu.n - 1) ** 2 + cu.k**2)[inside] / ((cu.n + 1) ** 2 + cu.k**2)[inside])
    n = (1 + np.sqrt(F0)) / (1 - np.sqrt(F0))
    assert row.F0_average == pytest.approx(F0, rel=1e-6)
    assert row.n_average == pytest.approx(n, rel=1e-6)
    excess = lambda deg: float(_fresnel_sin_tan(np.radians(deg), n)) - F0  # noqa: E731
    angles = np.linspace(0, 89.999, 90000)
    values = _fresnel_sin_tan(np.radians(angles), n) - F0
    assert row.dip == pytest.approx(values.min(), abs=1e-6)
    assert row.dip_deg == pytest.approx(angles[np.argmin(values)], abs=2e-3)
    onset = brentq(excess, angles[np.argmin(values)], 89.99999)
    assert row.onset_deg == pytest.approx(onset, abs=1e-6)
    assert 89.0 < onset < 89.5  # the "about 89.2 degrees"
    half = brentq(lambda d: excess(d) / (1 - F0) - 0.5, onset, 89.99999)
    assert row["t_0.5_deg"] == pytest.approx(half, abs=1e-6)

    # The strip: (c) is exactly the 0-degree colour below the onset, and moves away above it.
    strip = pd.read_csv(out["strip"])
    c = strip[strip.method == "approximation"]
    zero = c[c.angle_deg == 0][["X", "Y", "Z"]].to_numpy()[0]
    below, above = c[c.angle_deg < onset - 1e-3], c[c.angle_deg > onset + 0.05]
    assert len(below) > 300 and len(above) >= 50
    np.testing.assert_allclose(below[["X", "Y", "Z"]].to_numpy(), np.broadcast_to(zero, (len(below), 3)),
                               rtol=1e-5)
    assert np.all(np.abs(above.Y.to_numpy() - zero[1]) > 1e-4)
    # fine sampling from fine_from_deg to 90, proportional angles as written
    fine = c[c.angle_deg >= fig["strip"]["fine_from_deg"]].angle_deg.to_numpy()
    assert np.allclose(np.diff(fine), fig["strip"]["fine_step_deg"], atol=1e-5)
    assert fine[-1] == 90
