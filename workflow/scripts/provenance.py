"""results/provenance.yaml: commit, configuration, spectra, packages and every output's SHA-256
(reflectance.io.provenance)."""

from reflectance.io.provenance import provenance, write_provenance
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    params = snakemake.params  # every file; the rule's inputs name one output per job
    manifest = provenance(params.outputs, params.spectra, dict(params.config),
                          config_file=snakemake.input.config_file, git=params.git,
                          measurements=params.measurements)
    write_provenance(snakemake.output[0], manifest)
    log.info("%d outputs, %d spectra, commit %s", len(manifest["outputs"]),
             len(manifest["spectra"]), manifest["git"]["commit"])
