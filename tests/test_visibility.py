"""Tests of reflectance.render.visibility against independent ray geometry written here."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.geometry.shapes import VASE_PARTS, compose, plane, sphere, torus, vase
from reflectance.render.camera import Camera
from reflectance.render.idbuffer import (IdRenderer, decode_ids, distinct_keys, encode_ids,
                                         id_buffer)
from reflectance.render.primitives import Primitives
from reflectance.render.lights import DirectionalLight, PointLight, as_light, light_vectors
from reflectance.render.rays import ray_sphere, ray_triangle_MollerTrumbore1997
from reflectance.render.shadows import shadow_mask, shadow_masks
from reflectance.render.visibility import visibility


# ---- independent helpers (textbook formulas, not the module's) --------------------------------

def sphere_hit(origin, directions, centre, radius):
    """Nearest t > 0 of unit rays from outside a sphere by the plain quadratic; nan if none."""
    oc = np.asarray(origin) - centre
    b = directions @ oc
    disc = b**2 - (oc @ oc - radius**2)
    with np.errstate(invalid="ignore"):
        t = -b - np.sqrt(disc)
    return np.where((disc >= 0) & (t > 0), t, np.nan)


def blocked_by_sphere(points, towards, centre, radius):
    """Whether rays from points along unit directions meet the sphere at t > 0."""
    oc = points - centre
    b = np.einsum("ij,ij->i", towards, oc)
    c = np.einsum("ij,ij->i", oc, oc) - radius**2
    disc = b**2 - c
    with np.errstate(invalid="ignore"):
        far = -b + np.sqrt(disc)
    return (disc > 0) & (far > 0) & (c > 0)


def rays_through_pixels(position, look_at, up, fov_deg, width, height, xs, ys):
    """Pinhole rays through image points (x right, y down, in pixels)."""
    f = np.subtract(look_at, position)
    f = f / np.linalg.norm(f)
    r = np.cross(f, up)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    h = np.tan(np.radians(fov_deg) / 2)
    sx = (2 * xs / width - 1) * h * width / height
    sy = (1 - 2 * ys / height) * h
    d = f + sx[:, None] * r + sy[:, None] * u
    return d / np.linalg.norm(d, axis=1, keepdims=True)


CENTRE, RADIUS = np.array([0.0, 0.0, 0.0]), 1.0
GROUND = -1.5


@pytest.fixture(scope="module")
def ball_scene():
    return compose([(sphere(CENTRE, RADIUS, 48, 24), 1),
                    (plane((0, 0, GROUND), (0, 0, 1), (8, 8), (8, 8)), 2)])


@pytest.fixture(scope="module")
def ball_camera():
    return Camera((0.4, -5.0, 3.0), (0, 0, -0.6), (0, 0, 1), 40.0, 64, 64, 1)


@pytest.fixture(scope="module")
def ball_samples(ball_scene, ball_camera):
    return visibility(ball_scene, ball_camera)


# ---- camera ----------------------------------------------------------------------------------

def test_sample_coordinates_are_pixel_centres_and_stratified_subpixels():
    one = Camera((0, 0, 5), (0, 0, 0), (0, 1, 0), 30, 3, 2, 1)
    x, y = one.sample_coordinates()
    np.testing.assert_array_equal(x, [0.5, 1.5, 2.5, 0.5, 1.5, 2.5])
    np.testing.assert_array_equal(y, [0.5, 0.5, 0.5, 1.5, 1.5, 1.5])
    three = Camera((0, 0, 5), (0, 0, 0), (0, 1, 0), 30, 2, 1, 3)
    x, y = three.sample_coordinates()
    assert three.shape == (3, 6)
    np.testing.assert_allclose(x[:6], [1 / 6, 3 / 6, 5 / 6, 7 / 6, 9 / 6, 11 / 6])
    np.testing.assert_allclose(y.reshape(3, 6)[:, 0], [1 / 6, 3 / 6, 5 / 6])


def test_camera_rays_match_a_pinhole_model():
    cam = Camera((0.3, -4.0, 2.0), (0.1, 0.2, 0.4), (0, 0, 1), 37.0, 20, 12, 2)
    eye, d = cam.rays()
    x, y = cam.sample_coordinates()
    expected = rays_through_pixels(cam.position, cam.look_at, cam.up, cam.fov_deg, 20, 12, x, y)
    np.testing.assert_allclose(eye, cam.position)
    np.testing.assert_allclose(d, expected, atol=1e-14)


def test_camera_projection_matches_vtk_world_to_display():
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow

    cam = Camera((0.3, -4.0, 2.0), (0.1, 0.2, 0.4), (0, 0, 1), 37.0, 80, 50, 1)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(80, 50)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    vc = renderer.GetActiveCamera()
    vc.SetPosition(*cam.position)
    vc.SetFocalPoint(*cam.look_at)
    vc.SetViewUp(*cam.up)
    vc.SetViewAngle(cam.fov_deg)
    points = np.random.default_rng(3).normal(size=(6, 3))
    x, y, _ = cam.project(points)
    for p, xi, yi in zip(points, x, y):
        renderer.SetWorldPoint(*p, 1.0)
        renderer.WorldToDisplay()
        dx, dy, _ = renderer.GetDisplayPoint()
        assert abs(dx - xi) < 1e-9 and abs((50 - dy) - yi) < 1e-9  # VTK's y runs upwards
    window.Finalize()


@pytest.mark.parametrize("kwargs, message", [
    (dict(fov_deg=180.0), "fov_deg"),
    (dict(width=0), "width"),
    (dict(supersample=1.5), "supersample"),
    (dict(up=(0, 2, 2)), "parallel"),
    (dict(look_at=(0, 1, 1)), "differ"),
])
def test_camera_rejects_bad_input(kwargs, message):
    args = dict(position=(0, 1, 1), look_at=(0, 0, 0), up=(0, 0, 1), fov_deg=30.0, width=4,
                height=4)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        Camera(**args)


# ---- exact ray tests -------------------------------------------------------------------------

@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**31 - 1))
def test_moller_trumbore_recovers_barycentrics_of_a_known_point(seed):
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(3, 3))
    w = rng.dirichlet([1, 1, 1])
    target = w @ v
    origin = target + rng.normal(size=3) * 3
    direction = target - origin
    t, b1, b2, hit = ray_triangle_MollerTrumbore1997(origin, direction, *v)
    normal = np.cross(v[1] - v[0], v[2] - v[0])
    if abs(normal @ direction) < 1e-6 * np.linalg.norm(normal) * np.linalg.norm(direction):
        return  # grazing: ill-conditioned by nature
    assert hit
    np.testing.assert_allclose([t, b1, b2], [1.0, w[1], w[2]], rtol=1e-7, atol=1e-9)
    # outside the triangle by a margin: no hit
    outside = v[0] + 1.2 * (v[1] - v[0]) - 0.1 * (v[2] - v[0])
    assert not ray_triangle_MollerTrumbore1997(origin, outside - origin, *v)[3]


def test_ray_triangle_parallel_and_behind_give_no_hit_and_no_warning():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    with np.errstate(all="raise"):
        assert not ray_triangle_MollerTrumbore1997([0.2, 0.2, 1], [1, 0, 0], *v)[3]
        assert not ray_triangle_MollerTrumbore1997([0.2, 0.2, 1], [0, 0, 1], *v)[3]
        t, *_, hit = ray_triangle_MollerTrumbore1997([0.2, 0.2, 1], [0, 0, -1], *v, t_max=0.5)
    assert not hit and np.isinf(t)


def test_ray_sphere_matches_quadratic_and_is_precise_far_away():
    rng = np.random.default_rng(0)
    d = rng.normal(size=(200, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    origin = np.array([0.0, 0.0, 4.0])
    t, hit = ray_sphere(origin, d, CENTRE, RADIUS)
    t_ref = sphere_hit(origin, d, CENTRE, RADIUS)
    np.testing.assert_array_equal(hit, np.isfinite(t_ref))
    np.testing.assert_allclose(t[hit], t_ref[hit], rtol=1e-12)
    # a small sphere 1e6 away: the point found lies on the sphere to ~1e-10 of its radius
    far = np.array([1e6, 0.0, 0.0])
    t, hit = ray_sphere([0, 0, 0.5e-3], [1, 0, 0], far, 1e-3)
    p = np.array([0, 0, 0.5e-3]) + t * np.array([1, 0, 0])
    assert hit and abs(np.linalg.norm(p - far) - 1e-3) < 1e-10


# ---- the ID buffer ---------------------------------------------------------------------------

def test_id_encoding_round_trips():
    ids = np.array([0, 1, 255, 256, 65535, 65536, 2**24 - 1])
    np.testing.assert_array_equal(decode_ids(encode_ids(ids)), ids)
    with pytest.raises(ValueError):
        encode_ids([2**24])


def test_id_buffer_decodes_to_valid_ids_that_match_brute_force_first_hits():
    scene = compose([(torus(1.0, 0.35, 24, 12), 0)])
    cam = Camera((0.5, -3.0, 2.0), (0, 0, 0), (0, 0, 1), 45.0, 48, 40, 1)
    ids = id_buffer(scene, cam)
    n = scene.n_cells
    assert ids.shape == (40, 48) and ids.min() >= 0 and ids.max() <= n
    assert len(np.unique(ids)) > 100  # many distinct triangles, all decoded exactly
    eye, d = cam.rays()
    t = np.asarray(scene.faces).reshape(-1, 4)[:, 1:]
    P = np.asarray(scene.points)
    best, first = np.full(len(d), np.inf), np.zeros(len(d), np.int64)
    for k in range(n):  # brute force: every triangle against every ray
        tk, _, _, hit = ray_triangle_MollerTrumbore1997(eye, d, P[t[k, 0]], P[t[k, 1]],
                                                        P[t[k, 2]])
        better = hit & (tk < best)
        best[better], first[better] = tk[better], k + 1
    agree = np.mean(ids.ravel() == first)
    assert agree > 0.995  # rasterisation rules may differ only on exact edges


# ---- visibility ------------------------------------------------------------------------------

def test_sphere_samples_are_exact(ball_samples, ball_camera):
    s = ball_samples
    eye, d = ball_camera.rays()
    on = s.object_id == 1
    assert on.sum() > 300
    p, n = s.position[on], s.normal[on]
    np.testing.assert_allclose(np.linalg.norm(p - CENTRE, axis=1), RADIUS, atol=1e-9)
    np.testing.assert_allclose(n, (p - CENTRE) / RADIUS, atol=1e-9)
    t_ref = sphere_hit(eye, d[on], CENTRE, RADIUS)
    np.testing.assert_allclose(p, eye + t_ref[:, None] * d[on], atol=1e-9)
    np.testing.assert_allclose(s.depth[on], t_ref, atol=1e-9)
    np.testing.assert_allclose(s.view[on], -d[on], atol=0)
    # uv of the exact point: azimuth and polar angle from -z
    np.testing.assert_allclose(s.uv[on, 1], np.arccos(-n[:, 2]) / np.pi, atol=1e-9)


def test_sphere_hit_mask_is_the_analytic_disc():
    cam = Camera((0, 0, 6.0), (0, 0, 0), (0, 1, 0), 30.0, 64, 64, 1)
    s = visibility([(sphere(CENTRE, RADIUS, 32, 16), 7)], cam)
    eye, d = cam.rays()
    analytic = np.isfinite(sphere_hit(eye, d, CENTRE, RADIUS))
    assert np.sum(s.hit != analytic) <= 2  # exact up to samples within rounding of the limb
    assert np.all(s.object_id[s.hit] == 7) and np.all(s.object_id[~s.hit] == -1)
    # area of the projected disc: radius tan(asin(r / D)) in units of tan(fov / 2)
    rho = np.tan(np.arcsin(RADIUS / 6.0)) / np.tan(np.radians(15.0)) * 32
    assert abs(s.hit.sum() - np.pi * rho**2) < 2 * np.pi * rho * 0.5 + 4


def test_plane_positions_lie_on_the_plane():
    depth = -2.0
    scene = compose([(plane((0, 0, depth), (0, 0, 1), (10, 10), (3, 3)), 3)])
    cam = Camera((0.3, -0.2, 3.0), (0.1, 0.4, depth), (0, 1, 0), 50.0, 32, 24, 2)
    s = visibility(scene, cam)
    assert s.hit.all()
    np.testing.assert_allclose(s.position[:, 2], depth, atol=1e-12)
    eye, d = cam.rays()
    t = (depth - eye[2]) / d[:, 2]
    np.testing.assert_allclose(s.position, eye + t[:, None] * d, atol=1e-12)
    np.testing.assert_allclose(s.normal, np.tile([0, 0, 1.0], (len(t), 1)), atol=1e-12)
    np.testing.assert_allclose(s.uv[:, 0], s.position[:, 0] / 10 + 0.5, atol=1e-12)


def test_plane_seen_from_behind_has_normals_toward_the_camera():
    scene = compose([(plane((0, 0, 0), (0, 0, 1), (10, 10), (2, 2)), 0)])
    s = visibility(scene, Camera((0, 0.1, -3.0), (0, 0, 0), (0, 1, 0), 40.0, 8, 8))
    assert s.hit.all() and s.flipped.all()
    np.testing.assert_allclose(s.normal, np.tile([0, 0, -1.0], (64, 1)), atol=1e-12)


def test_supersampling_equals_the_finer_grid():
    scene = compose([(sphere(CENTRE, RADIUS, 32, 16), 1),
                     (plane((0, 0, GROUND), (0, 0, 1), (8, 8), (4, 4)), 2)])
    coarse = Camera((0.4, -5.0, 3.0), (0, 0, -0.6), (0, 0, 1), 40.0, 16, 12, 2)
    fine = Camera((0.4, -5.0, 3.0), (0, 0, -0.6), (0, 0, 1), 40.0, 32, 24, 1)
    a, b = visibility(scene, coarse), visibility(scene, fine)
    for name in ("hit", "object_id", "position", "normal", "uv", "view"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    # samples (2i + a, 2j + b) belong to pixel (i, j)
    rows, cols = np.divmod(np.arange(32 * 24), 32)
    np.testing.assert_array_equal(a.pixel, (rows // 2) * 16 + cols // 2)
    pix = a.to_pixels(a.hit.astype(float))
    assert pix.shape == (12, 16)
    np.testing.assert_allclose(pix, a.image(a.hit.astype(float)).reshape(12, 2, 16, 2)
                               .mean(axis=(1, 3)))


def test_visibility_stats_report_raster_disagreements(ball_samples):
    stats = ball_samples.stats
    assert set(stats) == {"raster_miss", "recovered", "searched", "dropped"}
    assert all(0.0 <= v < 0.05 for v in stats.values())


def test_reruns_give_identical_arrays(ball_scene, ball_camera, ball_samples):
    again = visibility(ball_scene, ball_camera)
    for f in ("hit", "object_id", "triangle", "position", "normal", "uv", "view", "depth"):
        assert np.array_equal(getattr(again, f), getattr(ball_samples, f), equal_nan=True)
    light = {"type": "point", "position": [2.0, -1.0, 4.0]}
    assert np.array_equal(shadow_mask(again, ball_scene, light),
                          shadow_mask(ball_samples, ball_scene, light))


def test_one_window_for_camera_and_light_maps_gives_the_same_arrays(ball_scene, ball_camera,
                                                                     ball_samples):
    # the pipeline draws the camera's ID buffer and every light map in one window, resized
    # between views; each must be what a fresh window draws
    lights = [{"type": "point", "position": [2.0, -1.0, 4.0]},
              {"type": "directional", "direction": [0.35, 0.2, 1.0]}]
    alone = shadow_masks(ball_samples, ball_scene, lights, 96)
    scene = Primitives(ball_scene)
    with IdRenderer(scene) as window:
        for band in [(0, 64), (16, 40)]:  # the camera's whole grid, then a band (another size)
            shared = visibility(scene, ball_camera, band, renderer=window)
            fresh = visibility(scene, ball_camera, band)
            for f in ("hit", "triangle", "position", "normal", "depth"):
                assert np.array_equal(getattr(shared, f), getattr(fresh, f), equal_nan=True)
        np.testing.assert_array_equal(
            shadow_masks(visibility(scene, ball_camera, renderer=window), ball_scene, lights,
                         96, renderer=window), alone)


def test_distinct_keys_match_a_per_row_set(seed=3):
    rng = np.random.default_rng(seed)
    for width, high in [(9, 4), (9, 50), (9, 2**24), (5, 6)]:
        keys = rng.integers(-1, high, (400, width)).astype(np.int32)
        exclude = rng.integers(-1, high, 400).astype(np.int32)
        out = distinct_keys(keys, exclude)
        assert out.shape == keys.shape
        for row, k, e in zip(out, keys, exclude):
            kept = [v for v in row.tolist() if v >= 0]
            assert kept == sorted(set(k.tolist()) - {e, -1})  # each once, ascending


def test_camera_seeing_nothing():
    scene = compose([(sphere(CENTRE, RADIUS, 16, 8), 0)])
    s = visibility(scene, Camera((0, 0, 5), (0, 0, 10), (0, 1, 0), 20.0, 8, 8))
    assert not s.hit.any() and np.all(s.depth == np.inf) and np.all(s.triangle == -1)
    assert not shadow_mask(s, scene, {"type": "directional", "direction": [0, 0, 1]}).any()


# ---- shadows ---------------------------------------------------------------------------------

@pytest.mark.parametrize("light", [
    DirectionalLight((0.35, 0.2, 1.0)),
    PointLight((0.8, 0.5, 3.0)),
])
def test_sphere_shadow_on_plane_is_the_analytic_shadow(ball_scene, ball_samples, light):
    s = ball_samples
    mask = shadow_mask(s, ball_scene, light)
    ground = s.object_id == 2
    L, _ = light_vectors(light, s.position[ground])
    expected = blocked_by_sphere(s.position[ground], L, CENTRE, RADIUS)
    assert expected.sum() > 50 and (~expected).sum() > 50
    np.testing.assert_array_equal(mask[ground], expected)
    # on the sphere itself only the side turned away from the light is dark
    ball = s.object_id == 1
    L, _ = light_vectors(light, s.position[ball])
    np.testing.assert_array_equal(mask[ball], np.einsum("ij,ij->i", s.normal[ball], L) <= 0)
    assert not mask[~s.hit].any()


@pytest.mark.parametrize("light", [
    {"type": "directional", "direction": [1.0, 0.15, -0.25]},  # below the rim, from the side
    {"type": "point", "position": [2.5, 0.3, 0.4]},
])
def test_vase_interior_is_not_lit_through_the_wall(light):
    mesh = vase([(0.4, 0.0), (0.5, 0.4), (0.45, 0.8), (0.42, 1.0)], 48, 24, 0.03)
    scene = compose([(mesh, 1)])
    cam = Camera((0.0, -0.6, 2.6), (0.0, 0.0, 0.4), (0, 0, 1), 40.0, 48, 48, 1)
    s = visibility(scene, cam)
    part = np.asarray(scene.cell_data["part"])[np.maximum(s.triangle, 0)]
    inside = s.hit & np.isin(part, [VASE_PARTS["inner"], VASE_PARTS["floor"]])
    L, _ = light_vectors(light, s.position)
    turned = inside & (np.einsum("ij,ij->i", s.normal, L) > 0)
    assert turned.sum() > 50  # interior points facing the light, which sits below the rim
    assert shadow_mask(s, scene, light)[inside].all()


def test_shadow_masks_of_several_lights_equal_single_masks(ball_scene, ball_samples):
    lights = [{"type": "directional", "direction": [0.3, 0.1, 1.0]},
              {"type": "point", "position": [-1.0, 0.5, 2.5]}]
    both = shadow_masks(ball_samples, ball_scene, lights)
    assert both.shape == (2, ball_samples.hit.size)
    for mask, light in zip(both, lights):
        np.testing.assert_array_equal(mask, shadow_mask(ball_samples, ball_scene, light))


def test_point_light_inside_the_scene_uses_a_cube_map():
    # a light between a sphere and a large plane: directions span more than a hemisphere
    scene = compose([(sphere((0, 0, 1.5), 0.5, 32, 16), 1),
                     (plane((0, 0, 0), (0, 0, 1), (10, 10), (4, 4)), 2)])
    cam = Camera((0.0, -6.0, 4.0), (0, 0, 0.5), (0, 0, 1), 50.0, 48, 48, 1)
    s = visibility(scene, cam)
    light = PointLight((0.2, -0.1, 0.6))
    mask = shadow_mask(s, scene, light)
    ground = s.object_id == 2
    L, dist = light_vectors(light, s.position[ground])
    assert np.all(mask[ground] == False)  # noqa: E712  the sphere is above the light
    ball = s.object_id == 1
    L, _ = light_vectors(light, s.position[ball])
    np.testing.assert_array_equal(mask[ball], np.einsum("ij,ij->i", s.normal[ball], L) <= 0)


def test_lights_parse_and_reject_bad_input():
    assert as_light({"type": "point", "position": [1, 2, 3]}) == PointLight((1, 2, 3))
    np.testing.assert_allclose(DirectionalLight((0, 0, 5)).direction, (0, 0, 1))
    with pytest.raises(ValueError, match="directional"):
        as_light({"type": "spot", "position": [0, 0, 1]})
    with pytest.raises(ValueError, match="direction"):
        as_light({"type": "directional", "position": [0, 0, 1]})
    with pytest.raises(ValueError, match="non-zero"):
        DirectionalLight((0, 0, 0))
    L, dist = light_vectors(PointLight((0, 0, 2)), np.array([[0, 0, 0.0], [0, 3, 2.0]]))
    np.testing.assert_allclose(L, [[0, 0, 1], [0, -1, 0]])
    np.testing.assert_allclose(dist, [2, 3])


def lifted_origins(scene, samples, idx):
    """Shadow-ray origins by Hanika 2021 (Ray Tracing Gems II, ch. 4), written out again here:
    p' = p - sum_i b_i min(0, (p - v_i).n_i) n_i, then 1e-9 of the scene radius along n."""
    tris = np.asarray(scene.faces).reshape(-1, 4)[:, 1:][samples.triangle[idx]]
    V = np.asarray(scene.points)[tris]
    Nv = np.asarray(scene.point_data["Normals"])[tris]
    Nv = np.where(samples.flipped[idx][:, None, None], -Nv, Nv)
    b = samples.barycentric[idx]
    w = np.column_stack([1 - b[:, 0] - b[:, 1], b])
    p = samples.position[idx]
    below = np.minimum(np.einsum("nkj,nkj->nk", p[:, None, :] - V, Nv), 0.0)
    lifted = p - np.einsum("nk,nk,nkj->nj", w, below, Nv)
    pts = np.asarray(scene.points)
    centre = 0.5 * (pts.min(axis=0) + pts.max(axis=0))
    radius = np.linalg.norm(pts - centre, axis=1).max()
    return lifted + 1e-9 * radius * samples.normal[idx], 1e-9 * radius


