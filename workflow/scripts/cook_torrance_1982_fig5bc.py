"""Cook & Torrance 1982, Fig. 5b and 5c: the colour of copper vs incidence angle, (b) from the exact
spectral Fresnel equation and (c) from the paper's approximation, as swatches at the config's angles
and continuous strips (0-90 degrees, and finely from 80 degrees); under the strips, why (c) keeps
copper's colour until near grazing: the k = 0 Fresnel F of the fitted index dips below its F0, and
the approximation's max(0, F - F0) holds its weight at 0. The other Fresnel shortcuts (not in the
paper) go to a variant figure, fig5bc_variants.png."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.patches import Rectangle

from reflectance.audit.colour_shift import (COLOUR_METHODS, approximation_agreement,
                                            approximation_onset_CookTorrance1982, colour_table)
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import display_tag
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, paper_name, savefig
from reflectance.io.images import write_exr_XYZ
from reflectance.io.tables import write_csv
from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.scripting import script_log

LABELS = {"exact": "(b) exact n, k", "approximation": "(c) C&T approx.",
          "fitted": "k = 0 fit per \u03bb", "schlick": "Schlick 1994", "f82": "F82 tint"}
EDGE = dict(edgecolor="0.55", linewidth=0.4)  # outlines the white swatches on the white page


def _bare(ax, keep=("bottom",)):
    for side, spine in ax.spines.items():
        spine.set_visible(side in keep)
    ax.tick_params(axis="y", length=0)


def angle_ticks(lo):
    """Ticks of an angle axis from ``lo`` to 90 degrees: every 30 from 0, else every 5 (the fine
    strip's and its F panel's)."""
    return np.arange(lo, 90.1, 30 if lo == 0 else 5)


def draw_rows(fig, cells, table, strip, rows, angles, fine_from, fine_step):
    """Swatches at ``angles`` and two strips, one line per row; under every row but (b), its
    CIEDE2000 from (b). Returns the two strip axes."""
    ax = fig.add_subplot(cells[0])
    for i, method in enumerate(rows):
        y = len(rows) - 1 - i
        for j, r in enumerate(table[table.method == method].itertuples()):
            ax.add_patch(Rectangle((j + 0.06, y + 0.3), 0.88, 0.65, facecolor=(r.R, r.G, r.B), **EDGE))
            if method != "exact":
                ax.text(j + 0.5, y + 0.13, f"{r.dE2000_vs_exact:.1f}", ha="center", va="center",
                        fontsize=TEXT_SIZE["table"] - 1, color="0.25")
    ax.set(xlim=(0, len(angles)), ylim=(0, len(rows)))
    ax.set_xticks(np.arange(len(angles)) + 0.5, [f"{a:g}" for a in angles], fontsize=TEXT_SIZE["table"])
    ax.set_yticks(np.arange(len(rows)) + 0.62, [LABELS.get(m, m) for m in reversed(rows)])
    _bare(ax, keep=())
    ax.tick_params(axis="x", length=0)
    ax.set_xlabel("\u03b8 (\u00b0); grey: \u0394E$_{00}$ from (b)")
    ax.set_title("the paper's angles", fontsize=TEXT_SIZE["annotation"], pad=3)
    strips = []
    for cell, lo in ((cells[1], 0.0), (cells[2], fine_from)):
        sax = fig.add_subplot(cell)
        for i, method in enumerate(rows):
            part = strip[(strip.method == method) & (strip.angle_deg >= lo)]
            a = part.angle_deg.to_numpy()
            edges = np.concatenate([[lo], (a[1:] + a[:-1]) / 2, [90.0]])
            y = len(rows) - 1 - i
            sax.pcolormesh(edges, [y + 0.3, y + 0.95], part[["R", "G", "B"]].to_numpy()[None],
                           shading="flat", rasterized=True)
            sax.add_patch(Rectangle((lo, y + 0.3), 90 - lo, 0.65, fill=False, **EDGE))
        sax.set(xlim=(lo, 90), ylim=(0, len(rows)), yticks=[])
        sax.set_xticks(angle_ticks(lo))
        _bare(sax)
        sax.set_title(f"{lo:g}\u201390\u00b0" + (f", step {fine_step:g}\u00b0" if lo > 0 else ""),
                      fontsize=TEXT_SIZE["annotation"], pad=3)
        strips.append(sax)
    return strips


with script_log(snakemake) as log:
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    material = load_material(fig_cfg["material"], grid,
                             spectra_dir=Path(snakemake.input.spectrum).parent)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    rows, variants = fig_cfg["rows"], fig_cfg["variant_rows"]
    every = list(dict.fromkeys(rows + variants))
    angles = np.asarray(fig_cfg["angles_deg"], dtype=float)
    options = dict(methods=every, space=colour_cfg["space"], clip=colour_cfg["gamut_clip"],
                   illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
                   average_range_nm=fig_cfg["average_F0_range_nm"])
    table = colour_table(material, angles, W, **options)
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    # The strips: with 90 degrees among the angles the light's white sets the exposure, as above.
    st = fig_cfg["strip"]
    fine = np.arange(st["fine_from_deg"], 90.0 + st["fine_step_deg"] / 2, st["fine_step_deg"])
    strip_angles = np.unique(np.round(np.concatenate(
        [np.arange(0.0, st["fine_from_deg"], st["step_deg"]), fine, [90.0]]), 9))
    strip = colour_table(material, strip_angles, W, **options)
    strip.pipe(write_csv, snakemake.output.strip, float_format="%.6g")
    onset = approximation_onset_CookTorrance1982(material, fig_cfg["average_F0_range_nm"],
                                                 fractions=(0.1, 0.5))
    agree = approximation_agreement(strip, fig_cfg["agreement_dE00"])
    pd.DataFrame([{"material": material.name, "average_F0_range_nm":
                   "-".join(f"{x:g}" for x in fig_cfg["average_F0_range_nm"]), **onset,
                   "agreement_dE00": fig_cfg["agreement_dE00"], **agree}]).pipe(
        write_csv, snakemake.output.approximation, float_format="%.8g")
    written = pd.read_csv(snakemake.output.approximation).iloc[0]  # figure and caption: as written
    log.info("approximation: %s", written.to_dict())

    # Linear XYZ of the default figure's swatch grid (one 16 x 16 block per swatch), for the archive.
    paper = table[table.method.isin(rows)]
    XYZ = np.stack([paper[paper.method == m][["X", "Y", "Z"]].to_numpy() for m in rows])
    write_exr_XYZ(snakemake.output.exr, np.kron(XYZ, np.ones((16, 16, 1))), attributes={
        "figure": "Cook & Torrance 1982 Fig. 5b/5c", "material": material.name,
        "rows": ",".join(rows), "angles_deg": ",".join(f"{a:g}" for a in angles),
        "illuminant": colour_cfg["illuminant"], "observer": colour_cfg["observer"]})

    name, tag = paper_name(material.name), display_tag(colour_cfg["space"])
    fine_from, fine_step = st["fine_from_deg"], st["fine_step_deg"]
    ratios = [len(angles) * 0.5, 2.2, 2.2]
    # --- the default figure: the paper's two rows, (b) and (c), and in the title what they show ---
    title = (f"Cook & Torrance 1982, Fig. 5b/5c \u2014 the colour of {name} against the incidence "
             f"angle ({colour_cfg['illuminant']}, {colour_cfg['space']})\n(c) is within \u0394E$_{{00}}$ "
             f"{written.agreement_dE00:g} of (b) up to {written.agree_deg:g}\u00b0; above, (c) keeps its "
             f"0\u00b0 colour while (b) whitens (\u0394E$_{{00}}$ up to {written.worst_dE00:.1f}, "
             f"at {written.worst_deg:.1f}\u00b0),\nbecause F of the k = 0 index fitted to F$_0$ stays "
             f"below F$_0$ until {written.onset_deg:.2f}\u00b0 (why: "
             f"{Path(snakemake.output.why_png).name})")
    fig = new_figure(PRINT_WIDTH_IN, 1.35 + 0.42 * len(rows))
    cells = fig.add_gridspec(1, 3, width_ratios=ratios, wspace=0.14, left=0.14, right=0.995,
                             top=1 - 0.82 / fig.get_figheight(), bottom=0.45 / fig.get_figheight())
    strips = draw_rows(fig, list(cells), table, strip, rows, angles, fine_from, fine_step)
    for sax in strips:
        sax.set_xlabel("\u03b8 (\u00b0)")
    fig.suptitle(title, y=0.995, va="top", fontsize=TEXT_SIZE["annotation"] + 1)
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=tag)

    # --- why (c) stays copper: F of the k = 0 fit against F0, on the strips' two angle axes ---
    n, F0 = written.n_average, written.F0_average
    lo, hi = fig_cfg["average_F0_range_nm"]
    exact, ax = strip[strip.method == "exact"], None
    fig = new_figure(PRINT_WIDTH_IN, 2.9)  # the legend in a narrower first column
    cells = fig.add_gridspec(1, 3, width_ratios=[3.6, 2.2, 2.2], wspace=0.22, left=0.02, right=0.995,
                             top=1 - 0.62 / fig.get_figheight(), bottom=0.5 / fig.get_figheight())
    for k, left in enumerate((0.0, fine_from)):  # the strips' two angle axes
        ax = fig.add_subplot(cells[k + 1], sharey=ax)
        theta = np.linspace(left, 90.0, 4001)
        F = fresnel_dielectric_CookTorrance1982(np.cos(np.radians(theta)), n)  # C&T 1982 eq. (Fresnel), k = 0
        ax.axvspan(left, written.onset_deg, color="0.92", lw=0,
                   label=f"max(0, F \u2212 F$_0$) = 0: (c) keeps the 0\u00b0 colour")
        ax.fill_between(theta, F, F0, where=F < F0, color=OKABE_ITO[5], alpha=0.35, lw=0,
                        label="F below F$_0$ (the dip towards Brewster's angle)")
        ax.axhline(F0, color="0.3", lw=0.8, ls=(0, (4, 2)),
                   label=f"F$_0$ = {F0:.2f}, {name}'s mean over {lo:g}\u2013{hi:g} nm")
        ax.plot(theta, F, color=OKABE_ITO[0], lw=1.2, label=f"F, k = 0 and n = {n:.1f} (C&T's fit to F$_0$)")
        part = exact[exact.angle_deg >= left]
        ax.plot(part.angle_deg, part.Y, color=OKABE_ITO[1], lw=1.2,
                label=f"{name}, exact n, k: F weighted by luminance (Y)")
        ax.set(xlim=(left, 90), ylim=(0.4, 1.02), xlabel="\u03b8 (\u00b0)", xticks=angle_ticks(left))
        ax.set_ylabel("F" if k == 0 else None)
        ax.tick_params(axis="y", labelleft=k == 0)
        ax.set_title(f"{left:g}\u201390\u00b0", fontsize=TEXT_SIZE["annotation"], pad=3)
        if k == 1:
            ax.axvline(written.onset_deg, color="0.3", lw=0.6)
            ax.annotate(f"F = F$_0$ at {written.onset_deg:.2f}\u00b0", (written.onset_deg, F0),
                        xytext=(-6, 18), textcoords="offset points", ha="right",
                        fontsize=TEXT_SIZE["annotation"], arrowprops=dict(arrowstyle="-", lw=0.5))
    handles, labels = ax.get_legend_handles_labels()
    key = fig.add_subplot(cells[0])
    key.axis("off")
    key.legend(handles, labels, loc="center left", frameon=False, fontsize=TEXT_SIZE["table"],
               borderaxespad=0, handlelength=1.6)
    fig.suptitle(f"Cook & Torrance 1982, Fig. 5c: why the approximation keeps {name}'s 0\u00b0 colour "
                 f"up to {written.onset_deg:.2f}\u00b0", y=0.995, va="top",
                 fontsize=TEXT_SIZE["annotation"] + 1)
    savefig(fig, snakemake.output.why_png, tag=tag)

    # --- the variant figure: every row, the paper's and the later shortcuts ---
    fig = new_figure(PRINT_WIDTH_IN, 0.9 + 0.42 * len(every))
    cells = fig.add_gridspec(1, 3, width_ratios=ratios, wspace=0.14, left=0.15, right=0.995,
                             top=1 - 0.5 / fig.get_figheight(), bottom=0.45 / fig.get_figheight())
    for sax in draw_rows(fig, list(cells), table, strip, every, angles, fine_from, fine_step):
        sax.set_xlabel("\u03b8 (\u00b0)")
    fig.suptitle(f"Cook & Torrance 1982, Fig. 5b/5c and, NOT IN THE PAPER, later Fresnel shortcuts "
                 f"({', '.join(LABELS.get(m, m) for m in every if m not in rows)})",
                 y=0.995, va="top", fontsize=TEXT_SIZE["annotation"] + 1)
    savefig(fig, snakemake.output.variants_png, tag=tag)
    for method in every:
        log.info("%s: max dE2000 vs exact %.3f (%s)", method,
                 table[table.method == method].dE2000_vs_exact.max(), COLOUR_METHODS[method])

    # the caption's numbers (workflow/report/ct82_fig5bc.rst), from the table as written
    write_caption_values(snakemake.output.values, {
        "F0_average": f"{written.F0_average:.2f}", "n_average": f"{written.n_average:.1f}",
        "dip": f"{-written.dip:.2f}", "dip_deg": f"{written.dip_deg:.1f}",
        "onset_deg": f"{written.onset_deg:.2f}", "last_deg": f"{90 - written.onset_deg:.2f}",
        "half_deg": f"{written['t_0.5_deg']:.2f}", "agreement_dE00": f"{written.agreement_dE00:g}",
        "agree_deg": f"{written.agree_deg:g}", "worst_dE00": f"{written.worst_dE00:.1f}",
        "worst_deg": f"{written.worst_deg:.1f}",
        "fractions": " and ".join(c[2:-4] for c in written.index if c.startswith("t_"))})
