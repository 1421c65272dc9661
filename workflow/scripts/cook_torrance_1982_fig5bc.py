"""Cook & Torrance 1982, Fig. 5b and 5c: the colour of copper vs incidence angle, (b) from the exact
spectral Fresnel equation and (c) from the paper's approximation; further rows from other Fresnel
shortcuts, each with its CIEDE2000 difference from (b)."""

from pathlib import Path

import numpy as np
from matplotlib.patches import Rectangle

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.audit.colour_shift import COLOUR_METHODS, colour_table
from reflectance.io.images import write_exr_XYZ
from reflectance.io.figures import new_figure, savefig
from reflectance.scripting import script_log
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.io.tables import write_csv

LABELS = {"exact": "(b) exact n, k", "approximation": "(c) C&T approximation",
          "fitted": "k = 0 fit per wavelength", "schlick": "Schlick 1994", "f82": "F82 tint"}

with script_log(snakemake) as log:
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    material = load_material(fig_cfg["material"], grid,
                             spectra_dir=Path(snakemake.input.spectrum).parent)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    rows, angles = fig_cfg["rows"], np.asarray(fig_cfg["angles_deg"], dtype=float)
    table = colour_table(material, angles, W, methods=rows, space=colour_cfg["space"],
                         clip=colour_cfg["gamut_clip"], illuminant=colour_cfg["illuminant"],
                         average_range_nm=fig_cfg["average_F0_range_nm"],
                         observer=colour_cfg["observer"])
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    # Linear XYZ of the swatch grid (one 16 x 16 block per swatch) for the archive.
    XYZ = table[["X", "Y", "Z"]].to_numpy().reshape(len(rows), len(angles), 3)
    block = np.kron(XYZ, np.ones((16, 16, 1)))
    write_exr_XYZ(snakemake.output.exr, block, attributes={
        "figure": "Cook & Torrance 1982 Fig. 5b/5c", "material": material.name,
        "rows": ",".join(rows), "angles_deg": ",".join(f"{a:g}" for a in angles),
        "illuminant": colour_cfg["illuminant"], "observer": colour_cfg["observer"]})

    fig = new_figure(1.0 + 0.75 * len(angles), 0.9 + 0.95 * len(rows))
    ax = fig.add_axes((0.2, 0.12, 0.78, 0.72), facecolor="black")  # white swatches stay visible
    for i, method in enumerate(rows):
        part = table[table.method == method]
        for j, (_, r) in enumerate(part.iterrows()):
            y = len(rows) - 1 - i
            ax.add_patch(Rectangle(
                (j + 0.05, y + 0.28), 0.9, 0.68, color=(r.R, r.G, r.B)))
            if method != "exact":
                ax.text(j + 0.5, y + 0.12, f"{r.dE2000_vs_exact:.2f}", ha="center",
                        va="center", fontsize=7, color="white")
    ax.set_xlim(0, len(angles))
    ax.set_ylim(0, len(rows))
    ax.set_xticks(np.arange(len(angles)) + 0.5, [f"{a:g}\u00b0" for a in angles])
    ax.set_yticks(np.arange(len(rows)) + 0.6, [LABELS.get(m, m) for m in reversed(rows)])
    ax.tick_params(length=0)
    for side in ax.spines.values():
        side.set_visible(False)
    ax.set_xlabel("incidence angle \u03b8 (numbers: CIEDE2000 vs exact)")
    fig.suptitle(f"Cook & Torrance 1982, Fig. 5b/5c \u2014 colour of {material.name} under "
                 f"{colour_cfg['illuminant']} vs incidence angle ({colour_cfg['space']}, "
                 f"gamut clip: {colour_cfg['gamut_clip']})", fontsize=10)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    for method in rows:
        log.info("%s: max dE2000 vs exact %.3f (%s)", method,
                 table[table.method == method].dE2000_vs_exact.max(), COLOUR_METHODS[method])
