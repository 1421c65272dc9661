"""CAM16 and CAM16-UCS in numpy (reflectance.colour.appearance) against colour-science's own."""

import math

import colour
import numpy as np
import pytest

from reflectance.colour.appearance import XYZ_to_CAM16, XYZ_to_CAM16UCS

VIEWING = {"L_A": 64 / math.pi * 0.2, "Y_b": 20.0}


@pytest.mark.parametrize("surround", ["Average", "Dim", "Dark"])
def test_cam16_equals_colour_science(surround):
    XYZ = np.random.default_rng(3).uniform(0.1, 100.0, (500, 3))
    XYZ_w = np.array([95.047, 100.0, 108.883])
    mine = XYZ_to_CAM16(XYZ, XYZ_w, surround=surround, **VIEWING)
    ref = colour.XYZ_to_CAM16(XYZ, XYZ_w, surround=colour.VIEWING_CONDITIONS_CAM16[surround],
                              **VIEWING)
    for name in "JChM":
        np.testing.assert_allclose(mine[name], getattr(ref, name), rtol=1e-9, atol=1e-9)


def test_cam16ucs_equals_colour_science_on_its_0_to_1_scale():
    """colour-science's XYZ_to_CAM16UCS takes XYZ and XYZ_w with Y_w = 1 (it multiplies both by
    100); ours takes the Y_w = 100 scale of XYZ_to_CAM16."""
    XYZ = np.random.default_rng(4).uniform(0.001, 1.0, (500, 3))
    XYZ_w = np.array([0.95047, 1.0, 1.08883])
    ref = colour.XYZ_to_CAM16UCS(XYZ, XYZ_w=XYZ_w,
                                 surround=colour.VIEWING_CONDITIONS_CAM16["Average"], **VIEWING)
    np.testing.assert_allclose(XYZ_to_CAM16UCS(100 * XYZ, 100 * XYZ_w, **VIEWING), ref,
                               rtol=1e-9, atol=1e-9)


def test_audit_cam16_difference_is_colour_sciences():
    """The `reflectance audit` column dE_CAM16UCS_vs_exact, recomputed with colour-science."""
    from reflectance.audit.shortcuts import audit_table, resolve_material
    from reflectance.colour.colorimetry import tristimulus_weights

    grid = np.arange(360.0, 831.0, 5.0)
    W = tristimulus_weights(grid, "D65", "CIE 1931 2 Degree Standard Observer")
    table = audit_table(resolve_material("Au", grid), [0, 60, 85], W, methods=["exact", "schlick"])
    XYZ = np.stack([table["X"], table["Y"], table["Z"]], -1)
    white = W.sum(axis=0)
    ucs = colour.XYZ_to_CAM16UCS(XYZ, XYZ_w=white, L_A=VIEWING["L_A"], Y_b=VIEWING["Y_b"],
                                 surround=colour.VIEWING_CONDITIONS_CAM16["Average"])
    dE = np.linalg.norm(ucs[3:] - ucs[:3], axis=-1)
    np.testing.assert_allclose(table["dE_CAM16UCS_vs_exact"][3:], dE, rtol=1e-8, atol=1e-10)
    assert dE[-1] > 1  # schlick at 85 degrees: a visible difference
