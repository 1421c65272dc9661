"""Adaptive supersampling (reflectance.render.adaptive): which pixels get more samples, that
they get exactly the finer grid's samples, determinism, and accuracy on the hard bench scene
against brute-force supersampling."""

import numpy as np
import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.colour.difference import pixel_difference_CIEDE2000
from reflectance.render.adaptive import Refinement, refine_mask, refinement_bands
from reflectance.render.pipeline import render
from reflectance.render.scene import SceneError, scene_from_dict
from reflectance.render.visibility import visibility


def plane_scene(spectra, material, light, size=24, n=2, adaptive=None, fov=20.0):
    """A plane filling the frame, seen from above (the camera looks straight down)."""
    doc = {"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0],
                      "fov_deg": fov, "width": size, "height": size, "supersample": n,
                      "adaptive": {"enabled": True, **(adaptive or {})}},
           "objects": [{"geometry": {"type": "plane", "center": [0, 0, 0], "normal": [0, 0, 1],
                                     "size": [40, 40]}, "material": material}],
           "lights": [light]}
    return scene_from_dict(doc, spectra_dir=spectra)


LAMBERT = {"model": "Lambert", "convention": "physical", "albedo": 0.6}
SUN = {"type": "directional", "direction": [0.3, -0.2, 1.0], "solid_angle": 1.0}


