# Lecture: Russin, "Advanced Reflection Models" (JHU 605.767 Applied Computer Graphics, Module 3B):
# its sample BRDFs, Fresnel reflectance and shadowing / masking slides, rebuilt from the library.

LECTURE = config["figures"]["lecture"]
LECTURE_OUT = "results/lecture"

TARGETS += [
    f"{LECTURE_OUT}/{name}"
    for name in (
        "brdf_lobes_2d.png",
        "brdf_lobes_2d.pdf",
        "brdf_lobes_2d.csv",
        "brdf_lobes_3d.png",
        "brdf_lobes_3d.values.rst",
        "fresnel.png",
        "fresnel.pdf",
        "fresnel.csv",
        "shadowing_masking.png",
        "shadowing_masking.pdf",
        "shadowing_masking_g1.csv",
        "shadowing_masking_by_slope.csv",
        "distributions.png",
        "distributions.pdf",
        "distributions.csv",
        "distributions_normalisation.csv",
    )
]


rule lecture_distributions:
    output:
        png=report(
            f"{LECTURE_OUT}/distributions.png",
            caption="../report/lecture_distributions.rst",
            category="Lecture",
            subcategory="Microfacet distributions",
        ),
        pdf=f"{LECTURE_OUT}/distributions.pdf",
        csv=f"{LECTURE_OUT}/distributions.csv",
        summary=f"{LECTURE_OUT}/distributions_normalisation.csv",
    log:
        "logs/lecture/distributions.log",
    benchmark:
        "benchmarks/lecture/distributions.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=LECTURE["distributions"],
    script:
        "../scripts/lecture_distributions.py"


rule lecture_brdf_lobes_2d:
    output:
        png=report(
            f"{LECTURE_OUT}/brdf_lobes_2d.png",
            caption="../report/lecture_brdf_lobes_2d.rst",
            category="Lecture",
            subcategory="Sample BRDFs",
        ),
        pdf=f"{LECTURE_OUT}/brdf_lobes_2d.pdf",
        csv=f"{LECTURE_OUT}/brdf_lobes_2d.csv",
    log:
        "logs/lecture/brdf_lobes_2d.log",
    benchmark:
        "benchmarks/lecture/brdf_lobes_2d.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=LECTURE["brdf_lobes"],
    script:
        "../scripts/lecture_brdf_lobes_2d.py"


rule lecture_brdf_lobes_3d:
    input:
        plane=f"{LECTURE_OUT}/brdf_lobes_2d.csv",
    output:
        png=report(
            f"{LECTURE_OUT}/brdf_lobes_3d.png",
            caption="../report/lecture_brdf_lobes_3d.rst",
            category="Lecture",
            subcategory="Sample BRDFs",
        ),
        values=f"{LECTURE_OUT}/brdf_lobes_3d.values.rst",
    log:
        "logs/lecture/brdf_lobes_3d.log",
    benchmark:
        "benchmarks/lecture/brdf_lobes_3d.tsv"
    threads: 1
    resources:
        mem_mb=1400,
        runtime=10,
    params:
        fig=LECTURE["brdf_lobes"],
    script:
        "../scripts/lecture_brdf_lobes_3d.py"


rule lecture_fresnel:
    input:
        spectra=[spectrum_csv(name) for name in LECTURE["fresnel"]["materials"]],
    output:
        png=report(
            f"{LECTURE_OUT}/fresnel.png",
            caption="../report/lecture_fresnel.rst",
            category="Lecture",
            subcategory="Fresnel reflectance",
        ),
        pdf=f"{LECTURE_OUT}/fresnel.pdf",
        csv=f"{LECTURE_OUT}/fresnel.csv",
    log:
        "logs/lecture/fresnel.log",
    benchmark:
        "benchmarks/lecture/fresnel.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        fig=LECTURE["fresnel"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/lecture_fresnel.py"


rule lecture_shadowing_masking:
    output:
        png=report(
            f"{LECTURE_OUT}/shadowing_masking.png",
            caption="../report/lecture_shadowing_masking.rst",
            category="Lecture",
            subcategory="Shadowing and masking",
        ),
        pdf=f"{LECTURE_OUT}/shadowing_masking.pdf",
        g1=report(
            f"{LECTURE_OUT}/shadowing_masking_g1.csv",
            caption="../report/lecture_shadowing_masking_table.rst",
            category="Lecture",
            subcategory="Shadowing and masking",
        ),
        by_slope=f"{LECTURE_OUT}/shadowing_masking_by_slope.csv",
    log:
        "logs/lecture/shadowing_masking.log",
    benchmark:
        "benchmarks/lecture/shadowing_masking.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=LECTURE["shadowing_masking"],
    script:
        "../scripts/lecture_shadowing_masking.py"
