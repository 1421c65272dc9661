"""Facet distributions D: normalisation, Blinn's half-angle beta, golden values by hand formulas."""

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from scipy import integrate
from scipy.optimize import brentq

from reflectance.optics.microfacet import (
    C3_MAX_FOR_BETA,
    DISTRIBUTION_METHODS,
    beta_to_c1_Blinn1977,
    beta_to_c2_Blinn1977,
    beta_to_c3_Blinn1977,
    c3_texture_Blinn1977,
    c3_to_beta_Blinn1977,
    distribution,
    distribution_Beckmann1963,
    distribution_Gaussian_CookTorrance1982,
    distribution_mixture,
    distribution_Phong1975,
    distribution_TorranceSparrow1967,
    distribution_TrowbridgeReitz1975,
    distribution_TrowbridgeReitz_texture_Blinn1977,
)


def hemisphere_integral(D, width):
    """2 pi int_0^{pi/2} D(cos t) cos t sin t dt by adaptive quadrature (scipy), breakpoints at
    multiples of the lobe width so that narrow lobes are resolved."""
    points = [p for p in (0.5 * width, width, 3 * width, 6 * width) if p < np.pi / 2]
    value, error = integrate.quad(
        lambda t: D(np.cos(t)) * np.cos(t) * np.sin(t), 0.0, np.pi / 2, points=points, limit=400,
        epsabs=1e-13, epsrel=1e-11,
    )
    return 2 * np.pi * value


# --- normalisation of the physical convention -----------------------------------------------------

@pytest.mark.parametrize("m", [0.02, 0.05, 0.15, 0.3, 0.6, 1.0, 2.0])
def test_beckmann_physical_integrates_to_one(m):
    assert hemisphere_integral(lambda c: distribution_Beckmann1963(c, m, "physical"), m) == pytest.approx(1, abs=1e-8)


@pytest.mark.parametrize("m", [0.05, 0.3, 1.0])
def test_beckmann_paper_integrates_to_pi(m):
    # Cook & Torrance's printed D lacks the 1/pi: its projected-area integral is pi.
    assert hemisphere_integral(lambda c: distribution_Beckmann1963(c, m), m) == pytest.approx(np.pi, abs=1e-7)


@pytest.mark.parametrize("c3", [0.02, 0.1, 0.35, 0.5, 0.9, 1.0])
def test_trowbridge_reitz_physical_integrates_to_one(c3):
    D = lambda c: distribution_TrowbridgeReitz1975(c, c3, "physical")  # noqa: E731
    # The GGX tail is heavy (~ c3^2 / theta^4): breakpoints near the peak suffice.
    assert hemisphere_integral(D, c3) == pytest.approx(1, abs=1e-8)


@pytest.mark.parametrize("c1", [0.0, 1.0, 10.0, 60.0, 1000.0])
def test_phong_physical_integrates_to_one(c1):
    D = lambda c: distribution_Phong1975(c, c1, "physical")  # noqa: E731
    assert hemisphere_integral(D, 1.0 / np.sqrt(c1 + 1.0)) == pytest.approx(1, abs=1e-8)


@pytest.mark.parametrize("c2", [0.0, 0.5, 3.0, 30.0, 300.0])
def test_torrance_sparrow_physical_integrates_to_one(c2):
    D = lambda c: distribution_TorranceSparrow1967(c, c2, "physical")  # noqa: E731
    assert hemisphere_integral(D, 1.0 / max(c2, 1.0)) == pytest.approx(1, abs=1e-8)


@pytest.mark.parametrize("m", [0.01, 0.2, 0.6, 5.0])
def test_gaussian_cook_torrance_physical_integrates_to_one(m):
    D = lambda c: distribution_Gaussian_CookTorrance1982(c, m, convention="physical")  # noqa: E731
    assert hemisphere_integral(D, min(m, 1.0)) == pytest.approx(1, abs=1e-8)


@pytest.mark.parametrize(
    "base, lobes",
    [
        ("Beckmann1963", [(0.4, 0.4), (0.6, 0.2)]),  # Cook & Torrance 1982, Fig. 6b copper vase
        ("TrowbridgeReitz1975", [(0.25, 0.1), (0.25, 0.3), (0.5, 0.7)]),
        ("Phong1975", [(0.5, 5.0), (0.5, {"c1": 200.0})]),
    ],
)
def test_mixture_of_normalised_lobes_integrates_to_one(base, lobes):
    D = lambda c: distribution_mixture(c, lobes, base=base, convention="physical")  # noqa: E731
    assert hemisphere_integral(D, 0.05) == pytest.approx(1, abs=1e-8)


