"""Blinn's printed intensities in the plane of incidence, against the formulas written out by hand
(Fresnel from Blinn's own sin/tan form, not the g, c form the library uses)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982
from reflectance.papers.polar import (direction_from_angles, intensity_in_plane_of_incidence,
                              plane_of_incidence_vectors)


def fresnel_sin_tan(phi, n):
    """Blinn 1977's first Fresnel formula: 1/2 (sin^2(phi - theta)/sin^2(phi + theta) + tan^2/tan^2).

    At normal incidence (phi = 0) the form is 0/0; its limit is ((n - 1)/(n + 1))^2."""
    if phi == 0:
        return ((n - 1) / (n + 1)) ** 2
    theta = np.arcsin(np.sin(phi) / n)
    return 0.5 * (np.sin(phi - theta) ** 2 / np.sin(phi + theta) ** 2
                  + np.tan(phi - theta) ** 2 / np.tan(phi + theta) ** 2)


def torrance_sparrow_by_hand(ti, tr, p_d, p_s, n, c3):
    half = (ti - tr) / 2  # H's angle from N (towards the light's side)
    NL, NE, NH, EH = np.cos(ti), np.cos(tr), np.cos(half), np.cos((ti + tr) / 2)
    D = (c3**2 / (NH**2 * (c3**2 - 1) + 1)) ** 2
    G = min(1.0, 2 * NH * NE / EH, 2 * NH * NL / EH)
    return p_d * NL + p_s * D * G * fresnel_sin_tan(np.arccos(EH), n) / NE


def test_direction_from_angles():
    assert direction_from_angles(0.0, 1.0) == pytest.approx([0.0, 0.0, 1.0])
    for theta, phi in ((0.3, 2.0), (1.2, -0.7), (np.pi / 2, np.pi)):
        v = direction_from_angles(theta, phi)
        assert np.linalg.norm(v) == pytest.approx(1.0)
        assert v[2] == pytest.approx(np.cos(theta))
        assert np.arctan2(v[1], v[0]) == pytest.approx(np.arctan2(np.sin(phi), np.cos(phi)))


def test_direction_from_angles_broadcasts():
    theta, phi = np.linspace(0.1, 1.5, 4)[:, None], np.linspace(-3, 3, 5)
    v = direction_from_angles(theta, phi)
    assert v.shape == (4, 5, 3)
    np.testing.assert_allclose(np.linalg.norm(v, axis=-1), 1.0, rtol=1e-15)
    assert v[2, 3] == pytest.approx(direction_from_angles(theta[2, 0], phi[3]), abs=0)


def test_vectors():
    L, E, N = plane_of_incidence_vectors(0.4, np.array([0.4, -0.1]))
    assert E.shape == (2, 3)
    H = (L + E[0]) / np.linalg.norm(L + E[0])
    assert H == pytest.approx(N)
    # the documented convention: light on the -x side, positive view angles on the mirror (+x) side
    assert L[0] < 0 and E[0, 0] > 0 > E[1, 0] and L[1] == E[0, 1] == 0
    with pytest.raises(ValueError, match="theta_i"):
        plane_of_incidence_vectors(np.pi / 2, 0.0)


@given(st.floats(0, 1.5), st.floats(-1.55, 1.55), st.floats(1, 100))
def test_phong(ti, tr, c1):
    i = intensity_in_plane_of_incidence(ti, tr, "BlinnPhong1977", p_d=0.3, p_s=0.7, c1=c1)
    assert i == pytest.approx(0.3 * np.cos(ti) + 0.7 * np.cos((ti - tr) / 2) ** c1, rel=1e-10)


@given(st.floats(0.01, 1.5), st.floats(-1.55, 1.55), st.floats(1.1, 3.0), st.floats(0.1, 0.8))
def test_torrance_sparrow(ti, tr, n, c3):
    F = lambda c: fresnel_dielectric_CookTorrance1982(c, n)  # noqa: E731
    i = intensity_in_plane_of_incidence(ti, tr, "TorranceSparrow_Blinn1977", F=F, p_d=0.2,
                                        p_s=0.8, distribution="TrowbridgeReitz1975", c3=c3)
    assert i == pytest.approx(torrance_sparrow_by_hand(ti, tr, 0.2, 0.8, n, c3), rel=1e-9)


def test_below_horizon_and_shape():
    tr = np.array([[-np.pi / 2, 0.0], [np.pi / 2, 2.0]])
    i = intensity_in_plane_of_incidence(0.5, tr, "BlinnPhong1977", p_d=0.5, p_s=0.5, c1=10)
    assert i.shape == (2, 2)
    assert i[0, 0] == 0 and i[1, 0] == 0 and i[1, 1] == 0 and i[0, 1] > 0
