"""Blinn 1977's cost claim (reflectance.papers.highlight_cost): each term's operations as Blinn
would count them, against counts derived by hand from the printed formulas and against sympy's
``count_ops`` (an independent counter); the table's shape; the counted formulas equal the
project's implementations; the timing code runs (nothing here asserts a time)."""

import math

import numpy as np
import pandas as pd
import pytest

from reflectance.optics.fresnel import fresnel_Blinn1977, fresnel_dielectric_CookTorrance1982
from reflectance.optics.microfacet import (distribution_Phong1975,
                                           distribution_TorranceSparrow1967,
                                           distribution_TrowbridgeReitz1975)
from reflectance.optics.shadowing import G_over_NE_Blinn1977, shadowing_VCavity_Blinn1977
from reflectance.papers.highlight_cost import (OPERATIONS, TERMS, count_table, count_term,
                                               formula_terms, frame_constants, project_terms,
                                               sample_dot_products, time_per_evaluation,
                                               timing_verdict)
from script_runner import run_script

#: MgO, Blinn Fig. 7b (c3 = .35, n = 1.8); c1 and c2 any values of their kind
K = frame_constants(23.27, 3.43, 0.35, 1.8)


def ops(adds=0, multiplies=0, divides=0, square_roots=0, compares=0, transcendental=0):
    return dict(zip(OPERATIONS, (adds, multiplies, divides, square_roots, compares,
                                 transcendental)))


#: Derived by hand from the formulas as Blinn 1977 prints them, per pixel, with what
#: "Computational considerations" computes once per frame (k1, k2, n^2 - 1) not counted.
BY_HAND = {
    # cos^c1 alpha: one call of pow
    "D1_pow": ops(transcendental=1),
    # c1 = 23 = 10111 in binary: 4 squarings, and a multiply for each 1 bit after the first (3)
    "D1_squaring": ops(multiplies=4 + 3),
    # exp(-(alpha c2)^2), alpha = acos(N.H): acos, alpha c2, its square, the minus sign, exp
    "D2": ops(adds=1, multiplies=2, transcendental=2),
    # (k2 / (cos^2 alpha + k1))^2: cos^2, + k1, k2 / ..., the square
    "D3": ops(adds=1, multiplies=2, divides=1),
    # G_b = 2 (N.H)(N.E) / (E.H), G_c = 2 (N.H)(N.L) / (E.H): 2 multiplies and a divide each;
    # the minimum of 1, G_b, G_c: 2 comparisons
    "G": ops(multiplies=4, divides=2, compares=2),
    "one_over_NE": ops(divides=1),
    # if (N.E) < (N.L) [1 comparison] ... else if 2(N.L)(N.H) < (E.H) [2 multiplies,
    # 1 comparison] then G := 2(N.H)(N.L) / (E.H)(N.E) [3 multiplies, 1 divide]: the longest path
    "G_over_NE": ops(multiplies=5, divides=1, compares=2),
    # g = sqrt(n^2 + c^2 - 1): c^2, + (n^2 - 1), sqrt; g - c, g + c; (g-c)^2, (g+c)^2 and their
    # quotient; c (g+c) - 1 and c (g-c) + 1 (2 multiplies, 2 adds); their squares and quotient;
    # 1 + ...; the product of the two factors
    "F": ops(adds=1 + 2 + 2 + 1, multiplies=1 + 2 + 2 + 2 + 1, divides=2, square_roots=1),
    "phong": ops(transcendental=1),
    # D3 + G/(N.E) + F, and the two multiplies of D G F / (N.E)
    "torrance_sparrow": ops(adds=1 + 6, multiplies=2 + 5 + 8 + 2, divides=1 + 1 + 2,
                            square_roots=1, compares=2),
    # F once per frame: D3 + G/(N.E) and the same two multiplies
    "torrance_sparrow_F_per_frame": ops(adds=1, multiplies=2 + 5 + 2, divides=2, compares=2),
}


