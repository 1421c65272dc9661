"""Audit 1, the Fresnel shortcut atlas: CIEDE2000 of every shortcut against the exact spectral
Fresnel colour, for every bundled metal and incidence angle; the first angle above each level."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.colors import BoundaryNorm

from reflectance.audit.shortcuts import AUDIT_METHODS, dE2000_against_angle, first_angle_above
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.io.atomic import atomic_write
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.scripting import script_log, write_audit_metadata
from reflectance.io.tables import write_csv

BOUNDS = [0, 0.5, 1, 2, 5, 10, 20, 50]  # colour bands of the heat map (CIEDE2000)

with script_log(snakemake) as log:
    cfg, colour_cfg = snakemake.params.audit, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    angles = np.arange(0.0, 90.0, cfg["angle_step_deg"])
    metals, methods, levels = cfg["materials"], cfg["methods"], cfg["levels"]
    spectra_dir = Path(snakemake.input.spectra[0]).parent
    dE = np.stack([dE2000_against_angle(load_material(name, grid, spectra_dir=spectra_dir), angles,
                                        W, methods, colour_cfg["space"],
                                        cfg["average_F0_range_nm"]) for name in metals])
    # dE: (metal, method, angle)
    long = pd.DataFrame({"material": np.repeat(metals, len(methods) * angles.size),
                         "method": np.tile(np.repeat(methods, angles.size), len(metals)),
                         "angle_deg": np.tile(angles, len(metals) * len(methods)),
                         "dE2000_vs_exact": dE.ravel()})
    long.pipe(write_csv, snakemake.output.table, float_format="%.6g")
    first = pd.DataFrame([{"material": name, "method": method,
                           **{f"first_deg_above_{level:g}": first_angle_above(
                               angles, dE[i, j], level) for level in levels},
                           "max_dE2000": dE[i, j].max()}
                          for i, name in enumerate(metals) for j, method in enumerate(methods)])
    first.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    write_audit_metadata(
        snakemake, "Audit 1, the Fresnel shortcut atlas: CIEDE2000 of each shortcut against the "
        "exact spectral Fresnel colour of each metal (smooth), per incidence angle",
        illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
        wavelengths_nm=snakemake.params.wavelengths, space=colour_cfg["space"],
        methods={m: AUDIT_METHODS[m] for m in methods},
        units={"material": "text", "method": "text", "angle_deg": "deg", "dE2000_*": "CIEDE2000",
               "first_deg_above_*": "deg", "max_dE2000": "CIEDE2000"})

    # drawn at the print width, so its text prints at the figures' sizes
    fig = new_figure(PRINT_WIDTH_IN, 5.6)
    axes = fig.subplots(2, 3, sharex=True, sharey=True,
                        gridspec_kw={"left": 0.15, "right": 0.86, "top": 0.85, "bottom": 0.09,
                                     "hspace": 0.2, "wspace": 0.16})
    norm = BoundaryNorm(BOUNDS, 256, extend="max")
    step = cfg["angle_step_deg"]
    for j, (ax, method) in enumerate(zip(axes.flat, methods)):
        image = ax.imshow(dE[:, j, :], aspect="auto", cmap="magma_r", norm=norm,
                          extent=(-step / 2, angles[-1] + step / 2, len(metals) - 0.5, -0.5),
                          interpolation="nearest")
        ax.set_title(method)
        ax.set_yticks(range(len(metals)), metals, fontsize=TEXT_SIZE["table"])
        ax.set_xticks(np.arange(0, 91, 30))
        if j >= 3:
            ax.set_xlabel("incidence \u03b8 (\u00b0)")
    for ax in axes.flat[len(methods):]:
        ax.set_visible(False)
    bar = fig.colorbar(image, ax=axes, fraction=0.04, pad=0.03, ticks=BOUNDS)
    bar.set_label("CIEDE2000 against exact")
    fig.suptitle(f"Fresnel shortcut atlas: colour error of each shortcut against\nthe exact "
                 f"spectral Fresnel colour ({colour_cfg['illuminant']}, smooth metal)",
                 linespacing=1.3, y=0.995, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    lo, hi = f"first_deg_above_{levels[0]:g}", f"first_deg_above_{levels[-1]:g}"
    parts = []
    for method in methods:
        rows = first[first.method == method]
        worst = rows.loc[rows[lo].fillna(np.inf).idxmin()]
        if np.isnan(worst[lo]):
            parts.append(f"{method} never (max {rows.max_dE2000.max():.2f})")
            continue
        above_hi = rows[hi].dropna()
        high = (f"{above_hi.min():g}\u00b0 ({rows.loc[above_hi.idxmin(), 'material']})"
                if len(above_hi) else "never")
        parts.append(f"{method} {worst[lo]:g}\u00b0 ({worst.material}) / {high}")
    answer = (f"**Answer:** over the {len(metals)} metals, the first angle at which each shortcut "
              f"exceeds CIEDE2000 {levels[0]:g} / {levels[-1]:g} (worst metal) is: "
              + "; ".join(parts) + ".\n")
    with atomic_write(snakemake.output.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
    for method in methods:
        log.info("%s: %s", method, AUDIT_METHODS[method])
