# Blinn 1977, "Models of light reflection for computer synthesized pictures": the analytic figures
# (Figs. 1-4 V-groove geometry, Figs. 5-6 polar plots, D1/D2/D3 at equal beta, the cost of each
# term). Figs. 7, 8 elsewhere.

# Each figure's keys (the rule's params, exactly) and outputs: its one line in
# reflectance.papers.figures.blinn_1977.
B77_FIG1 = figure_def("blinn77_fig1")
B77_FIG2_4 = figure_def("blinn77_fig2_4")
B77_FIG5_6 = figure_def("blinn77_fig5_6")
B77_DISTRIBUTIONS = figure_def("blinn77_distributions")
B77_COST_COUNTS = figure_def("blinn77_cost_counts")
B77_COST_TIMING = figure_def("blinn77_cost_timing")
TARGETS += figure_targets(
    B77_FIG1, B77_FIG2_4, B77_FIG5_6, B77_DISTRIBUTIONS, B77_COST_COUNTS, B77_COST_TIMING
)
MEASUREMENTS += figure_targets(B77_COST_TIMING)


rule blinn77_fig1:
    output:
        png=report(
            B77_FIG1.outputs["png"],
            caption="../report/blinn77_fig1.rst",
            category="Blinn 1977",
            subcategory="Figs. 1-4",
        ),
        pdf=B77_FIG1.outputs["pdf"],
        csv=report(
            B77_FIG1.outputs["csv"],
            caption="../report/blinn77_fig1_table.rst",
            category="Blinn 1977",
            subcategory="Figs. 1-4",
        ),
    log:
        "logs/blinn_1977/fig1.log",
    benchmark:
        "benchmarks/blinn_1977/fig1.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        **B77_FIG1.params,
    script:
        "../scripts/blinn_1977_fig1.py"


rule blinn77_fig2_4:
    output:
        png=report(
            B77_FIG2_4.outputs["png"],
            caption="../report/blinn77_fig2_4.rst",
            category="Blinn 1977",
            subcategory="Figs. 1-4",
        ),
        pdf=B77_FIG2_4.outputs["pdf"],
        csv=report(
            B77_FIG2_4.outputs["csv"],
            caption="../report/blinn77_fig2_4_table.rst",
            category="Blinn 1977",
            subcategory="Figs. 1-4",
        ),
    log:
        "logs/blinn_1977/fig2_4.log",
    benchmark:
        "benchmarks/blinn_1977/fig2_4.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **B77_FIG2_4.params,
    script:
        "../scripts/blinn_1977_fig2_4.py"


rule blinn77_fig5_6:
    output:
        png=report(
            B77_FIG5_6.outputs["png"],
            caption="../report/blinn77_fig5_6.rst",
            category="Blinn 1977",
            subcategory="Figs. 5-6",
        ),
        pdf=B77_FIG5_6.outputs["pdf"],
        variant_png=report(
            B77_FIG5_6.outputs["variant_png"],
            caption="../report/blinn77_fig5_6_fig7_materials.rst",
            category="Blinn 1977",
            subcategory="Figs. 5-6",
        ),
        variant_pdf=B77_FIG5_6.outputs["variant_pdf"],
        csv=B77_FIG5_6.outputs["csv"],
        summary=report(
            B77_FIG5_6.outputs["summary"],
            caption="../report/blinn77_fig5_6_table.rst",
            category="Blinn 1977",
            subcategory="Figs. 5-6",
        ),
        values=B77_FIG5_6.outputs["values"],
    log:
        "logs/blinn_1977/{fig}.log",
    benchmark:
        "benchmarks/blinn_1977/{fig}.tsv"
    wildcard_constraints:
        fig="fig5|fig6",
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=B77_FIG5_6.params["fig"],
        # each job its own figure's angle, of the declared fig5_6.incidence_deg
        incidence_deg=lambda wildcards: B77_FIG5_6.params["incidence_deg"][wildcards.fig],
        figure_number=lambda wildcards: wildcards.fig[3:],
    script:
        "../scripts/blinn_1977_fig5_6.py"


rule blinn77_distributions:
    output:
        png=report(
            B77_DISTRIBUTIONS.outputs["png"],
            caption="../report/blinn77_distributions.rst",
            category="Blinn 1977",
            subcategory="D1, D2, D3",
        ),
        pdf=B77_DISTRIBUTIONS.outputs["pdf"],
        csv=B77_DISTRIBUTIONS.outputs["csv"],
        summary=report(
            B77_DISTRIBUTIONS.outputs["summary"],
            caption="../report/blinn77_distributions_table.rst",
            category="Blinn 1977",
            subcategory="D1, D2, D3",
        ),
    log:
        "logs/blinn_1977/distributions.log",
    benchmark:
        "benchmarks/blinn_1977/distributions.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **B77_DISTRIBUTIONS.params,
    script:
        "../scripts/blinn_1977_distributions.py"


rule blinn77_cost_counts:
    output:
        csv=report(
            B77_COST_COUNTS.outputs["csv"],
            caption="../report/blinn77_cost_counts.rst",
            category="Blinn 1977",
            subcategory="Cost of D1, D2, D3, G, F",
        ),
        values=B77_COST_COUNTS.outputs["values"],
    log:
        "logs/blinn_1977/cost_counts.log",
    benchmark:
        "benchmarks/blinn_1977/cost_counts.tsv"
    threads: 1
    resources:
        mem_mb=500,
        runtime=10,
    params:
        **B77_COST_COUNTS.params,
    script:
        "../scripts/blinn_1977_cost_counts.py"


# A measurement: its outputs differ from run to run (MEASUREMENTS); one thread, so that the
# numpy loops it times are the ones a render's job runs.
rule blinn77_cost_timing:
    input:
        counts=B77_COST_COUNTS.outputs["csv"],
    output:
        csv=report(
            B77_COST_TIMING.outputs["csv"],
            caption="../report/blinn77_cost_timing.rst",
            category="Blinn 1977",
            subcategory="Cost of D1, D2, D3, G, F",
        ),
        measurement=B77_COST_TIMING.outputs["measurement"],
        values=B77_COST_TIMING.outputs["values"],
    log:
        "logs/blinn_1977/cost_timing.log",
    benchmark:
        "benchmarks/blinn_1977/cost_timing.tsv"
    threads: 1
    resources:
        mem_mb=1200,
        runtime=10,
    params:
        **B77_COST_TIMING.params,
    script:
        "../scripts/blinn_1977_cost_timing.py"
