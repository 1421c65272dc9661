"""Tests of reflectance.render.shading against formulas written out here, colour-science and brute force."""

import colour
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.colour.colorimetry import dominant_wavelength, tristimulus_weights
from reflectance.render.shading import (SHADING_MODELS, Ambient, Light, RoughnessTexture,
                                 ShadingMaterial, ambient_intensity, emission_XYZ,
                                 fresnel_XYZ_table, lookup_table, shade)
from reflectance.geometry.texture import texture
from reflectance.optics.spectra import load_material
from reflectance.render.lights import DirectionalLight, PointLight

OBSERVER = "CIE 1931 2 Degree Standard Observer"


@pytest.fixture(scope="module")
def copper(root, grid):
    return load_material("Cu", grid, spectra_dir=root / "spectra")


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def random_geometry(seed, n=400):
    """Random unit N, V, L above each other's horizon (N.V > 0, N.L > 0)."""
    rng = np.random.default_rng(seed)
    N = unit(rng.normal(size=(n, 3)))
    V = unit(rng.normal(size=(n, 3)))
    V = np.where((np.sum(N * V, 1) < 0)[:, None], -V, V)
    L = unit(rng.normal(size=(n, 3)))
    L = np.where((np.sum(N * L, 1) < 0)[:, None], -L, L)
    return N, V, L


def colour_weights(grid, illuminant="D65"):
    """CIE 15 tristimulus weights built directly from colour-science's tables."""
    shape = colour.SpectralShape(grid[0], grid[-1], grid[1] - grid[0])
    cmfs = colour.MSDS_CMFS[OBSERVER].copy().align(shape).values
    S = colour.SDS_ILLUMINANTS[illuminant].copy().align(shape).values
    return S[:, None] * cmfs / np.sum(S * cmfs[:, 1])


def fresnel_textbook(c, n, k):
    """Unpolarised Fresnel reflectance of n + ik from the s and p amplitude coefficients."""
    eta = n + 1j * k
    s = np.sqrt(1 - c**2)
    ct = np.sqrt(1 - (s / eta) ** 2)
    rs = (c - eta * ct) / (c + eta * ct)
    rp = (eta * c - ct) / (eta * c + ct)
    return 0.5 * (abs(rs) ** 2 + abs(rp) ** 2)


# ---- textures, ambient, emission ---------------------------------------------------------------

def test_ambient_intensity_readings():
    lights = [Light(DirectionalLight((0, 0, 1)), intensity=2.0, solid_angle=1e-4),
              Light(DirectionalLight((1, 0, 1)), intensity=4.0, solid_angle=2e-4)]
    # as printed: I_ia = 0.01 I_i (the lights' mean intensity)
    assert ambient_intensity(Ambient(0.01, "intensity"), lights) == pytest.approx(0.03)
    # irradiance: a uniform hemisphere of intensity I_ia gives irradiance pi I_ia
    I_ia = ambient_intensity(Ambient(0.01, "irradiance"), lights)
    assert np.pi * I_ia == pytest.approx(0.01 * (2.0 * 1e-4 + 4.0 * 2e-4))
    assert ambient_intensity(Ambient(0.0), lights) == 0.0
    with pytest.raises(ValueError, match="known: intensity, irradiance"):
        Ambient(0.01, "radiance")


@pytest.mark.parametrize("wavelength, purity", [(640.0, 1.0), (640.0, 0.6), (520.0, 0.8),
                                                (470.0, 0.3)])
def test_emission_has_the_asked_dominant_wavelength_purity_and_luminance(wavelength, purity):
    XYZ = emission_XYZ(wavelength, 0.7, purity)
    assert XYZ[1] == pytest.approx(0.7, rel=1e-12)
    found, p = dominant_wavelength(XYZ, "D65")
    assert abs(float(found) - wavelength) <= 1.0  # colour-science's locus is sampled every 1 nm
    assert float(p) == pytest.approx(purity, abs=5e-3)


