"""colour-science's spectral objects accepted where a spectrum is taken (issue 27, part 4): a
``SpectralDistribution`` or ``MultiSpectralDistributions`` gives the same numbers as the same data
read from a CSV file, and colour-science's own colorimetry agrees with ours on it."""

import colour
import numpy as np
import pandas as pd
import pytest

from reflectance.audit.shortcuts import audit_table, audit_weights, resolve_material
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.optics.spectra import (SpectraError, material_from_file, material_from_table,
                                        wavelength_grid)

GRID = wavelength_grid(380, 780, 5)


def _same(a, b):
    assert (a.kind, a.name) == (b.kind, b.name)
    for field in ("wavelengths", "n", "k", "F0"):
        np.testing.assert_array_equal(getattr(a, field), getattr(b, field))


def test_measured_index_as_multi_spectral_distributions(root):
    """Cu's n, k as colour-science's MultiSpectralDistributions: the Material of the CSV."""
    data = pd.read_csv(root / "spectra" / "Cu.csv")
    msds = colour.MultiSpectralDistributions(data[["n", "k"]].to_numpy(),
                                             data.wavelength_nm.to_numpy(), labels=["n", "k"],
                                             name="Cu")
    from_csv = material_from_file(root / "spectra" / "Cu.csv", GRID, "Cu")
    _same(material_from_table("Cu", msds, GRID), from_csv)
    _same(resolve_material(msds, GRID), from_csv)
    # (the labels in another order, and a third label, change nothing)
    shuffled = colour.MultiSpectralDistributions(data[["k", "n", "n"]].to_numpy(),
                                                 data.wavelength_nm.to_numpy(),
                                                 labels=["k", "n", "other"], name="Cu")
    _same(material_from_table("Cu", shuffled, GRID), from_csv)


def test_colour_science_reflectance_as_spectral_distribution(tmp_path):
    """A ColorChecker patch (colour-science's data) as a SpectralDistribution: the Material of
    the same values written to a CSV, and its F0 colour under D65 as colour.sd_to_XYZ gives it."""
    sd = colour.SDS_COLOURCHECKERS["ColorChecker N Ohta"]["dark skin"]
    path = tmp_path / "dark_skin.csv"
    pd.DataFrame({"wavelength_nm": sd.wavelengths, "reflectance": sd.values}).to_csv(
        path, index=False, float_format="%.17g")
    from_sd = material_from_table("dark skin", sd, GRID)
    _same(from_sd, material_from_file(path, GRID, "dark skin"))
    _same(resolve_material(sd, GRID), from_sd)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(380, 780, 5))
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(cmfs.shape)
    expected = colour.sd_to_XYZ(sd.copy().align(cmfs.shape), cmfs, d65,
                                method="Integration") / 100
    np.testing.assert_allclose(from_sd.F0 @ tristimulus_weights(GRID, "D65"), expected,
                               rtol=1e-12)
    # the audit takes it too: the same table as from the file
    W, observer = audit_weights(GRID, "D65", "2")
    angles = np.array([0.0, 45.0, 80.0])
    by_sd = audit_table(resolve_material(sd, GRID), angles, W, observer=observer)
    by_file = audit_table(resolve_material(str(path), GRID), angles, W, observer=observer)
    for column in by_file:
        if column != "material":
            np.testing.assert_array_equal(np.asarray(by_sd[column]), np.asarray(by_file[column]))


def test_illuminant_as_spectral_distribution(tmp_path):
    """Illuminant A as colour-science's SpectralDistribution: the weights of its name, and of
    the same SPD as a CSV file (audit_weights' file route)."""
    sd = colour.SDS_ILLUMINANTS["A"]
    np.testing.assert_allclose(tristimulus_weights(GRID, sd), tristimulus_weights(GRID, "A"),
                               rtol=1e-12)
    path = tmp_path / "A.csv"
    pd.DataFrame({"wavelength_nm": sd.wavelengths, "A": sd.values}).to_csv(
        path, index=False, float_format="%.17g")
    by_sd, name = audit_weights(GRID, sd, "10")
    np.testing.assert_array_equal(by_sd, audit_weights(GRID, str(path), "10")[0])
    assert name == "CIE 1964 10 Degree Standard Observer"
    short = colour.SpectralDistribution({500: 1.0, 600: 1.0}, name="narrow")
    with pytest.raises(ValueError, match="illuminant 'narrow': covers 500-600 nm"):
        tristimulus_weights(GRID, short)


def test_unlabelled_multi_spectral_distributions_are_refused():
    msds = colour.MultiSpectralDistributions(np.ones((3, 2)), [400, 500, 600], labels=["a", "b"],
                                             name="two")
    with pytest.raises(SpectraError, match=r"labels \['a', 'b'\]; expected 'n' and 'k'"):
        material_from_table("two", msds, wavelength_grid(400, 600, 50))