@pytest.mark.parametrize("light", [
    DirectionalLight((-0.5, -0.8, 0.6)),
    DirectionalLight((1.0, 0.2, 0.12)),  # low: long shadows, grazing rim
    PointLight((0.1, -0.2, 2.2)),  # above the opening: the interior is partly lit
])
def test_shadow_mask_agrees_with_brute_force_ray_casting(light):
    profile = [(0.35, 0.0), (0.55, 0.15), (0.75, 0.45), (0.7, 0.75), (0.4, 1.05),
               (0.3, 1.3), (0.42, 1.5)]
    scene = compose([(vase(profile, 32, 20, 0.04), 1),
                     (plane((0, 0, -0.01), (0, 0, 1), (4, 4), (4, 4)), 2)])
    s = visibility(scene, Camera((0.2, -4.2, 2.4), (0, 0, 0.6), (0, 0, 1), 28.0, 40, 40))
    mask = shadow_mask(s, scene, light)
    idx = np.nonzero(s.hit)[0]
    L, dist = light_vectors(light, s.position[idx])
    facing = np.einsum("ij,ij->i", s.normal[idx], L) > 0
    origin, eps = lifted_origins(scene, s, idx)
    tris = np.asarray(scene.faces).reshape(-1, 4)[:, 1:]
    P = np.asarray(scene.points)
    truth = ~facing
    v0, e1, e2 = P[tris[:, 0]], P[tris[:, 1]] - P[tris[:, 0]], P[tris[:, 2]] - P[tris[:, 0]]
    n12 = np.cross(e1, e2)
    todo = np.nonzero(facing)[0]
    for chunk in np.array_split(todo, max(1, len(todo) // 64)):
        # every triangle against every shadow ray: o + t L = v0 + u e1 + v e2 by Cramer's rule
        s_ = origin[chunk, None, :] - v0[None]
        Lc = L[chunk, None, :]
        det = -np.einsum("tj,sj->st", n12, L[chunk])
        with np.errstate(divide="ignore", invalid="ignore"):
            u = -np.einsum("stj,stj->st", s_, np.cross(e2[None], Lc)) / det
            v = -np.einsum("stj,stj->st", np.cross(e1[None], s_), Lc) / det
            t = np.einsum("tj,stj->st", n12, s_) / det
            inside = ((u >= 0) & (v >= 0) & (u + v <= 1) & (t > eps)
                      & (t < dist[chunk, None] - eps))
        inside[np.arange(len(chunk)), s.triangle[idx[chunk]]] = False  # its own triangle
        truth[chunk] = inside.any(axis=1)
    got = mask[idx]
    assert truth.sum() > 100 and (~truth).sum() > 100
    assert not np.any(got & ~truth)  # every reported shadow has a real occluder
    assert np.sum(truth & ~got) <= 0.005 * truth.sum()


def test_sub_pixel_triangles_are_found_exactly():
    """The watch has many triangles smaller than a pixel at this size: samples whose true
    triangle never reached the ID buffer are found by the exact bounding-box search, so no
    covered sample is dropped, and every hit agrees with a brute-force nearest hit."""
    from reflectance.geometry.watch import watch

    scene = compose([(watch(), 0)])
    cam = Camera((-10, -7, 11), (0, 0, -1.2), (0, 0, 1), 34.0, 240, 192)
    s = visibility(scene, cam)
    assert s.stats["searched"] > 0 and s.stats["dropped"] == 0.0
    # brute force on a deterministic subset of hit samples: nearest triangle along the ray
    tris = np.asarray(scene.faces).reshape(-1, 4)[:, 1:]
    P = np.asarray(scene.points, np.float64)
    eye, d = cam.rays()
    idx = np.nonzero(s.hit)[0][::997]
    a, b, c = P[tris[:, 0]], P[tris[:, 1]], P[tris[:, 2]]
    for i in idx:
        e1, e2 = b - a, c - a
        pvec = np.cross(d[i], e2)
        det = np.einsum("ij,ij->i", e1, pvec)
        ok = np.abs(det) > 1e-14
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        tvec = eye - a
        u = np.einsum("ij,ij->i", tvec, pvec) * inv
        q = np.cross(tvec, e1)
        v = (q @ d[i]) * inv
        t = np.einsum("ij,ij->i", e2, q) * inv
        valid = ok & (u >= -1e-9) & (v >= -1e-9) & (u + v <= 1 + 1e-9) & (t > 0)
        assert valid.any()
        assert np.isclose(t[valid].min(), np.linalg.norm(s.position[i] - eye), rtol=1e-6,
                          atol=1e-9)


@pytest.mark.parametrize("height", [1.0, 0.05])
def test_large_floor_under_the_camera_is_not_clipped_near_the_eye(height):
    # two triangles 2000 units wide whose far corners are the only vertices ahead of the eye:
    # the floor seen at the bottom of the image is far nearer than any of them
    floor = plane((0, 0, 0), (0, 0, 1), (2000.0, 2000.0), (1, 1))
    assert floor.n_cells == 2
    cam = Camera((0, 0, height), (0, 5, 0), (0, 0, 1), 60.0, 48, 32)
    s = visibility([(floor, 1)], cam)
    eye, d = cam.rays()
    t = -height / d[:, 2]  # the exact ray meets z = 0 at t > 0 iff it points down
    with np.errstate(invalid="ignore"):
        p = eye + t[:, None] * d
    truth = (d[:, 2] < 0) & (np.abs(p[:, 0]) < 1000) & (np.abs(p[:, 1]) < 1000)
    assert truth.mean() > 0.4  # the bottom half and more
    np.testing.assert_array_equal(s.hit, truth)
    np.testing.assert_allclose(s.depth[truth], t[truth], rtol=1e-9)


# ---- interpolated normals of a tessellated surface (issue 25: a mutant that skipped the
# renormalisation passed every test) ---------------------------------------------------------------

def torus_normal(p, major):
    """The analytic outward normal of a ring torus about the z axis at (or near) points p."""
    ring = p * np.array([1.0, 1.0, 0.0])
    ring *= major / np.linalg.norm(ring, axis=1, keepdims=True)
    q = p - ring
    return q / np.linalg.norm(q, axis=1, keepdims=True)


@pytest.mark.parametrize("n_u, n_v", [(12, 8), (48, 24)])
def test_interpolated_normals_of_a_torus_are_unit_and_near_the_analytic(n_u, n_v):
    """Inside a flat triangle the blend of its corners' unit normals is shorter than 1 (by
    1 - cos of up to half the angle between them: about 4 % on 8 facets round the tube): the
    visible normal must be renormalised, and point near the torus's analytic normal there, the
    nearer the finer the mesh (a facet's half-angle bounds it)."""
    major, minor = 1.0, 0.4
    cam = Camera((0.0, -4.0, 2.5), (0, 0, 0), (0, 0, 1), 40.0, 96, 64, 1)
    s = visibility([(torus(major, minor, n_u, n_v), 5)], cam)
    on = s.object_id == 5
    assert on.sum() > 1000
    n = s.normal[on]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-12)
    exact = torus_normal(s.position[on], major)
    angle = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", n, exact), -1, 1)))
    half_facet = 0.5 * 360.0 / min(n_u, n_v)
    assert np.percentile(angle, 99) < half_facet, np.percentile(angle, 99)


def test_a_coarse_torus_shades_as_the_fine_one_at_a_high_percentile(root):
    """The renormalised normal is what shading sees: a gold torus of 48 x 24 facets, rendered,
    against one of 768 x 384 (whose corner normals differ by 0.5 degree, so that its blended
    normals are unit to 1e-5: the analytic torus, as far as the image can tell). Over the
    object's pixels, the 99th percentile of the luminance difference stays within 5 % of the
    brightest pixel (the highlight's tessellation; measured 1.3 %); the normals unrenormalised
    give 29 %."""
    from reflectance.render import render, scene_from_dict

    def luminance(n_u, n_v):
        doc = {"camera": {"position": [0, -4, 2.5], "look_at": [0, 0, 0], "fov_deg": 40,
                          "width": 96, "height": 64, "supersample": 1},
               "objects": [{"geometry": {"type": "torus", "major_radius": 1.0,
                                         "minor_radius": 0.4, "n_u": n_u, "n_v": n_v},
                            "material": {"name": "Au", "m": 0.15, "s": 1.0, "d": 0.0}}],
               "lights": [{"type": "directional", "direction": [0.3, -0.5, 0.8]}]}
        return render(scene_from_dict(doc, spectra_dir=[root / "spectra"])).XYZ[..., 1]

    coarse, fine = luminance(48, 24), luminance(768, 384)
    on = (coarse > 0) & (fine > 0)
    assert on.sum() > 1000
    difference = np.abs(coarse - fine)[on] / fine.max()
    assert np.percentile(difference, 99) < 0.05, np.percentile(difference, 99)
