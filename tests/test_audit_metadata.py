"""The metadata file beside every audit of the workflow (issue 26, part 4): what each audit's
tables were computed from (illuminant, observer, wavelength grid, the SHA-256 of every input, the
package's version, the unit of every column), checked against config.yaml and the inputs' own
bytes in the session's build."""

import csv
import hashlib

import pytest
import yaml

import reflectance

pytestmark = pytest.mark.workflow

#: audit -> its CSV tables (the metadata file is results/audits/<audit>_metadata.yaml)
AUDITS = {
    "fresnel_atlas": ["fresnel_atlas.csv", "fresnel_atlas_thresholds.csv"],
    "rgb_rendering": ["rgb_rendering.csv"],
    "gamut_mapping": ["gamut_mapping.csv", "gamut_mapping_images.csv"],
    "spectral_sampling": ["spectral_sampling.csv"],
    "illuminant_observer": ["illuminant_observer.csv"],
    "spectral_recovery": ["spectral_recovery.csv"],
    "white_furnace": ["white_furnace.csv"],
}


def sha256(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def config_grid(config):
    w = config["wavelengths"]
    return {"start": w["start_nm"], "end": w["end_nm"], "step": w["step_nm"]}


@pytest.fixture(scope="module")
def metadata(built):
    return {name: yaml.safe_load((built / "results/audits" / f"{name}_metadata.yaml").read_text())
            for name in AUDITS}


@pytest.fixture(scope="module")
def config(built):
    return yaml.safe_load((built / "config.yaml").read_text())


@pytest.mark.parametrize("name", AUDITS)
def test_each_audit_says_its_version_inputs_and_columns(built, metadata, name):
    doc = metadata[name]
    assert doc["format"] == "reflectance audit metadata 1"
    assert doc["command"] == f"snakemake rule audit_{name}"
    assert doc["reflectance"] == reflectance.__version__
    # every input's hash is the hash of that file's bytes in the build
    for path, digest in doc["inputs"].items():
        assert digest == sha256(built / path), path
    # every table: its hash, and every column of its header with a unit, in order
    assert sorted(doc["tables"]) == sorted(AUDITS[name])
    for table in AUDITS[name]:
        path = built / "results/audits" / table
        assert doc["tables"][table] == sha256(path)
        with open(path, newline="") as stream:
            header = next(csv.reader(stream))
        assert list(doc["columns"][table]) == header
        assert all(column["unit"] for column in doc["columns"][table].values())


@pytest.mark.parametrize("name", ["fresnel_atlas", "spectral_sampling", "illuminant_observer",
                                  "spectral_recovery"])
def test_spectrum_audits_list_exactly_their_materials(metadata, config, name):
    expected = {f"spectra/{m}.csv" for m in config["audits"][name]["materials"]}
    assert set(metadata[name]["inputs"]) == expected


def test_the_illuminant_observer_and_grid_are_the_configs(metadata, config):
    colour, grid, audits = config["colour"], config_grid(config), config["audits"]
    for name in ("fresnel_atlas", "rgb_rendering"):
        doc = metadata[name]
        assert (doc["illuminant"], doc["observer"]) == (colour["illuminant"], colour["observer"])
        assert doc["wavelengths_nm"] == grid
    metals = config["figures"]["cook_torrance_1982"]["fig7"]["metals"]
    assert set(metadata["rgb_rendering"]["inputs"]) == {f"spectra/{m['material']}.csv"
                                                       for m in metals}

    io = metadata["illuminant_observer"]
    cfg = audits["illuminant_observer"]
    assert io["illuminant"]["reference"] == cfg["reference_illuminant"]
    assert io["illuminant"]["others"] == cfg["illuminants"]
    assert [io["observer"]["reference"], io["observer"]["other"]] == cfg["observers"]
    assert io["wavelengths_nm"] == grid

    rec = metadata["spectral_recovery"]
    assert rec["illuminant"] == audits["spectral_recovery"]["illuminants"]
    assert rec["observer"] == colour["observer"] and rec["wavelengths_nm"] == grid

    sampling, cfg = metadata["spectral_sampling"], audits["spectral_sampling"]
    assert (sampling["illuminant"], sampling["observer"]) == (colour["illuminant"],
                                                             colour["observer"])
    lo, hi = cfg["range_nm"]
    steps = [cfg["reference_step_nm"], *cfg["steps_nm"]]
    grids = [g for g in sampling["wavelengths_nm"].values() if isinstance(g, dict)]
    assert grids == [{"start": lo, "end": hi, "step": step} for step in steps]
    assert cfg["three_wavelengths_nm"] in sampling["wavelengths_nm"].values()

    # the rendered figures' EXRs, each hashed; the colorimetry their headers name is the config's
    gamut = metadata["gamut_mapping"]
    assert gamut["inputs"] and all(path.endswith(".exr") for path in gamut["inputs"])
    assert gamut["illuminant"] == colour["illuminant"]
    assert gamut["observer"] == colour["observer"]
    assert gamut["wavelengths_nm"] == grid

    # the white furnace is achromatic (F = 1): no light, no observer, no grid, no input
    furnace = metadata["white_furnace"]
    assert (furnace["illuminant"], furnace["observer"], furnace["wavelengths_nm"]) == \
        (None, None, None)
    assert furnace["inputs"] == {}
