"""Cook & Torrance 1982, Fig. 4: (a) a copper mirror's normal reflectance vs wavelength (um);
(b) D65's spectral energy distribution and that reflected by the copper mirror at normal incidence."""

from pathlib import Path

import numpy as np
import pandas as pd

from reflectance.colour.colorimetry import cmfs, illuminant_range_nm, illuminant_sd
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import PRINT_WIDTH_IN, new_figure, paper_name, savefig
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

    name = paper_name(material.name)
    fig = new_figure(PRINT_WIDTH_IN, 0.42 * PRINT_WIDTH_IN)
    ax_a, ax_b = fig.subplots(1, 2)
    ax_a.plot(grid * scale, material.F0, color="#b3672b", label="from n, k (linear interpolation)")
    raw = read_spectrum_csv(snakemake.input.spectrum)
    raw = raw[(raw.wavelength_nm >= grid[0]) & (raw.wavelength_nm <= grid[-1])]
    if "n" in raw:
        ax_a.plot(raw.wavelength_nm * scale, F0_from_nk(raw.n, raw.k), "o", ms=3,
                  color="#5a3315", label="$F_0$ from measured n, k")
    ax_a.legend(loc="lower right")
    ax_a.set(xlabel=f"wavelength ({unit})", ylabel="normal reflectance $F_0$", ylim=(0, 1),
             title=f"(a) {name} mirror, normal incidence")
    ax_b.plot(grid * scale, light, color="0.3", label=f"CIE {colour_cfg['illuminant']}")
    tabulated_end = illuminant_range_nm(colour_cfg["illuminant"])[1]  # colour-science's table
    if min(grid[-1], fig_cfg["axis_nm"][1]) > tabulated_end:  # the table stops here; beyond, held constant
        ax_b.axvspan(tabulated_end * scale, grid[-1] * scale, color="0.92", zorder=0,
                     label="held constant (past the table)")
    ax_b.plot(grid * scale, reflected, color="#b3672b", label=f"reflected by {name}")
    ax_b.set(xlabel=f"wavelength ({unit})", ylabel="relative spectral energy",
             ylim=(0, 1.05 * max(light.max(), reflected.max())),  # fitted to the data
             title="(b) spectral energy distributions")
    ax_b.legend(loc="lower right")  # below the curves (they stay above ~1/3 of the peak there)
    # the axes span the paper's "visible wavelengths" (config axis_nm), not the whole colour grid
    start, end = fig_cfg["axis_nm"]
    for ax in (ax_a, ax_b):
        ax.set_xlim(start * scale, end * scale)
        ticks = np.arange(np.ceil(start / 100) * 100, end + 1e-9, 100)
        ax.set_xticks(np.round(ticks * scale, 1) if unit != "nm" else ticks)
    fig.suptitle(f"Cook & Torrance 1982, Fig. 4 \u2014 {name} ({material.kind} n, k; "
                 f"{start:g}\u2013{end:g} nm shown)")
    fig.tight_layout(w_pad=1.5)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("F0 of %s: %.4f .. %.4f", material.name, material.F0.min(), material.F0.max())

    # the caption's numbers (workflow/report/ct82_fig4.rst): where colour-science's table of the
    # illuminant stops, and how little the CMFs weigh beyond it
    weights = cmfs(colour_cfg["observer"], grid)
    beyond = weights[grid > tabulated_end].max(initial=0.0) / weights.max()
    values = {"tabulated_end": f"{tabulated_end:g}", "cmf_beyond": f"{beyond:.1e}"}

    # which copper: the comparison beside the figure (rule ct82_fig4_copper), in its numbers
    copper = pd.read_csv(snakemake.input.copper, keep_default_na=False)
    best, used = copper[copper.best].iloc[0], copper[copper.figure]
    used = used.iloc[0] if len(used) else None
    changed = copper[copper.changes_look]
    values.update({
        "copper_count": f"{len(copper)}", "best_label": best.label,
        "best_comments": best.comments or "(none given)", "best_ratio": f"{best.red_blue_ratio:.2f}",
        "best_L": f"{best.L:.1f}", "best_C": f"{best.C:.1f}", "best_h": f"{best.h:.0f}",
        "figure_label": used.label if used is not None else "none of them",
        "figure_ratio": f"{used.red_blue_ratio:.2f}" if used is not None else "-",
        "figure_L": f"{used.L:.1f}" if used is not None else "-",
        "figure_C": f"{used.C:.1f}" if used is not None else "-",
        "figure_h": f"{used.h:.0f}" if used is not None else "-",
        "best_dE": f"{best.dE00_from_figure:.1f}" if used is not None else "-",
        "best_verdict": "changes" if best.changes_look else "does not change",
        "look_dE00": f"{best.look_dE00:g}",
        "L_min": f"{copper.L.min():.1f}", "L_max": f"{copper.L.max():.1f}",
        "C_min": f"{copper.C.min():.1f}", "C_max": f"{copper.C.max():.1f}",
        "changed": (", ".join(f"{r.label} (h {r.h:.0f})" for r in changed.itertuples())
                    or "none")})
    write_caption_values(snakemake.output.values, values)
