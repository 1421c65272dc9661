# Rendered figures (reflectance.render.pipeline): Cook & Torrance 1982, Fig. 6, the two vases, once per
# reading of the paper's ambient term (figures.cook_torrance_1982.fig6.ambient_readings).

CT82_FIG6 = CT82["fig6"]
CT82_FIG6_READINGS = list(CT82_FIG6["ambient_readings"])
CT82_PUBLISHED = CT82_FIG6["published"]  # the default figures (unsuffixed names)
CT82_FIG6_SPECTRA = sorted(
    {
        spectrum_csv(panel[key])
        for panel in CT82_FIG6["panels"].values()
        for key in ("material", "diffuse_material")
    }
)

TARGETS += [
    f"{CT82_OUT}/{name}"
    for reading in CT82_FIG6_READINGS
    for name in [f"fig6_{reading}.png", f"fig6_{reading}.csv"]
    + [f"fig6{panel}_{reading}.{ext}" for panel in "ab" for ext in ("exr", "png", "scene.yaml")]
]


TARGETS += [
    f"{CT82_OUT}/{name}"
    for name in ["fig6.png", "fig6.csv", "fig6.values.rst"]
    + [f"fig6{panel}.{ext}" for panel in "ab" for ext in ("exr", "png", "scene.yaml")]
]


# One job for the whole family (the default figure, then each reading): the variants share one
# process's imports and, where their geometry, camera and lights agree (pipeline.trace_key), one
# trace. The trade-off: editing one variant's parameter (a reading, fig6.published) reruns them all.
CT82_FIG6_FILES = {
    "png": "fig6{}.png",
    "csv": "fig6{}.csv",
    **{
        f"{panel}_{ext.split('.')[0]}": f"fig6{panel}{{}}.{ext}"
        for panel in "ab"
        for ext in ("exr", "png", "scene.yaml")
    },
}


