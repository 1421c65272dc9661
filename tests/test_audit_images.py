"""Audits 2 and 3: the RGB renderer's Fresnel and the gamut clips, against independent truth."""

from functools import partial
from pathlib import Path

import colour
import numpy as np
import pytest
import yaml

from reflectance.audit.gamut import clip_differences, hue_difference_deg, out_of_gamut
from reflectance.audit.shortcuts import CAM16_VIEWING_CONDITIONS
from reflectance.colour.colorimetry import tristimulus_weights, white_XYZ
from reflectance.colour.display import (GAMUT_CLIP_METHODS, display_space, gamut_clip,
                                        linear_RGB_to_XYZ)
from reflectance.render.shading import (ShadingMaterial, fresnel_XYZ_table,
                                        fresnel_XYZ_table_rgb)

ROOT = Path(__file__).resolve().parents[1]
GRID = np.arange(360.0, 831.0, 5.0)
OBSERVER = "CIE 1931 2 Degree Standard Observer"


def _rng_rgb(n, low, high, seed=1):
    return np.random.default_rng(seed).uniform(low, high, (n, 3))


# --- audit 3: the gamut clips --------------------------------------------------------------------

@pytest.mark.parametrize("method", list(GAMUT_CLIP_METHODS))
def test_a_colour_inside_the_gamut_is_unchanged_by_every_clip(method):
    RGB = _rng_rgb(500, 0.0, 1.0)
    assert np.array_equal(gamut_clip(RGB, method, "sRGB"), RGB)


def test_clip_differences_are_zero_inside_the_gamut():
    RGB = _rng_rgb(200, 0.02, 0.98)
    got = clip_differences(RGB, "sRGB", white_XYZ("D65", OBSERVER, GRID), list(GAMUT_CLIP_METHODS),
                           CAM16_VIEWING_CONDITIONS)
    for method in GAMUT_CLIP_METHODS:
        assert np.max(got[method]["dE2000"]) == 0.0
        assert np.max(np.abs(got[method]["dh_CAM16"])) == 0.0


def test_per_channel_clip_is_np_clip():
    RGB = _rng_rgb(1000, -0.5, 1.5)
    assert np.array_equal(gamut_clip(RGB, "clip", "sRGB"), np.clip(RGB, 0.0, 1.0))


def _out_of_gamut_colours():
    """Out-of-gamut colours of lightness strictly between black and white."""
    RGB = _rng_rgb(4000, -0.4, 1.4, seed=7)
    L = colour.XYZ_to_Oklab(RGB @ display_space("sRGB").matrix_RGB_to_XYZ.T)[:, 0]
    keep = out_of_gamut(RGB) & (L > 0.05) & (L < 0.95)
    return RGB[keep][:600]


def test_oklch_mapping_is_in_gamut_and_keeps_the_oklab_hue():
    """CSS Color 4: the result is in gamut and lies within the JND (deltaEOK 0.02) of a colour of
    the original OKLab lightness and hue, so its (a, b) leaves the hue line by at most 0.02."""
    RGB = _out_of_gamut_colours()
    assert len(RGB) > 100
    mapped = gamut_clip(RGB, "css-oklch", "sRGB")
    assert not out_of_gamut(mapped).any()
    M = display_space("sRGB").matrix_RGB_to_XYZ
    lab, lab_mapped = (colour.XYZ_to_Oklab(x @ M.T) for x in (RGB, mapped))
    hue = lab[:, 1:] / np.linalg.norm(lab[:, 1:], axis=1, keepdims=True)
    across = np.abs(lab_mapped[:, 1] * hue[:, 1] - lab_mapped[:, 2] * hue[:, 0])
    along = lab_mapped[:, 1] * hue[:, 0] + lab_mapped[:, 2] * hue[:, 1]
    assert across.max() <= 0.02 + 1e-9
    assert np.all(along > -0.02)  # on the original hue's side of the neutral axis
    assert np.abs(lab_mapped[:, 0] - lab[:, 0]).max() <= 0.02 + 1e-9


