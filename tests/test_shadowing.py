"""Shadowing-masking G: V-cavity against a V-groove ray simulation, Blinn's division-free ordering,
Smith's G against its definition and the projected-area identity."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy import integrate
from scipy.special import erf

from reflectance.optics.microfacet import distribution_Beckmann1963
from reflectance.optics.shadowing import (
    G1_Smith_Beckmann_Walter2007,
    G_over_NE_Blinn1977,
    SHADOWING_METHODS,
    shadowing,
    shadowing_Smith_Beckmann_Walter2007,
    shadowing_VCavity_Blinn1977,
)
from reflectance.papers.vgroove import simulate_vgroove, vgroove_vertices


def direction(theta, phi=0.0):
    return np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)])


def blinn_terms(L, E, N=np.array([0.0, 0.0, 1.0])):
    """Blinn 1977's G_b and G_c written out from the vectors (independent of the library)."""
    H = (L + E) / np.linalg.norm(L + E)
    G_b = 2 * (N @ H) * (N @ E) / (E @ H)
    G_c = 2 * (N @ H) * (N @ L) / (E @ H)
    return G_b, G_c, (N @ L, N @ E, N @ H, E @ H)


# --- the V-groove simulation (Blinn Figs. 1-4) -------------------------------------------------------

CASES = {
    # Blinn Fig. 1: (a) no attenuation, (b) masking of reflected light, (c) shadowing of incident light.
    "a": (direction(np.radians(20)), direction(np.radians(10), np.pi)),
    "b": (direction(np.radians(10), np.pi), direction(np.radians(85))),
    "c": (direction(np.radians(85)), direction(np.radians(10), np.pi)),
}


@pytest.mark.parametrize("case", ["a", "b", "c"])
def test_vgroove_simulation_matches_blinn_cases(case):
    L, E = CASES[case]
    G_b, G_c, cosines = blinn_terms(L, E)
    result = simulate_vgroove(L, E, n_rays=40_000)
    assert result.case == case
    assert result.G == pytest.approx(min(1, G_b, G_c), abs=1e-3)
    assert result.G_masking == pytest.approx(min(1, G_b), abs=1e-3)
    assert result.G_shadowing == pytest.approx(min(1, G_c), abs=1e-3)
    assert shadowing_VCavity_Blinn1977(*cosines) == pytest.approx(result.G, abs=1e-3)
    # Blinn Figs. 3-4: 1 - m/l from the boundary ray through the opposite vertex (a construction).
    assert 1 - result.m_masking / result.facet_length == pytest.approx(min(1, G_b), abs=1e-12)
    assert 1 - result.m_shadowing / result.facet_length == pytest.approx(min(1, G_c), abs=1e-12)
    assert result.reflection_error < 1e-12
    if case == "a":
        assert G_b >= 1 and G_c >= 1
    elif case == "b":
        assert G_b < min(1, G_c)
    else:
        assert G_c < min(1, G_b)


def test_vgroove_simulation_random_out_of_plane_geometry():
    """L and E need not lie in the plane of N and H (Blinn Fig. 2): the simulation projects them
    onto the groove's cross-section, which is exact for an infinitely long groove."""
    rng = np.random.default_rng(1977)
    for _ in range(30):
        L = direction(rng.uniform(0, 1.55), rng.uniform(0, 2 * np.pi))
        E = direction(rng.uniform(0, 1.55), rng.uniform(0, 2 * np.pi))
        G_b, G_c, cosines = blinn_terms(L, E)
        result = simulate_vgroove(L, E, n_rays=20_000)
        assert result.G == pytest.approx(min(1, G_b, G_c), abs=1e-3)
        assert result.G_masking == pytest.approx(min(1, G_b), abs=1e-3)
        assert result.G_shadowing == pytest.approx(min(1, G_c), abs=1e-3)
        assert shadowing_VCavity_Blinn1977(*cosines) == pytest.approx(min(1, G_b, G_c), rel=1e-12)


def test_vgroove_geometry_for_figures():
    L, E = CASES["b"]
    result = simulate_vgroove(L, E, n_rays=2_000, n_keep=10)
    A, B, C = result.vertices
    alpha = result.alpha
    assert alpha == pytest.approx(np.radians(37.5), abs=1e-12)  # H halfway between -10 and 85 degrees
    np.testing.assert_allclose(result.H2, [np.sin(alpha), np.cos(alpha)])
    # side AB is perpendicular to H, the groove is symmetric, the opening is on w = 0
    assert (B - A) @ result.H2 == pytest.approx(0, abs=1e-12)
    assert np.linalg.norm(B - A) == pytest.approx(np.linalg.norm(C - B))
    assert A[1] == C[1] == 0
    assert result.ray_points.shape == (10, 3, 2)
    assert set(result.ray_status) <= {"escaped", "masked", "other side"}
    assert "masked" in set(result.ray_status) and "escaped" in set(result.ray_status)
    np.testing.assert_allclose(np.linalg.norm(result.basis, axis=1), 1)


