"""Rule import_spectrum: the user's own spectrum file (config `source: file`) -> spectra/<material>.csv
in the project's form (wavelength in nm, checked row by row)."""

from reflectance.scripting import script_log
from reflectance.optics.spectra import read_spectrum_csv, write_spectrum_csv

with script_log(snakemake) as log:
    entry = snakemake.params.entry
    table = read_spectrum_csv(snakemake.input[0], entry["units"])
    write_spectrum_csv(table, snakemake.output[0])
    log.info("%s: %s (%s), %d points, %g-%g nm, columns %s", snakemake.wildcards.material,
             entry["path"], entry["units"], len(table), table["wavelength_nm"].iloc[0],
             table["wavelength_nm"].iloc[-1], ",".join(table.columns))
