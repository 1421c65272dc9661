# Blinn 1977, "Models of light reflection for computer synthesized pictures": the analytic figures
# (Figs. 1-4 V-groove geometry, Figs. 5-6 polar plots, D1/D2/D3 at equal beta). Figs. 7, 8 elsewhere.

B77_ANALYTIC = config["figures"]["blinn_1977"]
B77_ANALYTIC_OUT = "results/blinn_1977"

TARGETS += [
    f"{B77_ANALYTIC_OUT}/{name}"
    for name in (
        "fig1.png",
        "fig1.pdf",
        "fig1.csv",
        "fig2_4.png",
        "fig2_4.pdf",
        "fig2_4.csv",
        "fig5.png",
        "fig5.pdf",
        "fig5.csv",
        "fig5_summary.csv",
        "fig5.values.rst",
        "fig6.png",
        "fig6.pdf",
        "fig6.csv",
        "fig6_summary.csv",
        "fig6.values.rst",
        "distributions.png",
        "distributions.pdf",
        "distributions.csv",
        "distributions_max_difference.csv",
    )
]


rule blinn77_fig1:
    output:
        png=report(
            f"{B77_ANALYTIC_OUT}/fig1.png",
            caption="../report/blinn77_fig1.rst",
            category="Blinn 1977",
            subcategory="Figs. 1-4",
        ),
        pdf=f"{B77_ANALYTIC_OUT}/fig1.pdf",
        csv=report(
            f"{B77_ANALYTIC_OUT}/fig1.csv",
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
        fig=B77_ANALYTIC["fig1_4"],
    script:
        "../scripts/blinn_1977_fig1.py"


rule blinn77_fig2_4:
    output:
        png=report(
            f"{B77_ANALYTIC_OUT}/fig2_4.png",
            caption="../report/blinn77_fig2_4.rst",
            category="Blinn 1977",
            subcategory="Figs. 1-4",
        ),
        pdf=f"{B77_ANALYTIC_OUT}/fig2_4.pdf",
        csv=report(
            f"{B77_ANALYTIC_OUT}/fig2_4.csv",
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
        fig=B77_ANALYTIC["fig1_4"],
    script:
        "../scripts/blinn_1977_fig2_4.py"


rule blinn77_fig5_6:
    output:
        png=report(
            f"{B77_ANALYTIC_OUT}/{{fig}}.png",
            caption="../report/blinn77_fig5_6.rst",
            category="Blinn 1977",
            subcategory="Figs. 5-6",
        ),
        pdf=f"{B77_ANALYTIC_OUT}/{{fig}}.pdf",
        csv=f"{B77_ANALYTIC_OUT}/{{fig}}.csv",
        summary=report(
            f"{B77_ANALYTIC_OUT}/{{fig}}_summary.csv",
            caption="../report/blinn77_fig5_6_table.rst",
            category="Blinn 1977",
            subcategory="Figs. 5-6",
        ),
        values=f"{B77_ANALYTIC_OUT}/{{fig}}.values.rst",
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
        fig=B77_ANALYTIC["fig5_6"],
        incidence_deg=lambda wildcards: B77_ANALYTIC["fig5_6"]["incidence_deg"][wildcards.fig],
        figure_number=lambda wildcards: wildcards.fig[3:],
    script:
        "../scripts/blinn_1977_fig5_6.py"


rule blinn77_distributions:
    output:
        png=report(
            f"{B77_ANALYTIC_OUT}/distributions.png",
            caption="../report/blinn77_distributions.rst",
            category="Blinn 1977",
            subcategory="D1, D2, D3",
        ),
        pdf=f"{B77_ANALYTIC_OUT}/distributions.pdf",
        csv=f"{B77_ANALYTIC_OUT}/distributions.csv",
        summary=report(
            f"{B77_ANALYTIC_OUT}/distributions_max_difference.csv",
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
        fig=B77_ANALYTIC["distributions"],
    script:
        "../scripts/blinn_1977_distributions.py"