def test_vgroove_flat_and_errors():
    L = direction(0.4)
    E = direction(0.4, np.pi)  # H = N: a flat groove
    result = simulate_vgroove(L, E, n_rays=100)
    assert (result.G, result.case) == (1.0, "a")
    with pytest.raises(ValueError, match="above the surface"):
        simulate_vgroove(direction(2.0), E)
    with pytest.raises(ValueError, match="alpha"):
        vgroove_vertices(np.pi / 2)


# --- Blinn's division-free ordering -----------------------------------------------------------------

unit_above = st.tuples(st.floats(0.0, 1.5707), st.floats(0.0, 2 * np.pi)).map(lambda a: direction(*a))


@given(unit_above, unit_above)
@settings(max_examples=300)
def test_blinn_division_free_ordering_equals_min_over_NE(L, E):
    G_b, G_c, (NL, NE, NH, EH) = blinn_terms(L, E)
    assume(NE > 1e-12 and NL > 1e-12)
    assert G_over_NE_Blinn1977(NL, NE, NH, EH) == pytest.approx(min(1, G_b, G_c) / NE, rel=1e-12)


def test_blinn_ordering_ties():
    # N.E = N.L (else branch with G_b = G_c), and 2 (N.E)(N.H) = E.H (inner comparison tied).
    for NE, NL, NH, EH in [(0.3, 0.3, 0.9, 0.5), (0.25, 0.7, 0.8, 0.4), (0.7, 0.25, 0.8, 0.4)]:
        G = min(1, 2 * NH * NE / EH, 2 * NH * NL / EH)
        assert G_over_NE_Blinn1977(NL, NE, NH, EH) == pytest.approx(G / NE, rel=1e-14)


def test_ambiguity_blinn_last_division_is_grouped():
    """Blinn prints G := 2(N.H)(N.L)/(E.H)(N.E). Read left to right, ``.../(E.H)*(N.E)``, it is not
    G_c/(N.E); grouped, ``/((E.H)(N.E))``, it is. The library uses the grouped reading."""
    NL, NE, NH, EH = 0.1, 0.6, 0.8, 0.7  # else branch (N.E >= N.L), G_c < 1
    G_c = 2 * NH * NL / EH
    left_to_right = 2 * NH * NL / EH * NE
    assert G_over_NE_Blinn1977(NL, NE, NH, EH) == pytest.approx(G_c / NE, rel=1e-14)
    assert left_to_right / (G_c / NE) == pytest.approx(NE**2, rel=1e-14)  # (N.E)^2 = 0.36


def test_blinn_ordering_is_finite_where_NE_vanishes():
    NE = np.array([0.0, 1e-300, 1e-12, 1e-6])
    with np.errstate(all="raise"):
        values = G_over_NE_Blinn1977(0.5, NE, 0.9, 0.6)
    assert np.all(np.isfinite(values))
    # G_b / N.E = 2 (N.H) / (E.H) as N.E -> 0
    np.testing.assert_allclose(values[1:], 2 * 0.9 / 0.6)


# --- properties of both G ------------------------------------------------------------------------

@given(unit_above, unit_above, st.sampled_from(list(SHADOWING_METHODS)))
def test_G_is_symmetric_bounded_and_zero_below_horizon(L, E, method):
    _, _, (NL, NE, NH, EH) = blinn_terms(L, E)
    kwargs = {"m": 0.4} if method.startswith("Smith") else {}
    G = shadowing(NL, NE, NH, EH, method, **kwargs)
    assert G == shadowing(NE, NL, NH, EH, method, **kwargs)  # reciprocity: exact
    # Walter et al. 2007's rational G1 for Beckmann is not clamped: just below a = 1.6 it exceeds 1
    # (at 1.6: (3.535 a + 2.181 a^2) / (1 + 2.276 a + 2.577 a^2) = 1 + 5.7e-5), so Smith's G may too
    a = 1.6
    overshoot = (3.535 * a + 2.181 * a**2) / (1 + 2.276 * a + 2.577 * a**2) - 1
    assert 0 < overshoot < 6e-5
    bound = (1 + overshoot) ** 2 if method == "Smith_Beckmann_Walter2007" else 1.0
    assert 0 <= G <= bound
    assert shadowing(-NL, NE, NH, EH, method, **kwargs) == 0
    assert shadowing(NL, -NE, NH, EH, method, **kwargs) == 0


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("method", list(SHADOWING_METHODS))
def test_G_finite_at_boundaries(method):
    values = np.array([-0.1, 0.0, 1e-300, 1e-8, 0.5, 1.0, 1.0 + 1e-15])
    NL, NV, NH, VH = np.meshgrid(values, values, values, values, indexing="ij")
    kwargs = {"m": 0.3} if method.startswith("Smith") else {}
    G = shadowing(NL, NV, NH, VH, method, **kwargs)
    assert G.shape == NL.shape
    assert np.all(np.isfinite(G)) and np.all((G >= 0) & (G <= 1))


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("method", list(SHADOWING_METHODS))
def test_G_nan_inputs_do_not_raise(method):
    kwargs = {"m": 0.3} if method.startswith("Smith") else {}
    G = shadowing(np.array([np.nan, 0.5]), 0.5, 0.9, 0.8, method, **kwargs)
    assert G.shape == (2,) and np.isfinite(G[1])
    assert np.shape(G_over_NE_Blinn1977(np.array([np.nan, 0.5]), 0.5, 0.9, 0.8)) == (2,)


