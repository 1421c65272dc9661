"""2-D microfacet height profiles: a seeded random surface, what a direction sees of it, and its G1.

A profile is a periodic polyline of heights ``h`` at unit spacing in x: node ``k`` sits at
``(k, h[k])`` and segment (facet) ``k`` joins nodes ``k`` and ``k + 1`` with slope
``p[k] = h[k + 1] - h[k]`` (the last segment wraps round to node 0). Its mean normal is +h.

Directions are signed angles ``theta`` from the mean normal, positive towards +x:
``d = (sin theta, cos theta)``. A light at ``-theta_i`` lies to the upper left, a viewer at
``+theta_o`` to the upper right. With that one convention:

- :func:`gaussian_profile`: Gaussian heights with a Gaussian autocorrelation, scaled to an rms slope.
- :func:`projected_length`: each facet's length projected across ``d`` (0 if it faces away).
- :func:`visible_fraction`: the fraction of each facet seen from ``d`` (exact, by a running maximum).
- :func:`masking_G1`: the masking of the whole profile, visible over facing projected length: the
  G1 of microfacet theory (Heitz 2014, the visible projected area), and the identity that the
  visible projected length of any periodic profile is ``n cos theta``.
- :func:`visible_fraction_by_slope`: the same weighted average within bins of facet slope (Smith's
  G1 assumes it does not depend on the slope).
- :func:`crossings`, :func:`first_hit`, :func:`first_blocker`: single rays against a stretch of
  the profile (which facet a light ray reaches, what masks or shadows a point), and
  :func:`trace_window`, which follows a row of light rays through a window of the profile to the
  facet they reach and on towards the viewer, for drawing.

References
----------
- Smith, B. G. (1967). Geometrical shadowing of a random rough surface. IEEE Transactions on
  Antennas and Propagation, 15(5), 668-671.
- Walter, B., Marschner, S. R., Li, H., & Torrance, K. E. (2007). Microfacet Models for Refraction
  through Rough Surfaces. Eurographics Symposium on Rendering. (Smith G1 for Beckmann slopes.)
- Heitz, E. (2014). Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs.
  Journal of Computer Graphics Techniques, 3(2), 48-107. (G1 as visible projected area; the
  projected area of the visible microsurface equals that of the geometric surface.)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

__all__ = [
    "gaussian_profile",
    "blocking_point",
    "projected_length",
    "visible_fraction",
    "masking_G1",
    "visible_fraction_by_slope",
    "crossings",
    "first_hit",
    "first_blocker",
    "WindowRays",
    "trace_window",
]


def gaussian_profile(n: int, correlation_length: float, rms_slope: float,
                     seed: int) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """A periodic random profile: Gaussian heights, autocorrelation ``~ exp(-(dx/l)^2)``.

    White noise is filtered by the square root of the power spectrum of ``exp(-(dx/l)^2)``, which is
    ``~ exp(-(pi f l)^2)``; the heights are then scaled so that the rms of the segment slopes is
    exactly ``rms_slope``.

    Parameters
    ----------
    n : int
        Number of samples (one period), >= 2.
    correlation_length : float
        ``l`` in samples, > 0.
    rms_slope : float
        Root mean square of the slopes ``p``, > 0.
    seed : int
        Seed of :func:`numpy.random.default_rng`: the same seed gives the same profile.

    Returns
    -------
    h, p : numpy.ndarray
        Heights at the ``n`` nodes and slopes of the ``n`` segments ``[k, k + 1]``.

    Examples
    --------
    >>> h, p = gaussian_profile(1024, 8.0, 0.5, seed=1)
    >>> print(f"{np.sqrt(np.mean(p * p)):.12f}")
    0.500000000000
    """
    n = int(n)
    if n < 2:
        raise ValueError(f"'n' (samples of the profile) must be >= 2, got {n!r}.")
    for name, value in (("correlation_length", correlation_length), ("rms_slope", rms_slope)):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"'{name}' must be finite and > 0, got {value!r}.")
    f = np.fft.rfftfreq(n)
    white = np.fft.rfft(np.random.default_rng(seed).standard_normal(n))
    h = np.fft.irfft(white * np.exp(-0.5 * (np.pi * f * correlation_length) ** 2), n)
    p = np.roll(h, -1) - h
    scale = rms_slope / np.sqrt(np.mean(p * p))
    return h * scale, p * scale


def projected_length(p: npt.ArrayLike, theta: float) -> npt.NDArray[np.float64]:
    """Length of each facet of slope ``p`` projected across direction ``theta``, 0 if it faces away.

    A facet of slope p has length ``sqrt(1 + p^2)`` and unit normal ``(-p, 1) / sqrt(1 + p^2)``;
    length times ``max(0, normal . d)`` is ``max(0, cos theta - p sin theta)``.

    Examples
    --------
    >>> projected_length(np.array([0.0, 1.0, -1.0]), np.pi / 4).round(6).tolist()
    [0.707107, 0.0, 1.414214]
    """
    return np.maximum(np.cos(theta) - np.asarray(p, dtype=np.float64) * np.sin(theta), 0.0)


def visible_fraction(h: npt.NDArray[np.float64], theta: float) -> npt.NDArray[np.float64]:
    """Fraction of each segment ``[k, k + 1]`` of the periodic profile ``h`` seen from ``theta``.

    A point is hidden iff a node ahead of it (towards the direction) has a larger
    ``g = h - x cot(theta)``; g is linear on each segment, so comparing with the running maximum of
    g over the nodes ahead (two periods) gives the exact visible part of every segment. Segments
    facing away from the direction get 0.

    Parameters
    ----------
    h : numpy.ndarray
        Heights of one period at unit spacing.
    theta : float
        Signed angle of the direction from the mean normal (radians), positive towards +x.

    Raises
    ------
    ValueError
        If ``theta`` is so grazing that a ray could cross more than one period
        (``n cot |theta| <= max(h) - min(h)``).

    Examples
    --------
    >>> # zigzag of slopes +-1 seen at 60 degrees: the rising facets face away, the falling ones are
    >>> # partly masked by the next rise (the V-groove's 2 cos 45 cos 60 / cos 15)
    >>> visible_fraction(np.array([0.0, 1.0, 0.0, 1.0]), np.radians(60)).round(6).tolist()
    [0.0, 0.732051, 0.0, 0.732051]
    """
    h = np.asarray(h, dtype=np.float64)
    if theta < 0:  # mirror x -> -x: node i <- node -i, segment k <- segment n - 1 - k
        return visible_fraction(np.roll(h[::-1], 1), -theta)[::-1]
    n, cot = h.size, np.cos(theta) / max(np.sin(theta), 1e-300)
    if n * cot <= np.ptp(h):
        raise ValueError(f"theta = {np.degrees(theta):.3g} deg is too grazing for a profile of "
                         f"{n} samples (n_samples x cot(theta) must exceed the height range)")
    x = np.arange(2 * n + 1)
    g = h[x % n] - x * cot
    ahead = np.maximum.accumulate(g[::-1])[::-1][1:n + 1]  # max of g over nodes k+1 .. 2n
    g0, drop = g[:n], g[:n] - g[1:n + 1]  # drop > 0: the segment faces the direction
    return np.where(drop > 0, np.clip((g0 - ahead) / np.where(drop > 0, drop, 1.0), 0, 1), 0.0)


def masking_G1(h: npt.NDArray[np.float64], p: npt.NDArray[np.float64],
               theta: float) -> tuple[float, float]:
    """Masking of the whole profile from ``theta``: visible over facing projected length.

    Returns
    -------
    G1 : float
        ``sum(visible fraction x projected length) / sum(projected length)`` (Heitz 2014, G1 as the
        visible share of the projected area of the facets facing the direction).
    visible_over_n_cos : float
        The visible projected length over ``n cos theta``: 1 for any periodic profile, since
        every ray from the direction meets it exactly once (a check of the visibility).

    Examples
    --------
    >>> G1, check = masking_G1(np.zeros(8), np.zeros(8), 0.7)  # flat: nothing is masked
    >>> print(f"{G1:.6f} {check:.6f}")
    1.000000 1.000000
    """
    proj = projected_length(p, theta)
    seen = np.sum(visible_fraction(h, theta) * proj)
    return seen / np.sum(proj), seen / (np.size(h) * np.cos(theta))


def visible_fraction_by_slope(h: npt.NDArray[np.float64], p: npt.NDArray[np.float64], theta: float,
                              edges: npt.ArrayLike
                             ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.intp]]:
    """Projected-length weighted visible fraction of the facing facets in each slope bin.

    Parameters
    ----------
    h, p : numpy.ndarray
        Heights and slopes of the profile (see :func:`gaussian_profile`).
    theta : float
        Signed direction (radians).
    edges : array_like
        Increasing slope bin edges; bin i holds ``edges[i] <= p < edges[i + 1]``.

    Returns
    -------
    fraction : numpy.ndarray
        Per bin; NaN where no facet of the bin faces the direction.
    count : numpy.ndarray
        Number of facets per bin (facing or not).

    Examples
    --------
    >>> f, c = visible_fraction_by_slope(np.zeros(4), np.zeros(4), 0.3, [-1.0, -0.5, 0.5, 1.0])
    >>> f.tolist(), c.tolist()
    ([nan, 1.0, nan], [0, 4, 0])
    """
    edges = np.asarray(edges, dtype=np.float64)
    nb = edges.size - 1
    b = np.digitize(p, edges) - 1
    inside = (b >= 0) & (b < nb)
    proj = projected_length(p, theta)
    w = inside & (proj > 0)
    total = np.bincount(b[w], proj[w], nb)
    seen = np.bincount(b[w], (visible_fraction(h, theta) * proj)[w], nb)
    return seen / np.where(total > 0, total, np.nan), np.bincount(b[inside], minlength=nb)


def crossings(xs: npt.NDArray[np.float64], hs: npt.NDArray[np.float64], s: npt.ArrayLike,
              s0: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Points where the polyline ``(xs, hs)`` (unit x spacing) crosses each ray ``s = s0``.

    ``s`` is the value at the nodes of a quantity that is constant along the rays and linear in
    (x, h), e.g. ``x - h tan(theta)`` for rays along direction theta.

    Returns
    -------
    x, h : numpy.ndarray
        Shape ``(len(s0), len(xs) - 1)``: the crossing on each segment, NaN where there is none.

    Examples
    --------
    >>> xs, hs = np.arange(4.0), np.array([0.0, 1.0, 0.0, 1.0])
    >>> x, h = crossings(xs, hs, hs, np.array([0.5]))  # the level h = 0.5
    >>> x.round(3).tolist(), h.round(3).tolist()
    ([[0.5, 1.5, 2.5]], [[0.5, 0.5, 0.5]])
    """
    xs, hs, s = (np.asarray(v, dtype=np.float64) for v in (xs, hs, s))
    s0 = np.asarray(s0, dtype=np.float64)
    a, b = s[:-1], s[1:]
    t = (s0[:, None] - a) / np.where(b != a, b - a, 1.0)
    ok = (b != a) & (t >= 0) & (t < 1)
    return np.where(ok, xs[:-1] + t, np.nan), np.where(ok, hs[:-1] + t * (hs[1:] - hs[:-1]), np.nan)


