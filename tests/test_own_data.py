"""The user's own spectra in the workflow: `materials.<Name>: {source: file, path, units}`."""

import copy

import numpy as np
import pytest
import yaml

from reflectance.config import ConfigError, check_config, validate_schema
from reflectance.optics.spectra import load_material, read_spectrum_csv, sources_table

NM = "wavelength_nm,n,k\n350,0.5,2.5\n600,0.4,3.0\n850,0.3,4.0\n"
UM = "wl,n,k\n0.35,0.5,2.5\n0.6,0.4,3.0\n0.85,0.3,4.0\n"
REFLECTANCE = "wavelength_nm,reflectance\n350,0.2\n850,0.6\n"


@pytest.fixture(scope="module")
def config(root):
    return yaml.safe_load((root / "config.yaml").read_text())


def with_material(config, **entry):
    c = copy.deepcopy(config)
    c["materials"]["Mine"] = {"source": "file", **entry}
    return c


@pytest.mark.parametrize("text, units", [(NM, "nm"), (UM, "um"), (REFLECTANCE, "nm")])
def test_own_file_is_accepted(config, tmp_path, text, units):
    path = tmp_path / "mine.csv"
    path.write_text(text)
    c = with_material(config, path=str(path), units=units, reference="my lab, 2026")
    validate_schema(c)
    check_config(c)


@pytest.mark.parametrize("text, units, entry, says", [
    (NM, "nm", {"units": "mm"}, "units"),                                   # schema
    (NM, "nm", {"colour": "red"}, "colour"),                                # schema: no extras
    (None, "nm", {}, "no such spectrum file"),
    ("wavelength_nm,n\n400,1\n500,1\n", "nm", {}, "line 1 (header)"),
    (NM, "um", {}, "says nm but the file is declared in um"),
    (UM.replace("0.85", "850"), "um", {}, "micrometres"),
    (NM.replace("850,", "700,"), "nm", {}, "the grid 360-830 nm leaves the data of materials.Mine"),
])
def test_bad_own_file_is_named(config, tmp_path, text, units, entry, says):
    path = tmp_path / "mine.csv"
    if text is not None:
        path.write_text(text)
    c = with_material(config, path=str(path), units=units)
    c["materials"]["Mine"].update(entry)
    with pytest.raises(Exception) as err:
        validate_schema(c)
        check_config(c)
    assert "Mine" in str(err.value) and says in str(err.value), str(err.value)


def test_own_file_inside_spectra_is_refused(config, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "spectra").mkdir()
    (tmp_path / "spectra" / "Mine.csv").write_text(NM)
    c = with_material(config, path="spectra/Mine.csv", units="nm")
    with pytest.raises(ConfigError, match=r"materials\.Mine\.path: .*outside spectra/"):
        check_config(c, check_spectra=False)


def test_micrometre_file_reads_as_the_nanometre_one(tmp_path, grid):
    (tmp_path / "a.csv").write_text(NM)
    (tmp_path / "b.csv").write_text(UM)
    a, b = read_spectrum_csv(tmp_path / "a.csv", "nm"), read_spectrum_csv(tmp_path / "b.csv", "um")
    assert np.allclose(a.to_numpy(), b.to_numpy(), rtol=1e-12)
    # the table the import rule writes loads like any bundled material
    (tmp_path / "Mine.csv").write_text(NM)
    m = load_material("Mine", grid, spectra_dir=tmp_path)
    assert m.kind == "measured" and m.n[0] == pytest.approx(0.5 - 0.1 * 10 / 250, rel=1e-12)


def test_sources_table_names_the_file(tmp_path):
    (tmp_path / "Mine.csv").write_text(REFLECTANCE)
    t = sources_table({"Mine": {"source": "file", "path": "data/mine.csv", "units": "nm",
                                "reference": "my lab"}}, spectra_dir=tmp_path)
    row = t.iloc[0]
    assert row.dataset == "file data/mine.csv" and row.kind == "derived"
    assert row.reference == "my lab" and "k = 0" in row.notes
