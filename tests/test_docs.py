"""The API reference (workflow/docs, Sphinx from the numpydoc docstrings) builds without warnings."""

import re
import subprocess
import sys

import pytest


def test_every_module_has_a_page(root):
    """Each module of the library is named by an ``automodule`` of workflow/docs/api/*.rst."""
    package = root / "workflow" / "reflectance"
    modules = {".".join(("reflectance",) + p.relative_to(package).with_suffix("").parts)
               for p in package.rglob("*.py") if p.name not in ("__init__.py", "__main__.py")}
    text = "\n".join(p.read_text() for p in (root / "workflow" / "docs" / "api").glob("*.rst"))
    documented = set(re.findall(r"^\.\. automodule:: (\S+)$", text, re.M))
    assert modules - documented == set(), "modules missing from workflow/docs/api"
    assert documented - modules - {f"reflectance.{p.name}" for p in package.iterdir()
                                   if (p / "__init__.py").exists()} == set()


def test_sphinx_builds_without_warnings(root, tmp_path):
    """`python -m sphinx -W`: any docutils or autodoc warning in a docstring fails the build."""
    pytest.importorskip("sphinx", reason="sphinx is in the test and docs extras of pyproject.toml")
    proc = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
         "-d", str(tmp_path / "doctrees"), str(root / "workflow" / "docs"), str(tmp_path / "html")],
        capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    page = (tmp_path / "html" / "api" / "optics.html").read_text()
    # the docstrings are in it, with their numpydoc sections rendered
    assert "fresnel_conductor" in page and "Parameters" in page
