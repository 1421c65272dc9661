"""Tests of reflectance.geometry.watch: the LED watch of Cook & Torrance 1982, Fig. 8."""

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from reflectance.geometry.shapes import compose
from reflectance.geometry.watch import WATCH_PARTS, watch

# lit segments of the digits of a seven-segment display, counted from the usual glyphs
# (0: all but the middle; 1: the two right; 7: top and the two right; 8: all seven; ...)
SEGMENTS_PER_DIGIT = {"0": 6, "1": 2, "2": 5, "3": 5, "4": 4, "5": 5, "6": 6, "7": 3, "8": 7,
                      "9": 6}


@pytest.fixture(scope="module")
def mesh():
    return watch()


def triangles(mesh):
    return np.asarray(mesh.faces).reshape(-1, 4)[:, 1:]


def face_normals_and_areas(mesh):
    P = np.asarray(mesh.points)
    t = triangles(mesh)
    n = np.cross(P[t[:, 1]] - P[t[:, 0]], P[t[:, 2]] - P[t[:, 0]])
    area2 = np.linalg.norm(n, axis=1)
    return n / area2[:, None], 0.5 * area2


def welded(mesh, cells):
    """Triangles of ``cells`` on welded points (coincident points merged): (tris, points)."""
    P = np.asarray(mesh.points)
    t = triangles(mesh)[cells]
    key = np.round(P / 1e-9).astype(np.int64)
    _, index, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return inverse.reshape(-1)[t], P[index]


def components(mesh, parts):
    """Connected pieces (on welded points) of the triangles of the given parts."""
    cells = np.isin(mesh.cell_data["part"], [WATCH_PARTS[p] for p in parts])
    t, P = welded(mesh, cells)
    rows = np.concatenate([t[:, 0], t[:, 1], t[:, 2]])
    cols = np.concatenate([t[:, 1], t[:, 2], t[:, 0]])
    graph = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(P), len(P)))
    _, label = connected_components(graph, directed=False)
    tri_label = label[t[:, 0]]
    return [t[tri_label == k] for k in np.unique(tri_label)], P


def test_triangles_parts_and_attributes(mesh):
    assert mesh.is_all_triangles
    assert sorted(np.unique(mesh.cell_data["part"]).tolist()) == sorted(WATCH_PARTS.values())
    assert len(set(WATCH_PARTS.values())) == len(WATCH_PARTS)
    assert np.all(mesh.cell_data["sphere_index"] == -1)
    N = mesh.point_data["Normals"]
    assert np.allclose(np.linalg.norm(N, axis=1), 1.0, atol=1e-12)
    uv = mesh.point_data["uv"]
    assert np.all(np.isfinite(uv)) and uv.min() >= 0.0 and uv.max() <= 1.0
    assert 10_000 < mesh.n_cells < 100_000  # "a few 10k triangles"


def normal_deviation(mesh):
    """Per triangle: largest angle between a vertex normal and the facet, and between two
    vertex normals (degrees)."""
    n, area = face_normals_and_areas(mesh)
    assert np.all(area > 0)
    N = mesh.point_data["Normals"][triangles(mesh)]
    facet = np.degrees(np.arccos(np.clip(np.einsum("tkj,tj->tk", N, n), -1, 1))).max(axis=1)
    pairs = [np.einsum("tj,tj->t", N[:, i], N[:, j]) for i, j in ((0, 1), (1, 2), (0, 2))]
    spread = np.degrees(np.arccos(np.clip(np.stack(pairs, 1), -1, 1))).max(axis=1)
    return facet, spread


def test_vertex_normals_follow_the_facets(mesh):
    # the analytic normals describe the surface the triangles approximate: each facet normal
    # lies within the spread of its vertex normals, at most ~ one segment (45 degrees max per
    # quarter circle) away, and the deviation shrinks as the tessellation is refined
    facet, spread = normal_deviation(mesh)
    assert np.all(facet <= spread + 1e-4)  # degrees; arccos near 1 loses half the digits
    assert facet.max() < 35.0
    fine, _ = normal_deviation(watch(n_quarter=12, spacing=0.03, links_per_side=1))
    assert fine.max() < 15.0


