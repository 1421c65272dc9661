"""Tests of reflectance.colour.display against colour-science, closed-form identities and brute force."""

import colour
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from reflectance.colour.colorimetry import (
    OBSERVER_DEFAULT,
    dominant_wavelength,
    spectrum_to_XYZ,
    tristimulus_weights,
    white_XYZ,
)
from reflectance.colour.display import (
    DISPLAY_SPACES,
    GAMUT_CLIP_METHODS,
    XYZ_to_display,
    XYZ_to_linear_RGB,
    display_space,
    encode,
    expose_CookTorrance1982,
    expose_key,
    gamut_clip,
    linear_RGB_to_XYZ,
)

COLOUR_NAMES = {"sRGB": "sRGB", "SMPTE-C": "SMPTE C"}
GRID_5NM = np.arange(360.0, 831.0, 5.0)


def derived_colourspace(space):
    """colour-science's colourspace using the matrices derived from primaries and whitepoint."""
    cs = colour.RGB_COLOURSPACES[COLOUR_NAMES[space]].copy()
    cs.use_derived_matrix_XYZ_to_RGB = True
    cs.use_derived_matrix_RGB_to_XYZ = True
    return cs


def to_display_XYZ(RGB, space):
    """Display XYZ of linear RGB via colour-science (white = space whitepoint, no adaptation)."""
    cs = derived_colourspace(space)
    return colour.RGB_to_XYZ(RGB, cs, illuminant=cs.whitepoint, chromatic_adaptation_transform=None)


def from_display_XYZ(XYZ, space):
    cs = derived_colourspace(space)
    return colour.XYZ_to_RGB(XYZ, cs, illuminant=cs.whitepoint, chromatic_adaptation_transform=None)


def random_XYZ(n, seed, Y_range=(0.0, 1.0)):
    """Realisable colours: random positive mixtures of 1-3 monochromatic stimuli, scaled to Y."""
    rng = np.random.default_rng(seed)
    msds = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    rows = msds.values[rng.integers(0, msds.values.shape[0], (n, 3))]
    weights = rng.uniform(0, 1, (n, 3, 1)) * (rng.uniform(0, 1, (n, 3, 1)) < 0.6)
    weights[:, 0] += 1e-3
    XYZ = (weights * rows).sum(axis=1)
    return XYZ / XYZ[:, 1:2] * rng.uniform(*Y_range, (n, 1))


# --- XYZ <-> linear RGB ---------------------------------------------------------------------


@pytest.mark.parametrize("space", list(DISPLAY_SPACES))
@pytest.mark.parametrize("illuminant", ["D65", "A", "C", "D50", "FL2"])
@pytest.mark.parametrize("wavelengths", [None, GRID_5NM])
def test_illuminant_white_maps_to_equal_RGB(space, illuminant, wavelengths):
    W = tristimulus_weights(
        colour.MSDS_CMFS[OBSERVER_DEFAULT].wavelengths if wavelengths is None else wavelengths,
        illuminant,
    )
    Y = np.array([0.0, 0.25, 1.0, 7.5])[:, None]
    scene_white = Y * spectrum_to_XYZ(np.ones(W.shape[0]), W)  # S = 1 integrated by the renderer
    RGB = XYZ_to_linear_RGB(scene_white, space, illuminant, wavelengths=wavelengths)
    np.testing.assert_allclose(RGB, Y * np.ones(3), rtol=1e-13, atol=1e-15)
    # Same with the white passed as XYZ instead of a name.
    RGB = XYZ_to_linear_RGB(scene_white, space, W.sum(axis=0))
    np.testing.assert_allclose(RGB, Y * np.ones(3), rtol=1e-13, atol=1e-15)


@pytest.mark.parametrize("space", list(DISPLAY_SPACES))
@pytest.mark.parametrize("illuminant", ["D65", "A", "C"])
def test_XYZ_to_linear_RGB_matches_colour_XYZ_to_RGB_with_CAT02(space, illuminant):
    XYZ = random_XYZ(200, seed=1).reshape(10, 20, 3)
    xy_w = colour.XYZ_to_xy(white_XYZ(illuminant, wavelengths=GRID_5NM))
    expected = colour.XYZ_to_RGB(
        XYZ, derived_colourspace(space), illuminant=xy_w, chromatic_adaptation_transform="CAT02"
    )
    RGB = XYZ_to_linear_RGB(XYZ, space, illuminant, wavelengths=GRID_5NM)
    np.testing.assert_allclose(RGB, expected, rtol=1e-11, atol=1e-12)


