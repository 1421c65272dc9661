"""Lecture (Russin, Module 3B), "BRDF" slide: the sample BRDFs of brdf_lobes_2d as 3-D lobe surfaces
(pyvista, off-screen), in the 2-D figure's grid of two rows of three. Each surface point is
V f(L, V) / top over the outgoing hemisphere: the radius along every outgoing direction V is the
BRDF itself (not f cos theta_o), on the 2-D figure's one scale for every panel, top = ``scale_margin`` times the
largest of the lobes' maxima up to ``scale_to_deg`` from N (``lobe_peak``); the grey disc's rim is
that scale, and the colour is f in sr^-1 with its key. A lobe that passes the rim nearer the horizon
(Ward's 1/sqrt(N.L N.V)) ends where it would. Ward's panel adds the lobe of its light turned by
``ward_turned_deg`` about N (across the grain). The job checks each maximum against the plane of
incidence at the 2-D figure's steps (``polar_step_deg``) and writes both to the caption's values."""

import numpy as np
import pyvista as pv
from matplotlib.colors import ListedColormap
from matplotlib import colormaps

from reflectance.io.captions import write_caption_values
from reflectance.io.figures import font_file, off_screen_plotter, save_plotter
from reflectance.optics.brdf import brdf
from reflectance.papers.polar import (direction_from_angles, lobe_peak, plane_angles,
                                      plane_of_incidence_vectors, turned_about_normal)
from reflectance.scripting import script_log

# config key -> (reflectance.optics.brdf method, panel title): the 2-D figure's models
MODELS = {
    "diffuse": ("Lambert", "Diffuse (Lambert)"),
    "phong": ("Phong1975", "Phong"),
    "blinn_phong": ("BlinnPhong_AkenineMoller2008", "normalised Blinn-Phong"),
    "cook_torrance": ("CookTorrance1982", "Cook-Torrance, shiny plastic"),
    "ward": ("Ward1992", "Ward, anisotropic"),
    "lunar": ("Hapke1981", "lunar (Hapke, opposition effect)"),
}
COLUMNS = 3
KEY_WEIGHT = 0.3  # the colour key's column, beside the panels, against a panel's 1
WIDTHS = ("phong", "blinn_phong")  # their titles print their lobes' half-maximum widths
ARROW = (1.15, 0.45)  # a light's arrow, from and to these radii (rim = 1): short of the lobes along L
RAY = 1.25  # the length of the mirror rays (N's is the rim's, 1); labels just beyond


def half_max_width(f, angles):
    """The angle (degrees) over which f stays at or above half its largest value."""
    return float(np.degrees(np.ptp(angles[f >= 0.5 * f.max()])))


