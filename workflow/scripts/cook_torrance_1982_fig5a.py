"""Cook & Torrance 1982, Fig. 5a: a copper mirror's reflectance as a function of wavelength and
incidence angle, from the exact complex-index Fresnel equation, as a 3-D surface (matplotlib)."""

from pathlib import Path

import numpy as np
import pandas as pd
from reflectance.optics.fresnel import fresnel_conductor
from reflectance.io.figures import PRINT_WIDTH_IN, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    fig_cfg = snakemake.params.fig
    grid = wavelength_grid(**snakemake.params.wavelengths)
    material = load_material(fig_cfg["material"], grid,
                             spectra_dir=Path(snakemake.input.spectrum).parent)
    angles = np.arange(0.0, 90.0 + 1e-9, fig_cfg["surface_angle_step_deg"])
    cos_theta = np.clip(np.cos(np.radians(angles)), 0.0, 1.0)
    F = fresnel_conductor(cos_theta[:, None], material.n, material.k)  # (angle, wavelength)

    pd.DataFrame({
        "angle_deg": np.repeat(angles, grid.size),
        "wavelength_nm": np.tile(grid, angles.size),
        "F": F.ravel(),
    }).pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    # A 3-D surface as the paper draws it, with matplotlib's 3-D axes (round ticks in micrometres and
    # degrees; the project's style); the angle axis runs towards the viewer as in the paper's figure.
    from matplotlib import cm, colors

    lam_um = grid / 1000.0
    X, Y = np.meshgrid(lam_um, angles)
    fig = new_figure(PRINT_WIDTH_IN, 0.7 * PRINT_WIDTH_IN)
    # the 3-D box over the whole figure, zoomed (matplotlib's default leaves a wide empty margin)
    ax = fig.add_axes((0.0, 0.0, 1.0, 0.95), projection="3d", computed_zorder=False)
    shade = cm.copper(colors.Normalize(0.3, 1.0)(F))
    ax.plot_surface(X, Y, F, facecolors=shade, rstride=2, cstride=2, linewidth=0.15,
                    edgecolor=(0, 0, 0, 0.15), antialiased=True, shade=False)
    ax.set(xlim=(0.35, 0.85), ylim=(0, 90), zlim=(0, 1), xticks=[0.4, 0.5, 0.6, 0.7, 0.8],
           yticks=[0, 30, 60, 90], zticks=[0, 0.5, 1.0])
    ax.set_xlabel("wavelength (\u00b5m)", labelpad=6)
    ax.set_ylabel("incidence angle \u03b8 (\u00b0)", labelpad=6)
    ax.set_zlabel("reflectance F", labelpad=4)
    ax.view_init(elev=24, azim=-58)
    ax.set_box_aspect((1.25, 1.0, 0.75), zoom=1.12)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.pane.set_facecolor((1, 1, 1, 0))
        axis.pane.set_edgecolor("0.7")
        axis._axinfo["grid"].update(color="0.88", linewidth=0.6)
    fig.suptitle(f"Cook & Torrance 1982, Fig. 5a \u2014 reflectance of a {material.name} mirror "
                 f"(exact Fresnel, measured n, k)", y=0.985)
    savefig(fig, snakemake.output.png)
    log.info("F range %.4f .. %.4f over %d angles x %d wavelengths",
             F.min(), F.max(), angles.size, grid.size)
