"""Audit 4, spectral sampling: each material's exact Fresnel colour on coarser wavelength grids
and from three wavelengths, against the 1 nm grid."""

from pathlib import Path

import colour
import numpy as np
import pandas as pd
from matplotlib.colors import BoundaryNorm

from reflectance.audit.colour_shift import reflected_XYZ
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import linear_RGB_to_XYZ
from reflectance.io.atomic import atomic_write
from reflectance.io.figures import new_figure, savefig
from reflectance.optics.fresnel import fresnel_conductor
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.scripting import script_log, write_audit_metadata
from reflectance.io.tables import write_csv

BOUNDS = [0, 0.5, 1, 2, 5, 10, 20, 50]  # colour bands of the heat map (CIEDE2000)

with script_log(snakemake) as log:
    cfg, colour_cfg = snakemake.params.audit, snakemake.params.colour
    ill, obs, space = colour_cfg["illuminant"], colour_cfg["observer"], colour_cfg["space"]
    spectra_dir = Path(snakemake.input.spectra[0]).parent
    cos_theta = np.cos(np.radians(cfg["angles_deg"]))
    lo, hi = cfg["range_nm"]
    grids = {f"{cfg['reference_step_nm']:g} nm": wavelength_grid(lo, hi, cfg["reference_step_nm"])}
    grids.update({f"{step:g} nm": wavelength_grid(lo, hi, step) for step in cfg["steps_nm"]})
    weights = {label: tristimulus_weights(grid, ill, obs) for label, grid in grids.items()}
    reference = next(iter(grids))
    white = {label: W.sum(axis=0) for label, W in weights.items()}  # Y = 1 on every grid
    three = f"3 wavelengths ({', '.join(f'{w:g}' for w in cfg['three_wavelengths_nm'])} nm)"
    rows = []
    for name in cfg["materials"]:
        XYZ = {label: reflected_XYZ(load_material(name, grid, spectra_dir=spectra_dir),
                                    cos_theta, weights[label]) for label, grid in grids.items()}
        m3 = load_material(name, np.asarray(cfg["three_wavelengths_nm"]), spectra_dir=spectra_dir)
        # F at the three wavelengths taken as the linear display channels (white = the light's)
        F3 = fresnel_conductor(cos_theta[:, None], m3.n, m3.k)
        XYZ[three] = linear_RGB_to_XYZ(F3, space, illuminant=white[reference])
        white[three] = white[reference]  # RGB (1, 1, 1) is the light's white by construction
        # CIELAB of each sampling relative to its own white, as CIE 15 normalises
        lab_ref = colour.XYZ_to_Lab(XYZ[reference], colour.XYZ_to_xy(white[reference]))
        for label, values in list(XYZ.items())[1:]:
            lab = colour.XYZ_to_Lab(values, colour.XYZ_to_xy(white[label]))
            dE = colour.delta_E(lab, lab_ref, method="CIE 2000")
            rows += [{"material": name, "angle_deg": a, "sampling": label, "dE2000_vs_1nm": d}
                     for a, d in zip(cfg["angles_deg"], dE)]
    # the light's own white on each grid, seen against the 1 nm white (a cast over the image)
    light = f"{ill} white"
    lab_white = colour.XYZ_to_Lab(white[reference], colour.XYZ_to_xy(white[reference]))
    for label in list(grids)[1:]:
        dE = colour.delta_E(colour.XYZ_to_Lab(white[label], colour.XYZ_to_xy(white[reference])),
                            lab_white, method="CIE 2000")
        rows += [{"material": light, "angle_deg": a, "sampling": label, "dE2000_vs_1nm": dE}
                 for a in cfg["angles_deg"]]
    rows += [{"material": light, "angle_deg": a, "sampling": three, "dE2000_vs_1nm": 0.0}
             for a in cfg["angles_deg"]]
    table = pd.DataFrame(rows)
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    write_audit_metadata(
        snakemake, "Audit 4, spectral sampling: each material's exact Fresnel colour on coarser "
        "wavelength grids and from three wavelengths, against the finest grid",
        illuminant=ill, observer=obs,
        wavelengths_nm={**{label: {"start": float(lo), "end": float(hi), "step": float(step)}
                           for label, step in zip(grids, [cfg["reference_step_nm"],
                                                          *cfg["steps_nm"]])},
                        three: [float(w) for w in cfg["three_wavelengths_nm"]]},
        space=space, reference=reference,
        units={"material": "text", "angle_deg": "deg", "sampling": "text",
               "dE2000_vs_1nm": "CIEDE2000"})

    samplings = list(dict.fromkeys(table.sampling))
    worst = table.groupby(["material", "sampling"], sort=False).dE2000_vs_1nm.max().unstack()
    worst = worst.loc[[*cfg["materials"], light], samplings]
    fig = new_figure(7.0, 1.4 + 0.24 * len(cfg["materials"]))
    ax = fig.add_axes((0.2, 0.1, 0.62, 0.82))
    image = ax.imshow(worst.to_numpy(), aspect="auto", cmap="magma_r",
                      norm=BoundaryNorm(BOUNDS, 256, extend="max"), interpolation="nearest")
    for (i, j), value in np.ndenumerate(worst.to_numpy()):
        ax.text(j, i, f"{value:.2f}", ha="center", va="center", fontsize=7,
                color="white" if value > 5 else "black")
    ax.set_xticks(range(len(samplings)), [s.replace(" (", "\n(") for s in samplings], fontsize=8)
    ax.set_yticks(range(len(worst)), worst.index, fontsize=8)
    ax.tick_params(length=0)
    bar = fig.colorbar(image, ax=ax, fraction=0.05, pad=0.03, ticks=BOUNDS)
    bar.set_label("largest CIEDE2000 against 1 nm")
    angles = ", ".join(f"{a:g}" for a in cfg["angles_deg"])
    ax.set_title(f"Spectral sampling: exact Fresnel colour at {angles}\u00b0 ({ill}), worst "
                 f"angle", fontsize=9)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    parts = []
    for label in samplings:
        part = table[(table.sampling == label) & (table.material != light)]
        w = part.loc[part.dE2000_vs_1nm.idxmax()]
        parts.append(f"{label} {w.dE2000_vs_1nm:.2f} ({w.material}, {w.angle_deg:g}\u00b0)")
    answer = (f"**Answer:** the largest CIEDE2000 against the {reference} grid, over "
              f"{len(cfg['materials'])} materials and the angles, is: " + "; ".join(parts)
              + "; the light's own white moves by "
              + ", ".join(f"{v:.2f} ({k})" for k, v in worst.loc[light].iloc[:-1].items())
              + " on the coarser grids.\n")
    with atomic_write(snakemake.output.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
