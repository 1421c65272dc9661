"""Lecture (Russin, Module 3B), "BRDF" slide: its angles (theta_i, phi_i, theta_v, phi_v) drawn, and
"Figure 9.18 (7.17 3rd edition) shows sample BRDFs" - diffuse, Phong, the lecture's normalised
Blinn-Phong, Cook-Torrance, an anisotropic Ward lobe and a lunar lobe (Hapke's, back-scattering
towards the light; dashed, its Lommel-Seeliger variant without back-scatter), as polar plots in the
plane of incidence. One radial scale for every panel, ``scale_margin`` times the largest f up to ``scale_to_deg``
from N (``lobe_peak``, as in the 3-D figure), so that Phong's protrusion stands on the diffuse
panel's hemisphere. Ward's panel adds the lobe of its light turned by ``ward_turned_deg`` about N
(dashed: across the grain). The radius is the BRDF f(L, V) itself along each outgoing direction V
(not f cos theta_o): a Lambertian surface is then "a simple hemisphere", as the slide says."""

import numpy as np
import pandas as pd
from matplotlib.ticker import MaxNLocator

from reflectance.optics.brdf import brdf
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.papers.brdf_geometry import draw_brdf_angles
from reflectance.papers.polar import (lobe_peak, plane_angles, plane_of_incidence_vectors,
                                      turned_about_normal)
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

# config key -> (reflectance.optics.brdf method, panel title)
MODELS = {
    "diffuse": ("Lambert", "Diffuse (Lambert)"),
    "phong": ("Phong1975", "Phong, (R\u00b7V)$^{c_1}$/(N\u00b7L)"),
    "blinn_phong": ("BlinnPhong_AkenineMoller2008", "normalised Blinn-Phong, (m+8)/(8\u03c0) cos$^m\\theta_h$"),
    "cook_torrance": ("CookTorrance1982", "Cook-Torrance, plastic: s DGF/(4(N\u00b7L)(N\u00b7V)) + d R$_d$"),
    "ward": ("Ward1992", "Ward, anisotropic"),
    "lunar": ("Hapke1981", "lunar: Hapke 1981, opposition effect"),
}
VARIANT = "lunar_lommel_seeliger"  # the lunar lobe's Lommel-Seeliger variant (same albedo), dashed
TURNED = "ward_turned"  # Ward's lobe with the light turned about N (across the grain), dashed


def parameters_text(params):
    return ", ".join(f"{k} = {v:g}" if not isinstance(v, str) else f"{v}" for k, v in params.items()
                     if not isinstance(v, list))


