"""Brute-force ray simulation of one symmetric V-groove: the geometry behind the V-cavity G.

Torrance & Sparrow (1967) and Blinn (1977, Figs. 1-4) model the surface as long symmetric
V-grooves whose sides make equal and opposite angles alpha with the mean normal N; the facet that
reflects light from L to E is the side whose normal is ``H = (L + E)/|L + E|``. Along the groove the
geometry does not change, so every ray stays in its own plane parallel to the plane of N and H
and the problem is exactly two-dimensional once L and E are projected onto that plane (Blinn's
E', Fig. 4). This module builds the groove in that plane and traces rays through it, counting:

- ``G_shadowing``: the fraction of the H facet that a parallel beam from the light reaches (rays
  are shot through the groove opening, evenly spaced, and traced to the first side they hit);
- ``G_masking``: the fraction of the H facet (sampled evenly along its length) whose mirror
  reflection towards the eye leaves the groove without hitting the opposite side;
- ``G``: the fraction of the beam that reaches the H facet *and* escapes after reflection,
  normalised by what a fully lit facet would intercept.

Each is compared in the tests with Blinn's closed forms ``min(1, G_c)``, ``min(1, G_b)`` and
``min(1, G_b, G_c)`` (:func:`reflectance.optics.shadowing.shadowing_VCavity_Blinn1977`). The function also
returns the drawing geometry of Blinn Figs. 1-4 computed from the construction itself: groove
vertices, a subset of ray paths, the facet length ``l`` and the masked / shadowed lengths ``m``
found by the ray through the top of the opposite side.

Coordinates in the groove plane are ``(u, w)``: ``u`` along the in-plane tangent ``t`` (the
direction of H's tilt), ``w`` along N; the groove opening lies on ``w = 0`` from ``(-h, 0)`` (A) to
``(h, 0)`` (C) with the bottom vertex B at ``(0, -h tan alpha)``. Side AB has normal
``(sin alpha, cos alpha)``, i.e. H.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. Figs. 1-4.
- Torrance, K. E., & Sparrow, E. M. (1967). Theory for off-specular reflection from roughened
  surfaces. J. Opt. Soc. Am., 57(9), 1105-1114.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

__all__ = ["VGrooveSimulation", "vgroove_vertices", "simulate_vgroove"]


@dataclass(frozen=True)
class VGrooveSimulation:
    """Result of :func:`simulate_vgroove` (all 2-D points in groove-plane coordinates (u, w)).

    Attributes
    ----------
    alpha : float
        Angle between N and H (radians).
    vertices : numpy.ndarray
        (3, 2): A (top of the H facet), B (bottom), C (top of the opposite side).
    facet_length : float
        ``l``, length of the H facet AB (Blinn Fig. 3).
    H2, L2, E2 : numpy.ndarray
        (2,) unit facet normal and unit projections of L and E onto the groove plane (Blinn's E').
    basis : numpy.ndarray
        (3, 3) rows ``t`` (in-plane tangent), ``axis`` (groove direction) and ``N``, in the frame of
        the input vectors, for a top view (Blinn Fig. 2).
    G, G_masking, G_shadowing : float
        Simulated fractions (see the module docstring).
    m_masking, m_shadowing : float
        Lengths along the H facet, from B, whose reflection is masked / that is in shadow, found by
        the ray through vertex C (Blinn Figs. 3-4: ``G_b = 1 - m/l``).
    masking_point, shadowing_point : numpy.ndarray
        (2,) the point on AB where that boundary ray meets it (B when nothing is blocked).
    case : str
        Blinn Fig. 1: ``"a"`` (no attenuation), ``"b"`` (masking dominates), ``"c"`` (shadowing).
    n_rays : int
        Rays in the beam (and samples along the facet).
    ray_points : numpy.ndarray
        (n_keep, 3, 2) a subset of beam rays: entry on the opening, first hit, end (the point where
        the reflected ray is blocked on BC, or leaves through the opening; for rays that hit BC
        first, the hit point repeated).
    ray_status : numpy.ndarray
        (n_keep,) ``"escaped"``, ``"masked"`` or ``"other side"``.
    reflection_error : float
        Largest difference between the traced reflected direction and E' (a self-check; ~1e-16).
    """

    alpha: float
    vertices: np.ndarray
    facet_length: float
    H2: np.ndarray
    L2: np.ndarray
    E2: np.ndarray
    basis: np.ndarray
    G: float
    G_masking: float
    G_shadowing: float
    m_masking: float
    m_shadowing: float
    masking_point: np.ndarray
    shadowing_point: np.ndarray
    case: str
    n_rays: int
    ray_points: np.ndarray
    ray_status: np.ndarray
    reflection_error: float


def vgroove_vertices(alpha: float, half_width: float = 1.0) -> npt.NDArray[np.float64]:
    """Vertices A, B, C of a symmetric V-groove whose side AB has normal (sin alpha, cos alpha).

    Examples
    --------
    >>> import numpy as np
    >>> vgroove_vertices(np.pi / 4).round(12).tolist()
    [[-1.0, 0.0], [0.0, -1.0], [1.0, 0.0]]
    """
    if not 0 <= alpha < np.pi / 2:
        raise ValueError(f"'alpha' must lie in [0, pi/2), got {alpha!r}.")
    h = float(half_width)
    if not h > 0:
        raise ValueError(f"'half_width' must be > 0, got {half_width!r}.")
    return np.array([[-h, 0.0], [0.0, -h * np.tan(alpha)], [h, 0.0]])


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _hit_segment(origins, direction, P0, P1, eps=1e-12):
    """Ray ``origins + s direction`` (s > eps) against segment P0-P1: (hit, s)."""
    edge = P1 - P0
    denominator = _cross(direction, edge)
    if abs(denominator) < 1e-300:  # parallel: no crossing
        return np.zeros(len(origins), bool), np.full(len(origins), np.inf)
    offset = P0 - origins
    s = _cross(offset, edge) / denominator
    u = _cross(offset, direction) / denominator
    hit = (s > eps) & (u >= 0.0) & (u <= 1.0)
    return hit, np.where(hit, s, np.inf)


def _blocked_length(vertices, direction):
    """Length of AB, from B, whose ray along ``direction`` is blocked by BC (via the ray through C)."""
    A, B, C = vertices
    if direction[0] <= 0:  # heading away from BC: nothing on AB is blocked
        return 0.0, B.copy()
    # Line C - s direction meets line A + u (B - A); the boundary ray of Blinn Fig. 4.
    edge = B - A
    u = _cross(C - A, direction) / _cross(edge, direction)
    u = min(max(u, 0.0), 1.0)
    length = float(np.hypot(*edge))
    return (1.0 - u) * length, A + u * edge


def _unit(v, name):
    v = np.asarray(v, dtype=np.float64)
    if v.shape != (3,):
        raise ValueError(f"'{name}' must be a 3-vector, got shape {v.shape}.")
    norm = np.linalg.norm(v)
    if not norm > 0:
        raise ValueError(f"'{name}' must be a non-zero vector, got {v!r}.")
    return v / norm


def simulate_vgroove(L: npt.ArrayLike, E: npt.ArrayLike, N: npt.ArrayLike = (0.0, 0.0, 1.0),
                     n_rays: int = 100_000, n_keep: int = 24,
                     half_width: float = 1.0) -> VGrooveSimulation:
    """Trace a parallel beam from L through the V-groove whose facet normal is ``H = (L + E)/|L + E|``.

    Parameters
    ----------
    L, E : array_like
        3-vectors towards the light and the eye (normalised here), both above the surface.
    N : array_like
        Mean surface normal.
    n_rays : int
        Rays in the beam and samples along the facet; the counting error is about 1/n_rays.
    n_keep : int
        Number of evenly spaced beam rays whose paths are returned for drawing.
    half_width : float
        Half the width of the groove opening.

    Returns
    -------
    VGrooveSimulation

    Raises
    ------
    ValueError
        If L or E is not above the surface, or a vector is zero or not 3-D.

    References
    ----------
    - Blinn 1977, Figs. 1-4; Torrance & Sparrow 1967.

    Examples
    --------
    >>> import numpy as np
    >>> L = np.array([np.sin(1.3), 0.0, np.cos(1.3)])   # grazing light: shadowing (case c)
    >>> E = np.array([-np.sin(0.2), 0.0, np.cos(0.2)])
    >>> result = simulate_vgroove(L, E, n_rays=20000)
    >>> result.case
    'c'
    """
    L, E, N = _unit(L, "L"), _unit(E, "E"), _unit(N, "N")
    if not (L @ N > 0 and E @ N > 0):
        raise ValueError(f"L and E must be above the surface (N.L = {L @ N!r}, N.E = {E @ N!r}).")
    n_rays = int(n_rays)
    H = _unit(L + E, "L + E")
    tilt = H - (H @ N) * N
    if np.linalg.norm(tilt) > 1e-12:
        t = tilt / np.linalg.norm(tilt)
    else:  # H = N: a flat groove; any in-plane tangent will do
        helper = L - (L @ N) * N
        if np.linalg.norm(helper) < 1e-12:
            helper = np.eye(3)[np.argmin(np.abs(N))]
            helper = helper - (helper @ N) * N
        t = helper / np.linalg.norm(helper)
    axis = np.cross(N, t)
    alpha = float(np.arctan2(H @ t, H @ N))
    H2 = np.array([np.sin(alpha), np.cos(alpha)])
    L2 = np.array([L @ t, L @ N])
    E2 = np.array([E @ t, E @ N])
    L2, E2 = L2 / np.linalg.norm(L2), E2 / np.linalg.norm(E2)
    vertices = vgroove_vertices(alpha, half_width)
    A, B, C = vertices
    length = float(np.hypot(*(B - A)))
    basis = np.array([t, axis, N])

    if alpha < 1e-9:  # no groove: nothing can be blocked
        entry = np.column_stack([np.linspace(-half_width, half_width, n_keep), np.zeros(n_keep)])
        points = np.stack([entry, entry, entry + E2], axis=1)
        return VGrooveSimulation(
            alpha, vertices, length, H2, L2, E2, basis, 1.0, 1.0, 1.0, 0.0, 0.0, B.copy(), B.copy(),
            "a", n_rays, points, np.full(n_keep, "escaped"), 0.0,
        )

    # --- the beam: evenly spaced rays through the opening, travelling along -L' ---
    dx = 2.0 * half_width / n_rays
    entry = np.column_stack([-half_width + (np.arange(n_rays) + 0.5) * dx, np.zeros(n_rays)])
    d = -L2
    hit_AB, s_AB = _hit_segment(entry, d, A, B)
    hit_BC, s_BC = _hit_segment(entry, d, B, C)
    on_facet = hit_AB & (s_AB <= s_BC)
    hits = entry + np.where(on_facet, s_AB, s_BC)[:, None] * d
    reflected = d - 2.0 * (d @ H2) * H2  # mirror reflection on the H facet
    reflection_error = float(np.max(np.abs(reflected - E2)))
    masked, s_mask = _hit_segment(hits, reflected, B, C)
    escaped = on_facet & ~masked
    # Rays a fully lit facet would intercept: its projected width over the rays' spacing.
    n_full = length * (L2 @ H2) / (dx * L2[1])
    G_shadowing = float(np.count_nonzero(on_facet) / n_full)
    G = float(np.count_nonzero(escaped) / n_full)

    # --- masking alone: evenly spaced points along the facet, reflected towards E' ---
    samples = A + ((np.arange(n_rays) + 0.5) / n_rays)[:, None] * (B - A)
    masked_sample, _ = _hit_segment(samples, E2, B, C)
    G_masking = float(1.0 - np.count_nonzero(masked_sample) / n_rays)

    # --- construction of Blinn Figs. 3-4: the boundary ray through C ---
    m_masking, masking_point = _blocked_length(vertices, E2)
    m_shadowing, shadowing_point = _blocked_length(vertices, L2)
    if m_masking <= 0 and m_shadowing <= 0:
        case = "a"
    else:
        case = "b" if m_masking >= m_shadowing else "c"

    # --- a few ray paths to draw ---
    keep = np.linspace(0, n_rays - 1, n_keep).round().astype(int)
    exit_s = -hits[keep, 1] / np.where(reflected[1] > 0, reflected[1], 1.0)  # reach w = 0
    end = hits[keep] + np.where(masked[keep], s_mask[keep], exit_s)[:, None] * reflected
    end = np.where(on_facet[keep][:, None], end, hits[keep])
    ray_points = np.stack([entry[keep], hits[keep], end], axis=1)
    ray_status = np.where(on_facet[keep], np.where(masked[keep], "masked", "escaped"), "other side")

    return VGrooveSimulation(
        alpha, vertices, length, H2, L2, E2, basis, G, G_masking, G_shadowing, m_masking,
        m_shadowing, masking_point, shadowing_point, case, n_rays, ray_points, ray_status,
        reflection_error,
    )
