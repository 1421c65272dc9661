# Cook & Torrance 1982, "A reflectance model for computer graphics": Figs. 4 and 5.

CT82_OUT = "results/cook_torrance_1982"

TARGETS += [
    f"{CT82_OUT}/{name}"
    for name in ("fig4.png", "fig4.pdf", "fig4.csv", "fig5a.png", "fig5a.csv",
                 "fig5bc.png", "fig5bc.pdf", "fig5bc.csv", "fig5bc.exr")
]


rule ct82_fig4:
    input:
        spectrum=spectrum_csv(CT82["fig4"]["material"]),
    output:
        png=report(f"{CT82_OUT}/fig4.png", caption="../report/ct82_fig4.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 4"),
        pdf=f"{CT82_OUT}/fig4.pdf",
        csv=report(f"{CT82_OUT}/fig4.csv", caption="../report/ct82_fig4_table.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 4"),
    params:
        fig=CT82["fig4"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    log:
        "logs/cook_torrance_1982/fig4.log",
    script:
        "../scripts/cook_torrance_1982_fig4.py"


rule ct82_fig5a:
    input:
        spectrum=spectrum_csv(CT82["fig5"]["material"]),
    output:
        png=report(f"{CT82_OUT}/fig5a.png", caption="../report/ct82_fig5a.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 5"),
        csv=f"{CT82_OUT}/fig5a.csv",
    params:
        fig=CT82["fig5"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    log:
        "logs/cook_torrance_1982/fig5a.log",
    script:
        "../scripts/cook_torrance_1982_fig5a.py"


rule ct82_fig5bc:
    input:
        spectrum=spectrum_csv(CT82["fig5"]["material"]),
    output:
        png=report(f"{CT82_OUT}/fig5bc.png", caption="../report/ct82_fig5bc.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 5"),
        pdf=f"{CT82_OUT}/fig5bc.pdf",
        csv=report(f"{CT82_OUT}/fig5bc.csv", caption="../report/ct82_fig5bc_table.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 5"),
        exr=f"{CT82_OUT}/fig5bc.exr",
    params:
        fig=CT82["fig5"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    log:
        "logs/cook_torrance_1982/fig5bc.log",
    script:
        "../scripts/cook_torrance_1982_fig5bc.py"