def test_dominant_wavelength_clip_stays_on_the_line_to_the_white_at_equal_luminance():
    """Cook & Torrance's clip: the clipped chromaticity lies between the colour's and the white's,
    on one line (colour-science's XYZ_to_xy), with the luminance kept."""
    RGB = _out_of_gamut_colours()
    M = display_space("sRGB").matrix_RGB_to_XYZ
    XYZ = RGB @ M.T  # real colours (X, Y, Z > 0) of a luminance the display can show
    RGB = RGB[np.all(XYZ > 0, axis=1) & (XYZ[:, 1] > 0.02) & (XYZ[:, 1] < 1.0)]
    assert len(RGB) > 100
    clipped = gamut_clip(RGB, "dominant-wavelength", "sRGB")
    XYZ, XYZ_c = RGB @ M.T, clipped @ M.T
    np.testing.assert_allclose(XYZ_c[:, 1], XYZ[:, 1], rtol=1e-9, atol=1e-12)
    xy, xy_c = colour.XYZ_to_xy(XYZ), colour.XYZ_to_xy(XYZ_c)
    xy_w = colour.XYZ_to_xy(M @ np.ones(3))
    u, v = xy - xy_w, xy_c - xy_w
    np.testing.assert_allclose(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0], 0.0, atol=1e-9)
    t = np.einsum("ij,ij->i", u, v) / np.einsum("ij,ij->i", u, u)
    assert np.all((t > -1e-9) & (t < 1.0))


def test_clip_differences_of_per_channel_clip_against_colour_science():
    """dE2000 and the CAM16 hue shift of the per-channel clip, recomputed with colour-science."""
    RGB = _out_of_gamut_colours()[:50]
    white = white_XYZ("D65", OBSERVER, GRID)
    got = clip_differences(RGB, "sRGB", white, ["clip"], CAM16_VIEWING_CONDITIONS)
    xy = colour.XYZ_to_xy(white)
    XYZ = linear_RGB_to_XYZ(RGB, "sRGB", illuminant=white)
    XYZ_c = linear_RGB_to_XYZ(np.clip(RGB, 0, 1), "sRGB", illuminant=white)
    dE = colour.delta_E(colour.XYZ_to_Lab(XYZ_c, xy), colour.XYZ_to_Lab(XYZ, xy), method="CIE 2000")
    np.testing.assert_allclose(got["clip"]["dE2000"], dE, rtol=1e-7, atol=1e-9)
    surround = colour.VIEWING_CONDITIONS_CAM16[CAM16_VIEWING_CONDITIONS["surround"]]
    h = [colour.XYZ_to_CAM16(100 * x, 100 * white, CAM16_VIEWING_CONDITIONS["L_A"],
                             CAM16_VIEWING_CONDITIONS["Y_b"], surround).h for x in (XYZ_c, XYZ)]
    dh = (h[0] - h[1] + 180) % 360 - 180
    finite = np.isfinite(dh)
    np.testing.assert_allclose(got["clip"]["dh_CAM16"][finite], dh[finite], atol=1e-7)


def test_hue_difference_wraps():
    assert hue_difference_deg([359.0, 1.0, 90.0, 180.0], [1.0, 359.0, 270.0, 0.0]).tolist() == [
        -2.0, 2.0, -180.0, -180.0]


# --- audit 2: the RGB renderer's Fresnel ---------------------------------------------------------

def _flat(n=0.4, k=3.0, fresnel="schlick"):
    return ShadingMaterial(n=np.full(GRID.shape, n), k=np.full(GRID.shape, k), roughness=0.3,
                           fresnel=fresnel)


