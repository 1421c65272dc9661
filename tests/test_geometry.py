"""Tests of reflectance.geometry.shapes against analytic surfaces (cones, tori, superellipsoids)."""

import numpy as np
import pytest
import pyvista as pv
from hypothesis import given, settings
from hypothesis import strategies as st

import reflectance.geometry.shapes as shapes
from reflectance.geometry.shapes import (
    VASE_INTERPOLATION_METHODS,
    VASE_PARTS,
    analytic_spheres,
    compose,
    mesh_from_file,
    place,
    plane,
    sphere,
    superellipsoid_Barr1981,
    torus,
    vase,
)

# a cone frustum: collinear profile points, which every interpolant reproduces exactly
SLOPE, R0, HEIGHT, WALL = 0.25, 0.5, 1.0, 0.04
CONE = [(R0 + SLOPE * z, z) for z in np.linspace(0.0, HEIGHT, 5)]
VASE_PROFILE = [(0.35, 0.0), (0.55, 0.15), (0.75, 0.45), (0.7, 0.75), (0.4, 1.05),
                (0.3, 1.3), (0.42, 1.5)]


def triangles(mesh):
    return np.asarray(mesh.faces).reshape(-1, 4)[:, 1:]


def face_normals(mesh):
    P = np.asarray(mesh.points)
    t = triangles(mesh)
    n = np.cross(P[t[:, 1]] - P[t[:, 0]], P[t[:, 2]] - P[t[:, 0]])
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def cells_of_part(mesh, part):
    return triangles(mesh)[np.asarray(mesh.cell_data["part"]) == VASE_PARTS[part]]


def points_of_part(mesh, part):
    return np.unique(cells_of_part(mesh, part))


@pytest.fixture(scope="module")
def cone():
    return vase(CONE, 48, 12, WALL)


@pytest.mark.parametrize("method", sorted(VASE_INTERPOLATION_METHODS))
def test_cone_outer_wall_normals_are_the_analytic_cone_normals(cone, method):
    mesh = cone if method == "cubic" else vase(CONE, 48, 12, WALL, interpolation=method)
    i = points_of_part(mesh, "outer")
    p, n = mesh.points[i], mesh.point_data["Normals"][i]
    rho = np.hypot(p[:, 0], p[:, 1])
    # surface r = R0 + SLOPE z: outward normal (cos t, sin t, -SLOPE) / sqrt(1 + SLOPE^2)
    expected = np.column_stack([p[:, 0] / rho, p[:, 1] / rho, np.full(len(p), -SLOPE)])
    expected /= np.sqrt(1 + SLOPE**2)
    np.testing.assert_allclose(n, expected, atol=1e-12)
    np.testing.assert_allclose(rho, R0 + SLOPE * p[:, 2], atol=1e-12)


def test_cone_inner_wall_is_the_offset_surface_at_wall_thickness(cone):
    i = points_of_part(cone, "inner")
    p, n = cone.points[i], cone.point_data["Normals"][i]
    rho = np.hypot(p[:, 0], p[:, 1])
    # distance from (rho, z) to the line rho = R0 + SLOPE z in the profile plane
    distance = (R0 + SLOPE * p[:, 2] - rho) / np.sqrt(1 + SLOPE**2)
    np.testing.assert_allclose(distance, WALL, atol=1e-12)
    assert np.all(np.einsum("ij,ij->i", n, p * [1, 1, 0]) < 0)  # faces the axis
    floor = cone.points[points_of_part(cone, "floor")]
    np.testing.assert_allclose(floor[:, 2], WALL, atol=1e-12)  # floor WALL above the bottom


def test_cone_uv_is_angle_and_arc_length_fraction(cone):
    i = points_of_part(cone, "outer")
    p, uv = cone.points[i], cone.point_data["uv"][i]
    # straight profile: arc length is proportional to height
    np.testing.assert_allclose(uv[:, 1], p[:, 2] / HEIGHT, atol=1e-12)
    angle = np.mod(np.arctan2(p[:, 1], p[:, 0]), 2 * np.pi) / (2 * np.pi)
    seam = np.isclose(uv[:, 0], 1.0)
    np.testing.assert_allclose(uv[~seam, 0], angle[~seam], atol=1e-12)
    np.testing.assert_allclose(angle[seam] % 1.0, 0.0, atol=1e-12)