@pytest.mark.parametrize("term", list(BY_HAND))
def test_counts_match_the_hand_derivation_from_the_printed_formulas(term):
    assert count_term(term, K)[0] == BY_HAND[term]


def test_every_term_is_derived_by_hand():
    assert set(BY_HAND) == set(TERMS)


def test_the_transcendental_calls_are_named():
    assert count_term("D1_pow", K)[1] == ["pow"]
    assert count_term("D2", K)[1] == ["acos", "exp"]
    assert count_term("D3", K)[1] == [] and count_term("torrance_sparrow", K)[1] == []


def test_the_table_has_a_row_per_term_and_a_column_per_operation():
    table = pd.DataFrame(count_table(K))
    assert list(table.term) == list(TERMS)
    assert list(table.columns) == ["term", "label", "printed", "blinn_1977_section",
                                   *OPERATIONS, "arithmetic", "calls"]
    assert (table.arithmetic == table[list(OPERATIONS[:-1])].sum(axis=1)).all()
    rows = table.set_index("term")
    parts = rows.loc[["D3", "G_over_NE", "F"], list(OPERATIONS)].sum()
    assert rows.loc["torrance_sparrow", "multiplies"] == parts["multiplies"] + 2
    # Blinn's "no transcendental functions in D3", and none in his whole highlight
    assert rows.loc["D3", "transcendental"] == 0 == rows.loc["torrance_sparrow", "transcendental"]


# --- sympy's count_ops: an independent counter of the same printed formulas --------------------

def sympy_counts(sp, expression, compares=0):
    """count_ops(visual=True) of ``expression`` after sympy's cse (each common subexpression
    once, as code computes it), in this module's classes. count_ops names ADD, SUB, NEG, MUL,
    DIV, POW, EXP, ACOS; its POW is any power but a reciprocal (a DIV): a square is one
    multiply, a square root (which it also counts as a DIV) is a square root, a symbolic exponent
    is pow, a call."""
    replacements, reduced = sp.cse(expression)
    parts = [value for _, value in replacements] + list(reduced)
    visual = sum((sp.count_ops(part, visual=True) for part in parts), sp.S.Zero)
    n = {str(symbol): int(visual.coeff(symbol)) for symbol in visual.free_symbols}
    squares = roots = pows = 0
    for part in parts:
        for power in part.atoms(sp.Pow):
            if power.exp == -1:  # a reciprocal: count_ops's DIV alone
                continue
            if power.exp in (2, -2):
                squares += 1
            elif power.exp == sp.Rational(1, 2):
                roots += 1
            elif not power.exp.is_number:
                pows += 1
            else:
                raise AssertionError(f"unexpected power {power}")
    assert n.get("POW", 0) == squares + roots + pows
    return ops(adds=n.get("ADD", 0) + n.get("SUB", 0) + n.get("NEG", 0),
               multiplies=n.get("MUL", 0) + squares, divides=n.get("DIV", 0) - roots,
               square_roots=roots, compares=compares,
               transcendental=pows + n.get("EXP", 0) + n.get("ACOS", 0))


@pytest.fixture(scope="module")
def sp():
    return pytest.importorskip("sympy", reason="sympy is in the test extra of pyproject.toml")


def printed(sp):
    """Blinn's formulas as sympy expressions, per pixel; a per-frame value is a symbol (where
    sympy would square a per-frame symbol itself, its square is the symbol: c2^2 as C2, k2^2 as
    K2)."""
    NH, NL, NE, EH, c1, C2, k1, K2, n2m1 = sp.symbols("NH NL NE EH c1 C2 k1 K2 n2m1",
                                                      positive=True)
    g = sp.sqrt(n2m1 + EH**2)
    return {
        "D1_pow": (NH**c1, 0),
        "D2": (sp.exp(-C2 * sp.acos(NH) ** 2), 0),
        "D3": (K2 / (NH**2 + k1) ** 2, 0),
        # min(1, G_b, G_c): two comparisons
        "G": ((2 * NH * NE / EH, 2 * NH * NL / EH), 2),
        "one_over_NE": (1 / NE, 0),
        # the longest path: (N.E) < (N.L) fails, 2(N.L)(N.H) < (E.H) holds
        "G_over_NE": ((2 * NL * NH, 2 * NH * NL / (EH * NE)), 2),
        "F": ((g - EH) ** 2 / (g + EH) ** 2
              * (1 + (EH * (g + EH) - 1) ** 2 / (EH * (g - EH) + 1) ** 2), 0),
    }


