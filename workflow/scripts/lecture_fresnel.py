"""Lecture (Russin, Module 3B), "Fresnel reflectance" slide: F against incidence angle for dielectrics
(exact equation with a real index) and metals (exact complex-index equation from measured n, k,
plotted as the reflectance of the illuminant's luminance Y), with Schlick's approximation dashed."""

from pathlib import Path

import numpy as np
import pandas as pd

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.optics.fresnel import fresnel
from reflectance.io.figures import PRINT_WIDTH_IN, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    # Y weights: Y = F @ W_Y is the luminance reflected, relative to the illuminant's (Y_white = 1)
    W_Y = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])[:, 1]
    angles = np.arange(0.0, 90.0 + 1e-9, cfg["angle_step_deg"])
    c = np.clip(np.cos(np.radians(angles)), 0.0, 1.0)
    spectra_dir = Path(snakemake.input.spectra[0]).parent

    curves = {}  # (group, name, label) -> {method: F(angle)}
    for name, d in cfg["dielectrics"].items():
        curves[("dielectric", name, f"{name} (n = {d['n']:g})")] = {
            method: fresnel(c, d["n"], 0.0, method=method) for method in ("exact", "schlick")}
    for name in cfg["materials"]:
        material = load_material(name, grid, spectra_dir=spectra_dir)
        curves[("metal", name, name)] = {
            method: fresnel(c[:, None], material.n, material.k, method=method) @ W_Y
            for method in ("exact", "schlick")}

    table = {"angle_deg": angles}
    for (_, name, _), F in curves.items():
        table[f"{name}_exact"], table[f"{name}_schlick"] = F["exact"], F["schlick"]
    pd.DataFrame(table).pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    fig = new_figure(PRINT_WIDTH_IN, 0.5 * PRINT_WIDTH_IN)
    axes = dict(zip(("dielectric", "metal"), fig.subplots(1, 2)))
    for (group, name, label), F in curves.items():
        error = np.max(np.abs(F["schlick"] - F["exact"]))
        (line,) = axes[group].plot(angles, F["exact"], label=f"{label}: {error:.3f}")
        axes[group].plot(angles, F["schlick"], color=line.get_color(), lw=1.0, ls="--")
        log.info("%s: F(0) = %.5f, max |Schlick - exact| = %.5f at %.2f deg", name, F["exact"][0],
                 error, angles[np.argmax(np.abs(F["schlick"] - F["exact"]))])
    axes["dielectric"].set_title("(a) dielectrics (real index, k = 0)")
    axes["metal"].set_title(f"(b) metals (measured n, k; Y under {colour_cfg['illuminant']})")
    for ax in axes.values():
        ax.set(xlabel="incidence angle \u03b8 (degrees)", ylabel="reflectance F", xlim=(0, 90),
               ylim=(0, 1.01), xticks=np.arange(0, 91, 15))
        ax.grid(True)
    for group, where in (("dielectric", "upper left"), ("metal", "lower left")):
        axes[group].legend(loc=where, handlelength=1.4, labelspacing=0.3)
    fig.suptitle("Lecture (Russin, Module 3B), \u201cFresnel reflectance\u201d: unpolarised F against the "
                 "incidence angle\nsolid: exact Fresnel; dashed: Schlick 1994; in the legends: max |Schlick \u2212 exact|")
    fig.tight_layout(w_pad=1.5)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
