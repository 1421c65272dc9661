"""config.yaml checks beyond the schema: each problem names its key and the known choices."""

import copy
import json

import pytest
import yaml

from reflectance.config import (SCHEMA_PATH, ConfigError, check_config, unknown_keys,
                                validate_schema)


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


def _open_mappings(node, pointer=""):
    """JSON pointers of the schema's object schemas that do not close their keys."""
    found = []
    if isinstance(node, dict):
        is_object = node.get("type") == "object" or "properties" in node
        if is_object and "additionalProperties" not in node and "$ref" not in node:
            found.append(pointer)
        for key, value in node.items():
            found += _open_mappings(value, f"{pointer}/{key}")
    elif isinstance(node, list):
        for i, value in enumerate(node):
            found += _open_mappings(value, f"{pointer}/{i}")
    return found


def test_every_mapping_of_the_schema_is_closed():
    """additionalProperties on every mapping, except the three whose keys are checked in code:
    keyword arguments of a library function and a scene geometry (reflectance.config)."""
    from reflectance.config import KEYWORD_MAPPINGS, SCENE_MAPPINGS

    schema = json.loads(SCHEMA_PATH.read_text())
    open_ = sorted(p.rsplit("/", 1)[-1] for p in _open_mappings(schema))
    assert open_ == ["object", "parameters", "watch"]
    assert {p[-1] for p in KEYWORD_MAPPINGS} | {p[-1] for p in SCENE_MAPPINGS} == set(open_)


def test_a_key_added_to_the_schema_is_accepted(config):
    """The schema is the one list of allowed keys: adding a key there is all it takes."""
    schema = copy.deepcopy(json.loads(SCHEMA_PATH.read_text()))
    fig6 = schema["properties"]["figures"]["properties"]["cook_torrance_1982"]["properties"]["fig6"]
    bad = copy.deepcopy(config)
    bad["figures"]["cook_torrance_1982"]["fig6"]["exposure"] = 1.0
    assert len(unknown_keys(bad, schema)) == 1
    assert unknown_keys(bad, schema)[0].startswith(
        "unknown key 'figures.cook_torrance_1982.fig6.exposure'")
    fig6["properties"]["exposure"] = {"type": "number"}
    assert unknown_keys(bad, schema) == []
    assert unknown_keys(config) == []


def test_unknown_key_without_a_close_match_lists_the_known_keys(config):
    bad = copy.deepcopy(config)
    bad["colour"]["zzz"] = 1
    assert unknown_keys(bad) == ["unknown key 'colour.zzz' (known: illuminant, observer, space, "
                                 "gamut_clip, png_bit_depth, linear_rgb_exr)"]


def test_a_material_whose_spectrum_is_not_made_yet_passes(config, root, tmp_path):
    """A new material in config.yaml used by a rendered figure: its CSV is written by a job, so
    the scene check at parse time must not refuse it."""
    good = copy.deepcopy(config)
    good["materials"]["Teal"] = {"source": "munsell", "notation": "5BG 5/6",
                                 "reason": "a test pigment"}
    good["figures"]["cook_torrance_1982"]["fig6"]["panels"]["a"]["diffuse_material"] = "Teal"
    assert not (root / "spectra" / "Teal.csv").exists()
    validate_schema(good)
    check_config(good, check_spectra=False, spectra_dir=root / "spectra")
    # a name that no job makes is refused, naming the key
    good["figures"]["cook_torrance_1982"]["fig6"]["panels"]["a"]["diffuse_material"] = "Teel"
    with pytest.raises(ConfigError, match=r"fig6\.panels\.a\.diffuse_material: unknown material "
                                          r"'Teel'"):
        check_config(good, check_spectra=False, spectra_dir=root / "spectra")
