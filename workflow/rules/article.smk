# Article: Wikipedia, "Specular highlight" (oldid 793299363, 31 July 2017): its specular
# distributions side by side, and its worked Phong example recomputed step by step.

ARTICLE = config["figures"]["article"]
ARTICLE_OUT = "results/article"

TARGETS += [
    f"{ARTICLE_OUT}/{name}"
    for name in (
        "distributions.png",
        "distributions.pdf",
        "distributions.csv",
        "phong_example.png",
        "phong_example.pdf",
        "phong_example.csv",
        "phong_example.values.rst",
    )
]


rule article_distributions:
    output:
        png=report(
            f"{ARTICLE_OUT}/distributions.png",
            caption="../report/article_distributions.rst",
            category="Article",
            subcategory="Models of specular highlight",
        ),
        pdf=f"{ARTICLE_OUT}/distributions.pdf",
        csv=f"{ARTICLE_OUT}/distributions.csv",
    log:
        "logs/article/distributions.log",
    benchmark:
        "benchmarks/article/distributions.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        fig=ARTICLE["distributions"],
    script:
        "../scripts/article_distributions.py"


rule article_phong_example:
    output:
        png=report(
            f"{ARTICLE_OUT}/phong_example.png",
            caption="../report/article_phong_example.rst",
            category="Article",
            subcategory="Phong example",
        ),
        pdf=f"{ARTICLE_OUT}/phong_example.pdf",
        csv=report(
            f"{ARTICLE_OUT}/phong_example.csv",
            caption="../report/article_phong_example_table.rst",
            category="Article",
            subcategory="Phong example",
        ),
        values=f"{ARTICLE_OUT}/phong_example.values.rst",
    log:
        "logs/article/phong_example.log",
    benchmark:
        "benchmarks/article/phong_example.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        fig=ARTICLE["phong_example"],
    script:
        "../scripts/article_phong_example.py"
