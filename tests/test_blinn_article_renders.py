"""Rendered figures of Blinn 1977 (Figs. 7, 8, the light sweep) and of the article (pair of spheres).

The Blinn helpers of ``reflectance.papers.scenes`` are checked against Blinn's formulas written out here.
Each figure script runs once, as Snakemake would run it, with the parameters of config.yaml at a
small image size and outputs in a temporary directory; the images are then checked against what
the paper's formulas say they must show (computed here, not taken from the scripts' tables).
"""

import copy
import json
import re
import runpy
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image, ImageSequence

from reflectance.io.images import read_exr
from reflectance.render.scene import constant_index_material
from reflectance.papers.scenes import (PHONG_SPECULAR_READINGS, light_direction,
                                            materials_Blinn1977)

ROOT = Path(__file__).resolve().parents[1]
CONFIG = yaml.safe_load((ROOT / "config.yaml").read_text())
B77 = CONFIG["figures"]["blinn_1977"]
WAVELENGTHS = CONFIG["wavelengths"]


class Files(SimpleNamespace):
    """Snakemake's input/output/params objects: items and attributes (an output may be named
    ``values``, so not a dict's attributes)."""

    def __init__(self, items):
        super().__init__(**items)

    def __getitem__(self, key):
        return getattr(self, key)


def run_script(name, tmp, params, output, input=None):
    snakemake = SimpleNamespace(params=Files(params), output=Files(output),
                                input=Files(input or {}), log=[str(tmp / f"{name}.log")], rule=name)
    runpy.run_path(str(ROOT / "workflow" / "scripts" / name), init_globals={"snakemake": snakemake})


def fresnel_sin_tan(phi, n):
    """Blinn 1977's sin/tan Fresnel formula with its 1/2 (independent of the library's g, c form)."""
    theta = np.arcsin(np.sin(phi) / n)
    return 0.5 * (np.sin(phi - theta) ** 2 / np.sin(phi + theta) ** 2
                  + np.tan(phi - theta) ** 2 / np.tan(phi + theta) ** 2)


# --- Blinn's helpers in reflectance.papers.scenes ----------------------------------------

@pytest.mark.parametrize("n", [1.8, 200.0, 1.5])
def test_constant_index_material_gives_the_dielectric_fresnel(n):
    from reflectance.optics.fresnel import fresnel

    material = constant_index_material(n, 0.0, np.arange(360.0, 831.0, 5.0))
    assert np.all(material.n == n) and np.all(material.k == 0)
    np.testing.assert_allclose(material.F0, ((n - 1) / (n + 1)) ** 2, rtol=1e-12)
    phi = np.radians([10.0, 45.0, 70.0, 85.0])
    F = fresnel(np.cos(phi)[:, None], material.n, material.k, method="exact")
    np.testing.assert_allclose(F, np.broadcast_to(fresnel_sin_tan(phi, n)[:, None], F.shape),
                               rtol=1e-9)


@settings(max_examples=60, deadline=None)
@given(angle=st.floats(0.0, 180.0), azimuth=st.floats(-360.0, 360.0),
       eye=st.tuples(*[st.floats(-10, 10)] * 3).filter(lambda e: np.hypot(e[0], e[1]) > 0.5))
def test_light_direction_makes_the_angle_with_the_eye(angle, azimuth, eye):
    look_at = np.array([0.3, -0.2, 0.1])
    L = light_direction(np.add(eye, look_at), look_at, (0, 0, 1), angle, azimuth)
    E = np.asarray(eye) / np.linalg.norm(eye)
    assert np.linalg.norm(L) == pytest.approx(1.0, abs=1e-12)
    assert np.degrees(np.arccos(np.clip(L @ E, -1, 1))) == pytest.approx(angle, abs=1e-5)
    if 1.0 < angle < 179.0:  # the azimuth: 90 degrees puts the light above the view axis
        up = np.array([0.0, 0.0, 1.0]) - E[2] * E
        right = np.cross(up, E)
        measured = np.degrees(np.arctan2(L @ up / np.linalg.norm(up),
                                         L @ right / np.linalg.norm(right)))
        assert (measured - azimuth + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-6)


@pytest.mark.parametrize("c3", [0.2, 0.35, 0.5, 0.8])
def test_phong_c1_halves_where_d3_halves(c3):
    m = materials_Blinn1977(0.4, 0.6, c3, 200.0)
    cos_b = np.cos(np.radians(m["beta_deg"]))
    assert (c3**2 / (cos_b**2 * (c3**2 - 1) + 1)) ** 2 == pytest.approx(0.5, rel=1e-9)  # Blinn D3
    assert cos_b ** m["c1"] == pytest.approx(0.5, rel=1e-9)  # Blinn D1 = cos^c1
    assert m["phong"]["c1"] == m["c1"] and m["torrance_sparrow"]["c3"] == c3


def test_matched_phong_specular_is_p_s_times_normal_fresnel():
    printed = materials_Blinn1977(0.667, 0.333, 0.35, 1.8, "as_printed")
    matched = materials_Blinn1977(0.667, 0.333, 0.35, 1.8, "matched")
    assert printed["phong"]["s"] == 0.667
    assert matched["phong"]["s"] == pytest.approx(0.667 * (0.8 / 2.8) ** 2, rel=1e-12)
    assert matched["torrance_sparrow"] == printed["torrance_sparrow"]
    with pytest.raises(ValueError, match="known: " + ", ".join(PHONG_SPECULAR_READINGS)):
        materials_Blinn1977(0.4, 0.6, 0.5, 200, "printed")


# --- Fig. 7 ---------------------------------------------------------------------------------------

def _fig7_config():
    fig = copy.deepcopy(B77["fig7"])
    fig["camera"].update(width=192, height=128, supersample=1)
    fig["grazing"]["camera"].update(width=192, height=128, supersample=1)
    # the close-up inset at a quarter of its size (the same aspect and field of view): only the
    # PNG shows it; test_fig7_rim_closeup_shows_the_edge_lit_highlight checks it at full size
    fig["rim_closeup"].update(width=160, height=48, supersample=1)
    return fig


