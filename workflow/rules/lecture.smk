# Lecture: Russin, "Advanced Reflection Models" (JHU 605.767 Applied Computer Graphics, Module 3B):
# its sample BRDFs, Fresnel reflectance and shadowing / masking slides, rebuilt from the library.

# Each figure's keys (the rule's params, exactly), spectra and outputs: its one line in
# reflectance.papers.figures.lecture.
LECTURE_LOBES_2D = figure_def("lecture_brdf_lobes_2d")
LECTURE_LOBES_3D = figure_def("lecture_brdf_lobes_3d")
LECTURE_FRESNEL = figure_def("lecture_fresnel")
LECTURE_SHADOWING = figure_def("lecture_shadowing_masking")
LECTURE_DISTRIBUTIONS = figure_def("lecture_distributions")
TARGETS += figure_targets(
    LECTURE_LOBES_2D, LECTURE_LOBES_3D, LECTURE_FRESNEL, LECTURE_SHADOWING, LECTURE_DISTRIBUTIONS
)


rule lecture_distributions:
    output:
        png=report(
            LECTURE_DISTRIBUTIONS.outputs["png"],
            caption="../report/lecture_distributions.rst",
            category="Lecture",
            subcategory="Microfacet distributions",
        ),
        pdf=LECTURE_DISTRIBUTIONS.outputs["pdf"],
        csv=LECTURE_DISTRIBUTIONS.outputs["csv"],
        summary=LECTURE_DISTRIBUTIONS.outputs["summary"],
    log:
        "logs/lecture/distributions.log",
    benchmark:
        "benchmarks/lecture/distributions.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **LECTURE_DISTRIBUTIONS.params,
    script:
        "../scripts/lecture_distributions.py"


rule lecture_brdf_lobes_2d:
    output:
        png=report(
            LECTURE_LOBES_2D.outputs["png"],
            caption="../report/lecture_brdf_lobes_2d.rst",
            category="Lecture",
            subcategory="Sample BRDFs",
        ),
        pdf=LECTURE_LOBES_2D.outputs["pdf"],
        csv=LECTURE_LOBES_2D.outputs["csv"],
        values=LECTURE_LOBES_2D.outputs["values"],
    log:
        "logs/lecture/brdf_lobes_2d.log",
    benchmark:
        "benchmarks/lecture/brdf_lobes_2d.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **LECTURE_LOBES_2D.params,
    script:
        "../scripts/lecture_brdf_lobes_2d.py"


rule lecture_brdf_lobes_3d:
    output:
        png=report(
            LECTURE_LOBES_3D.outputs["png"],
            caption="../report/lecture_brdf_lobes_3d.rst",
            category="Lecture",
            subcategory="Sample BRDFs",
        ),
        values=LECTURE_LOBES_3D.outputs["values"],
    log:
        "logs/lecture/brdf_lobes_3d.log",
    benchmark:
        "benchmarks/lecture/brdf_lobes_3d.tsv"
    threads: 1
    resources:
        mem_mb=1400,
        runtime=10,
    params:
        **LECTURE_LOBES_3D.params,
    script:
        "../scripts/lecture_brdf_lobes_3d.py"


rule lecture_fresnel:
    input:
        spectra=LECTURE_FRESNEL.spectra,
    output:
        png=report(
            LECTURE_FRESNEL.outputs["png"],
            caption="../report/lecture_fresnel.rst",
            category="Lecture",
            subcategory="Fresnel reflectance",
        ),
        pdf=LECTURE_FRESNEL.outputs["pdf"],
        csv=LECTURE_FRESNEL.outputs["csv"],
    log:
        "logs/lecture/fresnel.log",
    benchmark:
        "benchmarks/lecture/fresnel.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        **LECTURE_FRESNEL.params,
    script:
        "../scripts/lecture_fresnel.py"


rule lecture_shadowing_masking:
    output:
        png=report(
            LECTURE_SHADOWING.outputs["png"],
            caption="../report/lecture_shadowing_masking.rst",
            category="Lecture",
            subcategory="Shadowing and masking",
        ),
        pdf=LECTURE_SHADOWING.outputs["pdf"],
        g1=report(
            LECTURE_SHADOWING.outputs["g1"],
            caption="../report/lecture_shadowing_masking_table.rst",
            category="Lecture",
            subcategory="Shadowing and masking",
        ),
        by_slope=LECTURE_SHADOWING.outputs["by_slope"],
    log:
        "logs/lecture/shadowing_masking.log",
    benchmark:
        "benchmarks/lecture/shadowing_masking.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **LECTURE_SHADOWING.params,
    script:
        "../scripts/lecture_shadowing_masking.py"
