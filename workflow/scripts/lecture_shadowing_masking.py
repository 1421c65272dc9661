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
    pd.DataFrame({"angle_deg": np.degrees(angles), "G1_simulated": sim[:, 0], "G1_Smith": smith,
                  "visible_projected_over_n_cos": sim[:, 1], "G_slide_light_at_incidence": G_slide,
                  "G1L_G1V_Smith_light_at_incidence": G2_smith}).pipe(
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

    # drawn at the print width, so its text prints at the figures' sizes
    fig = new_figure(PRINT_WIDTH_IN, 7.0)
    grid = fig.add_gridspec(2, 3, height_ratios=[1.15, 1], hspace=0.62, wspace=0.42, top=0.87,
                            bottom=0.2, left=0.08, right=0.99)
    ax = fig.add_subplot(grid[0, :])
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
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=3, frameon=False)
    ax.set_title(f"(a) light from the left at \u03b8i = {cfg['incidence_deg']:g}\u00b0 (solid), viewer on the "
                 f"right at \u03b8o = {cfg['view_deg']:g}\u00b0 (dashed)\nx: the facet that blocks a shadowed "
                 "(dotted) or a masked (red dashed) point", fontsize=TEXT_SIZE["symbol"], linespacing=1.3)
    ax = fig.add_subplot(grid[1, 0])
    ax.plot(np.degrees(angles), smith, color="k", lw=1.5, label=f"Smith G1, m = {m:.3g}\n(not in the lecture)")
    ax.plot(np.degrees(angles), sim[:, 0], "o", ms=2.5, color=OKABE_ITO[0], label="simulated profile")
    ax.set(xlabel="\u03b8 from the normal (\u00b0)", ylabel="G1", ylim=(0, 1.02), xticks=[0, 30, 60, 90],
           title="(b) G1 of the profile")
    ax.legend(loc="upper left", bbox_to_anchor=(-0.3, -0.3))
    ax = fig.add_subplot(grid[1, 1])
    for name, c, lab in (("view", "#d62728", "masking, \u03b8o"), ("light", "#e69f00", "shadowing, \u03b8i")):
        ax.plot((edges[1:] + edges[:-1]) / (2 * sigma), by[f"visible_{name}"], "o-", ms=3, color=c,
                label=f"{lab}: simulated")
        ax.axhline(g1[name][1], color=c, ls="--", lw=1, label=f"{lab}: Smith")
    ax.set(xlabel="facet slope / rms slope", ylabel="visible fraction", ylim=(0, 1.02),
           title="(c) visibility by slope")
    ax.legend(loc="upper left", bbox_to_anchor=(-0.3, -0.3))
    ax = fig.add_subplot(grid[1, 2])
    ax.plot(np.degrees(angles), G_slide, color="#d55e00",
            label="slide: min{1, G$_s$, G$_m$}\n(V-cavity)")
    ax.plot(np.degrees(angles), G2_smith, color="k", lw=1.5, label="Smith G1(L) G1(V)\n(not in the lecture)")
    ax.set(xlabel="view \u03b8o, mirror side (\u00b0)", ylabel="G", ylim=(0, 1.02), xticks=[0, 30, 60, 90],
           title=f"(d) G, light at \u03b8i = {cfg['incidence_deg']:g}\u00b0")
    ax.legend(loc="upper left", bbox_to_anchor=(-0.3, -0.3), labelspacing=0.9)
    ax.grid(True)
    fig.suptitle("Lecture (Russin, Module 3B), \u201cShadowing and masking effects\u201d,\non a simulated "
                 f"Gaussian surface profile (seed {cfg['seed']})", y=0.995, va="top", linespacing=1.3)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("visible projected / (n cos) in [%.12f, %.12f]", sim[:, 1].min(), sim[:, 1].max())
