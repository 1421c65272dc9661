import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

# pyvista renders off-screen (EGL); never try to open a window in tests.
os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def grid():
    from reflectance.spectra import wavelength_grid

    return wavelength_grid(360, 830, 5)
