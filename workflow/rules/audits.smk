# Colour-accuracy audits: how far each shortcut of the papers (and of today's renderers) lies from
# the exact spectral answer. One rule, one script, one caption per audit; results/audits/.

AUDITS = config["audits"]
AUDITS_OUT = "results/audits"

TARGETS += [
    f"{AUDITS_OUT}/{name}"
    for name in ("fresnel_atlas.png", "fresnel_atlas.pdf", "fresnel_atlas.csv",
                 "fresnel_atlas_thresholds.csv", "fresnel_atlas_answer.rst",
                 "spectral_sampling.png", "spectral_sampling.pdf", "spectral_sampling.csv",
                 "spectral_sampling_answer.rst",
                 "spectral_recovery.png", "spectral_recovery.pdf", "spectral_recovery.csv",
                 "spectral_recovery_answer.rst",
                 "illuminant_observer.png", "illuminant_observer.pdf", "illuminant_observer.csv",
                 "illuminant_observer_answer.rst",
                 "white_furnace.png", "white_furnace.pdf", "white_furnace.csv",
                 "white_furnace_answer.rst")
]


rule audit_fresnel_atlas:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["fresnel_atlas"]["materials"]],
    output:
        png=report(f"{AUDITS_OUT}/fresnel_atlas.png", caption="../report/audit_fresnel_atlas.rst",
                   category="Audits", subcategory="1. Fresnel shortcut atlas"),
        pdf=f"{AUDITS_OUT}/fresnel_atlas.pdf",
        csv=report(f"{AUDITS_OUT}/fresnel_atlas_thresholds.csv",
                   caption="../report/audit_fresnel_atlas_table.rst",
                   category="Audits", subcategory="1. Fresnel shortcut atlas"),
        table=f"{AUDITS_OUT}/fresnel_atlas.csv",
        answer=f"{AUDITS_OUT}/fresnel_atlas_answer.rst",
    params:
        audit=AUDITS["fresnel_atlas"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    log:
        "logs/audits/fresnel_atlas.log",
    script:
        "../scripts/audit_fresnel_atlas.py"


rule audit_spectral_sampling:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["spectral_sampling"]["materials"]],
    output:
        png=report(f"{AUDITS_OUT}/spectral_sampling.png",
                   caption="../report/audit_spectral_sampling.rst",
                   category="Audits", subcategory="4. Spectral sampling"),
        pdf=f"{AUDITS_OUT}/spectral_sampling.pdf",
        csv=report(f"{AUDITS_OUT}/spectral_sampling.csv",
                   caption="../report/audit_spectral_sampling_table.rst",
                   category="Audits", subcategory="4. Spectral sampling"),
        answer=f"{AUDITS_OUT}/spectral_sampling_answer.rst",
    params:
        audit=AUDITS["spectral_sampling"],
        colour=config["colour"],
    log:
        "logs/audits/spectral_sampling.log",
    script:
        "../scripts/audit_spectral_sampling.py"


rule audit_illuminant_observer:
    input:
        spectra=[spectrum_csv(name) for name in AUDITS["illuminant_observer"]["materials"]],
    output:
        png=report(f"{AUDITS_OUT}/illuminant_observer.png",
                   caption="../report/audit_illuminant_observer.rst",
                   category="Audits", subcategory="5. Illuminant and observer"),
        pdf=f"{AUDITS_OUT}/illuminant_observer.pdf",
        csv=report(f"{AUDITS_OUT}/illuminant_observer.csv",
                   caption="../report/audit_illuminant_observer_table.rst",
                   category="Audits", subcategory="5. Illuminant and observer"),
        answer=f"{AUDITS_OUT}/illuminant_observer_answer.rst",
    params:
        audit=AUDITS["illuminant_observer"],
        wavelengths=config["wavelengths"],
    log:
        "logs/audits/illuminant_observer.log",
    script:
        "../scripts/audit_illuminant_observer.py"


rule audit_spectral_recovery:
    output:
        png=report(f"{AUDITS_OUT}/spectral_recovery.png",
                   caption="../report/audit_spectral_recovery.rst",
                   category="Audits", subcategory="7. Judgement: spectral recovery"),
        pdf=f"{AUDITS_OUT}/spectral_recovery.pdf",
        csv=report(f"{AUDITS_OUT}/spectral_recovery.csv",
                   caption="../report/audit_spectral_recovery_table.rst",
                   category="Audits", subcategory="7. Judgement: spectral recovery"),
        answer=f"{AUDITS_OUT}/spectral_recovery_answer.rst",
    params:
        audit=AUDITS["spectral_recovery"],
        entries={name: config["materials"][name]
                 for name in AUDITS["spectral_recovery"]["materials"]},
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    log:
        "logs/audits/spectral_recovery.log",
    script:
        "../scripts/audit_spectral_recovery.py"


rule audit_white_furnace:
    output:
        png=report(f"{AUDITS_OUT}/white_furnace.png", caption="../report/audit_white_furnace.rst",
                   category="Audits", subcategory="6. Conventions: the factor 4"),
        pdf=f"{AUDITS_OUT}/white_furnace.pdf",
        csv=report(f"{AUDITS_OUT}/white_furnace.csv",
                   caption="../report/audit_white_furnace_table.rst",
                   category="Audits", subcategory="6. Conventions: the factor 4"),
        answer=f"{AUDITS_OUT}/white_furnace_answer.rst",
    params:
        audit=AUDITS["white_furnace"],
    log:
        "logs/audits/white_furnace.log",
    script:
        "../scripts/audit_white_furnace.py"
