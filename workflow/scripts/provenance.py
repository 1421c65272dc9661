"""results/provenance.yaml: commit, configuration, spectra, packages and every output's SHA-256
(reflectance.io.provenance)."""

from reflectance.io.provenance import provenance, write_provenance
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    inputs = snakemake.input
    manifest = provenance(inputs.outputs, inputs.spectra, dict(snakemake.params.config),
                          config_file=inputs.config_file, git=snakemake.params.git,
                          measurements=inputs.measurements)
    write_provenance(snakemake.output[0], manifest)
    log.info("%d outputs, %d spectra, commit %s", len(manifest["outputs"]),
             len(manifest["spectra"]), manifest["git"]["commit"])
