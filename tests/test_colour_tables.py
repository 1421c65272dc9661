"""The cached colour-science tables and the numpy formulas that replace colour-science's on the
colour path, each checked against colour-science computed fresh in this process."""

import colour
import numpy as np
import pytest

from reflectance.colour import tables
from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy, dominant_wavelength, white_XYZ
from reflectance.colour.difference import delta_E_CIE2000
from reflectance.colour.display import (
    CHROMATIC_ADAPTATION_TRANSFORM,
    DISPLAY_SPACES,
    XYZ_to_linear_RGB,
    decode_8bit,
    display_space,
    encode,
)

OBSERVERS = colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER
GRIDS = [(360, 830, 5), (380, 780, 10), (400, 700, 1), (340, 850, 10)]


def grid(start, end, step):
    return tuple(np.arange(start, end + step / 2, step, dtype=np.float64).tolist())


def shape(g):
    return colour.SpectralShape(g[0], g[-1], g[1] - g[0])


@pytest.fixture()
def fresh_cache(tmp_path, monkeypatch):
    """An empty cache folder, and nothing held in memory: every table is computed, written, and
    then (after :func:`tables.forget`) read back from its file."""
    monkeypatch.setenv(tables.CACHE_ENVIRONMENT_VARIABLE, str(tmp_path))
    tables.forget()
    yield tmp_path
    tables.forget()


def written_then_read(compute):
    """``compute()`` on an empty cache, then again from the files alone."""
    first = compute()
    tables.forget()
    return first, compute()


# -- the cache against colour-science ------------------------------------------------------------

def test_cache_folder_names_the_colour_science_version(fresh_cache):
    assert tables.cache_directory() == fresh_cache / f"colour-science-{colour.__version__}"


def test_names_and_their_variants_are_colour_sciences(fresh_cache):
    for kind, mapping, names, resolve in (
        ("observers", OBSERVERS, tables.observer_names, tables.resolve_observer),
        ("illuminants", colour.SDS_ILLUMINANTS, tables.illuminant_names,
         tables.resolve_illuminant),
    ):
        first, again = written_then_read(names)
        assert first == again == tuple(mapping.keys())
        keys = list(mapping.keys())
        variants = (keys + [k.lower() for k in keys] + [k.upper() for k in keys]
                    + list(mapping.slugified_keys()) + list(mapping.canonical_keys()))
        for name in variants + ["", "D 65", "nope", "cie 1931"]:
            key = resolve(name)
            assert (key is not None) == (name in mapping), (kind, name)
            if key is not None:
                assert mapping[key] is mapping[name], (kind, name)
        assert resolve(None) is None and resolve(65) is None


@pytest.mark.parametrize("observer", list(OBSERVERS))
def test_tabulated_cmfs_are_colour_sciences(fresh_cache, observer):
    first, again = written_then_read(lambda: tables.cmfs_tabulated(observer))
    for wavelengths, values in (first, again):
        np.testing.assert_array_equal(wavelengths, OBSERVERS[observer].wavelengths)
        np.testing.assert_array_equal(values, OBSERVERS[observer].values)


@pytest.mark.parametrize("start, end, step", GRIDS)
@pytest.mark.parametrize("observer", ["CIE 1931 2 Degree Standard Observer",
                                      "CIE 1964 10 Degree Standard Observer"])
def test_aligned_cmfs_are_colour_sciences(fresh_cache, start, end, step, observer):
    g = grid(start, end, step)
    expected = OBSERVERS[observer].copy().align(shape(g)).values
    for values in written_then_read(lambda: tables.cmfs_aligned(observer, g)):
        np.testing.assert_array_equal(values, expected)


@pytest.mark.parametrize("start, end, step", GRIDS)
@pytest.mark.parametrize("name", ["D65", "A", "C", "FL2", "D50"])
def test_illuminants_are_colour_sciences(fresh_cache, start, end, step, name):
    g = grid(start, end, step)
    sd = colour.SDS_ILLUMINANTS[name]
    expected = sd.copy().align(shape(g)).values
    for values in written_then_read(lambda: tables.illuminant_aligned(name, g)):
        np.testing.assert_array_equal(values, expected)
    for wavelengths, values in written_then_read(lambda: tables.illuminant_tabulated(name)):
        np.testing.assert_array_equal(wavelengths, sd.wavelengths)
        np.testing.assert_array_equal(values, sd.values)


