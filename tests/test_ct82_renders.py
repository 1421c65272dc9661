"""Cook & Torrance 1982, Figs. 6, 7 and 8 (rendered): each script runs once, as Snakemake would
run it, with config.yaml's parameters at a small image size and outputs in a temporary directory;
its tables and images are checked against config.yaml / Table I and against colour-science, and
the default figures against what a reader of the paper must see (issue 13's acceptance).
"""

import copy
import json
import runpy
from pathlib import Path
from types import SimpleNamespace

import colour
import numpy as np
import pandas as pd
import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
CONFIG = yaml.safe_load((ROOT / "config.yaml").read_text())
CT82 = CONFIG["figures"]["cook_torrance_1982"]
TABLE1 = CT82["table1"]["rows"]
SPECTRA = ROOT / "spectra"
OBSERVER = "CIE 1931 2 Degree Standard Observer"
ROWS = [CT82["fig7"]["table1_spectra"].get(r["material"], r["material"]) for r in TABLE1]
VASES = ([m["material"] for m in CT82["fig7"]["metals"]] + ROWS
         + [f"{e['table1']}_{e['material']}" for e in CT82["fig7"]["extras"]])
PUBLISHED = CT82["fig6"]["published"]


def reading_params(reading):
    """(ambient reference, published, readings) of the rule's params that make one variant alone:
    "published", the default figure; else that reading of fig6.ambient_readings."""
    if reading == "published":
        return PUBLISHED["ambient_reference"], PUBLISHED, {}
    return None, None, {reading: CT82["fig6"]["ambient_readings"][reading]}


def prefixed(files, reading):
    """The rule's output names of one variant: a reading's are prefixed by it (as_printed_png),
    but for the values file of the captions, one for the whole job."""
    prefix = "" if reading == "published" else f"{reading}_"
    return {key if key == "values" else prefix + key: value for key, value in files.items()}


def run_fig7(tmp, reading="irradiance", size=(48, 64, 1)):
    fig = copy.deepcopy(CT82["fig7"])
    fig["vase_image"] = dict(zip(("width", "height", "supersample"), size))
    out = SimpleNamespace(png=str(tmp / "fig7.png"), csv=str(tmp / "fig7.csv"),
                          values=str(tmp / "fig7.values.rst"),
                          exrs=[str(tmp / f"{v}.exr") for v in VASES],
                          scenes=[str(tmp / f"{v}.scene.yaml") for v in VASES],
                          pngs=[str(tmp / f"{v}.png") for v in VASES],
                          variants_png=str(tmp / "fig7_variants.png"))
    reference, published, readings = reading_params(reading)
    snakemake = SimpleNamespace(
        input=SimpleNamespace(sources=str(SPECTRA / "sources.csv")),
        output=SimpleNamespace(**prefixed(vars(out), reading)),
        params=SimpleNamespace(fig=fig, fig6=CT82["fig6"], table1=TABLE1, reference=reference,
                               published=published, readings=readings,
                               visible_nm=CT82["table1"]["average_F0_range_nm"],
                               wavelengths=CONFIG["wavelengths"], colour=CONFIG["colour"]),
        log=[str(tmp / "fig7.log")], rule="ct82_fig7")
    runpy.run_path(str(ROOT / "workflow/scripts/cook_torrance_1982_fig7.py"),
                   init_globals={"snakemake": snakemake})
    return out


class Output(SimpleNamespace):
    """Snakemake's output: named files, by attribute or by key."""

    def __getitem__(self, key):
        return getattr(self, key)


def run_fig6(tmp, reading="published", width=192, height=256, supersample=2):
    fig = copy.deepcopy(CT82["fig6"])
    fig["camera"].update(width=width, height=height, supersample=supersample)
    out = Output(png=str(tmp / "fig6.png"), csv=str(tmp / "fig6.csv"),
                 values=str(tmp / "fig6.values.rst"), **{
                     f"{p}_{key}": str(tmp / f"fig6{p}.{ext}") for p in "ab"
                     for key, ext in (("exr", "exr"), ("png", "png"), ("scene", "scene.yaml"))})
    reference, published, readings = reading_params(reading)
    files = prefixed(vars(out), reading)
    # the default figure shown otherwise, and with its panels as printed
    names = [published["display_variant"]["name"]] if published and "display_variant" in published \
        else []
    names += [published["printed_variant"]] if published and "printed_variant" in published else []
    for name in names:
        files.update({f"{name}_png": str(tmp / f"fig6_{name}.png"),
                      f"{name}_csv": str(tmp / f"fig6_{name}.csv"), **{
                          f"{name}_{p}_{key}": str(tmp / f"fig6{p}_{name}.{ext}") for p in "ab"
                          for key, ext in (("exr", "exr"), ("png", "png"),
                                           ("scene", "scene.yaml"))}})
    snakemake = SimpleNamespace(
        input=SimpleNamespace(spectra=[str(SPECTRA / "Cu.csv")]),
        output=Output(**files),
        params=SimpleNamespace(fig=fig, reference=reference, published=published,
                               readings=readings, wavelengths=CONFIG["wavelengths"],
                               colour=CONFIG["colour"]),
        log=[str(tmp / "fig6.log")], rule="ct82_fig6")
    runpy.run_path(str(ROOT / "workflow/scripts/cook_torrance_1982_fig6.py"),
                   init_globals={"snakemake": snakemake})
    return Output(**{**vars(out), **files})  # the display and printed variants' files too


