# Rendered figures (reflectance.render.pipeline). Each is defined once, in its module of
# reflectance.papers.figures: the config keys it reads (the rule's params, exactly: the params
# trigger reruns it for those keys and no other), its scenes (what the config check validates and
# the job renders) and its outputs. The rules add the report marks, resources and the script,
# which is one call of the figure's drawing, reflectance.papers.draw.<rule>; the param code, that
# module's SHA-256 (draw_digest), reruns the figure when its drawing changes.
# Their resources follow the measured peaks and times in workflow/docs/guides/cluster.rst.

# Cook & Torrance 1982, Fig. 6, the two vases: the default figure (fig6.published) and one figure
# per reading of the paper's ambient term (fig6.ambient_readings).
# One job for the whole family: the variants share one process's imports and, where their
# geometry, camera and lights agree (tracing.trace_key), one trace. The trade-off: editing one
# variant's parameter (a reading, fig6.published) reruns them all.
CT82_FIG6_DEF, CT82_FIG6_PARAMS, CT82_FIG6_OUTPUTS = figure_rule("ct82_fig6")
TARGETS += flat_outputs(CT82_FIG6_OUTPUTS)


rule ct82_fig6:
    input:
        spectra=[spectrum_csv(name) for name in CT82_FIG6_DEF.spectra(CT82_FIG6_PARAMS)],
    output:
        **ct82_reported(
            CT82_FIG6_DEF, CT82_FIG6_PARAMS, CT82_FIG6_OUTPUTS, "fig6", subcategory="Fig. 6"
        ),
    log:
        "logs/cook_torrance_1982/fig6.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig6.tsv"
    threads: 1
    resources:
        mem_mb=1800,
        runtime=10,
    params:
        **CT82_FIG6_PARAMS,
        code=draw_digest("ct82_fig6"),
    script:
        "../scripts/cook_torrance_1982_fig6.py"


# Rendered figures of Blinn 1977: Fig. 7, Phong vs Torrance-Sparrow, one row per light of
# fig7.lights, once per reading of Phong's p_s; the same as a light sweep (GIF); Fig. 8,
# shininess varying with two texture patterns.
B77_RENDER_OUT = "results/blinn_1977"
B77_FIG7_DEF, B77_FIG7_PARAMS, B77_FIG7_OUTPUTS = figure_rule("blinn77_fig7")
B77_FIG7_STEMS = B77_FIG7_DEF.stems(B77_FIG7_PARAMS)
TARGETS += flat_outputs(B77_FIG7_OUTPUTS)


rule blinn77_fig7:
    output:
        figures=[
            report(
                path,
                caption="../report/blinn77_fig7.rst",
                category="Blinn 1977",
                subcategory="Fig. 7",
            )
            for path in B77_FIG7_OUTPUTS["figures"]
        ],
        csv=report(
            B77_FIG7_OUTPUTS["csv"],
            caption="../report/blinn77_fig7_table.rst",
            category="Blinn 1977",
            subcategory="Fig. 7",
        ),
        renders=B77_FIG7_OUTPUTS["renders"],
        values=B77_FIG7_OUTPUTS["values"],
    log:
        "logs/blinn_1977/fig7.log",
    benchmark:
        "benchmarks/blinn_1977/fig7.tsv"
    threads: 1
    resources:
        mem_mb=2500,
        runtime=15,
    params:
        **B77_FIG7_PARAMS,
        code=draw_digest("blinn77_fig7"),
    script:
        "../scripts/blinn_1977_fig7.py"


B77_SWEEP_DEF, B77_SWEEP_PARAMS, B77_SWEEP_OUTPUTS = figure_rule("blinn77_fig7_sweep")
TARGETS += flat_outputs(B77_SWEEP_OUTPUTS)


rule blinn77_fig7_sweep:
    output:
        gif=report(
            B77_SWEEP_OUTPUTS["gif"],
            caption="../report/blinn77_fig7_sweep.rst",
            category="Blinn 1977",
            subcategory="Fig. 7",
        ),
        contact=report(
            B77_SWEEP_OUTPUTS["contact"],
            caption="../report/blinn77_fig7_sweep_contact.rst",
            category="Blinn 1977",
            subcategory="Fig. 7",
        ),
        csv=B77_SWEEP_OUTPUTS["csv"],
        values=B77_SWEEP_OUTPUTS["values"],
    log:
        "logs/blinn_1977/fig7_sweep.log",
    benchmark:
        "benchmarks/blinn_1977/fig7_sweep.tsv"
    threads: 1
    resources:
        mem_mb=1400,
        runtime=10,
    params:
        **B77_SWEEP_PARAMS,
        code=draw_digest("blinn77_fig7_sweep"),
    script:
        "../scripts/blinn_1977_fig7_sweep.py"


# Cook & Torrance 1982, Fig. 7 (the vases: six metals, Table I's six nonmetals and labelled variants,
# each rendered alone under Fig. 6's lighting): the default figure (fig7.png, fig7/<vase>.*), each
# vase exposed as fig6.published says, and once per reading of the ambient term with one exposure
# for the grid. One job for the family, as Fig. 6: the default figure and each reading share
# imports and the vases' one trace; editing one variant's parameter reruns them all.
CT82_FIG7_DEF, CT82_FIG7_PARAMS, CT82_FIG7_OUTPUTS = figure_rule("ct82_fig7")
CT82_FIG7_VASES = CT82_FIG7_DEF.vases(CT82_FIG7_PARAMS)
TARGETS += flat_outputs(CT82_FIG7_OUTPUTS)


