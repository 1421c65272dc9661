"""The angles of a BRDF, drawn: ``f(lambda, phi_i, theta_i, phi_v, theta_v)`` (the lecture's "BRDF"
slide): the surface, its normal N, the light direction L at (theta_i, phi_i) and the view direction
V at (theta_v, phi_v), with their projections on the surface and the four angles as arcs.

- :func:`draw_brdf_angles`: onto a matplotlib axes, in an oblique parallel projection.

References
----------
- Russin, B. Advanced Reflection Models (JHU 605.767, Module 3B), "Bidirectional Reflectivity
  Distribution Function (BRDF)".
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.io.figures import TEXT_SIZE, text_colour
from reflectance.papers.polar import direction_from_angles

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["draw_brdf_angles"]


def _projector(azimuth_deg=-62.0, elevation_deg=22.0):
    """3-D -> 2-D: a parallel view from ``azimuth`` (about z) and ``elevation`` above the surface."""
    a, e = np.radians(azimuth_deg), np.radians(elevation_deg)
    right = np.array([-np.sin(a), np.cos(a), 0.0])
    up = np.array([-np.sin(e) * np.cos(a), -np.sin(e) * np.sin(a), np.cos(e)])
    return lambda p: np.stack([np.asarray(p) @ right, np.asarray(p) @ up], axis=-1)


def _arc(u, v, radius, n=60):
    """Points on the great-circle arc from unit vector u to unit vector v, at ``radius``."""
    angle = np.arccos(np.clip(np.dot(u, v), -1.0, 1.0))
    w = v - np.dot(u, v) * u
    w = w / np.linalg.norm(w)
    t = np.linspace(0.0, angle, n)[:, None]
    return radius * (np.cos(t) * u + np.sin(t) * w)


def draw_brdf_angles(ax: Axes, theta_i_deg: float, phi_i_deg: float, theta_v_deg: float,
                     phi_v_deg: float, colours: Mapping[str, str] | None = None
                     ) -> dict[str, npt.NDArray[np.float64]]:
    """Draw N, L, V, the surface with its x axis, and theta_i, phi_i, theta_v, phi_v as arcs.

    Angles in degrees; phi from the surface's x axis, counter-clockwise seen from above. Labels sit
    outside the arcs and away from the vectors.
    """
    phi_label = {"\u03c6\u1d62": (0.12, 0.5), "\u03c6\u1d65": (0.7, 0.84)}
    colours = colours or {"L": "#e69f00", "V": "#0072b2", "N": "0.15", "surface": "0.85"}
    P = _projector()
    N, x = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    L = direction_from_angles(np.radians(theta_i_deg), np.radians(phi_i_deg))
    V = direction_from_angles(np.radians(theta_v_deg), np.radians(phi_v_deg))
    circle = 1.25 * np.stack([np.cos(np.linspace(0, 2 * np.pi, 181)),
                              np.sin(np.linspace(0, 2 * np.pi, 181)), np.zeros(181)], -1)
    ax.fill(*P(circle).T, color=colours["surface"], alpha=0.6, lw=0)
    ax.plot(*P(circle).T, color="0.6", lw=0.8)
    ax.plot(*P(np.array([[0, 0, 0], 1.25 * x])).T, color="0.45", lw=0.9, ls=(0, (4, 2)))
    ax.text(*P(1.36 * x), "x", ha="center", va="center", fontsize=TEXT_SIZE["symbol"], color="0.35")
    for vec, name, colour in ((N, "N", colours["N"]), (L, "L", colours["L"]), (V, "V", colours["V"])):
        ax.annotate("", xy=P(vec), xytext=P(np.zeros(3)),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.6, shrinkA=0, shrinkB=0))
        ax.text(*(P(1.12 * vec)), name, color=text_colour(colour), ha="center", va="center",
                fontsize=TEXT_SIZE["symbol"] + 1.5, fontweight="bold")
    for vec, theta_name, phi_name, colour, r_theta, r_phi in (
            (L, "\u03b8\u1d62", "\u03c6\u1d62", colours["L"], 0.4, 0.38),
            (V, "\u03b8\u1d65", "\u03c6\u1d65", colours["V"], 0.55, 0.62)):
        flat = np.array([vec[0], vec[1], 0.0]) / np.hypot(vec[0], vec[1])
        ax.plot(*P(np.array([vec, [vec[0], vec[1], 0.0]])).T, color=colour, lw=0.7, ls=":")
        ax.plot(*P(np.array([np.zeros(3), [vec[0], vec[1], 0.0]])).T, color=colour, lw=0.9,
                ls=(0, (4, 2)))
        arc = _arc(N, vec / np.linalg.norm(vec), r_theta)  # theta: from N to the direction
        ax.plot(*P(arc).T, color=colour, lw=1.2)
        mid = arc[len(arc) // 2] / r_theta
        ax.text(*P((r_theta + 0.2) * mid), theta_name, color=text_colour(colour), ha="center",
                va="center", fontsize=TEXT_SIZE["symbol"] + 1.5)
        phi = np.arctan2(flat[1], flat[0]) % (2 * np.pi)  # phi: from x, counter-clockwise
        t = np.linspace(0.0, phi, 90)
        ring = r_phi * np.stack([np.cos(t), np.sin(t), np.zeros_like(t)], -1)
        ax.plot(*P(ring).T, color=colour, lw=1.2)
        ax.annotate("", xy=P(ring[-1]), xytext=P(ring[-4]),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.0))
        # the label beside its ring where no other ring or vector passes: phi_label = (fraction of
        # phi along the ring, radius of the label)
        at, radius = phi_label[phi_name]
        spot = radius * np.array([np.cos(at * phi), np.sin(at * phi), 0.0])
        ax.text(*P(spot), phi_name, color=text_colour(colour), ha="center", va="center",
                fontsize=TEXT_SIZE["symbol"] + 1.5)
    points = P(np.concatenate([circle, 1.2 * np.stack([N, L, V])]))
    lo, hi = points.min(axis=0) - 0.08, points.max(axis=0) + 0.08
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), aspect="equal")
    ax.set_axis_off()
    return {"L": L, "V": V}
