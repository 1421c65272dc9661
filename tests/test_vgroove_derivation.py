"""Blinn's derivation of G (Figs. 1-4): the case helper and the law-of-sines construction, checked
against G_b, G_c written out from the vectors and against Blinn's trigonometric relations."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from reflectance.optics.shadowing import shadowing_VCavity_Blinn1977, vcavity_terms_Blinn1977
from reflectance.papers.vgroove import simulate_vgroove
from reflectance.papers.vgroove_derivation import groove_angles_Blinn1977, vgroove_case


def vec(theta_deg, phi_deg):
    t, p = np.radians(theta_deg), np.radians(phi_deg)
    return np.array([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])


def by_hand(L, E):
    """G_b, G_c of Blinn 1977 from unit vectors, N = z."""
    H = (L + E) / np.linalg.norm(L + E)
    return 2 * H[2] * E[2] / (E @ H), 2 * H[2] * L[2] / (E @ H)


@given(st.floats(0.0, 89.0), st.floats(-180, 180), st.floats(0.0, 89.0), st.floats(-180, 180))
def test_vcavity_terms_min_is_the_library_G(tl, pl, te, pe):
    L, E = vec(tl, pl), vec(te, pe)
    assume(np.linalg.norm(L + E) > 1e-6)
    H = (L + E) / np.linalg.norm(L + E)
    G_b, G_c = vcavity_terms_Blinn1977(L[2], E[2], H[2], E @ H)
    assert (G_b, G_c) == pytest.approx(by_hand(L, E), rel=1e-12)
    assert min(1.0, G_b, G_c) == pytest.approx(
        shadowing_VCavity_Blinn1977(L[2], E[2], H[2], E @ H), rel=1e-12)


def test_vcavity_terms_rejects_grazing_half_vector():
    with pytest.raises(ValueError, match="E.H"):
        vcavity_terms_Blinn1977(0.5, 0.5, 0.5, 0.0)


@pytest.mark.parametrize("light,eye,case", [
    ((45, 0), (15, 0), "a"), ((20, 200), (75, -20), "b"), ((78, 15), (25, 170), "c")])
def test_vgroove_case(light, eye, case):
    sim, row = vgroove_case({"theta_deg": light[0], "phi_deg": light[1]},
                            {"theta_deg": eye[0], "phi_deg": eye[1]}, n_rays=20_000)
    G_b, G_c = by_hand(vec(*light), vec(*eye))
    assert row["case"] == case == sim.case
    assert row["G_b"] == pytest.approx(G_b) and row["G_c"] == pytest.approx(G_c)
    assert row["G_closed"] == pytest.approx(min(1, G_b, G_c))
    assert row["G_simulated"] == pytest.approx(min(1, G_b, G_c), abs=5e-4)


@settings(max_examples=40, deadline=None)
@given(st.floats(0, 40), st.floats(-180, 180), st.floats(55, 88), st.floats(-60, 60))
def test_law_of_sines_construction(tl, pl, te, pe):
    # The eye grazing on the far side and the light near the normal on the other: masking.
    L, E = vec(tl, 180 + pl), vec(te, pe)
    G_b, G_c = by_hand(L, E)
    assume(G_b < min(1.0, G_c) - 1e-6)
    g = groove_angles_Blinn1977(simulate_vgroove(L, E, n_rays=200))
    # the angles (arctan2 of cross and dot products) agree to about 1e-15 on 400 random cases;
    # hypothesis once found one off by 1.4e-12 (tl 3.03, pl 63.9, te 60.4, pe 0, rounded: the
    # rounded case does not reproduce it), hence 1e-11
    assert np.sin(g.b) == pytest.approx(np.cos(g.e), abs=1e-11)  # Blinn: sin b = cos e
    assert g.c == pytest.approx(2 * g.d, abs=1e-11)                # c = 2d
    assert g.d + g.a == pytest.approx(np.pi / 2, abs=1e-12)        # d, a complementary
    assert g.b + g.c + g.f == pytest.approx(np.pi, abs=1e-12)     # the triangle P, B, C
    assert g.m_over_l_sines == pytest.approx(g.m_over_l_lengths, abs=1e-12)
    assert 1 - g.m_over_l_sines == pytest.approx(G_b, abs=1e-12)   # G_b = 1 - m/l


def test_shadowing_construction_swaps_L_and_E():
    L, E = vec(80, 0), vec(15, 180)
    G_b, G_c = by_hand(L, E)
    g = groove_angles_Blinn1977(simulate_vgroove(L, E, n_rays=200), blocked="shadowing")
    assert 1 - g.m_over_l_sines == pytest.approx(G_c, abs=1e-12)
    with pytest.raises(ValueError, match="No masking"):
        groove_angles_Blinn1977(simulate_vgroove(L, E, n_rays=200), blocked="masking")
    with pytest.raises(ValueError, match="known: masking, shadowing"):
        groove_angles_Blinn1977(simulate_vgroove(L, E, n_rays=200), blocked="both")
