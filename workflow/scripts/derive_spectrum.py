"""Rule derive_spectrum: a Munsell notation -> reflectance spectrum spectra/<material>.csv."""

from reflectance.scripting import script_log
from reflectance.optics.spectra import reflectance_from_munsell, write_spectrum_csv

with script_log(snakemake) as log:
    entry = snakemake.params.entry
    method = entry.get("recovery", "Meng 2015")
    table = reflectance_from_munsell(entry["notation"], method=method)
    write_spectrum_csv(table, snakemake.output[0])
    log.info("%s: Munsell %s, %s, reflectance %.4f-%.4f", snakemake.wildcards.material,
             entry["notation"], method, table["reflectance"].min(), table["reflectance"].max())
