"""Lecture (Russin, Module 3B), "Shadowing and masking effects": a seeded random surface profile
(Gaussian heights, Gaussian autocorrelation) lit from the left and seen from the right, with the
light rays traced to the facet they reach and on towards the viewer. The masking fraction of the
whole profile (projected-area weighted, the G1 of microfacet theory) is compared with Smith's G1
for the profile's Gaussian slopes: in a 2-D profile with rms slope sigma, Smith's G1 is the
Beckmann G1 of Walter et al. with m = sqrt(2) sigma (both have a = cot(theta) / (sqrt(2) sigma))."""

import numpy as np
import pandas as pd
from matplotlib.collections import LineCollection

from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.papers.polar import plane_of_incidence_vectors
from reflectance.papers.profile import blocking_point, gaussian_profile, masking_G1, trace_window, visible_fraction_by_slope
from reflectance.papers.vgroove_derivation import vgroove_case
from reflectance.papers.vgroove_plot import COLOURS, draw_groove
from reflectance.scripting import script_log
from reflectance.optics.shadowing import G1_Smith_Beckmann_Walter2007
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    h, p = gaussian_profile(cfg["n_samples"], cfg["correlation_length"], cfg["rms_slope"], cfg["seed"])
    sigma = np.sqrt(np.mean(p * p))
    m = np.sqrt(2.0) * sigma  # Smith's a = cot / (sqrt 2 sigma) = Walter's 1 / (m tan)
    ti, to = np.radians(cfg["incidence_deg"]), np.radians(cfg["view_deg"])
    angles = np.radians(np.arange(0.0, 89.0 + 1e-9, cfg["angle_step_deg"]))
    sim = np.array([masking_G1(h, p, a) for a in angles])
    smith = G1_Smith_Beckmann_Walter2007(np.cos(angles), m)
    # The slide's own G for the light at theta_i and the viewer at each angle on the mirror side:
    # Masking G_m = 2(N.H)(N.V)/(V.H), shadowing G_s = 2(N.H)(N.L)/(V.H), G = min{1, G_s, G_m}
    L, V, _ = plane_of_incidence_vectors(ti, angles)
    H = (L + V) / np.linalg.norm(L + V, axis=-1, keepdims=True)
    NH, NV, NL, VH = H[:, 2], V[:, 2], L[2], np.einsum("ij,ij->i", V, H)
    G_slide = np.minimum(1.0, np.minimum(2 * NH * NL / VH, 2 * NH * NV / VH))
    G2_smith = G1_Smith_Beckmann_Walter2007(np.cos(ti), m) * smith  # Smith, uncorrelated L and V
    # ... and the same G found by tracing rays through Blinn's V-groove (Blinn 1977 Fig. 1, the
    # slide's source: "Blinn described dependence of this ratio on L, V, H"), light from the left
    vg = cfg["vgroove"]
    light = {"theta_deg": cfg["incidence_deg"], "phi_deg": 180.0}
    G_traced = np.array([vgroove_case(light, {"theta_deg": float(np.degrees(a)), "phi_deg": 0.0},
                                      n_rays=vg["n_rays"], n_keep=1)[1]["G_simulated"]
                         for a in angles])
    G2_profile = masking_G1(h, p, -ti)[0] * sim[:, 0]  # the profile's G1(L) G1(V), simulated
    pd.DataFrame({"angle_deg": np.degrees(angles), "G1_simulated": sim[:, 0], "G1_Smith": smith,
                  "visible_projected_over_n_cos": sim[:, 1], "G_slide_light_at_incidence": G_slide,
                  "G1L_G1V_Smith_light_at_incidence": G2_smith,
                  "G_vgroove_traced_light_at_incidence": G_traced,
                  "G1L_G1V_profile_light_at_incidence": G2_profile}).pipe(
        write_csv, snakemake.output.g1, float_format="%.6g")

    # Shadowing (light at -theta_i) and masking (view at +theta_o), overall and by facet slope
    nb, edges = cfg["slope_bins"], np.linspace(-3 * sigma, 3 * sigma, cfg["slope_bins"] + 1)
    by, g1 = {"slope_lo": edges[:-1], "slope_hi": edges[1:]}, {}
    for name, a in (("light", -ti), ("view", to)):
        fraction, by["count"] = visible_fraction_by_slope(h, p, a, edges)
        by[f"visible_{name}"] = fraction
        g1[name] = (masking_G1(h, p, a)[0], G1_Smith_Beckmann_Walter2007(np.cos(a), m))
        by[f"smith_{name}"] = np.full(nb, g1[name][1])
        log.info("%s: G1 simulated %.5f, Smith %.5f", name, *g1[name])
    pd.DataFrame(by).pipe(write_csv, snakemake.output.by_slope, float_format="%.6g")

    # (a) a window of the profile: light rays to the first facet they meet, and on to the viewer
    w0, w1 = cfg["window"]
    try:
        rays = trace_window(h, p, cfg["window"], -ti, to, cfg["n_rays"])
    except ValueError as err:
        raise ValueError(f"figures.lecture.shadowing_masking: {err}") from None
    xs, hs, (hit_x, hit_h), (mask_x, mask_h) = rays.x, rays.h, rays.hit.T, rays.masked_at.T
    hit_segment = np.floor(hit_x).astype(int) - int(xs[0])
    log.info("rays traced to the viewer agree with visible_fraction for %d of %d rays",
             np.sum(rays.escaped == (rays.seen[hit_segment] > 0.5)), hit_x.size)

    # drawn at the print width, so its text prints at the figures' sizes: the slide's two sketches
    # (Shadowing, Masking) on Blinn's V-groove, its G against the groove traced, then the effects
    # on a random surface
    fig = new_figure(PRINT_WIDTH_IN, 7.4)
    grid = fig.add_gridspec(2, 3, height_ratios=[1, 1.0], hspace=0.42, wspace=0.32, top=0.88,
                            bottom=0.13, left=0.07, right=0.99)
    other = {"theta_deg": vg["other_deg"], "phi_deg": 0.0}
    sketches = (("Shadowing", light, other, "c"),
                ("Masking", {**other, "phi_deg": 180.0}, {"theta_deg": cfg["view_deg"], "phi_deg": 0.0}, "b"))
    for k, (name, L_dir, E_dir, case) in enumerate(sketches):
        groove, row = vgroove_case(L_dir, E_dir, n_rays=vg["n_rays"], n_keep=vg["n_drawn_rays"])
        if row["case"] != case:
            raise ValueError(f"figures.lecture.shadowing_masking.vgroove.other_deg: "
                             f"{vg['other_deg']:g} degrees gives Blinn's case {row['case']!r} in the "
                             f"{name.lower()} sketch, not {case!r}")
        ax = fig.add_subplot(grid[0, k])
        draw_groove(ax, groove)
        lost = row["G_shadowing_simulated"] if case == "c" else row["G_masking_simulated"]
        ax.set_title(f"({'ab'[k]}) {name}: light {L_dir['theta_deg']:g}\u00b0, view "
                     f"{E_dir['theta_deg']:g}\u00b0\nG traced {row['G_simulated']:.3f}, "
                     f"min{{1, G$_s$, G$_m$}} {row['G_closed']:.3f}", fontsize=TEXT_SIZE["annotation"],
                     linespacing=1.3)
        log.info("%s sketch: case %s, G traced %.6f (%s %.6f), closed %.6f", name, row["case"],
                 row["G_simulated"], name.lower(), lost, row["G_closed"])
    handles = [fig.axes[0].plot([], [], color=COLOURS[key], lw=w)[0] for key, w in
               (("light", 1), ("eye", 1), ("masked", 1), ("other", 1), ("shadowed", 4),
                ("masked", 4))]
    fig.legend(handles, ["incident ray", "reflected ray, seen", "reflected ray, masked",
                         "ray landing on the other facet", "facet part shadowed",
                         "facet part masked"],
               loc="upper left", bbox_to_anchor=(0.03, 0.59), ncol=2, frameon=False,
               fontsize=TEXT_SIZE["annotation"], handlelength=1.6, columnspacing=1.0)
    ax = fig.add_subplot(grid[0, 2])
    step = max(1, int(round(vg["step_deg"] / cfg["angle_step_deg"])))
    ax.plot(np.degrees(angles), G_slide, color="#d55e00", label="slide: min{1, G$_s$, G$_m$}")
    ax.plot(np.degrees(angles)[::step], G_traced[::step], "o", ms=3.5, mfc="none", color="#d55e00",
            label="V-groove, traced")
    ax.plot(np.degrees(angles), G2_smith, color="k", lw=1.2, ls="--",
            label="(d): Smith G1(L) G1(V),\nnot in the lecture")
    ax.plot(np.degrees(angles)[::step], G2_profile[::step], ".", ms=4, color="k",
            label="(d), simulated")
    ax.set(xlabel="view \u03b8o, mirror side (\u00b0)", ylabel="G", ylim=(0, 1.05),
           xticks=[0, 30, 60, 90])
    ax.set_title(f"(c) G, light at \u03b8i = {cfg['incidence_deg']:g}\u00b0",
                 fontsize=TEXT_SIZE["annotation"])
    ax.legend(loc="lower left", fontsize=TEXT_SIZE["annotation"], frameon=False, labelspacing=0.4,
              handlelength=1.5, borderaxespad=0.2)
    ax.grid(True)

    ax = fig.add_subplot(grid[1, :])
    top, keep = hs.max() + 0.15 * (w1 - w0), (xs[:-1] >= w0) & (xs[1:] <= w1)
    # the facets by what happens to them: cast shadow (facing the light, blocked) apart from
    # facing away from the light; masked (lit, facing the viewer, blocked) apart from facing away
    faces_light, faces_viewer = rays.slope > -1 / np.tan(ti), rays.slope < 1 / np.tan(to)
    classes = {"lit and seen": "#e69f00", "lit, masked by another facet": "#d62728",
               "lit, facing away from the viewer": "#56b4e9", "in a cast shadow": "#2a2a2a",
               "facing away from the light": "#a0a0a0"}
    kind = np.where(~faces_light, "facing away from the light", np.where(
        rays.lit < 0.5, "in a cast shadow", np.where(~faces_viewer, "lit, facing away from the viewer", np.where(
            rays.seen > 0.5, "lit and seen", "lit, masked by another facet"))))
    seg = np.stack([np.stack([xs[:-1], hs[:-1]], -1), np.stack([xs[1:], hs[1:]], -1)], 1)
    ax.add_collection(LineCollection(seg[keep], colors=[classes[k] for k in kind[keep]], linewidths=3.5, zorder=3))
    for x, y, ok in zip(hit_x, hit_h, rays.escaped):
        ax.plot([x - (top - y) * np.tan(ti), x], [top, y], color="#f0c040", lw=0.8)
        if ok:
            ax.plot([x, x + (top - y) * np.tan(to)], [y, top], color="#e69f00", lw=0.8, ls="--")

    # one example per run of cast shadow and per run of masked facets in the window: from the
    # run's middle towards the light (dotted) or the viewer (dashed) to the facet that blocks it (x)
    to_light, to_viewer = (-np.sin(ti), np.cos(ti)), (np.sin(to), np.cos(to))
    for name, direction, c, ls in (("in a cast shadow", to_light, "#2a2a2a", ":"),
                                   ("lit, masked by another facet", to_viewer, "#d62728", "--")):
        run = np.r_[False, keep & (kind == name), False].astype(int)
        for a, b in zip(np.nonzero(np.diff(run) == 1)[0], np.nonzero(np.diff(run) == -1)[0]):
            mid = (xs[a] + xs[b]) / 2
            hit = blocking_point(xs, hs, mid, np.interp(mid, xs, hs) + 1e-6, direction)
            if hit is None or not w0 <= hit[0] <= w1:
                continue
            ax.plot([mid, hit[0]], [np.interp(mid, xs, hs), hit[1]], color=c, lw=1.4, ls=ls, zorder=5)
            ax.plot(*hit, "x", color=c, ms=7, mew=2, zorder=6)
    for label, c in classes.items():
        ax.plot([], [], color=c, lw=3.5, label=label)
    ax.set(xlim=(w0, w1), ylim=(hs.min() - 0.05 * (w1 - w0), top), aspect="equal",
           xlabel="x (samples)", ylabel="height")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=3, frameon=False,
              fontsize=TEXT_SIZE["annotation"])
    ax.set_title(f"(d) a random surface (Gaussian heights, seed {cfg['seed']}, rms slope "
                 f"{sigma:.3g}, correlation length {cfg['correlation_length']:g}): light from the left "
                 f"at \u03b8i = {cfg['incidence_deg']:g}\u00b0 (solid),\nviewer on the right at "
                 f"\u03b8o = {cfg['view_deg']:g}\u00b0 (dashed); x: the facet that blocks a shadowed "
                 "(dotted) or a masked (red dashed) point", fontsize=TEXT_SIZE["annotation"],
                 linespacing=1.3)
    fig.suptitle("Lecture (Russin, Module 3B), \u201cShadowing and masking effects\u201d: "
                 "the geometrical attenuation G\nof Blinn's V-groove, as the slide gives it, "
                 "and on a random surface", y=0.995, va="top", linespacing=1.3)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("visible projected / (n cos) in [%.12f, %.12f]", sim[:, 1].min(), sim[:, 1].max())
