"""reflectance.io.provenance: the manifest's hashes, versions and git state, and its bytes."""

import json
import subprocess
import sys
from importlib.metadata import version

import pytest
import yaml

from reflectance.io.provenance import git_state, provenance, write_provenance


def sha256sum(path):
    """The coreutils tool's answer (independent of hashlib)."""
    return subprocess.run(["sha256sum", str(path)], capture_output=True, text=True,
                          check=True).stdout.split()[0]


@pytest.fixture
def project(tmp_path):
    (tmp_path / "results").mkdir()
    (tmp_path / "spectra").mkdir()
    (tmp_path / "results" / "a.csv").write_text("x,y\n1,2\n")
    (tmp_path / "results" / "b.png").write_bytes(bytes(range(256)) * 3)
    (tmp_path / "spectra" / "Cu.csv").write_text("wavelength_nm,n,k\n500,1,2\n")
    (tmp_path / "config.yaml").write_text("colour: {space: sRGB}\n")
    return tmp_path


def manifest(project, **kwargs):
    return provenance(["results/b.png", "results/a.csv"], ["spectra/Cu.csv"],
                      {"colour": {"space": "sRGB"}}, root=project, **kwargs)


def test_manifest_hashes_every_file_and_names_the_environment(project):
    m = manifest(project)
    assert list(m["outputs"]) == ["results/a.csv", "results/b.png"]  # sorted
    for name, digest in {**m["outputs"], **m["spectra"]}.items():
        assert digest == sha256sum(project / name), name
    assert m["config"]["file_sha256"] == sha256sum(project / "config.yaml")
    assert m["packages"]["numpy"] == version("numpy")
    assert m["packages"]["colour-science"] == version("colour-science")
    assert m["python"]["version"] == "%d.%d.%d" % sys.version_info[:3]
    assert m["git"] == {"commit": None, "dirty": None}  # not a repository


def test_manifest_follows_the_configuration_not_its_key_order(project):
    a = manifest(project)
    b = provenance(["results/a.csv", "results/b.png"], ["spectra/Cu.csv"],
                   json.loads('{"colour": {"space": "sRGB"}}'), root=project)
    c = provenance(["results/a.csv", "results/b.png"], ["spectra/Cu.csv"],
                   {"colour": {"space": "SMPTE-C"}}, root=project)
    assert a == b and a["config"]["resolved_sha256"] != c["config"]["resolved_sha256"]


def test_written_manifest_is_deterministic_yaml(project):
    write_provenance(project / "results" / "p1.yaml", manifest(project))
    write_provenance(project / "results" / "p2.yaml", manifest(project))
    one = (project / "results" / "p1.yaml").read_bytes()
    assert one == (project / "results" / "p2.yaml").read_bytes()
    assert yaml.safe_load(one) == manifest(project)
    (project / "results" / "a.csv").write_text("x,y\n1,3\n")  # an output changes: so does it
    write_provenance(project / "results" / "p2.yaml", manifest(project))
    assert (project / "results" / "p2.yaml").read_bytes() != one


def test_a_measurement_is_listed_not_hashed(project):
    """A timing (the workflow's MEASUREMENTS) differs from run to run: the manifest names it
    without its SHA-256, so a rerun that measures again writes the same manifest."""
    (project / "results" / "timing.csv").write_text("ns\n31.2\n")
    one = manifest(project, measurements=["results/timing.csv"])
    (project / "results" / "timing.csv").write_text("ns\n29.8\n")
    assert manifest(project, measurements=["results/timing.csv"]) == one
    assert one["measurements"] == ["results/timing.csv"]
    assert "results/timing.csv" not in one["outputs"]
    assert manifest(project)["measurements"] == []


def test_git_state_is_the_checkout_commit_and_dirty_flag(project):
    git = ["git", "-c", "user.name=t", "-c", "user.email=t@t", "-c", "commit.gpgsign=false"]
    run = lambda *a: subprocess.run([*git, *a], cwd=project, check=True, capture_output=True,  # noqa: E731
                                    text=True).stdout.strip()
    run("init", "-q")
    run("add", "config.yaml", "spectra")
    run("commit", "-qm", "first")
    head = run("rev-parse", "HEAD")
    assert git_state(project) == {"commit": head, "dirty": False}
    assert manifest(project)["git"] == {"commit": head, "dirty": False}
    (project / "config.yaml").write_text("colour: {space: SMPTE-C}\n")
    assert git_state(project) == {"commit": head, "dirty": True}
    # a folder inside the repository is not a checkout of its own
    assert git_state(project / "spectra") == {"commit": None, "dirty": None}


def _job(tmp_path, header, rule="audit_x"):
    """A stand-in for a job of an audit rule: one input, one table, the metadata file."""
    from types import SimpleNamespace

    (tmp_path / "in.csv").write_bytes(b"wavelength_nm,reflectance\n400,0.5\n")
    (tmp_path / "t.csv").write_text(header + "\n1,2\n")
    return SimpleNamespace(rule=rule, input=[str(tmp_path / "in.csv")],
                           output=_Outputs(table=str(tmp_path / "t.csv"),
                                           metadata=str(tmp_path / "t_metadata.yaml")))


class _Outputs(list):
    """Snakemake's named output list: iterable, and each file by name."""

    def __init__(self, **named):
        super().__init__(named.values())
        self.__dict__.update(named)


def test_audit_metadata_hashes_the_inputs_and_gives_every_column_a_unit(tmp_path):
    import hashlib

    import reflectance
    from reflectance.scripting import write_audit_metadata

    job = _job(tmp_path, "angle_deg,dE2000_max")
    write_audit_metadata(job, "a test", illuminant="A", observer="CIE 1931 2 Degree Standard "
                         "Observer", wavelengths_nm={"start_nm": 380, "end_nm": 780, "step_nm": 5},
                         units={"angle_deg": "deg", "dE2000_*": "CIEDE2000"}, space="sRGB")
    doc = yaml.safe_load((tmp_path / "t_metadata.yaml").read_text())
    assert doc["reflectance"] == reflectance.__version__
    assert doc["illuminant"] == "A" and doc["space"] == "sRGB"
    assert doc["wavelengths_nm"] == {"start": 380, "end": 780, "step": 5}
    digest = hashlib.sha256(b"wavelength_nm,reflectance\n400,0.5\n").hexdigest()
    assert doc["inputs"] == {str(tmp_path / "in.csv"): digest}
    assert doc["columns"] == {"t.csv": {"angle_deg": {"unit": "deg"},
                                        "dE2000_max": {"unit": "CIEDE2000"}}}
    assert doc["tables"]["t.csv"] == hashlib.sha256((tmp_path / "t.csv").read_bytes()).hexdigest()


def test_audit_metadata_refuses_a_column_without_a_unit(tmp_path):
    from reflectance.scripting import write_audit_metadata

    job = _job(tmp_path, "angle_deg,hue")
    with pytest.raises(ValueError, match="audit_x: t.csv: column 'hue' has no unit"):
        write_audit_metadata(job, "a test", illuminant=None, observer=None, wavelengths_nm=None,
                             units={"angle_deg": "deg"})
    assert not (tmp_path / "t_metadata.yaml").exists()