@pytest.mark.parametrize("term", ["D1_pow", "D2", "D3", "G", "one_over_NE", "G_over_NE", "F"])
def test_counts_match_sympy_count_ops(sp, term):
    expression, compares = printed(sp)[term]
    expressions = expression if isinstance(expression, tuple) else (expression,)
    total = ops(compares=compares)
    for e in expressions:  # parts computed one after the other: their counts add
        total = {op: total[op] + sympy_counts(sp, e)[op] for op in OPERATIONS}
    assert total == count_term(term, K)[0]


def test_sympy_formulas_are_blinns(sp):
    """The sympy expressions are the printed formulas: D3's k1, k2 form is D3, and the g, c
    form of F is (without its 1/2) the sin/tan form Blinn prints first."""
    NH, k1, K2 = sp.symbols("NH k1 K2", positive=True)
    c3 = sp.Rational(7, 20)
    D3 = (c3**2 / (NH**2 * (c3**2 - 1) + 1)) ** 2  # Blinn 1977, D3 as printed
    k1_value = 1 / (c3**2 - 1)
    assert sp.simplify(printed(sp)["D3"][0].subs({k1: k1_value, K2: (k1_value + 1) ** 2}) - D3) == 0
    EH, n2m1 = sp.symbols("EH n2m1", positive=True)
    phi = sp.acos(sp.Rational(3, 5))
    theta = sp.asin(sp.sin(phi) / sp.Rational(9, 5))  # sin theta = sin phi / n, n = 1.8
    sin_tan = sp.Rational(1, 2) * (sp.sin(phi - theta) ** 2 / sp.sin(phi + theta) ** 2
                                   + sp.tan(phi - theta) ** 2 / sp.tan(phi + theta) ** 2)
    g_c = printed(sp)["F"][0].subs({EH: sp.Rational(3, 5), n2m1: sp.Rational(81, 25) - 1})
    assert abs(float(g_c) - 2 * float(sin_tan)) < 1e-12


# --- the counted formulas are the project's terms ----------------------------------------------

@pytest.fixture(scope="module")
def samples():
    return sample_dot_products(20000, 1)


def test_samples_are_valid_geometry(samples):
    for name in ("NH", "NL", "NE", "EH"):
        assert np.all((samples[name] > 0) & (samples[name] <= 1)), name
    # H halves L and E: N.H = (N.L + N.E) / len(L + E), and len(L + E) = 2 (E.H)
    assert np.allclose(samples["NH"] * 2 * samples["EH"], samples["NL"] + samples["NE"])


def test_counted_formulas_equal_the_projects_implementations(samples):
    NH, NL, NE, EH = (samples[k] for k in ("NH", "NL", "NE", "EH"))
    f = {key: function() for key, function in formula_terms(samples, K).items()}
    assert np.allclose(f["D1_pow"], distribution_Phong1975(NH, K.c1), rtol=1e-12, atol=0)
    assert np.allclose(f["D1_squaring"], NH ** K.c1_integer, rtol=1e-12, atol=0)
    assert np.allclose(f["D2"], distribution_TorranceSparrow1967(NH, K.c2), rtol=1e-12, atol=0)
    assert np.allclose(f["D3"], distribution_TrowbridgeReitz1975(NH, 0.35), rtol=1e-12, atol=0)
    assert np.allclose(f["G"], shadowing_VCavity_Blinn1977(NL, NE, NH, EH), rtol=1e-12, atol=0)
    assert np.allclose(f["G_over_NE"], G_over_NE_Blinn1977(NL, NE, NH, EH), rtol=1e-12, atol=0)
    assert np.allclose(f["F"], fresnel_Blinn1977(EH, 1.8), rtol=1e-12, atol=0)
    assert np.allclose(f["torrance_sparrow"], f["D3"] * f["G_over_NE"] * f["F"], rtol=1e-12)


