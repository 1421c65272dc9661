"""Audit 7, judgement: how much the colours of Cook & Torrance 1982 Table I's Munsell-derived
materials depend on the spectral recovery (the configured method against colour-science's others).
The configured method's spectrum is the material's own file (spectra/<name>.csv, which that
recovery wrote): the spectrum every figure renders, and not recovered a second time."""

from pathlib import Path

import colour
import numpy as np
import pandas as pd

from reflectance.audit.colour_shift import reflected_XYZ
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.io.atomic import atomic_write
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.optics.spectra import (DEFAULT_RECOVERY, material_from_table,
                                        read_spectrum_csv, reflectance_from_munsell,
                                        wavelength_grid)
from reflectance.scripting import script_log, write_audit_metadata
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg, entries, obs = snakemake.params.audit, snakemake.params.entries, \
        snakemake.params.colour["observer"]
    grid = wavelength_grid(**snakemake.params.wavelengths)
    cos_theta = np.cos(np.radians(cfg["angles_deg"]))
    rows, spectra = [], {}
    files = dict(zip(cfg["materials"], snakemake.input.spectra))
    for name in cfg["materials"]:
        entry = entries[name]
        own = entry.get("recovery", DEFAULT_RECOVERY)
        tables = {method: read_spectrum_csv(files[name]) if method == own
                  else reflectance_from_munsell(entry["notation"], method, grid)
                  for method in cfg["methods"]}
        spectra[name] = (own, tables)
        for illuminant in cfg["illuminants"]:
            W = tristimulus_weights(grid, illuminant, obs)
            white_xy = colour.XYZ_to_xy(W.sum(axis=0))
            lab = {method: colour.XYZ_to_Lab(reflected_XYZ(
                material_from_table(name, table, grid), cos_theta, W), white_xy)
                for method, table in tables.items()}
            for method in cfg["methods"]:
                dE = colour.delta_E(lab[method], lab[own], method="CIE 2000")
                rows += [{"material": name, "notation": entry["notation"], "illuminant": illuminant,
                          "angle_deg": a, "recovery": method, "against": own,
                          "L": l[0], "a": l[1], "b": l[2], "dE2000_vs_own": d}
                         for a, l, d in zip(cfg["angles_deg"], lab[method], dE)]
    table = pd.DataFrame(rows)
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    write_audit_metadata(
        snakemake, "Audit 7, spectral recovery: the colour of each Munsell-derived material of "
        "Cook & Torrance 1982 Table I by each recovery method, against the one its spectrum used",
        illuminant=list(cfg["illuminants"]), observer=obs,
        wavelengths_nm=snakemake.params.wavelengths, methods=list(cfg["methods"]),
        units={"material": "text", "notation": "text (Munsell)", "illuminant": "text",
               "angle_deg": "deg", "recovery": "text", "against": "text",
               "L": "CIELAB L* (0-100)", "a": "CIELAB a*", "b": "CIELAB b*",
               "dE2000_vs_own": "CIEDE2000"})

    fig = new_figure(PRINT_WIDTH_IN, 3.0)  # the print width: its text prints at the figures' sizes
    axes = fig.subplots(1, len(spectra), sharey=True,
                        gridspec_kw={"left": 0.08, "right": 0.99, "top": 0.77, "bottom": 0.15,
                                     "wspace": 0.1})
    styles = dict(zip(cfg["methods"], ["-", "--", ":", "-."]))
    for ax, (name, (own, tables)) in zip(np.atleast_1d(axes), spectra.items()):
        for method, t in tables.items():
            ax.plot(t.wavelength_nm, t.reflectance, styles[method], color="k",
                    linewidth=1.6 if method == own else 1.0,
                    label=f"{method}{' (used)' if method == own else ''}")
        worst = table[(table.material == name)].dE2000_vs_own.max()
        ax.set_title(f"{name} ({entries[name]['notation']})\nlargest \u0394E00 {worst:.2f}",
                     fontsize=TEXT_SIZE["annotation"])
        ax.set_xlabel("wavelength (nm)")
        ax.set_xticks([400, 600, 800])
        ax.spines[["top", "right"]].set_visible(False)
    np.atleast_1d(axes)[0].set_ylabel("reflectance")
    np.atleast_1d(axes)[0].legend(fontsize=TEXT_SIZE["table"], frameon=False, handlelength=1.5)
    fig.suptitle("Table I's derived materials: the same Munsell colour recovered three ways",
                 y=0.99, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    w = table.loc[table.dE2000_vs_own.idxmax()]
    at0 = table[table.angle_deg == min(cfg["angles_deg"])].dE2000_vs_own.max()
    answer = (f"**Answer:** at most CIEDE2000 {w.dE2000_vs_own:.2f} ({w.material}, {w.recovery} "
              f"against {w.against}, under {w.illuminant} at {w.angle_deg:g}\u00b0); for the "
              f"reflectance itself ({min(cfg['angles_deg']):g}\u00b0) at most {at0:.2f}.\n")
    with atomic_write(snakemake.output.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
