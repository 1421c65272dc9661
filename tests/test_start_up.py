"""Fast start: `reflectance --help` and `reflectance colour` import no heavy library (not timed).

Each command runs in a fresh interpreter under ``python -X importtime``, whose report names every
module the command imported. The colour command's first run fills an empty table cache (and so
imports colour-science once); the check is on the second run, which must print the same bytes.
"""

import os
import subprocess
import sys
from pathlib import Path

import pytest

import reflectance

HEAVY = {"colour", "pandas", "scipy", "matplotlib", "vtk", "vtkmodules", "pyvista"}


def run(args, cache, cwd):
    env = dict(os.environ)
    env["PYTHONPATH"] = str(Path(reflectance.__file__).resolve().parents[1])
    env["REFLECTANCE_CACHE"] = str(cache)
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "reflectance", *args],
                            capture_output=True, text=True, env=env, cwd=cwd)
    imported = set()
    errors = []
    for line in result.stderr.splitlines():
        if line.startswith("import time:"):
            name = line.rsplit("|", 1)[-1].strip()
            if name != "package":  # the report's header line
                imported.add(name.split(".")[0])
        else:
            errors.append(line)
    assert result.returncode == 0, "\n".join(errors)
    return result.stdout, imported


COLOUR_OPTIONS = [
    [],
    ["--fresnel", "approximation"],
    ["--space", "SMPTE-C", "--clip", "clip"],
    ["--illuminant", "A", "--observer", "CIE 1964 10 Degree Standard Observer"],
]


def _colour_args(root, options):
    return ["colour", "Cu", "--angle", "0", "60", "89", "--spectra-dir", str(root / "spectra"),
            *options]


@pytest.fixture(scope="module")
def starts(root, tmp_path_factory):
    """Every command below, side by side (tests/side_by_side.py): `--help`, and for each set of
    colour options its two runs in order (the first fills that case's own empty cache, the second
    reads it). The tests make their assertions on the results."""
    from side_by_side import SideBySide

    def twice(args, cache):
        return run(args, cache, root), run(args, cache, root)

    with SideBySide() as runs:
        runs.start("help", run, ["--help"], tmp_path_factory.mktemp("help"), root)
        for i, options in enumerate(COLOUR_OPTIONS):
            runs.start(i, twice, _colour_args(root, options), tmp_path_factory.mktemp("cache"))
        yield runs


def test_help_imports_no_heavy_library(starts):
    out, imported = starts.result("help")
    assert "colour" in out and "render" in out
    assert not imported & HEAVY
    assert "numpy" not in imported


@pytest.mark.parametrize("case", range(len(COLOUR_OPTIONS)),
                         ids=[" ".join(o) or "defaults" for o in COLOUR_OPTIONS])
def test_colour_command_imports_no_heavy_library(starts, case):
    (first, imported_first), (second, imported) = starts.result(case)
    assert "colour" in imported_first  # the empty cache was filled by colour-science
    assert second == first
    assert not imported & HEAVY, sorted(imported & HEAVY)