rule ct82_fig6:
    input:
        spectra=CT82_FIG6_SPECTRA,
    output:
        **{
            key: path
            for reading in [None] + CT82_FIG6_READINGS
            for key, path in ct82_reported(
                ct82_fig6_outputs(reading), "fig6", reading, subcategory="Fig. 6"
            ).items()
        },
        values=f"{CT82_OUT}/fig6.values.rst",
    log:
        "logs/cook_torrance_1982/fig6.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig6.tsv"
    threads: 1
    resources:
        mem_mb=1800,  # script peak 872 MB (3 variants, one trace)
        runtime=10,  # measured 8 s (2026-12-02; the 3 jobs it replaces: 21 s)
    params:
        fig=CT82_FIG6,
        reference=CT82_PUBLISHED["ambient_reference"],
        published=CT82_PUBLISHED,
        readings=CT82_FIG6["ambient_readings"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_fig6.py"


# Rendered figures of Blinn 1977 (reflectance.papers.scenes): Fig. 7, Phong vs Torrance-Sparrow,
# edge and front lit, once per reading of Phong's p_s; the same as a light sweep (GIF); Fig. 8,
# shininess varying with two texture patterns.

B77_RENDER = config["figures"]["blinn_1977"]
B77_RENDER_OUT = "results/blinn_1977"
B77_FIG7 = B77_RENDER["fig7"]
B77_FIG7_READINGS = list(B77_FIG7["phong_specular_readings"])
B77_FIG7_STEMS = {
    key: f"{B77_RENDER_OUT}/fig7{key[0]}{key[1:]}"
    for p in "ab"
    for light in ("edge", "front")
    for key in [f"{p}_torrance_sparrow_{light}"]
    + [f"{p}_phong_{light}_{r}" for r in B77_FIG7_READINGS]
}

TARGETS += (
    [f"{B77_RENDER_OUT}/fig7_{r}.png" for r in B77_FIG7_READINGS]
    + [f"{B77_RENDER_OUT}/fig7.csv", f"{B77_RENDER_OUT}/fig7.values.rst"]
    + [f"{stem}.{ext}" for stem in B77_FIG7_STEMS.values() for ext in ("exr", "png", "scene.yaml")]
)


rule blinn77_fig7:
    output:
        figures=[
            report(
                f"{B77_RENDER_OUT}/fig7_{r}.png",
                caption="../report/blinn77_fig7.rst",
                category="Blinn 1977",
                subcategory="Fig. 7",
            )
            for r in B77_FIG7_READINGS
        ],
        csv=report(
            f"{B77_RENDER_OUT}/fig7.csv",
            caption="../report/blinn77_fig7_table.rst",
            category="Blinn 1977",
            subcategory="Fig. 7",
        ),
        renders=[
            f"{stem}.{ext}"
            for stem in B77_FIG7_STEMS.values()
            for ext in ("exr", "png", "scene.yaml")
        ],
        values=f"{B77_RENDER_OUT}/fig7.values.rst",
    log:
        "logs/blinn_1977/fig7.log",
    benchmark:
        "benchmarks/blinn_1977/fig7.tsv"
    threads: 1
    resources:
        mem_mb=1500,  # script peak 709 MB (three shared traces held)
        runtime=15,  # measured 242 s
    params:
        fig=B77_FIG7,
        stems=B77_FIG7_STEMS,
        wavelengths=config["wavelengths"],
    script:
        "../scripts/blinn_1977_fig7.py"


B77_SWEEP = B77_RENDER["fig7_sweep"]

TARGETS += [f"{B77_RENDER_OUT}/fig7_sweep.{ext}" for ext in ("gif", "png", "csv", "values.rst")]


rule blinn77_fig7_sweep:
    output:
        gif=report(
            f"{B77_RENDER_OUT}/fig7_sweep.gif",
            caption="../report/blinn77_fig7_sweep.rst",
            category="Blinn 1977",
            subcategory="Fig. 7",
        ),
        contact=report(
            f"{B77_RENDER_OUT}/fig7_sweep.png",
            caption="../report/blinn77_fig7_sweep_contact.rst",
            category="Blinn 1977",
            subcategory="Fig. 7",
        ),
        csv=f"{B77_RENDER_OUT}/fig7_sweep.csv",
        values=f"{B77_RENDER_OUT}/fig7_sweep.values.rst",
    log:
        "logs/blinn_1977/fig7_sweep.log",
    benchmark:
        "benchmarks/blinn_1977/fig7_sweep.tsv"
    threads: 1
    resources:
        mem_mb=1400,  # script peak 494 MB
        runtime=10,  # measured 185 s
    params:
        sweep=B77_SWEEP,
        fig7=B77_FIG7,
        wavelengths=config["wavelengths"],
    script:
        "../scripts/blinn_1977_fig7_sweep.py"


# Cook & Torrance 1982, Fig. 7 (the vases: six metals, Table I's six nonmetals and labelled variants,
# each rendered alone under Fig. 6's lighting): the default figure (fig7.png, fig7/<vase>.*), each
# vase exposed as fig6.published says, and once per reading of the ambient term with one exposure
# for the grid; Fig. 8 (the watch).

CT82_FIG7 = CT82["fig7"]
CT82_FIG7_ROWS = [
    CT82_FIG7["table1_spectra"].get(row["material"], row["material"])
    for row in CT82["table1"]["rows"]
]
CT82_FIG7_VASES = (
    [metal["material"] for metal in CT82_FIG7["metals"]]
    + CT82_FIG7_ROWS
    + [f"{extra['table1']}_{extra['material']}" for extra in CT82_FIG7["extras"]]
)
CT82_FIG7_SPECTRA = sorted(
    {spectrum_csv(m["material"]) for m in CT82_FIG7["metals"]}
    | {spectrum_csv(name) for name in CT82_FIG7_ROWS}
    | {spectrum_csv(e["material"]) for e in CT82_FIG7["extras"]}
)
CT82_FIG7_STEMS = ["fig7"] + [f"fig7_{r}" for r in CT82_FIG6_READINGS]

TARGETS += [
    f"{CT82_OUT}/{name}"
    for stem in CT82_FIG7_STEMS
    for name in [f"{stem}.png", f"{stem}.csv"]
    + [f"{stem}/{vase}.{ext}" for vase in CT82_FIG7_VASES for ext in ("exr", "scene.yaml")]
] + [f"{CT82_OUT}/fig7/{vase}.png" for vase in CT82_FIG7_VASES]
TARGETS += [f"{CT82_OUT}/fig7.values.rst"]


# One job for the family, as Fig. 6: the default figure and each reading share imports and the
# vases' one trace; editing one variant's parameter reruns them all.
rule ct82_fig7:
    input:
        spectra=CT82_FIG7_SPECTRA,
        sources="spectra/sources.csv",
    output:
        **{
            key: path
            for reading in [None] + CT82_FIG6_READINGS
            for key, path in ct82_reported(
                ct82_fig7_outputs(reading), "fig7", reading, subcategory="Fig. 7"
            ).items()
        },
        values=f"{CT82_OUT}/fig7.values.rst",
    log:
        "logs/cook_torrance_1982/fig7.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig7.tsv"
    threads: 1
    resources:
        mem_mb=1500,  # script peak 639 MB (3 variants, one trace)
        runtime=10,  # measured 10 s (2026-12-02; the 3 jobs it replaces: 24 s)
    params:
        fig=CT82_FIG7,
        fig6=CT82_FIG6,
        table1=CT82["table1"]["rows"],
        reference=CT82_PUBLISHED["ambient_reference"],
        published=CT82_PUBLISHED,
        readings=CT82_FIG6["ambient_readings"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_fig7.py"


CT82_FIG8 = CT82["fig8"]


CT82_FIG8_MATERIALS = {
    spec.get("material", spec.get("table1"))  # a Table I row names its material
    for spec in CT82_FIG8["parts"].values()
}

TARGETS += [
    f"{CT82_OUT}/fig8{suffix}"
    for suffix in (".png", ".csv", ".exr", "_render.png", ".scene.yaml", ".values.rst")
]


rule ct82_fig8:
    input:
        spectra=sorted(spectrum_csv(name) for name in CT82_FIG8_MATERIALS),
    output:
        png=report(
            f"{CT82_OUT}/fig8.png",
            caption="../report/ct82_fig8.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 8",
        ),
        csv=report(
            f"{CT82_OUT}/fig8.csv",
            caption="../report/ct82_fig8_table.rst",
            category="Cook & Torrance 1982",
            subcategory="Fig. 8",
        ),
        exr=f"{CT82_OUT}/fig8.exr",
        render_png=f"{CT82_OUT}/fig8_render.png",
        scene=f"{CT82_OUT}/fig8.scene.yaml",
        values=f"{CT82_OUT}/fig8.values.rst",
    log:
        "logs/cook_torrance_1982/fig8.log",
    benchmark:
        "benchmarks/cook_torrance_1982/fig8.tsv"
    threads: 1
    resources:
        mem_mb=1700,  # script peak 743 MB
        runtime=10,  # measured 139 s
    params:
        fig=CT82_FIG8,
        fig6=CT82_FIG6,
        table1=CT82["table1"]["rows"],
        wavelengths=config["wavelengths"],
        colour=config["colour"],
    script:
        "../scripts/cook_torrance_1982_fig8.py"


B77_FIG8 = B77_RENDER["fig8"]

TARGETS += [f"{B77_RENDER_OUT}/fig8.{ext}" for ext in ("png", "csv", "values.rst")] + [
    f"{B77_RENDER_OUT}/fig8{part}.{ext}" for part in "ab" for ext in ("exr", "png", "scene.yaml")
]


rule blinn77_fig8:
    output:
        png=report(
            f"{B77_RENDER_OUT}/fig8.png",
            caption="../report/blinn77_fig8.rst",
            category="Blinn 1977",
            subcategory="Fig. 8",
        ),
        csv=report(
            f"{B77_RENDER_OUT}/fig8.csv",
            caption="../report/blinn77_fig8_table.rst",
            category="Blinn 1977",
            subcategory="Fig. 8",
        ),
        a_exr=f"{B77_RENDER_OUT}/fig8a.exr",
        a_png=f"{B77_RENDER_OUT}/fig8a.png",
        a_scene=f"{B77_RENDER_OUT}/fig8a.scene.yaml",
        b_exr=f"{B77_RENDER_OUT}/fig8b.exr",
        b_png=f"{B77_RENDER_OUT}/fig8b.png",
        b_scene=f"{B77_RENDER_OUT}/fig8b.scene.yaml",
        values=f"{B77_RENDER_OUT}/fig8.values.rst",
    log:
        "logs/blinn_1977/fig8.log",
    benchmark:
        "benchmarks/blinn_1977/fig8.tsv"
    threads: 1
    resources:
        mem_mb=1500,  # script peak 590 MB
        runtime=10,  # measured 88 s
    params:
        fig=B77_FIG8,
        fig7=B77_FIG7,
        n=B77_FIG7["panels"][B77_FIG8["panel"]]["n"],
        wavelengths=config["wavelengths"],
    script:
        "../scripts/blinn_1977_fig8.py"


# Rendered figure of the Wikipedia article "Specular highlight": its pair of spheres.

ARTICLE_SPHERES = config["figures"]["article"]["spheres"]
ARTICLE_SPHERES_OUT = "results/article"

TARGETS += [
    f"{ARTICLE_SPHERES_OUT}/spheres.{ext}"
    for ext in ("png", "csv", "exr", "scene.yaml", "values.rst")
] + [f"{ARTICLE_SPHERES_OUT}/spheres_render.png"]


rule article_spheres:
    input:
        spectra=[
            spectrum_csv(ARTICLE_SPHERES["material"]),
            spectrum_csv(ARTICLE_SPHERES["metal_sphere"]["material"]),
        ]
        + [spectrum_csv(s["diffuse_material"]) for s in ARTICLE_SPHERES["spheres"]],
    output:
        png=report(
            f"{ARTICLE_SPHERES_OUT}/spheres.png",
            caption="../report/article_spheres.rst",
            category="Article",
            subcategory="Pair of spheres",
        ),
        csv=report(
            f"{ARTICLE_SPHERES_OUT}/spheres.csv",
            caption="../report/article_spheres_table.rst",
            category="Article",
            subcategory="Pair of spheres",
        ),
        exr=f"{ARTICLE_SPHERES_OUT}/spheres.exr",
        render=f"{ARTICLE_SPHERES_OUT}/spheres_render.png",
        scene=f"{ARTICLE_SPHERES_OUT}/spheres.scene.yaml",
        values=f"{ARTICLE_SPHERES_OUT}/spheres.values.rst",
    log:
        "logs/article/spheres.log",
    benchmark:
        "benchmarks/article/spheres.tsv"
    threads: 1
    resources:
        mem_mb=2100,  # script peak 1079 MB
        runtime=10,  # measured 83 s
    params:
        fig=ARTICLE_SPHERES,
        pigments={
            s["diffuse_material"]: config["materials"][s["diffuse_material"]]
            for s in ARTICLE_SPHERES["spheres"]
        },
        wavelengths=config["wavelengths"],
        colour=config["colour"],
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
        mem_mb=1500,  # not measured (off by default): as a render of its size
        runtime=10,  # not measured
    script:
        "../scripts/linear_rgb_exr.py"
