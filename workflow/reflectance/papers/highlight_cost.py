"""Blinn 1977's cost claim: each highlight term's operations, counted as Blinn would count them,
and its time per evaluation.

Blinn 1977, "Conclusions": D3 "is, happily, easier to compute than D1 or D2. This savings
effectively offsets the extra computation time for G and F yielding a highlight generation
function having a high degree of realism for no increase in computation time".

**Counting.** Each term is written once below as Blinn prints it (:data:`TERMS`), per pixel, its
inputs the dot products ``N.H``, ``N.L``, ``N.E``, ``E.H``; what his "Computational
considerations" compute once per frame (``k1``, ``k2``, ``n^2 - 1``, c1, c2) are plain numbers
(:class:`FrameConstants`). Evaluated on :class:`Counted` values, an operation is tallied when a
per-pixel value takes part in it: additions (subtractions and negations too), multiplications
(a square is one), divisions, square roots, comparisons (a ``min`` of two is one) and
transcendental calls (``pow``, ``exp``, ``acos``). A branch is counted along the path the values
take; :func:`count_term` takes the path with the most operations.

**Timing.** The same formulas evaluate on numpy arrays (:data:`NUMPY`: both arms of a branch,
then ``numpy.where``), and so do the project's own implementations of each term
(:func:`project_terms`); :func:`time_per_evaluation` times both over the same samples, the best of
interleaved repeats. Timings are measurements: they differ from run to run.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics 11(2), 192-198: "Facet distribution functions" (D1, D2, D3), "Torrance-Sparrow
  model" (s = DGF/(N.E), G_b, G_c), "Computational considerations" (k1, k2; G with 1/(N.E)
  before the divisions; F in g and c), "Conclusions" (the claim).
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

import numpy as np

__all__ = ["OPERATIONS", "Tally", "Counted", "COUNTING", "NUMPY", "FrameConstants",
           "frame_constants", "TERMS", "count_term", "count_table", "sample_dot_products",
           "project_terms", "formula_terms", "time_per_evaluation", "timing_verdict"]

#: the operation classes counted, in the table's column order
OPERATIONS = ("adds", "multiplies", "divides", "square_roots", "compares", "transcendental")


class Tally:
    """Counts of :data:`OPERATIONS` and the names of the transcendental functions called."""

    def __init__(self) -> None:
        self.counts = dict.fromkeys(OPERATIONS, 0)
        self.calls: list[str] = []

    def add(self, operation: str, name: str | None = None) -> None:
        self.counts[operation] += 1
        if name is not None:
            self.calls.append(name)


class Counted:
    """A per-pixel value that tallies every operation it takes part in.

    An operation between plain numbers (a per-frame constant) is not counted: it is done once
    per frame. Comparisons return a plain bool, so a branch follows the value.

    Examples
    --------
    >>> tally = Tally()
    >>> x = Counted(0.5, tally)
    >>> y = (2.0 * x * x + 1.0) / x
    >>> y.value, tally.counts["multiplies"], tally.counts["adds"], tally.counts["divides"]
    (3.0, 2, 1, 1)
    """

    __slots__ = ("value", "tally")

    def __init__(self, value: float, tally: Tally) -> None:
        self.value = float(value)
        self.tally = tally

    def _binary(self, other, operation, function):
        self.tally.add(operation)
        other = other.value if isinstance(other, Counted) else float(other)
        return Counted(function(self.value, other), self.tally)

    def __add__(self, other): return self._binary(other, "adds", lambda a, b: a + b)
    def __radd__(self, other): return self._binary(other, "adds", lambda a, b: b + a)
    def __sub__(self, other): return self._binary(other, "adds", lambda a, b: a - b)
    def __rsub__(self, other): return self._binary(other, "adds", lambda a, b: b - a)
    def __mul__(self, other): return self._binary(other, "multiplies", lambda a, b: a * b)
    def __rmul__(self, other): return self._binary(other, "multiplies", lambda a, b: b * a)
    def __truediv__(self, other): return self._binary(other, "divides", lambda a, b: a / b)
    def __rtruediv__(self, other): return self._binary(other, "divides", lambda a, b: b / a)

    def __neg__(self):
        self.tally.add("adds")
        return Counted(-self.value, self.tally)

    def _compare(self, other, function):
        self.tally.add("compares")
        return function(self.value, other.value if isinstance(other, Counted) else float(other))

    def __lt__(self, other): return self._compare(other, lambda a, b: a < b)
    def __gt__(self, other): return self._compare(other, lambda a, b: a > b)


def _tally_of(*values):
    return next(v.tally for v in values if isinstance(v, Counted))


def _call(name, operation, function, x, *rest):
    tally = _tally_of(x)
    tally.add(operation, name if operation == "transcendental" else None)
    return Counted(function(x.value, *rest), tally)


class _Ops(NamedTuple):
    """What the formulas call besides + - * /: the same names on counted values and on arrays."""

    sqrt: Callable[..., Any]
    acos: Callable[..., Any]
    exp: Callable[..., Any]
    pow: Callable[..., Any]
    minimum: Callable[..., Any]
    branch: Callable[..., Any]


def _counted_minimum(a, b):
    # one comparison; a plain number (1, Blinn's G_a) compares with a counted value
    counted = a if isinstance(a, Counted) else b
    other = b if counted is a else a
    return counted if counted < other else other


#: the formulas on :class:`Counted` values: each call tallied, a branch taking one arm
COUNTING = _Ops(sqrt=lambda x: _call("sqrt", "square_roots", math.sqrt, x),
                acos=lambda x: _call("acos", "transcendental", math.acos, x),
                exp=lambda x: _call("exp", "transcendental", math.exp, x),
                pow=lambda x, c: _call("pow", "transcendental", math.pow, x, c),
                minimum=_counted_minimum,
                branch=lambda condition, then, otherwise: then() if condition else otherwise())

#: the formulas on numpy arrays: both arms of a branch, then numpy.where
NUMPY = _Ops(sqrt=np.sqrt, acos=np.arccos, exp=np.exp, pow=np.power, minimum=np.minimum,
             branch=lambda condition, then, otherwise: np.where(condition, then(), otherwise()))


class FrameConstants(NamedTuple):
    """What Blinn computes once per frame ("Computational considerations")."""

    c1: float            # D1's exponent
    c1_integer: int      # c1 rounded, for D1 by repeated squaring
    c2: float            # D2's inverse width
    k1: float            # 1 / (c3^2 - 1)
    k2: float            # k1 + 1
    n2_minus_1: float    # n^2 - 1 of g = sqrt(n^2 + c^2 - 1)


def frame_constants(c1: float, c2: float, c3: float, n: float) -> FrameConstants:
    """Blinn's per-frame values for one material: ``k1 = 1/(c3^2 - 1)``, ``k2 = k1 + 1``."""
    k1 = 1.0 / (c3 * c3 - 1.0)  # Blinn 1977, "Computational considerations", k1 = 1/(c3^2 - 1)
    return FrameConstants(c1=float(c1), c1_integer=max(1, int(round(c1))), c2=float(c2),
                          k1=k1, k2=k1 + 1.0, n2_minus_1=n * n - 1.0)


