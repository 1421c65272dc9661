"""The Sphinx site (workflow/docs: the guides README points to, and the API reference from the
numpydoc docstrings) builds without warnings."""

import importlib.util
import re
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
    packages = {".".join(("reflectance",) + p.parent.relative_to(package).parts)
                for p in package.rglob("__init__.py") if p.parent != package}
    assert documented - modules - packages == set()


def start_with_session(runs, root, tmp_path_factory, items):
    """The Sphinx build starts with the session, on its pool (tests/conftest.py's ``early``
    calls this), if it is selected: it needs nothing of the session's build, and so overlaps the
    other tests; the test takes its result."""
    if any(item.originalname == "test_sphinx_builds_without_warnings" for item in items):
        _start_sphinx(runs, root, tmp_path_factory)


def _start_sphinx(runs, root, tmp_path_factory):
    if not runs.started("sphinx") and importlib.util.find_spec("sphinx") is not None:
        runs.start("sphinx", _sphinx, runs, root, tmp_path_factory.mktemp("sphinx"))


def _sphinx(runs, root, out):
    """`python -m sphinx -W` of workflow/docs into ``out``: (its folder, finished process)."""
    return out, runs.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
         "-d", str(out / "doctrees"), str(root / "workflow" / "docs"), str(out / "html")])


def test_sphinx_builds_without_warnings(root, early, tmp_path_factory):
    """`python -m sphinx -W`: any docutils or autodoc warning in a docstring fails the build.
    The build (``_sphinx``) starts with the session; taken here."""
    pytest.importorskip("sphinx", reason="sphinx is in the test and docs extras of pyproject.toml")
    _start_sphinx(early, root, tmp_path_factory)  # (``early`` did, unless run without it)
    out, proc = early.result("sphinx")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    page = (out / "html" / "api" / "optics.html").read_text()
    # the docstrings are in it, with their numpydoc sections rendered
    assert "fresnel_conductor" in page and "Parameters" in page
    # the guides README points to are pages of the site, their equations rendered by MathJax
    # (sphinx.ext.mathjax: TeX in the page, typeset in the browser) rather than plain text
    guides = sorted((root / "workflow" / "docs" / "guides").glob("*.rst"))
    assert len(guides) >= 8
    for guide in guides:
        html = (out / "html" / "guides" / f"{guide.stem}.html").read_text()
        math = html.count('class="math notranslate nohighlight"')
        if ":math:" in guide.read_text() or ".. math::" in guide.read_text():
            assert math and re.search(r"<script[^>]+mathjax", html, re.I), guide.name
    rendering = (out / "html" / "guides" / "rendering.html").read_text()
    assert r"\(Y = I \omega / \pi\)" in rendering
