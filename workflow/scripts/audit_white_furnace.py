"""Audit 6, conventions: the directional albedo (white furnace, F = 1) of Cook & Torrance 1982's
specular BRDF as printed against the normalised form, against the rms slope m."""

from pathlib import Path

import numpy as np
import pandas as pd

from reflectance.io.atomic import atomic_write
from reflectance.io.figures import new_figure, savefig
from reflectance.optics.brdf import directional_albedo
from reflectance.scripting import script_log, write_audit_metadata
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg = snakemake.params.audit
    rows = []
    for incidence in cfg["incidence_deg"]:
        t = np.radians(incidence)
        L = np.array([np.sin(t), 0.0, np.cos(t)])
        for m in cfg["m"]:
            albedo = {convention: float(directional_albedo(
                L, "CookTorrance1982", n_phi=cfg["n_phi"], F=1.0, s=1.0, d=0.0, R_d=0.0, m=m,
                distribution=cfg["distribution"], shadowing_method=cfg["shadowing"],
                convention=convention)) for convention in ("paper", "physical")}
            rows.append({"incidence_deg": incidence, "m": m, "albedo_paper": albedo["paper"],
                         "albedo_physical": albedo["physical"],
                         "ratio": albedo["paper"] / albedo["physical"]})
    table = pd.DataFrame(rows)
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    write_audit_metadata(
        snakemake, "Audit 6, the factor 4: directional albedo (white furnace, F = 1) of Cook & "
        "Torrance 1982's specular term as printed and normalised, against the rms slope m",
        # achromatic: F = 1 at every wavelength, no light's spectrum and no observer enter it
        illuminant=None, observer=None, wavelengths_nm=None,
        distribution=cfg["distribution"], shadowing=cfg["shadowing"], n_phi=cfg["n_phi"],
        units={"incidence_deg": "deg", "m": "1 (Beckmann rms slope)",
               "albedo_paper": "1 (reflected / incident power)",
               "albedo_physical": "1 (reflected / incident power)",
               "ratio": "1 (paper / physical)"})

    fig = new_figure(6.4, 4.2)
    ax = fig.add_axes((0.12, 0.13, 0.6, 0.78))
    colours = ["#1b4f72", "#b9770e", "#7d3c98", "#196f3d"]
    for colour, (incidence, part) in zip(colours, table.groupby("incidence_deg", sort=False)):
        ax.plot(part.m, part.albedo_paper, "-o", color=colour, markersize=3,
                label=f"as printed, \u03b8i = {incidence:g}\u00b0")
        ax.plot(part.m, part.albedo_physical, "--s", color=colour, markersize=3,
                label=f"normalised, \u03b8i = {incidence:g}\u00b0")
    ax.axhline(1.0, color="0.5", linewidth=0.8)
    ax.text(table.m.max(), 1.02, "energy conserved: albedo \u2264 1", ha="right", va="bottom",
            fontsize=7, color="0.3")
    ax.set_xlim(0, table.m.max() * 1.02)
    ax.set_ylim(0, 4.4)
    ax.set_yticks(np.arange(0, 4.5, 0.5))
    ax.set_xlabel("Beckmann rms slope m")
    ax.set_ylabel("directional albedo with F = 1")
    ax.set_title("Cook & Torrance 1982, R_s: white furnace", fontsize=10)
    ax.spines[["top", "right"]].set_visible(False)
    ax.legend(fontsize=7, frameon=False, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    worst = table.loc[table.albedo_paper.idxmax()]
    answer = (f"**Answer:** as printed, the specular term returns up to "
              f"{worst.albedo_paper:.3f} times the light it receives (m = {worst.m:g}, "
              f"\u03b8i = {worst.incidence_deg:g}\u00b0); it is {table.ratio.min():.4f} to "
              f"{table.ratio.max():.4f} times the normalised BRDF at every m and angle, whose "
              f"albedo stays at or below {table.albedo_physical.max():.4f}.\n")
    with atomic_write(snakemake.output.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
