"""Lecture (Russin, Module 3B), "Shadowing and masking effects": a seeded random surface profile
(Gaussian heights, Gaussian autocorrelation) lit from the left and seen from the right, with the
light rays traced to the facet they reach and on towards the viewer. The masking fraction of the
whole profile (projected-area weighted, the G1 of microfacet theory) is compared with Smith's G1
for the profile's Gaussian slopes: in a 2-D profile with rms slope sigma, Smith's G1 is the
Beckmann G1 of Walter et al. with m = sqrt(2) sigma (both have a = cot(theta) / (sqrt(2) sigma))."""

import numpy as np
import pandas as pd
from matplotlib.collections import LineCollection

from reflectance.plotting import new_figure, savefig
from reflectance.scripting import script_log
from reflectance.shadowing import G1_Smith_Beckmann_Walter2007


def gaussian_profile(n, correlation_length, rms_slope, seed):
    """Periodic heights at unit spacing, autocorrelation ~ exp(-(dx/l)^2), scaled so that the rms
    of the segment slopes is ``rms_slope``; returns (heights, slopes of segments [k, k+1])."""
    f = np.fft.rfftfreq(n)  # the spectrum of exp(-(dx/l)^2) is ~ exp(-(pi f l)^2): filter by its root
    white = np.fft.rfft(np.random.default_rng(seed).standard_normal(n))
    h = np.fft.irfft(white * np.exp(-0.5 * (np.pi * f * correlation_length) ** 2), n)
    p = np.roll(h, -1) - h
    scale = rms_slope / np.sqrt(np.mean(p * p))
    return h * scale, p * scale


def visible_fraction(h, theta):
    """Fraction of each segment [k, k+1] of the periodic polyline ``h`` seen from direction
    (sin theta, cos theta), theta > 0 towards +x; 0 for segments facing away. A point is hidden iff
    a later node has a larger g = h - x cot(theta); g is linear on segments, so it suffices to
    compare with the running maximum of g over the nodes ahead (two periods)."""
    if theta < 0:  # mirror x -> -x: node i <- node -i, segment k <- segment n - 1 - k
        return visible_fraction(np.roll(h[::-1], 1), -theta)[::-1]
    n, cot = h.size, np.cos(theta) / max(np.sin(theta), 1e-300)
    if n * cot <= np.ptp(h):
        raise ValueError(f"theta = {np.degrees(theta):.3g} deg is too grazing for a profile of "
                         f"{n} samples (n_samples x cot(theta) must exceed the height range)")
    x = np.arange(2 * n + 1)
    g = h[x % n] - x * cot
    ahead = np.maximum.accumulate(g[::-1])[::-1][1:n + 1]  # max of g over nodes k+1 .. 2n
    g0, drop = g[:n], g[:n] - g[1:n + 1]  # drop > 0: the segment faces the direction
    return np.where(drop > 0, np.clip((g0 - ahead) / np.where(drop > 0, drop, 1.0), 0, 1), 0.0)


def masking_G1(h, p, theta):
    """Visible / total projected length of the facets facing direction theta, and the visible
    projected length over n cos(theta) (1 for any periodic profile: every ray hits it once)."""
    proj = np.maximum(np.cos(theta) - p * np.sin(theta), 0.0)
    seen = np.sum(visible_fraction(h, theta) * proj)
    return seen / np.sum(proj), seen / (h.size * np.cos(theta))


def crossings(xs, hs, s, s0):
    """(x, h) where the polyline (xs, hs) crosses each ray s = s0 (s is constant along the rays)."""
    a, b = s[:-1], s[1:]
    t = (s0[:, None] - a) / np.where(b != a, b - a, 1.0)
    ok = (b != a) & (t >= 0) & (t < 1)
    return np.where(ok, xs[:-1] + t, np.nan), np.where(ok, hs[:-1] + t * (hs[1:] - hs[:-1]), np.nan)


