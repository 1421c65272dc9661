"""Tests of reflectance.geometry.texture: shininess textures t(u, v) for Blinn 1977, Fig. 8."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.optics.microfacet import (c3_texture_Blinn1977,
                                    distribution_TrowbridgeReitz_texture_Blinn1977)
from reflectance.geometry.texture import (TEXTURE_METHODS, texture, texture_sinusoid, texture_spots,
                                 texture_value_noise)

METHODS = sorted(TEXTURE_METHODS)
coordinate = st.floats(-3.0, 3.0, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(METHODS), st.lists(coordinate, min_size=1, max_size=20),
       st.lists(coordinate, min_size=1, max_size=20), st.integers(1, 9), st.integers(1, 9))
def test_range_and_periodicity(method, u, v, a, b):
    params = ({"cycles_u": a, "cycles_v": b} if method == "sinusoid"
              else {"cells_u": a, "cells_v": b})
    u, v = np.array(u)[:, None], np.array(v)[None, :]
    t = texture(u, v, method, **params)
    assert t.shape == (u.size, v.size) and t.dtype == np.float64
    assert np.all((t >= 0.0) & (t <= 1.0))
    for du, dv in ((1.0, 0.0), (-2.0, 0.0), (0.0, 1.0)):
        assert np.allclose(texture(u + du, v + dv, method, **params), t, atol=1e-9)


@pytest.mark.parametrize("method", METHODS)
def test_seam_and_shapes(method):
    v = np.linspace(0.0, 1.0, 7)
    # the seam u = 0 / u = 1 of a surface of revolution shows no step
    assert np.array_equal(texture(0.0, v, method), texture(1.0, v, method))
    # broadcasting: (3, 1) x (4,) -> (3, 4), each entry the scalar evaluation
    u = np.array([0.1, 0.5, 0.9])[:, None]
    t = texture(u, v[:4], method)
    assert t.shape == (3, 4)
    assert t[2, 1] == texture(0.9, v[1], method)
    assert np.ndim(texture(0.3, 0.4, method)) == 0
    assert texture(np.zeros((2, 0)), 0.5, method).shape == (2, 0)


@pytest.mark.parametrize("method", METHODS)
def test_deterministic(method):
    rng = np.random.default_rng(1)
    u, v = rng.random(500), rng.random(500)
    assert np.array_equal(texture(u, v, method), texture(u.copy(), v.copy(), method))
    # the value of a point does not depend on which other points are evaluated with it
    assert np.array_equal(texture(u, v, method)[::7], texture(u[::7], v[::7], method))


def test_sinusoid_is_a_product_of_sines_and_sharpens_to_a_checkerboard():
    rng = np.random.default_rng(2)
    u, v = rng.random(1000), rng.random(1000)
    expected = 0.5 + 0.5 * np.sin(2 * np.pi * 3 * u) * np.sin(2 * np.pi * 5 * v)
    assert np.allclose(texture_sinusoid(u, v, 3, 5), expected, atol=1e-12)
    # large sharpness: 1 on the squares where floor(6u) + floor(10v) is even, 0 on the others
    t = texture_sinusoid(u, v, 3, 5, sharpness=200.0)
    even = (np.floor(6 * u) + np.floor(10 * v)) % 2 == 0
    product = np.abs(np.sin(2 * np.pi * 3 * u) * np.sin(2 * np.pi * 5 * v))
    clear = product > 0.05  # away from the square edges
    assert np.allclose(t[clear & even], 1.0, atol=1e-6)
    assert np.allclose(t[clear & ~even], 0.0, atol=1e-6)


def test_spots_are_round_raised_cosines():
    # 4 x 2 cells: a spot centre at (1/8, 1/4); distance d in cell units along any direction
    r = 0.4
    angles = np.linspace(0.0, 2 * np.pi, 13)
    for d in (0.0, 0.1, 0.25, 0.39, 0.45):
        u = 1 / 8 + d * np.cos(angles) / 4
        v = 1 / 4 + d * np.sin(angles) / 2
        t = texture_spots(u, v, 4, 2, radius=r)
        expected = 0.5 * (1 + np.cos(np.pi * d / r)) if d < r else 0.0
        assert np.allclose(t, expected, atol=1e-12)


def test_value_noise_statistics_and_smoothness():
    # lattice values are uniform on [0, 1): at the lattice points of a single octave the
    # texture is those values; their mean and spread match the uniform distribution
    n = 64
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    values = texture_value_noise(i / n, j / n, cells_u=n, cells_v=n, octaves=1, seed=7)
    assert abs(values.mean() - 0.5) < 0.02
    assert abs(values.var() - 1 / 12) < 0.01
    hist, _ = np.histogram(values, bins=8, range=(0, 1))
    assert hist.min() > 0.7 * n * n / 8
    # between two lattice points the quintic blend is monotone
    x = np.linspace(0.0, 1.0, 101) / n
    row = texture_value_noise(3 / n + x, 5 / n, cells_u=n, cells_v=n, octaves=1, seed=7)
    assert np.all(np.diff(row) >= 0) or np.all(np.diff(row) <= 0)
    # C1: the one-sided slopes agree across a cell boundary
    h = 1e-7
    slope = lambda u0: (texture_value_noise(u0 + h, 0.37, octaves=3) -  # noqa: E731
                        texture_value_noise(u0 - h, 0.37, octaves=3)) / (2 * h)
    left, right = slope(0.25 - 1e-4), slope(0.25 + 1e-4)
    assert abs(left - right) < 0.05 * (abs(left) + abs(right)) + 1e-3
    # the seed changes the pattern
    a = texture_value_noise(np.linspace(0, 1, 50), 0.3, seed=0)
    b = texture_value_noise(np.linspace(0, 1, 50), 0.3, seed=1)
    assert not np.allclose(a, b)


def test_texture_drives_blinn_c3():
    # Blinn 1977, "Varying surface shininess": C3 = C_min + (1 - C_min) t, D3 normalised by C_min
    # stays <= 1 for every texture value and reaches C_min^2 ... 1 at alpha = 0
    u, v = np.meshgrid(np.linspace(0, 1, 40), np.linspace(0, 1, 20))
    c_min = 0.2
    for method in METHODS:
        c3 = c3_texture_Blinn1977(texture(u, v, method), c_min)
        assert c3.min() >= c_min and c3.max() <= 1.0
        D = distribution_TrowbridgeReitz_texture_Blinn1977(1.0, c3, c_min)
        assert np.all(D <= 1.0 + 1e-12)


@pytest.mark.parametrize("call, match", [
    (lambda: texture(0.1, 0.2, "marble"), "known: sinusoid, spots, value_noise"),
    (lambda: texture(0.1, 0.2, "spots", frequency=3), "unknown parameters"),
    (lambda: texture_sinusoid(0.1, 0.2, cycles_u=2.5), "cycles_u"),
    (lambda: texture_sinusoid(0.1, 0.2, sharpness=-1), "sharpness"),
    (lambda: texture_spots(0.1, 0.2, radius=0.6), "radius"),
    (lambda: texture_value_noise(0.1, 0.2, octaves=0), "octaves"),
    (lambda: texture_value_noise(0.1, 0.2, seed=-1), "seed"),
    (lambda: texture(np.nan, 0.2), "finite"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
