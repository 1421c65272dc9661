"""End-to-end tests of reflectance.render.pipeline on small images, against geometry written out here."""

import colour
import numpy as np
import pytest

from reflectance.cli import main
from reflectance.io.images import read_exr
from reflectance.colour.difference import image_difference_CIEDE2000
from reflectance.render.pipeline import display_image, render, render_to_files, write_render
from reflectance.render.scene import load_scene, scene_from_dict
from reflectance.render.shading import emission_XYZ


@pytest.fixture(scope="module")
def spectra(root):
    return root / "spectra"


def camera(position, look_at, width, height, fov=30.0, supersample=1):
    return {"position": list(position), "look_at": list(look_at), "up": [0, 0, 1],
            "fov_deg": fov, "width": width, "height": height, "supersample": supersample}


def lambert(albedo):
    return {"model": "Lambert", "convention": "physical", "albedo": albedo}


def pixel_rays(cam):
    """Unit rays through the pixel centres of a pinhole camera (rows top to bottom)."""
    f = np.subtract(cam["look_at"], cam["position"])
    f = f / np.linalg.norm(f)
    r = np.cross(f, cam["up"])
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    W, H = cam["width"], cam["height"]
    h = np.tan(np.radians(cam["fov_deg"]) / 2)
    y, x = np.mgrid[0:H, 0:W] + 0.5
    sx = (2 * x / W - 1) * h * W / H
    sy = (1 - 2 * y / H) * h
    d = f + sx[..., None] * r + sy[..., None] * u
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def hit_sphere(origin, d, centre, radius):
    """Nearest t > 0 along unit rays d from origin (outside the sphere); nan if none."""
    oc = np.asarray(origin, float) - centre
    b = d @ oc
    disc = b**2 - (oc @ oc - radius**2)
    with np.errstate(invalid="ignore"):
        t = -b - np.sqrt(disc)
    return np.where((disc >= 0) & (t > 0), t, np.nan)


def d65_white():
    """XYZ / 100 of the D65 white on 360-830 nm by 5 nm, integrated by colour-science."""
    shape = colour.SpectralShape(360, 830, 5)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    return colour.sd_to_XYZ(colour.sd_ones(shape), cmfs, d65, method="Integration") / 100


SUN = np.array([0.3, -0.6, 0.7]) / np.linalg.norm([0.3, -0.6, 0.7])


def lambert_sphere(spectra, width=48, height=40, supersample=1):
    cam = camera((0, -5, 0), (0, 0, 0), width, height, supersample=supersample)
    doc = {"camera": cam,
           "objects": [{"geometry": {"type": "sphere", "radius": 1.0}, "material": lambert(0.8)}],
           "lights": [{"type": "directional", "direction": SUN.tolist(), "intensity": 2.0,
                       "solid_angle": 0.5}]}
    return scene_from_dict(doc, spectra_dir=spectra), cam


def test_lambertian_sphere_matches_analytic_shading(spectra):
    scene, cam = lambert_sphere(spectra)
    Y = render(scene).XYZ[..., 1]
    d = pixel_rays(cam)
    t = hit_sphere(cam["position"], d, np.zeros(3), 1.0)
    hit = np.isfinite(t)
    N = np.asarray(cam["position"]) + t[..., None] * d  # unit sphere: the point is its normal
    expected = np.where(hit, 0.8 * 2.0 * 0.5 * np.maximum(N @ SUN, 0) / np.pi, 0.0)
    assert np.array_equal(Y > 0, expected > 0)
    assert np.allclose(Y, expected, rtol=1e-9, atol=1e-15)
    assert hit.sum() > 300


def test_lambert_white_facing_the_light_has_Y_I_omega_over_pi(spectra):
    doc = {"camera": camera((2, -4, 3), (0, 0, 0), 24, 16, supersample=2),
           "objects": [{"geometry": {"type": "plane", "center": [0, 0, 0], "normal": [0, 0, 1],
                                     "size": [20, 20]}, "material": lambert(1.0)}],
           "lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": 3.0,
                       "solid_angle": 0.2}]}
    XYZ = render(scene_from_dict(doc, spectra_dir=spectra)).XYZ
    assert np.allclose(XYZ[..., 1], 3.0 * 0.2 / np.pi, rtol=1e-12)
    assert np.allclose(XYZ[0, 0], 3.0 * 0.2 / np.pi * d65_white(), rtol=1e-9)