def test_rgb_table_of_a_flat_material_is_schlick_times_the_white():
    """A spectrally flat metal: F0 = ((n-1)^2 + k^2)/((n+1)^2 + k^2) (Born & Wolf), and the RGB
    renderer's table is Schlick of it times the light's white, the spectral Schlick table."""
    W = tristimulus_weights(GRID, "D65", OBSERVER)
    n, k = 0.4, 3.0
    F0 = ((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2)
    c = np.linspace(0.0, 1.0, 65)
    expected = (F0 + (1 - F0) * (1 - c[:, None]) ** 5) * W.sum(axis=0)
    rgb = fresnel_XYZ_table_rgb(_flat(n, k), W, 65)
    np.testing.assert_allclose(rgb, expected, rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(fresnel_XYZ_table(_flat(n, k), W, 65), expected, rtol=1e-12)


def test_rgb_table_at_normal_incidence_is_the_exact_F0_inside_the_gamut():
    """Copper's F0 lies inside sRGB: at V.H = 1 the RGB renderer gives its exact colour."""
    from reflectance.optics.spectra import load_material

    W = tristimulus_weights(GRID, "D65", OBSERVER)
    cu = load_material("Cu", GRID, ROOT / "spectra")
    table = fresnel_XYZ_table_rgb(ShadingMaterial(n=cu.n, k=cu.k, roughness=0.3), W, 33)
    np.testing.assert_allclose(table[-1], cu.F0 @ W, rtol=1e-10)
    # at c = 0.25 (75.5 degrees) Schlick per channel is not the exact spectral F
    assert not np.allclose(table[8], fresnel_XYZ_table(
        ShadingMaterial(n=cu.n, k=cu.k, roughness=0.3), W, 33)[8], rtol=1e-3)


def _tiny_vase(material):
    from reflectance.papers.scenes import vase_scene_CookTorrance1982

    config = yaml.safe_load((ROOT / "config.yaml").read_text())
    fig6 = config["figures"]["cook_torrance_1982"]["fig6"]
    return vase_scene_CookTorrance1982(fig6, material, "weighted", config["wavelengths"],
                                       config["colour"], str(ROOT / "spectra"),
                                       {"width": 24, "height": 32, "supersample": 1},
                                       exposure=fig6["published"]["exposure"])


def test_exr_display_RGB_is_what_the_png_shows(tmp_path):
    """Audit 3 reads an EXR's colours as its PNG was made: clipping them with the scene's own
    method and encoding gives the pipeline's display image."""
    from reflectance.audit.gamut import exr_display_RGB
    from reflectance.colour.display import encode
    from reflectance.io.images import read_exr
    from reflectance.render.pipeline import display_image, render, write_render
    from reflectance.render.scene import scene_from_dict

    result = render(scene_from_dict(_tiny_vase({"name": "Au", "s": 1.0, "d": 0.0, "m": 0.2})))
    write_render(result, tmp_path / "vase.exr")
    RGB, space, white, lit = exr_display_RGB(*read_exr(tmp_path / "vase.exr"))
    shown, _ = display_image(result)
    d = result.scene.display
    np.testing.assert_allclose(encode(gamut_clip(RGB, d.gamut_clip, space), space), shown,
                               atol=2e-6)  # the EXR holds float32 XYZ
    assert lit.sum() == (result.XYZ[..., 1] > 0).sum() > 50


def test_rgb_render_of_a_flat_material_equals_the_spectral_render():
    """The whole render path: a flat metal with spectral Schlick F renders with dE2000 0 as the
    RGB renderer (one visibility pass, Fig. 6's lights and exposure, a tiny image)."""
    from reflectance.colour.difference import dE2000_map
    from reflectance.io import cache
    from reflectance.render.rgb import display_exposure, render_spectral_and_rgb
    from reflectance.render.scene import scene_from_dict

    document = _tiny_vase({"index": {"n": 0.4, "k": 3.0}, "s": 1.0, "d": 0.0, "m": 0.3,
                           "fresnel": "schlick"})
    scene = scene_from_dict(document)
    cache.clear()  # the gold scene below differs in its material only: one trace (bit for bit)
    spectral, rgb = render_spectral_and_rgb(scene, "sRGB", keep_trace=True)
    lit = spectral[..., 1] > 0
    assert lit.sum() > 50
    W = tristimulus_weights(scene.wavelengths, "D65", scene.observer)
    dE = dE2000_map(rgb, spectral, display_exposure(spectral, scene), W.sum(axis=0))
    assert np.nanmax(dE[lit]) < 1e-6
    # and a coloured metal (gold: F0 outside sRGB) does differ
    gold = {"name": "Au", "s": 1.0, "d": 0.0, "m": 0.3}
    scene = scene_from_dict({**document, "objects": [{**document["objects"][0],
                                                      "material": gold}],
                             "spectra_dir": str(ROOT / "spectra")})
    spectral, rgb = render_spectral_and_rgb(scene, "sRGB", keep_trace=True)
    assert len(cache.TRACES) == 1
    dE = dE2000_map(rgb, spectral, display_exposure(spectral, scene), W.sum(axis=0))
    assert np.nanmax(dE[spectral[..., 1] > 0]) > 0.5


def test_rgb_table_needs_the_table_path():
    from reflectance.render.shading import shade

    with pytest.raises(ValueError, match="fresnel_table"):
        shade(np.zeros((1, 3)), [[0, 0, 1]], [[0, 0, 1]], np.zeros((1, 2)), _flat(), [],
              wavelengths=GRID, spectral="brute-force",
              fresnel_table=partial(fresnel_XYZ_table_rgb, space="sRGB"))
