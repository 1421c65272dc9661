"""The errata table (workflow/report/errata.yaml, text only; reflectance.papers.errata, one function
per erratum), the symbol table of Cook & Torrance 1982 Fig. 1 (workflow/report/ct82_symbols.csv),
and the errata that no library test shows: the article's worked Phong example, Blinn's triangle
and projection, the lecture's Gaussian, Beckmann D and glare term."""

import ast
import re

import numpy as np
import pandas as pd
import pytest
import yaml

from reflectance.optics.brdf import brdf
from reflectance.optics.microfacet import distribution_Gaussian_CookTorrance1982, distribution_TorranceSparrow1967
from reflectance.papers.errata import ERRATA, TEXT_KEYS, errata_table
from reflectance.papers.vgroove import simulate_vgroove

N_Z = np.array([0.0, 0.0, 1.0])


def direction(theta, phi=0.0):
    return np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)])


@pytest.fixture(scope="module")
def errata(root):
    return yaml.safe_load((root / "workflow" / "report" / "errata.yaml").read_text())


@pytest.fixture(scope="module")
def table(root):
    config = yaml.safe_load((root / "config.yaml").read_text())["figures"]["errata"]
    settings = {k: v for k, v in config.items() if k != "rows"}
    return errata_table(root / config["rows"], settings)