def run_fig8(tmp, width=320, height=256, supersample=1):
    fig = copy.deepcopy(CT82["fig8"])
    fig["camera"].update(width=width, height=height, supersample=supersample)
    out = SimpleNamespace(**{key: str(tmp / name) for key, name in (
        ("png", "fig8.png"), ("csv", "fig8.csv"), ("exr", "fig8.exr"),
        ("render_png", "fig8_render.png"), ("scene", "fig8.scene.yaml"),
        ("values", "fig8.values.rst"))})
    snakemake = SimpleNamespace(
        input=SimpleNamespace(spectra=[str(SPECTRA / "Au.csv")]), output=out,
        params=SimpleNamespace(fig=fig, fig6=CT82["fig6"], table1=TABLE1,
                               wavelengths=CONFIG["wavelengths"], colour=CONFIG["colour"]),
        log=[str(tmp / "fig8.log")], rule="ct82_fig8")
    runpy.run_path(str(ROOT / "workflow/scripts/cook_torrance_1982_fig8.py"),
                   init_globals={"snakemake": snakemake})
    return out


@pytest.fixture(scope="module")
def fig7(tmp_path_factory):
    return run_fig7(tmp_path_factory.mktemp("ct82_fig7"))


@pytest.fixture(scope="module")
def fig8(tmp_path_factory):
    return run_fig8(tmp_path_factory.mktemp("ct82_fig8"))