def label(pl, point, text, colour, size=22):
    """``text`` at the 3-D ``point``, in the figures' typeface, never hidden by a lobe."""
    pl.add_point_labels([point], [text], font_size=size, text_color=colour, show_points=False,
                        shape_opacity=0.0, font_file=font_file(), always_visible=True)


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    limit = cfg["scale_to_deg"]
    theta_i = np.radians(cfg["incidence_deg"])
    L, _, N = plane_of_incidence_vectors(theta_i, theta_i)  # light on the -x side
    n_theta, n_phi = cfg["hemisphere_samples"]
    theta, phi = np.meshgrid(np.linspace(0.0, np.pi / 2, n_theta), np.linspace(0.0, 2 * np.pi, n_phi),
                             indexing="ij")
    V = direction_from_angles(theta, phi)
    # f in the plane of incidence at the 2-D figure's steps (as its table, computed here so that
    # this figure reads only its own keys)
    theta_plane = plane_angles(cfg["polar_step_deg"])
    L_plane, V_plane, _ = plane_of_incidence_vectors(theta_i, theta_plane)

    turn = np.radians(cfg["ward_turned_deg"])
    L_turned = turned_about_normal(L, -turn)  # Ward's second light, across the grain, behind (+y)
    f_all = {key: brdf(L, V, N, method, **cfg["models"][key]) for key, (method, _) in MODELS.items()}
    f_turned = brdf(L_turned, V, N, "Ward1992", **cfg["models"]["ward"])
    peaks = {key: lobe_peak(f, theta, limit) for key, f in f_all.items()}
    turned_peak, _ = lobe_peak(f_turned, theta, limit)
    # the 2-D figure's one scale (the disc's rim): over every lobe drawn, the turned one too
    top = cfg["scale_margin"] * max([peak for peak, _ in peaks.values()] + [turned_peak])
    # every lobe stops at scale_to_deg from N, where its printed max is taken (Ward's
    # 1/sqrt(N.L N.V) grows without bound towards the horizon)
    last = int(np.count_nonzero(theta[:, 0] <= np.radians(limit) * (1 + 1e-12)))
    # half-maximum widths on two great circles through the mirror direction R: in the plane of
    # incidence, and across it (towards +y); up to scale_to_deg from N, at the 2-D figure's steps
    R = L * np.array([-1.0, -1.0, 1.0])
    circles = {"in": plane_of_incidence_vectors(theta_i, theta_i + theta_plane)[1],
               "across": np.cos(theta_plane)[:, None] * R + np.sin(theta_plane)[:, None] * [0.0, 1.0, 0.0]}
    widths = {}
    for way, W in circles.items():
        keep = W[:, 2] >= np.cos(np.radians(limit)) - 1e-12
        for key in WIDTHS:
            f = brdf(L, W[keep], N, MODELS[key][0], **cfg["models"][key])
            widths[key, way] = half_max_width(f, theta_plane[keep])
    # viridis from its floor up: the weakest lobe (lunar) stays light enough to read its shape
    floor = cfg["render_3d"]["colour_floor"]
    cmap = ListedColormap(colormaps["viridis"](np.linspace(floor, 1.0, 256)), name="viridis_floor")

    rows = -(-len(MODELS) // COLUMNS)
    pl = off_screen_plotter(*cfg["render_3d"]["size"], shape=(rows, COLUMNS + 1),
                            col_weights=[1] * COLUMNS + [KEY_WEIGHT], groups=[(np.s_[:], COLUMNS)])
    pl.set_background("white")
    found = {}  # per model: its maximum over the hemisphere and in the 2-D table, where, how far drawn
    for i, (key, (method, title)) in enumerate(MODELS.items()):
        peak, at = peaks[key]
        in_plane, _ = lobe_peak(brdf(L_plane, V_plane, N, method, **cfg["models"][key]), theta_plane, limit)
        pl.subplot(i // COLUMNS, i % COLUMNS)
        lights = [(L, f_all[key], "")] + ([(L_turned, f_turned, "'")] if key == "ward" else [])
        for light, f, prime in lights:
            r = f / top
            lobe = pv.StructuredGrid(*(r[:last] * V[:last, :, j] for j in range(3)))
            lobe["f (1/sr)"] = f[:last].ravel(order="F")
            actor = pl.add_mesh(lobe, scalars="f (1/sr)", cmap=cmap, clim=(0, top),
                                smooth_shading=True, show_scalar_bar=False,
                                ambient=cfg["render_3d"]["ambient"])  # lit from the camera's side too
            # the light's arrow stops short of the lobes (the lunar lobe's spike along L shows);
            # its mirror direction R (its lobe's axis) a grey ray
            pl.add_mesh(pv.Arrow(start=ARROW[0] * light, direction=-light, scale=ARROW[0] - ARROW[1],
                                 tip_length=0.15, tip_radius=0.04, shaft_radius=0.014), color="#d98c00")
            mirrored = light * np.array([-1.0, -1.0, 1.0])
            pl.add_mesh(pv.Line((0, 0, 0), RAY * mirrored), color="#595959", line_width=2)
            label(pl, (ARROW[0] + 0.08) * light, "L" + prime, "#8a5a00")
            label(pl, (RAY + 0.08) * mirrored, "R" + prime, "#404040")
            drawn_to = np.degrees(theta[last - 1, 0])
        pl.add_mesh(pv.Line((0, 0, 0), (0, 0, 1.0)), color="black", line_width=2)  # the normal
        label(pl, (0, 0, 1.08), "N", "black")
        pl.add_mesh(pv.Disc(inner=0.0, outer=1.0, normal=(0, 0, 1), c_res=96), color="#d9d9d9",
                    opacity=0.5)
        if key == "ward":  # the turn about N, on the surface: the lights' azimuths and the arc between
            feet = [np.array([*light[:2], 0.0]) / np.hypot(*light[:2]) for light in (L, L_turned)]
            for foot in feet:
                pl.add_mesh(pv.Line((0, 0, 0), foot), color="#d98c00", line_width=2)
            pl.add_mesh(pv.CircularArc(pointa=0.6 * feet[0], pointb=0.6 * feet[1], center=(0, 0, 0)),
                        color="#d98c00", line_width=2)
            middle = 0.68 * (feet[0] + feet[1]) / np.linalg.norm(feet[0] + feet[1])
            label(pl, middle, f"{cfg['ward_turned_deg']:g} deg", "#8a5a00", size=18)
            text = (f"{title}: max f = {peak:.3g} /sr\n"
                    f"L' = L turned {cfg['ward_turned_deg']:g} deg about N: {turned_peak:.3g} /sr")
        else:
            text = f"{title}\nmax f = {peak:.3g} /sr"
        if key in WIDTHS:  # Phong's lobe is round about R, Blinn-Phong's (through H) is not
            text += (f"\nhalf-max width {widths[key, 'in']:.0f} deg in plane, "
                     f"{widths[key, 'across']:.0f} across")
        pl.add_text(text, font_size=11, color="black", position="upper_edge",
                    font_file=font_file())  # the figures' typeface
        pl.view_vector(cfg["render_3d"]["view"], viewup=(0, 0, 1))  # one camera for every panel
        pl.reset_camera(bounds=(-1.1, 1.1, -1.1, 1.1, -0.3, 1.3))  # lobes up under their titles
        pl.camera.zoom(cfg["render_3d"]["zoom"])
        t_deg, p_deg = np.degrees(theta.flat[at]), np.degrees(phi.flat[at])
        found[key] = {"max": f"{peak:.3g}", "plane": f"{in_plane:.3g}",
                      "at": f"theta_o = {t_deg:.1f} deg, phi_o = {p_deg:.0f} deg",
                      "drawn_to": f"{drawn_to:.1f}"}
        log.info("%s: max f %.6g sr^-1 at (theta_o, phi_o) = (%.2f, %.1f) deg; in the plane %.6g; "
                 "drawn to %.2f deg", key, peak, t_deg, p_deg, in_plane, drawn_to)
    log.info("half-max widths (deg, in the plane / across): %s", widths)
    pl.subplot(0, COLUMNS)  # the key, outside the panels: f in sr^-1, colour and radius of every lobe
    pl.add_scalar_bar(title=f"f (1/sr)\n\ndisc rim\n= {top:.2g} /sr\n", mapper=actor.mapper, n_labels=4,
                      fmt="%.1f", vertical=True, position_x=0.12, position_y=0.2, width=0.3,
                      height=0.6, color="black", title_font_size=18, label_font_size=16,
                      font_family="arial")
    write_caption_values(snakemake.output.values, {
        "diffuse_max": found["diffuse"]["max"], "diffuse_max_plane": found["diffuse"]["plane"],
        "phong_max": found["phong"]["max"], "phong_max_plane": found["phong"]["plane"],
        "blinn_phong_max": found["blinn_phong"]["max"], "blinn_phong_max_plane": found["blinn_phong"]["plane"],
        "cook_torrance_max": found["cook_torrance"]["max"],
        "cook_torrance_max_plane": found["cook_torrance"]["plane"],
        "cook_torrance_max_at": found["cook_torrance"]["at"],
        "ward_max": found["ward"]["max"], "ward_max_plane": found["ward"]["plane"],
        "ward_drawn_to": found["ward"]["drawn_to"], "ward_turned_max": f"{turned_peak:.3g}",
        "lunar_max": found["lunar"]["max"], "lunar_max_plane": found["lunar"]["plane"],
        "lunar_max_at": found["lunar"]["at"], "scale": f"{top:.2g}",
        "phong_width_in": f"{widths['phong', 'in']:.0f}", "phong_width_across": f"{widths['phong', 'across']:.0f}",
        "blinn_phong_width_in": f"{widths['blinn_phong', 'in']:.0f}",
        "blinn_phong_width_across": f"{widths['blinn_phong', 'across']:.0f}",
    })
    save_plotter(pl, snakemake.output.png, margin=cfg["render_3d"]["margin"])
