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