# --- the terms, as Blinn prints them ----------------------------------------------------------
# Each takes (N.H, N.L, N.E, E.H, per-frame constants, ops).

def _d1_pow(NH, NL, NE, EH, k, ops):
    return ops.pow(NH, k.c1)  # Blinn 1977, D1 = cos^c1 alpha, cos alpha = N.H


def _d1_squaring(NH, NL, NE, EH, k, ops):
    # Blinn 1977, D1 = cos^c1 alpha with c1 an integer: binary powering, a multiply per
    # squaring and one per further set bit of c1
    result, power, exponent = None, NH, k.c1_integer
    while exponent:
        if exponent & 1:
            result = power if result is None else result * power
        exponent >>= 1
        if exponent:
            power = power * power
    return result


def _d2(NH, NL, NE, EH, k, ops):
    a = ops.acos(NH) * k.c2  # Blinn 1977, D2 = exp(-(alpha c2)^2), alpha = acos(N.H)
    return ops.exp(-(a * a))


def _d3(NH, NL, NE, EH, k, ops):
    q = k.k2 / (NH * NH + k.k1)  # Blinn 1977, "Computational considerations": D3 = (k2 / (cos^2 alpha + k1))^2
    return q * q


def _g(NH, NL, NE, EH, k, ops):
    G_b = 2.0 * NH * NE / EH  # Blinn 1977, G_b = 2 (N.H)(N.E) / (E.H)
    G_c = 2.0 * NH * NL / EH  # Blinn 1977, G_c = 2 (N.H)(N.L) / (E.H)
    return ops.minimum(ops.minimum(1.0, G_b), G_c)  # "the minimum of G_a, G_b and G_c", G_a = 1