def test_vase_is_a_closed_shell_with_consistent_normals():
    mesh = vase(VASE_PROFILE, 64, 40, 0.03)
    assert mesh.is_all_triangles
    assert set(np.unique(mesh.cell_data["part"])) == set(VASE_PARTS.values())
    welded = mesh.clean(tolerance=1e-9, absolute=True)
    edges = welded.extract_feature_edges(boundary_edges=True, non_manifold_edges=True,
                                         feature_edges=False, manifold_edges=False)
    assert edges.n_cells == 0  # closed: a point inside can only see out through the opening
    n = mesh.point_data["Normals"]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-12)
    # facets agree with the smooth normals of their corners
    corner = n[triangles(mesh)].sum(axis=1)
    assert np.all(np.einsum("ij,ij->i", face_normals(mesh), corner) > 0)
    assert welded.volume > 0


def test_vase_normals_are_smooth_across_the_rim():
    mesh = vase(VASE_PROFILE, 32, 40, 0.03)
    n, p = mesh.point_data["Normals"], mesh.points
    # coincident vertices of adjacent parts (outer/rim, rim/inner) carry the same normal
    for a, b in (("outer", "rim"), ("rim", "inner")):
        ia, ib = points_of_part(mesh, a), points_of_part(mesh, b)
        d = np.linalg.norm(p[ia][:, None] - p[ib][None], axis=2)
        ja, jb = np.nonzero(d < 1e-12)
        assert len(ja) >= 32
        np.testing.assert_allclose(n[ia][ja], n[ib][jb], atol=1e-12)


def test_vase_outer_normals_are_perpendicular_to_the_surface():
    mesh = vase(VASE_PROFILE, 64, 400, 0.03)
    i = points_of_part(mesh, "outer")
    p, n = mesh.points[i], mesh.point_data["Normals"][i]
    # rotational symmetry: no azimuthal component
    np.testing.assert_allclose(n[:, 0] * p[:, 1] - n[:, 1] * p[:, 0], 0.0, atol=1e-12)
    # along the profile (one meridian, densely sampled): normal is perpendicular to the chord
    meridian = i[np.isclose(mesh.point_data["uv"][i, 0], 0.0)]
    q = mesh.points[meridian][np.argsort(mesh.point_data["uv"][meridian, 1])]
    m = mesh.point_data["Normals"][meridian][np.argsort(mesh.point_data["uv"][meridian, 1])]
    chord = np.diff(q, axis=0)
    chord /= np.linalg.norm(chord, axis=1, keepdims=True)
    mid = m[:-1] + m[1:]
    mid /= np.linalg.norm(mid, axis=1, keepdims=True)
    assert np.abs(np.einsum("ij,ij->i", chord, mid)).max() < 1e-4


def same_mesh(a, b):
    """The same arrays, bit for bit (NaN nowhere)."""
    assert a.n_points == b.n_points and a.n_cells == b.n_cells
    assert np.array_equal(a.points, b.points) and a.points.dtype == b.points.dtype
    assert np.array_equal(a.faces, b.faces)
    for data in ("point_data", "cell_data"):
        A, B = getattr(a, data), getattr(b, data)
        assert list(A.keys()) == list(B.keys())
        for name in A.keys():
            assert A[name].dtype == B[name].dtype and np.array_equal(A[name], B[name]), name
    return True


def test_vase_is_deterministic():
    # two builds, not one build and its cached copy (shapes._vase: the build behind the cache)
    args = (VASE_PROFILE, 32, 20, 0.03, 9, "cubic")
    assert same_mesh(shapes._vase(*args), shapes._vase(*args))


# --- the vase's cache (reflectance.io.cache) -------------------------------------------------------

@pytest.fixture
def mesh_cache(tmp_path, monkeypatch):
    """An empty cache folder of this test's own; the builds of shapes._vase counted."""
    monkeypatch.setenv("REFLECTANCE_CACHE", str(tmp_path / "cache"))
    builds = []
    build = shapes._vase

    def counted(*args):
        builds.append(args)
        return build(*args)

    monkeypatch.setattr(shapes, "_vase", counted)
    return tmp_path / "cache", builds


