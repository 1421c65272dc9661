# The provenance manifest (reflectance.io.provenance): results/provenance.yaml holds the git commit,
# the configuration's and every spectrum's SHA-256, the package versions and the SHA-256 of every
# other output (of a measurement, MEASUREMENTS, its path only). Included last: it hashes all the
# targets the other rules files listed (its inputs name one output of each job), and nothing takes
# it as input. The commit is a parameter, so a new commit rewrites the manifest.

from reflectance.io.provenance import git_state

PROVENANCE = "results/provenance.yaml"
PROVENANCE_GIT = git_state(workflow.basedir)
PROVENANCE_INPUTS = [t for t in TARGETS if t != PROVENANCE]
PROVENANCE_OUTPUTS = [
    t for t in PROVENANCE_INPUTS if not t.startswith("spectra/") and t not in MEASUREMENTS
]
PROVENANCE_MEASUREMENTS = [t for t in PROVENANCE_INPUTS if t in MEASUREMENTS]
PROVENANCE_SPECTRA = [t for t in PROVENANCE_INPUTS if t.startswith("spectra/")]

TARGETS += [PROVENANCE]


rule provenance:
    input:
        # one output of each job (common.smk, one_output_per_job): the manifest runs after them
        # all and again after any of them; the script hashes every file (params)
        outputs=one_output_per_job(PROVENANCE_OUTPUTS + PROVENANCE_MEASUREMENTS),
        spectra=one_output_per_job(PROVENANCE_SPECTRA),
        config_file="config.yaml",
    output:
        PROVENANCE,
    log:
        "logs/provenance.log",
    benchmark:
        "benchmarks/provenance.tsv"
    threads: 1
    resources:
        mem_mb=800,
        runtime=10,
    params:
        outputs=PROVENANCE_OUTPUTS,
        measurements=PROVENANCE_MEASUREMENTS,
        spectra=PROVENANCE_SPECTRA,
        git=PROVENANCE_GIT,
        config=config,
    message:
        "results/provenance.yaml: the SHA-256 of every output and spectrum"
    script:
        "../scripts/provenance.py"