def _one_over_ne(NH, NL, NE, EH, k, ops):
    return 1.0 / NE  # Blinn 1977, s = D G F / (N.E): the 1/(N.E) term


def _g_over_ne(NH, NL, NE, EH, k, ops):
    # Blinn 1977, "Computational considerations": the minimum found before the divisions
    # (the last one read as 2(N.H)(N.L) / ((E.H)(N.E)), as reflectance.optics.shadowing does)
    return ops.branch(
        NE < NL,
        lambda: ops.branch(2.0 * NE * NH < EH, lambda: 2.0 * NH / EH, lambda: 1.0 / NE),
        lambda: ops.branch(2.0 * NL * NH < EH, lambda: 2.0 * NH * NL / (EH * NE),
                           lambda: 1.0 / NE))


def _fresnel(NH, NL, NE, EH, k, ops):
    c = EH
    g = ops.sqrt(k.n2_minus_1 + c * c)  # Blinn 1977, g = sqrt(n^2 + c^2 - 1), c = E.H
    minus, plus = g - c, g + c
    u, v = c * plus - 1.0, c * minus + 1.0
    # Blinn 1977, F = (g - c)^2 / (g + c)^2 [1 + (c (g + c) - 1)^2 / (c (g - c) + 1)^2] (as printed,
    # without Cook & Torrance's 1/2: the same operations)
    return minus * minus / (plus * plus) * (1.0 + u * u / (v * v))


def _torrance_sparrow(NH, NL, NE, EH, k, ops):
    # Blinn 1977, s = D G F / (N.E), D3 and G/(N.E) as in "Computational considerations"
    return _d3(NH, NL, NE, EH, k, ops) * _g_over_ne(NH, NL, NE, EH, k, ops) \
        * _fresnel(NH, NL, NE, EH, k, ops)


def _torrance_sparrow_f_per_frame(NH, NL, NE, EH, k, ops, F=1.0):
    # Blinn 1977: with E = (0 0 -1) and L at infinity, E.H and so F are computed "only once per
    # change in light source direction": per pixel, one multiply by F
    return _d3(NH, NL, NE, EH, k, ops) * _g_over_ne(NH, NL, NE, EH, k, ops) * F


class Term(NamedTuple):
    """One row of the table: a formula as printed, where Blinn prints it, and its code."""

    label: str
    printed: str
    where: str
    formula: Callable[..., Any]


#: every term and the two highlights, by key, in the table's order
TERMS: dict[str, Term] = {
    "D1_pow": Term("D1 (pow)", "cos^c1 alpha", "Facet distribution functions", _d1_pow),
    "D1_squaring": Term("D1 (repeated squaring)", "cos^c1 alpha, c1 an integer",
                        "Facet distribution functions", _d1_squaring),
    "D2": Term("D2", "exp(-(alpha c2)^2), alpha = acos(N.H)", "Facet distribution functions", _d2),
    "D3": Term("D3", "(k2 / (cos^2 alpha + k1))^2", "Computational considerations", _d3),
    "G": Term("G", "min(1, G_b, G_c), G_b = 2(N.H)(N.E)/(E.H), G_c = 2(N.H)(N.L)/(E.H)",
              "Torrance-Sparrow model", _g),
    "one_over_NE": Term("1/(N.E)", "s = DGF/(N.E)", "Torrance-Sparrow model", _one_over_ne),
    "G_over_NE": Term("G/(N.E)", "minimum before the divisions (if ... then G := ...)",
                      "Computational considerations", _g_over_ne),
    "F": Term("F", "(g-c)^2/(g+c)^2 [1 + (c(g+c)-1)^2/(c(g-c)+1)^2], g = sqrt(n^2+c^2-1)",
              "Computational considerations", _fresnel),
    "phong": Term("Phong highlight", "s = (N.H)^c1 (D1, pow)", "Simple hilight models", _d1_pow),
    "torrance_sparrow": Term("Torrance-Sparrow highlight", "s = D3 G F / (N.E), F per pixel",
                             "Torrance-Sparrow model", _torrance_sparrow),
    "torrance_sparrow_F_per_frame": Term(
        "Torrance-Sparrow highlight, F per frame", "s = D3 G F / (N.E), E and L at infinity",
        "Computational considerations", _torrance_sparrow_f_per_frame),
}

