"""The Snakefile and the rules files are formatted as snakefmt formats them (pyproject's
[tool.snakefmt]); `snakefmt Snakefile workflow/rules` fixes what this finds."""

import subprocess
import sys

import pytest


def test_rules_are_snakefmt_clean(root):
    pytest.importorskip("snakefmt", reason="snakefmt comes with the test extra (Python >= 3.11)")
    proc = subprocess.run([sys.executable, "-m", "snakefmt", "--check", "--diff", "Snakefile",
                           "workflow/rules"], cwd=root, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-2000:]
