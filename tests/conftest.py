import os
from pathlib import Path

import pytest
from hypothesis import settings

# Property tests: no wall-clock deadline (a shared 2-core machine is not a benchmark), and in CI
# (CI=true) a fixed example sequence, so a submission's result does not depend on the draw.
settings.register_profile("dev", deadline=None)
settings.register_profile("ci", deadline=None, derandomize=True, print_blob=True)
settings.load_profile("ci" if os.environ.get("CI") else "dev")

ROOT = Path(__file__).resolve().parents[1]

# pyvista renders off-screen (EGL); never try to open a window in tests.
os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def built(root, tmp_path_factory):
    """The whole workflow, `snakemake --cores 2`, run once per test session in a temporary copy
    of the project; shared by every end-to-end test that reads (never changes) its results.

    The copy starts without the committed spectra, so the build exports and derives every one
    again (whether Snakemake would rerun them beside a checkout depends on the files' times)."""
    from test_workflow import copy_project, snakemake

    cwd = copy_project(root, tmp_path_factory.mktemp("workflow"))
    for spectrum in (cwd / "spectra").glob("*.csv"):
        spectrum.unlink()
    snakemake(cwd, "--cores", "2")
    return cwd


@pytest.fixture(scope="session")
def grid():
    from reflectance.optics.spectra import wavelength_grid

    return wavelength_grid(360, 830, 5)
