"""reflectance.config.check_once: checks that passed are not repeated on the same inputs, and
are repeated (with their own error) as soon as anything they depend on changes."""

import copy
import json
import os

import pytest
import yaml

from reflectance import config as C


@pytest.fixture(scope="module")
def project_config(root):
    return yaml.safe_load((root / "config.yaml").read_text())


@pytest.fixture()
def counted(monkeypatch, tmp_path):
    """check_config and validate_schema replaced by stand-ins that count their calls and read
    ``data.txt`` (as the real checks read spectra and data files); ``fail`` makes them fail."""
    state = {"calls": 0, "fail": False, "data": tmp_path / "data.txt"}
    state["data"].write_text("1 2 3\n")

    def validate_schema(config, *args, **kwargs):
        state["calls"] += 1

    def check_config(config, **kwargs):
        with open(state["data"]) as f:
            f.read()
        if state["fail"]:
            raise C.ConfigError("config.yaml: figures.x: the same one-line error")

    monkeypatch.setattr(C, "validate_schema", validate_schema)
    monkeypatch.setattr(C, "check_config", check_config)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "spectra").mkdir()
    return state


@pytest.fixture(autouse=True)
def fresh_process(monkeypatch):
    """Each test starts as a new process would: no checks run yet (only those are recorded)."""
    monkeypatch.setattr(C, "_checked", False)


def run(config, state, **kwargs):
    C._checked = False  # each call stands for one `snakemake` process
    C.check_once(config, state["data"].parent / "record.json", **kwargs)
    return state["calls"]


def test_a_passed_check_is_not_repeated_on_the_same_inputs(counted):
    config = {"a": 1, "b": [1.0, 2.5]}
    assert run(config, counted) == 1
    assert run(config, counted) == 1
    assert run(copy.deepcopy(config), counted) == 1  # the same content


@pytest.mark.parametrize("change", [
    lambda c: c.update(a=2),
    lambda c: c.update(a=1.0),  # equal in Python, not the same config
    lambda c: c["b"].append(3.0),
    lambda c: c.update(z={"1": 2}),
])
def test_another_config_is_checked(counted, change):
    config = {"a": 1, "b": [1.0, 2.5]}
    run(config, counted)
    change(config)
    assert run(config, counted) == 2


def test_other_arguments_are_checked(counted):
    config = {"a": 1}
    run(config, counted)
    assert run(config, counted, check_scenes=False) == 2
    assert run(config, counted, check_scenes=False, memory=2**30) == 3
    assert run(config, counted, check_scenes=False, memory=2**30) == 3


def test_a_changed_file_that_the_checks_read_is_checked_again(counted):
    config = {"a": 1}
    run(config, counted)
    counted["data"].write_text("1 2 3 4\n")
    assert run(config, counted) == 2
    stat = counted["data"].stat()
    os.utime(counted["data"], ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))  # same size
    assert run(config, counted) == 3
    counted["data"].unlink()
    with pytest.raises(FileNotFoundError):
        run(config, counted)


def test_a_new_or_changed_spectrum_is_checked_again(counted, tmp_path):
    config = {"a": 1}
    run(config, counted)
    (tmp_path / "spectra" / "Cu.csv").write_text("wavelength_nm,R\n")  # a job wrote it
    assert run(config, counted) == 2
    assert run(config, counted) == 2
    (tmp_path / "spectra" / "Cu.csv").write_text("wavelength_nm,R\n400,0.5\n")
    assert run(config, counted) == 3


def test_in_a_folder_on_sys_path_only_what_an_import_could_find_counts(counted, tmp_path,
                                                                        monkeypatch):
    """Snakemake puts the workflow's folder on sys.path, so the import system lists it while the
    checks import: a build's results/ and logs/ there, which no import finds, repeat nothing; a
    module there named as one the checks import (here one they tried and did not find) does."""
    import importlib
    import sys

    search, name = tmp_path / "search", "reflectance_check_once_probe"
    search.mkdir()
    monkeypatch.syspath_prepend(str(search))
    stand_in = C.check_config

    def check_config(config, **kwargs):
        stand_in(config, **kwargs)
        try:
            __import__(name)  # as an import statement does
        except ImportError:
            pass

    monkeypatch.setattr(C, "check_config", check_config)
    config = {"a": 1}
    assert run(config, counted) == 1
    (search / "results").mkdir()
    (search / "logs").mkdir()
    assert run(config, counted) == 1
    (search / f"{name}.py").write_text("")
    importlib.invalidate_caches()
    try:
        assert run(config, counted) == 2
    finally:
        sys.modules.pop(name, None)


