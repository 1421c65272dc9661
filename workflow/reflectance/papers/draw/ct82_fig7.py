"""Cook & Torrance 1982, Fig. 7, drawn: the job of rule ``ct82_fig7``, called by its script,
``workflow/scripts/cook_torrance_1982_fig7.py`` (which says what the figure shows). What the job
reads, renders and writes is declared in :mod:`reflectance.papers.figures.ct82_fig7`."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

from colour.colorimetry import lightness_CIE1976
import numpy as np
import pandas as pd

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import display_tag, XYZ_to_display
from reflectance.io.cache import TRACES
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, savefig
from reflectance.optics.spectra import list_materials, load_material
from reflectance.io.tables import write_csv
from reflectance.papers.figures import ct82_fig7 as definition
from reflectance.render.composite import appearance, common_exposure, covered_rows, image_grid
from reflectance.render.pipeline import render_to_files
from reflectance.render.scene import scene_from_dict
from reflectance.scripting import params_dict

__all__ = ["run"]

GROUPS = {"metal": "six metals: Fig. 6b's s, d, D; F from measured n, k",
          "nonmetal": "six nonmetals: Table I's s, d, m", "extra": "variants, not in the paper's grid: Table I's s, d, m with other spectra"}
READINGS = {"intensity": "as printed, I_ia = {f} I_i",
            "irradiance": "{f} of the lights' irradiance, I_ia = {f} \u03a3 I_i d\u03c9_i / \u03c0"}


def label(material, sources, names):
    """The paper's name of the material and where its spectrum comes from (the n, k data set, or
    the Munsell notation it is derived from), each on a line of its own: the grid is print-wide."""
    name = material["name"]
    row = sources.loc[name]
    kind = (row.dataset.rsplit('/', 1)[-1] if row.kind == "measured"
            else f"Munsell {row.dataset.split(' ', 1)[-1]}")
    return f"{names.get(name, name)}\n{kind}"


def carbon_F0(snakemake, spectra_dir):
    """Carbon's F0 from its measured n, k over Table I's visible range
    (table1.average_F0_range_nm), for the caption."""
    lo, hi = snakemake.params.visible_nm
    grid = np.arange(lo, hi + 1, snakemake.params.wavelengths["step_nm"], dtype=float)
    return load_material("Carbon", grid, str(spectra_dir)).F0


def variant(snakemake, log, out, reference, published, items):
    """One variant of the figure (its vases' scenes ``items``): table and grid written to
    ``out``."""
    p = snakemake.params
    colour_cfg = p.colour
    spectra_dir = str(Path(snakemake.input.sources).parent)
    sources = list_materials(spectra_dir).set_index("material")
    rows, images, shown, groups, labels = [], [], [], [], []
    for item in items:
        k, vase, group, material = (item.tags[key] for key in ("index", "vase", "group",
                                                               "material"))
        scene = scene_from_dict(item.document, source=f"config.yaml {item.source} {vase}")
        result = render_to_files(scene, out["scenes"][k], out["exrs"][k],
                                 out["pngs"][k] if published else None, keep_trace=True)
        rgb, scale = result.display  # the vase alone, as its scene file shows it
        W = tristimulus_weights(scene.wavelengths, colour_cfg["illuminant"], scene.observer)
        F0 = load_material(material["name"], scene.wavelengths, spectra_dir).F0 @ W
        albedo = scene.objects[0].material.albedo @ W  # pi R_d (Cook & Torrance 1982: R_d = F0/pi)
        on = result.XYZ[..., 1] > 0
        mean = result.XYZ[on].mean(axis=0)
        rows.append({"vase": vase, "group": group, "material": material["name"],
                     "label": p.fig["labels"].get(material["name"], material["name"]),
                     "kind": sources.loc[material["name"], "kind"],
                     "model": scene.objects[0].material.model, "s": material["s"],
                     "d": material["d"], "m": material.get("m", np.nan),
                     "lobes": " ".join(f"{b['w']:g}x{b['m']:g}" for b in material.get("lobes", [])),
                     "ambient_reference": reference,
                     **{f"{name}_{c}": v for name, XYZ in (("F0", F0), ("albedo", albedo),
                                                           ("mean", mean))
                        for c, v in zip("XYZ", XYZ)},
                     "mean_x": mean[0] / mean.sum(), "mean_y": mean[1] / mean.sum(),
                     "Y_max": result.XYZ[..., 1].max(), "pixels": int(on.sum()),
                     "vase_exposure_scale": scale})
        images.append(result.XYZ), shown.append(rgb), groups.append(group)
        labels.append(label(material, sources, p.fig["labels"]))
        log.info("%s: %s; timings %s", vase, rows[-1], result.timings)

    display = dict(illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
                   wavelengths=scene.wavelengths)
    if published:  # one exposure per row, metered on a white card; the label: relative to metals
        scales = [row["vase_exposure_scale"] for row in rows]
        factors = [p.fig.get("vase_exposure", {}).get(row["vase"], 1.0) for row in rows]
        labels = [f"{text}\nexposure x{s / scales[0]:.3g}" + (f"\n({f:g}x its row)" if f != 1 else "")
                  for text, s, f in zip(labels, scales, factors)]
        metered = {g: (f"white card at {e['white']['luminance']:g}" if "white" in e
                       else f"median at {e['key']['luminance']:g}")
                   for g, e in p.fig["exposure"].items()}
        # each factor with its reason (config fig7.vase_exposure_reasons): a departure from one
        # exposure per row, said where the reader sees it
        reasons = p.fig.get("vase_exposure_reasons", {})
        departures = ", ".join(
            f"{p.fig['labels'].get(r['material'], r['material']).lower()} {f:g}x"
            + (f" ({reasons[r['vase']]})" if r["vase"] in reasons else "")
            for r, f in zip(rows, factors) if f != 1)
        title = ("Cook & Torrance 1982, Fig. 7 \u2014 one exposure per row:\nmetals "
                 f"{metered['metal']}, nonmetals {metered['nonmetal']}"
                 + (f";\nper vase: {departures}" if departures else ""))
    else:  # the grid is one scene: "all XYZ values in the scene are scaled equally"
        scale = common_exposure(images, colour_cfg["space"], **display)
        scales = [scale] * len(images)
        shown = [XYZ_to_display(XYZ * scale, colour_cfg["space"], colour_cfg["gamut_clip"],
                                expose=False, **display) for XYZ in images]
        reading = READINGS[reference].format(f=f"{p.fig6['ambient_fraction']:g}")
        title = (f"Cook & Torrance 1982, Fig. 7 \u2014 one exposure for all vases\n"
                 f"ambient {reading}")
    table = pd.DataFrame(rows).assign(exposure_scale=scales)
    for i, (rgb, XYZ) in enumerate(zip(shown, images)):
        for key, value in appearance(rgb, XYZ, colour_cfg["space"]).items():
            table.loc[i, key] = value
    table.pipe(write_csv, out["csv"], float_format="%.6g")

    # the paper's grid: metals in the first row, nonmetals in the second; the variants (not in the
    # paper): in the default figure, a file of their own (issue 28), each beside the paper's vase
    # of its Table I row; in a reading's grid (one scene), a row of their own below it
    vases = [row["vase"] for row in rows]
    n_cols = max(groups.count("metal"), groups.count("nonmetal"))
    # the grid drawn at the print width, the vases pixel for pixel, so its text prints at its size
    dpi = shown[0].shape[1] * n_cols * 1.04 / PRINT_WIDTH_IN
    crop = covered_rows(images)
    grid = [g for g in groups if g != "extra" or not published]
    draw(out["png"], title, [(group, rgb, text) for group, rgb, text in zip(groups, shown, labels)
                             if group in grid], n_cols, crop, dpi, published, colour_cfg)
    if published and "extra" in groups:  # (the rule's outputs have variants_png then)
        spectra = p.fig.get("table1_spectra", {})
        pairs = []
        for extra in p.fig["extras"]:
            paper = vases.index(spectra.get(extra["table1"], extra["table1"]))
            variant_k = vases.index(f"{extra['table1']}_{extra['material']}")
            pairs += [(f"row{len(pairs) // 2}", shown[k], text) for k, text in (
                (paper, f"{labels[paper]}\n(as in Fig. 7)"), (variant_k, labels[variant_k]))]
        draw(out["variants_png"], "Not in the paper:\nC&T 1982 Fig. 7, variants",
             pairs, 2, crop, dpi, published, colour_cfg,
             headings={g: "Table I's s, d, m" for g, _, _ in pairs})


def draw(path, title, vases, n_cols, crop, dpi, published, colour_cfg, headings=None):
    """A grid of ``vases`` (group, encoded RGB, label), a row per group in order of first
    appearance and at most ``n_cols`` a row, with each group's heading (``headings``, default
    :data:`GROUPS`) over its first vase, written to ``path`` at ``dpi``."""
    headings = headings or GROUPS
    order = list(dict.fromkeys(group for group, _, _ in vases))
    slots, cells, heads = dict.fromkeys(order, 0), [], []
    for group, rgb, text in vases:
        row, col = order.index(group), slots[group]
        if col == 0:
            heads.append((row, col, headings[group],
                          {"x": 0.01, **({"color": "#ffcc66"} if group == "extra" else {})}))
        slots[group] += 1
        cells.append((row, col, rgb, text))
    fig = image_grid(cells, len(order), n_cols, title, headings=heads, crop=crop,
                     foot=0.6 if published else 0.4, top=0.12 + 0.22 * (title.count("\n") + 1),
                     dpi=dpi, label_size=TEXT_SIZE["table"])
    savefig(fig, path, dpi=dpi, tag=display_tag(colour_cfg["space"]))


def run(snakemake: Any, log: logging.Logger) -> None:
    """Render every vase of every variant of the figure (the default figure, then each reading
    of the ambient term) from one trace, write each variant's table and grid, and the captions'
    values: ``snakemake`` is the rule's job (its params, input and output), ``log`` its log."""
    # the variants' vases share geometry, camera and lights: traced once (keep_trace)
    # the default figure (if params.published; unprefixed outputs), then each reading
    params = params_dict(snakemake.params)
    variants = definition.variants(params)
    scenes = definition.scenes(params, str(Path(snakemake.input.sources).parent))
    for prefix, reference, published in variants:
        log.info("variant %s (ambient reference %s)", prefix.rstrip("_") or "published", reference)
        out = {key: getattr(snakemake.output, prefix + key) for key in ("png", "csv", "exrs", "scenes")}
        if published:  # the default figure alone writes each vase's PNG and its variants'
            out["pngs"] = getattr(snakemake.output, "pngs")
            out["variants_png"] = getattr(snakemake.output, "variants_png", None)
        variant(snakemake, log, out, reference, published,
                [item for item in scenes if item.tags["prefix"] == prefix])
    log.info("%d distinct traces for %d variants", len(TRACES), len(variants))


    # the captions' numbers (workflow/report/ct82_fig7_*.rst): the Munsell notations of the
    # derived nonmetals (spectra/sources.csv) and how the default figure's vases read, from its
    # table as written
    munsell = list_materials(Path(snakemake.input.sources).parent).set_index("material").dataset
    munsell = munsell.str.removeprefix("Munsell ")
    values = {"RustMunsell_notation": munsell.RustMunsell, "OliveDrab_notation": munsell.OliveDrab,
              "Rubber_notation": munsell.Rubber, "LunarDust_notation": munsell.LunarDust,
              "Obsidian_notation": munsell.Obsidian}
    if any(published for _, _, published in variants):
        vases = pd.read_csv(snakemake.output.csv).set_index("vase")
        L, span = vases.L50, vases.L99 - vases.L10
        carbon = carbon_F0(snakemake, Path(snakemake.input.sources).parent)
        values.update({
            "Obsidian_F0": f"{vases.F0_Y.Obsidian:.2f}", "Ag_F0": f"{vases.F0_Y.Ag:.2f}",
            "Carbon_F0": f"{vases.F0_Y.Carbon:.2f}", "RustMunsell_L": f"{L.RustMunsell:.0f}",
            "OliveDrab_L": f"{L.OliveDrab:.0f}", "Rubber_L": f"{L.Rubber:.0f}",
            "LunarDust_L": f"{L.LunarDust:.0f}", "Obsidian_L": f"{L.Obsidian:.0f}",
            "Obsidian_visible": f"{100 * vases.visible.Obsidian:.0f}",
            "Obsidian_span": f"{span.Obsidian:.0f}", "LunarDust_span": f"{span.LunarDust:.1f}",
            "LunarDust_C": f"{vases.body_chroma.LunarDust:.0f}",
            # carbon (issue 28): its measured F0 over the visible, the lightness of its F0 (the
            # albedo of R_d = F0/pi, CIE 1976 L*) against the median L* the figure shows
            "Carbon_L": f"{L.Carbon:.0f}",
            "Carbon_F0_L": f"{lightness_CIE1976(100 * vases.F0_Y.Carbon):.0f}",
            "Carbon_F0_min": f"{carbon.min():.2f}", "Carbon_F0_max": f"{carbon.max():.2f}",
            "visible_lo": f"{snakemake.params.visible_nm[0]:g}",
            "visible_hi": f"{snakemake.params.visible_nm[1]:g}"})
    write_caption_values(snakemake.output.values, values)
