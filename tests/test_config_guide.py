"""workflow/config/README.md describes config.yaml: every section and every figure key of the
config in use is named there, and the workflow catalog's file parses and points at it."""

import yaml


def test_every_section_and_figure_is_described(root):
    guide = (root / "workflow" / "config" / "README.md").read_text(encoding="utf-8")
    config = yaml.safe_load((root / "config.yaml").read_text(encoding="utf-8"))
    missing = [f"`{section}`" for section in config if f"`{section}`" not in guide]
    for text, figures in config["figures"].items():
        if f"`figures.{text}`" not in guide:
            missing.append(f"figures.{text}")
        if isinstance(figures, dict) and text != "errata":
            missing += [f"figures.{text}.{key}" for key in figures if f"`{key}`" not in guide]
    missing += [f"audits.{key}" for key in config.get("audits", {}) if f"`{key}`" not in guide]
    assert missing == []


def test_the_catalog_file_says_what_is_tested(root):
    catalog = yaml.safe_load((root / ".snakemake-workflow-catalog.yml").read_text())
    usage = catalog["usage"]
    assert usage["report"] is True  # snakemake --report: tests/test_workflow.py reads it
    # no per-rule conda or container environments are provided (workflow/docs/guides/
    # building.rst says why)
    assert not any(usage["software-stack-deployment"].values())
    assert "--cores" in usage["mandatory-flags"]["flags"]