def test_display_white_shows_a_white_card_at_its_luminance(spectra):
    """display.white: the white Lambertian card facing the light (Y = I d omega / pi, as the test
    above renders it) is shown at the given display luminance, whatever the light's strength."""
    from reflectance.render.pipeline import display_image

    for intensity, luminance in ((3.0, 0.5), (0.01, 0.08)):
        doc = {"camera": camera((2, -4, 3), (0, 0, 0), 24, 16),
               "objects": [{"geometry": {"type": "plane", "center": [0, 0, 0],
                                         "normal": [0, 0, 1], "size": [20, 20]},
                            "material": lambert(1.0)}],
               "lights": [{"type": "directional", "direction": [0, 0, 1],
                           "intensity": intensity, "solid_angle": 0.2}],
               "display": {"white": {"luminance": luminance}}}
        _, scale = display_image(render(scene_from_dict(doc, spectra_dir=spectra)))
        assert scale * intensity * 0.2 / np.pi == pytest.approx(luminance, rel=1e-12)


def test_sphere_casts_its_analytic_shadow_on_a_plane(spectra):
    cam = camera((0, -6, 5), (0, 0, 0), 64, 48, fov=35)
    doc = {"camera": cam,
           "objects": [{"geometry": {"type": "sphere", "center": [0, 0, 1], "radius": 0.5},
                        "material": lambert(0.5)},
                       {"geometry": {"type": "plane", "center": [0, 0, 0], "normal": [0, 0, 1],
                                     "size": [8, 8]}, "material": lambert(1.0)}],
           "lights": [{"type": "directional", "direction": [0, 0, 1], "solid_angle": 1.0}]}
    Y = render(scene_from_dict(doc, spectra_dir=spectra)).XYZ[..., 1]
    d = pixel_rays(cam)
    origin = np.asarray(cam["position"], float)
    t_plane = -origin[2] / d[..., 2]
    P = origin + t_plane[..., None] * d
    on_plane = (np.abs(P[..., 0]) < 4) & (np.abs(P[..., 1]) < 4) \
        & ~np.isfinite(hit_sphere(origin, d, np.array([0, 0, 1.0]), 0.5))
    rho = np.hypot(P[..., 0], P[..., 1])  # light from straight above: shadow disc of radius 0.5
    inside = on_plane & (rho < 0.48)
    outside = on_plane & (rho > 0.52)
    assert inside.sum() > 20 and outside.sum() > 1000
    assert np.all(Y[inside] == 0.0)
    assert np.allclose(Y[outside], 1.0 / np.pi, rtol=1e-12)


def test_a_light_without_shadows_passes_the_plane_that_would_block_it(spectra):
    """A light's ``shadows: false`` (a fill light, e.g. a floor's bounce): a light from straight
    below a sphere resting over a plane lights the sphere's underside through the plane, by
    Lambert's cosine written out here; with shadows the plane blocks it and the underside is
    black. Neither changes the plane, which faces away from it (N.L < 0)."""
    cam = camera((0, -6, 0.9), (0, 0, 0.9), 64, 48, fov=15)  # level with it, a little below
    centre, radius = np.array([0, 0, 1.0]), 0.5
    d = pixel_rays(cam)
    origin = np.asarray(cam["position"], float)
    t = hit_sphere(origin, d, centre, radius)
    # pixels well inside the sphere's image (their centre ray is not near grazing)
    oc = origin - centre
    miss = np.sqrt(np.maximum(0.0, oc @ oc - (d @ oc) ** 2))  # ray's distance from the centre
    inner = np.isfinite(t) & (miss < 0.95 * radius)
    normal_z = ((origin + t[..., None] * d)[..., 2] - centre[2]) / radius
    images = {}
    for shadows in (True, False):
        doc = {"camera": cam,
               "objects": [{"geometry": {"type": "sphere", "center": centre.tolist(),
                                         "radius": radius}, "material": lambert(0.5)},
                           {"geometry": {"type": "plane", "center": [0, 0, 0],
                                         "normal": [0, 0, 1], "size": [8, 8]},
                            "material": lambert(1.0)}],
               "lights": [{"type": "directional", "direction": [0, 0, 1], "solid_angle": 1.0},
                          {"type": "directional", "direction": [0, 0, -1], "solid_angle": 1.0,
                           "shadows": shadows}]}
        images[shadows] = render(scene_from_dict(doc, spectra_dir=spectra)).XYZ[..., 1]
    below = inner & (normal_z < -0.05)
    above = inner & (normal_z > 0.05)
    assert below.sum() > 50 and above.sum() > 50
    assert np.allclose(images[False][below], 0.5 / np.pi * -normal_z[below], rtol=1e-9)
    assert np.all(images[True][below] == 0.0)
    for image in images.values():  # the light from above, as before
        assert np.allclose(image[above], 0.5 / np.pi * normal_z[above], rtol=1e-9)
    plane = ~np.isfinite(t)
    assert np.array_equal(images[True][plane], images[False][plane])