#: points (N.H, N.L, N.E, E.H) that take every arm of G/(N.E)'s branches (N.E < N.L or not,
#: the minimum below 1 or not): a term's count is that of its costliest path over these
_BRANCH_POINTS = ((0.8, 0.9, 0.1, 0.5), (0.9, 0.9, 0.6, 0.7), (0.8, 0.1, 0.9, 0.5),
                  (0.9, 0.6, 0.9, 0.7))


def count_term(key: str, k: FrameConstants) -> tuple[dict[str, int], list[str]]:
    """Operations of one term of :data:`TERMS` per evaluation, on its costliest path.

    Returns the counts (:data:`OPERATIONS`) and the transcendental functions it calls.

    Examples
    --------
    >>> counts, calls = count_term("D3", frame_constants(10.0, 2.0, 0.35, 1.8))
    >>> counts["multiplies"], counts["adds"], counts["divides"], calls
    (2, 1, 1, [])
    """
    tallies = []
    for point in _BRANCH_POINTS:
        tally = Tally()
        TERMS[key].formula(*(Counted(x, tally) for x in point), k, COUNTING)
        tallies.append(tally)
    worst = max(tallies, key=lambda t: sum(t.counts.values()))  # the first of the costliest
    return worst.counts, worst.calls


def count_table(k: FrameConstants) -> list[dict[str, Any]]:
    """One row per term of :data:`TERMS`: its counts, ``arithmetic`` (every counted operation
    but the transcendental calls, each as one) and ``calls``."""
    rows = []
    for key, term in TERMS.items():
        counts, calls = count_term(key, k)
        arithmetic = sum(counts[op] for op in OPERATIONS if op != "transcendental")
        rows.append({"term": key, "label": term.label, "printed": term.printed,
                     "blinn_1977_section": term.where, **counts, "arithmetic": arithmetic,
                     "calls": " ".join(calls)})
    return rows


# --- timing ------------------------------------------------------------------------------------

def sample_dot_products(n: int, seed: int) -> dict[str, np.ndarray]:
    """``N.H``, ``N.L``, ``N.E``, ``E.H`` of ``n`` random light and eye directions, each uniform
    over the hemisphere about ``N = z`` (all four cosines > 0)."""
    rng = np.random.default_rng(seed)

    def directions():
        z = 1.0 - rng.random(n)  # (0, 1]
        phi = 2.0 * np.pi * rng.random(n)
        r = np.sqrt(1.0 - z * z)
        return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=-1)

    L, E = directions(), directions()
    H = L + E
    H /= np.linalg.norm(H, axis=-1, keepdims=True)  # Blinn 1977, H = (L + E) / len(L + E)
    return {"NH": H[:, 2], "NL": L[:, 2], "NE": E[:, 2], "EH": np.sum(E * H, axis=-1)}


def formula_terms(samples: Mapping[str, np.ndarray],
                  k: FrameConstants) -> dict[str, Callable[[], Any]]:
    """Each term of :data:`TERMS` as counted, on numpy arrays: ``{key: function of nothing}``."""
    args = (samples["NH"], samples["NL"], samples["NE"], samples["EH"], k, NUMPY)
    return {key: functools.partial(term.formula, *args) for key, term in TERMS.items()}


