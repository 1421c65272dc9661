# README's picture strip: a few of the rendered figures side by side, built like any other output
# (results/readme/strip.png; README.md says how the copy it shows is refreshed).

README_STRIP = config.get("readme", {}).get("strip", {"fig7_vases": []})
README_OUT = "results/readme"
# (check_config, in common.smk, has named any fig7_vases entry that is not a vase of Fig. 7)
if "readme" in config:  # (a config without the section builds no strip)
    TARGETS += [f"{README_OUT}/strip.png"]


rule readme_strip:
    input:
        vase=f"{CT82_OUT}/fig6b.png",
        vases=[f"{CT82_OUT}/fig7/{vase}.png" for vase in README_STRIP["fig7_vases"]],
        colours=f"{CT82_OUT}/fig5bc_strip.csv",
    output:
        png=f"{README_OUT}/strip.png",
    log:
        "logs/readme/strip.log",
    benchmark:
        "benchmarks/readme/strip.tsv"
    threads: 1
    resources:
        mem_mb=900,
        runtime=10,
    params:
        strip=README_STRIP,
        space=config["colour"]["space"],
    script:
        "../scripts/readme_strip.py"
