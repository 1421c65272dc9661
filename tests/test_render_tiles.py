"""Rendering in bands of rows (reflectance.render.tracing.tiles): the same image as one pass."""

import numpy as np
import pytest

import reflectance.render.pipeline as pipeline
import reflectance.render.tracing as tracing
from reflectance.render.camera import Camera
from reflectance.render.pipeline import render
from reflectance.render.tracing import tiles
from reflectance.render.scene import scene_from_dict
from reflectance.render.visibility import visibility


def sphere_on_plane(spectra, supersample=2):
    doc = {"camera": {"position": [0, -6, 5], "look_at": [0, 0, 0], "up": [0, 0, 1],
                      "fov_deg": 35.0, "width": 64, "height": 48, "supersample": supersample},
           "objects": [{"geometry": {"type": "sphere", "center": [0, 0, 1], "radius": 0.5},
                        "material": {"model": "Lambert", "convention": "physical",
                                     "albedo": 0.5}},
                       {"geometry": {"type": "plane", "center": [0, 0, 0], "normal": [0, 0, 1],
                                     "size": [8, 8]},
                        "material": {"model": "Lambert", "convention": "physical",
                                     "albedo": 1.0}}],
           "lights": [{"type": "directional", "direction": [0.3, -0.2, 1.0], "solid_angle": 1.0},
                      {"type": "point", "position": [2.0, -2.0, 4.0], "intensity": 20.0,
                       "solid_angle": 0.1}]}
    return scene_from_dict(doc, spectra_dir=spectra)


@pytest.mark.parametrize("shape", [(48, 64, 2), (5, 7, 3), (100, 1, 1)])
def test_tiles_cover_the_rows_in_whole_pixels_within_the_budget(shape):
    height, width, n = shape
    cam = Camera((0, -5, 0), (0, 0, 0), (0, 0, 1), 30.0, width, height, n)
    rows, cols = cam.shape
    assert tiles(cam, single=rows * cols) == [(0, rows)]
    for budget in (1, cols * n, 3 * cols * n + 1, rows * cols - 1):
        bands = tiles(cam, single=0, tile=budget)
        assert bands[0][0] == 0 and bands[-1][1] == rows
        assert all(a[1] == b[0] for a, b in zip(bands, bands[1:]))
        assert all(start % n == 0 and stop % n == 0 and stop > start for start, stop in bands)
        # a band holds at most the budget, or a single pixel row when one row exceeds it
        assert all((stop - start) * cols <= max(budget, n * cols) for start, stop in bands)


def test_a_band_of_visibility_is_those_rows_of_the_whole(root):
    scene = sphere_on_plane(root / "spectra")
    whole = visibility(scene.mesh, scene.camera)
    rows, cols = scene.camera.shape
    for start, stop in [(0, 10), (10, 44), (44, rows)]:
        band = visibility(scene.mesh, scene.camera, (start, stop))
        part = slice(start * cols, stop * cols)
        assert band.shape == (stop - start, cols)
        np.testing.assert_array_equal(band.pixel, whole.pixel[part])
        np.testing.assert_array_equal(band.hit, whole.hit[part])
        np.testing.assert_array_equal(band.triangle, whole.triangle[part])
        np.testing.assert_array_equal(band.position, whole.position[part])  # the same rays
    with pytest.raises(ValueError, match="whole pixels"):
        visibility(scene.mesh, scene.camera, (1, 10))  # not a multiple of the supersampling


def test_banded_render_equals_one_pass(root, monkeypatch):
    scene = sphere_on_plane(root / "spectra")
    one = render(scene)
    monkeypatch.setattr(tracing, "SINGLE_TILE_SAMPLES", 0)
    monkeypatch.setattr(tracing, "TILE_SAMPLES", 1000)  # 6 sample rows (3 pixel rows) of 128
    assert len(tiles(scene.camera)) == 96 // 6
    banded = render(scene)
    for key in ("raster_miss", "recovered", "searched", "dropped", "hit", "seen_from_back"):
        assert banded.stats[key] == one.stats[key], key
    # the light maps are drawn per band: a shadow may be found on a different map, never more
    # than a handful of samples apart
    assert np.allclose(banded.stats["shadowed"], one.stats["shadowed"], atol=2e-3)
    differs = np.any(banded.XYZ != one.XYZ, axis=-1)
    assert differs.mean() < 0.01
    assert one.XYZ[..., 1].max() > 0.1 and (one.XYZ[..., 1] == 0).mean() > 0.05  # lit and shadow


@pytest.mark.parametrize("key", [None, (50.0, 0.18)])
def test_display_in_bands_is_the_same_image(root, monkeypatch, key):
    """A large image's exposure scale (Cook & Torrance's, or the metered key) and display RGB,
    computed band by band, equal the one-call result exactly."""
    import dataclasses

    import reflectance.colour.exposure as exposure

    scene = sphere_on_plane(root / "spectra")
    if key is not None:
        scene = dataclasses.replace(scene, display=dataclasses.replace(scene.display, key=key))
    result = render(scene)
    whole, scale = pipeline.display_image(result)
    monkeypatch.setattr(exposure, "_BAND_PIXELS", 200)  # 3 rows of 64 pixels
    banded, banded_scale = pipeline.display_image(result)
    assert banded_scale == scale != 1.0
    np.testing.assert_array_equal(banded, whole)


def test_a_cached_trace_renders_other_materials_exactly_as_a_fresh_one(root, monkeypatch):
    """render(keep_trace=True): scenes that differ only in materials and light strength reuse
    one trace (Cook & Torrance's Fig. 7 vases) and give the very pixels of a render without it; a
    moved light or camera is traced again."""
    from reflectance.io import cache

    first = sphere_on_plane(root / "spectra")
    other = sphere_on_plane(root / "spectra")
    object.__setattr__(other.objects[0], "material", first.objects[1].material)  # albedo 1.0
    calls = []
    real_trace = tracing.trace
    monkeypatch.setattr(tracing, "trace", lambda *a, **k: calls.append(1) or real_trace(*a, **k))
    cache.clear()
    got_first = render(first, keep_trace=True)
    got_other = render(other, keep_trace=True)
    assert len(calls) == 1 and len(cache.TRACES) == 1
    np.testing.assert_array_equal(got_first.XYZ, render(first).XYZ)
    np.testing.assert_array_equal(got_other.XYZ, render(other).XYZ)
    assert not np.array_equal(got_first.XYZ, got_other.XYZ)  # the material did change
    assert got_other.stats == render(other).stats
    moved = sphere_on_plane(root / "spectra", supersample=3)
    assert tracing.trace_key(moved) != tracing.trace_key(first)
    render(moved, keep_trace=True)
    assert len(cache.TRACES) == 2
