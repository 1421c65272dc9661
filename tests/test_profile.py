"""2-D height profiles (reflectance.papers.profile): visibility against rays marched here by brute force,
against the V-groove's closed form, and the projected-area identity of G1."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from reflectance.papers.profile import (crossings, first_blocker, first_hit, gaussian_profile, masking_G1,
                                 projected_length, trace_window, visible_fraction,
                                 visible_fraction_by_slope)


def ray_against_polyline(xs, hs, origin, d):
    """Nearest point (s > 1e-9) where the ray origin + s d meets the polyline (xs, hs), or None."""
    p0 = np.stack([xs[:-1], hs[:-1]], 1)
    e = np.stack([np.diff(xs), np.diff(hs)], 1)
    den = d[0] * e[:, 1] - d[1] * e[:, 0]
    w = p0 - origin
    with np.errstate(divide="ignore", invalid="ignore"):
        s = (w[:, 0] * e[:, 1] - w[:, 1] * e[:, 0]) / den
        u = (w[:, 0] * d[1] - w[:, 1] * d[0]) / den
    ok = (den != 0) & (s > 1e-9) & (u >= 0) & (u <= 1)
    return None if not ok.any() else origin + s[ok].min() * d


def brute_force_visible(h, theta, k, samples=40):
    """Visible fraction of segment k of the periodic unit-spaced polyline h from direction
    (sin theta, cos theta): march each sample point's ray against every segment of three periods."""
    n = h.size
    x = np.arange(-n, 2 * n + 1)
    y = h[x % n]
    d = np.array([math.sin(theta), math.cos(theta)])
    seen = 0
    for t in (np.arange(samples) + 0.5) / samples:
        o = np.array([k + t, h[k] + t * (h[(k + 1) % n] - h[k])])
        if d[1] - (h[(k + 1) % n] - h[k]) * d[0] <= 0:  # facing away: (1, slope) x d <= 0
            continue
        seen += ray_against_polyline(x.astype(float), y, o, d) is None
    return seen / samples


def zigzag(n, slope):
    """n nodes alternating 0, slope: segments of slope +slope and -slope (a row of V-grooves)."""
    return np.where(np.arange(n) % 2 == 0, 0.0, slope)


# --- the profile ---------------------------------------------------------------------------------

def test_visible_fraction_against_brute_force_rays():
    h = gaussian_profile(64, 4.0, 0.8, 7)[0]
    for theta in (math.radians(60), math.radians(-75), math.radians(30)):
        fast = visible_fraction(h, theta)
        for k in range(h.size):
            assert fast[k] == pytest.approx(brute_force_visible(h, theta, k), abs=1.0 / 40 + 1e-9), (theta, k)


def test_gaussian_profile_statistics():
    h, p = gaussian_profile(2**16, 8.0, 0.5, seed=3)
    assert np.sqrt(np.mean(p * p)) == pytest.approx(0.5, rel=1e-12)
    np.testing.assert_allclose(p, np.roll(h, -1) - h, rtol=0, atol=1e-12)  # periodic segments
    z = (h - h.mean()) / h.std()
    assert abs(np.mean(z**3)) < 0.1 and abs(np.mean(z**4) - 3) < 0.2  # Gaussian heights
    # Autocorrelation exp(-(dx/l)^2), estimated by circular correlation over the whole period
    acf = np.fft.irfft(np.abs(np.fft.rfft(h - h.mean())) ** 2, h.size)
    assert acf[8] / acf[0] == pytest.approx(math.exp(-1), abs=0.05)
    assert acf[16] / acf[0] == pytest.approx(math.exp(-4), abs=0.05)


def test_gaussian_profile_is_seeded():
    a, b, c = (gaussian_profile(256, 4.0, 0.3, seed)[0] for seed in (1, 1, 2))
    np.testing.assert_array_equal(a, b)
    assert not np.allclose(a, c)


@pytest.mark.parametrize("args,name", [((1, 4.0, 0.5, 0), "'n'"), ((64, 0.0, 0.5, 0), "correlation_length"),
                                       ((64, 4.0, -1.0, 0), "rms_slope"), ((64, np.nan, 0.5, 0), "correlation_length")])
