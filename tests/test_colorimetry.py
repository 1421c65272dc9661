"""Tests of reflectance.colour.colorimetry against colour-science and published CIE / ASTM values."""

import colour
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.colour.colorimetry import (
    OBSERVER_DEFAULT,
    cmfs,
    dominant_wavelength,
    illuminant_range_nm,
    cmfs_wavelengths,
    illuminant_sd,
    spectrum_to_XYZ,
    tristimulus_weights,
    white_XYZ,
)

OBSERVER_10 = "CIE 1964 10 Degree Standard Observer"
GRIDS = [(360, 830, 5), (380, 780, 10), (400, 700, 1)]


def grid(start, end, step):
    return np.arange(start, end + step / 2, step, dtype=np.float64)


def smooth_spectra(wl, n, seed):
    """Random smooth reflectances in [0, 1]: sums of broad Gaussian bumps."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(380, 780, (n, 3, 1))
    widths = rng.uniform(20, 120, (n, 3, 1))
    heights = rng.uniform(0, 1, (n, 3, 1))
    S = (heights * np.exp(-0.5 * ((wl - centres) / widths) ** 2)).sum(axis=1)
    return S / np.maximum(S.max(axis=-1, keepdims=True), 1.0)


def dataset_spectra(wl):
    """ColorChecker (Ohta) and CIE test colour samples (Munsell samples), aligned like colour."""
    shape = colour.SpectralShape(wl[0], wl[-1], wl[1] - wl[0])
    sds = list(colour.SDS_COLOURCHECKERS["ColorChecker N Ohta"].values())
    sds += list(colour.quality.SDS_TCS["CIE 1995"].values())[:14]
    return np.array([sd.copy().align(shape).values for sd in sds])


def colour_XYZ(S, wl, illuminant, observer):
    """colour-science's own "Integration" sum on the same grid, scaled to Y(white) = 1."""
    shape = colour.SpectralShape(wl[0], wl[-1], wl[1] - wl[0])
    cmfs_aligned = colour.MSDS_CMFS[observer].copy().align(shape)
    illuminant_aligned = colour.SDS_ILLUMINANTS[illuminant].copy().align(shape)
    return np.array([
        colour.sd_to_XYZ(
            colour.SpectralDistribution(s, wl), cmfs_aligned, illuminant_aligned,
            method="Integration",
        )
        / 100
        for s in S
    ])


@pytest.mark.parametrize("start, end, step", GRIDS)
@pytest.mark.parametrize(
    "illuminant, observer",
    [
        ("D65", OBSERVER_DEFAULT),
        ("A", OBSERVER_DEFAULT),
        ("C", OBSERVER_10),
        ("FL2", OBSERVER_DEFAULT),
    ],
)
def test_weights_match_colour_sd_to_XYZ_integration(start, end, step, illuminant, observer):
    wl = grid(start, end, step)
    W = tristimulus_weights(wl, illuminant, observer)
    S = np.vstack([smooth_spectra(wl, 8, seed=step), dataset_spectra(wl)])
    expected = colour_XYZ(S, wl, illuminant, observer)
    np.testing.assert_allclose(spectrum_to_XYZ(S, W), expected, rtol=1e-10, atol=1e-14)


@pytest.mark.filterwarnings("ignore:Aligning")
@pytest.mark.parametrize("name", ["D65", "A", "C", "FL2", "d50", "LED-B1"])
def test_illuminant_range_is_colour_sciences_shape(name):
    shape = colour.SDS_ILLUMINANTS[name].shape
    assert illuminant_range_nm(name) == (shape.start, shape.end)


@pytest.mark.parametrize("observer", ["CIE 1931 2 Degree Standard Observer",
                                      "CIE 1964 10 Degree Standard Observer", "cie_2_1931"])
def test_cmfs_wavelengths_are_colour_sciences_tabulation(observer):
    key = colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER.get(observer)  # canonical and slug keys
    np.testing.assert_array_equal(cmfs_wavelengths(observer), colour.MSDS_CMFS[key.name].wavelengths)