def test_supersampling_converges(spectra):
    reference = render(lambert_sphere(spectra, 24, 20, 12)[0]).XYZ[..., 1]
    errors = [np.abs(render(lambert_sphere(spectra, 24, 20, n)[0]).XYZ[..., 1]
                     - reference).mean() for n in (1, 2, 4)]
    assert errors[0] > errors[1] > errors[2] > 0
    assert errors[2] < 0.4 * errors[0]


def test_table_is_within_dE2000_001_of_brute_force_on_the_copper_vase(root, spectra):
    from reflectance.papers.scenes import fig6_scene_CookTorrance1982
    from reflectance.bench.measure import load_bench_scene

    doc = fig6_scene_CookTorrance1982("b", "irradiance", spectra_dir=spectra)
    scene = load_bench_scene(doc, spectra_dir=spectra, width=48, height=64, supersample=2)
    table = render(scene, spectral="table").XYZ
    brute = render(scene, spectral="brute-force").XYZ
    # CIELAB of both on one scale (the brute-force image's peak luminance at L* = 100)
    xy = colour.XYZ_to_xy(d65_white())
    scale = 1.0 / brute[..., 1].max()
    dE = colour.delta_E(colour.XYZ_to_Lab(table * scale, xy),
                        colour.XYZ_to_Lab(brute * scale, xy), method="CIE 2000")
    assert (brute[..., 1] > 0).sum() > 500
    assert dE.max() < 0.01
    mean, worst = image_difference_CIEDE2000(table, brute, "D65", wavelengths=scene.wavelengths)
    assert worst < 0.01 and mean <= worst


def test_paper_convention_specular_is_four_times_physical_on_an_image(spectra):
    images = []
    for convention in ("paper", "physical"):
        doc = {"camera": camera((0, -5, 0), (0, 0, 0), 32, 32),
               "objects": [{"geometry": {"type": "sphere", "radius": 1.0},
                            "material": {"name": "Cu", "m": 0.3, "convention": convention}}],
               "lights": [{"type": "directional", "direction": [0.2, -1, 0.3]}]}
        images.append(render(scene_from_dict(doc, spectra_dir=spectra),
                             components=True).components["specular"])
    assert images[1][..., 1].max() > 0
    assert np.allclose(images[0], 4.0 * images[1], rtol=1e-12, atol=1e-290)


def test_emissive_object_without_lights(spectra):
    doc = {"camera": camera((0, -5, 0), (0, 0, 0), 16, 16),
           "objects": [{"geometry": {"type": "sphere", "radius": 1.0},
                        "material": {"model": "Lambert", "albedo": 0.5, "emission": {
                            "dominant_wavelength_nm": 640, "luminance": 0.25}}}],
           "lights": []}
    XYZ = render(scene_from_dict(doc, spectra_dir=spectra)).XYZ
    assert np.allclose(XYZ[8, 8], emission_XYZ(640, 0.25))
    assert np.all(XYZ[0, 0] == 0)