def wrap_items(text, width=30):
    """``"a = 1, b = 2, ..."`` over lines of at most about ``width`` characters, broken between items."""
    lines = []
    for item in text.split(", "):
        if lines and len(lines[-1]) + 2 + len(item) <= width:
            lines[-1] += ", " + item
        else:
            lines.append(item)
    return ",\n".join(lines)


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    theta_i = np.radians(cfg["incidence_deg"])
    theta_o = plane_angles(cfg["polar_step_deg"])
    L, V, N = plane_of_incidence_vectors(theta_i, theta_o)  # light on the -x side (on the left)

    table = {"theta_o_deg": np.degrees(theta_o)}
    for key, (method, _) in MODELS.items():
        table[key] = brdf(L, V, N, method, **cfg["models"][key])
    table[VARIANT] = brdf(L, V, N, "LommelSeeliger", albedo=cfg["models"]["lunar"]["albedo"])
    turn = np.radians(cfg["ward_turned_deg"])  # the same plane of incidence, turned about N
    table[TURNED] = brdf(turned_about_normal(L, turn), turned_about_normal(V, turn), N, "Ward1992",
                         **cfg["models"]["ward"])
    # one radial scale for every panel: scale_margin times the largest of their maxima (Ward's f grows
    # without bound at the horizon: each maximum is taken up to scale_to_deg, lobe_peak)
    # every curve drawn (the dashed ones too) stops at scale_to_deg from N, so that the largest
    # value drawn is the "max f" printed under it
    peaks = {key: lobe_peak(table[key], theta_o, cfg["scale_to_deg"])
             for key in (*MODELS, VARIANT, TURNED)}
    top = cfg["scale_margin"] * max(peak for peak, _ in peaks.values())
    rings = [t for t in MaxNLocator(3).tick_values(0, top) if 0 < t < 0.9 * top] + [top]  # and the rim
    pd.DataFrame(table).pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    # drawn at the print width (its text prints at the figures' sizes): the angle diagram and the
    # legend over two rows of three polar plots
    fig = new_figure(PRINT_WIDTH_IN, 6.9)
    grid = fig.add_gridspec(3, 3, height_ratios=[1.2, 1, 1], wspace=0.3, hspace=0.62,
                            left=0.03, right=0.97, top=0.92, bottom=0.03)
    g = cfg["geometry"]
    ax = fig.add_subplot(grid[0, :2])
    draw_brdf_angles(ax, g["light"]["theta_deg"], g["light"]["phi_deg"], g["view"]["theta_deg"],
                     g["view"]["phi_deg"])
    ax.text(0.5, -0.01, "BRDF = f(\u03bb, \u03c6\u1d62, \u03b8\u1d62, \u03c6\u1d65, \u03b8\u1d65) = f(\u03bb, L, V)",
            fontsize=TEXT_SIZE["symbol"], transform=ax.transAxes, ha="center", va="top")  # under the disc
    for i, (key, (method, title)) in enumerate(MODELS.items()):
        ax = fig.add_subplot(grid[1 + i // 3, i % 3], projection="polar")
        ax.set_theta_zero_location("N")
        ax.set_theta_direction(-1)
        ax.set_thetalim(-np.pi / 2, np.pi / 2)
        # drawn up to scale_to_deg from N, where the printed max is taken (Ward's 1/sqrt(N.V) grows
        # without bound towards the horizon); beyond it each curve returns to the centre
        seen = np.abs(theta_o) <= np.radians(cfg["scale_to_deg"]) * (1 + 1e-12)  # as lobe_peak
        f = np.where(seen, table[key], 0.0)
        peak, at = peaks[key]
        ax.plot(theta_o, f, color=OKABE_ITO[0], lw=1.6)
        ax.fill(theta_o, f, color=OKABE_ITO[0], alpha=0.15)
        if key == "lunar":
            ax.plot(theta_o, np.where(seen, table[VARIANT], 0.0), color=OKABE_ITO[3], lw=1.2, ls=(0, (4, 2)),
                    label="lunar variant: Lommel-Seeliger\n(same w, no back-scatter)")
        if key == "ward":
            ax.plot(theta_o, np.where(seen, table[TURNED], 0.0), color=OKABE_ITO[2], lw=1.2, ls=(0, (4, 2)),
                    label=f"Ward, light turned {cfg['ward_turned_deg']:g}\u00b0 about N\n(across the grain)")
        ax.plot([-theta_i, -theta_i], [0, top], color=OKABE_ITO[4], lw=1.5, label="towards the light L")
        ax.plot([theta_i, theta_i], [0, top], color="0.4", lw=1, ls="--", label="mirror direction")
        ax.set_ylim(0, top)
        ax.set_title(f"{title}\n" + wrap_items(parameters_text(cfg["models"][key])),
                     fontsize=TEXT_SIZE["annotation"], pad=0, linespacing=1.25)
        ax.tick_params(pad=1)
        ax.set_xticks(np.radians([-90, -45, 0, 45, 90]), ["", "-45\u00b0", "0\u00b0", "45\u00b0", ""])
        ax.set_yticks(rings, [])  # the one scale: each ring's value centred under it, the rim's too
        for t in rings:
            ax.annotate(f"{t:.2g}", xy=(np.pi / 2, t), xytext=(0, -2), textcoords="offset points",
                        ha="center", va="top", fontsize=TEXT_SIZE["table"], annotation_clip=False)
        flat = np.ptp(f[seen]) <= 1e-9 * peak  # Lambert's: no one direction
        where = "" if flat else f" at \u03b8 = {np.degrees(theta_o[at]):.0f}\u00b0"
        if key == "ward":  # the dashed lobe's own maximum, at the limit
            where += (f";\nturned: {peaks[TURNED][0]:.3g} at "
                      f"{np.degrees(theta_o[peaks[TURNED][1]]):.0f}\u00b0")
        ax.text(0.5, 0.02, f"max f = {peak:.3g} sr$^{{-1}}${where}",
                transform=ax.transAxes, ha="center", va="top", fontsize=TEXT_SIZE["annotation"])
        log.info("%s: max f %.6g at theta_o = %.2f deg (up to %g deg from N)", key, peak,
                 np.degrees(theta_o[at]), cfg["scale_to_deg"])
    handles, labels = fig.axes[-1].get_legend_handles_labels()
    extra = fig.axes[-2].get_legend_handles_labels()  # Ward's turned lobe
    fig.legend(extra[0][:1] + handles, extra[1][:1] + labels, loc="center left",
               bbox_to_anchor=(0.67, 0.8), title=f"incidence {cfg['incidence_deg']:g}\u00b0,\n"
               "light on the left;\nradius f(L, V) in sr$^{-1}$,\none scale for all panels;\n"
               f"max f: largest up to {cfg['scale_to_deg']:g}\u00b0 from N", alignment="left")
    fig.suptitle("Lecture (Russin, Module 3B), the BRDF's angles\nand sample BRDFs in the plane of "
                 "incidence", y=0.995, va="top", linespacing=1.3)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
