"""The user's own spectra in the workflow: `materials.<Name>: {source: file, path, units}`."""

import copy
import re

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
def test_own_file_is_accepted(config, tmp_path, monkeypatch, text, units):
    monkeypatch.chdir(tmp_path)  # the project folder: the file's path is relative to it
    (tmp_path / "spectra").mkdir()  # (every spectrum pending: made by the jobs)
    (tmp_path / "data").mkdir()
    (tmp_path / "data" / "mine.csv").write_text(text)
    c = with_material(config, path="data/mine.csv", units=units, reference="my lab, 2026")
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
def test_bad_own_file_is_named(config, tmp_path, monkeypatch, text, units, entry, says):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "spectra").mkdir()
    path = tmp_path / "mine.csv"
    if text is not None:
        path.write_text(text)
    c = with_material(config, path="mine.csv", units=units)
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


#: where an own file may not lie: (path written in config.yaml, how it is made in the folder
#: tmp_path/outside beside the project tmp_path/project, what the message says)
LEAVING = [
    ("../outside/mine.csv", None, r"'\.\./outside/mine\.csv' leaves the project folder"),
    ("data/../../outside/mine.csv", None, r"leaves the project folder"),
    ("ABSOLUTE", None, r"is absolute; give a path inside the project folder"),
    ("data/link.csv", "data/link.csv", r"'data/link\.csv' leaves the project folder"),
    ("linked/mine.csv", "linked", r"'linked/mine\.csv' leaves the project folder"),
]


@pytest.mark.parametrize("value, link, says", LEAVING, ids=["dotdot", "dotdot-inside",
                                                           "absolute", "file-link", "folder-link"])
def test_own_file_outside_the_project_is_refused_unread(config, tmp_path, monkeypatch, value,
                                                        link, says):
    """README: the path is relative to the project folder. One leaving it (.., absolute, a
    symbolic link to a file or folder outside) is refused before it is read: the message names
    the key and never shows a line of the file (its header here is a secret)."""
    project, outside = tmp_path / "project", tmp_path / "outside"
    (project / "data").mkdir(parents=True)
    outside.mkdir()
    (outside / "mine.csv").write_text("secret-header-line,x\n1,2\n")
    if link == "data/link.csv":
        (project / link).symlink_to(outside / "mine.csv")
    elif link == "linked":
        (project / link).symlink_to(outside)
    if value == "ABSOLUTE":
        value = str(outside / "mine.csv")
    monkeypatch.chdir(project)
    c = with_material(config, path=value, units="nm")
    validate_schema(c)
    with pytest.raises(ConfigError) as err:
        check_config(c)
    message = str(err.value)
    assert re.search(rf"^config\.yaml: materials\.Mine\.path: .*{says}", message, re.M), message
    assert "secret" not in message and len(message.splitlines()) == 1, message


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
