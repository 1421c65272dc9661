"""Lecture (Russin, Module 3B), "BRDF" slide: the sample BRDFs of brdf_lobes_2d as 3-D lobe surfaces
(pyvista, off-screen). Each surface point is V f(L, V) / max f over the outgoing hemisphere: the
radius along every outgoing direction V is the BRDF itself (not f cos theta_o), scaled per lobe by its
largest value up to ``scale_to_deg`` from the normal (and clipped there: Ward's lobe grows without
bound at the horizon)."""

import numpy as np
import pyvista as pv

from reflectance.optics.brdf import brdf
from reflectance.io.figures import font_file, off_screen_plotter, save_plotter
from reflectance.papers.polar import direction_from_angles, plane_of_incidence_vectors
from reflectance.scripting import script_log

# config key -> (reflectance.optics.brdf method, panel title)
MODELS = {
    "diffuse": ("Lambert", "Diffuse\n(Lambert)"),
    "phong": ("Phong1975", "Phong"),
    "blinn_phong": ("BlinnPhong_AkenineMoller2008", "Blinn-Phong\n(m+8)/(8 pi)"),
    "cook_torrance": ("CookTorrance1982", "Cook-Torrance"),
    "ward": ("Ward1992", "Ward,\nanisotropic"),
    "lunar": ("LommelSeeliger", "lunar\n(Lommel-Seeliger)"),
}

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    theta_i = np.radians(cfg["incidence_deg"])
    L, mirror, N = plane_of_incidence_vectors(theta_i, theta_i)  # light on the -x side
    n_theta, n_phi = cfg["hemisphere_samples"]
    theta, phi = np.meshgrid(np.linspace(0.0, np.pi / 2, n_theta), np.linspace(0.0, 2 * np.pi, n_phi),
                             indexing="ij")
    V = direction_from_angles(theta, phi)

    pl = off_screen_plotter(1800, 400, shape=(1, len(MODELS)))  # the lobes and their titles, little empty canvas
    pl.set_background("white")
    for i, (key, (method, title)) in enumerate(MODELS.items()):
        f = brdf(L, V, N, method, **cfg["models"][key])
        # Ward's 1/sqrt(N.V) grows without bound at the horizon: scale by the peak short of it
        peak = float(f[theta <= np.radians(cfg["scale_to_deg"])].max())
        r = np.minimum(f / peak, 1.0)
        lobe = pv.StructuredGrid(*(r * V[..., j] for j in range(3)))
        lobe["f / max f"] = r.ravel(order="F")
        pl.subplot(0, i)
        pl.add_mesh(lobe, scalars="f / max f", cmap="viridis", clim=(0, 1), smooth_shading=True,
                    show_scalar_bar=False)
        pl.add_mesh(pv.Disc(inner=0.0, outer=1.15, normal=(0, 0, 1), c_res=96), color="#d9d9d9",
                    opacity=0.5)
        pl.add_mesh(pv.Arrow(start=1.45 * L, direction=-L, scale=1.3, tip_length=0.12,
                             tip_radius=0.035, shaft_radius=0.012), color="#d98c00")
        pl.add_mesh(pv.Line((0, 0, 0), 1.3 * mirror), color="#595959", line_width=2)
        pl.add_text(f"{title}\nmax f = {peak:.3g} /sr", font_size=12, color="black",
                    position="upper_edge", font_file=font_file())  # the figures' typeface, ~8 pt at 7 in
        pl.view_vector((0.2, -1.0, 0.45), viewup=(0, 0, 1))
        pl.reset_camera(bounds=(-1.45, 1.45, -1.0, 1.0, 0.0, 1.2))
        pl.camera.zoom(1.45)
        log.info("%s: max f %.6g sr^-1", key, peak)
    save_plotter(pl, snakemake.output.png)
