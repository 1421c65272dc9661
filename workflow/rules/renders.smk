# Rendered figures (reflectance.render): Cook & Torrance 1982, Fig. 6, the two vases, once per
# reading of the paper's ambient term (figures.cook_torrance_1982.fig6.ambient_readings).

CT82_FIG6 = CT82["fig6"]
CT82_FIG6_READINGS = list(CT82_FIG6["ambient_readings"])

TARGETS += [
    f"{CT82_OUT}/{name}"
    for reading in CT82_FIG6_READINGS
    for name in [f"fig6_{reading}.png", f"fig6_{reading}.csv"] + [
        f"fig6{panel}_{reading}.{ext}" for panel in "ab" for ext in ("exr", "png", "scene.yaml")
    ]
]


rule ct82_fig6:
    input:
        spectra=sorted({spectrum_csv(panel[key]) for panel in CT82_FIG6["panels"].values()
                        for key in ("material", "diffuse_material")}),
    output:
        png=report(f"{CT82_OUT}/fig6_{{reading}}.png", caption="../report/ct82_fig6.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 6"),
        csv=report(f"{CT82_OUT}/fig6_{{reading}}.csv", caption="../report/ct82_fig6_table.rst",
                   category="Cook & Torrance 1982", subcategory="Fig. 6"),
        a_exr=f"{CT82_OUT}/fig6a_{{reading}}.exr",
        a_png=f"{CT82_OUT}/fig6a_{{reading}}.png",
        a_scene=f"{CT82_OUT}/fig6a_{{reading}}.scene.yaml",
        b_exr=f"{CT82_OUT}/fig6b_{{reading}}.exr",
        b_png=f"{CT82_OUT}/fig6b_{{reading}}.png",
        b_scene=f"{CT82_OUT}/fig6b_{{reading}}.scene.yaml",
    wildcard_constraints:
        reading=_one_of(CT82_FIG6_READINGS),
    params:
        fig=CT82_FIG6,
        reference=lambda wildcards: CT82_FIG6["ambient_readings"][wildcards.reading],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    log:
        "logs/cook_torrance_1982/fig6_{reading}.log",
    script:
        "../scripts/cook_torrance_1982_fig6.py"
