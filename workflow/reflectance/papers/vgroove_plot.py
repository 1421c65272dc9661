"""Drawing a simulated V-groove (Blinn 1977, Figs. 1-4) on a matplotlib axes.

Everything drawn comes from a :class:`reflectance.papers.vgroove.VGrooveSimulation`: the vertices, the
facet normal H, the projected directions L' and E', the traced ray paths and the blocked lengths.
Nothing here computes physics; it only draws what the simulation found.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (Figs. 1-4.)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, TYPE_CHECKING

import numpy as np
import numpy.typing as npt
from matplotlib.patches import Arc, Polygon

from reflectance.io.figures import TEXT_SIZE, text_colour

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from reflectance.papers.vgroove import VGrooveSimulation

__all__ = ["COLOURS", "draw_groove", "draw_top_view", "draw_arrow", "draw_angle", "draw_dimension"]

#: Colours (Okabe-Ito, readable by colour-blind readers) of the groove drawings.
COLOURS = {"light": "#e69f00", "eye": "#0072b2", "masked": "#d55e00", "facet": "#009e73",
           "other": "0.75", "normal": "0.2", "shadowed": "#cc79a7"}


def draw_arrow(ax: Axes, start: npt.ArrayLike, vector: npt.ArrayLike, label: str | None = None,
               color: str = "k", label_offset: Sequence[float] = (0.0, 0.0), **kwargs: Any) -> None:
    """An arrow from ``start`` along ``vector`` with an optional label just beyond its tip (moved by
    ``label_offset``, data units, where a line passes there)."""
    start, vector = np.asarray(start, float), np.asarray(vector, float)
    ax.annotate("", xy=start + vector, xytext=start,
                arrowprops=dict(arrowstyle="-|>", color=color, lw=1.4, shrinkA=0, shrinkB=0,
                                **kwargs))
    if label:
        tip = start + vector * (1 + 0.14 / max(np.linalg.norm(vector), 1e-9)) + label_offset
        ax.text(*tip, label, color=text_colour(color), ha="center", va="center",
                fontsize=TEXT_SIZE["symbol"], zorder=6,  # opaque: the label reads over the rays
                bbox=dict(facecolor="white", edgecolor=color, lw=0.6, alpha=1.0, pad=1.2,
                          boxstyle="round,pad=0.15"))


def draw_angle(ax: Axes, vertex: npt.ArrayLike, u: npt.ArrayLike, v: npt.ArrayLike, radius: float,
               label: str, color: str = "k", fontsize: float | None = None,
               label_radius: float = 1.45, label_at: float = 0.5) -> None:
    """Arc of the (smaller) angle between directions u and v at ``vertex``, labelled at its bisector
    (or at the fraction ``label_at`` of the angle, where a line runs along the bisector)."""
    a1, a2 = np.degrees(np.arctan2(u[1], u[0])), np.degrees(np.arctan2(v[1], v[0]))
    if (a2 - a1) % 360 > 180:  # draw counter-clockwise over the smaller angle
        a1, a2 = a2, a1
    ax.add_patch(Arc(vertex, 2 * radius, 2 * radius, theta1=a1, theta2=a2, color=color, lw=1.1))
    mid = np.radians(a1 + label_at * ((a2 - a1) % 360))
    ax.text(*(np.asarray(vertex) + label_radius * radius * np.array([np.cos(mid), np.sin(mid)])),
            label, ha="center", va="center", fontsize=fontsize or TEXT_SIZE["symbol"],
            color=text_colour(color))


def draw_dimension(ax: Axes, P0: npt.ArrayLike, P1: npt.ArrayLike, offset: float, label: str,
                   color: str = "k") -> None:
    """A dimension line parallel to P0-P1, shifted by ``offset``, with end ticks and a label."""
    P0, P1, offset = (np.asarray(x, float) for x in (P0, P1, offset))
    Q0, Q1 = P0 + offset, P1 + offset
    ax.annotate("", xy=Q1, xytext=Q0, arrowprops=dict(arrowstyle="|-|", color=color, lw=1.0,
                                                      mutation_scale=4, shrinkA=0, shrinkB=0))
    for P, Q in ((P0, Q0), (P1, Q1)):
        ax.plot(*np.column_stack([P, Q + 0.25 * offset]), color=color, lw=0.5, ls=":")
    ax.text(*((Q0 + Q1) / 2 + 0.9 * offset), label, ha="center", va="center",
            fontsize=TEXT_SIZE["symbol"], color=color, style="italic")


def draw_groove(ax: Axes, sim: VGrooveSimulation, ray_length: float = 1.1, exit_length: float = 0.6,
                rays: bool = True, vectors: bool = True, names: bool = False,
                normal_label_offset: Sequence[float] | None = None) -> None:
    """Cross-section of the groove in the plane of N and H, with the simulation's ray paths.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    sim : reflectance.papers.vgroove.VGrooveSimulation
    ray_length, exit_length : float
        How far incoming rays are drawn above the opening and escaping rays beyond it.
    rays, vectors, names : bool
        Draw the traced rays; the arrows N, H, L', E' at the facet's midpoint; the vertex names.
    normal_label_offset : sequence of float, optional
        Where N's label goes from just beyond its tip, in units of the half-width; given, N is drawn
        as long as H (its whole shaft shows); None keeps the short N labelled beside its shaft.
    """
    A, B, C = sim.vertices
    h = abs(A[0])
    depth = -B[1]
    ground = [(-1.75 * h, 0.0), A, B, C, (1.75 * h, 0.0)]
    ax.add_patch(Polygon(ground + [(1.75 * h, -depth - 0.45 * h), (-1.75 * h, -depth - 0.45 * h)],
                         closed=True, facecolor="0.93", edgecolor="none", zorder=0))
    ax.plot(*np.array(ground).T, color="k", lw=1.4, zorder=2)
    ax.plot(*np.array([A, B]).T, color=COLOURS["facet"], lw=4, solid_capstyle="butt", zorder=3)
    for length, point, color in ((sim.m_shadowing, sim.shadowing_point, COLOURS["shadowed"]),
                                 (sim.m_masking, sim.masking_point, COLOURS["masked"])):
        if length > 0:  # the blocked part of the facet, from B
            ax.plot(*np.array([B, point]).T, color=color, lw=4, solid_capstyle="butt", zorder=4)
    if rays:
        for (entry, hit, end), status in zip(sim.ray_points, sim.ray_status):
            if status == "other side":  # lands on the opposite side BC first: not this facet
                ax.plot(*np.array([entry + ray_length * h * sim.L2, hit]).T, color=COLOURS["other"],
                        lw=0.8, zorder=1)
                continue
            ax.plot(*np.array([entry + ray_length * h * sim.L2, hit]).T, color=COLOURS["light"],
                    lw=0.9, alpha=0.6, zorder=1)
            if status == "masked":
                ax.plot(*np.array([hit, end]).T, color=COLOURS["masked"], lw=0.9, alpha=0.6, zorder=1)
                ax.plot(*end, marker="x", color=COLOURS["masked"], ms=5, zorder=5)
            else:
                ax.plot(*np.array([hit, end + exit_length * h * sim.E2]).T, color=COLOURS["eye"],
                        lw=0.9, alpha=0.6, zorder=1)
    if vectors:
        M = (A + B) / 2
        # N shorter than H, L', E': its label stays clear of theirs when E' or L' lies near N
        # ... and beside its tip, on the side away from the steeper of L', E' (its shaft runs there)
        steep = max((sim.L2, sim.E2), key=lambda v: v[1])
        if normal_label_offset is None:
            draw_arrow(ax, M, 0.38 * h * np.array([0.0, 1.0]), "N", COLOURS["normal"], ls="--",
                       label_offset=(-0.17 * np.sign(steep[0] or 1.0), -0.16))
        else:
            draw_arrow(ax, M, 0.55 * h * np.array([0.0, 1.0]), "N", COLOURS["normal"], ls="--",
                       label_offset=h * np.asarray(normal_label_offset, float))
        draw_arrow(ax, M, 0.55 * h * sim.H2, "H", "k")
        draw_arrow(ax, M, 0.8 * h * sim.L2, "L'", COLOURS["light"])
        draw_arrow(ax, M, 0.8 * h * sim.E2, "E'", COLOURS["eye"])
    if names:
        for P, name, dy, va in ((A, "A", 0.06, "bottom"), (B, "B", -0.1, "top"), (C, "C", 0.06, "bottom")):
            ax.text(P[0], P[1] + dy * h, name, ha="center", va=va, fontsize=TEXT_SIZE["symbol"], zorder=6,
                    bbox=dict(facecolor="white", edgecolor="none", alpha=0.85, pad=0.5))
    ax.set_aspect("equal")
    ax.set_xlim(-1.75 * h, 1.75 * h)
    ax.set_ylim(-depth - 0.45 * h, (ray_length + 0.15) * h)
    ax.axis("off")


def draw_top_view(ax: Axes, sim: VGrooveSimulation, L: npt.NDArray[np.float64],
                  E: npt.NDArray[np.float64], H: npt.NDArray[np.float64]) -> None:
    """Blinn's Fig. 2: the groove seen along N, with L, E, H and the projections L', E'.

    The axes are ``t`` (the direction H tilts to, across the groove) and ``g`` (along it), the first
    two rows of ``sim.basis``; the groove's opening is drawn from ``t = -1`` (A) to ``1`` (C), the
    vectors at unit length from the middle of the facet AB. L' and E' are the feet of L and E on
    the plane of N and H (``g = 0``, seen edge-on).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    sim : reflectance.papers.vgroove.VGrooveSimulation
    L, E, H : numpy.ndarray
        (3,) the unit vectors, in the frame of ``sim.basis``.
    """
    t, axis = sim.basis[0], sim.basis[1]
    ax.axvspan(-1, 0, color=COLOURS["facet"], alpha=0.18, lw=0)
    ax.axvspan(0, 1, color="0.9", lw=0)
    for u, ls in ((-1, "-"), (0, "--"), (1, "-")):
        ax.axvline(u, color="k", lw=1, ls=ls)
    ax.axhline(0, color="0.4", lw=0.8, ls="-.")
    ax.text(0.94, -1.02, "dash-dot:\nN-H plane\n(edge-on)", ha="right", va="bottom",
            fontsize=TEXT_SIZE["annotation"], color="0.3")
    O = np.array([-0.5, 0.0])
    for vec, label, c in ((L, "L", COLOURS["light"]), (E, "E", COLOURS["eye"]), (H, "H", "k")):
        top = np.array([vec @ t, vec @ axis])
        draw_arrow(ax, O, top, label, c)
        if label != "H":
            ax.plot(*np.column_stack([O + top, O + [top[0], 0]]), color=c, ls=":", lw=1.2)
            ax.plot(*(O + [top[0], 0]), "o", color=c, ms=5)
            ax.text(*(O + [top[0], 0.06 * np.sign(-top[1])]), f"{label}'", color=text_colour(c),
                    fontsize=TEXT_SIZE["symbol"],
                    ha="center", va="bottom" if top[1] < 0 else "top")
    for u, label in ((-1, "A"), (0, "B"), (1, "C")):
        ax.text(u, 1.06, label, ha="center", va="top", fontsize=TEXT_SIZE["symbol"],
                bbox=dict(facecolor="white", edgecolor="none", pad=1))
    ax.set(xlim=(-1.3, 1.3), ylim=(-1.1, 1.1), aspect="equal", xticks=[], yticks=[],
           xlabel="t: direction of H's tilt", ylabel="g: along the groove")