@pytest.fixture(scope="module")
def fig7(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fig7")
    fig = _fig7_config()
    readings = fig["phong_specular_readings"]
    stems = {key: str(tmp / f"fig7{key}")
             for p in "ab" for light in [*fig["lights"], "grazing_edge", "grazing_front"]
             for key in [f"{p}_torrance_sparrow_{light}"] + [f"{p}_phong_{light}_{r}" for r in readings]}
    output = {"figures": [str(tmp / f"fig7_{r}{s}.png") for r in readings for s in ("", "_edge")],
              "csv": str(tmp / "fig7.csv"),
              "values": str(tmp / "fig7.values.rst")}
    run_script("blinn_1977_fig7.py", tmp, {"fig": fig, "stems": stems, "wavelengths": WAVELENGTHS},
               output)
    Y = {key: read_exr(f"{stem}.exr")[0][..., 1] for key, stem in stems.items()}
    return fig, Y, pd.read_csv(output["csv"]), tmp


def test_fig7_writes_exr_png_and_a_scene_that_re_renders(fig7):
    from reflectance.render.pipeline import render
    from reflectance.render.scene import load_scene

    fig, Y, _, tmp = fig7
    for key in Y:
        assert (tmp / f"fig7{key}.png").stat().st_size > 0
    scene = load_scene(tmp / "fig7b_torrance_sparrow_front.scene.yaml")
    np.testing.assert_allclose(render(scene).XYZ[..., 1], Y["b_torrance_sparrow_front"],
                               rtol=1e-6, atol=1e-7)  # the EXR holds float32


def test_fig7_front_lit_models_agree_and_edge_lit_differ(fig7):
    """Blinn: "both models essentially same" front lit; Torrance-Sparrow much brighter edge lit."""
    _, Y, table, _ = fig7
    for p in "ab":
        ts_edge, ts_front = Y[f"{p}_torrance_sparrow_edge"], Y[f"{p}_torrance_sparrow_front"]
        diff_front = np.abs(Y[f"{p}_phong_front_matched"] - ts_front).max()
        diff_edge = np.abs(Y[f"{p}_phong_edge_matched"] - ts_edge).max()
        assert diff_front < 0.1 * ts_front.max()
        assert diff_edge > 0.25 and diff_edge > 5 * diff_front
        assert ts_edge.max() > 1.5 * Y[f"{p}_phong_edge_matched"].max()
        rows = table[(table.panel == p) & (table.phong_specular == "matched")].set_index("light")
        assert rows.loc["front", "max_abs_difference"] == pytest.approx(diff_front, rel=1e-5)
        assert rows.loc["edge", "max_abs_difference"] == pytest.approx(diff_edge, rel=1e-5)
    # as printed, MgO's Phong highlight is p_s = 0.667 against T-S's p_s F0 = 0.054: not "same"
    assert np.abs(Y["b_phong_front_as_printed"] - Y["b_torrance_sparrow_front"]).max() > 0.4


def test_fig7_edge_highlight_reads_at_full_view_and_the_tangential_one_does_not(fig7):
    """On the torus at 172 degrees (Blinn's "almost tangentially", a variant, with close-ups) the
    Torrance-Sparrow highlight is a rim of a few dozen pixels in ~50,000; at the variant's edge
    light it is a band: over 1.5 % of the object brighter than i = 0.5 in each material, against
    under 0.3 % at the tangential angle. The object's pixels: those the front light reaches (i > p_a
    everywhere lit)."""
    fig, Y, _, tmp = fig7
    for p in "ab":
        obj = Y[f"{p}_torrance_sparrow_front"] > 0
        share = {light: (Y[f"{p}_torrance_sparrow_{light}"][obj] > 0.5).mean()
                 for light in ("edge", "tangential")}
        assert share["edge"] > 0.015 and share["tangential"] < 0.003, (p, share)
    for r in fig["phong_specular_readings"]:  # Blinn's layout, once per light but the front one
        for suffix in ("", "_tangential", "_edge"):
            assert (tmp / f"fig7_{r}{suffix}.png").is_file(), (r, suffix)


def _srgb_8bit(linear):
    """IEC 61966-2-1 encoding of linear values in [0, 1], as 8-bit codes (written out here)."""
    v = np.clip(linear, 0.0, 1.0)
    return np.round(255 * np.where(v <= 0.0031308, 12.92 * v, 1.055 * v ** (1 / 2.4) - 0.055))


def test_fig7_grazing_view_puts_h_on_the_top_face():
    """The default figure's eye and light: 172 degrees apart, their bisector H the bar's top-face
    normal (+y at its middle), each 4 degrees above the face (Blinn's paper held edge on)."""
    g = B77["fig7"]["grazing"]
    E = np.subtract(g["camera"]["position"], g["camera"]["look_at"])
    E /= np.linalg.norm(E)
    up = np.asarray(g["camera"]["up"], float) - np.dot(g["camera"]["up"], E) * E
    up /= np.linalg.norm(up)
    a = np.radians(g["light"]["angle_deg"])
    assert g["light"]["azimuth_deg"] == 90  # in the plane of E and the image's up
    L = np.cos(a) * E + np.sin(a) * up
    H = (E + L) / np.linalg.norm(E + L)
    np.testing.assert_allclose(H, [0.0, 1.0, 0.0], atol=1e-6)
    assert np.degrees(np.arcsin(E[1])) == pytest.approx(4.0, abs=1e-4)
    assert np.degrees(np.arcsin(L[1])) == pytest.approx(4.0, abs=1e-4)
    radii = g["object"]["radii"]
    assert radii[2] > 5 * radii[0]  # long along the view: the top face reads at sin 4 deg


def test_fig7_grazing_edge_lit_highlight_reads_at_full_view(fig7):
    """The default figure's four edge-lit images at their shared exposure (white = the brightest
    Torrance-Sparrow i, the knee of fig7.grazing; encoded here by the formulas): the
    Torrance-Sparrow highlight covers over a third of each object at mid-grey or brighter, Phong's
    none of it; MgO's highlight is brighter than aluminium's by Blinn's p_s F ratio at
    E.H = cos 86 deg (Fresnel's sin/tan form, "even more so than the aluminum"), and over twice as
    much of the object is at 192/255 or brighter."""
    fig, Y, _, _ = fig7
    k = fig["grazing"]["highlight_knee"]
    ts = {p: Y[f"{p}_torrance_sparrow_grazing_edge"] for p in "ab"}
    white = max(y.max() for y in ts.values())

    def codes(i):  # Y / white, compressed above the knee: k + (1 - k) tanh((v - k) / (1 - k))
        v = i / white
        return _srgb_8bit(np.where(v > k, k + (1 - k) * np.tanh((v - k) / (1 - k)), v))

    near_white = {}
    for p in "ab":
        obj = Y[f"{p}_torrance_sparrow_grazing_front"] > 0  # p_a > 0 on every object pixel
        assert obj.mean() > 0.25, p  # the object fills the frame
        lit = (codes(ts[p])[obj] >= 128).mean()
        for r in fig["phong_specular_readings"]:
            assert (codes(Y[f"{p}_phong_grazing_edge_{r}"])[obj] >= 128).mean() == 0, (p, r)
        assert lit > 1 / 3, (p, lit)
        near_white[p] = (codes(ts[p])[obj] >= 192).mean()
    assert near_white["b"] > 2 * near_white["a"] > 0, near_white
    q = fig["panels"]
    c = np.cos(np.radians(fig["grazing"]["light"]["angle_deg"] / 2))
    blinn = (q["b"]["p_s"] * fresnel_sin_tan(np.arccos(c), q["b"]["n"])
             / (q["a"]["p_s"] * fresnel_sin_tan(np.arccos(c), q["a"]["n"])))
    assert blinn > 1.2
    assert ts["b"].max() / ts["a"].max() == pytest.approx(blinn, rel=0.05)


def test_rim_profile_takes_the_brightest_column_and_the_object_rows():
    """The figure's profile: the column through the brightest pixel of any render, and the rows
    from the first to the last where any render shows the object (i > 0)."""
    from reflectance.papers.draw.blinn77_fig7 import _rim_profile

    a, b = np.zeros((9, 7)), np.zeros((9, 7))
    a[2:5, 1:6], b[3:8, 1:6] = 0.1, 0.1  # two objects, overlapping rows 3-4
    a[2, 4], b[3, 2] = 5.0, 7.0  # the brightest pixel is b's, in column 2
    column, rows = _rim_profile([a, b])
    assert column == 2
    assert rows.tolist() == [2, 3, 4, 5, 6, 7]


def _topmost_row(rgb, colour, tolerance=12):
    """The first row (from the top) with a pixel within ``tolerance`` of ``colour`` (#rrggbb)."""
    target = np.array([int(colour[k:k + 2], 16) for k in (1, 3, 5)])
    hit = (np.abs(rgb.astype(int) - target) <= tolerance).all(axis=-1).any(axis=1)
    return int(np.flatnonzero(hit)[0])


def test_fig7_profile_draws_mgo_above_aluminium(fig7):
    """Blinn: edge lit, MgO is "even more so [specular] than the aluminum". The default figure
    shows it by eye in its profile plot (lower left): MgO's line (Okabe-Ito vermilion) peaks
    higher in the PNG than aluminium's (blue), by Blinn's p_s F ratio at E.H = cos 86 deg read
    off the pixel rows against the plot's zero line (the lowest row of both lines)."""
    fig, Y, _, tmp = fig7
    rgb = np.asarray(Image.open(tmp / "fig7_matched.png").convert("RGB"))
    h, w, _ = rgb.shape
    plot = rgb[int(0.6 * h):, : int(0.45 * w)]  # the profile's axes, under every image
    top = {p: _topmost_row(plot, c) for p, c in (("a", "#0072b2"), ("b", "#d55e00"))}
    assert top["b"] < top["a"], top  # MgO's peak higher up
    q = fig["panels"]
    c = np.cos(np.radians(fig["grazing"]["light"]["angle_deg"] / 2))
    blinn = (q["b"]["p_s"] * fresnel_sin_tan(np.arccos(c), q["b"]["n"])
             / (q["a"]["p_s"] * fresnel_sin_tan(np.arccos(c), q["a"]["n"])))
    target = np.array([0xd5, 0x5e, 0x00])
    rows = np.flatnonzero((np.abs(plot.astype(int) - target) <= 12).all(axis=-1).any(axis=1))
    zero = rows[-1]  # the vermilion line runs along i = 0 below the object
    assert (zero - top["b"]) / (zero - top["a"]) == pytest.approx(blinn, rel=0.1)


@pytest.mark.parametrize("p", ["a", "b"])
def test_fig7_front_lit_peak_is_blinns_intensity(fig7, p):
    """At N = H, Blinn's i = p_a + p_d (N.L) + p_s s with N.L = E.H = cos(angle / 2): Phong s = 1,
    Torrance-Sparrow s = D G F / (N.E) = F(E.H) / (E.H) (D = G = 1)."""
    fig, Y, _, _ = fig7
    q, c = fig["panels"][p], np.cos(np.radians(fig["lights"]["front"]["angle_deg"] / 2))
    phong = fig["p_a"] + q["p_d"] * c + q["p_s"]
    assert phong - 0.02 < Y[f"{p}_phong_front_as_printed"].max() < phong + 0.005
    ts = fig["p_a"] + q["p_d"] * c + q["p_s"] * fresnel_sin_tan(np.arccos(c), q["n"]) / c
    assert ts - 0.02 < Y[f"{p}_torrance_sparrow_front"].max() < ts + 0.01


# --- the light sweep --------------------------------------------------------------------------

def _run_sweep(tmp, n_frames=5, **changes):
    fig7 = _fig7_config()
    sweep = dict(B77["fig7_sweep"], n_frames=n_frames, size=64, supersample=1, contact_frames=4,
                 **changes)
    out = {"gif": str(tmp / "sweep.gif"), "contact": str(tmp / "sweep.png"), "csv": str(tmp / "sweep.csv"),
           "values": str(tmp / "sweep.values.rst")}
    run_script("blinn_1977_fig7_sweep.py", tmp,
               {"sweep": sweep, "fig7": fig7, "wavelengths": WAVELENGTHS}, out)
    return sweep, {k: Path(v) for k, v in out.items()}


def _gif_frames(path):
    with Image.open(path) as gif:
        return [np.asarray(frame.convert("L")).copy() for frame in ImageSequence.Iterator(gif)]


def _gif_cells(frame, panels):
    """A GIF frame's images by (panel, model index): 0 Phong, 1 Torrance-Sparrow (its layout: a
    96-px label column, a 20-px head, a 22-px foot, 4-px gaps)."""
    label_w, head, gap = 96, 20, 4
    w = (frame.shape[1] - label_w - gap) // 2
    h = (frame.shape[0] - head - 22 - 2 * gap) // 2
    return {(key, k): frame[head + r * (h + gap):head + r * (h + gap) + h,
                            label_w + k * (w + gap):label_w + k * (w + gap) + w]
            for r, key in enumerate(panels) for k in range(2)}


def test_sweep_gif_frames_and_determinism(tmp_path):
    (tmp_path / "1").mkdir(), (tmp_path / "2").mkdir()
    sweep, first = _run_sweep(tmp_path / "1")
    _, second = _run_sweep(tmp_path / "2")
    for key in first:
        assert first[key].read_bytes() == second[key].read_bytes(), key
    with Image.open(first["gif"]) as gif:
        assert gif.n_frames == sweep["n_frames"] and gif.info["loop"] == 0
        assert gif.info["duration"] == sweep["frame_ms"]
        assert gif.size[0] > 2 * sweep["size"]  # a label column, then Phong and Torrance-Sparrow
    table = pd.read_csv(first["csv"])
    assert sorted(set(table.panel)) == sorted(sweep["panels"])
    for panel in sweep["panels"]:
        part = table[table.panel == panel]
        np.testing.assert_allclose(part.light_angle_deg,
                                   np.linspace(*sweep["angles_deg"], sweep["n_frames"]))
        # front lit the models agree; toward the edge the Torrance-Sparrow highlight outgrows Phong's
        assert part.max_abs_difference.iloc[0] < 0.1 < part.max_abs_difference.iloc[-2]
        assert part.torrance_sparrow_max.iloc[-2] > 1.5 * part.phong_max.iloc[-2]
        # the mirror-point highlight p_s F(c)/c, c = cos(angle/2), with Blinn's sin/tan Fresnel
        q = B77["fig7"]["panels"][panel]
        c = np.cos(np.radians(part.light_angle_deg.to_numpy()) / 2)
        np.testing.assert_allclose(part.mirror_highlight, q["p_s"] * fresnel_sin_tan(np.arccos(c), q["n"]) / c,
                                   rtol=1e-5)


def test_sweep_contact_sheet_shows_the_frame_before_the_crossover():
    """The review: no frame of the contact sheet lay between 137 degrees and the 172-degree frame,
    so the computed crossover could not be seen. The sheet's frames: contact_frames of them, the
    sweep's first and last, and the last frame before the crossover (aluminium still the
    brighter), the others evenly spaced; without a crossover, all evenly spaced."""
    from reflectance.papers.draw.blinn77_fig7_sweep import _contact_picks

    sweep = B77["fig7_sweep"]
    angles = np.linspace(*sweep["angles_deg"], sweep["n_frames"])
    crossover = highlight_crossover(B77)
    picks = _contact_picks(angles, sweep["contact_frames"], crossover)
    assert len(picks) == sweep["contact_frames"] and picks[0] == 0 and picks[-1] == len(angles) - 1
    assert angles[picks[-2]] < crossover < angles[picks[-2] + 1]
    np.testing.assert_array_equal(_contact_picks(angles, 6, None),
                                  np.round(np.linspace(0, len(angles) - 1, 6)).astype(int))


def test_sweep_frames_labels_true_of_pixels_and_unclipped(tmp_path):
    """Each GIF frame's four images share one exposure (so grey order is i order), no object pixel
    sits at 255, and MgO's Torrance-Sparrow peak, measured on the frame's pixels, is above
    aluminium's exactly where the table (and so the "MgO > Al" label) says so."""
    sweep, out = _run_sweep(tmp_path, n_frames=8)
    table = pd.read_csv(out["csv"])
    frames = _gif_frames(out["gif"])
    for f, frame in enumerate(frames):
        cell = _gif_cells(frame, sweep["panels"])
        obj = np.concatenate([c[c > 0] for c in cell.values()])
        assert (obj == 255).mean() < 0.02, f
        rows = table[table.frame == f].set_index("panel")
        # brighter on screen exactly when brighter in i (ties aside)
        ts_a, ts_b = rows.torrance_sparrow_max["a"], rows.torrance_sparrow_max["b"]
        if abs(ts_b / ts_a - 1) > 0.05:
            assert (cell["b", 1].max() > cell["a", 1].max()) == (ts_b > ts_a), f


def test_sweep_rim_closeup_holds_each_materials_brightest_pixel(tmp_path):
    """Past the crossover the lit rim is about a pixel thick: the contact sheet magnifies one crop
    of the last frame's Torrance-Sparrow images of the torus (view fig7). The crop the caption
    names holds, in the GIF's last frame, the brightest pixel of each material's Torrance-Sparrow
    image."""
    sweep, out = _run_sweep(tmp_path, n_frames=4, view="fig7", angles_deg=[5, 170])
    assert sweep["angles_deg"][1] > highlight_crossover(B77)  # the default draws the close-up
    values = _caption_values(out["values"])
    r0, r1, c0, c1 = (int(v) for v in re.search(r"rows (\d+) to (\d+), columns (\d+) to (\d+)",
                                                 values["closeup"]).groups())
    cell = _gif_cells(_gif_frames(out["gif"])[-1], sweep["panels"])
    h, w = cell[sweep["panels"][0], 1].shape
    assert (r1 - r0 + 1, c1 - c0 + 1) == (min(sweep["rim_closeup"]["height_px"], h),
                                          min(sweep["rim_closeup"]["width_px"], w))
    assert 0 <= r0 and r1 < h and 0 <= c0 and c1 < w
    for key in sweep["panels"]:
        ts = cell[key, 1]  # the Torrance-Sparrow image
        assert ts.max() > 0, key
        assert ts[r0:r1 + 1, c0:c1 + 1].max() == ts.max(), key


def highlight_crossover(config):
    from reflectance.papers.scenes import highlight_crossover_Blinn1977

    return highlight_crossover_Blinn1977(config["fig7"]["panels"]["a"], config["fig7"]["panels"]["b"])


def test_mgo_passes_aluminium_only_near_grazing_light():
    """Blinn: MgO "even more [specular] than the aluminum" edge lit: true beyond about 166.9 degrees."""
    from scipy.optimize import brentq

    from reflectance.papers.scenes import highlight_crossover_Blinn1977

    a, b = B77["fig7"]["panels"]["a"], B77["fig7"]["panels"]["b"]

    def ratio(angle):  # written out here: p_s F(c) / c at N = H, with Blinn's sin/tan Fresnel
        c = np.cos(np.radians(angle) / 2)
        return (b["p_s"] * fresnel_sin_tan(np.arccos(c), b["n"])) / (a["p_s"] * fresnel_sin_tan(np.arccos(c), a["n"]))

    by_hand = brentq(lambda x: ratio(x) - 1, 100, 179)
    assert 166 < by_hand < 168
    assert highlight_crossover_Blinn1977(a, b) == pytest.approx(by_hand, abs=1e-6)
    assert ratio(130) < 0.3 and ratio(175) > 1.5
    # the configured edge light lies beyond it; the sweep reaches past it
    # Blinn's "almost tangentially" (the default figure) lies beyond it, the variant's edge light
    # short of it (its highlight a band at full view); the sweep reaches past it
    assert B77["fig7"]["lights"]["edge"]["angle_deg"] < by_hand
    assert B77["fig7"]["lights"]["tangential"]["angle_deg"] > by_hand
    assert max(B77["fig7_sweep"]["angles_deg"]) > by_hand + 2


# --- Fig. 8 ---------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def fig8(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fig8")
    fig7 = _fig7_config()
    fig = dict(B77["fig8"], width=288)  # renders 288 x 192 at fig7.camera's aspect
    out = {"png": tmp / "fig8.png", "csv": tmp / "fig8.csv", "values": tmp / "fig8.values.rst"}
    out.update({f"{p}_{k}": tmp / f"fig8{p}.{ext}" for p in "ab"
                for k, ext in (("exr", "exr"), ("png", "png"), ("scene", "scene.yaml"))})
    run_script("blinn_1977_fig8.py", tmp, {"fig": fig, "fig7": fig7, "wavelengths": WAVELENGTHS,
                                           "n": fig7["panels"][fig["panel"]]["n"]},
               {k: str(v) for k, v in out.items()})
    return fig, out


@pytest.mark.parametrize("part", ["a", "b"])
def test_fig8_texture_modulates_the_highlight(fig8, part):
    """Blinn's D3 with C3 = C_min + (1 - C_min) t, normalised by C_min, against the untextured D3
    of C_min: per sample the specular parts differ only by D, so their ratio is
    [C_min C3 / (cos^2 a (C3^2 - 1) + 1)]^2 / [C_min^2 / (cos^2 a (C_min^2 - 1) + 1)]^2. The
    texture lowers the peak (ratio (C_min / C3)^2 at a = 0) and widens the lobe (ratio > 1 far
    from the highlight)."""
    from reflectance.render.integrator import shade_samples
    from reflectance.render.tracing import trace
    from reflectance.render.scene import load_scene, scene_from_dict
    from reflectance.geometry.texture import texture

    fig, out = fig8
    scene = load_scene(out[f"{part}_scene"])
    document = yaml.safe_load(Path(out[f"{part}_scene"]).read_text())
    material = document["objects"][0]["material"]
    del material["roughness_texture"]
    material["c3"] = c_min = fig["c_min"]
    plain = scene_from_dict(document)
    samples, shadowed, _ = trace(scene)
    spec = {name: shade_samples(s, samples, shadowed, components=True)[1]["specular"][:, 1]
            for name, s in (("texture", scene), ("plain", plain))}
    lit = samples.hit & (spec["plain"] > 1e-6)
    pattern = fig["patterns"][part]
    c3 = c_min + (1 - c_min) * texture(samples.uv[lit, 0], samples.uv[lit, 1], pattern["method"],
                                       **pattern["parameters"])
    L = np.asarray(scene.lights[0].source.direction, dtype=float)
    H = L / np.linalg.norm(L) + samples.view[lit]
    H /= np.linalg.norm(H, axis=1, keepdims=True)
    cos2 = np.einsum("ij,ij->i", samples.normal[lit], H) ** 2
    expected = ((c_min * c3 / (cos2 * (c3**2 - 1) + 1)) / (c_min**2 / (cos2 * (c_min**2 - 1) + 1))) ** 2
    ratio = spec["texture"][lit] / spec["plain"][lit]
    np.testing.assert_allclose(ratio, expected, rtol=1e-6)
    peak, far = cos2 > np.cos(np.radians(5.0)) ** 2, cos2 < np.cos(np.radians(30.0)) ** 2
    assert peak.sum() > 20 and far.sum() > 20
    # shiny (ratio 1) and dull (down to C_min^2 where C3 = 1) patches both fall in the highlight
    assert ratio[peak].max() > 0.9 and ratio[peak].min() < 0.5 * (1 + c_min**2)
    assert ratio[far].max() > 2  # dull patches still reflect where the shiny lobe has fallen off


def test_fig8_table_and_images(fig8):
    fig, out = fig8
    table = pd.read_csv(out["csv"])
    assert list(table.method) == [fig["patterns"][p]["method"] for p in "ab"]
    assert [json.loads(s) for s in table.parameters] == [fig["patterns"][p]["parameters"] for p in "ab"]
    assert np.all(table.C3_min_on_map >= fig["c_min"] - 1e-12) and np.all(table.C3_max_on_map <= 1 + 1e-12)
    for p in "ab":
        XYZ, header = read_exr(out[f"{p}_exr"])
        assert XYZ[..., 1].max() == pytest.approx(table.set_index("pattern").loc[p, "max_i"], rel=1e-5)


def test_fig8_renders_share_one_unclipped_exposure(fig8):
    """Both renders on one exposure (white = the brighter render's peak i, read from the EXRs) and
    no highlight at 255 in the figure: under 2 % of each render's object pixels."""
    fig, out = fig8
    table = pd.read_csv(out["csv"])
    peak = max(read_exr(out[f"{p}_exr"])[0][..., 1].max() for p in "ab")
    assert table.white_i.to_numpy() == pytest.approx([peak, peak], rel=1e-5)
    grey = np.asarray(Image.open(out["png"]).convert("L")).astype(int)
    width = grey.shape[1]
    for half in (grey[:, :width // 2], grey[:, width // 2:]):
        rows = np.flatnonzero((half == 0).sum(axis=1) > 50)  # the render's black background,
        rows = rows[:np.argmax(np.diff(rows) > 1)]            # its first block (the C3 map below)
        cols = np.flatnonzero((half[rows] == 0).sum(axis=0) > 20)
        render = half[rows[0]:rows[-1], cols[0]:cols[-1]]
        obj = render[render > 0]
        assert obj.size > 1000 and (obj >= 254).mean() < 0.02  # matplotlib truncates 1.0 - eps to 254


# --- the article's pair of spheres ------------------------------------------------------------

@pytest.fixture(scope="module")
def spheres(tmp_path_factory):
    """The article's spheres, run as Snakemake would at a small size: (config, outputs, pair XYZ,
    gold XYZ)."""
    tmp = tmp_path_factory.mktemp("spheres")
    fig = copy.deepcopy(CONFIG["figures"]["article"]["spheres"])
    fig["camera"].update(width=160, height=100, supersample=1)
    fig["metal_sphere"]["image"].update(width=80, height=100)  # the panels' one scale, as config's
    spectra = ROOT / "spectra"
    out = {"png": tmp / "spheres.png", "csv": tmp / "spheres.csv",
           "exr": tmp / "spheres.exr", "render": tmp / "render.png",
           "scene": tmp / "spheres.scene.yaml", "values": tmp / "spheres.values.rst",
           "gold_exr": tmp / "gold.exr", "gold_render": tmp / "gold_render.png",
           "gold_scene": tmp / "gold.scene.yaml"}
    pigments = {s["diffuse_material"]: CONFIG["materials"][s["diffuse_material"]]
                for s in fig["spheres"]}
    from reflectance.papers.figures import article_spheres as definition

    params = {"fig": fig, "pigments": pigments, "wavelengths": WAVELENGTHS,
              "colour": CONFIG["colour"]}
    run_script("article_spheres.py", tmp, params, {k: str(v) for k, v in out.items()},
               {"spectra": [str(spectra / f"{name}.csv") for name in definition.spectra(params)]})
    return fig, out, read_exr(out["exr"])[0], read_exr(out["gold_exr"])[0]


def _XYZ_of(values):
    """XYZ (Y = 1 for a white of reflectance 1) of a reflectance on 360-830 nm by 5 nm under D65,
    CIE 15:2004 tristimulus integration by colour-science."""
    import colour

    shape = colour.SpectralShape(360, 830, 5)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    sd = colour.SpectralDistribution(dict(zip(range(360, 835, 5), values)))
    with colour.utilities.suppress_warnings(colour_runtime_warnings=True):
        return colour.sd_to_XYZ(sd, cmfs, d65, shape=shape) / 100


def _xy_tools():
    import colour

    return lambda values: colour.XYZ_to_xy(_XYZ_of(values))


def _gold_F0(fig):
    """The metal sphere's F0 on 360-830 nm by 5 nm from its measured n, k (spectra/), by hand."""
    au = pd.read_csv(ROOT / "spectra" / f"{fig['metal_sphere']['material']}.csv")
    nm = np.arange(360, 835, 5)
    n, k = (np.interp(nm, au.wavelength_nm, au[q]) for q in ("n", "k"))
    return ((n - 1) ** 2 + k**2) / ((n + 1) ** 2 + k**2)


def _caption_values(path):
    """The |name| replace:: value pairs of a figure's values file."""
    return dict(re.findall(r"\|(\w+)\| replace:: (.*)", Path(path).read_text()))


def _xy(XYZ):
    total = XYZ.sum(-1, keepdims=True)
    return XYZ[..., :2] / np.where(total > 0, total, 1.0)


def test_article_spheres_pair_has_white_highlights_on_coloured_spheres(spheres):
    from reflectance.optics.spectra import read_spectrum_csv

    fig, out, XYZ, _ = spheres
    xy_of, xy, spectra = _xy_tools(), _xy(XYZ), ROOT / "spectra"
    white = xy_of(np.ones(95))
    width = XYZ.shape[1]
    for k, s in enumerate(sorted(fig["spheres"], key=lambda s: s["center"][0])):  # left, right
        half = slice(k * width // 2, (k + 1) * width // 2)
        Y, c = XYZ[:, half, 1], xy[:, half]
        peak = np.unravel_index(np.argmax(Y), Y.shape)
        table = read_spectrum_csv(spectra / f"{s['diffuse_material']}.csv")
        target = xy_of(np.interp(np.arange(360, 835, 5), table.wavelength_nm, table.reflectance))
        body = (Y > 0) & (np.linalg.norm(c - white, axis=-1) > 0.5 * np.linalg.norm(target - white))
        assert body.sum() > 100
        # the highlight is close to white, much closer than the pigment's colour
        assert np.linalg.norm(c[peak] - white) < 0.25 * np.linalg.norm(target - white)
        # the body has the pigment's hue (angle around the white point)
        hue = np.arctan2(*(c[body] - white).mean(0)[::-1])
        assert np.degrees(abs(hue - np.arctan2(*(target - white)[::-1]))) < 8.0


def _spheres_in(image):
    """Column ranges of the spheres of a written panel: the floor is spectrally flat under a D65
    light and the background black, so their pixels are neutral; a sphere's (pigment or gold)
    are not, or are its white highlight, which lies inside it. One range per connected blob."""
    from scipy import ndimage

    labels, n = ndimage.label(image.max(-1) - image.min(-1) > 8)
    runs = []
    for i in range(1, n + 1):
        blob = labels == i
        if blob.sum() > 0.01 * blob.size:  # not a stray antialiased edge pixel
            columns = np.flatnonzero(blob.any(axis=0))
            runs.append((columns[0], columns[-1] + 1))
    return runs


def test_article_spheres_built_image_pair_panel_highlights_are_near_white(spheres):
    """The issue: the pair's highlights peaked at (130, 106, 109) and (101, 109, 123), dim grey.
    In the written render each plastic sphere's highlight (its brightest pixel) reaches at least
    240/255 and is nearly neutral (channels within 20/255), and the panel shows two spheres."""
    fig, out, _, _ = spheres
    image = np.asarray(Image.open(out["render"]).convert("RGB"), dtype=float)
    runs = _spheres_in(image)
    assert len(runs) == 2, runs  # a pair: two spheres, no gold between them
    for a, b in runs:
        part = image[:, a:b]
        peak = part.reshape(-1, 3)[np.argmax(part.sum(-1))]
        assert peak.max() >= 240, peak
        assert peak.max() - peak.min() <= 20, peak  # low chroma: white, not pink or blue-grey
    values = Path(out["values"]).read_text()  # the caption states each sphere's peak
    for s in fig["spheres"]:
        assert f"({s['name']})" in values.split("|pair_peaks| replace:: ")[1]


def test_article_spheres_gold_in_its_own_panel(spheres):
    """The gold sphere alone in its panel, exposed on its own: its highlight has gold's colour (F0
    from measured n, k, written out here), not the light's white (the article: "the color of the
    specular highlight will reflect the color of the material"), and is bright (a channel at
    240/255 or more; the second review: not a plateau, under 0.5 % of the sphere at 250 or more)."""
    fig, out, pair, XYZ = spheres
    xy_of, xy = _xy_tools(), _xy(XYZ)
    white = xy_of(np.ones(95))
    gold = xy_of(_gold_F0(fig))
    peak = np.unravel_index(np.argmax(XYZ[..., 1]), XYZ.shape[:2])
    assert np.linalg.norm(xy[peak] - gold) < 0.35 * np.linalg.norm(gold - white)
    assert np.linalg.norm(xy[peak] - white) > 0.6 * np.linalg.norm(gold - white)
    image = np.asarray(Image.open(out["gold_render"]).convert("RGB"), dtype=float)
    assert len(_spheres_in(image)) == 1
    assert image.reshape(-1, 3)[np.argmax(XYZ[..., 1].ravel())].max() >= 240
    sphere = image.max(-1) - image.min(-1) > 8
    assert (image[sphere].max(-1) >= 250).mean() < 0.005
    # and no gold in the pair's panel: nowhere there is the colour of gold's highlight
    pxy = _xy(pair)
    bright = pair[..., 1] > 0.5 * pair[..., 1].max()
    assert not (np.linalg.norm(pxy[bright] - gold, axis=-1) < 0.35 * np.linalg.norm(gold - white)).any()


def _gold_sphere(out):
    """The written gold render, its sphere's pixels (chromatic: the floor is neutral, the sky
    black) and the EXR's luminance."""
    image = np.asarray(Image.open(out["gold_render"]).convert("RGB"), dtype=float)
    return image, image.max(-1) - image.min(-1) > 8, read_exr(out["gold_exr"])[0][..., 1]


def test_article_spheres_gold_reads_as_metal_not_a_flat_disc(spheres):
    """The review: outside its highlight the gold sphere was one flat colour (113, 95, 68), a
    khaki disc. Mirroring a sky and the floor (config metal_sphere.environment), its body outside
    the highlight (luminance under half the peak) spans a luminance range: its median over its
    10th percentile above 2 (a flat fill covering most of the body gives 1)."""
    fig, out, _, _ = spheres
    _, sphere, Y = _gold_sphere(out)
    body = Y[sphere & (Y < 0.5 * Y[sphere].max())]
    assert body.size > 200
    p10, p50 = np.percentile(body, [10, 50])
    assert p50 > 2.0 * p10, (p10, p50)


def test_article_spheres_gold_mirrors_the_floor_below_its_horizon(spheres):
    """The review: the gold sphere's lower half was black (it mirrored nothing below the horizon).
    With the floor's ground lights, the lower half of its disc (inside 0.9 of the radius, the
    disc fitted to its chromatic pixels' extent) has under 10 % of its pixels below 30/255 and a
    median above 0.4 times the upper half's; and its darkest band is at the bottom, where it
    mirrors its own shadow and the floor it rests on."""
    fig, out, _, _ = spheres
    image, sphere, _ = _gold_sphere(out)
    cols, rows = np.flatnonzero(sphere.any(0)), np.flatnonzero(sphere.any(1))
    r, cx = (cols[-1] - cols[0] + 1) / 2, (cols[0] + cols[-1]) / 2
    cy = rows[0] + r  # the top of the sphere is lit, so chromatic
    yy, xx = np.mgrid[:image.shape[0], :image.shape[1]] + 0.5
    disc = (xx - cx) ** 2 + (yy - cy) ** 2 < (0.9 * r) ** 2
    value = image.max(-1)
    lower, upper = value[disc & (yy > cy)], value[disc & (yy < cy)]
    assert lower.size > 500
    assert (lower < 30).mean() < 0.10, (lower < 30).mean()
    assert np.median(lower) > 0.4 * np.median(upper), (np.median(lower), np.median(upper))
    bands = [np.mean(value[disc & (yy > cy + f * r) & (yy < cy + (f + 0.2) * r)])
             for f in (0.0, 0.2, 0.4, 0.7)]
    assert bands[-1] == min(bands), bands


def test_article_spheres_gold_highlight_has_a_gradient_and_gold_hue(spheres):
    """The review: the gold highlight was a clipped plateau about 60 px wide. Under 2 % of the
    gold sphere's pixels have a channel at 255, and the highlight (pixels above half the peak
    luminance) keeps gold's hue: the CIELAB hue of its mean colour (colour-science, sRGB decoded
    to XYZ under D65) within 10 degrees of that of gold's F0 from measured n, k."""
    import colour

    fig, out, _, _ = spheres
    image, sphere, Y = _gold_sphere(out)
    clipped = (image[sphere].max(-1) >= 255).mean()
    assert clipped < 0.02, clipped
    d65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    F0 = _XYZ_of(_gold_F0(fig))
    gold = colour.xyY_to_XYZ([*colour.XYZ_to_xy(F0), 0.5])
    bright = sphere & (Y > 0.5 * Y[sphere].max())
    XYZ = colour.sRGB_to_XYZ(image[bright].mean(0) / 255)
    hue = [colour.Lab_to_LCHab(colour.XYZ_to_Lab(v, d65))[2] for v in (XYZ, gold)]
    assert abs((hue[0] - hue[1] + 180) % 360 - 180) < 10.0, hue
    # the caption's F0 colour (L*, C*, hue), against colour-science's integration of F0 under D65
    LCh = colour.Lab_to_LCHab(colour.XYZ_to_Lab(F0, d65))
    values = _caption_values(out["values"])
    assert [float(values[f"gold_F0_{q}"]) for q in ("L", "C", "hue")] == pytest.approx(LCh, abs=1.0)


def test_article_spheres_sky_cropped(spheres):
    """The review: 19 % of the figure was black sky. The figure drops the rows above the spheres:
    the written figure's panels are shorter than the renders by the rows the caption states."""
    fig, out, _, _ = spheres
    values = Path(out["values"]).read_text()
    rows = int(values.split("|cropped_rows| replace:: ")[1].split()[0])
    render = np.asarray(Image.open(out["render"]).convert("RGB"))
    assert rows > 0.1 * render.shape[0]
    top = np.flatnonzero((render.max(-1) - render.min(-1) > 8).any(1))[0]
    assert rows <= top  # nothing of a sphere is cropped
    # the second review: a black band of empty space lay behind the spheres (the floor ended in
    # the frame); the floor (config floor_size) now fills every pixel of each render's top row
    for name in ("render", "gold_render"):
        first = np.asarray(Image.open(out[name]).convert("RGB"))[0]
        assert first.min() > 40, (name, first.min())


def test_config_check_builds_the_scenes_the_scripts_render(fig8):
    """reflectance.config validates, at parse time, the scenes of reflectance.papers.scenes: they
    must be the scenes the figure script renders (read back from its scene files)."""
    from reflectance.papers.scenes import blinn_scene_Blinn1977, texture_material_Blinn1977
    from reflectance.render.scene import validate_scene

    fig, out = fig8
    fig7 = _fig7_config()
    fig7["camera"].update(width=288, height=192)  # as the fixture
    for part in "ab":
        material = texture_material_Blinn1977(fig, fig["patterns"][part],
                                              fig7["panels"][fig["panel"]]["n"])
        document = validate_scene(blinn_scene_Blinn1977(fig7, material, fig["light"], WAVELENGTHS))
        assert yaml.safe_load(yaml.safe_dump(document)) == yaml.safe_load(
            Path(out[f"{part}_scene"]).read_text()), part


def test_fig7_rim_closeup_shows_the_edge_lit_highlight():
    """The close-up inset of Fig. 7: aimed at the torus point whose normal is H (checked against
    the torus's own parametrisation), it shows the Torrance-Sparrow rim several pixels wide, and
    MgO's rim brighter than aluminium's (beyond the crossover), Phong's far dimmer."""
    from reflectance.papers.scenes import (blinn_scene_Blinn1977, materials_Blinn1977,
                                           rim_camera_Blinn1977)
    from reflectance.render.pipeline import render
    from reflectance.render.scene import scene_from_dict

    fig7 = B77["fig7"]
    edge = fig7["lights"][fig7["rim_closeup"]["light"]]
    cam = rim_camera_Blinn1977(fig7, edge)
    # the point is on the torus: R (cos u, sin u, 0) + r (cos v cos u, cos v sin u, sin v), and
    # its normal (cos v cos u, cos v sin u, sin v) bisects L and E
    R, r = fig7["object"]["major_radius"], fig7["object"]["minor_radius"]
    p = np.asarray(cam["look_at"])
    u = np.arctan2(p[1], p[0])
    n = (p - R * np.array([np.cos(u), np.sin(u), 0.0])) / r
    assert np.linalg.norm(n) == pytest.approx(1.0, abs=1e-12)
    c = fig7["camera"]
    L = light_direction(c["position"], c["look_at"], c["up"], edge["angle_deg"], edge["azimuth_deg"])
    E = np.subtract(c["position"], c["look_at"]) / np.linalg.norm(np.subtract(c["position"],
                                                                            c["look_at"]))
    np.testing.assert_allclose(n, (L + E) / np.linalg.norm(L + E), atol=1e-12)
    peaks = {}  # one trace for the four renders, as the script keeps it (bit for bit)
    for panel in "ab":
        q = fig7["panels"][panel]
        m = materials_Blinn1977(q["p_s"], q["p_d"], q["c3"], q["n"], "matched")
        for model in ("phong", "torrance_sparrow"):
            Y = render(scene_from_dict(blinn_scene_Blinn1977(fig7, m[model], edge,
                                                             CONFIG["wavelengths"], cam)),
                       keep_trace=True).XYZ[..., 1]
            peaks[panel, model] = Y.max()
            if model == "torrance_sparrow":
                bright = Y > 1  # brighter than display white
                assert np.median(bright.sum(axis=0)[bright.any(axis=0)]) >= 4, panel
    assert peaks["b", "torrance_sparrow"] > peaks["a", "torrance_sparrow"]
    assert peaks["a", "torrance_sparrow"] > 5 * peaks["a", "phong"]
