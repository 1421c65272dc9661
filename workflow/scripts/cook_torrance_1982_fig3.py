"""Cook & Torrance 1982, Fig. 3: the Beckmann and Gaussian facet distributions for two rms slopes m,
each as a surface over the hemisphere of facet normals H: the distance from P along H is D(alpha)."""

import numpy as np
import pandas as pd
import pyvista as pv
from scipy.integrate import simpson

from reflectance.optics.microfacet import distribution_Beckmann1963, distribution_Gaussian_CookTorrance1982
from reflectance.io.figures import font_file, off_screen_plotter, save_plotter, set_vtk_font
from reflectance.papers.polar import direction_from_angles
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

FONT = font_file()  # the figures' typeface, for VTK's text too

with script_log(snakemake) as log:
    fig = snakemake.params.fig
    alpha = np.radians(np.arange(0.0, 90.0 + 1e-9, fig["alpha_step_deg"]))
    phi = np.radians(np.arange(0.0, 360.0 + 1e-9, fig["azimuth_step_deg"]))
    panels, columns = [], {"alpha_deg": np.degrees(alpha)}
    for m in fig["m"]:
        # "c is an arbitrary constant": beckmann_peak sets D(0) = 1/m^2, Beckmann's value at alpha = 0.
        c = 1.0 / m**2 if fig["gaussian_c"] == "beckmann_peak" else 1.0
        for model, D in (("Beckmann", distribution_Beckmann1963(np.cos(alpha), m)),
                         ("Gaussian", distribution_Gaussian_CookTorrance1982(np.cos(alpha), m, c=c))):
            panels.append((model, m, c, D))
            columns[f"{model}_m{m:g}"] = D
    pd.DataFrame(columns).pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    pl = off_screen_plotter(1600, 1400, shape=(2, 2))
    pl.set_background("white")
    A, P = np.meshgrid(alpha, phi, indexing="ij")
    for i, (model, m, c, D) in enumerate(panels):
        letter = "abcd"[i]
        pl.subplot(i // 2, i % 2)
        radius = D[:, None] * m**2  # common scale per m: Beckmann's peak 1/m^2 at unit distance
        H = direction_from_angles(A, P)  # facet normals over the hemisphere
        surface = pv.StructuredGrid(*(radius * H[..., j] for j in range(3)))
        surface["D"] = np.broadcast_to(D[:, None], A.shape).ravel(order="F")  # VTK point order
        pl.add_mesh(pv.Disc(inner=0, outer=0.8, c_res=96), color="#e4dfd3")
        pl.add_mesh(pv.Line((0, 0, 0), (0, 0, 1.15)), color="black", line_width=2)
        pl.add_mesh(surface, scalars="D", cmap="viridis", smooth_shading=True, clim=(0, 1 / m**2),
                    scalar_bar_args={"title": f"D ({letter})", "n_labels": 3, "fmt": "%.3g",
                                     "color": "black", "vertical": True,
                                     "position_x": 0.9, "position_y": 0.15, "height": 0.6,
                                     "width": 0.04, "title_font_size": 26, "label_font_size": 24})
        bar = pl.scalar_bars[f"D ({letter})"]
        set_vtk_font(bar.GetTitleTextProperty(), bar.GetLabelTextProperty())
        # Projected-area integral 2 pi int D cos(alpha) sin(alpha) d alpha (pi for Beckmann, paper).
        integral = 2 * np.pi * simpson(D * np.cos(alpha) * np.sin(alpha), x=alpha)
        constant = "" if model == "Beckmann" else (
            f", c = 1/m\u00b2 = {c:.4g}" if fig["gaussian_c"] == "beckmann_peak" else f", c = {c:g}")
        pl.add_text(f"({letter}) {model}, m = {m:g}{constant}\nD(0) = {D[0]:.4g},  "
                    f"\u222b D cos\u03b1 d\u03c9 = {integral:.4g}", font_size=14,
                    color="black", position="upper_left", font_file=FONT)
        pl.camera_position = [(0.0, -2.9, 2.5), (0.0, 0.0, 0.38), (0.0, 0.0, 1.0)]  # from 36 degrees above the disc
        log.info("(%s) %s m=%g c=%g: D(0)=%.6g, projected-area integral %.6g",
                 letter, model, m, c, D[0], integral)
    save_plotter(pl, snakemake.output.png)