def closed_and_outward(P, t):
    """Every edge shared by two triangles, and a positive enclosed volume (divergence theorem)."""
    edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    edges = edges[edges[:, 0] != edges[:, 1]]
    _, counts = np.unique(edges, axis=0, return_counts=True)
    a, b, c = P[t[:, 0]], P[t[:, 1]], P[t[:, 2]]
    return np.all(counts == 2), np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0


def piece_vertices(mesh, parts, piece, P):
    """Unwelded (point, normal) pairs of a welded piece of the given parts."""
    cells = np.isin(mesh.cell_data["part"], [WATCH_PARTS[p] for p in parts])
    t = triangles(mesh)[cells]
    tw, _ = welded(mesh, cells)
    rows = np.isin(tw, np.unique(piece)).all(axis=1)
    idx = np.unique(t[rows])
    return np.asarray(mesh.points)[idx], mesh.point_data["Normals"][idx]


@pytest.mark.parametrize("parts, count", [(["case"], 2),
                                          (["band_outer_border", "band_outer_interior"], 24)])
def test_convex_solids_are_closed_with_outward_normals(mesh, parts, count):
    # case body and button; every gold link: closed surfaces whose triangles (oriented like
    # their normals) enclose a positive volume, with normals pointing away from their centroid
    pieces, P = components(mesh, parts)
    assert len(pieces) == count
    for t in pieces:
        closed, volume = closed_and_outward(P, t)
        assert closed and volume > 0
        p, n = piece_vertices(mesh, parts, t, P)
        assert np.all(np.einsum("ij,ij->i", n, p - P[np.unique(t)].mean(axis=0)) > 0)


def test_steel_strips_are_closed_with_outward_normals(mesh):
    # each strip is a rounded-rectangle section revolved about the wrist axis; its normals point
    # away from the section's mid-line (radius 4.5 - 0.05 - 0.18 / 2 about the axis at zc), or
    # along the band at its two flat ends
    pieces, P = components(mesh, ["band_inner"])
    assert len(pieces) == 2
    zc = 0.3 - np.sqrt(4.5**2 - 1.44**2)
    r_mid = 4.5 - 0.05 - 0.09
    for t in pieces:
        closed, volume = closed_and_outward(P, t)
        assert closed and volume > 0
        p, n = piece_vertices(mesh, ["band_inner"], t, P)
        radial = p - [0.0, 0.0, zc]
        radial[:, 0] = 0.0
        rho = np.linalg.norm(radial, axis=1)
        e_r = radial / rho[:, None]
        e_phi = np.column_stack([np.zeros(len(p)), e_r[:, 2], -e_r[:, 1]])
        along = np.abs(np.einsum("ij,ij->i", n, e_phi))
        section = along < 1e-9
        assert np.all(section | (along > 1 - 1e-12))  # end caps face along the band
        d = p - ([0.0, 0.0, zc] + r_mid * e_r)
        assert np.all(np.einsum("ij,ij->i", n, d)[section] > 0)


def test_flat_parts(mesh):
    part = mesh.cell_data["part"]
    t = triangles(mesh)
    P, N = np.asarray(mesh.points), mesh.point_data["Normals"]
    face = np.unique(t[part == WATCH_PARTS["face"]])
    led = np.unique(t[part == WATCH_PARTS["led"]])
    bezel = np.unique(t[part == WATCH_PARTS["bezel"]])
    assert np.all(N[face] == [0.0, 0.0, 1.0]) and np.all(N[led] == [0.0, 0.0, 1.0])
    assert np.ptp(P[face, 2]) == 0 and np.ptp(P[led, 2]) == 0
    # LEDs lie just above the face and inside it; the bezel stands above both
    assert P[face, 2][0] < P[led, 2][0] < P[bezel, 2].max()
    lo, hi = P[face, :2].min(axis=0), P[face, :2].max(axis=0)
    assert np.all(P[led, :2] > lo) and np.all(P[led, :2] < hi)
    assert N[bezel, 2].min() >= -1e-12  # the half-round bezel faces up
    # the face is the top of the watch's body: the case lies below it
    case = np.unique(t[part == WATCH_PARTS["case"]])
    assert P[case, 2].max() < P[face, 2][0]


