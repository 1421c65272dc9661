"""Deterministic figure output for matplotlib (2-D plots) and pyvista (3-D scenes).

Same inputs give byte-identical PNG and PDF files: no creation dates, no software versions in
the metadata, fixed DPI, and the file is written atomically.
"""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reflectance.io.atomic import atomic_write  # noqa: E402

__all__ = ["savefig", "new_figure", "off_screen_plotter", "save_plotter"]

_METADATA = {
    ".png": {"Software": None},
    ".pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
}


def new_figure(width_in=6.4, height_in=4.8, **kwargs):
    """A matplotlib figure with the project's fixed style (no global state changed)."""
    fig = plt.figure(figsize=(width_in, height_in), **kwargs)
    return fig


def savefig(fig, *paths, dpi=150):
    """Save ``fig`` to each path (.png or .pdf) deterministically and atomically, then close it."""
    paths = [Path(p) for p in paths]
    for path in paths:
        if path.suffix.lower() not in _METADATA:
            raise ValueError(f"figure path {path}: suffix must be one of {sorted(_METADATA)}")
    os.environ.setdefault("SOURCE_DATE_EPOCH", "0")
    try:
        for path in paths:
            suffix = path.suffix.lower()
            with atomic_write(path) as tmp:
                fig.savefig(tmp, dpi=dpi, metadata=_METADATA[suffix], format=suffix[1:])
    finally:
        plt.close(fig)


def off_screen_plotter(width, height, shape=(1, 1)):
    """A pyvista plotter that renders off-screen (EGL on a machine without a display).

    ``shape = (rows, columns)`` makes a grid of subplots (select one with ``plotter.subplot(i, j)``),
    drawn without borders between them.
    """
    import pyvista as pv

    pv.OFF_SCREEN = True
    return pv.Plotter(off_screen=True, window_size=(int(width), int(height)),
                      shape=tuple(int(n) for n in shape), border=False)


def save_plotter(plotter, path):
    """Screenshot a pyvista plotter to a deterministic PNG (through the project's PNG writer)."""
    from reflectance.io.images import write_png

    img = plotter.screenshot(return_img=True)
    plotter.close()
    write_png(path, img[..., :3] / 255.0, bit_depth=8)