def test_sRGB_differs_from_colours_rounded_IEC_matrix_by_a_few_1e_4():
    cs = colour.RGB_COLOURSPACES["sRGB"]
    # The rounded IEC 61966-2-1 matrix that colour's 'sRGB' uses misses the white by > 1e-4 ...
    white = colour.XYZ_to_RGB(colour.xy_to_XYZ(cs.whitepoint), "sRGB", illuminant=cs.whitepoint)
    assert np.max(np.abs(white - 1)) > 1e-4
    # ... and our derived matrix (plus CAT02 from the 1 nm D65 white) stays within 3e-4 of it.
    RGB = np.random.default_rng(2).uniform(0, 1, (2000, 3))
    XYZ = colour.RGB_to_XYZ(RGB, "sRGB", illuminant=cs.whitepoint)
    rounded = colour.XYZ_to_RGB(XYZ, "sRGB", illuminant=cs.whitepoint)
    np.testing.assert_allclose(XYZ_to_linear_RGB(XYZ, "sRGB", "D65"), rounded, atol=3e-4)


def test_sRGB_primaries_come_from_colour():
    np.testing.assert_allclose(
        display_space("sRGB").matrix_RGB_to_XYZ,
        colour.normalised_primary_matrix(
            [[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]], [0.3127, 0.3290]  # IEC 61966-2-1 Table 1
        ),
        rtol=1e-14,
    )


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.floats(-2, 5, allow_nan=False), min_size=3, max_size=30).filter(
        lambda v: len(v) % 3 == 0
    ),
    st.sampled_from(list(DISPLAY_SPACES)),
    st.sampled_from(["D65", "A", "C"]),
)
def test_linear_RGB_to_XYZ_inverts_XYZ_to_linear_RGB(values, space, illuminant):
    XYZ = np.reshape(values, (-1, 3))
    RGB = XYZ_to_linear_RGB(XYZ, space, illuminant)
    np.testing.assert_allclose(linear_RGB_to_XYZ(RGB, space, illuminant), XYZ, atol=1e-12)


# --- exposure -----------------------------------------------------------------------------


def test_expose_puts_brightest_colour_at_its_maximum_luminance():
    brightest_in_gamut = linear_RGB_to_XYZ([2.7, 2.85, 2.1])  # Y ~ 2.8, in-gamut chromaticity
    XYZ = np.concatenate([random_XYZ(300, seed=3, Y_range=(0, 2.5)), [brightest_in_gamut]])
    scaled, scale = expose_CookTorrance1982(XYZ.reshape(1, -1, 3), "sRGB", "D65")
    RGB = XYZ_to_linear_RGB(scaled.reshape(-1, 3))
    Y = RGB @ display_space("sRGB").matrix_RGB_to_XYZ[1]
    brightest = np.argmax(Y)
    assert brightest == XYZ.shape[0] - 1
    # At its maximum luminance: in gamut, and any brighter version of it would not be.
    assert np.all(RGB[brightest] <= 1 + 1e-12)
    assert np.any(RGB[brightest] * (1 + 1e-9) > 1)
    # Every colour's luminance is now displayable (Y <= 1), as Cook & Torrance require.
    assert np.all(Y <= 1 + 1e-12)
    assert scaled.shape == (1, XYZ.shape[0], 3)
    np.testing.assert_allclose(scaled.reshape(-1, 3), XYZ * scale, rtol=1e-15)


@settings(max_examples=25, deadline=None)
@given(st.floats(1e-3, 1e3), st.integers(0, 10_000))
def test_expose_is_invariant_to_overall_scene_scale(k, seed):
    XYZ = random_XYZ(50, seed=seed, Y_range=(0, 2))
    scaled_1, scale_1 = expose_CookTorrance1982(XYZ)
    scaled_k, scale_k = expose_CookTorrance1982(k * XYZ)
    np.testing.assert_allclose(scaled_k, scaled_1, rtol=1e-12)
    assert scale_k == pytest.approx(scale_1 / k, rel=1e-12)


