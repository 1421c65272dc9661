"""Cook & Torrance 1982, Table I: the six nonmetals of Fig. 7 with s, d and m as printed, the source of
each spectrum, its F0 averaged over the visible, and the colour of F0 = pi R_d under the light (the swatch: Y = F0)."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.patches import Rectangle

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import display_tag, XYZ_to_display
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, paper_name, savefig
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
        # the spectrum Fig. 7 gives this row (fig7.table1_spectra: rust's Munsell-derived
        # reflectance, not hematite's n, k), so that the table shows the vases' colours
        spectrum = snakemake.params.spectra.get(entry["material"], entry["material"])
        material = load_material(spectrum, grid, Path(snakemake.input.sources).parent)
        F0_mean = material.mean_F0((lo, hi))
        XYZ = material.F0 @ W  # the colour of pi R_d = F0 (C&T 1982 Fig. 7: R_d = F0/pi)
        source = sources.loc[material.name]
        rows.append({
            "material": entry["material"], "spectrum_material": material.name,
            "name": paper_name(entry["material"]), "s": entry["s"], "d": entry["d"], "m": entry["m"],
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

    # Drawn at the print width, so its text prints at the table size of the figures (TEXT_SIZE)
    T = TEXT_SIZE
    headers = ["Material", "s", "d", "m", "spectrum (source)", f"mean F0\n{lo:g}-{hi:g} nm",
               "x, y, Y", "F0 = \u03c0$R_d$\nunder " + colour_cfg["illuminant"]]  # the swatch is F0's colour (Y = F0)
    widths = [0.85, 0.35, 0.35, 0.6, 1.7, 0.85, 1.35, 0.75]  # inches
    xs = np.concatenate([[0.05], 0.05 + np.cumsum(widths)[:-1]])
    row_in, head_in, title_in = 0.36, 0.42, 0.5
    W, H = PRINT_WIDTH_IN, title_in + head_in + row_in * len(table) + 0.05
    fig = new_figure(W, H)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_axis_off()
    ax.set(xlim=(0, W), ylim=(H, 0))  # inches from the top left
    y0 = title_in + head_in
    for x, h in zip(xs, headers):
        ax.text(x, y0 - 0.06, h, fontsize=T["annotation"], fontweight="bold", va="bottom",
                linespacing=1.15)
    ax.axhline(y0 - 0.03, color="0.2", lw=0.8)
    for i, r in table.iterrows():
        m = "not used" if r.m is None or np.isnan(r.m) else f"{r.m:.2f}"
        y = y0 + (i + 0.5) * row_in
        cells = [r["name"], f"{r.s:.1f}", f"{r.d:.1f}", m, f"{r.spectrum}:\n{r.dataset}",
                 f"{r[f'F0_mean_{lo:g}_{hi:g}nm']:.4f}", f"{r.x:.4f}, {r.y:.4f}, {r.Y:.4f}"]
        for x, text in zip(xs, cells):
            ax.text(x, y, text, fontsize=T["table"], va="center", linespacing=1.15)
        ax.add_patch(Rectangle((xs[-1], y - 0.4 * row_in), widths[-1] - 0.05, 0.8 * row_in,
                               color=RGB[i], ec="0.5", lw=0.5))
    fig.suptitle(f"Cook & Torrance 1982, Table I \u2014 s, d, m of the nonmetals of Fig. 7,\nwith "
                 f"their spectra ({colour_cfg['space']} swatch, not exposed: white = Y 1)",
                 y=1 - 0.04 / H, va="top", linespacing=1.3)
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(colour_cfg["space"]))
    for r in table.itertuples():
        log.info("%s: mean F0 %.4f, Y %.4f, %s", r.material, r.R_d_mean_per_sr * np.pi, r.Y,
                 r.display_RGB)
