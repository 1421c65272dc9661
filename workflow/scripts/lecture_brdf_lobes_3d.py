"""Lecture (Russin, Module 3B), "BRDF" slide: the sample BRDFs of brdf_lobes_2d as 3-D lobe surfaces
(pyvista, off-screen), in the 2-D figure's grid of two rows of three. Each surface point is
V f(L, V) / max f over the outgoing hemisphere: the radius along every outgoing direction V is the
BRDF itself (not f cos theta_o), scaled per lobe by its largest value up to ``scale_to_deg`` from the
normal (``lobe_peak``, the 2-D figure's scale). A lobe that rises past that value nearer the horizon
(Ward's 1/sqrt(N.L N.V)) ends at ``scale_to_deg``; the others reach the surface. The job checks each
maximum against the plane of incidence at the 2-D figure's steps (``polar_step_deg``) and writes
both to the caption's values."""

import numpy as np
import pyvista as pv

from reflectance.io.captions import write_caption_values
from reflectance.io.figures import font_file, off_screen_plotter, save_plotter
from reflectance.optics.brdf import brdf
from reflectance.papers.polar import (direction_from_angles, lobe_peak, plane_angles,
                                      plane_of_incidence_vectors)
from reflectance.scripting import script_log

# config key -> (reflectance.optics.brdf method, panel title): the 2-D figure's models
MODELS = {
    "diffuse": ("Lambert", "Diffuse (Lambert)"),
    "phong": ("Phong1975", "Phong"),
    "blinn_phong": ("BlinnPhong_AkenineMoller2008", "Blinn-Phong, (m+8)/(8 pi)"),
    "cook_torrance": ("CookTorrance1982", "Cook-Torrance"),
    "ward": ("Ward1992", "Ward, anisotropic"),
    "lunar": ("Hapke1981", "lunar (Hapke, opposition effect)"),
}
COLUMNS = 3

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    limit = cfg["scale_to_deg"]
    theta_i = np.radians(cfg["incidence_deg"])
    L, mirror, N = plane_of_incidence_vectors(theta_i, theta_i)  # light on the -x side
    n_theta, n_phi = cfg["hemisphere_samples"]
    theta, phi = np.meshgrid(np.linspace(0.0, np.pi / 2, n_theta), np.linspace(0.0, 2 * np.pi, n_phi),
                             indexing="ij")
    V = direction_from_angles(theta, phi)
    # f in the plane of incidence at the 2-D figure's steps (as its table, computed here so that
    # this figure reads only its own keys)
    theta_plane = plane_angles(cfg["polar_step_deg"])
    L_plane, V_plane, _ = plane_of_incidence_vectors(theta_i, theta_plane)

    rows = -(-len(MODELS) // COLUMNS)
    pl = off_screen_plotter(*cfg["render_3d"]["size"], shape=(rows, COLUMNS))
    pl.set_background("white")
    found = {}  # per model: its maximum over the hemisphere and in the 2-D table, where, how far drawn
    for i, (key, (method, title)) in enumerate(MODELS.items()):
        f = brdf(L, V, N, method, **cfg["models"][key])
        peak, at = lobe_peak(f, theta, limit)
        in_plane, _ = lobe_peak(brdf(L_plane, V_plane, N, method, **cfg["models"][key]), theta_plane, limit)
        r = f / peak
        # rings of theta past the limit are drawn while the lobe stays within its scale (Ward's does not)
        beyond = (theta[:, 0] > np.radians(limit)) & (r.max(axis=1) > 1.0)
        last = int(np.argmax(beyond)) if beyond.any() else n_theta
        r, Vd = r[:last], V[:last]
        lobe = pv.StructuredGrid(*(r * Vd[..., j] for j in range(3)))
        lobe["f / max f"] = r.ravel(order="F")
        pl.subplot(i // COLUMNS, i % COLUMNS)
        pl.add_mesh(lobe, scalars="f / max f", cmap="viridis", clim=(0, 1), smooth_shading=True,
                    show_scalar_bar=False)
        pl.add_mesh(pv.Disc(inner=0.0, outer=1.1, normal=(0, 0, 1), c_res=96), color="#d9d9d9",
                    opacity=0.5)
        pl.add_mesh(pv.Arrow(start=1.35 * L, direction=-L, scale=1.25, tip_length=0.12,
                             tip_radius=0.035, shaft_radius=0.012), color="#d98c00")
        pl.add_mesh(pv.Line((0, 0, 0), 1.25 * mirror), color="#595959", line_width=2)
        pl.add_text(f"{title}\nmax f = {peak:.3g} /sr", font_size=11, color="black",
                    position="upper_edge", font_file=font_file())  # the figures' typeface
        pl.view_vector((0.3, -1.0, 0.75), viewup=(0, 0, 1))  # from above the front: Ward's width across the plane shows
        pl.reset_camera(bounds=(-1.1, 1.1, -1.1, 1.1, -0.3, 1.0))  # lobes up under their titles
        pl.camera.zoom(cfg["render_3d"]["zoom"])
        t_deg, p_deg = np.degrees(theta.flat[at]), np.degrees(phi.flat[at])
        found[key] = {"max": f"{peak:.3g}", "plane": f"{in_plane:.3g}",
                      "at": f"theta_o = {t_deg:.1f} deg, phi_o = {p_deg:.0f} deg",
                      "drawn_to": f"{np.degrees(theta[last - 1, 0]):.1f}"}
        log.info("%s: max f %.6g sr^-1 at (theta_o, phi_o) = (%.2f, %.1f) deg; in the plane %.6g; "
                 "drawn to %.2f deg", key, peak, t_deg, p_deg, in_plane, np.degrees(theta[last - 1, 0]))
    write_caption_values(snakemake.output.values, {
        "diffuse_max": found["diffuse"]["max"], "diffuse_max_plane": found["diffuse"]["plane"],
        "phong_max": found["phong"]["max"], "phong_max_plane": found["phong"]["plane"],
        "blinn_phong_max": found["blinn_phong"]["max"], "blinn_phong_max_plane": found["blinn_phong"]["plane"],
        "cook_torrance_max": found["cook_torrance"]["max"],
        "cook_torrance_max_plane": found["cook_torrance"]["plane"],
        "cook_torrance_max_at": found["cook_torrance"]["at"],
        "ward_max": found["ward"]["max"], "ward_max_plane": found["ward"]["plane"],
        "ward_drawn_to": found["ward"]["drawn_to"],
        "lunar_max": found["lunar"]["max"], "lunar_max_plane": found["lunar"]["plane"],
        "lunar_max_at": found["lunar"]["at"],
    })
    save_plotter(pl, snakemake.output.png, margin=cfg["render_3d"]["margin"])