def test_light_and_material_reject_bad_input():
    with pytest.raises(ValueError, match="exactly one of solid_angle and area"):
        Light(PointLight((0, 0, 1)), solid_angle=None, area=None)
    with pytest.raises(ValueError, match="not an area"):
        Light(DirectionalLight((0, 0, 1)), solid_angle=None, area=1.0)
    with pytest.raises(ValueError, match="known: CookTorrance1982"):
        ShadingMaterial(model="Oren-Nayar")
    with pytest.raises(ValueError, match="needs the specular material"):
        ShadingMaterial(model="CookTorrance1982", s=1.0, roughness=0.3)


# ---- the Fresnel table -------------------------------------------------------------------------

def test_fresnel_table_ends_are_F0_and_the_white(copper, grid):
    material = ShadingMaterial(n=copper.n, k=copper.k, roughness=0.3)
    W = colour_weights(grid)
    table = fresnel_XYZ_table(material, W, size=65)
    F0 = fresnel_textbook(1.0, copper.n, copper.k)
    assert np.allclose(table[-1], F0 @ W, rtol=1e-12)
    assert np.allclose(table[0], W.sum(axis=0), rtol=1e-12)  # F = 1 at grazing incidence
    i = 23  # any node c = i / 64
    assert np.allclose(table[i], fresnel_textbook(i / 64, copper.n, copper.k) @ W, rtol=1e-10)


def test_lookup_table_is_exact_for_linear_tables():
    c = np.linspace(0, 1, 11)
    table = np.stack([1 + 2 * c, 3 - c, 0.5 * c], -1)
    x = np.random.default_rng(0).random(1000)
    assert np.allclose(lookup_table(table, x), np.stack([1 + 2 * x, 3 - x, 0.5 * x], -1))
    assert np.allclose(lookup_table(table, [-0.5, 1.5]), table[[0, -1]])


# ---- shading -----------------------------------------------------------------------------------

def lights_at(L, solid_angle=1e-2, intensity=1.0, spectrum="D65"):
    return [Light(DirectionalLight(tuple(l)), spectrum, intensity, solid_angle) for l in L]


def test_lambert_white_head_on_has_Y_I_omega_over_pi(grid):
    n = 5
    N = np.tile([0.0, 0.0, 1.0], (n, 1))
    V = unit(np.random.default_rng(2).normal(size=(n, 3)) * [1, 1, 0] + [0, 0, 2])
    material = ShadingMaterial(model="Lambert", convention="physical", s=0.0, d=1.0, albedo=1.0)
    lights = lights_at([[0, 0, 1]], solid_angle=0.25, intensity=3.0)
    XYZ = shade(np.zeros((n, 3)), N, V, np.zeros((n, 2)), material, lights, wavelengths=grid)
    assert np.allclose(XYZ[:, 1], 3.0 * 0.25 / np.pi, rtol=1e-12)
    white = colour_weights(grid).sum(axis=0)
    assert np.allclose(XYZ, 3.0 * 0.25 / np.pi * white, rtol=1e-12)


def cook_torrance_spectrum(N, V, L, n, k, m, s, d, albedo):
    """Cook & Torrance's R(lambda), written out: Beckmann as printed, V-cavity G, exact F."""
    H = unit(L + V)
    NL, NV, NH, VH = (np.sum(a * b, -1) for a, b in ((N, L), (N, V), (N, H), (V, H)))
    tan2 = (1 - NH**2) / NH**2
    D = np.exp(-tan2 / m**2) / (m**2 * NH**4)
    G = np.minimum(1, np.minimum(2 * NH * NV / VH, 2 * NH * NL / VH))
    F = fresnel_textbook(VH[:, None], n, k)
    Rs = F / np.pi * (D * G / (NL * NV))[:, None]
    return s * Rs + d * albedo / np.pi, NL