def test_mixture_is_the_weighted_sum():
    c = np.linspace(0, 1, 11)
    expected = 0.4 * distribution_Beckmann1963(c, 0.4) + 0.6 * distribution_Beckmann1963(c, 0.2)
    np.testing.assert_allclose(distribution_mixture(c, [(0.4, 0.4), (0.6, 0.2)]), expected, rtol=1e-15)


# --- golden values by hand formulas ---------------------------------------------------------------

@pytest.mark.parametrize("m", [0.1, 0.3, 0.7])
def test_beckmann_at_tan_alpha_equal_m(m):
    # tan(alpha) = m: cos^2 = 1 / (1 + m^2), exp(-1), so D = e^-1 (1 + m^2)^2 / m^2.
    cos_alpha = 1 / np.sqrt(1 + m * m)
    expected = np.exp(-1) * (1 + m * m) ** 2 / (m * m)
    assert distribution_Beckmann1963(cos_alpha, m) == pytest.approx(expected, rel=1e-13)
    assert distribution_Beckmann1963(cos_alpha, m, "physical") == pytest.approx(expected / np.pi, rel=1e-13)
    assert distribution_Beckmann1963(1.0, m) == pytest.approx(1 / (m * m), rel=1e-15)


def test_beckmann_matches_wikipedia_form():
    # Article: exp(-tan^2 a / m^2) / (pi m^2 cos^4 a), with tan^2 = (1 - cos^2) / cos^2.
    c = np.linspace(0.3, 1, 40)
    m = 0.35
    article = np.exp(-((1 - c**2) / (c**2 * m**2))) / (np.pi * m**2 * c**4)
    np.testing.assert_allclose(distribution_Beckmann1963(c, m, "physical"), article, rtol=1e-12)


@given(st.floats(0.0, 1.0), st.floats(0.02, 1.0))
def test_trowbridge_reitz_physical_is_ggx(cos_alpha, c3):
    # Walter et al. 2007 GGX in the tan form: a^2 / (pi cos^4 (a^2 + tan^2)^2), written as
    # a^2 / (pi (a^2 cos^2 + sin^2)^2), which is finite at cos = 0.
    sin2 = 1 - cos_alpha**2
    ggx = c3**2 / (np.pi * (c3**2 * cos_alpha**2 + sin2) ** 2)
    assert distribution_TrowbridgeReitz1975(cos_alpha, c3, "physical") == pytest.approx(ggx, rel=1e-12)


def test_blinn_k1_k2_form_equals_D3():
    # Blinn 1977, "Computational considerations": k1 = 1/(c3^2 - 1), k2 = k1 + 1, D3 = (k2/(cos^2 + k1))^2.
    c = np.linspace(0, 1, 21)
    for c3 in (0.2, 0.5, 0.8):
        k1 = 1 / (c3**2 - 1)
        k2 = k1 + 1
        np.testing.assert_allclose(distribution_TrowbridgeReitz1975(c, c3), (k2 / (c**2 + k1)) ** 2, rtol=1e-12)


def test_gaussians_at_one_width():
    alpha = 0.3
    assert distribution_Gaussian_CookTorrance1982(np.cos(alpha), alpha) == pytest.approx(np.exp(-1), rel=1e-13)
    assert distribution_Gaussian_CookTorrance1982(np.cos(alpha), alpha, c=2.5) == pytest.approx(2.5 * np.exp(-1), rel=1e-13)
    assert distribution_TorranceSparrow1967(np.cos(alpha), 1 / alpha) == pytest.approx(np.exp(-1), rel=1e-13)
    assert distribution_Phong1975(0.5, 3.0) == pytest.approx(0.125, rel=1e-15)


def test_paper_to_physical_factors():
    c = np.linspace(0.5, 1, 10)
    np.testing.assert_allclose(distribution_Beckmann1963(c, 0.3) / distribution_Beckmann1963(c, 0.3, "physical"), np.pi)
    np.testing.assert_allclose(
        distribution_TrowbridgeReitz1975(c, 0.4) / distribution_TrowbridgeReitz1975(c, 0.4, "physical"), np.pi * 0.16
    )
    np.testing.assert_allclose(distribution_Phong1975(c, 8.0) / distribution_Phong1975(c, 8.0, "physical"), 2 * np.pi / 10)


# --- Blinn's beta and D(0) = 1 ----------------------------------------------------------------------

@given(st.floats(0.005, 1.5))
@example(0.005859375)  # a draw that a fixed 1e-12 refused (0.4999999999988933)
def test_blinn_distributions_fall_to_half_at_beta(beta):
    c = np.cos(beta)
    # cos(beta) is rounded near 1, and 1 - cos(beta), about beta^2 / 2, carries that rounding
    # magnified by 2 / beta^2 into the exponents: the tolerance follows that conditioning
    rel = 1e-12 + 8 * np.finfo(float).eps / beta**2
    assert distribution_Phong1975(c, beta_to_c1_Blinn1977(beta)) == pytest.approx(0.5, rel=rel)
    assert distribution_TorranceSparrow1967(c, beta_to_c2_Blinn1977(beta)) == pytest.approx(0.5, rel=rel)
    assert distribution_TrowbridgeReitz1975(c, beta_to_c3_Blinn1977(beta)) == pytest.approx(0.5, rel=1e-9)