def test_an_environment_variable_of_the_project_is_part_of_the_key(counted, monkeypatch):
    config = {"a": 1}
    run(config, counted)
    monkeypatch.setenv("REFLECTANCE_CACHE", str(counted["data"].parent / "cache"))
    assert run(config, counted) == 2


def test_a_failed_check_is_never_recorded(counted):
    config = {"a": 1}
    counted["fail"] = True
    for calls in (1, 2):
        with pytest.raises(C.ConfigError, match=r"^config\.yaml: figures\.x: the same one-line "
                                                r"error$"):
            run(config, counted)
        assert counted["calls"] == calls
    assert not (counted["data"].parent / "record.json").exists()


def test_a_damaged_record_means_checking(counted):
    config = {"a": 1}
    run(config, counted)
    record = counted["data"].parent / "record.json"
    record.write_text("{not json")
    assert run(config, counted) == 2
    record.write_text(json.dumps({"key": 3, "files": [], "folders": None}))
    assert run(config, counted) == 3
    assert json.loads(record.read_text())["key"] != 3


def test_the_real_checks_name_a_bad_key_with_a_record_of_the_good_config(
        project_config, root, tmp_path, monkeypatch):
    """The project's config passes and is recorded; a one-key change is checked for real and
    gets the same error as validate_schema gives, every time."""
    monkeypatch.chdir(root)
    record = tmp_path / "record.json"
    C.check_once(project_config, record, check_spectra=False, check_scenes=False)
    assert json.loads(record.read_text())["files"]  # the files the checks read
    bad = copy.deepcopy(project_config)
    bad["colour"]["spaec"] = bad["colour"]["space"]
    with pytest.raises(C.ConfigError) as expected:
        C.validate_schema(bad)
    for _ in range(2):
        with pytest.raises(C.ConfigError) as got:
            C.check_once(bad, record, check_spectra=False, check_scenes=False)
        assert str(got.value) == str(expected.value)
        assert "colour.spaec" in str(got.value) and "\n" not in str(got.value)


def test_only_a_process_s_first_checks_are_recorded(counted):
    """A second check in one process reads from memory what the first loaded, so its record
    would miss files: it is not written (the first record stays)."""
    record = counted["data"].parent / "record.json"
    C.check_once({"a": 1}, record)
    kept = record.read_text()
    C.check_once({"a": 2}, record)  # checked (another config), not recorded
    assert counted["calls"] == 2 and record.read_text() == kept


def test_checks_without_scenes_import_no_colour_science_nor_vtk(root, tmp_path):
    """What a job's re-parse (cluster) and a config refused by the schema cost: the schema walk
    reads the watch's keywords without pyvista, the names and Munsell notations come from the
    colour-science cache (filled by the first run, checked on the second)."""
    import subprocess
    import sys
    from pathlib import Path

    import reflectance

    code = ("from reflectance.config import read_config, validate_schema, check_config\n"
            "c = read_config('config.yaml')\nvalidate_schema(c)\n"
            "check_config(c, check_spectra=False, check_scenes=False)\n")
    env = dict(os.environ, PYTHONPATH=str(Path(reflectance.__file__).resolve().parents[1]),
               REFLECTANCE_CACHE=str(tmp_path))
    for _ in range(2):
        result = subprocess.run([sys.executable, "-X", "importtime", "-c", code], cwd=root,
                                env=env, capture_output=True, text=True)
        assert result.returncode == 0, result.stderr[-2000:]
    imported = {line.rsplit("|", 1)[-1].strip().split(".")[0]
                for line in result.stderr.splitlines() if line.startswith("import time:")}
    assert not imported & {"colour", "pandas", "matplotlib", "vtk", "vtkmodules", "pyvista"}


def test_read_config_gives_what_the_pure_python_parser_gives(root, tmp_path):
    """config.yaml is parsed by libyaml; the values are those of PyYAML's own safe loader, and a
    key given twice is still named with its line (also twice on one line)."""
    text = (root / "config.yaml").read_text()
    assert C.read_config(root / "config.yaml") == yaml.load(text, Loader=yaml.SafeLoader)
    (tmp_path / "config.yaml").write_text("a: 1\nb:\n  c: 2\n  d: {x: 1, x: 2}\n")
    with pytest.raises(C.ConfigError, match=r"line 4, column 13: .*'x' given twice \(first on "
                                            r"line 4\)"):
        C.read_config(tmp_path / "config.yaml")
    (tmp_path / "config.yaml").write_text("a:\n\tb: 1\n")  # the pure-Python parser's words
    with pytest.raises(C.ConfigError, match=r"line 2, column 1: .*found character '\\t'"):
        C.read_config(tmp_path / "config.yaml")
