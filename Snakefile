# The reflectance workflow: rebuilds every figure of Blinn 1977, Cook & Torrance 1982, the
# advanced-reflection lecture and the specular-highlight article from measured spectra.
# Run: snakemake --cores 2   (README.md says more)

from pathlib import Path

from snakemake.utils import min_version, validate

from reflectance.config import ConfigError, read_config
from reflectance.resume import report_memory_kills, resume_after_kill

min_version("9.14")  # update(): a failing job restores the committed spectrum it would replace

# A plain `snakemake` resumes a run that was killed: Snakemake reads no workflow profile from
# workflow/profiles/, so the Snakefile clears what a dead run left (reflectance/resume.py says how).
resume_after_kill(main_process=workflow.exec_mode.name == "DEFAULT")

# A YAML syntax error or a key given twice, named with its line (Snakemake's own reading of the
# config file says neither).
try:
    if Path("config.yaml").exists():  # (Snakemake says so if it is missing)
        read_config("config.yaml")
except ConfigError as err:
    raise WorkflowError(str(err)) from None


configfile: "config.yaml"


report: "workflow/report/workflow.rst"


# common.smk checks config.yaml first, naming each bad key (config.yaml: colour.space: ...);
# Snakemake's validate() then applies the same schema (JSON: read in ms) and fills in its defaults.
include: "workflow/rules/common.smk"


validate(config, "workflow/schemas/config.schema.json")


include: "workflow/rules/spectra.smk"
include: "workflow/rules/cook_torrance_1982.smk"
include: "workflow/rules/blinn_1977.smk"
include: "workflow/rules/lecture.smk"
include: "workflow/rules/article.smk"
include: "workflow/rules/renders.smk"
include: "workflow/rules/audits.smk"
include: "workflow/rules/readme.smk"
include: "workflow/rules/provenance.smk"  # last: it hashes every other target


# A job a cluster killed for its memory: Snakemake's SLURM executor says only that it failed; name
# the rule, its mem_mb request and SLURM's line about it (reflectance/resume.py, memory_kills).
onerror:
    report_memory_kills(log)


# Every target, not the provenance manifest alone (whose inputs they are): Snakemake does not
# rebuild a missing input of an up-to-date output, so a figure deleted by hand would stay missing.
rule all:
    default_target: True
    input:
        TARGETS,
    message:
        "every figure, table, audit and spectrum, and their provenance"
