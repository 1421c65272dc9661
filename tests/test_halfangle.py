"""Blinn's half-value angle beta from c3: against a root of D3 = 1/2 and the forward conversion."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.optimize import brentq

from reflectance.halfangle import C3_MAX_FOR_BETA, c3_to_beta_Blinn1977
from reflectance.microfacet import beta_to_c3_Blinn1977


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


def test_paper_parameters():
    # Blinn 1977 Figs. 7a, 7b: c3 = 0.5 (aluminium), 0.35 (MgO); beta by bisection in degrees.
    for c3 in (0.5, 0.35):
        root = brentq(lambda a: d3_by_hand(a, c3) - 0.5, 1e-9, np.pi / 2, xtol=1e-14)
        assert np.degrees(c3_to_beta_Blinn1977(c3)) == pytest.approx(np.degrees(root), abs=1e-9)
    # D3 at 90 degrees is c3^4: the largest c3 with a half-value angle has c3^4 = 1/2.
    assert C3_MAX_FOR_BETA**4 == pytest.approx(0.5)


def test_shapes():
    c3 = np.array([[0.1, 0.3], [0.5, 0.7]])
    out = c3_to_beta_Blinn1977(c3)
    assert out.shape == (2, 2)
    assert out[1, 0] == c3_to_beta_Blinn1977(0.5)
    assert isinstance(c3_to_beta_Blinn1977(0.5), np.floating)


@pytest.mark.parametrize("bad", [0.0, -0.2, C3_MAX_FOR_BETA, 0.9, 1.0, np.nan, np.inf])
def test_bad_c3_raises(bad):
    with pytest.raises(ValueError, match="c3"):
        c3_to_beta_Blinn1977(bad)