def test_weights_on_native_grid_match_colour_without_our_alignment():
    # colour aligns D65 (5 nm) onto the CMFs' own 1 nm shape itself: independent of our code path.
    msds = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    wl = msds.wavelengths
    W = tristimulus_weights(wl, "D65", OBSERVER_DEFAULT)
    for s in smooth_spectra(wl, 5, seed=7):
        expected = colour.sd_to_XYZ(
            colour.SpectralDistribution(s, wl), msds, colour.SDS_ILLUMINANTS["D65"],
            method="Integration",
        ) / 100
        np.testing.assert_allclose(s @ W, expected, rtol=1e-10)


@pytest.mark.parametrize("illuminant", ["A", "C", "D50", "D65"])
@pytest.mark.parametrize("observer", [OBSERVER_DEFAULT, OBSERVER_10])
def test_white_chromaticity_matches_CIE_15(illuminant, observer):
    XYZ = white_XYZ(illuminant, observer)
    # CIE 15:2004 Table T.3 chromaticities, printed to 4 decimals (colour.CCS_ILLUMINANTS).
    xy = XYZ[:2] / XYZ.sum()
    np.testing.assert_allclose(xy, colour.CCS_ILLUMINANTS[observer][illuminant], atol=1e-4)


@pytest.mark.parametrize(
    "illuminant, expected",
    # ASTM E308-15 Table 5 (1 nm), CIE 1931 2 degree observer, printed to 0.001 on the 100 scale.
    [("D65", [95.047, 100.0, 108.883]), ("A", [109.850, 100.0, 35.585])],
)
def test_white_matches_ASTM_E308(illuminant, expected):
    # colour tabulates these SPDs at 5 nm and Sprague-interpolates them to 1 nm: a few 1e-5.
    np.testing.assert_allclose(white_XYZ(illuminant), np.array(expected) / 100, atol=1e-4)


def test_white_is_the_perfect_reflector_with_Y_one():
    wl = grid(360, 830, 5)
    W = tristimulus_weights(wl)
    white = white_XYZ("D65", OBSERVER_DEFAULT, wl)
    np.testing.assert_array_equal(white, spectrum_to_XYZ(np.ones(wl.size), W))
    assert abs(white[1] - 1) < 1e-14
    # The 1 nm and 5 nm whites differ (~1e-4 in Z), which is why the grid is a parameter.
    assert 1e-6 < np.max(np.abs(white - white_XYZ("D65"))) < 1e-3


def test_cmfs_and_illuminant_on_grid_are_colour_values_at_tabulated_points():
    wl = grid(380, 780, 5)
    native = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    # to rounding, not bit for bit: colour's lookup at the tabulated points goes through its
    # interpolator's arithmetic, whose last bits follow the CPU's BLAS kernel (under OpenBLAS's
    # Prescott kernel they differ by up to 2.4e-15 from the cached tables made under another)
    np.testing.assert_allclose(cmfs(OBSERVER_DEFAULT, wl), native[wl], rtol=1e-13, atol=1e-17)
    np.testing.assert_allclose(illuminant_sd("D65", wl), colour.SDS_ILLUMINANTS["D65"][wl],
                               rtol=1e-13, atol=1e-15)
    assert cmfs(OBSERVER_DEFAULT).shape == (471, 3)


def test_weights_are_cached_but_returned_as_copies():
    wl = grid(360, 830, 5)
    W = tristimulus_weights(wl)
    W[:] = 0
    assert tristimulus_weights(wl)[:, 1].sum() == pytest.approx(1.0, abs=1e-14)
    assert tristimulus_weights(list(wl)).flags.writeable