# beta from c3 (the inverse of Blinn's conversion): against a root of D3 = 1/2 and the forward one.

def d3_by_hand(alpha, c3):
    """Blinn 1977, D3 written out: (c3^2 / (cos^2 alpha (c3^2 - 1) + 1))^2."""
    return (c3**2 / (np.cos(alpha) ** 2 * (c3**2 - 1) + 1)) ** 2


@given(st.floats(0.01, 0.83))
def test_beta_is_where_d3_falls_to_one_half(c3):
    # Independent truth: bisect D3(alpha) = 1/2 on (0, pi/2).
    root = brentq(lambda a: d3_by_hand(a, c3) - 0.5, 1e-12, np.pi / 2, xtol=1e-15)
    assert c3_to_beta_Blinn1977(c3) == pytest.approx(root, abs=1e-10)


@given(st.floats(0.001, 1.5))
def test_inverse_of_blinns_conversion(beta):
    assert c3_to_beta_Blinn1977(beta_to_c3_Blinn1977(beta)) == pytest.approx(beta, rel=1e-9, abs=1e-9)


def test_c3_to_beta_paper_parameters():
    # Blinn 1977 Figs. 7a, 7b: c3 = 0.5 (aluminium), 0.35 (MgO); beta by bisection in degrees.
    for c3 in (0.5, 0.35):
        root = brentq(lambda a: d3_by_hand(a, c3) - 0.5, 1e-9, np.pi / 2, xtol=1e-14)
        assert np.degrees(c3_to_beta_Blinn1977(c3)) == pytest.approx(np.degrees(root), abs=1e-9)
    # D3 at 90 degrees is c3^4: the largest c3 with a half-value angle has c3^4 = 1/2.
    assert C3_MAX_FOR_BETA**4 == pytest.approx(0.5)


def test_c3_to_beta_shapes():
    c3 = np.array([[0.1, 0.3], [0.5, 0.7]])
    out = c3_to_beta_Blinn1977(c3)
    assert out.shape == (2, 2)
    assert out[1, 0] == c3_to_beta_Blinn1977(0.5)
    assert isinstance(c3_to_beta_Blinn1977(0.5), np.floating)


@pytest.mark.parametrize("bad", [0.0, -0.2, C3_MAX_FOR_BETA, 0.9, 1.0, np.nan, np.inf])
def test_c3_to_beta_bad_c3_raises(bad):
    with pytest.raises(ValueError, match="c3"):
        c3_to_beta_Blinn1977(bad)


@given(st.floats(0.0, 500.0), st.floats(0.0, 50.0), st.floats(0.01, 1.0))
def test_blinn_distributions_peak_at_one(c1, c2, c3):
    assert distribution_Phong1975(1.0, c1) == 1.0
    assert distribution_TorranceSparrow1967(1.0, c2) == 1.0
    assert distribution_TrowbridgeReitz1975(1.0, c3) == pytest.approx(1.0, rel=1e-15)


@given(st.floats(0.0, 1.0), st.floats(0.05, 1.0), st.floats(0.0, 1.0))
def test_texture_form(cos_alpha, c_min, t):
    # Blinn 1977: at t = 0, C3 = C_min and the texture form is D3; elsewhere D(0) = (C_min / C3)^2.
    assert distribution_TrowbridgeReitz_texture_Blinn1977(cos_alpha, c3_texture_Blinn1977(0.0, c_min), c_min) == (
        pytest.approx(distribution_TrowbridgeReitz1975(cos_alpha, c_min), rel=1e-13)
    )
    c3 = c3_texture_Blinn1977(t, c_min)
    assert distribution_TrowbridgeReitz_texture_Blinn1977(1.0, c3, c_min) == pytest.approx((c_min / c3) ** 2, rel=1e-13)


def test_errata_blinn_c2_large_values_are_shiny():
    """Blinn 1977 calls c2 "the standard deviation" and says "large values yield dull surfaces"; with
    his D2 = exp(-(alpha c2)^2) a larger c2 gives a narrower lobe (a shinier surface): the half
    angle is beta = sqrt(ln 2) / c2. (The lecture repeats D = exp(-(alpha m)^2), "m is standard
    deviation"; Cook & Torrance write exp(-(alpha/m)^2), where m is a width.)"""
    alpha = 0.2
    values = [distribution_TorranceSparrow1967(np.cos(alpha), c2) for c2 in (1.0, 3.0, 10.0)]
    assert values[0] > values[1] > values[2]
    for c2 in (1.0, 3.0, 10.0):
        assert distribution_TorranceSparrow1967(np.cos(np.sqrt(np.log(2)) / c2), c2) == pytest.approx(0.5)


