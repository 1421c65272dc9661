"""BRDF models: reciprocity, positivity, white furnace, and each text's formula written out here."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.optics.brdf import (
    BRDF_METHODS,
    ambient_reflectance_CookTorrance1982,
    brdf,
    brdf_BlinnPhong1977,
    brdf_CookTorrance1982,
    brdf_HeidrichSeidel1998,
    brdf_Ward1992,
    directional_albedo,
    intensity_CookTorrance1982,
)
from reflectance.optics.fresnel import fresnel_conductor, fresnel_dielectric_CookTorrance1982

N = np.array([0.0, 0.0, 1.0])
X, Y = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])


def direction(theta, phi=0.0):
    return np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)])


def half(L, V):
    return (L + V) / np.linalg.norm(L + V)


def beckmann_by_hand(cos_a, m):
    # Cook & Torrance 1982: D = exp(-[(tan a)/m]^2) / (m^2 cos^4 a)
    a = np.arccos(cos_a)
    return np.exp(-((np.tan(a) / m) ** 2)) / (m**2 * np.cos(a) ** 4)


def vcavity_by_hand(L, V):
    H = half(L, V)
    return min(1, 2 * (N @ H) * (N @ V) / (V @ H), 2 * (N @ H) * (N @ L) / (V @ H))


# --- models and parameters used by the property tests ----------------------------------------------

RECIPROCAL = {
    "Lambert": ("Lambert", {"rho_d": 0.7}),
    "BlinnPhong_AkenineMoller2008": ("BlinnPhong_AkenineMoller2008", {"c_diff": 0.3, "c_spec": 0.5, "m": 40.0}),
    "Blinn1977 MgO": (  # Blinn Fig. 7b: p_s = .667, p_d = .333, n = 1.8, c3 = .35
        "TorranceSparrow_Blinn1977",
        {"F": lambda c: fresnel_dielectric_CookTorrance1982(c, 1.8), "p_d": 0.333, "p_s": 0.667, "c3": 0.35},
    ),
    "CookTorrance paper plastic": (  # C&T Fig. 6a: s = 0.1, d = 0.9, Beckmann m = 0.15
        "CookTorrance1982", {"n": 1.5, "s": 0.1, "d": 0.9, "R_d": 0.2, "m": 0.15},
    ),
    "CookTorrance physical Smith": (
        "CookTorrance1982",
        {"n": 1.5, "m": 0.3, "convention": "physical", "shadowing_method": "Smith_Beckmann_Walter2007"},
    ),
    "CookTorrance copper two slopes, spectral": (  # C&T Fig. 6b: m1 = .4, w1 = .4, m2 = .2, w2 = .6
        "CookTorrance1982",
        {"n": np.array([0.27, 0.68, 1.1]), "k": np.array([3.4, 2.6, 2.5]), "distribution": "mixture",
         "lobes": [(0.4, 0.4), (0.6, 0.2)]},
    ),
    "Ward anisotropic": ("Ward1992", {"rho_s": 0.3, "rho_d": 0.1, "alpha_x": 0.1, "alpha_y": 0.3, "X": X, "Y": Y}),
}

NON_RECIPROCAL = {
    "Phong1975": ("Phong1975", {"p_d": 0.6, "p_s": 0.4, "c1": 50.0}),
    "BlinnPhong1977": ("BlinnPhong1977", {"p_d": 0.6, "p_s": 0.4, "c1": 50.0}),
    "HeidrichSeidel1998": ("HeidrichSeidel1998", {"s": 30.0, "k_d": 0.2, "k_s": 0.8, "T": X}),
    "HeidrichSeidel1998 as printed": (
        "HeidrichSeidel1998", {"s": 30.0, "k_d": 0.2, "k_s": 0.8, "T": X, "form": "as_printed"}
    ),
}

above = st.tuples(st.floats(0.0, 1.5707963), st.floats(0.0, 2 * np.pi)).map(lambda a: direction(*a))


@given(above, above, st.sampled_from(sorted(RECIPROCAL)))
@settings(max_examples=300, deadline=None)
def test_reciprocity(L, V, name):
    method, params = RECIPROCAL[name]
    forward, backward = brdf(L, V, N, method, **params), brdf(V, L, N, method, **params)
    np.testing.assert_allclose(forward, backward, rtol=1e-10, atol=0)
    assert np.all(forward >= 0)


@pytest.mark.parametrize("name", sorted(NON_RECIPROCAL))
def test_printed_intensity_models_are_not_reciprocal(name):
    """Phong's and Blinn's "s" lack the N.L of the diffuse term (the lecture: the Blinn-Phong
    "specular term is not modulated by cos"), and Heidrich-Seidel's k_spec likewise: as BRDFs,
    f(L, V) != f(V, L) where N.L != N.V."""
    method, params = NON_RECIPROCAL[name]
    L, V = direction(0.6, 0.0), direction(0.7, np.pi)  # near the highlight, N.L != N.V
    if name.startswith("Heidrich"):
        L, V = (direction(0.8, 5.9), direction(1.2, 0.0)) if "printed" in name else (direction(0.5, 0.3), direction(1.0, 2.9))
    forward, backward = brdf(L, V, N, method, **params), brdf(V, L, N, method, **params)
    assert forward > 0 and backward > 0
    # each is (diffuse + specular) / (N.L) of its own light: the specular term S^e is symmetric
    # in L and V (Phong: R.V = (mirror of V).L; Blinn: N.H; Heidrich-Seidel: V.R on the cone),
    # Heidrich-Seidel's diffuse sqrt(1 - (L.T)^2) is not; Phong's and Blinn's diffuse p_d
    # multiplies N.L, so it cancels
    NL, NV = N @ L, N @ V
    if method == "Phong1975":
        S, k_s, e, diffuse = (2 * N * NL - L) @ V, params["p_s"], params["c1"], 0.0
    elif method == "BlinnPhong1977":
        S, k_s, e, diffuse = N @ half(L, V), params["p_s"], params["c1"], 0.0
    else:
        LT, VT = L @ params["T"], V @ params["T"]
        S = np.sqrt(1 - LT**2) * np.sqrt(1 - VT**2) - LT * VT
        k_s, e = params["k_s"], params["s"]
        diffuse = params["k_d"] * (np.sqrt(1 - LT**2) / NL - np.sqrt(1 - VT**2) / NV)
    expected = diffuse + k_s * max(S, 0.0) ** e * (1 / NL - 1 / NV)
    assert abs(expected) > 1e-3 * forward  # (not reciprocal)
    assert forward - backward == pytest.approx(expected, rel=1e-9)


def test_blinn_phong_times_NL_is_the_printed_intensity():
    # Blinn 1977: i = p_a + d p_d + s p_s with d = N.L and s = (N.H)^c1.
    L, V = direction(0.4, 0.0), direction(0.9, 2.5)
    NL, NH = L @ N, N @ half(L, V)
    i = 0.1 + NL * 0.6 + NH**50 * 0.4
    R = brdf(L, V, N, "BlinnPhong1977", p_d=0.6, p_s=0.4, c1=50)
    assert intensity_CookTorrance1982([R], [NL], 1.0, 1.0, I_ia=1.0, R_a=0.1) == pytest.approx(i, rel=1e-14)


# --- robustness at normal and grazing angles ------------------------------------------------------

ANGLES = [0.0, 1e-8, 0.3, 1.2, np.pi / 2 - 1e-9, np.pi / 2, np.pi / 2 + 0.1]


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("name", sorted(RECIPROCAL) + sorted(NON_RECIPROCAL))
def test_finite_and_non_negative_at_grazing_and_normal(name):
    method, params = {**RECIPROCAL, **NON_RECIPROCAL}[name]
    directions = np.array([direction(t, p) for t in ANGLES for p in (0.0, 1.0, np.pi)])
    L = directions[:, None, :]
    V = directions[None, :, :]
    f = brdf(L, V, N, method, **params)
    assert np.all(np.isfinite(f)) and np.all(f >= 0)
    below = (L[..., 2] <= 0) | (V[..., 2] <= 0)
    if np.ndim(f) > below.ndim:
        below = below[..., None]
    assert np.all(np.where(below, f, 0) == 0)


@pytest.mark.filterwarnings("error")
def test_cosine_level_functions_at_exact_zeros():
    zeros = np.array([0.0, 1e-300, 1e-20, 1.0])
    NL, NV = np.meshgrid(zeros, zeros, indexing="ij")
    for NH, VH in [(0.0, 0.0), (1e-300, 1e-300), (1.0, 1.0), (0.7, 1e-300)]:
        for convention in ("paper", "physical"):
            R = brdf_CookTorrance1982(NL, NV, NH, VH, 1.0, m=0.2, convention=convention)
            assert np.all(np.isfinite(R)) and np.all(R >= 0)
        assert np.all(np.isfinite(brdf_Ward1992(NL, NV, NH, 0.0, 0.0, 1.0, 0.1, 0.1)))


# --- white furnace ----------------------------------------------------------------------------------

INCIDENCES = [0, 30, 60, 80, 89, 89.9]


@pytest.mark.parametrize("m", [0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.5])
def test_white_furnace_physical_cook_torrance(m):
    """With F = 1 the normalised Cook-Torrance albedo is <= 1 at every incidence (single scattering
    with the V-cavity G loses energy to masking), = 1 for smooth surfaces away from grazing.
    The paper convention is 4x larger (Beckmann without 1/pi, R_s over pi): reported, not bounded."""
    rows = []
    for degrees in INCIDENCES:
        L = direction(np.radians(degrees))
        physical = directional_albedo(L, "CookTorrance1982", F=1.0, m=m, convention="physical")
        paper = directional_albedo(L, "CookTorrance1982", F=1.0, m=m, convention="paper")
        smith = directional_albedo(
            L, "CookTorrance1982", F=1.0, m=m, convention="physical", shadowing_method="Smith_Beckmann_Walter2007"
        )
        rows.append((degrees, physical, smith, paper, paper / physical))
        assert physical <= 1 + 1e-9
        assert smith <= 1 + 1e-9
        assert paper / physical == pytest.approx(4, rel=1e-12)
        if m <= 0.1 and degrees <= 60:
            assert physical == pytest.approx(1, abs=1e-3)
    print(f"\nwhite furnace, Beckmann m = {m}: theta_i, V-cavity physical, Smith physical, paper, paper/physical")
    for row in rows:
        print("  {:5.1f}  {:.5f}  {:.5f}  {:.5f}  {:.3f}".format(*row))


def test_albedo_integrator_against_direct_quadrature():
    """directional_albedo integrates over half vectors; redo it over outgoing directions with a
    tensor Gauss-Legendre rule in cos(theta_o) and the midpoint rule in phi_o."""
    x, w = np.polynomial.legendre.leggauss(400)
    mu, w_mu = 0.5 * (x + 1), 0.5 * w
    phi = (np.arange(512) + 0.5) * 2 * np.pi / 512
    s = np.sqrt(1 - mu**2)
    V = np.stack([s[:, None] * np.cos(phi), s[:, None] * np.sin(phi), np.broadcast_to(mu[:, None], (400, 512))], -1)
    for method, params in [
        ("CookTorrance1982", {"F": 1.0, "m": 0.4, "convention": "physical"}),
        ("Ward1992", {"rho_s": 1.0, "alpha_x": 0.3, "alpha_y": 0.3}),
        ("Lambert", {"rho_d": 1.0}),
    ]:
        L = direction(np.radians(30))
        f = brdf(L, V, N, method, **params)
        direct = np.sum(f * mu[:, None] * w_mu[:, None]) * 2 * np.pi / 512
        assert directional_albedo(L, method, **params) == pytest.approx(direct, abs=2e-4)


@pytest.mark.parametrize("alpha", [0.02, 0.05])
def test_ward_normalisation(alpha):
    # The 1/(4 pi ax ay) constant makes the albedo at normal incidence close to rho_s for small alpha.
    assert directional_albedo(N, "Ward1992", rho_s=1.0, alpha_x=alpha, alpha_y=alpha) == pytest.approx(1, abs=0.01)
    assert directional_albedo(
        N, "Ward1992", rho_s=1.0, alpha_x=alpha, alpha_y=2 * alpha, X=X, Y=Y
    ) == pytest.approx(1, abs=0.02)


@pytest.mark.parametrize("m", [8.0, 50.0, 200.0])
def test_lecture_normalised_blinn_phong(m):
    """(m + 8)/(8 pi) nearly normalises the lobe: albedo at normal incidence within 8 % of 1 (it
    reaches 1.075 at m = 8)."""
    assert 0.99 < directional_albedo(N, "BlinnPhong_AkenineMoller2008", c_spec=1.0, m=m) < 1.08


@pytest.mark.parametrize("m", [20.0, 50.0])  # (not m = 8, where (m+8)/8 = (m+8)/m)
def test_errata_lecture_blinn_phong_factor_is_m_plus_8_over_8(m):
    """The lecture: Blinn-Phong L_o = (cos t_i c_diff + cos^m t_h c_spec) B_L, B_L = E_L / pi,
    "lacks the (m+8)/m factor and specular term is not modulated by cos". Against its normalised
    L_o = (c_diff/pi + (m+8)/(8 pi) cos^m t_h c_spec) E_L cos t_i the specular term lacks
    (m+8)/8 cos t_i: the printed (m+8)/m is a misprint."""
    E_L = 1.0
    for L, V in [(direction(0.3), direction(0.5, np.pi)), (direction(1.0), direction(0.2, 2.0))]:
        NL, NH = L @ N, N @ half(L, V)
        blinn_phong_specular = NH**m * 1.0 * E_L / np.pi
        normalised_specular = NL * E_L * (
            brdf(L, V, N, "BlinnPhong_AkenineMoller2008", c_diff=0.0, c_spec=1.0, m=m)
        )
        ratio = normalised_specular / blinn_phong_specular
        assert ratio == pytest.approx((m + 8) / 8 * NL, rel=1e-12)
        assert ratio / ((m + 8) / m * NL) == pytest.approx(m / 8, rel=1e-12)  # the misprint's


# --- each text's formula written out --------------------------------------------------------------

def test_cook_torrance_at_normal_incidence():
    # L = V = N: alpha = theta = 0, G = 1, Beckmann D(0) = 1/m^2.
    m, F0, R_d = 0.3, 0.9, 0.2
    assert brdf(N, N, N, "CookTorrance1982", F=F0, m=m) == pytest.approx(F0 / (np.pi * m**2), rel=1e-14)
    assert brdf(N, N, N, "CookTorrance1982", F=F0, m=m, convention="physical") == pytest.approx(
        F0 / (4 * np.pi * m**2), rel=1e-14
    )
    R = brdf(N, N, N, "CookTorrance1982", F=F0, m=m, s=0.1, d=0.9, R_d=R_d)
    assert R == pytest.approx(0.1 * F0 / (np.pi * m**2) + 0.9 * R_d, rel=1e-14)


@pytest.mark.parametrize("geometry", [(0.3, 0.0, 0.7, 2.8), (1.3, 0.5, 0.2, 3.5), (1.5, 0.0, 1.5, np.pi)])
def test_cook_torrance_against_the_printed_equations(geometry):
    L, V = direction(*geometry[:2]), direction(*geometry[2:])
    H = half(L, V)
    n, m = 1.5, 0.35
    F = fresnel_dielectric_CookTorrance1982(V @ H, n)
    R_s = F / np.pi * beckmann_by_hand(N @ H, m) * vcavity_by_hand(L, V) / ((N @ L) * (N @ V))
    assert brdf(L, V, N, "CookTorrance1982", n=n, fresnel_method="exact", m=m) == pytest.approx(R_s, rel=1e-10)
    # the article: D F G / (4 (V.N)(N.L)) with its Beckmann (with 1/pi) is the physical form
    article = beckmann_by_hand(N @ H, m) / np.pi * F * vcavity_by_hand(L, V) / (4 * (V @ N) * (N @ L))
    assert brdf(L, V, N, "CookTorrance1982", F=F, m=m, convention="physical") == pytest.approx(article, rel=1e-10)
    assert R_s / article == pytest.approx(4, rel=1e-10)


def test_errata_lecture_specular_term_is_blinns_not_cook_torrances():
    """The lecture attributes R_s = DGF/(N.V) to Cook & Torrance; that is Blinn's s. Cook & Torrance's
    R_s = (F/pi) D G / ((N.L)(N.V)): the two differ by pi (N.L), which depends on the light."""
    m = 0.3
    ratios = []
    for L, V in [(direction(0.2), direction(0.5, np.pi)), (direction(1.2), direction(0.5, np.pi))]:
        H = half(L, V)
        D, G, F = beckmann_by_hand(N @ H, m), vcavity_by_hand(L, V), 0.5
        lecture = D * G * F / (N @ V)
        ratios.append(lecture / brdf(L, V, N, "CookTorrance1982", F=F, m=m))
        assert ratios[-1] == pytest.approx(np.pi * (N @ L), rel=1e-12)
    assert ratios[0] / ratios[1] == pytest.approx(np.cos(0.2) / np.cos(1.2), rel=1e-12)


def test_errata_lecture_specular_term_with_its_own_D_is_pi_NL_times_the_normalised_brdf():
    """With the lecture's own D, exp(-(tan d/m)^2) / (4 m^2 cos^4 d), its DGF/(N.V) is pi (N.L)
    times the normalised microfacet BRDF D' F G / (4 (N.L)(N.V)), D' = exp(..)/(pi m^2 cos^4 d)
    (the integral of D' cos d over the hemisphere is 1, checked here by quadrature): a radiance per
    E_L/pi, consistent, only misnamed; and pi (N.L)/4 times Cook & Torrance's R_s."""
    from scipy.integrate import quad

    from reflectance.papers.errata import ERRATA

    m = 0.3
    normalised = lambda c: beckmann_by_hand(c, m) / np.pi  # noqa: E731
    total, _ = quad(lambda a: normalised(np.cos(a)) * np.cos(a) * np.sin(a) * 2 * np.pi, 0, np.pi / 2)
    assert total == pytest.approx(1.0, rel=1e-6)
    for L, V in [(direction(0.2), direction(0.5, np.pi)), (direction(1.2), direction(0.9, np.pi))]:
        H = half(L, V)
        G, F = vcavity_by_hand(L, V), 0.7
        lecture = beckmann_by_hand(N @ H, m) / 4 * G * F / (N @ V)
        assert lecture == pytest.approx(np.pi * (N @ L) * normalised(N @ H) * F * G
                                        / (4 * (N @ L) * (N @ V)), rel=1e-12)
        assert lecture / brdf(L, V, N, "CookTorrance1982", F=F, m=m) == pytest.approx(
            np.pi * (N @ L) / 4, rel=1e-12)
    # the errata row's number: at the mirror, incidence 60 degrees, F = 1
    result = ERRATA["lecture-specular-term"](theta_deg=60.0, m=m)
    mu = np.cos(np.radians(60.0))
    # at the mirror N.H = 1 and E.H = N.E, so G_b = G_c = 2 and G = 1; D = 1/(4 m^2)
    assert result.numbers["own_D"] == pytest.approx(1 / (4 * m**2) / mu, rel=1e-12)


def test_blinn_torrance_sparrow_against_the_printed_equations():
    # Blinn Fig. 7a aluminium: p_s = .4, p_d = .6, n = 200, c3 = .5; s = D3 G F / (N.E)
    L, E = direction(1.2, 0.0), direction(0.4, np.pi)
    H = half(L, E)
    c3, F = 0.5, 0.97
    D3 = (c3**2 / ((N @ H) ** 2 * (c3**2 - 1) + 1)) ** 2
    s = D3 * vcavity_by_hand(L, E) * F / (N @ E)
    i = (N @ L) * 0.6 + s * 0.4  # i - p_a
    f = brdf(L, E, N, "TorranceSparrow_Blinn1977", F=F, p_d=0.6, p_s=0.4, c3=c3)
    assert (N @ L) * f == pytest.approx(i, rel=1e-12)


def test_ward_against_the_article():
    rng = np.random.default_rng(92)
    for _ in range(20):
        L, V = direction(rng.uniform(0, 1.5), rng.uniform(0, 6.3)), direction(rng.uniform(0, 1.5), rng.uniform(0, 6.3))
        H = half(L, V)
        ax, ay, rho_s = 0.15, 0.4, 0.8
        k_spec = (
            rho_s / np.sqrt((N @ L) * (N @ V)) * (N @ L) / (4 * np.pi * ax * ay)
            * np.exp(-2 * ((H @ X / ax) ** 2 + (H @ Y / ay) ** 2) / (1 + H @ N))
        )
        f = brdf(L, V, N, "Ward1992", rho_s=rho_s, alpha_x=ax, alpha_y=ay, X=X, Y=Y)
        assert (N @ L) * f == pytest.approx(k_spec, rel=1e-12)
        iso = brdf(L, V, N, "Ward1992", rho_s=rho_s, alpha_x=ax, alpha_y=ax)
        assert iso == pytest.approx(brdf(L, V, N, "Ward1992", rho_s=rho_s, alpha_x=ax, alpha_y=ax, X=Y, Y=-X), rel=1e-12)


def article_heidrich_seidel(L, V, Nv, D):
    """The article's Heidrich-Seidel vectors, built as printed (T with the corrected denominator)."""
    T = D - (D @ Nv) * Nv
    T /= np.linalg.norm(T)
    P = L - (L @ T) * T
    P /= np.linalg.norm(P)
    R = -L + 2 * (L @ T) * T
    R /= np.linalg.norm(R)
    return T, P, R


def test_heidrich_seidel_optimised_form():
    D = np.array([1.0, 0.2, 0.3])
    for L, V in [(direction(0.6, 0.4), direction(1.0, 2.0)), (direction(1.1, 2.0), direction(0.2, 4.0))]:
        T, P, _ = article_heidrich_seidel(L, V, N, D)
        k_diff = L @ P
        line2 = np.sqrt(1 - (L @ T) ** 2) * np.sqrt(1 - (V @ T) ** 2) - (L @ T) * (V @ T)
        expected = 0.3 * k_diff + 0.7 * max(line2, 0) ** 20
        f = brdf(L, V, N, "HeidrichSeidel1998", s=20.0, k_d=0.3, k_s=0.7, T=D)
        assert (N @ L) * f == pytest.approx(expected, rel=1e-12)
    # on the cone of mirror directions (V.T = -L.T) the highlight is 1
    L = direction(0.7, 0.5)
    T = X
    V = -(L @ T) * T + np.sqrt(1 - (L @ T) ** 2) * np.array([0.0, 0.6, 0.8])
    assert (N @ L) * brdf(L, V, N, "HeidrichSeidel1998", s=50.0, T=T) == pytest.approx(1, rel=1e-12)


def test_errata_heidrich_seidel_article():
    """Three slips in the article's Heidrich-Seidel section:

    1. its R = -L + 2 (L.T) T (reflection of -L in the plane normal to T) is not the fibre's mirror
       direction: where the optimised line gives V.R = 1 (V on the mirror cone, V.T = -L.T), the
       printed R gives V.R = -1 and the condition 0 < R.V makes the highlight vanish;
    2. "(-cos(a + b))^s = [cos a cos b - sin a sin b]^s" drops the minus sign;
    3. T = (D - (D.N) N) / |D - (D.T) N| has D.T for D.N in the denominator: not a unit vector.
    """
    # 1. V: the mirror image of L in the fibre normal P that lies in the plane of L and T
    L = direction(0.7, 0.5)
    T = X
    V = -(L @ T) * T + (L - (L @ T) * T)
    _, _, R = article_heidrich_seidel(L, V, N, T)
    assert V @ R == pytest.approx(-1, abs=1e-12)
    assert brdf(L, V, N, "HeidrichSeidel1998", s=50.0, T=T, form="as_printed") == 0
    assert brdf(L, V, N, "HeidrichSeidel1998", s=50.0, T=T) > 0
    # 2. with a, b the angles of L and V from T
    a, b = np.arccos(L @ T), np.arccos(V @ T)
    line2 = np.sqrt(1 - (L @ T) ** 2) * np.sqrt(1 - (V @ T) ** 2) - (L @ T) * (V @ T)
    assert line2 == pytest.approx(-np.cos(a + b), abs=1e-12)
    assert np.cos(a) * np.cos(b) - np.sin(a) * np.sin(b) == pytest.approx(-line2, abs=1e-12)
    assert line2 == pytest.approx(1, abs=1e-12)  # so the printed final line would give (-1)^s
    # 3.
    D = np.array([0.6, 0.0, 0.8])
    T_right = (D - (D @ N) * N) / np.linalg.norm(D - (D @ N) * N)
    T_printed = (D - (D @ N) * N) / np.linalg.norm(D - (D @ T_right) * N)
    assert np.linalg.norm(T_right) == pytest.approx(1)
    # D - (D.T) N = (0.6, 0, 0.2): T_printed = (0.6, 0, 0) / sqrt(0.4), of length 3 / sqrt(10)
    assert np.linalg.norm(T_printed) == pytest.approx(3 / np.sqrt(10), rel=1e-12)


# --- intensity, ambient, vector-level dispatcher ------------------------------------------------------

def test_intensity_cook_torrance_two_lights_and_ambient():
    # C&T: I_r = I_ia R_a + sum_l I_il (N.L_l) d omega_il R_l; Fig. 6: d omega = 0.0001 and 0.0002,
    # I_ia = 0.01 I_i, R_a = pi R_d.
    R_d = 0.05
    R = np.array([3.0, 2.0])
    NL = np.array([0.8, 0.5])
    I_r = intensity_CookTorrance1982(R, NL, 1.0, np.array([1e-4, 2e-4]), I_ia=0.01, R_a=ambient_reflectance_CookTorrance1982(R_d))
    assert I_r == pytest.approx(0.01 * np.pi * R_d + 3.0 * 0.8 * 1e-4 + 2.0 * 0.5 * 2e-4, rel=1e-14)
    # spectral: lights on axis 0, wavelengths last
    I_l = np.array([[1.0, 0.5, 0.2], [1.0, 0.5, 0.2]])
    assert intensity_CookTorrance1982(R[:, None], NL[:, None], I_l, 1e-4).shape == (3,)


def test_vector_level_matches_cosine_level_and_normalises_inputs():
    L, V = direction(0.5, 0.3), direction(0.9, 2.0)
    H = half(L, V)
    expected = brdf_BlinnPhong1977(L @ N, V @ N, H @ N, p_d=0.5, p_s=0.5, c1=20)
    assert brdf(3 * L, 0.5 * V, 2 * N, "BlinnPhong1977", p_d=0.5, p_s=0.5, c1=20) == pytest.approx(expected, rel=1e-14)
    expected = brdf_HeidrichSeidel1998(L @ N, V @ N, L @ X, V @ X, L @ V, s=5.0)
    assert brdf(L, V, N, "HeidrichSeidel1998", s=5.0, T=X + 0.3 * N) == pytest.approx(expected, rel=1e-14)


def test_spectral_fresnel_from_n_k():
    n, k = np.array([0.27, 0.68, 1.1, 1.2]), np.array([3.4, 2.6, 2.5, 2.4])
    rng = np.random.default_rng(0)
    L = np.array([direction(rng.uniform(0, 1.5), rng.uniform(0, 6)) for _ in range(6)]).reshape(2, 3, 3)
    V = direction(0.4, 1.0)
    R = brdf(L, V, N, "CookTorrance1982", n=n, k=k, m=0.2)
    assert R.shape == (2, 3, 4)
    for index in np.ndindex(2, 3):
        Li = L[index]
        H = half(Li, V)
        expected = (
            fresnel_conductor(V @ H, n, k) / np.pi * beckmann_by_hand(N @ H, 0.2) * vcavity_by_hand(Li, V)
            / ((N @ Li) * (N @ V))
        )
        np.testing.assert_allclose(R[index], expected, rtol=1e-10)
    # albedo keeps the spectral axis
    assert directional_albedo(N, "CookTorrance1982", n=n, k=k, m=0.2).shape == (4,)


def test_errors_name_the_problem():
    L, V = direction(0.3), direction(0.5, 2.0)
    with pytest.raises(ValueError, match="CookTorrance1982"):
        brdf(L, V, N, "Cook-Torrance")
    with pytest.raises(ValueError, match="'L'"):
        brdf(np.zeros(3), V, N, "Lambert")
    with pytest.raises(ValueError, match="X and Y"):
        brdf(L, V, N, "Ward1992", alpha_x=0.1, alpha_y=0.2)
    with pytest.raises(ValueError, match="fibre direction T"):
        brdf(L, V, N, "HeidrichSeidel1998")
    with pytest.raises(ValueError, match="Fresnel"):
        brdf(L, V, N, "CookTorrance1982", m=0.3)
    with pytest.raises(ValueError, match="s \\+ d = 1"):
        brdf(L, V, N, "CookTorrance1982", F=1.0, m=0.3, s=0.5, d=0.6)
    with pytest.raises(ValueError, match="convention='paper'"):
        brdf(L, V, N, "CookTorrance1982", F=1.0, distribution="TrowbridgeReitz_texture_Blinn1977",
             c3=0.4, c_min=0.2, convention="physical")
    with pytest.raises(ValueError, match="Beckmann"):
        brdf(L, V, N, "CookTorrance1982", F=1.0, distribution="TrowbridgeReitz1975", c3=0.4,
             shadowing_method="Smith_Beckmann_Walter2007")
    with pytest.raises(ValueError, match="Bad parameters"):
        brdf(L, V, N, "Lambert", m=0.3)
    with pytest.raises(ValueError, match="no Fresnel term"):
        brdf(L, V, N, "Lambert", n=1.5)


@pytest.mark.filterwarnings("error")
def test_nan_inputs_do_not_raise():
    nan = np.array([np.nan, 0.5])
    for f in (
        brdf_CookTorrance1982(nan, 0.5, 0.9, 0.8, 1.0, m=0.3),
        brdf_BlinnPhong1977(0.5, nan, 0.9),
        brdf_Ward1992(0.5, 0.5, nan, 0.1, 0.1),
        brdf_HeidrichSeidel1998(0.5, 0.5, nan, 0.2, 0.1),
    ):
        assert f.shape == (2,) and np.isfinite(f[1])


def test_registry_is_complete():
    assert set(BRDF_METHODS) == {
        "Lambert", "Phong1975", "BlinnPhong1977", "BlinnPhong_AkenineMoller2008", "TorranceSparrow_Blinn1977",
        "CookTorrance1982", "Ward1992", "HeidrichSeidel1998", "LommelSeeliger", "Hapke1981",
    }


def test_lommel_seeliger_reciprocal_and_its_albedo():
    """Lommel-Seeliger (Hapke 1981): f = w / (4 pi (mu0 + mu)); reciprocal; at normal incidence its
    directional albedo is (w / 2)(1 - ln 2), written out from the integral of mu / (1 + mu)."""
    from scipy.integrate import quad

    from reflectance.optics.brdf import brdf_LommelSeeliger

    rng = np.random.default_rng(7)
    mu0, mu = rng.uniform(0.01, 1, 50), rng.uniform(0.01, 1, 50)
    np.testing.assert_allclose(brdf_LommelSeeliger(mu0, mu, 0.7), brdf_LommelSeeliger(mu, mu0, 0.7))
    np.testing.assert_allclose(brdf_LommelSeeliger(mu0, mu, 0.7), 0.7 / (4 * np.pi * (mu0 + mu)))
    assert brdf_LommelSeeliger(-0.1, 0.5) == 0 and brdf_LommelSeeliger(0.5, -0.1) == 0
    albedo = quad(lambda m: brdf_LommelSeeliger(1.0, m, 0.9) * m * 2 * np.pi, 0, 1)[0]
    assert albedo == pytest.approx(0.45 * (1 - np.log(2)), rel=1e-9)


def test_hapke_opposition_effect_back_towards_the_light():
    """Hapke 1981 with Hapke 1986's B(g) = B0 / (1 + tan(g/2) / h) and Henyey-Greenstein p(g),
    written out here from the phase angle itself (arccos of L.V): Lommel-Seeliger without the
    opposition effect, the isotropic phase function and multiple scattering; 1 + B0 times brighter
    looking back along the light; B = B0 / 2 where tan(g/2) = h; reciprocal; the H function of
    Hapke 1981 (1 + 2x) / (1 + 2x sqrt(1 - w))."""
    from reflectance.optics.brdf import brdf_Hapke1981, brdf_LommelSeeliger

    rng = np.random.default_rng(11)
    mu0, mu, LV = rng.uniform(0.05, 1, 40), rng.uniform(0.05, 1, 40), rng.uniform(-0.9, 1, 40)
    plain = dict(B0=0.0, xi=0.0, multiple_scattering=False)
    np.testing.assert_allclose(brdf_Hapke1981(mu0, mu, LV, 0.6, **plain), brdf_LommelSeeliger(mu0, mu, 0.6))
    np.testing.assert_allclose(brdf_Hapke1981(mu0, mu, LV, 0.6, B0=0.8, xi=-0.3),
                               brdf_Hapke1981(mu, mu0, LV, 0.6, B0=0.8, xi=-0.3))
    B0, h, w, xi = 0.9, 0.05, 0.7, -0.25
    g = np.arccos(LV)
    B = B0 / (1 + np.tan(g / 2) / h)
    p = (1 - xi**2) / (1 + 2 * xi * np.cos(g) + xi**2) ** 1.5
    H = lambda x: (1 + 2 * x) / (1 + 2 * x * np.sqrt(1 - w))  # noqa: E731
    by_hand = w / (4 * np.pi * (mu0 + mu)) * ((1 + B) * p + H(mu0) * H(mu) - 1)
    np.testing.assert_allclose(brdf_Hapke1981(mu0, mu, LV, w, B0=B0, h=h, xi=xi), by_hand, rtol=1e-12)
    single = dict(xi=0.0, multiple_scattering=False, h=h)
    ls = brdf_LommelSeeliger(0.5, 0.5, w)
    assert brdf_Hapke1981(0.5, 0.5, 1.0, w, B0=B0, **single) == pytest.approx((1 + B0) * ls)
    half = np.cos(2 * np.arctan(h))  # tan(g/2) = h
    assert brdf_Hapke1981(0.5, 0.5, half, w, B0=B0, **single) == pytest.approx((1 + B0 / 2) * ls)
    assert brdf_Hapke1981(-0.1, 0.5, 0.2, w) == 0 and brdf_Hapke1981(0.5, -0.1, 0.2, w) == 0
    with pytest.raises(ValueError, match="h > 0"):
        brdf_Hapke1981(0.5, 0.5, 0.5, w, h=0.0)