@settings(max_examples=25, deadline=None)
@given(st.lists(st.integers(1, 4), min_size=0, max_size=3))
def test_spectrum_to_XYZ_broadcasts_over_leading_axes(shape):
    wl = grid(380, 780, 10)
    W = tristimulus_weights(wl)
    S = smooth_spectra(wl, int(np.prod(shape)), seed=len(shape)).reshape(*shape, wl.size)
    XYZ = spectrum_to_XYZ(S, W)
    assert XYZ.shape == (*shape, 3)
    np.testing.assert_allclose(XYZ.reshape(-1, 3), [s @ W for s in S.reshape(-1, wl.size)])


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: illuminant_sd("D64", grid(380, 780, 5)), "illuminant.*D65"),
        (lambda: tristimulus_weights(grid(380, 780, 5), illuminant="nope"), "illuminant.*FL2"),
        (lambda: cmfs("CIE 1931 3 Degree", grid(380, 780, 5)), "observer.*CIE 1964"),
        (lambda: tristimulus_weights([400.0, 410.0, 425.0, 430.0]), "wavelengths.*uniform"),
        (lambda: tristimulus_weights([[400.0, 410.0]]), "wavelengths"),
        (lambda: tristimulus_weights([400.0, np.nan, 420.0]), "wavelengths"),
        (lambda: tristimulus_weights([420.0, 410.0, 400.0]), "wavelengths.*increasing"),
        (lambda: spectrum_to_XYZ(np.ones(5), np.ones((6, 3))), "S:"),
        (lambda: dominant_wavelength([1.0, 2.0]), "XYZ"),
    ],
)
def test_bad_input_raises_value_error_naming_it(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_dominant_wavelength_of_spectral_colours_is_their_wavelength():
    msds = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    wl = np.arange(420.0, 651.0, 1.0)
    XYZ = msds[wl] * np.linspace(0.1, 2.0, wl.size)[:, None]
    dominant, purity = dominant_wavelength(XYZ, "D65")
    np.testing.assert_array_equal(dominant, wl)
    np.testing.assert_allclose(purity, 1.0, atol=1e-3)


def test_dominant_wavelength_matches_colour_in_any_shape():
    rng = np.random.default_rng(3)
    xy_n = colour.XYZ_to_xy(white_XYZ("D65"))
    XYZ = colour.xyY_to_XYZ(np.stack([
        rng.uniform(0.15, 0.6, 60), rng.uniform(0.1, 0.6, 60), rng.uniform(0.05, 1.0, 60)
    ], -1)).reshape(3, 4, 5, 3)
    wl, purity = dominant_wavelength(XYZ, "D65")
    assert wl.shape == purity.shape == (3, 4, 5)
    xy = colour.XYZ_to_xy(XYZ.reshape(-1, 3))
    msds = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    expected_wl, _, _ = colour.dominant_wavelength(xy, xy_n, msds)
    np.testing.assert_array_equal(wl.ravel(), expected_wl)
    np.testing.assert_allclose(purity.ravel(), colour.excitation_purity(xy, xy_n, msds), rtol=1e-12)
    assert np.any(wl < 0), "the sample should include purples (negative complementary wavelength)"


def test_purple_gets_negative_complementary_wavelength():
    msds = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    purple = msds[420.0] * 20 + msds[680.0] * 20
    wl, purity = dominant_wavelength(purple, "D65")
    assert -570 < wl < -480 and 0 < purity < 1
    # Same chromaticity reached with the white passed as XYZ.
    wl_2, purity_2 = dominant_wavelength(purple, white_XYZ("D65"))
    assert (wl_2, purity_2) == (wl, purity)


def test_dominant_wavelength_undefined_cases():
    white = white_XYZ("D65")
    XYZ = np.array([[0.0, 0.0, 0.0], 0.3 * white, [np.nan, 1, 1]])
    wl, purity = dominant_wavelength(XYZ, white)
    assert np.all(np.isnan(wl))
    np.testing.assert_array_equal(purity[:2], [0.0, 0.0])
    assert np.isnan(purity[2])
