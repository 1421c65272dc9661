"""reflectance: spectral reproduction and audit of the classic reflectance papers.

The folders are the architecture; data flows one way, from the bottom of this list to the top:

- ``cli``, ``config``, ``scripting``, ``resume``: the ``reflectance`` command and the workflow's
  support (``resume``: a plain ``snakemake`` resumes a run that was killed);
- ``papers``: what only one text needs (V-groove simulations, plots, scenes from config.yaml);
- ``bench``: the renderer's speed, memory and accuracy (``reflectance bench``), and a path
  tracer's cross-check of it;
- ``audit``: how far each shortcut lies from the exact spectral answer;
- ``render``: a spectral renderer that takes a scene (camera ... shading, scene files, pipeline);
- ``geometry``: shapes, the watch, texture patterns;
- ``optics``: spectra, Fresnel, microfacet D, shadowing G, BRDFs;
- ``colour``: CIE colorimetry and display encoding;
- ``io``: atomic, deterministic file output.

Each subpackage names its public functions in ``__all__`` and loads them on first use, so
``import reflectance`` loads neither colour-science nor VTK: ``from reflectance.optics import
fresnel_conductor``, ``from reflectance.render import render``.
"""

from importlib import import_module

__version__ = "0.4.0"

_SUBPACKAGES = ("optics", "colour", "geometry", "render", "audit", "papers", "bench", "io")

__all__ = ["__version__", *_SUBPACKAGES]


def __getattr__(name):
    if name in _SUBPACKAGES:
        return import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