def test_gaussian_profile_bad_arguments(args, name):
    with pytest.raises(ValueError, match=name):
        gaussian_profile(*args)


@given(st.floats(-5, 5), st.floats(-1.5, 1.5))
def test_projected_length_is_length_times_facing_cosine(p, theta):
    normal = np.array([-p, 1.0]) / math.hypot(1.0, p)
    d = np.array([math.sin(theta), math.cos(theta)])
    assert projected_length(p, theta) == pytest.approx(math.hypot(1.0, p) * max(0.0, normal @ d), abs=1e-12)


# --- visibility against the V-groove ---------------------------------------------------------------

@settings(max_examples=60)
@given(st.floats(0.1, 2.0), st.floats(-1.45, 1.45))
def test_zigzag_visibility_is_the_v_groove_closed_form(slope, theta):
    # A facet of normal H = (sin a, cos a) in a symmetric groove, seen from V: visible fraction
    # min(1, 2 (N.H)(N.V) / (V.H)) while V.H > 0 (Blinn 1977, G_b), written out with angles.
    # not so grazing that a ray crosses a whole 16-sample period (visible_fraction refuses: below)
    assume(16 * math.cos(theta) > slope * abs(math.sin(theta)))
    vis = visible_fraction(zigzag(16, slope), theta)
    a = math.atan(slope)
    rising = math.cos(theta + a)  # V.H of the rising facets (normal tilted to -x)
    falling = math.cos(theta - a)
    expected = [min(1.0, 2 * math.cos(a) * math.cos(theta) / c) if c > 1e-12 else 0.0 for c in (rising, falling)]
    np.testing.assert_allclose(vis[0::2], expected[0], atol=1e-9)
    np.testing.assert_allclose(vis[1::2], expected[1], atol=1e-9)


def test_too_grazing_is_refused():
    with pytest.raises(ValueError, match="too grazing"):
        visible_fraction(zigzag(4, 2.0), math.radians(89))


@pytest.mark.parametrize("theta", [0.0, 0.4, -0.9, 1.3])
def test_visible_projected_length_is_n_cos_theta(theta):
    # Heitz 2014: the projected area of the visible microsurface is that of the geometric surface.
    h, p = gaussian_profile(4096, 6.0, 0.6, seed=11)
    G1, check = masking_G1(h, p, theta)
    assert check == pytest.approx(1.0, abs=1e-9)
    assert 0 < G1 <= 1


@pytest.mark.parametrize("slope,theta_deg", [(1.0, 30.0), (0.5, 70.0), (1.0, 60.0), (2.0, -50.0)])
def test_masking_G1_of_a_zigzag_by_hand(slope, theta_deg):
    # Seen from the right, the rising walls of the grooves turn away from the viewer, the falling
    # ones towards it; only those are masked, by min(1, 2 cos a cos theta / cos(theta - a)).
    t, a = math.radians(abs(theta_deg)), math.atan(slope)
    proj_away, proj_towards = max(0.0, math.cos(t) - slope * math.sin(t)), math.cos(t) + slope * math.sin(t)
    vis_towards = min(1.0, 2 * math.cos(a) * math.cos(t) / math.cos(t - a))
    expected = (proj_away + vis_towards * proj_towards) / (proj_away + proj_towards)
    G1, _ = masking_G1(zigzag(8, slope), np.where(np.arange(8) % 2 == 0, slope, -slope), math.radians(theta_deg))
    assert G1 == pytest.approx(expected, rel=1e-12)


def test_visible_fraction_by_slope():
    h, p = gaussian_profile(2048, 6.0, 0.6, seed=5)
    one_bin, count = visible_fraction_by_slope(h, p, 0.8, [-100.0, 100.0])
    assert one_bin[0] == pytest.approx(masking_G1(h, p, 0.8)[0], rel=1e-12) and count[0] == p.size
    edges = np.linspace(-1.8, 1.8, 13)
    fraction, count = visible_fraction_by_slope(h, p, 0.8, edges)
    assert count.sum() == np.sum((p >= edges[0]) & (p < edges[-1]))
    for i in range(12):  # each bin by hand: facing facets of the bin, weighted by projected length
        inside = (p >= edges[i]) & (p < edges[i + 1]) & (np.cos(0.8) - p * np.sin(0.8) > 0)
        if not inside.any():
            assert np.isnan(fraction[i])
            continue
        w = (np.cos(0.8) - p * np.sin(0.8))[inside]
        assert fraction[i] == pytest.approx(np.sum(visible_fraction(h, 0.8)[inside] * w) / w.sum(), rel=1e-12)