@pytest.mark.parametrize("display", ["12:00", "88:88", "10:47", "3:59", "1", "0123456789"])
def test_led_segments_form_the_digits(display):
    kwargs = {"display": display}
    if len(display) > 5:
        kwargs.update(digit_height=0.25, segment_thickness=0.035)
    mesh = watch(**kwargs)
    pieces, _ = components(mesh, ["led"])
    expected = sum(SEGMENTS_PER_DIGIT[c] for c in display if c != ":") + 2 * display.count(":")
    assert len(pieces) == expected


def test_link_border_and_interior_areas():
    # with a border narrower than the link's corner radius the rough interior is a rounded
    # rectangle: area (w - 2b)(l - 2b) - (4 - pi)(r - b)^2, inscribed polygons slightly less
    w, length, r, b = 0.6, 0.8, 0.15, 0.1
    mesh = watch(link_size=(w, length, 0.25), link_corner_radius=r, link_border_width=b,
                 links_per_side=4, n_quarter=12, spacing=0.02)
    _, area = face_normals_and_areas(mesh)
    part = mesh.cell_data["part"]
    interior = area[part == WATCH_PARTS["band_outer_interior"]].sum()
    border = area[part == WATCH_PARTS["band_outer_border"]].sum()
    one = (w - 2 * b) * (length - 2 * b) - (4 - np.pi) * (r - b) ** 2
    assert interior == pytest.approx(16 * one, rel=2e-3)
    assert interior < 16 * one
    # the border's flat top ring alone is the plan minus the interior
    plan = w * length - (4 - np.pi) * r**2
    assert border > 16 * (plan - one)


def test_deterministic(mesh):
    again = watch()
    assert np.array_equal(mesh.points, again.points)
    assert np.array_equal(mesh.faces, again.faces)
    for key in ("Normals", "uv"):
        assert np.array_equal(mesh.point_data[key], again.point_data[key])
    assert np.array_equal(mesh.cell_data["part"], again.cell_data["part"])


def test_bracelet_follows_the_wrist(mesh):
    # every link's top centre touches the wrist cylinder (about an axis parallel to x), and the
    # two halves of the bracelet mirror each other through the case centre
    t = triangles(mesh)
    part = mesh.cell_data["part"]
    P = np.asarray(mesh.points)
    interior = P[np.unique(t[part == WATCH_PARTS["band_outer_interior"]])]
    assert np.allclose(np.sort(interior[:, 1]), np.sort(-interior[:, 1]), atol=1e-12)
    # documented defaults: top surface radius 4.5, at height 0.3 where it enters the case at
    # 80 % of the case's half-length (3.6 / 2); links 0.62 wide beside a 0.56 strip, gaps 0.05
    radius, y_enter, height = 4.5, 0.8 * 1.8, 0.3
    zc = height - np.sqrt(radius**2 - y_enter**2)
    pieces, W = components(mesh, ["band_outer_interior"])
    centres = []
    for t in pieces:  # area centroid of each flat interior
        a, b, c = W[t[:, 0]], W[t[:, 1]], W[t[:, 2]]
        area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
        centres.append((area[:, None] * (a + b + c) / 3.0).sum(axis=0) / area.sum())
    centres = np.array(centres)
    assert len(centres) == 24
    assert np.allclose(np.hypot(centres[:, 1], centres[:, 2] - zc), radius, atol=1e-9)
    assert np.allclose(np.abs(centres[:, 0]), 0.28 + 0.05 + 0.31, atol=1e-12)


def test_composes_into_a_scene(mesh):
    scene = compose([(mesh, 5)])
    assert np.array_equal(scene.cell_data["part"], mesh.cell_data["part"])
    assert np.all(scene.cell_data["object_id"] == 5)


@pytest.mark.parametrize("kwargs, match", [
    ({"display": "12:0A"}, "known"),
    ({"display": ""}, "display"),
    ({"display": "12:00:00"}, "does not fit"),
    ({"case_size": (3.0, -1.0, 0.8)}, r"case_size\[1\]"),
    ({"links_per_side": 0}, "links_per_side"),
    ({"link_border_width": 0.2}, "link_border_width"),
    ({"window_size": (3.5, 1.0)}, "window"),
    ({"digit_slant_deg": 60}, "digit_slant_deg"),
])
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        watch(**kwargs)
