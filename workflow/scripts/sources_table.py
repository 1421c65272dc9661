"""Rule sources_table: provenance of every material -> spectra/sources.csv."""

from pathlib import Path

from reflectance.scripting import command_line_job, script_log
from reflectance.optics.spectra import sources_table, write_sources_csv

# run by the rule's shell command, not script: (workflow/rules/spectra.smk says why)
snakemake = command_line_job("sources_table")

with script_log(snakemake) as log:
    table = sources_table(snakemake.params.materials, spectra_dir=Path(snakemake.output[0]).parent)
    write_sources_csv(table, snakemake.output[0])
    log.info("%d materials: %s", len(table), ", ".join(table["material"]))