def first_hit(xs: npt.NDArray[np.float64], hs: npt.NDArray[np.float64], x0: npt.NDArray[np.float64],
              theta: float) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Where rays coming down from direction ``theta`` first meet the polyline ``(xs, hs)``.

    Each ray is the line through ``(x0, 0)`` along ``(sin theta, cos theta)``; travelling down it
    from above, the highest crossing is met first.

    Returns
    -------
    x, h : numpy.ndarray
        Shape of ``x0``.

    Examples
    --------
    >>> xs, hs = np.arange(4.0), np.array([0.0, 0.0, 2.0, 0.0])
    >>> x, h = first_hit(xs, hs, np.array([0.5, 3.0]), -np.pi / 4)  # light from the upper left
    >>> x.round(4).tolist(), h.round(4).tolist()  # the floor before the bump; the bump's rising side
    ([0.5, 1.6667], [0.0, 1.3333])
    """
    x0 = np.asarray(x0, dtype=np.float64)
    hx, hh = crossings(xs, hs, xs - hs * np.tan(theta), x0)
    k = np.nanargmax(hh, axis=1)
    return hx[np.arange(x0.size), k], hh[np.arange(x0.size), k]


def blocking_point(xs: npt.NDArray[np.float64], hs: npt.NDArray[np.float64], x: float, y: float,
                   direction: Sequence[float], step: float = 0.01) -> tuple[float, float] | None:
    """By brute force, the first point of the polyline ``(xs, hs)`` on the ray from ``(x, y)``
    along the unit ``direction``: marching in steps of ``step`` until the profile reaches the ray.
    None where the ray leaves the polyline's x range or rises above its highest point first.

    Examples
    --------
    >>> xs, hs = np.arange(4.0), np.array([0.0, 0.0, 2.0, 0.0])
    >>> [round(v, 1) for v in blocking_point(xs, hs, 0.5, 0.0, (np.sqrt(0.5), np.sqrt(0.5)))]
    [1.5, 1.0]
    >>> blocking_point(xs, hs, 2.5, 1.0, (np.sqrt(0.5), np.sqrt(0.5))) is None
    True
    """
    t = np.arange(step, np.hypot(np.ptp(xs), np.ptp(hs)) + step, step)
    rx, ry = x + t * direction[0], y + t * direction[1]
    inside = (rx >= xs[0]) & (rx <= xs[-1]) & (ry <= hs.max())
    if not inside.all():  # past the end or above every peak: nothing further can block it
        stop = np.argmin(inside)
        rx, ry = rx[:stop], ry[:stop]
    met = np.nonzero(np.interp(rx, xs, hs) >= ry)[0]
    return (float(rx[met[0]]), float(np.interp(rx[met[0]], xs, hs))) if met.size else None


def first_blocker(xs: npt.NDArray[np.float64], hs: npt.NDArray[np.float64],
                  x0: npt.NDArray[np.float64], h0: npt.NDArray[np.float64],
                  theta: float) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """First point of the polyline ``(xs, hs)`` on the ray from each ``(x0, h0)`` towards ``theta``.

    Returns
    -------
    x, h : numpy.ndarray
        Shape of ``x0``; NaN where the ray escapes (nothing of the polyline blocks it).

    Examples
    --------
    >>> xs, hs = np.arange(4.0), np.array([0.0, 0.0, 2.0, 0.0])
    >>> x, h = first_blocker(xs, hs, np.array([0.5, 2.5]), np.array([0.0, 1.0]), np.pi / 4)
    >>> x.round(12).tolist(), h.round(12).tolist()  # 1st ray meets the bump, 2nd escapes
    ([1.5, nan], [1.0, nan])
    """
    side = np.sign(theta)
    x0, h0 = np.asarray(x0, dtype=np.float64), np.asarray(h0, dtype=np.float64)
    tan = np.tan(abs(theta))
    bx, bh = crossings(xs, hs, xs - side * hs * tan, x0 - side * h0 * tan)
    bx = np.where(side * (bx - x0[:, None]) > 1e-9, bx, np.nan)
    j = np.argmin(np.nan_to_num(side * bx, nan=np.inf), axis=1)
    return bx[np.arange(x0.size), j], bh[np.arange(x0.size), j]


@dataclass(frozen=True)
class WindowRays:
    """Light rays through a window of a profile (see :func:`trace_window`); points are (x, h).

    Attributes
    ----------
    x, h : numpy.ndarray
        The nodes of the window and a margin either side, unwrapped (x continues past the period).
    slope, lit, seen : numpy.ndarray
        Per segment of ``x, h``: its slope and its visible fraction from the light and the viewer
        (:func:`visible_fraction`).
    hit : numpy.ndarray
        (n_rays, 2): where each light ray first meets the profile.
    faces_view : numpy.ndarray
        (n_rays,) bool: the facet hit faces the viewer.
    masked_at : numpy.ndarray
        (n_rays, 2): the first point of the profile on the way from ``hit`` to the viewer; NaN where
        the reflected ray escapes.
    shadowed, occluder : numpy.ndarray
        (k, 2): the points of the profile below the rays' entries whose facet faces the light but is
        in shadow, and the first point of the profile on the way from each towards the light.
    """

    x: np.ndarray
    h: np.ndarray
    slope: np.ndarray
    lit: np.ndarray
    seen: np.ndarray
    hit: np.ndarray
    faces_view: np.ndarray
    masked_at: np.ndarray
    shadowed: np.ndarray
    occluder: np.ndarray

    @property
    def escaped(self) -> npt.NDArray[np.bool_]:
        """(n_rays,) bool: the ray reaches a facet facing the viewer and nothing masks it."""
        return self.faces_view & np.isnan(self.masked_at[:, 0])


def trace_window(h: npt.NDArray[np.float64], p: npt.NDArray[np.float64], window: Sequence[int],
                 theta_light: float, theta_view: float, n_rays: int) -> WindowRays:
    """Follow ``n_rays`` light rays, evenly spaced across ``window``, to the profile and on.

    The rays enter through ``(x0, 0)`` for ``x0`` evenly spaced over ``window`` and travel away from
    the light; each is followed to the first facet it meets, and from there towards the viewer to
    the first facet that masks it. Independently of :func:`visible_fraction`, so that the two can
    be compared (``escaped`` against ``seen`` of the facet hit).

    Parameters
    ----------
    h, p : numpy.ndarray
        Heights and slopes of the periodic profile (see :func:`gaussian_profile`).
    window : sequence of 2 ints
        ``(first, last)`` nodes, ``0 <= first < last <= len(h)``.
    theta_light, theta_view : float
        Signed directions (radians): the light on the left (< 0), the viewer on the right (> 0).
    n_rays : int
        Number of light rays.

    Returns
    -------
    WindowRays

    Raises
    ------
    ValueError
        For a window outside the profile, or the light not on the left and the viewer on the right.

    Examples
    --------
    >>> rays = trace_window(np.zeros(16), np.zeros(16), (4, 8), -0.5, 0.5, 4)  # flat: all escape
    >>> rays.hit[:, 0].tolist(), rays.escaped.tolist()
    ([4.5, 5.5, 6.5, 7.5], [True, True, True, True])
    """
    w0, w1 = window
    if not 0 <= w0 < w1 <= np.size(h):
        raise ValueError(f"window: need 0 <= first < last <= n_samples ({np.size(h)}), got {window}")
    if not theta_light < 0 < theta_view:
        raise ValueError(f"need the light on the left (theta_light < 0) and the viewer on the right "
                         f"(theta_view > 0), got {theta_light!r}, {theta_view!r}")
    margin = int(np.ceil(np.ptp(h) * max(np.tan(-theta_light), np.tan(theta_view)))) + 2
    idx = np.arange(w0 - margin, w1 + margin + 1)
    xs, hs, segment = idx.astype(float), h[idx % h.size], idx[:-1] % h.size
    slope = p[segment]
    lit = visible_fraction(h, theta_light)[segment]
    seen = visible_fraction(h, theta_view)[segment]
    x0 = w0 + (np.arange(n_rays) + 0.5) * (w1 - w0) / n_rays
    hit = np.column_stack(first_hit(xs, hs, x0, theta_light))
    masked_at = np.column_stack(first_blocker(xs, hs, hit[:, 0], hit[:, 1], theta_view))
    faces_view = slope[np.floor(hit[:, 0]).astype(int) - idx[0]] < 1 / np.tan(theta_view)
    j = np.floor(x0).astype(int) - idx[0]
    dark = (lit[j] < 0.5) & (slope[j] > 1 / np.tan(theta_light))  # in shadow, facing the light
    shadowed = np.column_stack([x0[dark], np.interp(x0[dark], xs, hs)])
    occluder = np.column_stack(first_blocker(xs, hs, shadowed[:, 0], shadowed[:, 1], theta_light))
    return WindowRays(xs, hs, slope, lit, seen, hit, faces_view, masked_at, shadowed, occluder)
