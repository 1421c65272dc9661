"""Rule derive_spectra: every Munsell material's notation -> reflectance spectra/<material>.csv.

One job for all of them imports colour-science once, not once per material. Every spectrum is
made before any is written, so a material that fails (named in the log) leaves every committed
file as it was.
"""

from pathlib import Path

from reflectance.scripting import command_line_job, script_log
from reflectance.optics.spectra import (DEFAULT_RECOVERY, reflectance_from_munsell,
                                        spectra_by_material, write_spectrum_csvs)


def recovery(entry):
    return entry.get("recovery", DEFAULT_RECOVERY)


def derive(entry):
    return reflectance_from_munsell(entry["notation"], method=recovery(entry))


# run by the rule's shell command, not script: (workflow/rules/spectra.smk says why)
snakemake = command_line_job("derive_spectra")

with script_log(snakemake) as log:
    entries = snakemake.params.entries
    tables = spectra_by_material(entries, derive)
    write_spectrum_csvs({path: tables[Path(path).stem] for path in snakemake.output})
    for material, entry in entries.items():
        reflectance = tables[material]["reflectance"]
        log.info("%s: Munsell %s, %s, reflectance %.4f-%.4f", material, entry["notation"],
                 recovery(entry), reflectance.min(), reflectance.max())