def test_cli_render_is_byte_identical_on_rerun(root, tmp_path, capsys):
    scene = root / "workflow" / "scenes" / "example_spheres.yaml"
    outputs = []
    for k in range(2):
        exr, png = tmp_path / f"r{k}.exr", tmp_path / f"r{k}.png"
        assert main(["render", str(scene), "-o", str(exr), "--png", str(png), "--width", "40",
                     "--height", "24", "--spectra-dir", str(root / "spectra"), "--quiet"]) == 0
        outputs.append((exr.read_bytes(), png.read_bytes()))
    assert outputs[0] == outputs[1]
    XYZ, header = read_exr(tmp_path / "r0.exr")
    assert XYZ.shape == (24, 40, 3) and XYZ[..., 1].max() > 0
    assert '"width":40' in header["scene"] and "numpy" in header["software"]
    assert outputs[0][1][:8] == b"\x89PNG\r\n\x1a\n"


def test_cli_bad_scene_fails_before_writing_anything(root, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("camera: {position: [0, -5, 0], look_at: [0, 0, 0], fov_deg: 30, width: 8, "
                   "height: 8}\nobjects:\n  - geometry: {type: sphere, radius: 1}\n"
                   "    material: {name: Cu, m: 0.3, s: 2}\nlights: []\n")
    with pytest.raises(SystemExit) as info:
        main(["render", str(bad), "-o", str(tmp_path / "out.exr"), "--png",
              str(tmp_path / "out.png"), "--spectra-dir", str(root / "spectra")])
    assert "bad.yaml: objects[0].material.s: 2 is greater than the maximum of 1" in str(
        info.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.yaml"]


def test_write_render_writes_exr_and_png(spectra, tmp_path):
    scene, _ = lambert_sphere(spectra, 16, 12)
    result = render(scene)
    write_render(result, tmp_path / "a.exr", tmp_path / "a.png")
    XYZ, header = read_exr(tmp_path / "a.exr")
    assert np.allclose(XYZ, result.XYZ.astype(np.float32))
    assert float(header["display_exposure_scale"]) > 0
    assert (tmp_path / "a.png").stat().st_size > 0


def test_render_to_files_keeps_the_display_image_it_wrote(spectra, tmp_path):
    scene, _ = lambert_sphere(spectra, 16, 12)
    result = render_to_files(scene, tmp_path / "a.scene.yaml", tmp_path / "a.exr",
                             tmp_path / "a.png")
    rgb, scale = result.display
    again, again_scale = display_image(render(scene))
    np.testing.assert_array_equal(rgb, again)
    assert scale == again_scale
    _, header = read_exr(tmp_path / "a.exr")
    assert float(header["display_exposure_scale"]) == pytest.approx(scale, rel=1e-6)


def test_named_parts_are_shaded_with_their_materials(spectra):
    glow = {"model": "Lambert", "albedo": 0.0,
            "emission": {"dominant_wavelength_nm": 640, "luminance": 1.0}}
    doc = {"camera": {"position": [0, 0, 6], "look_at": [0, 0, 0], "up": [0, 1, 0],
                      "fov_deg": 30, "width": 33, "height": 33},
           "objects": [{"geometry": {"type": "vase", "profile": [[0.5, 0], [0.7, 0.5],
                                                                 [0.6, 1.0]],
                                     "n_theta": 64, "n_profile_samples": 32},
                        "material": {"model": "Lambert", "albedo": 0.0},
                        "parts": {"floor": glow}}],
           "lights": []}
    XYZ = render(scene_from_dict(doc, spectra_dir=spectra)).XYZ
    # looking straight down the axis: the centre pixel sees the floor, a corner the background,
    # and a ring whose rays pass z = 0 at radius 0.64 .. 0.69 (outside the floor's ~0.47) the
    # inner wall, rim or outer wall: black parts
    assert np.allclose(XYZ[16, 16], emission_XYZ(640, 1.0))
    assert np.all(XYZ[0, 0] == 0)
    rim = np.hypot(*np.mgrid[-16:17, -16:17]) * (2 * 6 * np.tan(np.radians(15)) / 33)
    assert np.all(XYZ[(rim > 0.64) & (rim < 0.69)] == 0)