@pytest.mark.parametrize("space", [v[0] for v in DISPLAY_SPACES.values()] + ["Adobe RGB (1998)"])
def test_colourspace_matrices_are_colour_sciences(fresh_cache, space):
    cs = colour.RGB_COLOURSPACES[space]
    for M, white in written_then_read(lambda: tables.rgb_colourspace_matrix(space)):
        np.testing.assert_array_equal(M, colour.normalised_primary_matrix(cs.primaries,
                                                                          cs.whitepoint))
        np.testing.assert_array_equal(white, colour.xy_to_XYZ(cs.whitepoint))


def test_chromatic_adaptation_matrix_is_colour_sciences(fresh_cache):
    for M in written_then_read(lambda: tables.chromatic_adaptation_matrix("CAT02")):
        np.testing.assert_array_equal(
            M, colour.adaptation.CHROMATIC_ADAPTATION_TRANSFORMS["CAT02"])


@pytest.mark.parametrize("notation", ["5R 4/14", "N2", "2.5YR 3/4", "5BG 5/6", "N9.5"])
def test_munsell_value_and_Y_are_colour_sciences(fresh_cache, notation):
    import warnings

    from colour.notation.munsell import munsell_colour_to_munsell_specification

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        V = float(munsell_colour_to_munsell_specification(notation)[1])
        Y = float(colour.munsell_colour_to_xyY(notation)[2])
    first, again = written_then_read(lambda: tables.munsell_value_and_Y(notation))
    assert first == again == (V, Y)  # bit-identical, also when read back from the file
    assert list(tables.cache_directory().glob("munsell-*.json"))


def test_munsell_errors_are_colour_sciences_and_not_cached(fresh_cache):
    with pytest.raises(ValueError):
        tables.munsell_value_and_Y("black")
    assert tables.munsell_value_and_Y("N99") == (99.0, None)  # outside 0-10: no Y asked for
    tables.forget()
    with pytest.raises(ValueError):
        tables.munsell_value_and_Y("black")  # computed again, raising again
    assert len(list(tables.cache_directory().glob("munsell-*.json"))) == 1


