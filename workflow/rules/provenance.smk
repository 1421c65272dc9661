# The provenance manifest (reflectance.io.provenance): results/provenance.yaml holds the git commit,
# the configuration's and every spectrum's SHA-256, the package versions and the SHA-256 of every
# other output (of a measurement, MEASUREMENTS, its path only). Included last: its inputs are all
# the targets the other rules files listed, and nothing takes it as input. The commit is a
# parameter, so a new commit rewrites the manifest.

from reflectance.io.provenance import git_state

PROVENANCE = "results/provenance.yaml"
PROVENANCE_GIT = git_state(workflow.basedir)
PROVENANCE_INPUTS = [t for t in TARGETS if t != PROVENANCE]

TARGETS += [PROVENANCE]


rule provenance:
    input:
        outputs=[
            t for t in PROVENANCE_INPUTS if not t.startswith("spectra/") and t not in MEASUREMENTS
        ],
        measurements=MEASUREMENTS,
        spectra=[t for t in PROVENANCE_INPUTS if t.startswith("spectra/")],
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
        git=PROVENANCE_GIT,
        config=config,
    script:
        "../scripts/provenance.py"