def test_expose_with_out_of_gamut_brightest_colour_uses_its_largest_channel():
    XYZ = random_XYZ(1, seed=4)[0]
    RGB = np.array([1.4, 0.6, -0.2])  # out-of-gamut chromaticity, the brightest colour
    brightest = linear_RGB_to_XYZ(RGB)
    _, scale = expose_CookTorrance1982(np.stack([0.1 * XYZ, brightest]))
    assert scale == pytest.approx(1 / 1.4, rel=1e-12)


def test_expose_edge_cases():
    _, scale = expose_CookTorrance1982(np.zeros((4, 4, 3)))
    assert scale == 1.0
    XYZ = np.array([[np.nan, 1, 1], [0.5, 0.5, 0.5], [np.inf, 0, 0]])
    scaled, scale = expose_CookTorrance1982(XYZ)
    assert scale == pytest.approx(1 / XYZ_to_linear_RGB(XYZ[1]).max())
    assert np.isnan(scaled[0, 0]) and np.all(np.isfinite(scaled[1]))


@pytest.mark.parametrize("percentile, luminance", [(90.0, 0.18), (10.0, 0.5), (99.0, 0.8)])
def test_expose_key_puts_that_percentile_of_the_objects_luminance_at_the_key(percentile,
                                                                              luminance):
    """Reflected-light metering: the given percentile of Y over the object (Y > 0; the black
    background and a non-finite pixel left out) lands at the key luminance."""
    rng = np.random.default_rng(25)
    Y = np.zeros((40, 50))
    Y[5:35, 10:40] = rng.lognormal(0.0, 1.0, (30, 30))  # the object; the rest is background
    xy = np.array([0.3127, 0.3290])  # any chromaticity: only Y is metered
    XYZ = np.stack([Y * xy[0] / xy[1], Y, Y * (1 - xy.sum()) / xy[1]], axis=-1)
    XYZ[0, 0] = np.nan
    scaled, scale = expose_key(XYZ, percentile, luminance)
    metered = np.percentile(Y[5:35, 10:40], percentile)  # numpy, on the object's pixels only
    assert scale == pytest.approx(luminance / metered, rel=1e-12)
    assert np.percentile(scaled[5:35, 10:40, 1], percentile) == pytest.approx(luminance,
                                                                              rel=1e-12)
    background = Y == 0
    background[0, 0] = False
    assert np.all(scaled[background] == 0) and np.isnan(scaled[0, 0]).all()


# --- gamut clipping: Cook & Torrance 1982 (dominant wavelength) ----------------------------


def display_Y(RGB, space):
    return to_display_XYZ(RGB, space)[..., 1]


def brute_force_clip(RGB, space, iterations=200):
    """Bisection on the retained fraction a of RGB(a) = Y + a (RGB - Y) for one colour."""
    Y = display_Y(RGB, space)
    low, high = 0.0, 1.0
    for _ in range(iterations):
        a = 0.5 * (low + high)
        if np.all((Y + a * (RGB - Y) >= 0) & (Y + a * (RGB - Y) <= 1)):
            low = a
        else:
            high = a
    return Y + low * (RGB - Y)


@pytest.mark.parametrize("space", list(DISPLAY_SPACES))
def test_dominant_wavelength_clip_keeps_wavelength_and_luminance(space):
    cs = derived_colourspace(space)
    XYZ = random_XYZ(2000, seed=5)
    RGB = from_display_XYZ(XYZ, space)
    out = ~np.all((RGB >= 0) & (RGB <= 1), axis=-1)
    assert out.sum() > 1000, "most random realisable colours lie outside the display gamut"
    RGB = RGB[out]
    clipped = gamut_clip(RGB, "dominant-wavelength", space)
    assert np.all((clipped >= 0) & (clipped <= 1))
    np.testing.assert_allclose(display_Y(clipped, space), display_Y(RGB, space), atol=1e-6)
    # Dominant (purples: negative complementary) wavelength by colour.dominant_wavelength about
    # the display white, via the thin wrapper (tested against colour in test_colorimetry).
    white = colour.xy_to_XYZ(cs.whitepoint)
    before, purity_before = dominant_wavelength(to_display_XYZ(RGB, space), white)
    after, purity_after = dominant_wavelength(to_display_XYZ(clipped, space), white)
    assert np.all(np.isfinite(before)) and np.any(before < 0)
    np.testing.assert_allclose(after, before, atol=0.5)
    assert np.all(purity_after <= purity_before + 1e-9)