def blocker(xs, hs, x0, h0, tan, side):
    """First crossing beyond (x0, h0) of the ray rising towards ``side`` (+1 right, -1 left) at
    angle atan(tan) from the normal; NaN where the ray escapes."""
    bx, bh = crossings(xs, hs, xs - side * hs * tan, x0 - side * h0 * tan)
    bx = np.where(side * (bx - x0[:, None]) > 1e-9, bx, np.nan)
    j = np.argmin(np.nan_to_num(side * bx, nan=np.inf), axis=1)
    return bx[np.arange(x0.size), j], bh[np.arange(x0.size), j]


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    h, p = gaussian_profile(cfg["n_samples"], cfg["correlation_length"], cfg["rms_slope"], cfg["seed"])
    sigma = np.sqrt(np.mean(p * p))
    m = np.sqrt(2.0) * sigma  # Smith's a = cot / (sqrt 2 sigma) = Walter's 1 / (m tan)
    ti, to = np.radians(cfg["incidence_deg"]), np.radians(cfg["view_deg"])
    angles = np.radians(np.arange(0.0, 89.0 + 1e-9, cfg["angle_step_deg"]))
    sim = np.array([masking_G1(h, p, a) for a in angles])
    smith = G1_Smith_Beckmann_Walter2007(np.cos(angles), m)
    pd.DataFrame({"angle_deg": np.degrees(angles), "G1_simulated": sim[:, 0], "G1_Smith": smith,
                  "visible_projected_over_n_cos": sim[:, 1]}).to_csv(
        snakemake.output.g1, index=False, float_format="%.6g", lineterminator="\n")

    # Shadowing (light at -theta_i) and masking (view at +theta_o), overall and by facet slope
    nb, edges = cfg["slope_bins"], np.linspace(-3 * sigma, 3 * sigma, cfg["slope_bins"] + 1)
    b = np.digitize(p, edges) - 1
    inside = (b >= 0) & (b < nb)
    by = {"slope_lo": edges[:-1], "slope_hi": edges[1:], "count": np.bincount(b[inside], minlength=nb)}
    vis, g1 = {}, {}
    for name, a in (("light", -ti), ("view", to)):
        proj, vis[name] = np.maximum(np.cos(a) - p * np.sin(a), 0.0), visible_fraction(h, a)
        w = inside & (proj > 0)
        total = np.bincount(b[w], proj[w], nb)
        by[f"visible_{name}"] = np.bincount(b[w], (vis[name] * proj)[w], nb) / np.where(total > 0, total, np.nan)
        g1[name] = (np.sum(vis[name] * proj) / np.sum(proj), G1_Smith_Beckmann_Walter2007(np.cos(a), m))
        by[f"smith_{name}"] = np.full(nb, g1[name][1])
        log.info("%s: G1 simulated %.5f, Smith %.5f", name, *g1[name])
    pd.DataFrame(by).to_csv(snakemake.output.by_slope, index=False, float_format="%.6g",
                            lineterminator="\n")

    # (a) a window of the profile: light rays to the first facet they meet, and on to the viewer
    w0, w1 = cfg["window"]
    if not 0 <= w0 < w1 <= h.size:
        raise ValueError(f"figures.lecture.shadowing_masking.window: need 0 <= first < last <= "
                         f"n_samples ({h.size}), got {cfg['window']}")
    margin = int(np.ceil(np.ptp(h) * max(np.tan(ti), np.tan(to)))) + 2
    idx = np.arange(w0 - margin, w1 + margin + 1)
    xs, hs, ps = idx.astype(float), h[idx % h.size], p[idx[:-1] % h.size]
    lit, seen = vis["light"][idx[:-1] % h.size], vis["view"][idx[:-1] % h.size]
    u0 = w0 + (np.arange(cfg["n_rays"]) + 0.5) * (w1 - w0) / cfg["n_rays"]
    hx, hh = crossings(xs, hs, xs + hs * np.tan(ti), u0)  # light rays: x + h tan(theta_i) constant
    k = np.nanargmax(hh, axis=1)  # coming down from above, the highest crossing is met first
    hit_x, hit_h = hx[np.arange(u0.size), k], hh[np.arange(u0.size), k]
    mask_x, mask_h = blocker(xs, hs, hit_x, hit_h, np.tan(to), +1)
    faces = ps[np.floor(hit_x).astype(int) - idx[0]] < 1 / np.tan(to)
    escaped = faces & np.isnan(mask_x)
    log.info("rays traced to the viewer agree with visible_fraction for %d of %d rays",
             np.sum(escaped == (seen[np.floor(hit_x).astype(int) - idx[0]] > 0.5)), u0.size)
    j = np.floor(u0).astype(int) - idx[0]
    dark = (lit[j] < 0.5) & (ps[j] > -1 / np.tan(ti))  # shadowed facets that face the light
    sx, sh = u0[dark], np.interp(u0[dark], xs, hs)
    shadow_x, shadow_h = blocker(xs, hs, sx, sh, np.tan(ti), -1)

    fig = new_figure(13, 8.4)
    grid = fig.add_gridspec(2, 2, height_ratios=[1.25, 1], hspace=0.3, wspace=0.22, top=0.9,
                            bottom=0.07, left=0.06, right=0.98)
    ax = fig.add_subplot(grid[0, :])
    top, keep = hs.max() + 0.15 * (w1 - w0), (xs[:-1] >= w0) & (xs[1:] <= w1)
    classes = {"lit and seen": "#e69f00", "lit, masked by another facet": "#d62728",
               "lit, facing away from the viewer": "#9ab0c8",
               "shadowed, or facing away from the light": "#3a3a3a"}
    colour = np.where(lit > 0.5, np.where(seen > 0.5, "#e69f00", np.where(
        ps >= 1 / np.tan(to), "#9ab0c8", "#d62728")), "#3a3a3a")
    seg = np.stack([np.stack([xs[:-1], hs[:-1]], -1), np.stack([xs[1:], hs[1:]], -1)], 1)
    ax.add_collection(LineCollection(seg[keep], colors=colour[keep], linewidths=3.5, zorder=3))
    for x, y, ok, face, bx, bh in zip(hit_x, hit_h, escaped, faces, mask_x, mask_h):
        ax.plot([x - (top - y) * np.tan(ti), x], [top, y], color="#f0c040", lw=0.9)
        if ok:
            ax.plot([x, x + (top - y) * np.tan(to)], [y, top], color="#e69f00", lw=0.9, ls="--")
        elif face:
            ax.plot([x, bx], [y, bh], color="#d62728", lw=1.1, ls="--")
            ax.plot(bx, bh, "x", color="#d62728", ms=7, mew=2, zorder=4)
    for x, y, bx, bh in zip(sx, sh, shadow_x, shadow_h):
        ax.plot([x, bx], [y, bh], color="0.35", lw=1.1, ls=":")
        ax.plot(bx, bh, "x", color="0.2", ms=7, mew=2, zorder=4)
    for label, c in classes.items():
        ax.plot([], [], color=c, lw=3.5, label=label)
    ax.set(xlim=(w0, w1), ylim=(hs.min() - 0.05 * (w1 - w0), top), aspect="equal",
           xlabel="x (samples)", ylabel="height")
    ax.legend(loc="lower center", ncol=4, fontsize=8, frameon=False)
    ax.set_title(f"(a) light from the left at \u03b8i = {cfg['incidence_deg']:g}\u00b0 (solid rays; dotted: "
                 "from a shadowed facet back to its occluder x), viewer on the right at \u03b8o = "
                 f"{cfg['view_deg']:g}\u00b0 (dashed; red: masked)\nG1 of the whole profile: shadowing "
                 f"{g1['light'][0]:.3f} (Smith {g1['light'][1]:.3f}), masking {g1['view'][0]:.3f} "
                 f"(Smith {g1['view'][1]:.3f}); rms slope \u03c3 = {sigma:.3g}, Beckmann m = "
                 f"\u221a2 \u03c3 = {m:.3g}", fontsize=9)

    ax = fig.add_subplot(grid[1, 0])
    ax.plot(np.degrees(angles), smith, color="k", lw=1.5, label=f"Smith G1, Beckmann m = {m:.3g}")
    ax.plot(np.degrees(angles), sim[:, 0], "o", ms=3, color="#1f77b4", label="simulated profile")
    ax.set(xlabel="direction from the normal \u03b8 (degrees)", ylabel="G1", ylim=(0, 1.02),
           title="(b) G1 of the whole profile (visible / facing projected length)")
    ax.legend(frameon=False, fontsize=8, loc="lower left")
    ax = fig.add_subplot(grid[1, 1])
    for name, c, lab in (("view", "#d62728", "masking, \u03b8o"), ("light", "#e69f00", "shadowing, \u03b8i")):
        ax.plot((edges[1:] + edges[:-1]) / (2 * sigma), by[f"visible_{name}"], "o-", ms=3, color=c,
                label=f"{lab}: simulated")
        ax.axhline(g1[name][1], color=c, ls="--", lw=1, label=f"{lab}: Smith (independent of slope)")
    ax.set(xlabel="facet slope / rms slope", ylabel="visible fraction", ylim=(0, 1.02),
           title="(c) visibility by facet slope at \u03b8o and \u03b8i")
    ax.legend(frameon=False, fontsize=7, loc="lower center")
    fig.suptitle("Lecture (Russin, Module 3B), \u201cShadowing and masking effects\u201d, on a simulated "
                 f"Gaussian surface profile (seed {cfg['seed']})", fontsize=11)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    log.info("visible projected / (n cos) in [%.12f, %.12f]", sim[:, 1].min(), sim[:, 1].max())