# --- single rays ------------------------------------------------------------------------------------

def test_crossings_of_a_ramp():
    xs = np.arange(11.0)
    hs = 0.5 * xs
    s0 = np.array([1.0, 4.5, 7.0])
    x, h = crossings(xs, hs, xs + 2.0 * hs, s0)  # lines x + 2h = s0 meet h = x/2 at x = s0 / 2
    for i, value in enumerate(s0):
        got = x[i][~np.isnan(x[i])]
        assert got == pytest.approx([value / 2]) and h[i][~np.isnan(h[i])] == pytest.approx([value / 4])


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_first_hit_and_first_blocker_against_brute_force(seed):
    rng = np.random.default_rng(seed)
    xs = np.arange(40.0)
    hs = rng.normal(0.0, 1.5, xs.size)
    for theta in (math.radians(-50), math.radians(35), math.radians(-70)):
        d = np.array([math.sin(theta), math.cos(theta)])
        x0 = np.linspace(12.0, 28.0, 23)
        hx, hh = first_hit(xs, hs, x0, theta)
        for x, h, start in zip(hx, hh, x0):  # come down towards -d from high above (x0, 0)
            top = np.array([start, 0.0]) + 100.0 * d
            expected = ray_against_polyline(xs, hs, top, -d)
            assert (x, h) == pytest.approx(tuple(expected), abs=1e-9)
        bx, bh = first_blocker(xs, hs, hx, hh, -theta)  # on from each hit, towards the other side
        for x, h, b in zip(hx, hh, zip(bx, bh)):
            expected = ray_against_polyline(xs, hs, np.array([x, h]), np.array([-d[0], d[1]]))
            if expected is None or not 0 < expected[0] < xs[-1]:
                assert np.isnan(b[0])
            else:
                assert b == pytest.approx(tuple(expected), abs=1e-9)


def test_trace_window():
    h, p = gaussian_profile(1024, 8.0, 0.5, seed=1977)
    ti, to = math.radians(60), math.radians(70)
    rays = trace_window(h, p, (100, 160), -ti, to, 25)
    assert rays.hit.shape == rays.masked_at.shape == (25, 2)
    # every hit lies on the profile and on its ray x + h tan(theta_i) = x0
    np.testing.assert_allclose(rays.hit[:, 1], np.interp(rays.hit[:, 0], rays.x, rays.h), atol=1e-9)
    x0 = 100 + (np.arange(25) + 0.5) * 60 / 25
    np.testing.assert_allclose(rays.hit[:, 0] + rays.hit[:, 1] * math.tan(ti), x0, atol=1e-9)
    d_view = np.array([math.sin(to), math.cos(to)])
    for (x, y), faces, escaped in zip(rays.hit, rays.faces_view, rays.escaped):
        blocked = ray_against_polyline(rays.x, rays.h, np.array([x, y]), d_view) is not None
        assert escaped == (faces and not blocked)
    np.testing.assert_array_equal(rays.lit, visible_fraction(h, -ti)[np.arange(rays.x[0], rays.x[-1]).astype(int) % 1024])
    flat = trace_window(np.zeros(64), np.zeros(64), (10, 20), -1.0, 1.0, 5)
    assert flat.escaped.all() and flat.shadowed.shape == (0, 2)


def test_trace_window_bad_arguments():
    h, p = gaussian_profile(64, 4.0, 0.3, 0)
    with pytest.raises(ValueError, match="window"):
        trace_window(h, p, (10, 80), -0.5, 0.5, 4)
    with pytest.raises(ValueError, match="theta_light < 0"):
        trace_window(h, p, (10, 20), 0.5, 0.5, 4)
