# Article: Wikipedia, "Specular highlight" (oldid 793299363, 31 July 2017): its specular
# distributions side by side, and its worked Phong example recomputed step by step.

# Each figure's keys (the rule's params, exactly) and outputs: its one line in
# reflectance.papers.figures.article.
ARTICLE_DISTRIBUTIONS = figure_def("article_distributions")
ARTICLE_PHONG = figure_def("article_phong_example")
TARGETS += figure_targets(ARTICLE_DISTRIBUTIONS, ARTICLE_PHONG)


rule article_distributions:
    output:
        png=report(
            ARTICLE_DISTRIBUTIONS.outputs["png"],
            caption="../report/article_distributions.rst",
            category="Article",
            subcategory="Models of specular highlight",
        ),
        pdf=ARTICLE_DISTRIBUTIONS.outputs["pdf"],
        csv=ARTICLE_DISTRIBUTIONS.outputs["csv"],
    log:
        "logs/article/distributions.log",
    benchmark:
        "benchmarks/article/distributions.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        **ARTICLE_DISTRIBUTIONS.params,
    script:
        "../scripts/article_distributions.py"


rule article_phong_example:
    output:
        png=report(
            ARTICLE_PHONG.outputs["png"],
            caption="../report/article_phong_example.rst",
            category="Article",
            subcategory="Phong example",
        ),
        pdf=ARTICLE_PHONG.outputs["pdf"],
        csv=report(
            ARTICLE_PHONG.outputs["csv"],
            caption="../report/article_phong_example_table.rst",
            category="Article",
            subcategory="Phong example",
        ),
        values=ARTICLE_PHONG.outputs["values"],
    log:
        "logs/article/phong_example.log",
    benchmark:
        "benchmarks/article/phong_example.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        **ARTICLE_PHONG.params,
    script:
        "../scripts/article_phong_example.py"
