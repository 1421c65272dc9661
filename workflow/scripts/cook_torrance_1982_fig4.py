"""Cook & Torrance 1982, Fig. 4: (a) a copper mirror's normal reflectance vs wavelength (um);
(b) D65's spectral energy distribution and that reflected by the copper mirror at normal incidence."""

from pathlib import Path

import colour

import pandas as pd

from reflectance.colour.colorimetry import illuminant_sd
from reflectance.io.figures import new_figure, savefig
from reflectance.scripting import script_log
from reflectance.optics.fresnel import F0_from_nk
from reflectance.optics.spectra import load_material, read_spectrum_csv, wavelength_grid
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    fig_cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    spectra_dir = Path(snakemake.input.spectrum).parent
    material = load_material(fig_cfg["material"], grid, spectra_dir=spectra_dir)
    light = illuminant_sd(colour_cfg["illuminant"], grid)
    reflected = light * material.F0  # C&T 1982 Fig. 4b: SPD of the light times the reflectance
    scale = 1e-3 if fig_cfg["wavelength_unit"] == "um" else 1.0
    unit = "\u03bcm" if fig_cfg["wavelength_unit"] == "um" else "nm"

    table = pd.DataFrame({"wavelength_nm": grid, "F0": material.F0,
                          f"{colour_cfg['illuminant']}": light, "reflected": reflected})
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    fig = new_figure(10, 4.2)
    ax_a, ax_b = fig.subplots(1, 2)
    ax_a.plot(grid * scale, material.F0, color="#b3672b", label="from n, k interpolated linearly")
    raw = read_spectrum_csv(snakemake.input.spectrum)
    raw = raw[(raw.wavelength_nm >= grid[0]) & (raw.wavelength_nm <= grid[-1])]
    if "n" in raw:
        ax_a.plot(raw.wavelength_nm * scale, F0_from_nk(raw.n, raw.k), "o", ms=4,
                  color="#5a3315", label="measured points")
    ax_a.legend(frameon=False, loc="lower right")
    ax_a.set(xlabel=f"wavelength ({unit})", ylabel="normal reflectance F0", ylim=(0, 1),
             title=f"(a) {material.name} mirror, normal incidence")
    ax_b.plot(grid * scale, light, color="0.3", label=f"CIE {colour_cfg['illuminant']}")
    tabulated_end = colour.SDS_ILLUMINANTS[colour_cfg["illuminant"]].shape.end
    if grid[-1] > tabulated_end:  # colour-science's table stops here; beyond it, held constant
        ax_b.axvspan(tabulated_end * scale, grid[-1] * scale, color="0.92", zorder=0,
                     label="beyond the tabulated SPD (held constant)")
    ax_b.plot(grid * scale, reflected, color="#b3672b", label=f"reflected by {material.name}")
    ax_b.set(xlabel=f"wavelength ({unit})", ylabel="relative spectral energy",
             title="(b) spectral energy distributions")
    ax_b.legend(frameon=False)
    fig.suptitle(f"Cook & Torrance 1982, Fig. 4 \u2014 {material.name} "
                 f"({material.kind} n,k; {grid[0]:g}-{grid[-1]:g} nm)")
    fig.tight_layout()
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("F0 of %s: %.4f .. %.4f", material.name, material.F0.min(), material.F0.max())