@pytest.mark.parametrize("space", list(DISPLAY_SPACES))
def test_dominant_wavelength_clip_of_spectral_colours(space):
    cs = derived_colourspace(space)
    msds = colour.MSDS_CMFS[OBSERVER_DEFAULT]
    # 420-690 nm: beyond, the tabulated locus folds back or repeats the same xy, so the nearest
    # locus sample of a chromaticity is not the stimulus wavelength.
    wl = np.arange(420.0, 691.0, 1.0)
    Y = np.random.default_rng(6).uniform(0.01, 0.99, wl.size)
    XYZ = msds[wl] / msds[wl][:, 1:2] * Y[:, None]
    clipped = gamut_clip(from_display_XYZ(XYZ, space), "dominant-wavelength", space)
    assert np.all((clipped >= 0) & (clipped <= 1))
    np.testing.assert_allclose(display_Y(clipped, space), Y, atol=1e-6)
    after, _ = dominant_wavelength(to_display_XYZ(clipped, space), colour.xy_to_XYZ(cs.whitepoint))
    np.testing.assert_allclose(after, wl, atol=0.5)


@settings(max_examples=200, deadline=None)
@given(
    st.tuples(*[st.floats(-1.0, 3.0, allow_nan=False)] * 3),
    st.sampled_from(list(DISPLAY_SPACES)),
)
def test_dominant_wavelength_clip_equals_brute_force_bisection(rgb, space):
    RGB = np.array(rgb)
    assume(0 <= display_Y(RGB, space) <= 1)  # clipping at constant Y needs a displayable Y
    np.testing.assert_allclose(
        gamut_clip(RGB, "dominant-wavelength", space), brute_force_clip(RGB, space), atol=1e-9
    )


@pytest.mark.parametrize("method", list(GAMUT_CLIP_METHODS))
def test_in_gamut_colours_are_untouched(method):
    RGB = np.random.default_rng(7).uniform(0, 1, (50, 40, 3))
    RGB[0, 0] = [0, 0, 0]
    RGB[0, 1] = [1, 1, 1]
    np.testing.assert_array_equal(gamut_clip(RGB, method, "sRGB"), RGB)


def test_dominant_wavelength_clip_edge_cases():
    RGB = np.array([
        [3.0, 2.0, 1.5],  # Y > 1: clamped to display white
        [-0.2, 0.1, -0.5],  # Y < 0: black
        [0.5, -0.3, 0.0],  # Y > 0, but small: desaturated
        [np.nan, 0.2, 0.3],
        [np.inf, 0.2, 0.3],
    ])
    with np.errstate(all="raise"):
        clipped = gamut_clip(RGB, "dominant-wavelength", "sRGB")
    np.testing.assert_array_equal(clipped[0], [1, 1, 1])
    np.testing.assert_array_equal(clipped[1], [0, 0, 0])
    assert np.all((clipped[2] >= 0) & (clipped[2] <= 1))
    assert np.all(np.isnan(clipped[3:]))


# --- gamut clipping: clip and CSS Color 4 --------------------------------------------------


def oklab(RGB, space):
    return colour.XYZ_to_Oklab(to_display_XYZ(RGB, space))


def css_gamut_map_reference(rgb, space):
    """Literal scalar transcription of CSS Color 4 §13.2 "CSS gamut map" (binary search)."""
    JND, EPSILON = 0.02, 0.0001
    to_rgb = lambda lab: from_display_XYZ(colour.Oklab_to_XYZ(lab), space)  # noqa: E731
    in_gamut = lambda c: bool(np.all((c >= 0) & (c <= 1)))  # noqa: E731
    delta = lambda rgb_c, lab: float(np.linalg.norm(oklab(rgb_c, space) - lab))  # noqa: E731
    if in_gamut(rgb):
        return rgb
    L, a, b = oklab(rgb, space)
    if L >= 1:
        return np.ones(3)
    if L <= 0:
        return np.zeros(3)
    C, h = np.hypot(a, b), np.arctan2(b, a)
    current = np.array([L, a, b])
    clipped = np.clip(to_rgb(current), 0, 1)
    if delta(clipped, current) < JND:
        return clipped
    low, high, min_in_gamut = 0.0, C, True
    while high - low > EPSILON:
        chroma = (low + high) / 2
        current = np.array([L, chroma * np.cos(h), chroma * np.sin(h)])
        if min_in_gamut and in_gamut(to_rgb(current)):
            low = chroma
            continue
        clipped = np.clip(to_rgb(current), 0, 1)
        E = delta(clipped, current)
        if E < JND:
            if JND - E < EPSILON:
                return clipped
            min_in_gamut = False
            low = chroma
        else:
            high = chroma
    return clipped