def test_an_unwritable_cache_is_ignored(tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    monkeypatch.setenv(tables.CACHE_ENVIRONMENT_VARIABLE, str(blocker))
    tables.forget()
    try:
        g = grid(360, 830, 5)
        np.testing.assert_array_equal(
            tables.cmfs_aligned("CIE 1931 2 Degree Standard Observer", g),
            OBSERVERS["CIE 1931 2 Degree Standard Observer"].copy().align(shape(g)).values)
        assert tables.resolve_illuminant("d65") == "D65"
    finally:
        tables.forget()
    assert blocker.read_text() == "not a folder"


def test_a_damaged_cache_file_is_recomputed(fresh_cache):
    g = grid(380, 780, 10)
    tables.illuminant_aligned("A", g)
    (path,) = tables.cache_directory().glob("illuminants-aligned-*.npy")
    path.write_bytes(b"\x93NUMPY garbage")
    tables.forget()
    np.testing.assert_array_equal(tables.illuminant_aligned("A", g),
                                  colour.SDS_ILLUMINANTS["A"].copy().align(shape(g)).values)
    assert not list(tables.cache_directory().glob(".*.tmp"))


def test_grid_errors_are_named(fresh_cache):
    with pytest.raises(ValueError, match="wavelengths: "):
        tables.illuminant_aligned("D65", (360.0, 365.0, 371.0))
    assert not list(tables.cache_directory().glob("illuminants-aligned-*"))


# -- the formulas against colour-science's functions ---------------------------------------------

def random_XYZ(n, seed):
    rng = np.random.default_rng(seed)
    XYZ = rng.uniform(0, 1.2, (n, 3)) * rng.choice([1e-4, 1e-2, 1.0], (n, 1))
    XYZ[:5] = [[0, 0, 0], [0.1, 0, 0], [1e-6, 2e-6, 3e-6], [0.95047, 1.0, 1.08883], [-0.01, 0.02, 0.5]]
    return XYZ


def test_XYZ_to_xy_is_colour_sciences():
    XYZ = random_XYZ(5000, 1)
    np.testing.assert_array_equal(XYZ_to_xy(XYZ), colour.XYZ_to_xy(XYZ))
    cube = XYZ.reshape(10, 20, 25, 3)
    np.testing.assert_array_equal(XYZ_to_xy(cube), colour.XYZ_to_xy(cube))
    np.testing.assert_array_equal(XYZ_to_xy(XYZ[7]), colour.XYZ_to_xy(XYZ[7]))


@pytest.mark.parametrize("seed", range(3))
def test_XYZ_to_Lab_is_colour_sciences(seed):
    rng = np.random.default_rng(seed)
    XYZ = random_XYZ(5000, seed + 10)
    white_xy = rng.uniform([0.25, 0.25], [0.45, 0.42])
    np.testing.assert_array_equal(XYZ_to_Lab(XYZ, white_xy), colour.XYZ_to_Lab(XYZ, white_xy))


# Sharma, G., Wu, W., & Dalal, E. N. (2005). The CIEDE2000 color-difference formula:
# Implementation notes, supplementary test data, and mathematical observations. Color Research &
# Application, 30(1), 21-30, Table 1: the 34 published test pairs (L*, a*, b*) and their
# CIEDE2000 to 4 decimals (also at http://www2.ece.rochester.edu/~gsharma/ciede2000/).
SHARMA_2005 = [
    ((50.0000, 2.6772, -79.7751), (50.0000, 0.0000, -82.7485), 2.0425),
    ((50.0000, 3.1571, -77.2803), (50.0000, 0.0000, -82.7485), 2.8615),
    ((50.0000, 2.8361, -74.0200), (50.0000, 0.0000, -82.7485), 3.4412),
    ((50.0000, -1.3802, -84.2814), (50.0000, 0.0000, -82.7485), 1.0000),
    ((50.0000, -1.1848, -84.8006), (50.0000, 0.0000, -82.7485), 1.0000),
    ((50.0000, -0.9009, -85.5211), (50.0000, 0.0000, -82.7485), 1.0000),
    ((50.0000, 0.0000, 0.0000), (50.0000, -1.0000, 2.0000), 2.3669),
    ((50.0000, -1.0000, 2.0000), (50.0000, 0.0000, 0.0000), 2.3669),
    ((50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0009), 7.1792),
    ((50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0010), 7.1792),
    ((50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0011), 7.2195),
    ((50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0012), 7.2195),
    ((50.0000, -0.0010, 2.4900), (50.0000, 0.0009, -2.4900), 4.8045),
    ((50.0000, -0.0010, 2.4900), (50.0000, 0.0010, -2.4900), 4.8045),
    ((50.0000, -0.0010, 2.4900), (50.0000, 0.0011, -2.4900), 4.7461),
    ((50.0000, 2.5000, 0.0000), (50.0000, 0.0000, -2.5000), 4.3065),
    ((50.0000, 2.5000, 0.0000), (73.0000, 25.0000, -18.0000), 27.1492),
    ((50.0000, 2.5000, 0.0000), (61.0000, -5.0000, 29.0000), 22.8977),
    ((50.0000, 2.5000, 0.0000), (56.0000, -27.0000, -3.0000), 31.9030),
    ((50.0000, 2.5000, 0.0000), (58.0000, 24.0000, 15.0000), 19.4535),
    ((50.0000, 2.5000, 0.0000), (50.0000, 3.1736, 0.5854), 1.0000),
    ((50.0000, 2.5000, 0.0000), (50.0000, 3.2972, 0.0000), 1.0000),
    ((50.0000, 2.5000, 0.0000), (50.0000, 1.8634, 0.5757), 1.0000),
    ((50.0000, 2.5000, 0.0000), (50.0000, 3.2592, 0.3350), 1.0000),
    ((60.2574, -34.0099, 36.2677), (60.4626, -34.1751, 39.4387), 1.2644),
    ((63.0109, -31.0961, -5.8663), (62.8187, -29.7946, -4.0864), 1.2630),
    ((61.2901, 3.7196, -5.3901), (61.4292, 2.2480, -4.9620), 1.8731),
    ((35.0831, -44.1164, 3.7933), (35.0232, -40.0716, 1.5901), 1.8645),
    ((22.7233, 20.0904, -46.6940), (23.0331, 14.9730, -42.5619), 2.0373),
    ((36.4612, 47.8580, 18.3852), (36.2715, 50.5065, 21.2231), 1.4146),
    ((90.8027, -2.0831, 1.4410), (91.1528, -1.6435, 0.0447), 1.4441),
    ((90.9257, -0.5406, -0.9208), (88.6381, -0.8985, -0.7239), 1.5381),
    ((6.7747, -0.2908, -2.4247), (5.8714, -0.0985, -2.2286), 0.6377),
    ((2.0776, 0.0795, -1.1350), (0.9033, -0.0636, -0.5514), 0.9082),
]
def test_CIEDE2000_matches_Sharma_2005():
    Lab_1, Lab_2, expected = (np.array(column) for column in zip(*SHARMA_2005))
    np.testing.assert_allclose(delta_E_CIE2000(Lab_1, Lab_2), expected, atol=5e-5)
    # The formula is symmetric (pairs 7-8 and 13-14 include hues 180 degrees apart).
    np.testing.assert_allclose(delta_E_CIE2000(Lab_2, Lab_1), expected, atol=5e-5)


@pytest.mark.parametrize("textiles", [False, True])
def test_CIEDE2000_is_colour_sciences(textiles):
    rng = np.random.default_rng(7)
    n = 20000
    Lab_1 = np.column_stack([rng.uniform(0, 100, n), rng.uniform(-120, 120, (n, 2))])
    # Near pairs (as in the audits) and far ones; neutral colours and exact hue ties included.
    Lab_2 = Lab_1 + rng.normal(0, 1, (n, 3)) * rng.choice([1e-3, 1.0, 30.0], (n, 1))
    Lab_1[:100, 1:] = 0.0
    Lab_2[100:200] = Lab_1[100:200] * [1, -1, -1]
    Lab_2[200:300] = Lab_1[200:300]
    expected = colour.delta_E(Lab_1, Lab_2, method="CIE 2000", textiles=textiles)
    np.testing.assert_array_equal(delta_E_CIE2000(Lab_1, Lab_2, textiles), expected)
    np.testing.assert_array_equal(
        delta_E_CIE2000(Lab_1.reshape(100, 200, 3), Lab_2.reshape(100, 200, 3), textiles),
        expected.reshape(100, 200))


@pytest.mark.parametrize("observer", ["CIE 1931 2 Degree Standard Observer",
                                      "CIE 1964 10 Degree Standard Observer"])
def test_dominant_wavelength_is_colour_sciences(observer):
    """Random chromaticities over the whole diagram (spectral colours and purples): the same
    quantised wavelength as colour.dominant_wavelength and a boundary point within 1e-12."""
    rng = np.random.default_rng(3)
    XYZ_n = white_XYZ("D65", observer)
    xy_n = XYZ_n[:2] / XYZ_n.sum()
    xy = rng.uniform([0.0, 0.0], [0.75, 0.85], (4000, 2))
    xy = xy[np.hypot(*(xy - xy_n).T) > 1e-3]
    XYZ = np.column_stack([xy, 1 - xy.sum(axis=1)]) * rng.uniform(0.01, 2.0, (len(xy), 1))

    wl, purity = dominant_wavelength(XYZ, "D65", observer)
    expected_wl, expected_xy_b, _ = colour.dominant_wavelength(xy, xy_n, OBSERVERS[observer])
    found = ~np.isnan(expected_xy_b[:, 0])  # colour's NaN rows: the library's retry covers them
    assert found.mean() > 0.99
    np.testing.assert_array_equal(wl[found], expected_wl[found])
    expected_purity = (np.hypot(*(xy - xy_n).T) / np.hypot(*(expected_xy_b - xy_n).T))[found]
    np.testing.assert_allclose(purity[found], expected_purity, rtol=1e-12, atol=1e-12)
    assert (wl < 0).any() and (wl > 0).any()  # purples and spectral colours were both drawn


@pytest.mark.parametrize("observer", ["CIE 1931 2 Degree Standard Observer",
                                      "CIE 1964 10 Degree Standard Observer"])
def test_dominant_wavelength_through_locus_vertices_is_colour_sciences(observer):
    """Lines from the white through every tabulated locus point, exactly and 1e-13 off it (where
    the shortlist of segments and of nearest samples is tightest): colour's wavelength and
    boundary point wherever colour finds one."""
    rng = np.random.default_rng(8)
    XYZ_n = white_XYZ("D65", observer)
    xy_n = XYZ_n[:2] / XYZ_n.sum()
    locus = XYZ_to_xy(tables.cmfs_tabulated(observer)[1])
    through = xy_n + (locus - xy_n) * rng.uniform(0.05, 1.0, (len(locus), 1))
    xy = np.vstack([through, through + rng.normal(0.0, 1e-13, through.shape)])
    XYZ = np.column_stack([xy, 1 - xy.sum(axis=1)])

    wl, purity = dominant_wavelength(XYZ, "D65", observer)
    expected_wl, expected_xy_b, _ = colour.dominant_wavelength(xy, xy_n, OBSERVERS[observer])
    found = ~np.isnan(expected_xy_b[:, 0])
    assert found.mean() > 0.9
    np.testing.assert_array_equal(wl[found], expected_wl[found])
    expected_purity = (np.hypot(*(xy - xy_n).T) / np.hypot(*(expected_xy_b - xy_n).T))[found]
    np.testing.assert_array_equal(purity[found], expected_purity)


def test_von_Kries_CAT02_is_colour_sciences():
    rng = np.random.default_rng(5)
    for space in DISPLAY_SPACES:
        ds = display_space(space)
        for XYZ_w in rng.uniform(0.5, 1.5, (50, 3)):
            XYZ = rng.uniform(0, 1, (20, 3))
            M = colour.adaptation.matrix_chromatic_adaptation_VonKries(
                XYZ_w / XYZ_w[1], ds.whitepoint_XYZ, transform=CHROMATIC_ADAPTATION_TRANSFORM)
            np.testing.assert_array_equal(XYZ_to_linear_RGB(XYZ, space, XYZ_w),
                                          XYZ @ (ds.matrix_XYZ_to_RGB @ M).T)


def test_transfer_functions_are_colour_sciences():
    L = np.concatenate([[0.0, 1e-12, 0.0031308, 0.0031309, 0.5, 1.0],
                        np.random.default_rng(9).uniform(0, 1, 5000)])
    np.testing.assert_array_equal(encode(L, "sRGB"), colour.cctf_encoding(L, function="sRGB"))
    np.testing.assert_array_equal(encode(L, "SMPTE-C"),
                                  colour.models.eotf_inverse_BT1886(L, L_B=0, L_W=1))
    assert np.isnan(encode([np.nan], "sRGB")).all() and np.isnan(encode([np.nan], "SMPTE-C")).all()


def test_decoding_of_8_bit_codes_is_colour_sciences(fresh_cache):
    """Every code, as computed and written to the cache and as read back from it, in any shape."""
    codes = np.random.default_rng(4).integers(0, 256, (40, 30, 3)).astype(np.float64)
    for _ in range(2):  # computed by colour-science, then read from the file
        np.testing.assert_array_equal(decode_8bit(codes, "sRGB"),
                                      colour.cctf_decoding(codes / 255, function="sRGB"))
        np.testing.assert_array_equal(decode_8bit(codes, "SMPTE-C"),
                                      colour.models.eotf_BT1886(codes / 255, L_B=0, L_W=1))
        np.testing.assert_array_equal(decode_8bit(np.arange(256), "sRGB"),
                                      colour.cctf_decoding(np.arange(256) / 255, function="sRGB"))
        tables.forget()
    assert list(fresh_cache.rglob("transfer-decoding-8bit-*.npy"))
    for bad in ([0.5], [-1], [256]):
        with pytest.raises(ValueError, match="integers 0-255"):
            decode_8bit(bad)


@pytest.mark.parametrize("step", [4.7, 0.0025])
def test_aligned_tables_sit_on_a_grid_colour_sciences_align_misses(fresh_cache, step):
    """colour-science's align samples at points of its own: D65, tabulated to 780 nm, came back
    up to 1.9 nm off a 4.7 nm grid and one sample too long at 0.0025 nm (issue 25). Truth: D65's
    interpolator is linear, so inside its range it is numpy's interp of its table, beyond it its
    last value; the CMFs (tabulated at every nm of 360-830) are colour-science's Sprague
    interpolation, evaluated here at the grid's own points by colour-science's interpolator."""
    g = np.linspace(360.0, 830.0, int(round(470 / step)) + 1)
    d65 = colour.SDS_ILLUMINANTS["D65"]
    assert d65.wavelengths[-1] == 780.0
    expected = np.where(g <= 780.0, np.interp(g, d65.wavelengths, d65.values), d65.values[-1])
    aligned = tables.illuminant_aligned("D65", tuple(g.tolist()))
    assert aligned.shape == g.shape
    np.testing.assert_allclose(aligned, expected, rtol=1e-12)
    observer = "CIE 1931 2 Degree Standard Observer"
    sprague = colour.SpragueInterpolator(OBSERVERS[observer].wavelengths,
                                         OBSERVERS[observer].values[:, 1])
    cmfs = tables.cmfs_aligned(observer, tuple(g.tolist()))
    assert cmfs.shape == (g.size, 3)
    np.testing.assert_allclose(cmfs[:, 1], sprague(g), rtol=1e-12, atol=1e-15)
