"""Audit 8, the whole database: the shards' tables merged in the datasets' order (the same bytes
for any number of shards), the counts per shelf with a total, the metadata file beside them, and
the counts' answer for the report."""

import csv
import io
from pathlib import Path

from reflectance.audit.database import database_metadata, merge_tables
from reflectance.audit.shortcuts import observer_name
from reflectance.io.atomic import write_text
from reflectance.io.provenance import write_metadata
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    params, out = snakemake.params.audit, snakemake.output
    shards = [(Path(t).read_text(), Path(c).read_text())
              for t, c in zip(snakemake.input.tables, snakemake.input.counts)]
    table, counts = merge_tables(shards)
    write_text(out.csv, table)
    write_text(out.counts, counts)
    write_metadata(out.metadata, database_metadata(params, observer_name(params["observer"]),
                                                   shards=len(shards),
                                                   command=f"snakemake rule {snakemake.rule}"),
                   tables=(out.csv, out.counts))

    total = list(csv.DictReader(io.StringIO(counts)))[-1]  # the total row
    n = {key: int(value) for key, value in total.items() if key != "shelf"}
    covering = n["audited"] + n["no_n"] + n["invalid"]
    answer = (f"**Answer:** of the {n['datasets']} datasets of the database, {covering} cover "
              f"{params['range_nm'][0]:g}-{params['range_nm'][1]:g} nm and {n['audited']} of them "
              f"are audited ({n['metal_like']} metal-like, {n['absorbing']} absorbing, "
              f"{n['transparent']} transparent); {n['no_n']} have no n and {n['invalid']} a "
              f"negative or undefined n or k on the grid (listed, not audited), "
              f"{n['partial_range']} cover only part of the range (listed, not audited) and "
              f"{n['outside_range']} none of it. Of the audited, {n['k_missing']} have no k "
              f"(audited with k = 0), {n['n_formula']} take n from a dispersion formula and "
              f"{n['data_repaired']} had samples out of order or repeated (sorted, averaged).\n")
    write_text(out.answer, answer)
    log.info("%s", answer.strip())
