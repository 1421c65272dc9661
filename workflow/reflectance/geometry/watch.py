"""The watch of Cook & Torrance 1982, Fig. 8, modelled from parts as a pyvista triangle mesh.

The paper says only this about its object: "The outer band of the watch is made of gold, and
the inner band is made of stainless steel. The pattern on the links of the outer band was made
by using a rougher surface for the interior than for the border. The light-emitting diodes
(LEDs) are standard red 640 nanometer LEDs." Everything else here is our reading of a 1980 LED
digital watch, and every dimension is a parameter of :func:`watch`:

- a cushion-shaped case (rounded-rectangle plan, rounded top and bottom edges) with a raised
  half-round bezel around a dark display window (the *face*);
- the display: flat seven-segment LED digits (segments a-g in the usual labelling, slanted as on
  the watches of the time) lying just above the face, e.g. ``"12:00"``;
- a bracelet leaving the case at 12 and 6 o'clock along +y and -y, bent around a wrist (a
  cylinder about the x axis): on each side two columns of rigid gold links (the *outer band*),
  each link a rounded slab whose flat top is a polished *border* framing a rougher *interior*,
  and between the two columns a continuous stainless-steel strip (the *inner band*), as in
  two-tone bracelets of the period. (The paper's "outer" and "inner" could also mean the
  outside and the wrist side of the band; we chose the reading that shows both metals from
  above.)

Units are centimetres. The case bottom lies in the plane z = 0, the face looks along +z, the
digits read along +x and the bracelet runs along y and bends down (-z) on both sides, so a
camera above the -y side looking down at the face sees the watch as on a display cushion.

The mesh follows :mod:`reflectance.geometry.shapes`: triangles only, exact vertex ``Normals`` (every
curved part is a sweep of a plane profile along a plane path, or a revolution about the wrist
axis, whose normal is the profile's normal carried along; flat parts have constant normals),
``uv`` in [0, 1] and ``cell_data["part"]`` (:data:`WATCH_PARTS`); ``sphere_index`` is -1
(no analytic spheres).

References
----------
Cook, R. L., & Torrance, K. E. (1982). A reflectance model for computer graphics. ACM
Transactions on Graphics, 1(1), 7-24 (Fig. 8: a watch).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

import reflectance.geometry as geometry

if TYPE_CHECKING:
    import pyvista as pv

# geometry.shapes (pyvista, scipy) is loaded on first use by the package's lazy attach
# (reflectance.lazy), when a function builds a mesh: config.py reads watch()'s keywords at every
# parse of the workflow without loading it.

__all__ = ["WATCH_PARTS", "SEVEN_SEGMENT_DIGITS", "watch"]

WATCH_PARTS = {
    "case": 0,
    "bezel": 1,
    "face": 2,
    "led": 3,
    "band_outer_border": 4,
    "band_outer_interior": 5,
    "band_inner": 6,
}
"""Codes of ``cell_data["part"]`` for :func:`watch`.