@pytest.mark.parametrize("space", list(DISPLAY_SPACES))
def test_css_oklch_matches_scalar_transcription_of_the_spec(space):
    RGB = from_display_XYZ(random_XYZ(150, seed=8), space)
    RGB = np.concatenate([RGB, [[1.02, 0.5, -0.01], [1.5, 1.5, 1.5], [-0.1, -0.1, 0.0]]])
    expected = np.array([css_gamut_map_reference(rgb, space) for rgb in RGB])
    np.testing.assert_allclose(gamut_clip(RGB, "css-oklch", space), expected, atol=1e-12)


@pytest.mark.parametrize("space", list(DISPLAY_SPACES))
def test_css_oklch_and_clip_are_in_gamut_and_css_keeps_hue(space):
    RGB = from_display_XYZ(random_XYZ(2000, seed=9), space).reshape(40, 50, 3)
    for method in ("clip", "css-oklch"):
        mapped = gamut_clip(RGB, method, space)
        assert mapped.shape == RGB.shape
        assert np.all((mapped >= 0) & (mapped <= 1))
    np.testing.assert_array_equal(gamut_clip(RGB, "clip", space), np.clip(RGB, 0, 1))
    lab_in, lab_out = oklab(RGB, space).reshape(-1, 3), oklab(mapped, space).reshape(-1, 3)
    keep = (lab_in[:, 0] > 0) & (lab_in[:, 0] < 1)
    hue = np.arctan2(lab_in[keep, 2], lab_in[keep, 1])
    # Distance of the result from the origin's plane of constant hue, and lightness change: both
    # within the JND of 0.02 that the algorithm allows between the clipped and the searched colour.
    off_hue = -lab_out[keep, 1] * np.sin(hue) + lab_out[keep, 2] * np.cos(hue)
    assert np.max(np.abs(off_hue)) < 0.02 + 1e-9
    assert np.max(np.abs(lab_out[keep, 0] - lab_in[keep, 0])) < 0.02 + 1e-9


@pytest.mark.parametrize("method", list(GAMUT_CLIP_METHODS))
def test_non_finite_rows_become_nan_without_warnings(method):
    RGB = np.array([[np.nan, 0.2, 0.3], [np.inf, 0.0, 0.0], [0.2, -np.inf, 0.1], [0.2, 0.3, 0.4]])
    with np.errstate(all="raise"):
        mapped = gamut_clip(RGB, method, "sRGB")
    assert np.all(np.isnan(mapped[:3]))
    np.testing.assert_array_equal(mapped[3], RGB[3])


def test_css_oklch_lightness_limits():
    RGB = np.array([[3.0, 3.0, 2.5], [-0.5, -0.1, -0.2], [np.nan, 0, 0]])
    with np.errstate(all="raise"):
        mapped = gamut_clip(RGB, "css-oklch", "sRGB")
    np.testing.assert_array_equal(mapped[:2], [[1, 1, 1], [0, 0, 0]])
    assert np.all(np.isnan(mapped[2]))


# --- transfer functions and the pipeline ----------------------------------------------------


def test_encode_sRGB_is_the_IEC_61966_2_1_curve():
    L = np.linspace(0, 1, 1001)
    # IEC 61966-2-1:1999 inverse: 12.92 L up to 0.0031308, else 1.055 L^(1/2.4) - 0.055.
    expected = np.where(L <= 0.0031308, 12.92 * L, 1.055 * L ** (1 / 2.4) - 0.055)
    np.testing.assert_allclose(encode(L, "sRGB"), expected, atol=1e-12)


