"""Every rule tells a cluster what it needs: threads, memory and time, from measurements.

workflow/rules/common.smk and workflow/docs/guides/cluster.rst say how the numbers were measured;
tests/test_slurm.py checks that SLURM receives them. Here, that no rule is left to the profile's
defaults, and that the requests stay modest (the project's machine has 2 cores and 24 GiB).
"""

import re

import pytest

RULE = re.compile(r"^rule (\w+):\n((?:    .*\n)+)", re.MULTILINE)


def _rules(root):
    rules = {}
    for path in sorted((root / "workflow" / "rules").glob("*.smk")):
        for name, body in RULE.findall(path.read_text()):
            rules[name] = (path.name, body)
    return rules


def test_the_rules_are_found(root):
    assert len(_rules(root)) >= 30


@pytest.mark.parametrize("field", ["threads", "mem_mb", "runtime"])
def test_every_rule_declares_its_threads_memory_and_time(root, field):
    missing, immodest = [], []
    for name, (_, body) in _rules(root).items():
        found = re.search(rf"^\s+{field}(?::|=)\s*(\d+)", body, flags=re.MULTILINE)
        if found is None:
            missing.append(name)
            continue
        value = int(found.group(1))
        limit = {"threads": 2, "mem_mb": 8000, "runtime": 120}[field]
        if not 0 < value <= limit:
            immodest.append((name, value))
    assert missing == [] and immodest == [], (missing, immodest)


def test_every_rule_but_the_committed_spectra_writes_a_benchmark(root):
    """The spectra rules have none: their outputs are committed, and a missing benchmark file
    would make Snakemake export every spectrum again on a fresh checkout."""
    without = sorted(name for name, (path, body) in _rules(root).items()
                     if "    benchmark:\n" not in body)
    spectra = sorted(name for name, (path, _) in _rules(root).items() if path == "spectra.smk")
    assert without == spectra
