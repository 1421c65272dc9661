"""config.yaml checks beyond the schema: each problem names its key and the known choices."""

import copy

import pytest
import yaml

from reflectance.config import ConfigError, check_config, validate_schema


@pytest.fixture(scope="module")
def config(root):
    return yaml.safe_load((root / "config.yaml").read_text())


def test_the_project_config_is_valid(config):
    validate_schema(config)
    check_config(config)


def test_unknown_ambient_reading_is_named(config):
    bad = copy.deepcopy(config)
    bad["figures"]["cook_torrance_1982"]["fig8"]["ambient_reading"] = "nope"
    with pytest.raises(ConfigError, match=r"fig8\.ambient_reading: 'nope'.*known: as_printed"):
        check_config(bad, check_spectra=False)


def test_unknown_table1_row_is_named(config):
    bad = copy.deepcopy(config)
    parts = bad["figures"]["cook_torrance_1982"]["fig8"]["parts"]
    part = next(name for name, spec in parts.items() if "table1" in spec)
    parts[part]["table1"] = "Cheese"
    with pytest.raises(ConfigError, match=rf"fig8\.parts\.{part}\.table1: 'Cheese' is not a row"):
        check_config(bad, check_spectra=False)


def test_grid_outside_a_dataset_is_named(config):
    bad = copy.deepcopy(config)
    bad["wavelengths"]["end_nm"] = 900
    with pytest.raises(ConfigError, match=r"wavelengths: the grid 360-900 nm leaves the data"):
        check_config(bad)