rule ct82_fig7:
    input:
        spectra=[spectrum_csv(name) for name in CT82_FIG7_DEF.spectra(CT82_FIG7_PARAMS)],
        sources="spectra/sources.csv",
    output:
        **ct82_reported(
            CT82_FIG7_DEF, CT82_FIG7_PARAMS, CT82_FIG7_OUTPUTS, "fig7", subcategory="Fig. 7"
        ),
    log:
        "logs/cook_torrance_1982/fig7.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig7.tsv"
    threads: 1
    resources:
        mem_mb=1500,
        runtime=10,
    params:
        **CT82_FIG7_PARAMS,
        code=draw_digest("ct82_fig7"),
    script:
        "../scripts/cook_torrance_1982_fig7.py"


# Cook & Torrance 1982, Fig. 8 (the watch).
CT82_FIG8_DEF, CT82_FIG8_PARAMS, CT82_FIG8_OUTPUTS = figure_rule("ct82_fig8")
TARGETS += flat_outputs(CT82_FIG8_OUTPUTS)


rule ct82_fig8:
    input:
        spectra=[spectrum_csv(name) for name in CT82_FIG8_DEF.spectra(CT82_FIG8_PARAMS)],
    output:
        **{k: CT82_FIG8_OUTPUTS[k] for k in ("exr", "render_png", "scene", "values")},
        png=report(
            CT82_FIG8_OUTPUTS["png"],
            caption="../report/ct82_fig8.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 8",
        ),
        csv=report(
            CT82_FIG8_OUTPUTS["csv"],
            caption="../report/ct82_fig8_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 8",
        ),
    log:
        "logs/cook_torrance_1982/fig8.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig8.tsv"
    threads: 1
    resources:
        mem_mb=1700,
        runtime=10,
    params:
        **CT82_FIG8_PARAMS,
        code=draw_digest("ct82_fig8"),
    script:
        "../scripts/cook_torrance_1982_fig8.py"


B77_FIG8_DEF, B77_FIG8_PARAMS, B77_FIG8_OUTPUTS = figure_rule("blinn77_fig8")
TARGETS += flat_outputs(B77_FIG8_OUTPUTS)


rule blinn77_fig8:
    output:
        **{k: v for k, v in B77_FIG8_OUTPUTS.items() if k not in ("png", "csv")},
        png=report(
            B77_FIG8_OUTPUTS["png"],
            caption="../report/blinn77_fig8.rst",
            category="Blinn 1977",
            subcategory="Fig. 8",
        ),
        csv=report(
            B77_FIG8_OUTPUTS["csv"],
            caption="../report/blinn77_fig8_table.rst",
            category="Blinn 1977",
            subcategory="Fig. 8",
        ),
    log:
        "logs/blinn_1977/fig8.log",
    benchmark:
        "benchmarks/blinn_1977/fig8.tsv"
    threads: 1
    resources:
        mem_mb=1500,
        runtime=10,
    params:
        **B77_FIG8_PARAMS,
        code=draw_digest("blinn77_fig8"),
    script:
        "../scripts/blinn_1977_fig8.py"


# Rendered figure of the Wikipedia article "Specular highlight": its pair of spheres.

ARTICLE_SPHERES_OUT = "results/article"
SPHERES_DEF, SPHERES_PARAMS, SPHERES_OUTPUTS = figure_rule("article_spheres")
TARGETS += flat_outputs(SPHERES_OUTPUTS)


rule article_spheres:
    input:
        spectra=[spectrum_csv(name) for name in SPHERES_DEF.spectra(SPHERES_PARAMS)],
    output:
        **{
            k: SPHERES_OUTPUTS[k]
            for k in ("exr", "render", "scene", "values", "gold_exr", "gold_render", "gold_scene")
        },
        png=report(
            SPHERES_OUTPUTS["png"],
            caption="../report/article_spheres.rst",
            category="Article",
            subcategory="Pair of spheres",
        ),
        csv=report(
            SPHERES_OUTPUTS["csv"],
            caption="../report/article_spheres_table.rst",
            category="Article",
            subcategory="Pair of spheres",
        ),
    log:
        "logs/article/spheres.log",
    benchmark:
        "benchmarks/article/spheres.tsv"
    threads: 1
    resources:
        mem_mb=2100,
        runtime=10,
    params:
        **SPHERES_PARAMS,
        code=draw_digest("article_spheres"),
    script:
        "../scripts/article_spheres.py"


# Display-referred linear RGB EXRs (colour.linear_rgb_exr): one beside every rendered XYZ EXR
# that has its scene file, for viewers that show XYZ channels as nothing.
if config["colour"].get("linear_rgb_exr", False):
    TARGETS += [
        f"{t[:-len('.exr')]}.rgb.exr"
        for t in list(TARGETS)
        if t.endswith(".exr") and f"{t[:-len('.exr')]}.scene.yaml" in TARGETS
    ]


rule linear_rgb_exr:
    input:
        exr="{stem}.exr",
        scene="{stem}.scene.yaml",
    output:
        "{stem}.rgb.exr",
    log:
        "logs/linear_rgb_exr/{stem}.log",
    benchmark:
        "benchmarks/linear_rgb_exr/{stem}.tsv"
    wildcard_constraints:
        stem=r"results/[^.]+",
    threads: 1
    resources:
        mem_mb=1500,  # no measurement (off by default): what a render of its size asks
        runtime=10,
    script:
        "../scripts/linear_rgb_exr.py"
