"""`reflectance brdf`: the reflected distribution of a BRDF model in a plane, as CSV."""

import io

import colour
import numpy as np
import pandas as pd
import pytest

from reflectance.cli import main


def run(args, capsys):
    main(["brdf", *args])
    return pd.read_csv(io.StringIO(capsys.readouterr().out))


def fails(args):
    with pytest.raises(SystemExit) as err:
        main(["brdf", *args])
    return str(err.value)


def by_hand_cook_torrance(incidence_deg, out_deg, n, m):
    """R_s of Cook & Torrance 1982 written out from the paper, in the plane of incidence
    (light on the -x side, positive view angles on the specular side)."""
    ti, to = np.radians(incidence_deg), np.radians(out_deg)
    N = np.array([0.0, 0.0, 1.0])
    L = np.array([-np.sin(ti), 0.0, np.cos(ti)])
    V = np.array([np.sin(to), 0.0, np.cos(to)])
    H = (V + L) / np.linalg.norm(V + L)
    alpha = np.arccos(N @ H)
    D = np.exp(-((np.tan(alpha) / m) ** 2)) / (m**2 * np.cos(alpha) ** 4)
    G = min(1.0, 2 * (N @ H) * (N @ V) / (V @ H), 2 * (N @ H) * (N @ L) / (V @ H))
    c = V @ H
    g = np.sqrt(n**2 + c**2 - 1)
    F = 0.5 * (g - c) ** 2 / (g + c) ** 2 * (1 + (c * (g + c) - 1) ** 2 / (c * (g - c) + 1) ** 2)
    return F / np.pi * D * G / ((N @ L) * (N @ V))