def node_names(path):
    """Node ids of the tests in a file: ``name`` and ``Class::name``."""
    tree = ast.parse(path.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name.startswith("test"):
            names.add(node.name)
        elif isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
            names |= {f"{node.name}::{f.name}" for f in node.body
                      if isinstance(f, ast.FunctionDef) and f.name.startswith("test")}
    return names




# --- the errata table ---------------------------------------------------------------------------

def test_every_cited_test_exists(root, errata):
    for row in errata["rows"]:
        path, _, name = row["test"].partition("::")
        assert (root / path).is_file(), row["test"]
        assert name in node_names(root / path), f"{row['test']} cited in errata.yaml does not exist"


def test_rows_are_complete(errata):
    for row in errata["rows"]:
        assert set(row) == set(TEXT_KEYS), row.get("id")
        assert all(isinstance(row[k], str) for k in TEXT_KEYS), row["id"]
        assert row["text"] in errata["texts"]
    assert [row["id"] for row in errata["rows"]] == list(dict.fromkeys(r["id"] for r in errata["rows"]))
    # every text is represented, and every registered erratum has its row
    assert {row["text"] for row in errata["rows"]} == set(errata["texts"])
    assert {row["id"] for row in errata["rows"]} == set(ERRATA)


def test_table_columns_and_finite_values(table):
    assert list(table.columns) == ["text", "kind", "location", "printed", "correct", "consequence", "value", "test"]
    assert np.all(np.isfinite(table.value.astype(float)))
    assert not table.consequence.str.contains(r"\{").any()  # every field was formatted


def value(table, location):
    rows = table[table.location == location]
    assert len(rows) == 1, location
    return float(rows.value.iloc[0])


def test_consequences_against_hand_values(table):
    """The computed headline numbers against values worked out by hand."""
    assert value(table, "Computational considerations: F in terms of g and c") == pytest.approx(2.0, rel=1e-12)
    # slide at c = 1, g = n = 1.5: 0.5 (0.5/2.5)^2 (1 + 1.5^2 / 0.5^2) = 0.2 against 0.04
    assert value(table, "Slide 'Fresnel Reflectance'") == pytest.approx(5.0, rel=1e-12)
    assert value(table, "Directional distribution: R_s and the Beckmann D; article 'Cook-Torrance model'") == (
        pytest.approx(4.0, rel=1e-9))
    assert value(table, "Slide 'Shading Equation'") == pytest.approx(50 / 8, rel=1e-12)
    assert value(table, "Slide 'Glare Term'") == pytest.approx(2.0, rel=1e-12)
    assert value(table, "Computational considerations: division-free G/(N.E), last branch") == (
        pytest.approx(0.6**2, rel=1e-12))
    assert value(table, "Phong distribution: worked example") == pytest.approx(
        -(0.6 * np.sqrt(3) / 2 + 0.4) ** 3, rel=1e-12)
    assert value(table, "Phong distribution: normalising H") == pytest.approx(np.hypot(0.133, 0.65), rel=1e-12)
    assert value(table, "Heidrich-Seidel: fibre direction T") == pytest.approx(0.6 / np.hypot(0.6, 0.2), rel=1e-12)
    assert value(table, "Heidrich-Seidel: optimisation of k_spec, last steps") == -1.0
    assert value(table, "Torrance-Sparrow model, derivation of G_b (Fig. 4)") > 1.0


# --- C&T 1982 Fig. 1: the symbol table ------------------------------------------------------------

# Cook & Torrance 1982, Fig. 1 "Summary of symbols", in the paper's order.
FIG1_SYMBOLS = ("alpha", "theta", "lambda", "D", "d", "d omega_i", "E_i", "F", "f", "G", "H", "I_i",
                "I_ia", "I_r", "I_ra", "k", "L", "m", "N", "n", "R_a", "R", "R_d", "R_s", "s", "V", "w")


def defined_names(path):
    """Top-level functions and classes of a module's source, each with its parameters (a class's
    are its annotated fields), read statically: the names of a data file are never imported."""
    names = {}
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            if isinstance(node, ast.FunctionDef):
                a = node.args
                params = [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs]
            else:
                params = [f.target.id for f in node.body if isinstance(f, ast.AnnAssign)]
            names[node.name] = set(params)
    return names


def resolve(root, entry):
    """``module.name`` or ``module.name(argument)`` of the symbols table, looked up in the source
    file of the module: (parameters of the name, argument or None)."""
    match = re.fullmatch(r"reflectance((?:\.\w+)+?)\.(\w+)(?:\((\w+)\))?", entry)
    assert match, f"malformed code name {entry!r}"
    module, name, argument = match.groups()
    path = root / "workflow" / "reflectance" / (module.strip(".").replace(".", "/") + ".py")
    assert path.is_file(), f"{entry}: no module {path}"
    names = defined_names(path)
    assert name in names, f"{entry}: {path} defines no {name}"
    return names[name], argument


def test_ct82_fig1_symbols_resolve(root):
    table = pd.read_csv(root / "workflow" / "report" / "ct82_symbols.csv", dtype=str, keep_default_na=False)
    assert tuple(table.symbol) == FIG1_SYMBOLS
    assert (table.meaning != "").all() and (table.mathtext != "").all()
    for symbol, code in zip(table.symbol, table.code):
        for entry in code.split(";"):
            parameters, argument = resolve(root, entry.strip())
            if argument is not None:
                assert argument in parameters, f"{symbol}: {entry}"


def test_symbol_lookup_can_fail(root):
    """The static lookup refuses a name the module does not define and an argument it lacks."""
    with pytest.raises(AssertionError, match="defines no"):
        resolve(root, "reflectance.optics.fresnel.system")
    parameters, argument = resolve(root, "reflectance.optics.brdf.brdf(nonsense)")
    assert argument not in parameters and "L" in parameters


# --- the article's worked Phong example -----------------------------------------------------------

# Wikipedia, "Specular highlight" (oldid 793299363), "Phong distribution": the example's data.
L_ART = np.array([-0.6, 0.8, 0.0])
E_ART = np.array([np.sqrt(3) / 2, 0.5, 0.0])
N_ART = np.array([0.0, 1.0, 0.0])


def test_errata_article_phong_example_arithmetic():
    """The article: [-0.6 sqrt(3)/2 + 0.8 (-0.5)]^3 = (-0.5196 - 0.4)^3 = 0.9196. The base is
    -0.9196; its cube is -0.7777. Then H / sqrt(0.133^2 + 0.65^2) = H / 0.668, printed as
    (0.20048, 0.979701): the norm is 0.66347, and the printed unit vector is (0.133, 0.65)/0.66347."""
    base = L_ART @ (E_ART - 2 * N_ART * (N_ART @ E_ART))
    assert base == pytest.approx(-0.5196 - 0.4, abs=1e-4)
    assert base**3 == pytest.approx(-0.7777, abs=1e-4)
    assert abs(base) == pytest.approx(0.9196, abs=1e-4)  # the printed "cube": the base's size
    H = np.array([0.133, 0.65])
    assert np.linalg.norm(H) == pytest.approx(0.66347, abs=1e-5)
    assert 0.668 - np.linalg.norm(H) == pytest.approx(0.004532, abs=1e-6)  # the printed norm
    np.testing.assert_allclose(H / np.linalg.norm(H), [0.20048, 0.979701], atol=2e-5)
    assert 0.133 / 0.668 == pytest.approx(0.199102, abs=1e-6)  # dividing by it: not 0.20048


def test_errata_article_phong_reflection_vector_sign():
    """E - 2N(N.E) is minus the mirror image of E: the printed k is (-R.L)^n, -0.7777 for n = 3,
    where Phong's (R.V)^n (R the mirror of L, equal to L.(mirror of E)) is +0.7777."""
    mirror_E = 2 * N_ART * (N_ART @ E_ART) - E_ART
    assert np.linalg.norm(mirror_E) == pytest.approx(1)
    assert mirror_E @ N_ART == pytest.approx(E_ART @ N_ART)  # same angle to N ...
    assert np.cross(mirror_E + E_ART, N_ART) == pytest.approx(np.zeros(3))  # ... on the other side
    printed = E_ART - 2 * N_ART * (N_ART @ E_ART)
    np.testing.assert_allclose(printed, -mirror_E)
    phong = (N_ART @ L_ART) * brdf(L_ART, E_ART, N_ART, "Phong1975", p_d=0.0, p_s=1.0, c1=3.0)
    assert phong == pytest.approx((L_ART @ mirror_E) ** 3, rel=1e-12)
    assert phong == pytest.approx(0.7777, abs=1e-4)
    assert (L_ART @ printed) ** 3 == pytest.approx(-phong, rel=1e-12)
    # a convention mismatch: for E pointing at the surface (-E_ART) the printed form is Phong's
    towards = -E_ART
    assert (L_ART @ (towards - 2 * N_ART * (N_ART @ towards))) ** 3 == pytest.approx(phong, rel=1e-12)
    numbers = ERRATA["article-phong-reflection-sign"]().numbers
    assert numbers["towards_k"] == pytest.approx(phong, rel=1e-12)
    assert numbers["printed_k"] == pytest.approx(-phong, rel=1e-12)


def test_errata_blinn_calls_the_half_vector_lobe_phongs(errata):
    """Blinn names s = (N.H)^c1 'the net Phong shading function'; the article's Phong is (R.V)^n
    and (N.H)^n is Blinn-Phong. In the plane of incidence, with L at -theta_i and V at theta_i + d,
    N.H = cos(d / 2) and R.V = cos d: at c1 = 50 they halve at d = 2 acos(2^(-1/50)) and
    acos(2^(-1/50)), a lobe twice as wide (written out here)."""
    half = np.degrees(np.arccos(2 ** (-1 / 50)))
    numbers = ERRATA["blinn-phong-naming"](theta_deg=60).numbers
    assert numbers["phong_half_deg"] == pytest.approx(half, abs=1e-3)
    assert numbers["blinn_half_deg"] == pytest.approx(2 * half, abs=1e-3)
    assert numbers["ratio"] == pytest.approx(2.0, abs=1e-3)
    row = next(r for r in errata["rows"] if r["id"] == "blinn-phong-naming")
    assert row["kind"] == "naming"


def test_errata_article_half_vector_needs_four_times_the_exponent():
    """The article's 'approximate formula' (N.H)^n: in the plane, the angle N to H is half the angle
    R to V, so (N.H)^n with the same n is a broader lobe (0.9403 against 0.7777); n' = 4n matches to
    about 0.5 % here (cos^4n(x/2) ~ cos^n(x) for small x). Its unnormalised H gives 0.65^3."""
    H = (L_ART + E_ART) / np.linalg.norm(L_ART + E_ART)
    mirror_L = 2 * N_ART * (N_ART @ L_ART) - L_ART
    assert np.arccos(N_ART @ H) == pytest.approx(np.arccos(mirror_L @ E_ART) / 2, rel=1e-12)
    blinn = (N_ART @ L_ART) * brdf(L_ART, E_ART, N_ART, "BlinnPhong1977", p_d=0.0, p_s=1.0, c1=3.0)
    phong = (N_ART @ L_ART) * brdf(L_ART, E_ART, N_ART, "Phong1975", p_d=0.0, p_s=1.0, c1=3.0)
    assert blinn == pytest.approx(0.940332, abs=5e-5)  # the article (from rounded 0.133, 0.65)
    assert phong == pytest.approx(0.7777, abs=1e-4)  # the article's (R.V)^3, its sign mended
    assert blinn - phong == pytest.approx(0.940332 - 0.7777, abs=1e-4)
    four_n = (N_ART @ L_ART) * brdf(L_ART, E_ART, N_ART, "BlinnPhong1977", p_d=0.0, p_s=1.0, c1=12.0)
    assert four_n == pytest.approx(phong, rel=0.01)
    assert (N_ART @ ((L_ART + E_ART) / 2)) ** 3 == pytest.approx(0.274625, abs=2e-4)


# --- Blinn's triangle -------------------------------------------------------------------------------

def test_errata_blinn_triangle_angles_sum_to_pi():
    """Blinn derives G_b = 1 - m/l with m/l = sin f / sin b and "the angles of the triangle must
    sum to 2 pi", sin f = sin(b + c). They sum to pi; taken literally, 2 pi gives sin f =
    -sin(b + c) and 1 - m/l = 2 - G_b. A ray simulation of the groove agrees with G_b."""
    L, E = direction(np.radians(10), np.pi), direction(np.radians(85))  # Blinn's case b
    H = (L + E) / np.linalg.norm(L + E)
    G_b = 2 * (N_Z @ H) * (N_Z @ E) / (E @ H)
    result = simulate_vgroove(L, E, n_rays=20_000)
    assert result.case == "b"
    assert result.G_masking == pytest.approx(G_b, abs=1e-3)
    assert 1 - result.m_masking / result.facet_length == pytest.approx(G_b, abs=1e-12)
    # the literal 2 pi: 2 - G_b, above the simulated fraction by 2 (1 - G_b), and above 1
    assert (2 - G_b) - result.G_masking == pytest.approx(2 * (1 - G_b), abs=2e-3)
    assert 2 - G_b > 1
    # f = pi - (b + c): sin f = sin(b + c); f = 2 pi - (b + c): sin f = -sin(b + c)
    b, c = 0.7, 0.9
    assert np.sin(np.pi - (b + c)) == pytest.approx(np.sin(b + c))
    assert np.sin(2 * np.pi - (b + c)) == pytest.approx(-np.sin(b + c))


def test_errata_blinn_projects_E_not_B():
    """Blinn: 'Since E_p is the projection of B onto the N,H plane then N.E_p = N.E and H.E_p =
    H.E'. No B is defined; projecting E (his own E' of Fig. 4) onto the plane of N and H keeps its
    dot products with N and H, so G_b = 2(N.H)(N.E)/(E.H) from the 3-D E equals 1 - m/l of the
    plane figure: checked against the ray simulation of the groove for eyes off the plane. The
    projection of L (the only other vector of the figure) does not give N.E."""
    rng = np.random.default_rng(7)
    off_plane = []
    for _ in range(20):
        L = direction(rng.uniform(0.0, 0.6), np.pi)
        E = direction(rng.uniform(1.2, 1.5), rng.uniform(-2.0, 2.0))
        H = (L + E) / np.linalg.norm(L + E)
        axis = np.cross(N_Z, H) / np.linalg.norm(np.cross(N_Z, H))
        E_p = E - (E @ axis) * axis
        assert E_p @ axis == pytest.approx(0.0, abs=1e-15)  # in the N,H plane
        assert N_Z @ E_p == pytest.approx(N_Z @ E, abs=1e-15)
        assert H @ E_p == pytest.approx(H @ E, abs=1e-15)
        L_p = L - (L @ axis) * axis
        assert N_Z @ L_p == pytest.approx(N_Z @ L, abs=1e-15)  # L's own N.L, not N.E
        # the plane figure, from the unit in-plane eye vector: 1 - m/l, simulated
        result = simulate_vgroove(L, E, n_rays=20_000)
        G_b = 2 * (N_Z @ H) * (N_Z @ E) / (E @ H)
        if result.case == "b":
            assert result.G_masking == pytest.approx(G_b, abs=2e-4)
            off_plane.append(np.degrees(np.arcsin(abs(E @ axis))))
    assert len(off_plane) >= 5 and max(off_plane) > 20  # eyes well off the plane were checked
    numbers = ERRATA["blinn-projection-of-B"]().numbers
    assert numbers["G_b"] == pytest.approx(numbers["simulated"], abs=2e-4)
    assert numbers["off_plane_deg"] > 20


def test_errata_blinn_vectors_are_unit():
    """Blinn: N, L, H and E 'are assumed to be nonnormalized'; his D3 and G read N.H as cos(alpha)
    and E.H as c, so they hold for unit vectors only: G_b = 2(N.H)(N.E)/(E.H), written out here,
    changes when N and E are lengthened (it is of degree 2 in N, 0 in E), and so does D3 of 'N.H'.
    The erratum's numbers say the same."""
    rng = np.random.default_rng(3)
    for _ in range(10):
        L, E = direction(rng.uniform(0.0, 1.2), np.pi), direction(rng.uniform(0.2, 1.4), 0.0)
        H = (L + E) / np.linalg.norm(L + E)
        k = rng.uniform(1.5, 3.0)
        unit = 2 * (N_Z @ H) * (N_Z @ E) / (E @ H)
        longer = 2 * ((k * N_Z) @ H) * ((k * N_Z) @ (k * E)) / ((k * E) @ H)
        assert longer == pytest.approx(k * k * unit, rel=1e-12)
        def D3(cos_alpha, c3=0.3):
            return (c3**2 / (cos_alpha**2 * (c3**2 - 1) + 1)) ** 2

        assert abs(D3((k * N_Z) @ H) - D3(N_Z @ H)) > 1e-3 * D3(N_Z @ H)
    numbers = ERRATA["blinn-nonnormalized-vectors"]().numbers
    assert numbers["long"] == pytest.approx(4 * numbers["unit"], rel=1e-12)
    assert numbers["long_NH"] == pytest.approx(2 * numbers["cos_alpha"], rel=1e-12)


def test_errata_lecture_beckmann_4m2_puts_cook_torrances_factor_4_in_D():
    """The factor-4 row: C&T's R_s = (F/pi) D G / ((N.L)(N.V)) with the lecture's D (4 m^2 below
    the bar) equals the article's D F G / (4 (V.N)(N.L)) with its normalised Beckmann D (1/(pi m^2
    cos^4)), each written out here, for any angles and m; with C&T's own D it is 4 times that."""
    rng = np.random.default_rng(11)
    for _ in range(20):
        m, a = rng.uniform(0.1, 0.6), rng.uniform(0.0, 1.2)
        NL, NV, F, G = rng.uniform(0.1, 1.0), rng.uniform(0.1, 1.0), rng.uniform(0, 1), rng.uniform(0, 1)
        e = np.exp(-(np.tan(a) / m) ** 2)
        lecture_D, ct_D, article_D = (e / (4 * m * m * np.cos(a) ** 4), e / (m * m * np.cos(a) ** 4),
                                      e / (np.pi * m * m * np.cos(a) ** 4))
        article = article_D * F * G / (4 * NV * NL)
        assert F / np.pi * lecture_D * G / (NL * NV) == pytest.approx(article, rel=1e-12)
        assert F / np.pi * ct_D * G / (NL * NV) == pytest.approx(4 * article, rel=1e-12)


# --- the lecture ------------------------------------------------------------------------------------

def test_errata_lecture_gaussian_puts_m_in_the_numerator():
    """The lecture's Torrance-Sparrow D = exp(-(alpha m)^2), 'm is standard deviation', is Blinn's
    D2 with c2 = m, i.e. Cook & Torrance's exp(-(alpha/m')^2) with m' = 1/m: an inverse width, so
    a small m is nearly uniform over the hemisphere where Cook & Torrance's m = 0.3 lobe halves at
    14.3 deg. (The slide's 'm near 0.2 ... nearly smooth' is said of the Beckmann m, not this one.)"""
    alpha = np.radians(np.linspace(0, 90, 19))
    for m in (0.2, 0.6):
        lecture = np.exp(-((alpha * m) ** 2))  # the slide as printed
        np.testing.assert_allclose(distribution_TorranceSparrow1967(np.cos(alpha), m), lecture, rtol=1e-12)
        np.testing.assert_allclose(distribution_Gaussian_CookTorrance1982(np.cos(alpha), 1 / m), lecture, rtol=1e-12)
        assert not np.allclose(distribution_Gaussian_CookTorrance1982(np.cos(alpha), m), lecture, rtol=0.1)
    assert np.exp(-((np.pi / 2 * 0.3) ** 2)) == pytest.approx(0.801, abs=5e-4)
    assert distribution_Gaussian_CookTorrance1982(np.cos(np.radians(14.3)), 0.3) == pytest.approx(0.5, abs=0.01)


def test_lecture_beckmann_4_is_the_normalised_brdf():
    """Not an erratum (no row; the slide pairs its D with no R_s, so its 1/4 is another placement
    of a constant): the slide's D = exp(-(tan d/m)^2) / (4 m^2 cos^4 d) is Cook & Torrance's D / 4, so its
    projected-area integral is pi/4 (C&T's: pi; the normalised one's: 1). Put into C&T's
    R_s = (F/pi) D G / ((N.L)(N.V)) it is exactly the normalised F D G / (4 (N.L)(N.V)) with
    D = exp(-(tan a/m)^2) / (pi m^2 cos^4 a): written out here for random geometries, F = 1."""
    from scipy.integrate import quad

    m = 0.3
    slide = lambda c: np.exp(-((1 - c * c) / (c * c)) / m**2) / (4 * m**2 * c**4)  # noqa: E731
    walter = lambda c: np.exp(-((1 - c * c) / (c * c)) / m**2) / (np.pi * m**2 * c**4)  # noqa: E731
    integral, _ = quad(lambda a: 2 * np.pi * slide(np.cos(a)) * np.cos(a) * np.sin(a), 0, np.pi / 2,
                       points=[m])
    assert integral == pytest.approx(np.pi / 4, rel=1e-8)
    rng = np.random.default_rng(4)
    for _ in range(50):
        L = direction(rng.uniform(0, 1.4), rng.uniform(0, 2 * np.pi))
        V = direction(rng.uniform(0, 1.4), rng.uniform(0, 2 * np.pi))
        H = (L + V) / np.linalg.norm(L + V)
        NL, NV, NH, VH = N_Z @ L, N_Z @ V, N_Z @ H, V @ H
        G = min(1.0, 2 * NH * NV / VH, 2 * NH * NL / VH)
        rs_with_slide_D = 1.0 / np.pi * slide(NH) * G / (NL * NV)
        normalised = walter(NH) * G / (4 * NL * NV)
        assert rs_with_slide_D == pytest.approx(normalised, rel=1e-12)
        assert brdf(L, V, N_Z, "CookTorrance1982", F=1.0, m=m, convention="physical") == (
            pytest.approx(normalised, rel=1e-9))
        # C&T's own D in the same R_s is four times the normalised BRDF
        assert brdf(L, V, N_Z, "CookTorrance1982", F=1.0, m=m) == pytest.approx(4 * normalised, rel=1e-9)


def projected_area(polygon, view):
    """Area of a planar polygon (k, 3) projected onto the plane perpendicular to ``view``."""
    view = view / np.linalg.norm(view)
    u = np.cross(view, [0.0, 1.0, 0.0] if abs(view[1]) < 0.9 else [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    w = np.cross(view, u)
    x, y = polygon @ u, polygon @ w
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))  # shoelace


def test_errata_lecture_glare_term_is_inverse_cosine():
    """A viewer sees a patch of the surface foreshortened by cos(angle) (Blinn: "inversely
    proportional to the cosine of the angle of tilt"); the lecture says "to the angle"."""
    square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    for theta in np.radians([0.0, 30.0, 60.0, 80.0]):
        V = direction(theta, 0.4)
        surface_per_projected_area = 1.0 / projected_area(square, V)
        assert surface_per_projected_area == pytest.approx(1 / np.cos(theta), rel=1e-12)
        if theta > 0:
            # the lecture's 1/angle, against the truth: off by the factor angle / cos(angle)
            assert (1 / theta) / surface_per_projected_area == pytest.approx(np.cos(theta) / theta,
                                                                           rel=1e-12)


# --- the figures of Cook & Torrance 1982 Figs. 1-3, Table I and the errata, built end to end -------

CT82 = "results/cook_torrance_1982"
BUILT = [f"{CT82}/{name}" for name in ("fig1.csv", "fig2.csv", "fig3.csv", "table1.csv")] + [
    "results/errata/errata.csv"]


# `built` is the session's whole build (tests/conftest.py), read here and never changed.

@pytest.mark.workflow
def test_the_whole_build_holds_these_tables(built):
    for p in BUILT:
        assert (built / p).stat().st_size > 0, p


@pytest.mark.workflow
def test_built_fig2_angles_by_the_spherical_law_of_cosines(built):
    config = yaml.safe_load((built / "config.yaml").read_text())["figures"]["cook_torrance_1982"]["fig2"]
    t = pd.read_csv(built / CT82 / "fig2.csv").set_index("quantity").value
    tl, pl = np.radians([config["light"]["polar_deg"], config["light"]["azimuth_deg"]])
    tv, pv = np.radians([config["viewer"]["polar_deg"], config["viewer"]["azimuth_deg"]])
    cos_LV = np.cos(tl) * np.cos(tv) + np.sin(tl) * np.sin(tv) * np.cos(pl - pv)
    # H bisects L and V: theta is half their angle; N.H = (N.L + N.V) / |L + V|
    assert t["theta_deg"] == pytest.approx(np.degrees(np.arccos(cos_LV)) / 2, abs=1e-4)
    assert t["theta_L_deg"] == pytest.approx(t["theta_deg"], abs=1e-6)
    cos_alpha = (np.cos(tl) + np.cos(tv)) / np.sqrt(2 + 2 * cos_LV)
    assert t["alpha_deg"] == pytest.approx(np.degrees(np.arccos(cos_alpha)), abs=1e-4)


@pytest.mark.workflow
def test_built_fig3_distributions(built):
    from scipy.integrate import quad

    config = yaml.safe_load((built / "config.yaml").read_text())["figures"]["cook_torrance_1982"]["fig3"]
    t = pd.read_csv(built / CT82 / "fig3.csv")
    a = np.radians(t.alpha_deg)
    for m in config["m"]:
        c = 1 / m**2 if config["gaussian_c"] == "beckmann_peak" else 1.0
        beckmann = np.exp(-np.tan(a) ** 2 / m**2) / (m**2 * np.cos(a) ** 4)
        np.testing.assert_allclose(t[f"Beckmann_m{m:g}"], np.nan_to_num(beckmann), rtol=1e-5, atol=1e-300)
        np.testing.assert_allclose(t[f"Gaussian_m{m:g}"], c * np.exp(-(a / m) ** 2), rtol=1e-5)
        # Cook & Torrance's Beckmann D has no 1/pi: its projected-area integral is pi
        integral, _ = quad(lambda x: 2 * np.pi * np.exp(-np.tan(x) ** 2 / m**2) / (m**2 * np.cos(x) ** 3)
                           * np.sin(x), 0, np.pi / 2, points=[m])
        assert integral == pytest.approx(np.pi, rel=1e-8)


@pytest.mark.workflow
def test_built_table1_against_colour_science(built):
    import colour

    config = yaml.safe_load((built / "config.yaml").read_text())
    rows = config["figures"]["cook_torrance_1982"]["table1"]["rows"]
    t = pd.read_csv(built / CT82 / "table1.csv")
    assert list(t.material) == [r["material"] for r in rows]
    np.testing.assert_allclose(t.s + t.d, 1.0)
    wl = np.arange(360, 831, 5.0)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(colour.SpectralShape(360, 830, 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    for r in t.itertuples():
        spectrum = config["figures"]["cook_torrance_1982"]["fig7"]["table1_spectra"].get(r.material, r.material)
        assert r.spectrum_material == spectrum  # the spectrum Fig. 7 gives the row
        data = pd.read_csv(built / "spectra" / f"{r.spectrum_material}.csv")
        if "reflectance" in data:
            F0 = np.interp(wl, data.wavelength_nm, data.reflectance)
        else:
            index = np.interp(wl, data.wavelength_nm, data.n) + 1j * np.interp(wl, data.wavelength_nm, data.k)
            F0 = abs((index - 1) / (index + 1)) ** 2
        XYZ = colour.sd_to_XYZ(colour.SpectralDistribution(dict(zip(wl, F0))), cmfs, d65, method="Integration") / 100
        np.testing.assert_allclose([r.X, r.Y, r.Z], XYZ, rtol=1e-5)
        visible = (wl >= 380) & (wl <= 780)
        assert r.F0_mean_380_780nm == pytest.approx(F0[visible].mean(), rel=1e-5)
        assert r.R_d_mean_per_sr == pytest.approx(F0[visible].mean() / np.pi, rel=1e-5)


@pytest.mark.workflow
def test_built_fig1_and_errata_tables(built, root, table):
    symbols = pd.read_csv(root / "workflow" / "report" / "ct82_symbols.csv", dtype=str, keep_default_na=False)
    assert pd.read_csv(built / CT82 / "fig1.csv", dtype=str, keep_default_na=False).equals(symbols)
    errata_csv = pd.read_csv(built / "results" / "errata" / "errata.csv")
    assert list(errata_csv.test) == list(table.test)
    np.testing.assert_allclose(errata_csv.value, table.value.astype(float), rtol=1e-5)


def test_figure_wrapping_leaves_no_orphans(root, table):
    """The errata figures wrap each field without a last line of a word or two ("1/2", "(N.E)"),
    and the wrapped lines hold every word of the field in order."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("errata_script", root / "workflow" / "scripts" / "errata.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    for key, width in (("printed", 82), ("correct", 82), ("consequence", 82), ("location", 25)):
        for text in table[key].astype(str):
            lines = script.wrap(text, width)
            assert "".join(lines).replace(" ", "") == text.replace(" ", "")  # (hyphens may end a line)
            assert all(len(line) <= width for line in lines if " " in line), text
            assert len(lines) == 1 or len(lines[-1]) >= width / 3, (text, lines)