# --- Smith ------------------------------------------------------------------------------------------

def smith_G1_from_definition(cos_theta, m):
    """Smith 1967: G1 = 1 / (1 + Lambda), Lambda(mu) = (1/mu) int_mu^inf (q - mu) p(q) dq for the
    slope q along the viewing direction, mu = cot(theta). A Beckmann surface of rms slope m has
    Gaussian slopes with variance m^2 / 2 per axis."""
    mu = cos_theta / np.sqrt(1 - cos_theta**2)
    sigma = m / np.sqrt(2)
    p = lambda q: np.exp(-0.5 * (q / sigma) ** 2) / (sigma * np.sqrt(2 * np.pi))  # noqa: E731
    tail, _ = integrate.quad(lambda q: (q - mu) * p(q), mu, np.inf, epsabs=1e-14)
    return 1 / (1 + tail / mu)


@pytest.mark.parametrize("m", [0.1, 0.4, 1.0])
@pytest.mark.parametrize("theta_deg", [5, 45, 70, 85, 89.5])
def test_smith_G1_against_its_definition(m, theta_deg):
    c = np.cos(np.radians(theta_deg))
    assert G1_Smith_Beckmann_Walter2007(c, m) == pytest.approx(smith_G1_from_definition(c, m), rel=1e-9)
    assert G1_Smith_Beckmann_Walter2007(c, m, "rational") == pytest.approx(smith_G1_from_definition(c, m), abs=3.5e-3)


def _max0_cos_integral(A, B):
    """int_0^{2 pi} max(0, A cos(phi) + B) d phi for A >= 0 (closed form)."""
    if B >= A:
        return 2 * np.pi * B
    if B <= -A:
        return 0.0
    phi0 = np.arccos(-B / A)
    return 2 * (B * phi0 + A * np.sin(phi0))


@pytest.mark.parametrize("m", [0.3, 0.8])
@pytest.mark.parametrize("theta_o", [0.3, 1.0, 1.4])
def test_smith_G1_satisfies_projected_area(m, theta_o):
    """Heitz 2014: int G1(o) max(0, o.h) D(h) d omega_h = cos(theta_o) for normalised D; Smith's G1
    does not depend on h, so G1 = cos(theta_o) / int max(0, o.h) D(h) d omega_h."""
    so, co = np.sin(theta_o), np.cos(theta_o)

    def ring(t):  # integral over phi_h at polar angle t, times sin(t) d t
        return distribution_Beckmann1963(np.cos(t), m, "physical") * np.sin(t) * _max0_cos_integral(
            so * np.sin(t), co * np.cos(t)
        )

    projected, _ = integrate.quad(ring, 0, np.pi / 2, points=[m / 2, m, 3 * m], limit=200, epsabs=1e-13)
    assert G1_Smith_Beckmann_Walter2007(co, m) == pytest.approx(co / projected, rel=1e-8)


def test_smith_separable_and_zero_for_back_facing_facets():
    G = shadowing_Smith_Beckmann_Walter2007(0.3, 0.8, 0.9, 0.5, m=0.5)
    assert G == pytest.approx(G1_Smith_Beckmann_Walter2007(0.3, 0.5) * G1_Smith_Beckmann_Walter2007(0.8, 0.5))
    assert shadowing_Smith_Beckmann_Walter2007(0.3, 0.8, 0.9, -0.1, m=0.5) == 0
    assert G1_Smith_Beckmann_Walter2007(0.0, 0.5) == 0
    assert G1_Smith_Beckmann_Walter2007(1.0, 0.5) == 1


def test_closed_form_G1_written_as_in_walter():
    # 2 / (1 + erf(a) + exp(-a^2) / (a sqrt(pi))), a = cot(theta) / m, away from a = 0
    c, m = 0.4, 0.6
    a = c / np.sqrt(1 - c * c) / m
    assert G1_Smith_Beckmann_Walter2007(c, m) == pytest.approx(2 / (1 + erf(a) + np.exp(-a * a) / (a * np.sqrt(np.pi))), rel=1e-14)


def test_errors():
    with pytest.raises(ValueError, match="VCavity_Blinn1977"):
        shadowing(0.5, 0.5, 0.9, 0.8, method="V-cavity")
    with pytest.raises(ValueError, match="'m'"):
        G1_Smith_Beckmann_Walter2007(0.5, 0.0)
    with pytest.raises(ValueError, match="form"):
        G1_Smith_Beckmann_Walter2007(0.5, 0.3, form="pade")
    with pytest.raises(ValueError, match="Bad parameters"):
        shadowing(0.5, 0.5, 0.9, 0.8, method="Smith_Beckmann_Walter2007")