@pytest.mark.parametrize("spectral", ["table", "brute-force"])
def test_cook_torrance_matches_the_formulas_written_out(copper, grid, spectral):
    N, V, _ = random_geometry(3, 300)  # some samples face away from a light: R = 0 there
    material = ShadingMaterial(n=copper.n, k=copper.k, s=0.7, d=0.3, albedo=copper.F0,
                               roughness=0.3)
    lights = [Light(DirectionalLight((0.2, -0.3, 0.9)), "D65", 2.0, 1e-3),
              Light(DirectionalLight((-0.5, 0.1, 0.6)), "A", 0.5, 3e-3)]
    XYZ = shade(np.zeros_like(N), N, V, np.zeros((len(N), 2)), material, lights,
                wavelengths=grid, spectral=spectral, table_size=4097)
    expected = np.zeros_like(XYZ)
    for light in lights:
        Lv = np.broadcast_to(unit(light.source.direction), N.shape)
        R, NL = cook_torrance_spectrum(N, V, Lv, copper.n, copper.k, 0.3, 0.7, 0.3, copper.F0)
        lit = (NL > 0)[:, None]
        E = light.intensity * light.solid_angle * np.maximum(NL, 0)[:, None]
        expected += np.where(lit, E * R, 0.0) @ colour_weights(grid, light.spectrum)
    rtol = 1e-9 if spectral == "brute-force" else 1e-6  # table: linear interpolation in c
    assert np.allclose(XYZ, expected, rtol=rtol, atol=1e-15)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10**6))
def test_paper_convention_is_four_times_physical_for_beckmann(seed, copper, grid):
    N, V, L = random_geometry(seed, 50)
    kwargs = dict(n=copper.n, k=copper.k, s=1.0, d=0.0, roughness=0.25, albedo=copper.F0)
    lights = lights_at([L[0]])
    parts = [shade(np.zeros_like(N), N, V, np.zeros((50, 2)),
                   ShadingMaterial(convention=c, **kwargs), lights, wavelengths=grid,
                   components=True)[1]["specular"] for c in ("paper", "physical")]
    # (atol: lobes far from H underflow to denormals, where a factor 4 loses digits)
    assert np.allclose(parts[0], 4.0 * parts[1], rtol=1e-12, atol=1e-290)
    assert parts[1][:, 1].max() > 0


@pytest.mark.parametrize("model, extra", [
    ("CookTorrance1982", {"lobes": ((0.4, 0.4), (0.6, 0.2)), "shadowing": "v-cavity"}),
    ("CookTorrance1982", {"roughness": 0.3, "shadowing": "smith", "convention": "physical"}),
    ("TorranceSparrow_Blinn1977", {"distribution": "TrowbridgeReitz1975", "roughness": 0.4}),
    ("BlinnPhong1977", {"roughness": 40.0}),
    ("Phong1975", {"roughness": 20.0}),
    ("Lambert", {"convention": "physical"}),
])
def test_table_equals_brute_force_for_every_model(model, extra, copper, grid):
    N, V, L = random_geometry(5, 500)
    s, d = (0.0, 1.0) if model == "Lambert" else (0.6, 0.4)
    material = ShadingMaterial(model=model, s=s, d=d, n=copper.n, k=copper.k, albedo=copper.F0,
                               **extra)
    lights = lights_at([L[0], L[1]], spectrum="D50")
    ambient = Ambient(0.02, "intensity", "D65")
    args = (np.zeros_like(N), N, V, np.random.default_rng(0).random((500, 2)), material, lights)
    table = shade(*args, ambient=ambient, wavelengths=grid, table_size=8193)
    brute = shade(*args, ambient=ambient, wavelengths=grid, spectral="brute-force")
    assert np.allclose(table, brute, rtol=1e-6, atol=1e-14)
    assert np.all(np.isfinite(table)) and table[:, 1].max() > 0


def test_blinn_texture_roughness_is_his_normalised_D3(copper, grid):
    N, V, L = random_geometry(6, 40)
    uv = np.random.default_rng(8).random((40, 2))
    c_min = 0.2
    common = dict(model="TorranceSparrow_Blinn1977", s=1.0, d=0.0, n=copper.n, k=copper.k,
                  distribution="TrowbridgeReitz1975")
    method = {"cycles_u": 3, "cycles_v": 2}
    textured = ShadingMaterial(texture=RoughnessTexture("sinusoid", c_min, 1.0, method),
                               **common)
    lights = lights_at([L[0]])
    a = shade(np.zeros_like(N), N, V, uv, textured, lights, wavelengths=grid)
    t = texture(uv[:, 0], uv[:, 1], "sinusoid", **method)
    for i in range(40):
        c3 = c_min + (1 - c_min) * t[i]  # Blinn 1977: C3 = C_min + (1 - C_min) t
        plain = ShadingMaterial(roughness=c3, **common)
        b = shade(np.zeros((1, 3)), N[i:i + 1], V[i:i + 1], uv[i:i + 1], plain, lights,
                  wavelengths=grid)
        # D3 normalised by C_min = (C_min / C3)^2 x D3(C3), whose D3(0) = 1
        assert np.allclose(a[i], (c_min / c3) ** 2 * b[0], rtol=1e-12, atol=1e-300)
    assert a[:, 1].max() > 0


