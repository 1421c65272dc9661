# Colour-accuracy audits: how far each shortcut of the papers (and of today's renderers) lies from
# the exact spectral answer. One rule, one script, one caption per audit; results/audits/.

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
        "rgb_rendering.png",
        "rgb_rendering.pdf",
        "rgb_rendering.csv",
        "rgb_rendering_answer.rst",
        "gamut_mapping.png",
        "gamut_mapping.pdf",
        "gamut_mapping.csv",
        "gamut_mapping_images.csv",
        "gamut_mapping_answer.rst",
        "spectral_sampling.png",
        "spectral_sampling.pdf",
        "spectral_sampling.csv",
        "spectral_sampling_answer.rst",
        "spectral_recovery.png",
        "spectral_recovery.pdf",
        "spectral_recovery.csv",
        "spectral_recovery_answer.rst",
        "illuminant_observer.png",
        "illuminant_observer.pdf",
        "illuminant_observer.csv",
        "illuminant_observer_answer.rst",
        "white_furnace.png",
        "white_furnace.pdf",
        "white_furnace.csv",
        "white_furnace_answer.rst",
    )
]


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
