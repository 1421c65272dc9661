"""Cook & Torrance 1982, Fig. 5a: a copper mirror's reflectance as a function of wavelength and
incidence angle, from the exact complex-index Fresnel equation, as a 3-D surface (pyvista)."""

from pathlib import Path

import numpy as np
import pandas as pd
import pyvista as pv

from reflectance.optics.fresnel import fresnel_conductor
from reflectance.io.figures import off_screen_plotter, save_plotter
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

    # Plot in unit box coordinates; the axes are labelled with the physical ranges.
    x, y = np.meshgrid((grid - grid[0]) / np.ptp(grid), angles / 90.0)
    surface = pv.StructuredGrid(x, y, F)
    surface["reflectance"] = F.ravel(order="F")
    pl = off_screen_plotter(1200, 900)
    pl.set_background("white")
    pl.add_mesh(surface, scalars="reflectance", cmap="copper", clim=(0, 1), smooth_shading=True,
                show_scalar_bar=False)
    pl.show_bounds(bounds=(0, 1, 0, 1, 0, 1),
                   axes_ranges=(grid[0] / 1000, grid[-1] / 1000, 0, 90, 0, 1),
                   xtitle="wavelength (um)", ytitle="incidence angle (deg)",
                   ztitle="reflectance F", font_size=12, color="black", location="outer",
                   n_xlabels=5, n_ylabels=4, n_zlabels=3, fmt="%.2f")
    pl.add_text(f"Cook & Torrance 1982, Fig. 5a: {material.name} mirror, exact Fresnel (n, k)",
                font_size=12, color="black", position="upper_left")
    pl.view_vector((0.55, -1.4, 0.95), viewup=(0, 0, 1))
    pl.reset_camera()
    pl.camera.zoom(0.9)
    save_plotter(pl, snakemake.output.png)
    log.info("F range %.4f .. %.4f over %d angles x %d wavelengths",
             F.min(), F.max(), angles.size, grid.size)
