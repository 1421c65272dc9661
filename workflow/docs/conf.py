"""Sphinx configuration of the API reference (built from the numpydoc docstrings).

The site: the guides (guides/*.rst, moved from README.md) and the API reference.
Build (guides/python.rst, "API reference"): ``python -m sphinx -W -b html workflow/docs docs_html``.
"""

import sys
from pathlib import Path

# The library as this checkout holds it (workflow/reflectance), installed or not.
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import reflectance  # noqa: E402

project = "reflectance"
author = "the reflectance authors"
copyright = "2026, the reflectance authors (BSD-3-Clause)"
release = version = reflectance.__version__

# sphinx.ext.mathjax (shipped with Sphinx) renders the guides' and docstrings' equations in the
# browser: MathJax is loaded from its CDN by the page, nothing is downloaded at build time.
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax"]
# numpydoc-style sections (Parameters, Returns, Raises, References, Examples) through napoleon,
# which ships with Sphinx: no extra package.
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
autodoc_default_options = {"members": True, "member-order": "bysource"}
autodoc_typehints = "none"
# Heavy libraries are real dependencies; nothing is mocked, so the reference documents the code
# that runs.
# numpydoc type fields ("array_like, shape (N, 3)") make every word a cross-reference; "shape"
# then finds two attributes of that name (Camera.shape, SurfaceSamples.shape) and Sphinx warns
# that it cannot choose. Those words are prose, not references: this silences only the
# "more than one target found" warnings of the Python domain.
suppress_warnings = ["ref.python"]
exclude_patterns = ["_build"]
html_theme = "alabaster"
html_title = f"reflectance {release}"
html_static_path = []