def test_texture_varies_beckmann_roughness_over_uv(copper, grid):
    n = 200
    N = np.tile([0.0, 0.0, 1.0], (n, 1))
    uv = np.random.default_rng(9).random((n, 2))
    material = ShadingMaterial(n=copper.n, k=copper.k, texture=RoughnessTexture(
        "spots", 0.1, 0.5, {"cells_u": 4, "cells_v": 4, "radius": 0.4}))
    Y = shade(np.zeros((n, 3)), N, N, uv, material, lights_at([[0, 0, 1]]),
              wavelengths=grid)[:, 1]
    m = 0.1 + 0.4 * texture(uv[:, 0], uv[:, 1], "spots", cells_u=4, cells_v=4, radius=0.4)
    # at the mirror direction the paper's Beckmann D = 1 / m^2 (G = 1, F = F0): Y m^2 is constant
    assert np.ptp(m) > 0.3
    assert np.allclose(Y * m**2, (Y * m**2)[0], rtol=1e-9)


def test_shadowed_samples_get_only_the_ambient(copper, grid):
    N, V, L = random_geometry(7, 100)
    material = ShadingMaterial(n=copper.n, k=copper.k, s=0.5, d=0.5, albedo=copper.F0,
                               roughness=0.3)
    lights = lights_at([L[0]])
    ambient = Ambient(0.05)
    shadowed = np.zeros((1, 100), bool)
    shadowed[0, ::2] = True
    XYZ = shade(np.zeros_like(N), N, V, np.zeros((100, 2)), material, lights, shadowed, ambient,
                wavelengths=grid)
    ambient_XYZ = 0.05 * copper.F0 @ colour_weights(grid)  # I_ia R_a, R_a = pi R_d = F0
    assert np.allclose(XYZ[::2], ambient_XYZ, rtol=1e-12)
    # where the light is behind a sample its Y is the ambient alone, summed in another order
    assert np.all(XYZ[1::2, 1] >= ambient_XYZ[1] * (1 - 1e-12))


def test_point_light_area_gives_inverse_square_falloff(grid):
    material = ShadingMaterial(model="Lambert", convention="physical", s=0.0, d=1.0, albedo=1.0)
    light = Light(PointLight((0.0, 0.0, 2.0)), "D65", 1.0, solid_angle=None, area=0.01)
    P = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    N = np.tile([0.0, 0.0, 1.0], (2, 1))
    Y = shade(P, N, N, np.zeros((2, 2)), material, [light], wavelengths=grid)[:, 1]
    assert np.allclose(Y, [0.01 / 4 / np.pi, 0.01 / 1 / np.pi], rtol=1e-12)


def test_emission_is_added_and_needs_no_light(grid):
    XYZ_e = emission_XYZ(640.0, 0.3)
    material = ShadingMaterial(model="Lambert", s=0.0, d=0.0, emission=XYZ_e)
    out = shade(np.zeros((3, 3)), np.tile([0, 0, 1.0], (3, 1)), np.tile([0, 0, 1.0], (3, 1)),
                np.zeros((3, 2)), material, [], wavelengths=grid)
    assert np.allclose(out, XYZ_e)


def test_shade_rejects_unknown_spectral_method(grid):
    with pytest.raises(ValueError, match="known: table, brute-force"):
        shade(np.zeros((1, 3)), [[0, 0, 1]], [[0, 0, 1]], np.zeros((1, 2)),
              ShadingMaterial(model="Lambert", s=0, d=1, albedo=1), [], wavelengths=grid,
              spectral="monte-carlo")


def test_models_registry_lists_the_renderer_models():
    assert set(SHADING_MODELS) == {"CookTorrance1982", "TorranceSparrow_Blinn1977",
                                   "BlinnPhong1977", "Phong1975", "Lambert"}
    assert np.allclose(tristimulus_weights(np.arange(360, 831, 5.0)),
                       colour_weights(np.arange(360, 831, 5.0)))