def F0_colour_science(name):
    """XYZ (D65 white Y = 1) of a material's normal reflectance, integrated by colour-science.

    Measured materials: n, k interpolated linearly onto the 5 nm grid, F0 = ((n-1)^2 + k^2) /
    ((n+1)^2 + k^2); derived ones: their reflectance.
    """
    grid = np.arange(CONFIG["wavelengths"]["start_nm"], CONFIG["wavelengths"]["end_nm"] + 1,
                     CONFIG["wavelengths"]["step_nm"], dtype=float)
    data = pd.read_csv(SPECTRA / f"{name}.csv")
    if "n" in data:
        n, k = (np.interp(grid, data.wavelength_nm, data[c]) for c in ("n", "k"))
        F0 = ((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2)
    else:
        F0 = np.interp(grid, data.wavelength_nm, data.reflectance)
    shape = colour.SpectralShape(grid[0], grid[-1], grid[1] - grid[0])
    cmfs = colour.MSDS_CMFS[OBSERVER].copy().align(shape)  # the CMFs' own 1 nm values, sampled
    D65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    return colour.sd_to_XYZ(colour.SpectralDistribution(F0, grid), cmfs, D65,
                            method="Integration") / 100


def D65_xy():
    w = colour.sd_to_XYZ(colour.SDS_ILLUMINANTS["D65"], colour.MSDS_CMFS[OBSERVER])
    return w[:2] / w.sum()


def test_fig7_parameters_come_from_fig6b_and_table1(fig7):
    table = pd.read_csv(fig7.csv, keep_default_na=False, na_values=[""])
    assert list(table.vase) == VASES
    b = CT82["fig6"]["panels"]["b"]
    lobes = " ".join(f"{lobe['w']:g}x{lobe['m']:g}" for lobe in b["lobes"])
    metals = table[table.group == "metal"]
    assert list(metals.material) == [m["material"] for m in CT82["fig7"]["metals"]]
    assert (metals.s == b["s"]).all() and (metals.d == b["d"]).all()
    assert (metals.lobes == lobes).all() and metals.m.isna().all()
    nonmetals = table[table.group == "nonmetal"].set_index("material")
    assert list(nonmetals.index) == ROWS
    for row, name in zip(TABLE1, ROWS):
        got = nonmetals.loc[name]
        assert (got.s, got.d) == (row["s"], row["d"])
        if row["m"] is None:  # "Not used": C&T with s = 0, R = d R_d
            assert np.isnan(got.m) and got.model == "CookTorrance1982" and row["s"] == 0
        else:
            assert got.m == row["m"] and got.model == "CookTorrance1982"
    extra = table[table.group == "extra"].iloc[0]
    rust = next(r for r in TABLE1 if r["material"] == "Rust")
    assert extra.material == "Rust"  # the hematite variant keeps Table I rust's s, d, m
    assert (extra.s, extra.d, extra.m) == (rust["s"], rust["d"], rust["m"])
    # the default rust vase is the Munsell-derived reflectance, labelled with the paper's names
    assert nonmetals.index[-1] == CT82["fig7"]["table1_spectra"]["Rust"]
    assert set(table.label) >= {"Lunar dust", "Olive drab", "Rust", "Rust (hematite)"}


def test_fig7_diffuse_colour_is_F0_over_pi_by_colour_science(fig7):
    table = pd.read_csv(fig7.csv).set_index("vase")
    for vase, row in table.iterrows():
        F0 = [row[f"F0_{c}"] for c in "XYZ"]
        albedo = [row[f"albedo_{c}"] for c in "XYZ"]  # pi R_d
        np.testing.assert_allclose(F0, F0_colour_science(row.material), rtol=5e-4)
        np.testing.assert_allclose(albedo, F0, rtol=1e-12)  # "In every case ... R_d = F0/pi"
    # hematite's specular F0 is grey-blue (x, y below D65's 0.3127, 0.3290); the rust
    # reflectance is red-brown: a CIELAB hue between red (0) and yellow (90), dark, saturated
    hematite, rust = F0_colour_science("Rust"), F0_colour_science("RustMunsell")
    assert hematite[0] / hematite.sum() < 0.3127 and hematite[1] / hematite.sum() < 0.3290
    L, a, b = colour.XYZ_to_Lab(rust, D65_xy())
    assert 20 < np.degrees(np.arctan2(b, a)) < 80 and L < 45 and np.hypot(a, b) > 20


def test_fig7_one_exposure_for_the_whole_grid(fig7):
    """The common scale puts the brightest colour of all vases at the display maximum."""
    from reflectance.colour.colorimetry import white_XYZ
    from reflectance.io.images import read_exr

    scale = pd.read_csv(fig7.csv).exposure_scale.unique()
    assert len(scale) == 1
    XYZ = np.concatenate([read_exr(path)[0].reshape(-1, 3) for path in fig7.exrs])
    w = white_XYZ("D65", OBSERVER, np.arange(360, 831, 5.0))
    sRGB = colour.RGB_COLOURSPACES["sRGB"].copy()
    sRGB.use_derived_transformation_matrices(True)  # the primaries' matrix, not IEC's rounding
    RGB = colour.XYZ_to_RGB(XYZ, sRGB, illuminant=w[:2] / w.sum(),
                            chromatic_adaptation_transform="CAT02")
    Y = RGB @ sRGB.matrix_RGB_to_XYZ[1]
    assert scale[0] == pytest.approx(1 / RGB[np.argmax(Y)].max(), rel=1e-5)  # CSV: 6 digits


def test_fig7_lunar_dust_is_cook_torrance_with_s_zero(fig7):
    """m "Not used": the Lambert vase equals a Cook & Torrance vase with s = 0 and any m."""
    from reflectance.io.images import read_exr
    from reflectance.render.pipeline import render
    from reflectance.render.scene import scene_from_dict

    document = yaml.safe_load(Path(fig7.scenes[VASES.index("LunarDust")]).read_text())
    material = document["objects"][0]["material"]
    material.update(model="CookTorrance1982", convention="paper", m=0.07)
    XYZ = render(scene_from_dict(document)).XYZ
    np.testing.assert_allclose(XYZ, read_exr(fig7.exrs[VASES.index("LunarDust")])[0],
                               rtol=1e-6, atol=1e-12)




def test_fig8_parts_and_materials_come_from_config(fig8):
    table = pd.read_csv(fig8.csv).set_index("part")
    parts = CT82["fig8"]["parts"]
    for part, spec in parts.items():
        if "table1" in spec:
            spec = next(dict(r) for r in TABLE1 if r["material"] == spec["table1"])
        assert table.loc[part, "material"] == spec["material"]
        assert (table.loc[part, "s"], table.loc[part, "d"], table.loc[part, "m"]) == \
            (spec["s"], spec["d"], spec["m"])
    # "a rougher surface for the interior than for the border"; gold outer, steel inner band
    assert table.loc["band_outer_interior", "m"] > table.loc["band_outer_border", "m"]
    assert table.loc["band_outer_border", "material"] == "Au"
    assert table.loc["band_inner", "material"] == "StainlessSteel"
    assert (table.pixels > 0).all()  # every part is in view


@pytest.fixture(scope="module")
def fig8_seen(fig8):
    """The camera samples of Fig. 8's scene file (the scene's own visibility, traced once for
    every test below that picks pixels by watch part) and the part each sample sees (-1: none)."""
    from reflectance.render.scene import load_scene
    from reflectance.render.visibility import visibility

    scene = load_scene(fig8.scene)
    samples = visibility(scene.mesh, scene.camera)
    part = np.where(samples.hit, scene.mesh.cell_data["part"][np.maximum(samples.triangle, 0)], -1)
    return samples, part


def part_pixels(seen, part):
    """Pixels whose every sample sees the watch part ``part``."""
    from reflectance.geometry.watch import WATCH_PARTS

    samples, code = seen
    return samples.to_pixels((code == WATCH_PARTS[part]).astype(float)) == 1.0


def test_fig8_led_pixels_show_dominant_wavelength_640(fig8, fig8_seen):
    """The displayed LED colour keeps the 640 nm dominant wavelength (colour-science's)."""
    from PIL import Image

    mask = part_pixels(fig8_seen, "led")
    assert mask.sum() > 50
    encoded = np.asarray(Image.open(fig8.render_png), dtype=float)[mask] / 255
    RGB = colour.cctf_decoding(encoded, function="sRGB")
    sRGB = colour.RGB_COLOURSPACES["sRGB"]
    XYZ = colour.RGB_to_XYZ(RGB, sRGB, illuminant=sRGB.whitepoint)
    xy = colour.XYZ_to_xy(XYZ)
    wl, _, _ = colour.dominant_wavelength(xy, sRGB.whitepoint, colour.MSDS_CMFS[OBSERVER])
    target = CT82["fig8"]["led"]["dominant_wavelength_nm"]
    assert np.all(np.abs(np.asarray(wl) - target) <= 3), np.unique(wl)
    # and in the linear image the LED is the configured emission, Y = factor I d omega / pi
    from reflectance.io.images import read_exr

    light = CT82["fig8"]["light"]
    Y = read_exr(fig8.exr)[0][mask][:, 1]
    expected = CT82["fig8"]["led"]["luminance_factor"] * light["intensity"] * light["solid_angle"]
    np.testing.assert_allclose(Y, expected / np.pi, rtol=1e-7)  # the EXR holds float32


def test_fig8_scene_file_rerenders_the_exr(fig8):
    """The scene YAML beside the image renders it again, bit for bit (in the EXR's float32)."""
    from reflectance.io.images import read_exr
    from reflectance.render.pipeline import render
    from reflectance.render.scene import load_scene

    XYZ = read_exr(fig8.exr)[0]
    assert XYZ.dtype == np.float32
    np.testing.assert_array_equal(render(load_scene(fig8.scene)).XYZ.astype(np.float32), XYZ)


def test_fig8_part_given_twice_is_rejected():
    """A watch part is either a Table I row or explicit s, d, m (schema oneOf)."""
    from reflectance.config import ConfigError, validate_schema

    config = copy.deepcopy(CONFIG)
    config["figures"]["cook_torrance_1982"]["fig8"]["parts"]["face"] = {"table1": "Obsidian",
                                                                        "m": 0.2}
    with pytest.raises(ConfigError, match="fig8.parts.face"):
        validate_schema(config)


def test_fig8_is_deterministic(fig8, tmp_path):
    """The same config gives byte-identical files (EXR header, PNG, CSV, scene)."""
    again = run_fig8(tmp_path)
    for key in ("png", "csv", "exr", "render_png", "scene"):
        assert Path(getattr(fig8, key)).read_bytes() == Path(getattr(again, key)).read_bytes(), key


def _as_written(document):
    """A scene mapping as validated and written to YAML (defaults filled in)."""
    from reflectance.render.scene import validate_scene

    return yaml.safe_load(yaml.safe_dump(validate_scene(document), sort_keys=True))


def test_config_check_builds_the_scenes_the_scripts_render(fig7, fig8):
    """reflectance.config validates, at parse time, the scenes of reflectance.papers.scenes: they
    must be the scenes the figure scripts render (here read back from the scripts' scene files)."""
    from reflectance.papers.scenes import (fig7_vases_CookTorrance1982,
                                           vase_scene_CookTorrance1982,
                                           watch_scene_CookTorrance1982)

    image = {"width": 48, "height": 64, "supersample": 1}  # as run_fig7
    for (vase, _, material), path in zip(
            fig7_vases_CookTorrance1982(CT82["fig7"], CT82["fig6"], TABLE1), fig7.scenes):
        document = vase_scene_CookTorrance1982(CT82["fig6"], material, "irradiance",
                                               CONFIG["wavelengths"], CONFIG["colour"],
                                               str(SPECTRA), image)
        assert _as_written(document) == yaml.safe_load(Path(path).read_text()), vase
    fig = copy.deepcopy(CT82["fig8"])
    fig["camera"].update(width=320, height=256, supersample=1)  # as run_fig8
    document = watch_scene_CookTorrance1982(fig, CT82["fig6"], TABLE1, CONFIG["wavelengths"],
                                            CONFIG["colour"], str(SPECTRA))
    assert _as_written(document) == yaml.safe_load(Path(fig8.scene).read_text())


# ------------------------------------------------------------------------------------------------
# Issue 13's acceptance, on the default figures as built (at a reduced size): measured with
# colour-science on the PNG a reader sees, the object taken from the EXR beside it.
# ------------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def fig6_published(tmp_path_factory):
    return run_fig6(tmp_path_factory.mktemp("ct82_fig6"))


@pytest.fixture(scope="module")
def fig7_published(tmp_path_factory):
    return run_fig7(tmp_path_factory.mktemp("ct82_fig7_default"), "published", (96, 128, 2))


def object_lab(codes, XYZ):
    """(8-bit codes, CIELAB) of the object's pixels of an image of 8-bit sRGB ``codes``
    (H, W, 3): Y > 0 in the rendered ``XYZ`` less a one-pixel rim."""
    from scipy import ndimage

    mask = ndimage.binary_erosion(np.asarray(XYZ)[..., 1] > 0)
    codes = np.asarray(codes, dtype=float)[mask]
    sRGB = colour.RGB_COLOURSPACES["sRGB"]
    shown = colour.RGB_to_XYZ(colour.cctf_decoding(codes / 255, function="sRGB"), sRGB,
                              illuminant=sRGB.whitepoint)
    return codes, colour.XYZ_to_Lab(shown, sRGB.whitepoint)


def row_misfit(image, png):
    """The least, over every place in ``image`` (H, W, 3 codes), of the largest code difference
    between it and the middle row of the vase PNG ``png`` (its object's span): 0 where the
    vase is drawn pixel for pixel."""
    from numpy.lib.stride_tricks import sliding_window_view
    from PIL import Image

    vase = np.asarray(Image.open(png).convert("RGB"), dtype=int)
    row = vase[vase.shape[0] // 2]
    span = np.flatnonzero(row.sum(axis=-1))
    row = row[span[0]:span[-1] + 1]
    windows = sliding_window_view(image, (len(row), 3), axis=(1, 2))[:, :, 0]
    return int(min(np.abs(line - row).max(axis=(1, 2)).min() for line in windows))


def shown_lab(png, exr):
    """:func:`object_lab` of a written PNG and its EXR."""
    from PIL import Image

    from reflectance.io.images import read_exr

    return object_lab(np.asarray(Image.open(png).convert("RGB")), read_exr(exr)[0])


def form_and_highlight(codes, Lab):
    """Issue 13's acceptance numbers: the share of the object at or above 20/255 in some
    channel, and the L* span between its 10th and 99th percentile (to pass: 0.9 and 25)."""
    visible = (codes.max(axis=-1) >= 20).mean()
    return visible, np.percentile(Lab[:, 0], 99) - np.percentile(Lab[:, 0], 10)


def assert_form_and_highlight_read(png, exr):
    codes, Lab = shown_lab(png, exr)
    visible, span = form_and_highlight(codes, Lab)
    assert visible >= 0.9, f"{png}: only {visible:.1%} of the object at or above 20/255"
    assert span >= 25, f"{png}: L* spans only {span:.1f} between its 10th and 99th percentile"
    return codes, Lab


@pytest.mark.parametrize("panel", ["a", "b"])
def test_fig6_default_shows_form_and_highlight(fig6_published, panel):
    assert_form_and_highlight_read(getattr(fig6_published, f"{panel}_png"),
                                   getattr(fig6_published, f"{panel}_exr"))


def test_fig6a_default_highlight_is_whiter_than_the_body(fig6_published):
    """A plastic: a light-coloured highlight on a copper body (C&T 1982 Fig. 6a)."""
    _, Lab = shown_lab(fig6_published.a_png, fig6_published.a_exr)
    chroma = np.hypot(Lab[:, 1], Lab[:, 2])
    highlight = Lab[:, 0] >= np.percentile(Lab[:, 0], 99.5)
    assert np.median(chroma[highlight]) <= 0.6 * np.median(chroma)


def test_fig6b_default_highlight_is_copper_coloured(fig6_published):
    """"The specular reflectance component has a copper color": the brightest pixels that are
    not clipped (no channel at 255) have the CIELAB hue of copper's F0 under D65, within 10 deg."""
    codes, Lab = shown_lab(fig6_published.b_png, fig6_published.b_exr)
    unclipped = codes.max(axis=-1) < 255
    brightest = unclipped & (Lab[:, 0] >= np.percentile(Lab[unclipped, 0], 99))
    hue = np.degrees(np.arctan2(Lab[brightest, 2], Lab[brightest, 1]))
    L, a, b = colour.XYZ_to_Lab(F0_colour_science("Cu"), D65_xy())
    difference = (hue - np.degrees(np.arctan2(b, a)) + 180) % 360 - 180
    assert brightest.sum() >= 5 and np.all(np.abs(difference) <= 10), difference


def test_fig6b_default_highlights_keep_a_gradient(fig6_published):
    """Issue 28: the copper highlights are not flat plateaus at 255 ("stickers, not metal"):
    under 2 % of the vase's pixels have a channel at 255, and the brightest pixels (the top
    1 % of L*, clipped or not) still have copper's CIELAB hue under D65 within 10 deg."""
    codes, Lab = shown_lab(fig6_published.b_png, fig6_published.b_exr)
    clipped = (codes.max(axis=-1) >= 255).mean()
    assert clipped < 0.02, f"{clipped:.1%} of the copper vase has a channel at 255"
    top = Lab[:, 0] >= np.percentile(Lab[:, 0], 99)
    hue = np.degrees(np.arctan2(Lab[top, 2].mean(), Lab[top, 1].mean()))
    L, a, b = colour.XYZ_to_Lab(F0_colour_science("Cu"), D65_xy())
    assert abs((hue - np.degrees(np.arctan2(b, a)) + 180) % 360 - 180) <= 10, hue


def copper_linear(F0_scale):
    """Linear sRGB of copper's F0 colour (colour-science, D65 white) times ``F0_scale``."""
    return colour.XYZ_to_RGB(F0_scale * F0_colour_science("Cu"), colour.RGB_COLOURSPACES["sRGB"],
                             illuminant=D65_xy(), chromatic_adaptation_transform="CAT02")


def copper_shown(F0_scale, transfer):
    """CIELAB of copper's F0 colour (colour-science, D65) times ``F0_scale`` as an sRGB screen
    shows it when its linear sRGB is written as the codes through ``transfer``: "sRGB" (the
    IEC 61966-2-1 encoding) or "none" (the linear values as the codes: a 1982 frame buffer)."""
    sRGB = colour.RGB_COLOURSPACES["sRGB"]
    linear = copper_linear(F0_scale)
    codes = np.clip(linear if transfer == "none" else colour.cctf_encoding(linear, "sRGB"), 0, 1)
    return colour.XYZ_to_Lab(colour.RGB_to_XYZ(colour.cctf_decoding(codes, function="sRGB"),
                                               sRGB, illuminant=sRGB.whitepoint), sRGB.whitepoint)


def lab_hue(a, b):
    return np.degrees(np.arctan2(b, a)) % 360


def hue_gap(h, other):
    return abs((h - other + 180) % 360 - 180)


@pytest.mark.parametrize("display", ["variant", "default"])
def test_fig6_uncorrected_display_shows_copper_coloured_copper(fig6_published, display):
    """The display variant (linear RGB written as the codes, as 1982 frame buffers drove their
    monitors) shows copper as copper (C&T 1982 Fig. 6; "The specular reflectance component has a
    copper color"): (a)'s body, copper's F0/pi, has at least 0.8 of the CIELAB chroma of copper's
    F0 colour dimmed to the body's median L* and shown that way, within 10 deg of its hue;
    (b)'s highlight (the top 1 % of L*) has copper's F0 hue shown that way within 10 deg and
    more than 1.2 times the chroma of (a)'s highlight (the top 0.5 %: vinyl's grey F on the body).
    The default figure (sRGB-encoded) fails it: expected to, the reason for the variant."""
    from scipy.optimize import brentq

    name = PUBLISHED["display_variant"]["name"]
    prefix = f"{name}_" if display == "variant" else ""
    _, body = shown_lab(fig6_published[f"{prefix}a_png"], fig6_published[f"{prefix}a_exr"])
    # (a) as printed is not written; its departure (a'), same body, is
    L50, brightest = np.median(body[:, 0]), 1.0 / copper_linear(1.0).max()
    # copper at the body's L* (none if brighter than copper can be shown that way)
    scale = (brentq(lambda k: copper_shown(k, "none")[0] - L50, 1e-6, brightest)
             if L50 < copper_shown(brightest, "none")[0] else None)
    predicted = copper_shown(scale or brightest, "none")
    C = np.hypot(np.median(body[:, 1]), np.median(body[:, 2]))
    ok_body = (scale is not None and C >= 0.8 * np.hypot(*predicted[1:])
               and hue_gap(lab_hue(np.median(body[:, 1]), np.median(body[:, 2])),
                           lab_hue(*predicted[1:])) <= 10)
    _, shine = shown_lab(fig6_published[f"{prefix}b_png"], fig6_published[f"{prefix}b_exr"])
    top = shine[shine[:, 0] >= np.percentile(shine[:, 0], 99)]
    top_a = body[body[:, 0] >= np.percentile(body[:, 0], 99.5)]
    copper = copper_shown(brightest, "none")  # at the display maximum
    ok_b = (hue_gap(lab_hue(*top[:, 1:].mean(axis=0)), lab_hue(*copper[1:])) <= 10
            and np.median(np.hypot(top[:, 1], top[:, 2]))
            > 1.2 * np.median(np.hypot(top_a[:, 1], top_a[:, 2])))
    assert (ok_body and ok_b) == (display == "variant"), (display, C, predicted, top.mean(0))


def test_fig6a_default_departure_is_labelled(fig6_published):
    """Fig. 6a departs from the print only as config.yaml says, and the CSV shows both."""
    table = pd.read_csv(fig6_published.csv)
    a = table[table.panel == "a"].set_index("written")
    printed, departed = CT82["fig6"]["panels"]["a"], PUBLISHED["departures"]["a"]
    assert a.loc[False, "s"] == printed["s"] and a.loc[True, "s"] == departed["s"]
    assert a.loc[True, "highlight_chroma_ratio"] < a.loc[False, "highlight_chroma_ratio"]


def test_fig6_default_pairs_the_two_vases_and_the_printed_panel_is_its_variant(fig6_published):
    """Review of issue 28: the default figure showed (a) as printed, its departure and (b), three
    vases, breaking the paper's pair. It shows two, (a) as departed and (b), each drawn pixel for
    pixel (its written PNG's middle row is in the figure); the variant ``printed_variant`` shows
    (a) with the printed s and d beside the same (b), and its table says so."""
    from PIL import Image

    name = PUBLISHED["printed_variant"]
    for figure, a_png, s in ((fig6_published.png, fig6_published.a_png, PUBLISHED["departures"]["a"]["s"]),
                             (fig6_published[f"{name}_png"], fig6_published[f"{name}_a_png"],
                              CT82["fig6"]["panels"]["a"]["s"])):
        image = np.asarray(Image.open(figure).convert("RGB"), dtype=int)
        with Image.open(a_png) as vase:
            assert round(image.shape[1] / vase.width) == 2, (figure, image.shape, vase.size)
        assert row_misfit(image, a_png) <= 2
    printed = pd.read_csv(fig6_published[f"{name}_csv"]).set_index("panel")
    assert printed.loc["a", "s"] == CT82["fig6"]["panels"]["a"]["s"] and printed.written.all()
    # the printed (a) is the default table's unwritten row, pixel for pixel the same render
    default = pd.read_csv(fig6_published.csv)
    unwritten = default[(default.panel == "a") & ~default.written].iloc[0]
    assert unwritten.highlight_chroma_ratio == pytest.approx(
        printed.loc["a", "highlight_chroma_ratio"], rel=1e-12)


@pytest.mark.parametrize("vase", VASES)
def test_fig7_default_every_vase_reads(fig7_published, vase):
    """Issue 13's acceptance on every vase, as for Figs. 6a and 6b: 90 % of the object at or
    above 20/255 in some channel, L* spanning 25 between its 10th and 99th percentile. Obsidian
    and lunar dust meet it only with their labelled exposure factors (config fig7.vase_exposure)."""
    k = VASES.index(vase)
    assert_form_and_highlight_read(fig7_published.pngs[k], fig7_published.exrs[k])


def test_fig7_default_variants_are_out_of_the_papers_grid(fig7_published, tmp_path,
                                                         monkeypatch):
    """Issue 28: the paper's figure is six metals over six nonmetals and nothing else; the
    variants (hematite) are in a file of their own, fig7_variants.png, each beside the paper's
    vase of its Table I row. On the built figure: it is six vases wide (each vase drawn pixel
    for pixel, 1.04 of its width per column) and two rows of vases high at most; in its layout:
    rows 0 and 1 hold exactly the paper's twelve, and the variants' figure holds every variant."""
    from PIL import Image

    # the figure's drawing (its script's call) lays out the grid with the image_grid it imported
    import reflectance.papers.draw.ct82_fig7 as drawing

    with Image.open(fig7_published.png) as grid, Image.open(fig7_published.pngs[0]) as vase:
        assert round(grid.width / (1.04 * vase.width)) == 6, (grid.size, vase.size)
    # pixel for pixel: each paper vase's middle row is in fig7.png; each variant's is not, but
    # is in fig7_variants.png
    figure, apart = (np.asarray(Image.open(path).convert("RGB"), dtype=int)
                     for path in (fig7_published.png, fig7_published.variants_png))
    for vase, png in zip(VASES, fig7_published.pngs):
        paper = "_" not in vase  # a variant's vase id is <Table I row>_<material>
        assert (row_misfit(figure, png) <= 2) == paper, (vase, row_misfit(figure, png))
        if not paper:
            assert row_misfit(apart, png) <= 2, (vase, row_misfit(apart, png))
    grids, original = [], drawing.image_grid
    monkeypatch.setattr(drawing, "image_grid",
                        lambda cells, *a, **k: grids.append(cells) or original(cells, *a, **k))
    run_fig7(tmp_path, "published", (24, 32, 1))
    rows = {}
    for row, _, _, label in grids[0]:
        rows.setdefault(row, []).append(label.split("\n")[0])
    names = CT82["fig7"]["labels"]
    metals = [names.get(m["material"], m["material"]) for m in CT82["fig7"]["metals"]]
    nonmetals = [names.get(r, r) for r in ROWS]
    extras = [names.get(e["material"], e["material"]) for e in CT82["fig7"]["extras"]]
    assert rows == {0: metals, 1: nonmetals}, rows
    apart = [label.split("\n")[0] for _, _, _, label in grids[1]]
    assert len(grids) == 2 and set(extras) <= set(apart), (len(grids), apart)


@pytest.mark.parametrize("metal", [m["material"] for m in CT82["fig7"]["metals"]])
def test_fig7_default_metal_highlights_keep_a_gradient(fig7_published, metal):
    """Issue 28, Fig. 6b's bound applied to Fig. 7's metals: under 2 % of each metal vase's
    pixels have a channel at 255 (every one clipped on 7-11 % of its pixels, flat plateaus,
    before), while its highlight still reads as a highlight: its brightest pixel has a channel
    at or above 240/255."""
    codes, _ = shown_lab(*(getattr(fig7_published, key)[VASES.index(metal)]
                           for key in ("pngs", "exrs")))
    clipped = (codes.max(axis=-1) >= 255).mean()
    assert clipped < 0.02, f"{metal}: {clipped:.1%} of the vase has a channel at 255"
    assert codes.max() >= 240, f"{metal}: the brightest code is {codes.max():.0f}"


def test_fig7_default_carbon_is_its_f0s_grey(fig7_published):
    """Issue 28: carbon's measured n, k give F0 between 0.08 and 0.16 over the visible (its
    luminance, by colour-science, about 0.12); with R_d = F0/pi the vase shows its F0's
    lightness at its row's exposure (median L* within 6 of the L* of F0's luminance), not a
    light stone."""
    grid = np.arange(400, 701, 5, dtype=float)
    data = pd.read_csv(SPECTRA / "Carbon.csv")
    n, k = (np.interp(grid, data.wavelength_nm, data[c]) for c in ("n", "k"))
    F0 = ((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2)
    assert 0.08 <= F0.min() and F0.max() <= 0.16, (F0.min(), F0.max())
    L_F0 = colour.XYZ_to_Lab(F0_colour_science("Carbon"), D65_xy())[0]
    i = VASES.index("Carbon")
    _, Lab = shown_lab(fig7_published.pngs[i], fig7_published.exrs[i])
    assert abs(np.median(Lab[:, 0]) - L_F0) <= 6, (np.median(Lab[:, 0]), L_F0)


def test_fig7_default_vase_factors_are_needed(fig7_published):
    """The per-vase factors are departures the acceptance needs: each factored vase passes it
    as shown (its PNG) and fails it at its row's exposure (the factor divided out, the same
    render encoded again), both measured by one routine (as issue 13 measured: obsidian below
    90 % at or above 20/255, lunar dust below an L* span of 25)."""
    from types import SimpleNamespace as Result

    from reflectance.io.images import read_exr
    from reflectance.render.pipeline import display_image
    from reflectance.render.scene import load_scene

    table = pd.read_csv(fig7_published.csv).set_index("vase")
    factors = CT82["fig7"]["vase_exposure"]
    assert factors, "no per-vase factor: nothing to show needed"
    for vase, factor in factors.items():
        i = VASES.index(vase)
        XYZ = read_exr(fig7_published.exrs[i])[0].astype(float)
        at_row = display_image(Result(XYZ=XYZ, scene=load_scene(fig7_published.scenes[i])),
                               table.loc[vase, "vase_exposure_scale"] / factor)[0]
        shown = form_and_highlight(*shown_lab(fig7_published.pngs[i], fig7_published.exrs[i]))
        without = form_and_highlight(*object_lab(np.round(at_row * 255), XYZ))
        assert shown[0] >= 0.9 and shown[1] >= 25, (vase, shown)
        assert without[0] < 0.9 or without[1] < 25, (vase, without)


def test_fig7_default_rows_keep_their_materials_lightness_order(fig7_published):
    """One exposure per row but for the labelled factors of fig7.vase_exposure: each vase's
    exposure is its row's times its factor (read back from the CSV, the white card's scale); and
    the shown median L* still follows Table I's materials as a reader knows them (a black
    obsidian, Munsell N2, darker than rubber, N2.5, darker than lunar dust, 10YR 4/1), as under
    one light it must: the factors open up a shadow and a shading range, not the order."""
    table = pd.read_csv(fig7_published.csv).set_index("vase")
    factors = CT82["fig7"]["vase_exposure"]
    for group in ("metal", "nonmetal"):
        rows = table[table.group == group]
        row_scale = rows.vase_exposure_scale / [factors.get(v, 1.0) for v in rows.index]
        assert np.allclose(row_scale, row_scale.iloc[0], rtol=1e-5), group  # CSV: 6 digits
    medians = {v: np.median(shown_lab(fig7_published.pngs[VASES.index(v)],
                                      fig7_published.exrs[VASES.index(v)])[1][:, 0])
               for v in ("Obsidian", "Rubber", "LunarDust")}
    assert medians["Obsidian"] < medians["Rubber"] < medians["LunarDust"], medians
    assert medians["LunarDust"] - medians["Obsidian"] >= 20, medians
    assert medians["Obsidian"] <= 20, medians  # still black glass


def watch_part_lab(fig8, seen, part):
    """(8-bit codes, CIELAB) of the pixels of fig8_render.png whose every sample sees ``part``."""
    from PIL import Image

    mask = part_pixels(seen, part)
    codes = np.asarray(Image.open(fig8.render_png).convert("RGB"), dtype=float)[mask]
    sRGB = colour.RGB_COLOURSPACES["sRGB"]
    XYZ = colour.RGB_to_XYZ(colour.cctf_decoding(codes / 255, function="sRGB"), sRGB,
                            illuminant=sRGB.whitepoint)
    return codes, colour.XYZ_to_Lab(XYZ, sRGB.whitepoint)


def test_fig8_default_reads_as_the_papers_watch(fig8, fig8_seen):
    """Issue 13: one light; the polished link borders shine against the rough insets; the gold
    case reads gold (the CIELAB hue of gold's F0 under D65), the steel band neutral and bright
    where lit; both bands visible."""
    scene = yaml.safe_load(Path(fig8.scene).read_text())
    assert len(scene["lights"]) == 1  # "illuminated by a single light source"
    _, border = watch_part_lab(fig8, fig8_seen, "band_outer_border")
    _, interior = watch_part_lab(fig8, fig8_seen, "band_outer_interior")
    # the frames catch the light: their brightest pixels well above the insets' brightest, and
    # a run of them (not a few glints) brighter than 90 % of the inset pixels
    assert np.percentile(border[:, 0], 95) >= np.percentile(interior[:, 0], 95) + 8
    assert (border[:, 0] > np.percentile(interior[:, 0], 90)).mean() >= 0.05
    codes, case = watch_part_lab(fig8, fig8_seen, "case")
    lit = case[:, 0] >= 20
    assert lit.mean() >= 0.5  # most of the case is lit, not a silhouette
    L, a, b = colour.XYZ_to_Lab(F0_colour_science("Au"), D65_xy())
    hue = np.degrees(np.arctan2(case[lit, 2], case[lit, 1]))
    assert abs((np.median(hue) - np.degrees(np.arctan2(b, a)) + 180) % 360 - 180) <= 10
    assert np.median(np.hypot(case[lit, 1], case[lit, 2])) >= 15  # gold, not khaki or grey
    _, steel = watch_part_lab(fig8, fig8_seen, "band_inner")
    lit = steel[:, 0] >= 20
    assert np.median(np.hypot(steel[lit, 1], steel[lit, 2])) <= 6  # steel is neutral
    assert np.percentile(steel[:, 0], 90) >= 60  # and has its sheen
    for part in ("band_inner", "band_outer_border", "band_outer_interior"):
        codes, _ = watch_part_lab(fig8, fig8_seen, part)
        assert (codes.max(axis=-1) >= 20).mean() >= 0.2, part  # both bands visible


@pytest.mark.parametrize("fig", ["fig6", "fig7"])
def test_every_ambient_reference_the_schema_allows_has_its_caption(fig):
    """The merged Fig. 6/7 rules caption a reading by its ambient reference
    (workflow/rules/renders.smk, ct82_caption): each reference a config may choose needs its
    caption, which names that reading's readings."""
    schema = json.loads((ROOT / "workflow" / "schemas" / "config.schema.json").read_text())
    readings = (schema["properties"]["figures"]["properties"]["cook_torrance_1982"]["properties"]
                ["fig6"]["properties"]["ambient_readings"])
    for reference in readings["additionalProperties"]["enum"]:
        caption = ROOT / "workflow" / "report" / f"ct82_{fig}_{reference}.rst"
        assert caption.is_file(), caption
        assert f'if ref == "{reference}"' in caption.read_text(), caption


def test_fig8_of_several_bands_gives_the_one_band_table(fig8, tmp_path, monkeypatch):
    """An image too large for one band keeps no trace (tracing.trace_once); Fig. 8 then traces it
    whole for its part table, which must be the one-band table (here forced: bands of 60 rows,
    the last one of 16; that banded renders equal one pass is test_render_tiles' claim)."""
    import reflectance.render.tracing as tracing

    monkeypatch.setattr(tracing, "SINGLE_TILE_SAMPLES", 1)
    monkeypatch.setattr(tracing, "TILE_SAMPLES", 60 * 320)
    bands = tracing.tiles(SimpleNamespace(shape=(256, 320), supersample=1))
    assert bands == [(0, 60), (60, 120), (120, 180), (180, 240), (240, 256)]
    banded = run_fig8(tmp_path)
    pd.testing.assert_frame_equal(pd.read_csv(banded.csv), pd.read_csv(fig8.csv))
