"""Audit 5, illuminant and observer: how far each material's colour moves under other lights
(adapted to the reference white) and for the 1964 10 degree observer; which are most metameric."""

from pathlib import Path

import colour
import numpy as np
import pandas as pd
from matplotlib.colors import BoundaryNorm

from reflectance.audit.colour_shift import reflected_XYZ
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.io.atomic import atomic_write
from reflectance.io.figures import new_figure, savefig
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.scripting import script_log, write_audit_metadata
from reflectance.io.tables import write_csv

BOUNDS = [0, 0.5, 1, 2, 5, 10, 20]  # colour bands of the heat map (CIEDE2000)

with script_log(snakemake) as log:
    cfg = snakemake.params.audit
    grid = wavelength_grid(**snakemake.params.wavelengths)
    spectra_dir = Path(snakemake.input.spectra[0]).parent
    cos_theta = np.cos(np.radians(cfg["angles_deg"]))
    ref, (obs2, obs10) = cfg["reference_illuminant"], cfg["observers"]
    W_ref = tristimulus_weights(grid, ref, obs2)
    white_ref = W_ref.sum(axis=0)
    xy_ref = colour.XYZ_to_xy(white_ref)
    W10 = tristimulus_weights(grid, ref, obs10)
    rows = []
    for name in cfg["materials"]:
        material = load_material(name, grid, spectra_dir=spectra_dir)
        lab_ref = colour.XYZ_to_Lab(reflected_XYZ(material, cos_theta, W_ref), xy_ref)
        moved = {}
        for illuminant in cfg["illuminants"]:
            W = tristimulus_weights(grid, illuminant, obs2)
            # the colour under the other light, adapted to the reference white (von Kries)
            XYZ = colour.chromatic_adaptation(reflected_XYZ(material, cos_theta, W), W.sum(axis=0),
                                              white_ref, method="Von Kries",
                                              transform=cfg["adaptation"])
            moved[f"{illuminant} ({cfg['adaptation']})"] = colour.XYZ_to_Lab(XYZ, xy_ref)
        # the other observer, each in CIELAB relative to its own white of the reference light
        moved["10\u00b0 observer"] = colour.XYZ_to_Lab(reflected_XYZ(material, cos_theta, W10),
                                                     colour.XYZ_to_xy(W10.sum(axis=0)))
        for label, lab in moved.items():
            dE = colour.delta_E(lab, lab_ref, method="CIE 2000")
            rows += [{"material": name, "kind": material.kind, "angle_deg": a, "change": label,
                      "dE2000": d} for a, d in zip(cfg["angles_deg"], dE)]
    table = pd.DataFrame(rows)
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    write_audit_metadata(
        snakemake, "Audit 5, illuminant and observer: how far each material's colour moves under "
        "other lights (adapted to the reference white) and for the other observer",
        illuminant={"reference": ref, "others": list(cfg["illuminants"]),
                    "adaptation": f"von Kries ({cfg['adaptation']})"},
        observer={"reference": obs2, "other": obs10},
        wavelengths_nm=snakemake.params.wavelengths,
        units={"material": "text", "kind": "text", "angle_deg": "deg", "change": "text",
               "dE2000": "CIEDE2000"})

    changes = list(dict.fromkeys(table.change))
    at0 = table[table.angle_deg == cfg["angles_deg"][0]]
    grid_dE = at0.pivot(index="material", columns="change", values="dE2000").loc[
        cfg["materials"], changes]
    fig = new_figure(6.6, 1.4 + 0.24 * len(cfg["materials"]))
    ax = fig.add_axes((0.22, 0.1, 0.58, 0.82))
    image = ax.imshow(grid_dE.to_numpy(), aspect="auto", cmap="magma_r",
                      norm=BoundaryNorm(BOUNDS, 256, extend="max"), interpolation="nearest")
    for (i, j), value in np.ndenumerate(grid_dE.to_numpy()):
        ax.text(j, i, f"{value:.2f}", ha="center", va="center", fontsize=7,
                color="white" if value > 5 else "black")
    ax.set_xticks(range(len(changes)), [c.replace(" (", "\n(") for c in changes], fontsize=8)
    ax.set_yticks(range(len(grid_dE)), grid_dE.index, fontsize=8)
    ax.tick_params(length=0)
    bar = fig.colorbar(image, ax=ax, fraction=0.05, pad=0.03, ticks=BOUNDS)
    bar.set_label(f"CIEDE2000 against {ref}, 2\u00b0")
    ax.set_title(f"Colour at {cfg['angles_deg'][0]:g}\u00b0 under other lights and observer",
                 fontsize=9)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    parts = []
    for label in changes:
        part = table[table.change == label]
        w = part.loc[part.dE2000.idxmax()]
        parts.append(f"{label} {w.dE2000:.2f} ({w.material}, {w.angle_deg:g}\u00b0)")
    answer = ("**Answer:** the largest CIEDE2000 against the reference colour is: "
              + "; ".join(parts) + ".\n")
    with atomic_write(snakemake.output.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