``band_outer_border`` is the polished frame of each gold link (flat top ring, rounded edges,
sides, ends and bottom); ``band_outer_interior`` the rougher inset top (Cook & Torrance 1982,
Fig. 8: "a rougher surface for the interior than for the border"); ``band_inner`` the steel
strip; ``led`` the lit segments; ``face`` the dark display window.
"""

SEVEN_SEGMENT_DIGITS = {
    "0": "abcdef", "1": "bc", "2": "abdeg", "3": "abcdg", "4": "bcfg",
    "5": "acdfg", "6": "acdefg", "7": "abc", "8": "abcdefg", "9": "abcdfg",
    " ": "",
}
"""Lit segments per character (a top, b upper right, c lower right, d bottom, e lower left,
f upper left, g middle); ``":"`` is drawn as two dots."""

_UP = np.array([0.0, 0.0, 1.0])


# --------------------------------------------------------------------------------------------
# Plane outlines, sweeps and caps
# --------------------------------------------------------------------------------------------

def _samples(length, spacing):
    return max(1, int(np.ceil(length / spacing - 1e-9)))


def _quarter_samples(radius, n_quarter, spacing):
    """Segments on a quarter circle: about one per ``spacing`` of arc, between 2 and n_quarter.

    Small fillets get few triangles (they would be smaller than a pixel), large curves enough for
    a smooth silhouette; the normals are exact either way.
    """
    return int(np.clip(np.ceil(0.5 * np.pi * radius / spacing - 1e-9), 2, max(2, n_quarter)))


def _rounded_rectangle(half_x, half_y, radius, n_quarter, spacing):
    """Closed counter-clockwise outline of a rounded rectangle centred at the origin.

    Returns points (m, 2), unit outward normals (m, 2) and the arc-length fraction (m,) from the
    point (half_x, 0); the last point repeats the first (a seam for u). Corners of radius 0 keep
    their coincident points with turning normals, so that an outward offset of the outline
    rounds them exactly.
    """
    r = radius
    pts, nrm = [], []

    def line(p, q, n):
        p, q = np.asarray(p, float), np.asarray(q, float)
        t = np.linspace(0.0, 1.0, _samples(np.linalg.norm(q - p), spacing) + 1)
        pts.append(p + t[:, None] * (q - p))
        nrm.append(np.tile(n, (len(t), 1)))

    def corner(cx, cy, start):
        a = start + np.linspace(0.0, 0.5 * np.pi, _quarter_samples(r, n_quarter, spacing) + 1)
        ca, sa = np.cos(a), np.sin(a)
        ca[np.abs(ca) < 1e-15], sa[np.abs(sa) < 1e-15] = 0.0, 0.0
        pts.append(np.column_stack([cx + r * ca, cy + r * sa]))
        nrm.append(np.column_stack([ca, sa]))

    hx, hy = half_x, half_y
    line((hx, 0.0), (hx, hy - r), (1.0, 0.0))
    corner(hx - r, hy - r, 0.0)
    line((hx - r, hy), (-hx + r, hy), (0.0, 1.0))
    corner(-hx + r, hy - r, 0.5 * np.pi)
    line((-hx, hy - r), (-hx, -hy + r), (-1.0, 0.0))
    corner(-hx + r, -hy + r, np.pi)
    line((-hx + r, -hy), (hx - r, -hy), (0.0, -1.0))
    corner(hx - r, -hy + r, 1.5 * np.pi)
    line((hx, -hy + r), (hx, 0.0), (1.0, 0.0))
    # consecutive pieces share an end point with the same normal: keep it once
    P = np.concatenate([pts[0]] + [p[1:] for p in pts[1:]])
    N = np.concatenate([nrm[0]] + [n[1:] for n in nrm[1:]])
    step = np.linalg.norm(np.diff(P, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(step)])
    return P, N, s / s[-1]


def _sweep(path, path_normal, binormal, u, rho, z, n_rho, n_z, part):
    """Sweep a plane profile along a path: ``P = C + rho N + z B``, normal ``n_rho N + n_z B``.

    The path C (m, 3) has unit normals N (m, 3) in its plane and the constant binormal B; the
    profile (rho, z) has unit normals (n_rho, n_z). Offset surfaces of this kind share their
    normals with the profile (the path derivative is parallel to the path tangent), so the
    normals are exact wherever the offset does not fold (rho > -path radius of curvature).
    Grid rows follow the profile (v = arc-length fraction), columns the path (u).
    """
    rho, z = np.asarray(rho, float), np.asarray(z, float)
    n_rho, n_z = np.asarray(n_rho, float), np.asarray(n_z, float)
    points = (path[None] + rho[:, None, None] * path_normal[None]
              + z[:, None, None] * binormal)
    normals = n_rho[:, None, None] * path_normal[None] + n_z[:, None, None] * binormal
    step = np.hypot(np.diff(rho), np.diff(z))
    v = np.concatenate([[0.0], np.cumsum(step)])
    v = v / v[-1] if v[-1] > 0 else np.linspace(0.0, 1.0, len(rho))
    uv = np.stack(np.broadcast_arrays(u[None, :], v[:, None]), -1)
    return geometry.shapes.grid_mesh(points, normals, uv, part)


def _cap(boundary, normal, e1, e2, n_rings, part):
    """Flat region inside a closed convex outline (m, 3): rings scaled towards its centre.

    uv is the planar map onto the outline's extent along e1 and e2.
    """
    centre = 0.5 * (boundary.min(axis=0) + boundary.max(axis=0))
    s = np.linspace(0.0, 1.0, n_rings + 1)
    points = centre + s[:, None, None] * (boundary - centre)[None]
    a, b = (boundary - centre) @ e1, (boundary - centre) @ e2
    d = points - centre
    uv = np.stack([0.5 + 0.5 * (d @ e1) / np.abs(a).max(), 0.5 + 0.5 * (d @ e2) / np.abs(b).max()],
                  -1)
    normals = np.broadcast_to(normal, points.shape)
    return geometry.shapes.grid_mesh(points, normals, np.clip(uv, 0.0, 1.0), part)


def _arc(centre, radius, start, stop, n):
    """Profile samples (rho, z, n_rho, n_z) on a circular arc, normal pointing away from centre."""
    a = np.linspace(start, stop, n + 1)
    c, s = np.cos(a), np.sin(a)
    return centre[0] + radius * c, centre[1] + radius * s, c, s


def _segment(p, q, n, spacing):
    t = np.linspace(0.0, 1.0, _samples(np.hypot(q[0] - p[0], q[1] - p[1]), spacing) + 1)
    return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]),
            np.full_like(t, n[0]), np.full_like(t, n[1]))


def _slab(half_x, half_y, corner_radius, height, edge_radius, inset, border, top, n_quarter,
          spacing):
    """Rounded slab, bottom z = 0, top z = ``height``: rounded-rectangle plan, rounded top edge.

    The profile climbs the vertical side, turns over the top edge (radius ``edge_radius``) and,
    when ``inset`` > ``edge_radius``, runs inwards over a flat ring of the top; these and the
    flat bottom get part ``border``, the flat top inside the inset outline part ``top``.
    """
    P2, N2, u = _rounded_rectangle(half_x, half_y, corner_radius, n_quarter, spacing)
    path = np.column_stack([P2, np.zeros(len(P2))])
    normal = np.column_stack([N2, np.zeros(len(N2))])
    pieces = []
    r = edge_radius
    side = _segment((0.0, 0.0), (0.0, height - r), (1.0, 0.0), spacing)
    pieces.append(_sweep(path, normal, _UP, u, *side, border))
    edge = _arc((-r, height - r), r, 0.0, 0.5 * np.pi, _quarter_samples(r, n_quarter, spacing))
    pieces.append(_sweep(path, normal, _UP, u, *edge, border))
    if inset > r:
        ring = _segment((-r, height), (-inset, height), (0.0, 1.0), spacing)
        pieces.append(_sweep(path, normal, _UP, u, *ring, border))
    n_rings = _samples(min(half_x, half_y), spacing)
    top_outline = path - max(inset, r) * normal + height * _UP
    pieces.append(_cap(top_outline, _UP, np.eye(3)[0], np.eye(3)[1], n_rings, top))
    pieces.append(_cap(path, -_UP, np.eye(3)[0], np.eye(3)[1], n_rings, border))
    return geometry.shapes.merge_meshes(pieces)


def _polygon(vertices, z, uv_box, part):
    """Flat convex polygon (k, 2) at height z facing +z, fanned from its first vertex."""
    k = len(vertices)
    points = np.column_stack([vertices, np.full(k, z)])
    (x0, y0), (x1, y1) = uv_box
    uv = np.column_stack([(vertices[:, 0] - x0) / (x1 - x0), (vertices[:, 1] - y0) / (y1 - y0)])
    tris = np.column_stack([np.zeros(k - 2, np.int64), np.arange(1, k - 1), np.arange(2, k)])
    return geometry.shapes.triangle_mesh(points, np.tile(_UP, (k, 1)), np.clip(uv, 0.0, 1.0),
                                         tris, part)


# --------------------------------------------------------------------------------------------
# The display
# --------------------------------------------------------------------------------------------

def _seven_segments(width, height, thickness):
    """Centre lines (start, end) of segments a-g in a digit box centred at the origin."""
    x0, x1 = -0.5 * width + 0.5 * thickness, 0.5 * width - 0.5 * thickness
    y0, y1 = -0.5 * height + 0.5 * thickness, 0.5 * height - 0.5 * thickness
    return {"a": ((x0, y1), (x1, y1)), "b": ((x1, y1), (x1, 0.0)), "c": ((x1, 0.0), (x1, y0)),
            "d": ((x0, y0), (x1, y0)), "e": ((x0, 0.0), (x0, y0)), "f": ((x0, y1), (x0, 0.0)),
            "g": ((x0, 0.0), (x1, 0.0))}


def _segment_hexagon(p, q, thickness, gap):
    """Elongated hexagon along p -> q with pointed ends, shortened by ``gap`` at both ends."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    d = (q - p) / np.linalg.norm(q - p)
    n = np.array([-d[1], d[0]])
    t = 0.5 * thickness
    return np.array([p + gap * d, p + (gap + t) * d - t * n, q - (gap + t) * d - t * n,
                     q - gap * d, q - (gap + t) * d + t * n, p + (gap + t) * d + t * n])