def sphere_scene(spectra, size=32, adaptive=None, m=None):
    material = LAMBERT if m is None else {"name": "Au", "s": 1.0, "d": 0.0, "m": m}
    doc = {"camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1],
                      "fov_deg": 30.0, "width": size, "height": size, "supersample": 2,
                      "adaptive": {"enabled": True, **(adaptive or {})}},
           "objects": [{"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 1.0},
                        "material": material}],
           "lights": [{"type": "directional", "direction": [0.4, -1.0, 0.5],
                       "solid_angle": 1.0}]}
    return scene_from_dict(doc, spectra_dir=spectra)


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 9), st.integers(1, 9), st.integers(1, 5), st.data())
def test_bands_hold_each_refined_pixel_once_with_its_n_by_n_samples(height, width, N, data):
    mask = np.array(data.draw(st.lists(st.booleans(), min_size=height * width,
                                       max_size=height * width))).reshape(height, width)
    max_samples = data.draw(st.integers(1, 400))
    bands = refinement_bands(mask, N, max_samples=max_samples, max_id_pixels=10**9)
    pixels = np.concatenate([p for _, _, p in bands]) if bands else np.zeros(0, int)
    np.testing.assert_array_equal(pixels, np.flatnonzero(mask))  # each once, in order
    cols = width * N
    for (start, stop), select, pix in bands:
        assert start % N == 0 and stop % N == 0 and stop > start
        assert len(select) == len(pix) * N * N
        # a band exceeds the budget only when it is a single pixel row
        assert len(select) <= max_samples or stop - start == N
        row = select // cols + start
        col = select % cols
        owner = (row // N) * width + col // N
        np.testing.assert_array_equal(owner, np.repeat(pix, N * N))  # each pixel's own samples
        assert len(np.unique(select)) == len(select)


def test_a_constant_image_needs_no_extra_samples(root):
    # a flat Lambertian plane filling the frame under a directional light: every sample is the
    # same colour, so no threshold however small refines anything
    for threshold in (2.0, 1e-6):
        result = render(plane_scene(root / "spectra", LAMBERT, SUN,
                                    adaptive={"threshold": threshold}))
        assert result.stats["hit"] == 1.0
        assert result.refined is not None and not result.refined.any()
        assert result.stats["refined"] == 0.0 and result.stats["samples_per_pixel"] == 4.0


def test_a_highlight_edge_gets_the_samples(root):
    """A gold plane under a point light beside the camera: a sharp highlight (m = 0.02) in a
    dark frame. Every pixel whose 2 x 2 value is more than 0.5 CIEDE2000 from the brute-force
    16 x 16 one is refined, few others are, and the worst pixel's error falls below 0.3."""
    import dataclasses

    material = {"name": "Au", "s": 1.0, "d": 0.0, "m": 0.02}
    light = {"type": "point", "position": [0.3, 0.2, 5.0], "solid_angle": 1.0}
    scene = plane_scene(root / "spectra", material, light, size=32, fov=40.0)
    result = render(scene)
    off = Refinement(enabled=False)
    plain = render(dataclasses.replace(scene, refinement=off))
    brute = render(dataclasses.replace(
        scene, camera=dataclasses.replace(scene.camera, supersample=16), refinement=off))

    def error_map(XYZ):
        lit = (XYZ[..., 1] > 0) | (brute.XYZ[..., 1] > 0)
        out = np.zeros(lit.shape)
        out[lit] = pixel_difference_CIEDE2000(XYZ, brute.XYZ)
        return out

    needs = error_map(plain.XYZ) > 0.5
    assert needs.sum() >= 5 and error_map(plain.XYZ).max() > 0.9  # a hard highlight for 2 x 2
    assert result.refined[needs].all()
    assert 0 < result.refined.mean() < 0.05
    assert error_map(result.XYZ).max() < 0.3
    assert not result.refined[:8].any() and not result.refined[-8:].any()  # the dark border


def test_a_silhouette_gets_the_samples_and_they_are_the_finer_grids(root):
    # a Lambertian sphere against black, a threshold no shading reaches: only silhouettes
    scene = sphere_scene(root / "spectra", adaptive={"threshold": 1e9, "supersample": 6})
    result = render(scene)
    fine = visibility(scene.mesh, scene.camera.__class__(
        scene.camera.position, scene.camera.look_at, scene.camera.up, scene.camera.fov_deg,
        scene.camera.width, scene.camera.height, 6))
    coverage = fine.to_pixels(fine.hit.astype(float))
    partial = (coverage > 0) & (coverage < 1)
    assert partial.sum() > 20
    assert result.refined[partial].mean() > 0.95
    # every refined pixel is at the silhouette (within a pixel of a partly covered one)
    near = partial.copy()
    near[1:] |= partial[:-1]
    near[:-1] |= partial[1:]
    near[:, 1:] |= near[:, :-1].copy()
    near[:, :-1] |= near[:, 1:].copy()
    assert near[result.refined].all()
    # a refined pixel holds the box-filter mean of the 6 x 6 grid: the whole image rendered at
    # 6 x 6 has the same value there (up to the order of the sum)
    import dataclasses

    brute = render(dataclasses.replace(
        scene, camera=dataclasses.replace(scene.camera, supersample=6),
        refinement=Refinement(enabled=False)))
    np.testing.assert_allclose(result.XYZ[result.refined], brute.XYZ[result.refined],
                               rtol=1e-12, atol=1e-15)
    assert result.stats["samples_per_pixel"] == pytest.approx(4 + 36 * result.refined.mean())


def test_same_input_byte_identical_output(root):
    scene = sphere_scene(root / "spectra", size=24, m=0.1)
    one, two = render(scene), render(scene)
    assert one.refined.any()
    assert one.XYZ.tobytes() == two.XYZ.tobytes()
    assert one.refined.tobytes() == two.refined.tobytes()


@pytest.mark.parametrize("level", [0.125, 0.004])  # above and on CIELAB's linear toe
@pytest.mark.parametrize("scale", [1.0, 8.0])
def test_refine_mask_threshold_is_a_CIELAB_difference_on_the_exposure(level, scale):
    """A window-minus-pixel difference is weighed as the CIELAB difference it makes at the
    pixel's exposed level: checked against colour-science's L*."""
    import colour

    white = np.array([0.95047, 1.0, 1.08883])
    delta = 1e-5
    # the exposed pixel is level x white; its difference delta x white (exposed)
    XYZ = (level / scale * white)[None, None, :]
    difference = (delta / scale * white)[None, None, :].astype(np.float32)
    xy = colour.XYZ_to_xy(white)
    dL = (colour.XYZ_to_Lab((level + delta) * white, xy)[0]
          - colour.XYZ_to_Lab(level * white, xy)[0])
    none = np.zeros((1, 1), bool)
    assert refine_mask(difference, none, XYZ, scale, 0.98 * dL, white)[0, 0]
    assert not refine_mask(difference, none, XYZ, scale, 1.02 * dL, white)[0, 0]
    assert refine_mask(difference, ~none, XYZ, scale, 1e9, white)[0, 0]  # a silhouette


def test_bad_adaptive_settings_are_named(root):
    with pytest.raises(SceneError, match=r"camera\.adaptive"):
        plane_scene(root / "spectra", LAMBERT, SUN, adaptive={"threshold": -1})
    with pytest.raises(SceneError, match=r"camera\.adaptive"):
        plane_scene(root / "spectra", LAMBERT, SUN, adaptive={"samples": 4})


ACCURACY_SIZE = 64
REFERENCE_N = 16
REFINED_N = 12  # at 64 px the spheres are 8 px wide: 8 x 8 is itself 0.23 / 1.4 from 16 x 16


def test_adaptive_meets_the_accuracy_goal_where_2x2_does_not(root):
    """Issue 9: within CIEDE2000 0.3 mean, 1.0 p95 of a converged box-filtered pixel integral
    (brute force, 16 x 16 samples per pixel everywhere) on the hard bench scene, refining to
    12 x 12 (other sample positions than the reference's). Measured (2026-12-02): 2 x 2 is
    1.79 / 9.9, adaptive 0.14 / 0.80 at 33 samples per pixel."""
    doc = yaml.safe_load((root / "workflow" / "scenes" / "bench_hard.yaml").read_text())
    doc["camera"].update(width=ACCURACY_SIZE, height=ACCURACY_SIZE)

    def image(n, enabled):
        d = yaml.safe_load(yaml.safe_dump(doc))
        d["camera"]["supersample"] = n
        d["camera"]["adaptive"] = {"enabled": enabled, "supersample": REFINED_N}
        scene = scene_from_dict(d, spectra_dir=root / "spectra")
        return scene, render(scene)

    scene, reference = image(REFERENCE_N, False)

    def error(result):
        dE = pixel_difference_CIEDE2000(result.XYZ, reference.XYZ, scene.display.illuminant,
                                        scene.observer, scene.wavelengths)
        return dE.mean(), np.percentile(dE, 95)

    plain = error(image(2, False)[1])
    adaptive_result = image(2, True)[1]
    adaptive = error(adaptive_result)
    assert plain[0] > 0.3 or plain[1] > 1.0, plain  # the scene is hard for 2 x 2
    assert adaptive[0] <= 0.3 and adaptive[1] <= 1.0, adaptive
    assert adaptive_result.stats["samples_per_pixel"] < 0.5 * REFERENCE_N**2


def test_refined_components_add_up_to_the_refined_image(root):
    result = render(sphere_scene(root / "spectra", size=24, m=0.1), components=True)
    assert result.refined.any()
    total = sum(result.components.values())
    np.testing.assert_allclose(total, result.XYZ, rtol=1e-12, atol=1e-12)