def test_the_projects_highlights_are_the_products_of_its_terms(samples):
    functions = project_terms(samples, K.c1, K.c2, 0.35, 1.8, p_s=0.667, p_d=0.333)
    NH, NL, NE, EH = (samples[k] for k in ("NH", "NL", "NE", "EH"))
    expected = (distribution_TrowbridgeReitz1975(NH, 0.35) * G_over_NE_Blinn1977(NL, NE, NH, EH)
                * fresnel_dielectric_CookTorrance1982(EH, 1.8))
    assert np.allclose(functions["torrance_sparrow"][1](), expected, rtol=1e-12)
    assert set(functions) - set(TERMS) == {"brdf_phong", "brdf_torrance_sparrow"}


# --- the timing runs (its numbers are a measurement: none is asserted) -------------------------

def test_the_timing_runs_and_gives_a_time_for_every_function(samples):
    functions = {key: f for key, f in formula_terms(samples, K).items()}
    ns = time_per_evaluation(functions, len(samples["NH"]), repeats=1)
    assert set(ns) == set(TERMS)
    assert all(math.isfinite(t) and t > 0 for t in ns.values())


def test_the_verdict_reads_a_ratio_with_a_margin():
    assert timing_verdict(1.0, 1.1, 1.5) == "holds"
    assert timing_verdict(1.1, 1.1, 1.5) == "holds"
    assert timing_verdict(1.2, 1.1, 1.5) == "within the timing noise"
    assert timing_verdict(1.5, 1.1, 1.5) == "fails"
    with pytest.raises(ValueError, match="holds_at_most"):
        timing_verdict(1.0, 1.5, 1.5)


PANELS = {"b": {"label": "magnesium oxide", "p_s": 0.667, "p_d": 0.333, "n": 1.8, "c3": 0.35}}


def test_the_two_scripts_write_their_tables(tmp_path):
    """The counts script, then the timing script on its table with a small sample: every term a
    row, the counts beside the times, the measurement's date and CPU, the caption values."""
    run_script("blinn_1977_cost_counts", tmp_path,
               {"csv": "cost_counts.csv", "values": "cost_counts.values.rst"},
               fig={"panel": "b"}, panels=PANELS)
    counts = pd.read_csv(tmp_path / "cost_counts.csv", keep_default_na=False)
    assert list(counts.term) == list(TERMS)
    run_script("blinn_1977_cost_timing", tmp_path,
               {"csv": "cost_timing.csv", "measurement": "cost_timing.yaml",
                "values": "cost_timing.values.rst"},
               inputs={"counts": str(tmp_path / "cost_counts.csv")},
               fig={"panel": "b", "n_samples": 2000, "repeats": 1, "seed": 1,
                    "verdict": {"holds_at_most": 1.1, "fails_at_least": 1.5}},
               panels=PANELS)
    timing = pd.read_csv(tmp_path / "cost_timing.csv")
    assert list(timing.term) == list(TERMS) + ["one_multiply", "brdf_phong",
                                               "brdf_torrance_sparrow"]
    rows = timing.set_index("term")
    assert rows.loc[list(TERMS), "arithmetic"].tolist() == counts.arithmetic.tolist()
    assert rows.ns_formula[list(TERMS)].notna().all()
    assert rows.ns_project[["D1_pow", "D3", "F", "torrance_sparrow", "brdf_phong"]].notna().all()
    import yaml

    measurement = yaml.safe_load((tmp_path / "cost_timing.yaml").read_text())
    assert {"measured", "cpu", "numpy", "ratios", "verdicts"} <= set(measurement)
    assert set(measurement["verdicts"].values()) <= {"holds", "fails", "within the timing noise"}
