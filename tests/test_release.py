"""Releases (issue 27, part 6): the newest version of CHANGELOG.md is the one `reflectance
--version` reports and the one CITATION.cff cites, with the same date; build outputs are
git-ignored."""

import re
import subprocess
import sys

import yaml

import reflectance

#: a released version's heading: "## 0.4.0 (2026-12-05)"
RELEASE = re.compile(r"^## (\d+\.\d+\.\d+) \((\d{4}-\d{2}-\d{2})\)$", re.M)


def releases(root):
    return RELEASE.findall((root / "CHANGELOG.md").read_text(encoding="utf-8"))


def test_changelog_releases_are_dated_and_newest_first(root):
    found = releases(root)
    assert len(found) >= 2, "CHANGELOG.md names no released versions"
    versions = [tuple(map(int, v.split("."))) for v, _ in found]
    assert versions == sorted(versions, reverse=True) and len(set(versions)) == len(versions)
    dates = [d for _, d in found]
    assert dates == sorted(dates, reverse=True)
    # the only section above the newest release is Unreleased
    text = (root / "CHANGELOG.md").read_text(encoding="utf-8")
    above = text[:text.index(f"## {found[0][0]} (")]
    assert re.findall(r"^## .*$", above, re.M) == ["## Unreleased"]


def test_version_and_citation_are_the_newest_release(root):
    version, date = releases(root)[0]
    assert reflectance.__version__ == version
    shown = subprocess.run([sys.executable, "-m", "reflectance", "--version"], cwd=root,
                           capture_output=True, text=True, check=True).stdout.strip()
    assert shown == f"reflectance {version}"
    citation = yaml.safe_load((root / "CITATION.cff").read_text(encoding="utf-8"))
    assert str(citation["version"]) == version
    assert str(citation["date-released"]) == date


def test_build_outputs_are_ignored(root):
    paths = ["build/lib/reflectance/__init__.py", "dist/reflectance-0.4.0.tar.gz",
             "reflectance-0.4.0-py3-none-any.whl", "workflow/docs/_build/html/index.html",
             "workflow/reflectance.egg-info/PKG-INFO", "results/audits/audit.csv"]
    proc = subprocess.run(["git", "check-ignore", "--no-index", *paths], cwd=root,
                          capture_output=True, text=True)
    assert proc.stdout.split() == paths