def _display(text, digit_height, thickness, slant_deg, z, box, window, part):
    """LED segments of ``text`` centred in the window; one flat piece per segment or dot."""
    width = 0.5 * digit_height
    pitch, colon_pitch = width + 0.18 * digit_height, 0.2 * digit_height
    cells = [colon_pitch if ch == ":" else pitch for ch in text]
    shear = np.tan(np.radians(slant_deg))
    total = sum(cells) - (pitch - width if text[-1] != ":" else 0.0)
    extent = total + abs(shear) * digit_height  # the slant widens the row
    if extent > window[0] - 2 * thickness or digit_height > window[1] - 2 * thickness:
        raise ValueError(f"watch: display {text!r} ({extent:.3g} x {digit_height:.3g} cm) does "
                         f"not fit the window ({window[0]:.3g} x {window[1]:.3g} cm) with a "
                         "margin of one segment thickness")
    pieces = []
    x = -0.5 * total
    for ch, cell in zip(text, cells):
        if ch == ":":
            centre = x + 0.5 * cell
            for y in (-0.22 * digit_height, 0.22 * digit_height):
                h = 0.5 * thickness
                square = np.array([[-h, -h], [h, -h], [h, h], [-h, h]]) + (centre, y)
                pieces.append(square)
        else:
            segments = _seven_segments(width, digit_height, thickness)
            for name in SEVEN_SEGMENT_DIGITS[ch]:
                p, q = segments[name]
                hexagon = _segment_hexagon(p, q, thickness, 0.12 * thickness)
                pieces.append(hexagon + (x + 0.5 * width, 0.0))
        x += cell
    meshes = []
    for vertices in pieces:
        vertices = vertices.copy()
        vertices[:, 0] += shear * vertices[:, 1]  # italic slant, shearing x with height
        meshes.append(_polygon(vertices, z, box, part))
    return meshes


