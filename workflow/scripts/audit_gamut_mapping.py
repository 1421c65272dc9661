"""Audit 3, gamut mapping: for every rendered figure (its EXRs), the fraction of object pixels
outside the display gamut, and what each gamut clip (constant dominant wavelength, per channel, CSS
Color 4 OKLCh) costs against the unclipped colour: CIEDE2000 and CAM16 hue shift; a chromaticity
diagram with the clipping paths."""

from pathlib import Path

import colour
import numpy as np
import pandas as pd

from reflectance.audit.gamut import (clip_differences, exr_colorimetry, exr_display_RGB,
                                     out_of_gamut)
from reflectance.audit.shortcuts import CAM16_VIEWING_CONDITIONS
from reflectance.colour.display import display_space
from reflectance.io.atomic import atomic_write
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.io.images import read_exr
from reflectance.io.tables import write_csv
from reflectance.scripting import script_log, write_audit_metadata

with script_log(snakemake) as log:
    cfg, figures = snakemake.params.audit, snakemake.params.figures
    methods, q = cfg["methods"], cfg["percentile"]
    image_rows, rows, paths, clouds, seen = [], [], [], [], []
    spaces, pooled = set(), {m: {"dE": [], "dh": []} for m in methods}
    for figure, exrs in figures.items():
        RGB_out, white = [], None
        for path in exrs:
            XYZ, header = read_exr(path)
            RGB, space, white, lit = exr_display_RGB(XYZ, header)
            spaces.add(space)
            seen.append(exr_colorimetry(header))
            outside = lit & out_of_gamut(RGB)
            image_rows.append({"figure": figure, "image": path, "space": space,
                               "object_pixels": int(lit.sum()), "out_of_gamut": int(outside.sum()),
                               "fraction": outside.sum() / max(lit.sum(), 1),
                               "fraction_negative": (outside & (RGB < 0).any(-1)).sum() / max(lit.sum(), 1),
                               "fraction_above_one": (outside & (RGB > 1).any(-1)).sum() / max(lit.sum(), 1)})
            RGB_out.append(RGB[outside])
        RGB_out = np.concatenate(RGB_out)
        lit_total = sum(r["object_pixels"] for r in image_rows if r["figure"] == figure)
        got = clip_differences(RGB_out, space, white, methods, CAM16_VIEWING_CONDITIONS)
        coloured = got["reference"]["C"] >= cfg["hue_min_chroma"]
        for method in methods:
            dE, dh = got[method]["dE2000"], np.abs(got[method]["dh_CAM16"][coloured])
            pooled[method]["dE"].append(dE), pooled[method]["dh"].append(dh)
            stat = lambda a, f: f(a) if a.size else np.nan  # noqa: E731
            rows.append({"figure": figure, "method": method, "object_pixels": lit_total,
                         "out_of_gamut": len(RGB_out), "fraction": len(RGB_out) / max(lit_total, 1),
                         "dE2000_mean": stat(dE, np.mean),
                         f"dE2000_p{q:g}": stat(dE, lambda a: np.percentile(a, q)),
                         "dE2000_max": stat(dE, np.max), "hue_pixels": int(coloured.sum()),
                         "dh_CAM16_abs_mean": stat(dh, np.nanmean),
                         f"dh_CAM16_abs_p{q:g}": stat(dh, lambda a: np.nanpercentile(a, q)),
                         "dh_CAM16_abs_max": stat(dh, np.nanmax)})
        # the diagram: every out-of-gamut colour, and the paths of a few at quantiles of xy
        # distance from the white
        if len(RGB_out):
            xy = colour.XYZ_to_xy(got["reference"]["XYZ"])
            clouds.append(xy)
            distance = np.linalg.norm(xy - colour.XYZ_to_xy(white), axis=-1)
            order = np.argsort(distance)
            for quantile in cfg["diagram_quantiles"]:
                i = order[int(round(quantile * (len(order) - 1)))]
                paths.append((figure, xy[i], {m: colour.XYZ_to_xy(got[m]["XYZ"][i]) for m in methods}))
        log.info("%s: %d of %d object pixels out of gamut", figure, len(RGB_out), lit_total)
    if len(spaces) != 1:
        raise ValueError(f"rendered figures use several display spaces {sorted(spaces)}: one "
                         "diagram cannot show them")
    table, images = pd.DataFrame(rows), pd.DataFrame(image_rows)
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    images.pipe(write_csv, snakemake.output.images, float_format="%.6g")
    # what the figures were rendered with, as their EXRs' headers say (one value where all agree)
    one = lambda key: (seen[0][key] if all(c[key] == seen[0][key] for c in seen)  # noqa: E731
                       else [c[key] for c in seen])
    write_audit_metadata(
        snakemake, "Audit 3, gamut mapping: the share of each rendered figure's object pixels "
        "outside the display gamut and what each gamut clip costs against the unclipped colour",
        illuminant=one("illuminant"), observer=one("observer"),
        wavelengths_nm=one("wavelengths"), space=space, methods=list(methods),
        units={"figure": "text", "image": "text", "space": "text", "method": "text",
               "object_pixels": "pixels", "out_of_gamut": "pixels", "hue_pixels": "pixels",
               "fraction*": "1 (share of object pixels)", "dE2000_*": "CIEDE2000",
               "dh_CAM16_*": "deg (CAM16 hue angle)"})

    # drawn at the print width, so its text prints at the figures' sizes
    fig = new_figure(PRINT_WIDTH_IN, 4.3)
    ax = fig.add_axes((0.08, 0.1, 0.42, 0.82))
    cmfs = colour.MSDS_CMFS[snakemake.params.observer]
    locus = colour.XYZ_to_xy(cmfs.values)
    ax.plot(*np.vstack([locus, locus[:1]]).T, color="0.3", linewidth=0.8)
    ds = display_space(space)
    primaries = colour.XYZ_to_xy(ds.matrix_RGB_to_XYZ.T)
    ax.plot(*np.vstack([primaries, primaries[:1]]).T, color="black", linewidth=1.0)
    ax.text(*primaries[1] + [-0.015, 0.0], f"{space} gamut", fontsize=TEXT_SIZE["annotation"],
            ha="right")  # inside the locus, clear of it
    cloud = np.concatenate(clouds)
    ax.scatter(*cloud[::max(1, len(cloud) // 4000)].T, s=4, color="0.6", lw=0,
               label="out-of-gamut pixels (unclipped)")
    white_xy = colour.XYZ_to_xy(white)
    ax.plot(*white_xy, marker="+", color="black", markersize=8)
    style = dict(zip(methods, OKABE_ITO[1:]))
    for figure, start, ends in paths:
        for method, end in ends.items():  # a line from the unclipped colour to the clipped one
            ax.plot(*np.stack([start, end]).T, color=style[method], lw=1.0)
            ax.plot(*end, "o", color=style[method], markersize=3)
        ax.plot(*start, "o", color="black", markersize=3)
    for method in methods:
        ax.plot([], [], color=style[method], label=f"clip: {method}")
    ax.set_xlim(0.0, 0.75), ax.set_ylim(0.0, 1.08)  # the legend above the locus
    ax.set_yticks(np.arange(0.0, 0.81, 0.2)), ax.set_xticks(np.arange(0.0, 0.71, 0.2))
    ax.set_aspect("equal")
    ax.set_xlabel("x"), ax.set_ylabel("y")
    ax.legend(fontsize=TEXT_SIZE["table"], loc="upper right", handlelength=1.2)
    ax.set_title("CIE 1931 xy: clipping paths\n(black dots: unclipped)", fontsize=TEXT_SIZE["symbol"])

    names = list(figures)
    bx = fig.add_axes((0.62, 0.64, 0.37, 0.28))
    fraction = table.drop_duplicates("figure").set_index("figure").loc[names, "fraction"]
    bx.bar(range(len(names)), 100 * fraction, color="0.5")
    for i, f in enumerate(fraction):
        text = f"{100 * f:.1f} %" if f == 0 or f >= 0.0005 else "< 0.1 %"
        bx.text(i, 100 * f, text, ha="center", va="bottom", fontsize=TEXT_SIZE["table"])
    bx.set_xticks(range(len(names)), [])
    bx.set_ylabel("object pixels\nout of gamut (%)", fontsize=TEXT_SIZE["annotation"])
    bx.set_ylim(0, max(5.0, 115 * fraction.max()))
    bx.spines[["top", "right"]].set_visible(False)
    cx = fig.add_axes((0.62, 0.2, 0.37, 0.4))
    width = 0.8 / len(methods)
    for j, method in enumerate(methods):
        part = table[table.method == method].set_index("figure").loc[names]
        x = np.arange(len(names)) + (j - (len(methods) - 1) / 2) * width
        cx.bar(x, part.dE2000_mean, width, color=style[method], label=f"{method} (mean)")
        cx.plot(x, part[f"dE2000_p{q:g}"], "_", color="black", markersize=6)
    cx.plot([], [], "_", color="black", label=f"{q:g}th percentile")
    short = [n.replace(" 1982", "").replace(" 1977", "") for n in names]  # the paper's year: caption
    cx.set_xticks(range(len(names)), [n.replace(" Fig.", "\nFig.") if " Fig." in n
                                      else n.replace(" ", "\n", 1) for n in short],
                  fontsize=TEXT_SIZE["table"])
    cx.set_ylabel("CIEDE2000 vs unclipped\n(out-of-gamut pixels)", fontsize=TEXT_SIZE["annotation"])
    top = np.nanmax(table[f"dE2000_p{q:g}"].to_numpy(float), initial=1.0)
    cx.set_ylim(0, 1.7 * top)  # head room for the legend above the bars
    cx.legend(fontsize=TEXT_SIZE["table"], frameon=False, handlelength=1.2, loc="upper right")
    cx.spines[["top", "right"]].set_visible(False)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    lit, out = images.object_pixels.sum(), images.out_of_gamut.sum()
    worst = fraction.idxmax()
    parts = []
    for method in methods:
        dE, dh = (np.concatenate(pooled[method][k]) for k in ("dE", "dh"))
        parts.append(f"{method} {dE.mean():.2f} (max {dE.max():.1f}; mean absolute CAM16 hue "
                     f"shift {np.nanmean(dh):.1f} degrees)")
    # where the methods disagree (elsewhere every method gives the same colour: too-bright greys)
    spread = table.groupby("figure").dE2000_mean.agg(lambda a: a.max() - a.min())
    differ = [f for f in names if spread.get(f, 0) > 0.01]
    detail = "; ".join(
        f"{f}: " + ", ".join(f"{r.method} {r.dE2000_mean:.1f} ({r.dh_CAM16_abs_mean:.1f} deg)"
                             for r in table[table.figure == f].itertuples(index=False))
        for f in differ)
    answer = (f"**Answer:** {100 * out / lit:.1f} % of the rendered figures' object pixels lie "
              f"outside {space} (most: {worst}, {100 * fraction[worst]:.1f} %); against the "
              f"unclipped colour, the mean CIEDE2000 of those pixels is " + "; ".join(parts)
              + ". The methods differ only in " + (detail or "no figure")
              + " (mean CIEDE2000, mean absolute CAM16 hue shift); elsewhere every method maps the "
              "out-of-gamut pixels to the same colour.\n")
    with atomic_write(snakemake.output.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