def test_errata_lecture_beckmann_has_4_where_cook_torrance_have_1_and_pi():
    """The lecture prints D = exp(-(tan d / m)^2) / (4 m^2 cos^4 d); Cook & Torrance print it
    without the 4 and the article (Walter et al.) with pi. Projected-area integrals: pi/4, pi, 1."""
    m = 0.3
    lecture = lambda c: np.exp(-((1 - c * c) / (c * c)) / m**2) / (4 * m**2 * c**4)  # noqa: E731
    assert hemisphere_integral(lecture, m) == pytest.approx(np.pi / 4, abs=1e-8)
    assert hemisphere_integral(lambda c: distribution_Beckmann1963(c, m), m) == pytest.approx(np.pi, abs=1e-8)


# --- robustness -------------------------------------------------------------------------------------

BOUNDARY = np.array([-0.5, 0.0, 1e-300, 1e-160, 1e-100, 1e-20, 1e-8, 0.5, 1 - 1e-16, 1.0, 1 + 1e-15])


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("convention", ["paper", "physical"])
@pytest.mark.parametrize(
    "method, params",
    [
        ("Phong1975", {"c1": 60.0}),
        ("TorranceSparrow1967", {"c2": 5.0}),
        ("TrowbridgeReitz1975", {"c3": 0.3}),
        ("Beckmann1963", {"m": 0.01}),
        ("Beckmann1963", {"m": 50.0}),
        ("Gaussian_CookTorrance1982", {"m": 0.2}),
        ("mixture", {"lobes": [(0.5, 0.1), (0.5, 0.4)]}),
    ],
)
def test_finite_non_negative_at_boundaries(method, params, convention):
    D = distribution(BOUNDARY, method, convention=convention, **params)
    assert np.all(np.isfinite(D)) and np.all(D >= 0)
    assert D[0] == 0  # no facets face away from N (N.H < 0)


@pytest.mark.filterwarnings("error")
def test_nan_propagates_without_raising():
    for method, params in [("Beckmann1963", {"m": 0.3}), ("TrowbridgeReitz1975", {"c3": 0.3}), ("Phong1975", {"c1": 5})]:
        assert np.isnan(distribution(np.nan, method, **params))


@pytest.mark.parametrize("shape", [(), (7,), (2, 3), (2, 3, 4)])
def test_shapes_and_broadcasting(shape):
    rng = np.random.default_rng(3)
    c = rng.uniform(0, 1, shape)
    m = rng.uniform(0.1, 1, shape)
    D = distribution_Beckmann1963(c, m)
    assert np.shape(D) == shape
    flat = [distribution_Beckmann1963(ci, mi) for ci, mi in zip(np.ravel(c), np.ravel(m))]
    np.testing.assert_allclose(np.ravel(D), flat, rtol=1e-15)
    # a roughness per wavelength against cosines per pixel
    assert np.shape(distribution_TrowbridgeReitz1975(np.asarray(c)[..., None], np.array([0.2, 0.5]))) == shape + (2,)


def test_scalar_in_scalar_out():
    assert isinstance(distribution_Beckmann1963(0.5, 0.3), np.float64)


def test_errors_name_the_problem():
    with pytest.raises(ValueError, match="Beckmann1963"):
        distribution(0.5, "Beckman")
    with pytest.raises(ValueError, match="'m'"):
        distribution_Beckmann1963(0.5, -0.1)
    with pytest.raises(ValueError, match="convention"):
        distribution_Beckmann1963(0.5, 0.1, "normalised")
    with pytest.raises(ValueError, match="sum to 1"):
        distribution_mixture(0.5, [(0.4, 0.2), (0.4, 0.3)])
    with pytest.raises(ValueError, match="'c'"):
        distribution_Gaussian_CookTorrance1982(0.5, 0.2, c=2.0, convention="physical")
    with pytest.raises(ValueError, match="beta"):
        beta_to_c3_Blinn1977(2.0)
    with pytest.raises(ValueError, match="Bad parameters"):
        distribution(0.5, "Beckmann1963", c3=0.2)


def test_registry_is_complete():
    assert set(DISTRIBUTION_METHODS) == {
        "Phong1975", "TorranceSparrow1967", "TrowbridgeReitz1975", "TrowbridgeReitz_texture_Blinn1977",
        "Beckmann1963", "Gaussian_CookTorrance1982", "mixture",
    }
