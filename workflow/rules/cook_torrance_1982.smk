# Cook & Torrance 1982, "A reflectance model for computer graphics": Figs. 4 and 5.

from reflectance.io.paths import project_file
from reflectance.papers.errata import errata_rows

CT82_OUT = "results/cook_torrance_1982"

TARGETS += [
    f"{CT82_OUT}/{name}"
    for name in (
        "fig4.png",
        "fig4.pdf",
        "fig4.csv",
        "fig4.values.rst",
        "fig5a.png",
        "fig5a.csv",
        "fig5bc.png",
        "fig5bc.pdf",
        "fig5bc.csv",
        "fig5bc.exr",
        "fig5bc_strip.csv",
        "fig5bc_approximation.csv",
        "fig5bc.values.rst",
    )
]


rule ct82_fig4:
    input:
        spectrum=spectrum_csv(CT82["fig4"]["material"]),
    output:
        png=report(
            f"{CT82_OUT}/fig4.png",
            caption="../report/ct82_fig4.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 4",
        ),
        pdf=f"{CT82_OUT}/fig4.pdf",
        csv=report(
            f"{CT82_OUT}/fig4.csv",
            caption="../report/ct82_fig4_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 4",
        ),
        values=f"{CT82_OUT}/fig4.values.rst",
    log:
        "logs/cook_torrance_1982/fig4.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig4.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=CT82["fig4"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_fig4.py"


rule ct82_fig5a:
    input:
        spectrum=spectrum_csv(CT82["fig5"]["material"]),
    output:
        png=report(
            f"{CT82_OUT}/fig5a.png",
            caption="../report/ct82_fig5a.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        csv=f"{CT82_OUT}/fig5a.csv",
    log:
        "logs/cook_torrance_1982/fig5a.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig5a.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        fig=CT82["fig5"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_fig5a.py"


rule ct82_fig5bc:
    input:
        spectrum=spectrum_csv(CT82["fig5"]["material"]),
    output:
        png=report(
            f"{CT82_OUT}/fig5bc.png",
            caption="../report/ct82_fig5bc.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        pdf=f"{CT82_OUT}/fig5bc.pdf",
        csv=report(
            f"{CT82_OUT}/fig5bc.csv",
            caption="../report/ct82_fig5bc_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        exr=f"{CT82_OUT}/fig5bc.exr",
        strip=f"{CT82_OUT}/fig5bc_strip.csv",
        approximation=report(
            f"{CT82_OUT}/fig5bc_approximation.csv",
            caption="../report/ct82_fig5bc_approximation.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        values=f"{CT82_OUT}/fig5bc.values.rst",
    log:
        "logs/cook_torrance_1982/fig5bc.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig5bc.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=CT82["fig5"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_fig5bc.py"


# Cook & Torrance 1982: Figs. 1-3 and Table I; the errata of all four texts.

CT82_ERRATA = config["figures"]["errata"]

# The symbols table and the errata rows are the project's own files (a path leaving the project
# is refused, naming its key); the errata rows are text, checked here (file and row named) before
# any job: an unknown id or a key other than the text ones stops the run.
try:
    CT82_SYMBOLS = project_file(
        CT82["fig1"]["symbols"], "figures.cook_torrance_1982.fig1.symbols", workflow.basedir
    )
    CT82_ERRATA_ROWS = project_file(CT82_ERRATA["rows"], "figures.errata.rows", workflow.basedir)
    errata_rows(CT82_ERRATA_ROWS)
except ValueError as err:
    raise WorkflowError(f"config.yaml: {err}") from None

TARGETS += [
    f"{CT82_OUT}/{name}"
    for name in (
        "fig1.png",
        "fig1.pdf",
        "fig1.csv",
        "fig2.png",
        "fig2.csv",
        "fig3.png",
        "fig3.csv",
        "table1.png",
        "table1.pdf",
        "table1.csv",
    )
] + ["results/errata/errata.csv", "results/errata/errata.png", "results/errata/errata.pdf"]


rule ct82_fig1:
    input:
        symbols=CT82_SYMBOLS,
    output:
        png=report(
            f"{CT82_OUT}/fig1.png",
            caption="../report/ct82_fig1.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 1",
        ),
        pdf=f"{CT82_OUT}/fig1.pdf",
        csv=f"{CT82_OUT}/fig1.csv",
    log:
        "logs/cook_torrance_1982/fig1.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig1.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=CT82["fig1"],
    script:
        "../scripts/cook_torrance_1982_fig1.py"


rule ct82_fig2:
    output:
        png=report(
            f"{CT82_OUT}/fig2.png",
            caption="../report/ct82_fig2.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 2",
        ),
        csv=f"{CT82_OUT}/fig2.csv",
    log:
        "logs/cook_torrance_1982/fig2.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig2.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        fig=CT82["fig2"],
    script:
        "../scripts/cook_torrance_1982_fig2.py"


rule ct82_fig3:
    output:
        png=report(
            f"{CT82_OUT}/fig3.png",
            caption="../report/ct82_fig3.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 3",
        ),
        csv=f"{CT82_OUT}/fig3.csv",
    log:
        "logs/cook_torrance_1982/fig3.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig3.tsv"
    threads: 1
    resources:
        mem_mb=1500,
        runtime=10,
    params:
        fig=CT82["fig3"],
    script:
        "../scripts/cook_torrance_1982_fig3.py"


rule ct82_table1:
    input:
        spectra=[
            spectrum_csv(CT82["fig7"]["table1_spectra"].get(row["material"], row["material"]))
            for row in CT82["table1"]["rows"]
        ],
        sources="spectra/sources.csv",
    output:
        png=report(
            f"{CT82_OUT}/table1.png",
            caption="../report/ct82_table1.rst",
            category="Cook & Torrance 1982",
            subcategory="Table I",
        ),
        pdf=f"{CT82_OUT}/table1.pdf",
        csv=report(
            f"{CT82_OUT}/table1.csv",
            caption="../report/ct82_table1.rst",
            category="Cook & Torrance 1982",
            subcategory="Table I",
        ),
    log:
        "logs/cook_torrance_1982/table1.log",
    benchmark:
        "benchmarks/cook_torrance_1982/table1.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        fig=CT82["table1"],
        spectra=CT82["fig7"]["table1_spectra"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_table1.py"


rule errata:
    input:
        rows=CT82_ERRATA_ROWS,
    output:
        csv=report(
            "results/errata/errata.csv",
            caption="../report/errata.rst",
            category="Errata",
            subcategory="All texts",
        ),
        png=report(
            "results/errata/errata.png",
            caption="../report/errata.rst",
            category="Errata",
            subcategory="All texts",
        ),
        pdf="results/errata/errata.pdf",
    log:
        "logs/errata/errata.log",
    benchmark:
        "benchmarks/errata/errata.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        errata=CT82_ERRATA,
    script:
        "../scripts/errata.py"