def test_cached_vase_is_the_built_one_bit_for_bit(mesh_cache):
    folder, builds = mesh_cache
    first = vase(VASE_PROFILE, 32, 20, 0.03)
    again = vase(VASE_PROFILE, 32, 20, 0.03)  # read back: no second build
    assert len(builds) == 1
    assert same_mesh(first, again)
    (stored,) = folder.glob("meshes-*/vase-*.npz")
    assert stored.stat().st_size > 0
    # other arguments: another file, built
    other = vase(VASE_PROFILE, 32, 20, 0.04)
    assert len(builds) == 2 and len(list(folder.glob("meshes-*/vase-*.npz"))) == 2
    assert not np.array_equal(other.points, first.points)


def test_damaged_or_unwritable_mesh_cache_builds_again(mesh_cache, tmp_path, monkeypatch):
    folder, builds = mesh_cache
    first = vase(VASE_PROFILE, 16, 10, 0.03)
    (stored,) = folder.glob("meshes-*/vase-*.npz")
    stored.write_bytes(stored.read_bytes()[: stored.stat().st_size // 2])  # cut short
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 2
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 2  # mended
    # a file of the right name holding other arrays (a vertex out of range) is not believed
    data = dict(np.load(stored))
    data["tris"] = data["tris"] + len(data["points"])
    with open(stored, "wb") as file:
        np.savez(file, **data)
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 3
    # nor a lone array (.npy) under the archive's name, nor a vertex that is not finite
    with open(stored, "wb") as file:
        np.save(file, np.zeros(3))
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 4
    data = dict(np.load(stored))
    data["normals"][0, 0] = np.nan
    with open(stored, "wb") as file:
        np.savez(file, **data)
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 5
    # a cache folder that cannot be made: every call builds, nothing is raised
    blocker = tmp_path / "blocker"
    blocker.write_text("a file where the folder would be")
    monkeypatch.setenv("REFLECTANCE_CACHE", str(blocker))
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 6
    assert same_mesh(vase(VASE_PROFILE, 16, 10, 0.03), first) and len(builds) == 7


def test_stale_mesh_cache_of_another_version_is_dropped_and_nothing_else(mesh_cache):
    import os
    import time

    folder, builds = mesh_cache
    week = shapes.MESH_CACHE_STALE_DAYS * 86400

    def made(name, age_s):
        path = folder / name
        path.mkdir(parents=True)
        (path / "vase-x.npz").write_bytes(b"old")
        os.utime(path, (time.time() - age_s, time.time() - age_s))
        return path

    stale = made("meshes-0000000000000000-numpy-0-scipy-0-pyvista-0", week + 3600)
    recent = made("meshes-1111111111111111-numpy-0-scipy-0-pyvista-0", week - 3600)  # in use
    mine = made("meshes-of-my-own", 10 * week)  # not a name of the cache's: not touched
    tables = made("colour-science-0.0", 10 * week)  # another user of the cache
    vase(VASE_PROFILE, 16, 10, 0.03)
    assert not stale.exists() and recent.exists() and mine.exists() and tables.exists()
    assert (folder / shapes._mesh_cache_name()).is_dir()


def test_mesh_cache_unreachable_builds(monkeypatch, mesh_cache):
    """No home folder to put the cache in (some containers, batch jobs): the vase is built."""
    folder, builds = mesh_cache
    monkeypatch.delenv("REFLECTANCE_CACHE")
    monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
    monkeypatch.setattr(shapes, "_mesh_cache_directory",
                        lambda: (_ for _ in ()).throw(RuntimeError("no home directory")))
    assert vase(VASE_PROFILE, 16, 10, 0.03).n_cells > 0 and len(builds) == 1


def test_bad_vase_input_is_refused_whatever_the_cache_holds(mesh_cache):
    folder, builds = mesh_cache
    with pytest.raises(ValueError, match="wall_thickness"):
        vase(VASE_PROFILE, 16, 10, 0.6)
    assert not list(folder.glob("meshes-*/vase-*.npz"))  # nothing cached of a refused call


@pytest.mark.parametrize("kwargs, message", [
    (dict(profile=[(0.5, 0), (0.6, 1)]), "at least 3"),
    (dict(profile=[(-0.1, 0), (0.5, 0.5), (0.4, 1)]), "radius must be >= 0"),
    (dict(profile=[(0.5, 0), (0.5, 0), (0.4, 1)]), "same point"),
    (dict(wall_thickness=0.0), "wall_thickness"),
    (dict(wall_thickness=0.6), "wall_thickness"),
    (dict(interpolation="akima"), "cubic"),
    (dict(n_theta=2), "n_theta"),
])
def test_vase_rejects_bad_input(kwargs, message):
    args = dict(profile=VASE_PROFILE, n_theta=16, n_profile_samples=10, wall_thickness=0.03)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        vase(**args)


def test_sphere_proxy_encloses_the_exact_sphere():
    c, r = np.array([0.3, -1.0, 2.0]), 1.7
    s = sphere(c, r, 24, 12)
    centers, radii = analytic_spheres(s)
    np.testing.assert_array_equal(centers, [c])
    np.testing.assert_array_equal(radii, [r])
    P, t = np.asarray(s.points), triangles(s)
    fn = face_normals(s)
    plane_distance = np.abs(np.einsum("ij,ij->i", fn, P[t[:, 0]] - c))
    assert plane_distance.min() >= r  # every ray that meets the ball meets the proxy
    assert plane_distance.min() < r * (1 + 1e-6)  # and the proxy is tight
    n = s.point_data["Normals"]
    np.testing.assert_allclose(n, (P - c) / np.linalg.norm(P - c, axis=1, keepdims=True),
                               atol=1e-12)
    assert np.all(s.cell_data["sphere_index"] == 0)


def test_torus_normals_point_from_the_tube_centre():
    R, r = 1.0, 0.3
    t = torus(R, r, 32, 16, center=(1, 2, 3))
    p = t.points - [1, 2, 3]
    ring = p * [1, 1, 0]
    ring = R * ring / np.linalg.norm(ring, axis=1, keepdims=True)
    np.testing.assert_allclose(np.linalg.norm(p - ring, axis=1), r, atol=1e-12)
    np.testing.assert_allclose(t.point_data["Normals"], (p - ring) / r, atol=1e-12)
    with pytest.raises(ValueError, match="minor_radius"):
        torus(1.0, 1.5, 8, 8)


@settings(max_examples=10, deadline=None)
@given(e1=st.floats(0.2, 1.8), e2=st.floats(0.2, 1.8))
def test_superellipsoid_points_and_normals_match_the_implicit_surface(e1, e2):
    a = np.array([1.0, 0.7, 0.5])
    mesh = superellipsoid_Barr1981(a, (e1, e2), 16, 8)
    x, y, z = (np.abs(mesh.points) / a).T
    # Barr 1981, inside-outside function F = ((x^(2/e2) + y^(2/e2))^(e2/e1) + z^(2/e1))
    xy = x ** (2 / e2) + y ** (2 / e2)
    np.testing.assert_allclose(xy ** (e2 / e1) + z ** (2 / e1), 1.0, atol=1e-9)
    # its gradient gives the normal direction, away from the poles and the axis planes
    with np.errstate(divide="ignore", invalid="ignore"):
        g = np.column_stack([
            xy ** (e2 / e1 - 1) * x ** (2 / e2 - 1) / a[0],
            xy ** (e2 / e1 - 1) * y ** (2 / e2 - 1) / a[1],
            z ** (2 / e1 - 1) / a[2],
        ]) * np.sign(mesh.points)
    ok = np.all(np.isfinite(g), axis=1) & (np.min(np.abs(mesh.points), axis=1) > 1e-6)
    g = g[ok] / np.linalg.norm(g[ok], axis=1, keepdims=True)
    np.testing.assert_allclose(mesh.point_data["Normals"][ok], g, atol=1e-9)


def test_plane_geometry_and_uv():
    p = plane((1, 2, 3), (0, 0, 2), (4, 2), (4, 2), u_direction=(1, 0, 0))
    np.testing.assert_allclose(p.points[:, 2], 3.0)
    np.testing.assert_allclose(p.point_data["Normals"], np.tile([0, 0, 1.0], (p.n_points, 1)))
    np.testing.assert_allclose(p.point_data["uv"][:, 0], (p.points[:, 0] - 1 + 2) / 4)
    np.testing.assert_allclose(p.point_data["uv"][:, 1], (p.points[:, 1] - 2 + 1) / 2)
    assert np.all(face_normals(p) @ [0, 0, 1] > 0.999)


@pytest.mark.parametrize("suffix", [".stl", ".ply", ".obj"])
def test_mesh_from_file_reads_triangles_with_unit_normals(tmp_path, suffix):
    source = pv.Sphere(radius=2.0, theta_resolution=16, phi_resolution=8)
    path = tmp_path / f"ball{suffix}"
    source.save(path)
    mesh = mesh_from_file(path)
    assert mesh.is_all_triangles and mesh.n_cells == source.n_cells
    n = mesh.point_data["Normals"]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-6)
    # outward on a sphere: normal close to the radial direction
    radial = mesh.points / np.linalg.norm(mesh.points, axis=1, keepdims=True)
    assert np.einsum("ij,ij->i", n, radial).min() > 0.9
    uv = mesh.point_data["uv"]
    assert uv.shape == (mesh.n_points, 2) and np.all((uv >= 0) & (uv <= 1))


def test_mesh_from_file_errors(tmp_path):
    with pytest.raises(ValueError, match="unsupported"):
        mesh_from_file(tmp_path / "x.dae")
    with pytest.raises(ValueError, match="not found"):
        mesh_from_file(tmp_path / "missing.stl")


def test_place_moves_points_normals_and_spheres():
    angle = 0.7
    Rz = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0],
                   [0, 0, 1]])
    s = sphere((1, 0, 0), 0.5, 16, 8)
    moved = place(s, offset=(0, 0, 2), scale=3.0, rotation=Rz)
    c, r = analytic_spheres(moved)
    np.testing.assert_allclose(c[0], 3 * Rz @ [1, 0, 0] + [0, 0, 2])
    np.testing.assert_allclose(r, [1.5])
    np.testing.assert_allclose(moved.points, 3 * s.points @ Rz.T + [0, 0, 2])
    np.testing.assert_allclose(moved.point_data["Normals"], s.point_data["Normals"] @ Rz.T)
    with pytest.raises(ValueError, match="rotation"):
        place(s, rotation=np.diag([1.0, 1.0, -1.0]))


