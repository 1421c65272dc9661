"""Cook & Torrance 1982, Fig. 5b and 5c: the colour of copper vs incidence angle, (b) from the exact
spectral Fresnel equation and (c) from the paper's approximation; further rows from other Fresnel
shortcuts, each with its CIEDE2000 difference from (b). Beside the swatches, continuous strips on a
proportional angle axis (0-90 degrees, and 80-90 degrees finely sampled), and the numbers of why the
approximation keeps copper's colour until near grazing."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.patches import Rectangle

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.audit.colour_shift import (COLOUR_METHODS, approximation_onset_CookTorrance1982,
                                            colour_table)
from reflectance.colour.display import display_tag
from reflectance.io.captions import write_caption_values
from reflectance.io.images import write_exr_XYZ
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, paper_name, savefig
from reflectance.scripting import script_log
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.io.tables import write_csv

LABELS = {"exact": "(b) exact n, k", "approximation": "(c) C&T approx.",
          "fitted": "k = 0 fit per \u03bb", "schlick": "Schlick 1994", "f82": "F82 tint"}

with script_log(snakemake) as log:
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    material = load_material(fig_cfg["material"], grid,
                             spectra_dir=Path(snakemake.input.spectrum).parent)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    rows, angles = fig_cfg["rows"], np.asarray(fig_cfg["angles_deg"], dtype=float)
    options = dict(methods=rows, space=colour_cfg["space"], clip=colour_cfg["gamut_clip"],
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
    pd.DataFrame([{"material": material.name, "average_F0_range_nm":
                   "-".join(f"{x:g}" for x in fig_cfg["average_F0_range_nm"]), **onset}]).pipe(
        write_csv, snakemake.output.approximation, float_format="%.8g")
    log.info("approximation: %s", onset)

    # Linear XYZ of the swatch grid (one 16 x 16 block per swatch) for the archive.
    XYZ = table[["X", "Y", "Z"]].to_numpy().reshape(len(rows), len(angles), 3)
    block = np.kron(XYZ, np.ones((16, 16, 1)))
    write_exr_XYZ(snakemake.output.exr, block, attributes={
        "figure": "Cook & Torrance 1982 Fig. 5b/5c", "material": material.name,
        "rows": ",".join(rows), "angles_deg": ",".join(f"{a:g}" for a in angles),
        "illuminant": colour_cfg["illuminant"], "observer": colour_cfg["observer"]})

    name = paper_name(material.name)
    fig = new_figure(PRINT_WIDTH_IN, 0.9 + 0.3 * len(rows))
    grid_spec = fig.add_gridspec(1, 3, width_ratios=[len(angles) * 0.5, 2.2, 2.2], wspace=0.12,
                                 top=1 - 0.75 / fig.get_figheight(), bottom=0.38 / fig.get_figheight(),
                                 left=0.15, right=0.995)
    ax = fig.add_subplot(grid_spec[0], facecolor="black")  # white swatches stay visible
    for i, method in enumerate(rows):
        part = table[table.method == method]
        for j, (_, r) in enumerate(part.iterrows()):
            y = len(rows) - 1 - i
            ax.add_patch(Rectangle((j + 0.05, y + 0.36), 0.9, 0.6, color=(r.R, r.G, r.B)))
            if method != "exact":
                ax.text(j + 0.5, y + 0.18, f"{r.dE2000_vs_exact:.1f}", ha="center",
                        va="center", fontsize=TEXT_SIZE["table"] - 1, color="white")
    ax.set(xlim=(0, len(angles)), ylim=(0, len(rows)))
    ax.set_xticks(np.arange(len(angles)) + 0.5, [f"{a:g}" for a in angles], fontsize=TEXT_SIZE["table"])
    ax.set_yticks(np.arange(len(rows)) + 0.66, [LABELS.get(m, m) for m in reversed(rows)])
    ax.tick_params(length=0)
    for side in ax.spines.values():
        side.set_visible(False)
    ax.set_xlabel("\u03b8 (\u00b0); white: \u0394E$_{00}$ from (b)")
    ax.set_title("the paper's angles", fontsize=TEXT_SIZE["annotation"], pad=3)
    for k, (lo, ticks) in enumerate(((0.0, np.arange(0, 91, 30)), (st["fine_from_deg"], None))):
        sax = fig.add_subplot(grid_spec[k + 1], facecolor="black")
        for i, method in enumerate(rows):
            part = strip[(strip.method == method) & (strip.angle_deg >= lo)]
            rgb = part[["R", "G", "B"]].to_numpy()[None]
            edges = np.concatenate([[lo], (part.angle_deg.to_numpy()[1:]
                                           + part.angle_deg.to_numpy()[:-1]) / 2, [90.0]])
            y = len(rows) - 1 - i
            sax.pcolormesh(edges, [y + 0.36, y + 0.96], rgb, shading="flat", rasterized=True)
        if lo > 0:
            sax.axvline(onset["onset_deg"], color="white", lw=0.8, ls=(0, (2, 2)))
        sax.set(xlim=(lo, 90), ylim=(0, len(rows)), yticks=[])
        sax.set_xticks(ticks if ticks is not None else np.arange(lo, 90.1, 5))
        sax.tick_params(axis="y", length=0)
        for side in ("left", "right", "top"):
            sax.spines[side].set_visible(False)
        sax.set_xlabel("\u03b8 (\u00b0)")
        sax.set_title(f"{lo:g}\u201390\u00b0" + (f", step {st['fine_step_deg']:g}\u00b0" if lo > 0 else ""),
                      fontsize=TEXT_SIZE["annotation"], pad=3)
    fig.suptitle(f"Cook & Torrance 1982, Fig. 5b/5c \u2014 the colour of {name} against the incidence angle "
                 f"({colour_cfg['illuminant']}, {colour_cfg['space']})\n"
                 f"swatches, then continuous strips on a proportional angle axis; dashed: (c) leaves copper "
                 f"at {onset['onset_deg']:.2f}\u00b0", y=0.995, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(colour_cfg["space"]))
    for method in rows:
        log.info("%s: max dE2000 vs exact %.3f (%s)", method,
                 table[table.method == method].dE2000_vs_exact.max(), COLOUR_METHODS[method])

    # the caption's numbers (workflow/report/ct82_fig5bc.rst), from the table as written
    written = pd.read_csv(snakemake.output.approximation).iloc[0]
    write_caption_values(snakemake.output.values, {
        "F0_average": f"{written.F0_average:.2f}", "n_average": f"{written.n_average:.1f}",
        "dip": f"{-written.dip:.2f}", "dip_deg": f"{written.dip_deg:.1f}",
        "onset_deg": f"{written.onset_deg:.2f}", "last_deg": f"{90 - written.onset_deg:.2f}",
        "half_deg": f"{written['t_0.5_deg']:.2f}",
        "fractions": " and ".join(c[2:-4] for c in written.index if c.startswith("t_"))})
