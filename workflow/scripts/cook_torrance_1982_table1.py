"""Cook & Torrance 1982, Table I: the six nonmetals of Fig. 7 with s, d and m as printed, the source of
each spectrum, its F0 averaged over the visible, and the colour of R_d = F0/pi under the light."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.patches import Rectangle

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import display_tag, XYZ_to_display
from reflectance.io.figures import new_figure, paper_name, savefig
from reflectance.scripting import script_log
from reflectance.optics.spectra import list_materials, load_material, wavelength_grid
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    sources = list_materials(Path(snakemake.input.sources).parent).set_index("material")
    lo, hi = fig_cfg["average_F0_range_nm"]
    rows = []
    for entry in fig_cfg["rows"]:
        material = load_material(entry["material"], grid, Path(snakemake.input.sources).parent)
        F0_mean = material.mean_F0((lo, hi))
        XYZ = material.F0 @ W  # the colour of pi R_d = F0 (C&T 1982 Fig. 7: R_d = F0/pi)
        source = sources.loc[material.name]
        rows.append({
            "material": material.name, "name": paper_name(material.name), "s": entry["s"], "d": entry["d"], "m": entry["m"],
            "spectrum": "measured n, k" if material.kind == "measured" else "derived reflectance",
            "dataset": source["dataset"], "reference": source["reference"],
            f"F0_mean_{lo:g}_{hi:g}nm": F0_mean, "R_d_mean_per_sr": F0_mean / np.pi,
            "X": XYZ[0], "Y": XYZ[1], "Z": XYZ[2],
            "x": XYZ[0] / XYZ.sum(), "y": XYZ[1] / XYZ.sum()})
    table = pd.DataFrame(rows)
    RGB = XYZ_to_display(table[["X", "Y", "Z"]].to_numpy(), colour_cfg["space"],
                         colour_cfg["gamut_clip"], expose=False,
                         illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
                         wavelengths=grid)
    table["display_RGB"] = ["#" + "".join(f"{round(255 * v):02x}" for v in rgb) for rgb in RGB]
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    headers = ["Material", "s", "d", "m", "spectrum (source)", f"mean F0\n{lo:g}-{hi:g} nm",
               "x, y, Y", "R_d = F0/\u03c0\nunder " + colour_cfg["illuminant"]]
    xs = [0.01, 0.12, 0.17, 0.22, 0.28, 0.64, 0.72, 0.87]
    fig = new_figure(12.5, 1.3 + 0.55 * len(table))
    ax = fig.add_axes((0.01, 0.02, 0.98, 0.84))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(len(table) - 0.4, -1.2)
    for x, h in zip(xs, headers):
        ax.text(x, -0.7, h, fontsize=9.5, fontweight="bold", va="center")
    ax.axhline(-0.45, color="0.2", lw=0.8)
    for i, r in table.iterrows():
        m = "not used" if r.m is None or np.isnan(r.m) else f"{r.m:.2f}"
        cells = [r["name"], f"{r.s:.1f}", f"{r.d:.1f}", m, f"{r.spectrum}: {r.dataset}",
                 f"{r[f'F0_mean_{lo:g}_{hi:g}nm']:.4f}", f"{r.x:.4f}, {r.y:.4f}, {r.Y:.4f}"]
        for x, text in zip(xs, cells):
            ax.text(x, i, text, fontsize=9, va="center")
        ax.add_patch(Rectangle((xs[-1], i - 0.38), 0.1, 0.76, color=RGB[i], ec="0.5", lw=0.5))
    fig.suptitle(f"Cook & Torrance 1982, Table I \u2014 s, d, m of the nonmetals of Fig. 7, with "
                 f"their spectra ({colour_cfg['space']} swatch, not exposed: white = Y 1)",
                 fontsize=10.5, y=0.97)
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(colour_cfg["space"]))
    for r in table.itertuples():
        log.info("%s: mean F0 %.4f, Y %.4f, %s", r.material, r.R_d_mean_per_sr * np.pi, r.Y,
                 r.display_RGB)