def luminous_F0(root, name):
    """Y of a measured material's F0 under D65 by colour-science (white Y = 1)."""
    data = pd.read_csv(root / "spectra" / f"{name}.csv")
    wl = np.arange(360, 831, 5.0)
    index = np.interp(wl, data.wavelength_nm, data.n) + 1j * np.interp(wl, data.wavelength_nm, data.k)
    F0 = abs((index - 1) / (index + 1)) ** 2
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(360, 830, 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    sd = colour.SpectralDistribution(dict(zip(wl, F0)))
    return colour.sd_to_XYZ(sd, cmfs, d65, method="Integration")[1] / 100


def test_copper_example_columns_and_shape(root, capsys, monkeypatch):
    monkeypatch.chdir(root)
    t = run(["cook-torrance", "--material", "Cu", "--m", "0.3", "--incidence", "70",
             "--angles", "-80", "-40", "0", "40", "80"], capsys)
    assert list(t.columns) == ["theta_out_deg", "diffuse", "specular", "total", "X", "Y", "Z"]
    assert list(t.theta_out_deg) == [-80, -40, 0, 40, 80]
    assert (t.diffuse == 0).all()  # a metal: s = 1, d = 0 by default
    np.testing.assert_allclose(t.total, t.specular, rtol=1e-12)
    # the light's side is dark, the lobe rises towards the specular side and grazing
    assert np.all(np.diff(t.total) > 0)
    # Y of a light of irradiance Y = 1 normal to its beam: total (luminous) times cos(incidence)
    np.testing.assert_allclose(t.Y, t.total * np.cos(np.radians(70)), rtol=1e-5)
    assert (t[["X", "Y", "Z"]] >= 0).all().all()


@pytest.mark.parametrize("incidence, out", [(30, 10), (30, 50), (60, 75), (0, -20)])
def test_cook_torrance_by_hand(capsys, incidence, out):
    n, m = 1.5, 0.3
    t = run(["cook-torrance", "--n", str(n), "--m", str(m), "--incidence", str(incidence),
             "--angles", str(out)], capsys)
    assert t.total[0] == pytest.approx(by_hand_cook_torrance(incidence, out, n, m), rel=1e-5)
    # with s = 0.4 the diffuse part is d R_d, R_d = F0 / pi (Cook & Torrance 1982 Fig. 7)
    t = run(["cook-torrance", "--n", str(n), "--m", str(m), "--s", "0.4", "--incidence",
             str(incidence), "--angles", str(out)], capsys)
    F0 = ((n - 1) / (n + 1)) ** 2
    assert t.diffuse[0] == pytest.approx(0.6 * F0 / np.pi, rel=1e-5)
    assert t.specular[0] == pytest.approx(0.4 * by_hand_cook_torrance(incidence, out, n, m), rel=1e-5)


def test_reciprocity_in_the_plane_of_incidence(capsys):
    common = ["cook-torrance", "--n", "1.8", "--m", "0.25", "--s", "0.7"]
    a = run([*common, "--incidence", "25", "--angles", "65"], capsys)
    b = run([*common, "--incidence", "65", "--angles", "25"], capsys)
    assert a.total[0] == pytest.approx(b.total[0], rel=1e-5)


def test_paper_convention_is_four_times_physical(capsys):
    common = ["cook-torrance", "--n", "1.5", "--m", "0.3", "--incidence", "40", "--angles", "0", "40"]
    paper = run(common, capsys)
    physical = run([*common, "--convention", "physical"], capsys)
    np.testing.assert_allclose(paper.total, 4 * physical.total, rtol=1e-5)


def test_lambert_diffuse_is_constant_and_equals_F0_over_pi(root, capsys, monkeypatch):
    monkeypatch.chdir(root)
    t = run(["lambert", "--material", "Rust", "--incidence", "30",
             "--angles", "-85", "-30", "0", "45", "89"], capsys)
    assert (t.specular == 0).all()
    np.testing.assert_allclose(t.diffuse, t.diffuse[0], rtol=1e-12)
    assert t.diffuse[0] == pytest.approx(luminous_F0(root, "Rust") / np.pi, rel=1e-5)


def test_azimuth_plane_is_symmetric(capsys):
    t = run(["cook-torrance", "--n", "1.5", "--m", "0.3", "--incidence", "50", "--azimuth", "90",
             "--angles", "-35", "35"], capsys)
    assert t.total[0] == pytest.approx(t.total[1], rel=1e-5)
    # out of the plane of incidence the mirror direction is never reached: below the in-plane peak
    peak = run(["cook-torrance", "--n", "1.5", "--m", "0.3", "--incidence", "50", "--angles", "50"],
               capsys)
    assert t.total[0] < peak.total[0]


def test_aliases_and_registry_names_agree(capsys):
    args = ["--n", "1.5", "--m", "0.3", "--incidence", "30", "--angles", "20"]
    values = [run([name, *args], capsys).total[0]
              for name in ("cook-torrance", "CookTorrance1982", "COOK-TORRANCE")]
    assert values[0] == values[1] == values[2]


def test_help_defines_the_sign_of_the_angles(capsys):
    with pytest.raises(SystemExit):
        main(["brdf", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "positive on the specular side" in text and "light's side" in text


def test_errors_name_the_problem():
    message = fails(["velvet", "--incidence", "30", "--angles", "0"])
    assert "velvet" in message and "cook-torrance" in message and "CookTorrance1982" in message
    assert "--c1" in fails(["phong", "--m", "0.3", "--incidence", "30", "--angles", "0"])
    assert "--material or --n" in fails(["cook-torrance", "--m", "0.3", "--incidence", "30",
                                         "--angles", "0"])
    assert "--m or --c3" in fails(["cook-torrance", "--n", "1.5", "--incidence", "30",
                                   "--angles", "0"])
    assert "--incidence" in fails(["lambert", "--incidence", "90", "--angles", "0"])
    assert "--angles" in fails(["lambert", "--incidence", "10", "--angles", "95"])
    assert "no specular term" in fails(["lambert", "--s", "0.5", "--incidence", "10", "--angles", "0"])
    assert "s + d = 1" in fails(["cook-torrance", "--n", "1.5", "--m", "0.3", "--s", "0.5",
                                 "--d", "0.2", "--incidence", "10", "--angles", "0"])
    assert "--convention" in fails(["phong", "--convention", "paper", "--incidence", "10",
                                    "--angles", "0"])


def test_unknown_material_lists_known(root, monkeypatch):
    monkeypatch.chdir(root)
    message = fails(["lambert", "--material", "Unobtainium", "--incidence", "10", "--angles", "0"])
    assert "Unobtainium" in message and "Cu" in message