def test_compose_tags_objects_and_renumbers_spheres():
    a, b = sphere((0, 0, 0), 1.0, 8, 4), sphere((3, 0, 0), 0.5, 8, 4)
    p = plane((0, 0, -1), (0, 0, 1), (2, 2), (1, 1))
    scene = compose([(a, 5), (p, 0), (b, 5)])
    oid = np.asarray(scene.cell_data["object_id"])
    np.testing.assert_array_equal(np.unique(oid), [0, 5])
    centers, radii = analytic_spheres(scene)
    np.testing.assert_allclose(radii, [1.0, 0.5])
    sidx = np.asarray(scene.cell_data["sphere_index"])
    assert np.all(sidx[: a.n_cells] == 0) and np.all(sidx[-b.n_cells:] == 1)
    assert np.all(sidx[a.n_cells: a.n_cells + p.n_cells] == -1)
    with pytest.raises(ValueError, match="object_id"):
        compose([(a, -1)])
    with pytest.raises(ValueError, match="pair"):
        compose([a])


def test_vase_discs_have_no_sliver_fan():
    mesh = vase(VASE_PROFILE, 64, 40, 0.03)
    P = mesh.points
    for part in ("floor", "bottom"):
        t = cells_of_part(mesh, part)
        corners = P[t]
        angles = []
        for k in range(3):
            u = corners[:, (k + 1) % 3] - corners[:, k]
            v = corners[:, (k + 2) % 3] - corners[:, k]
            cos = np.einsum("ij,ij->i", u, v) / np.linalg.norm(u, axis=1) / np.linalg.norm(v, axis=1)
            angles.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
        assert np.min(angles) > 15.0  # rings thin out toward the centre
        np.testing.assert_allclose(P[np.unique(t), 2], P[np.unique(t), 2][0], atol=0)