def test_encode_SMPTE_C_is_inverse_BT1886_with_black_zero():
    L = np.linspace(0, 1, 1001).reshape(7, 11, 13)
    np.testing.assert_allclose(encode(L, "SMPTE-C"), L ** (1 / 2.4), atol=1e-12)  # BT.1886 Annex 1


def test_encode_without_a_transfer_writes_the_linear_values():
    """transfer 'none': the linear RGB (clipped to [0, 1]) is the signal, as a frame buffer without
    gamma correction wrote it; an unknown transfer is refused by name."""
    L = np.linspace(-0.5, 1.5, 2001)
    np.testing.assert_array_equal(encode(L, "sRGB", "none"), np.clip(L, 0, 1))
    np.testing.assert_array_equal(encode(L, "SMPTE-C", "none"), np.clip(L, 0, 1))
    with pytest.raises(ValueError, match="transfer.*gamma.*display.*none"):
        encode(L, "sRGB", "gamma")


def test_XYZ_to_display_composes_the_steps():
    XYZ = random_XYZ(600, seed=10, Y_range=(0, 4)).reshape(20, 30, 3)
    for space in DISPLAY_SPACES:
        for method in GAMUT_CLIP_METHODS:
            out = XYZ_to_display(XYZ, space, method, illuminant="A")
            assert out.dtype == np.float64 and out.shape == XYZ.shape
            assert np.all((out >= 0) & (out <= 1))
            scaled, _ = expose_CookTorrance1982(XYZ, space, "A")
            RGB = XYZ_to_linear_RGB(scaled, space, "A")
            expected = encode(gamut_clip(RGB, method, space), space)
            np.testing.assert_array_equal(out, expected)


def test_XYZ_to_display_of_the_white_is_display_white():
    white = spectrum_to_XYZ(np.ones(GRID_5NM.size), tristimulus_weights(GRID_5NM))
    out = XYZ_to_display(np.stack([white, 0.5 * white]), wavelengths=GRID_5NM)
    np.testing.assert_allclose(out[0], 1.0, atol=1e-12)
    np.testing.assert_allclose(out[1], encode(np.full(3, 0.5)), atol=1e-12)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: XYZ_to_display(np.ones(3), space="Adobe RGB"), "space.*sRGB.*SMPTE-C"),
        (lambda: XYZ_to_display(np.ones(3), clip="nearest"), "method.*dominant-wavelength"),
        (lambda: gamut_clip(np.ones(3), "nearest"), "method.*css-oklch"),
        (lambda: XYZ_to_linear_RGB(np.ones(3), illuminant="D64"), "illuminant.*D65"),
        (lambda: XYZ_to_linear_RGB(np.ones(3), illuminant=[1.0, -1.0, 1.0]), "illuminant"),
        (lambda: XYZ_to_linear_RGB(np.ones(4)), "XYZ"),
        (lambda: gamut_clip(np.ones((2, 2))), "RGB_linear"),
    ],
)
def test_bad_input_raises_value_error_naming_it(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_rgb_renderer_fresnel_applies_the_function_it_is_given_per_channel():
    """fresnel_XYZ_rgb: a spectrally flat F0 (grey, inside the gamut) gives Schlick's F times the
    light's white at every angle (Schlick is linear in F0); a constant function gives back F0's
    own colour; the Fresnel function is the caller's (colour may not import optics)."""
    from reflectance.colour.colorimetry import white_XYZ
    from reflectance.colour.display import fresnel_XYZ_rgb
    from reflectance.optics.fresnel import fresnel_Schlick1994

    white, c = white_XYZ("D65"), np.linspace(0.0, 1.0, 11)
    for space in ("sRGB", "SMPTE-C"):
        got = fresnel_XYZ_rgb(0.3 * white, c, white, space, fresnel=fresnel_Schlick1994)
        expected = (0.3 + 0.7 * (1.0 - c) ** 5)[:, None] * white  # Schlick 1994 by hand
        np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12)
        F0 = np.array([0.5, 0.4, 0.2]) * white
        same = fresnel_XYZ_rgb(F0, c, white, space, fresnel=lambda cos, F0: F0 + 0 * cos)
        np.testing.assert_allclose(same, np.broadcast_to(F0, (11, 3)), rtol=1e-12, atol=1e-12)