def project_terms(samples: Mapping[str, np.ndarray], c1: float, c2: float, c3: float, n: float,
                  p_s: float, p_d: float) -> dict[str, tuple[str, Callable[[], Any]]]:
    """The project's own implementation of each term (where it has one): ``{key: (its name,
    function of nothing)}``; the highlights are composed of the terms' functions, and the two
    models' BRDFs are timed whole."""
    from reflectance.optics.brdf import brdf_BlinnPhong1977, brdf_TorranceSparrow_Blinn1977
    from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982
    from reflectance.optics.microfacet import (distribution_Phong1975,
                                               distribution_TorranceSparrow1967,
                                               distribution_TrowbridgeReitz1975)
    from reflectance.optics.shadowing import G_over_NE_Blinn1977, shadowing_VCavity_Blinn1977

    NH, NL, NE, EH = (samples[name] for name in ("NH", "NL", "NE", "EH"))
    F_of = lambda c: fresnel_dielectric_CookTorrance1982(c, n)  # noqa: E731
    F_frame = float(F_of(1.0))  # one value for every pixel, as Blinn's E and L at infinity give
    return {
        "D1_pow": ("distribution_Phong1975", lambda: distribution_Phong1975(NH, c1)),
        "D2": ("distribution_TorranceSparrow1967", lambda: distribution_TorranceSparrow1967(NH, c2)),
        "D3": ("distribution_TrowbridgeReitz1975", lambda: distribution_TrowbridgeReitz1975(NH, c3)),
        "G": ("shadowing_VCavity_Blinn1977", lambda: shadowing_VCavity_Blinn1977(NL, NE, NH, EH)),
        "G_over_NE": ("G_over_NE_Blinn1977", lambda: G_over_NE_Blinn1977(NL, NE, NH, EH)),
        "F": ("fresnel_dielectric_CookTorrance1982", lambda: F_of(EH)),
        "phong": ("distribution_Phong1975", lambda: distribution_Phong1975(NH, c1)),
        "torrance_sparrow": (
            "D3 x G_over_NE x F", lambda: distribution_TrowbridgeReitz1975(NH, c3)
            * G_over_NE_Blinn1977(NL, NE, NH, EH) * F_of(EH)),
        "torrance_sparrow_F_per_frame": (
            "D3 x G_over_NE x F(frame)", lambda: distribution_TrowbridgeReitz1975(NH, c3)
            * G_over_NE_Blinn1977(NL, NE, NH, EH) * F_frame),
        "brdf_phong": ("brdf_BlinnPhong1977",
                       lambda: brdf_BlinnPhong1977(NL, NE, NH, p_d=p_d, p_s=p_s, c1=c1)),
        "brdf_torrance_sparrow": (
            "brdf_TorranceSparrow_Blinn1977",
            lambda: brdf_TorranceSparrow_Blinn1977(NL, NE, NH, EH, F_of, p_d=p_d, p_s=p_s,
                                                   distribution="TrowbridgeReitz1975", c3=c3)),
    }


def time_per_evaluation(functions: Mapping[str, Callable[[], Any]], n: int,
                        repeats: int) -> dict[str, float]:
    """Nanoseconds per evaluation of each function of ``n`` samples: the best of ``repeats``
    timings, taken in turn (each repeat times every function once, so that a change of the
    machine's load falls on all of them), after one call each that is not timed."""
    for function in functions.values():
        function()
    best = dict.fromkeys(functions, math.inf)
    for _ in range(repeats):
        for key, function in functions.items():
            start = time.perf_counter()
            function()
            best[key] = min(best[key], time.perf_counter() - start)
    return {key: seconds / n * 1e9 for key, seconds in best.items()}


def timing_verdict(ratio: float, holds_at_most: float, fails_at_least: float) -> str:
    """Blinn's "no increase in computation time", read from a time ratio (Torrance-Sparrow
    highlight over Phong's): ``"holds"`` up to ``holds_at_most``, ``"fails"`` from
    ``fails_at_least``, ``"within the timing noise"`` between (a margin wider than the spread of
    the best-of-repeats ratio, so that a rerun on the same machine gives the same word).

    Examples
    --------
    >>> [timing_verdict(r, 1.1, 1.5) for r in (0.9, 1.3, 4.0)]
    ['holds', 'within the timing noise', 'fails']
    """
    if not holds_at_most < fails_at_least:
        raise ValueError(f"holds_at_most ({holds_at_most}) must be below fails_at_least "
                         f"({fails_at_least})")
    if ratio <= holds_at_most:
        return "holds"
    if ratio >= fails_at_least:
        return "fails"
    return "within the timing noise"