# --------------------------------------------------------------------------------------------
# The watch
# --------------------------------------------------------------------------------------------

def _positive(name, value):
    """geometry's check, with the message naming the watch's parameter."""
    return geometry.shapes.check_positive(value, f"watch: {name}")


def _pair(name, value):
    v = np.asarray(value, dtype=np.float64)
    if v.shape != (2,) or not np.all(np.isfinite(v)) or np.any(v <= 0):
        raise ValueError(f"watch: {name} must be 2 positive numbers, got {value!r}")
    return v


def _tuple3(value):
    v = np.asarray(value, dtype=np.float64)
    if v.shape != (3,):
        raise ValueError(f"watch: expected 3 numbers, got {value!r}")
    return v


def _rotation_x(angle):
    """Rotation about +x by ``angle``: +z turns to (0, sin, cos), +y to (0, cos, -sin)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])


def watch(*, case_size: Sequence[float] = (3.2, 3.6, 0.7), case_corner_radius: float = 0.8,
          case_edge_radius: float = 0.3, button_radius: float = 0.16, button_length: float = 0.18,
          window_size: Sequence[float] = (2.1, 1.0), window_corner_radius: float = 0.15,
          bezel_width: float = 0.16, bezel_height: float = 0.08, display: str = "12:00",
          digit_height: float = 0.62, segment_thickness: float = 0.085,
          digit_slant_deg: float = 8.0, wrist_radius: float = 4.5, band_height: float = 0.3,
          links_per_side: int = 6, link_size: Sequence[float] = (0.62, 0.8, 0.26),
          link_gap: float = 0.07, link_corner_radius: float = 0.12, link_edge_radius: float = 0.07,
          link_border_width: float = 0.12, inner_band_size: Sequence[float] = (0.56, 0.18),
          inner_band_depth: float = 0.05, column_gap: float = 0.05, n_quarter: int = 8,
          spacing: float = 0.12) -> pv.PolyData:
    """The LED watch of Cook & Torrance 1982, Fig. 8, as one triangle mesh (units: cm).

    Parameters
    ----------
    case_size : (float, float, float), optional
        Case width (x, across the band), length (y, along the band) and height (z); the case
        bottom lies at z = 0. Default (3.2, 3.6, 0.7).
    case_corner_radius : float, optional
        Radius of the rounded corners of the case plan (cushion shape). Default 0.8.
    case_edge_radius : float, optional
        Radius of the rounded top edge of the case. Default 0.3.
    button_radius, button_length : float, optional
        The push button (part ``case``) on the +x side at mid height: a rounded cylinder of
        this radius standing out this far from the case side. Defaults 0.16, 0.18.
    window_size : (float, float), optional
        Display window width (x) and height (y) inside the bezel. Default (2.1, 1.0).
    window_corner_radius : float, optional
        Corner radius of the window. Default 0.15.
    bezel_width, bezel_height : float, optional
        Base width and height of the half-round (elliptic) bezel ring around the window, which
        stands on the case top. Defaults 0.16, 0.08.
    display : str, optional
        Characters shown: digits, ``":"`` (two dots) and ``" "`` (blank). Default ``"12:00"``.
    digit_height : float, optional
        Height of a digit; its width is half of it. Default 0.62.
    segment_thickness : float, optional
        Width of one LED segment. Default 0.085.
    digit_slant_deg : float, optional
        Italic slant of the digits (degrees, positive leans right). Default 8.
    wrist_radius : float, optional
        Radius of the bracelet's top surface, bent around the x axis. Default 4.5.
    band_height : float, optional
        Height of the bracelet's top surface where it enters the case, at y = +-0.8 times the
        case's half-length. Default 0.3.
    links_per_side : int, optional
        Gold links in each column on each side of the case. Default 6.
    link_size : (float, float, float), optional
        Width (x), length (along the band) and thickness of a gold link. Default
        (0.62, 0.8, 0.26).
    link_gap : float, optional
        Gap between consecutive links along the band. Default 0.07.
    link_corner_radius : float, optional
        Corner radius of a link's plan, >= ``link_border_width`` and >= ``link_edge_radius``.
        Default 0.12.
    link_edge_radius : float, optional
        Radius of a link's rounded top edge. Default 0.07.
    link_border_width : float, optional
        Width of the polished border framing the rough interior of a link's top, measured from
        the link's outline. Default 0.12.
    inner_band_size : (float, float), optional
        Width and thickness of the steel strip between the link columns. Default (0.56, 0.18).
    inner_band_depth : float, optional
        How far the strip's top lies below the links' tops. Default 0.05.
    column_gap : float, optional
        Gap between the strip and each link column. Default 0.05.
    n_quarter : int, optional
        Most segments on a quarter circle of any rounded edge or corner; a quarter circle gets
        about one segment per ``spacing`` of arc, at least 2. Default 8.
    spacing : float, optional
        Largest sample spacing along straight edges and along the bent band, and the arc length
        per segment of rounded edges (within the bounds above). Default 0.12.

    Returns
    -------
    pyvista.PolyData
        Triangles with ``Normals``, ``uv`` and ``part`` (:data:`WATCH_PARTS`), ``sphere_index``
        -1 everywhere. The face looks along +z, the digits read along +x, the bracelet runs
        along y and bends down towards -z on both sides.

    References
    ----------
    Cook, R. L., & Torrance, K. E. (1982). A reflectance model for computer graphics. ACM
    Transactions on Graphics, 1(1), 7-24 (Fig. 8).

    Examples
    --------
    >>> mesh = watch()
    >>> mesh.is_all_triangles, sorted(set(mesh.cell_data["part"].tolist())) == list(range(7))
    (True, True)
    """
    cx, cy, cz = (_positive(f"case_size[{i}]", v) for i, v in enumerate(_tuple3(case_size)))
    c_corner = _positive("case_corner_radius", case_corner_radius)
    c_edge = _positive("case_edge_radius", case_edge_radius)
    b_radius = _positive("button_radius", button_radius)
    b_length = _positive("button_length", button_length)
    wx, wy = _pair("window_size", window_size)
    w_corner = _positive("window_corner_radius", window_corner_radius)
    bw, bh = _positive("bezel_width", bezel_width), _positive("bezel_height", bezel_height)
    dh = _positive("digit_height", digit_height)
    seg = _positive("segment_thickness", segment_thickness)
    slant = float(digit_slant_deg)
    if not (np.isfinite(slant) and abs(slant) < 45.0):
        raise ValueError(f"watch: digit_slant_deg must lie in (-45, 45), got {digit_slant_deg!r}")
    R = _positive("wrist_radius", wrist_radius)
    lx, ly, lz = (_positive(f"link_size[{i}]", v) for i, v in enumerate(_tuple3(link_size)))
    gap = _positive("link_gap", link_gap)
    l_corner = _positive("link_corner_radius", link_corner_radius)
    l_edge = _positive("link_edge_radius", link_edge_radius)
    border = _positive("link_border_width", link_border_width)
    sx, sz = _pair("inner_band_size", inner_band_size)
    depth = float(inner_band_depth)
    col_gap = float(column_gap)
    spacing = _positive("spacing", spacing)
    if isinstance(n_quarter, bool) or not isinstance(n_quarter, (int, np.integer)) \
            or n_quarter < 1:
        raise ValueError(f"watch: n_quarter must be an integer >= 1, got {n_quarter!r}")
    if isinstance(links_per_side, bool) or not isinstance(links_per_side, (int, np.integer)) \
            or links_per_side < 1:
        raise ValueError(f"watch: links_per_side must be an integer >= 1, got {links_per_side!r}")
    if not isinstance(display, str) or not display:
        raise ValueError(f"watch: display must be a non-empty string, got {display!r}")
    unknown = sorted(set(display) - set(SEVEN_SEGMENT_DIGITS) - {":"})
    if unknown:
        raise ValueError(f"watch: display {display!r} has characters {unknown} that a "
                         f"seven-segment display cannot show; known: "
                         f"{sorted(set(SEVEN_SEGMENT_DIGITS) | {':'})}")
    if not (np.isfinite(depth) and 0 <= depth < lz) or not (np.isfinite(col_gap) and col_gap >= 0):
        raise ValueError("watch: inner_band_depth must be in [0, link thickness) and column_gap "
                         f">= 0, got {inner_band_depth!r}, {column_gap!r}")
    if not (c_corner <= 0.5 * min(cx, cy) and c_edge <= min(c_corner, cz)):
        raise ValueError("watch: need case_edge_radius <= case_corner_radius <= half the smaller "
                         "case side, and case_edge_radius <= case height")
    if not (l_edge <= l_corner and border <= l_corner and l_corner <= 0.5 * min(lx, ly)
            and border < 0.5 * min(lx, ly) and l_edge <= lz):
        raise ValueError("watch: need link_edge_radius, link_border_width <= link_corner_radius "
                         "<= half the smaller link side and link_edge_radius <= link thickness")
    if w_corner > 0.5 * min(wx, wy):
        raise ValueError("watch: window_corner_radius exceeds half the smaller window side")
    if wx + 2 * bw > cx - 2 * c_edge or wy + 2 * bw > cy - 2 * c_edge:
        raise ValueError(f"watch: the window {tuple(window_size)} and its bezel do not fit on the "
                         f"flat top of the case {tuple(case_size)}")
    band_width = 2 * lx + sx + 2 * col_gap
    if band_width > cx:
        raise ValueError(f"watch: the bracelet ({band_width:.3g} wide) is wider than the case")
    if not (0 < band_height < cz) or 0.8 * 0.5 * cy >= R:
        raise ValueError("watch: band_height must lie in (0, case height) and wrist_radius must "
                         "exceed 0.4 case length")
    if b_radius >= 0.5 * cz:
        raise ValueError("watch: button_radius must be smaller than half the case height")

    quality = dict(n_quarter=n_quarter, spacing=spacing)
    parts = _case((cx, cy, cz), c_corner, c_edge, b_radius, b_length, quality)
    parts += _dial(cz, (wx, wy), w_corner, bw, bh, display, dh, seg, slant, quality)
    side = _bracelet_side(R, 0.8 * 0.5 * cy, band_height, links_per_side, (lx, ly, lz), gap,
                          l_corner, l_edge, border, (sx, sz), depth, col_gap, quality)
    turn = np.diag([-1.0, -1.0, 1.0])  # the -y side: the same band turned half about z
    parts += [side, geometry.shapes.place(side, rotation=turn)]
    return geometry.shapes.merge_meshes(parts)


def _case(size, corner_radius, edge_radius, button_radius, button_length, quality):
    """The case (a rounded slab, flat inside its top edge) and its push button on +x."""
    cx, cy, cz = size
    case = WATCH_PARTS["case"]
    body = _slab(0.5 * cx, 0.5 * cy, corner_radius, cz, edge_radius, edge_radius, case, case,
                 **quality)
    # the button: a rounded cylinder (a slab of circular plan) along +x from inside the case
    button = _slab(button_radius, button_radius, button_radius,
                   button_length + 0.5 * button_radius,
                   min(0.5 * button_radius, 0.5 * button_length), 0.0, case, case, **quality)
    to_x = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])  # local z -> +x
    return [body, geometry.shapes.place(button, (0.5 * cx - 0.5 * button_radius, 0.0, 0.5 * cz),
                                        rotation=to_x)]


def _dial(case_top, window, window_corner, bezel_width, bezel_height, display, digit_height,
          segment, slant_deg, quality):
    """Bezel ring, face (display window) and LED segments on top of the case."""
    wx, wy = window
    bw, bh = bezel_width, bezel_height
    # the bezel: a half-elliptic ring swept along the window outline offset by half its width
    P2, N2, u = _rounded_rectangle(0.5 * (wx + bw), 0.5 * (wy + bw), window_corner + 0.5 * bw,
                                   **quality)
    path = np.column_stack([P2, np.full(len(P2), case_top)])
    normal = np.column_stack([N2, np.zeros(len(N2))])
    psi = np.linspace(0.0, np.pi, 2 * _quarter_samples(max(0.5 * bw, bh), **quality) + 1)
    cp, sp = np.cos(psi), np.sin(psi)
    cp[np.abs(cp) < 1e-15] = 0.0
    en = np.column_stack([bh * cp, 0.5 * bw * sp])  # ellipse (a cos, b sin): normal (b cos, a sin)
    en /= np.linalg.norm(en, axis=1, keepdims=True)
    parts = [_sweep(path, normal, _UP, u, 0.5 * bw * cp, bh * sp, en[:, 0], en[:, 1],
                    WATCH_PARTS["bezel"])]
    # the face: flat, reaching under the bezel (to a quarter of its width) so no gap shows
    face_z = case_top + 0.3 * bh
    outline = path - 0.25 * bw * normal + (face_z - case_top) * _UP
    parts.append(_cap(outline, _UP, np.eye(3)[0], np.eye(3)[1],
                      _samples(0.5 * wy, quality["spacing"]), WATCH_PARTS["face"]))
    # the LEDs: flat segments just above the face
    half = 0.5 * np.array([wx + bw, wy + bw])
    parts += _display(display, digit_height, segment, slant_deg, face_z + 0.05 * bh,
                      (-half, half), window, WATCH_PARTS["led"])
    return parts


def _bracelet_side(radius, y_enter, height, n_links, link_size, gap, corner, edge, border,
                   strip_size, depth, column_gap, quality):
    """The +y half of the bracelet, bent about the wrist axis (parallel to x).

    Its top surface is the cylinder of ``radius`` about the axis through (0, 0, zc), at
    ``height`` where it enters the case (y = ``y_enter``).
    """
    lx, ly, lz = link_size
    sx, sz = strip_size
    phi_enter = np.arcsin(y_enter / radius)
    centre = np.array([0.0, 0.0, height - radius * np.cos(phi_enter)])
    dphi = (ly + gap) / radius
    phi_end = phi_enter + n_links * dphi - 0.5 * gap / radius
    ex = np.eye(3)[0]
    # the gold links: rigid slabs, each touching the cylinder at its middle
    link = _slab(0.5 * lx, 0.5 * ly, corner, lz, edge, border, WATCH_PARTS["band_outer_border"],
                 WATCH_PARTS["band_outer_interior"], **quality)
    x_link = 0.5 * sx + column_gap + 0.5 * lx
    parts = []
    for k in range(n_links):
        rot = _rotation_x(phi_enter + (k + 0.5) * dphi)
        for x in (-x_link, x_link):
            at = centre + (radius - lz) * (rot @ _UP) + x * ex
            parts.append(geometry.shapes.place(link, at, rotation=rot))
    # the steel strip: a rounded-rectangle cross-section revolved about the wrist axis, from
    # inside the case to the end of the last link
    phi_start = np.arcsin(0.5 * y_enter / radius)
    phi = np.linspace(phi_start, phi_end,
                      _samples((phi_end - phi_start) * radius, quality["spacing"]) + 1)
    e_r = np.column_stack([np.zeros_like(phi), np.sin(phi), np.cos(phi)])
    r_mid = radius - depth - 0.5 * sz
    # cross-section outline in (radial offset, x), with its normals
    Q2, M2, _ = _rounded_rectangle(0.5 * sz, 0.5 * sx, 0.45 * min(sx, sz), **quality)
    inner = WATCH_PARTS["band_inner"]
    parts.append(_sweep(centre + r_mid * e_r, e_r, ex, (phi - phi_start) / (phi_end - phi_start),
                        Q2[:, 0], Q2[:, 1], M2[:, 0], M2[:, 1], inner))
    for angle, sign in ((phi_start, -1.0), (phi_end, 1.0)):
        rot = _rotation_x(angle)
        er, ephi = rot @ _UP, rot @ np.array([0.0, 1.0, 0.0])
        outline = centre + (r_mid + Q2[:, :1]) * er + Q2[:, 1:] * ex
        parts.append(_cap(outline, sign * ephi, ex, er, _samples(0.5 * sx, quality["spacing"]),
                          inner))
    return geometry.shapes.merge_meshes(parts)
