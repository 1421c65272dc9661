"""Lecture (Russin, Module 3B), "BRDF" slide: its angles (theta_i, phi_i, theta_v, phi_v) drawn, and
"Figure 9.18 (7.17 3rd edition) shows sample BRDFs" - diffuse, Phong, the lecture's normalised
Blinn-Phong, Cook-Torrance as the lecture prints it (dashed: a variant convention), an anisotropic
Ward lobe and a lunar lobe (Hapke's, back-scattering towards the light; dashed, its Lommel-Seeliger
variant without back-scatter), as polar plots in the plane of incidence. One radial scale for every
panel, ``scale_margin`` times the largest f up to ``scale_to_deg`` from N (``lobe_peak``, as in the
3-D figure), so that Phong's protrusion stands on the diffuse panel's hemisphere; the lunar panel
alone is magnified ``plot_2d.lunar_zoom`` times, and says so. Ward's panel adds, dashed, the lobe of
its light turned by ``ward_turned_deg`` about N, drawn in that light's own plane of incidence (across
the grain), with its own light and mirror marks. The radius is the BRDF f(L, V) itself along each
outgoing direction V (not f cos theta_o): a Lambertian surface is then "a simple hemisphere"."""

import numpy as np
import pandas as pd
from matplotlib.ticker import MaxNLocator

from reflectance.io.captions import write_caption_values
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.io.tables import write_csv
from reflectance.optics.brdf import brdf
from reflectance.papers.brdf_geometry import draw_brdf_angles
from reflectance.papers.polar import (lobe_peak, plane_angles, plane_of_incidence_vectors,
                                      turned_about_normal)
from reflectance.scripting import script_log

# config key -> (reflectance.optics.brdf method, panel title)
MODELS = {
    "diffuse": ("Lambert", "Diffuse (Lambert)"),
    "phong": ("Phong1975", "Phong, (R\u00b7V)$^{c_1}$/(N\u00b7L)"),
    "blinn_phong": ("BlinnPhong_AkenineMoller2008", "normalised Blinn-Phong, (m+8)/(8\u03c0) cos$^m\\theta_h$"),
    "cook_torrance": ("CookTorrance1982", "Cook-Torrance as the lecture prints it,\nplastic: s DGF/(N\u00b7V) + d R$_d$"),
    "ward": ("Ward1992", "Ward, anisotropic"),
    "lunar": ("Hapke1981", "lunar: Hapke 1981, opposition effect"),
}
# the dashed curves: column -> (panel, colour, legend label)
CT_VARIANT, LS_VARIANT, TURNED = "cook_torrance_variant", "lunar_lommel_seeliger", "ward_turned"
DASHED = (0, (4, 2))


def parameters_text(params, width=30):
    """``"a = 1, b = 2, ..."`` over lines of at most about ``width`` characters (lists and the
    convention, which the title names, left out)."""
    lines = []
    for k, v in params.items():
        if isinstance(v, (list, str)):
            continue
        item = f"{k} = {v:g}"
        if lines and len(lines[-1]) + 2 + len(item) <= width:
            lines[-1] += ", " + item
        else:
            lines.append(item)
    return ",\n".join(lines)


def lobe_axes(ax, top):
    """A half-disc polar plot, 0 deg at N, angles clockwise; rings up to the rim ``top``, each
    labelled under it (the rim too)."""
    ax.set_theta_zero_location("N")
    ax.set_theta_direction(-1)
    ax.set_thetalim(-np.pi / 2, np.pi / 2)
    ax.set_ylim(0, top)
    ax.tick_params(pad=1)
    ax.set_xticks(np.radians([-90, -45, 0, 45, 90]), ["", "-45\u00b0", "0\u00b0", "45\u00b0", ""])
    rings = [t for t in MaxNLocator(3).tick_values(0, top) if 0 < t < 0.8 * top] + [top]
    ax.set_yticks(rings, [])
    for t in rings:
        ax.annotate(f"{t:.2g}", xy=(np.pi / 2, t), xytext=(0, -2), textcoords="offset points",
                    ha="center", va="top", fontsize=TEXT_SIZE["table"], annotation_clip=False)
    return ax

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    plot = cfg["plot_2d"]
    theta_i, limit = np.radians(cfg["incidence_deg"]), cfg["scale_to_deg"]
    theta_o = plane_angles(cfg["polar_step_deg"])
    L, V, N = plane_of_incidence_vectors(theta_i, theta_o)  # light on the -x side (on the left)

    table = {"theta_o_deg": np.degrees(theta_o)}
    for key, (method, _) in MODELS.items():
        table[key] = brdf(L, V, N, method, **cfg["models"][key])
    ct = {**cfg["models"]["cook_torrance"], "convention": plot["cook_torrance_variant"]}
    table[CT_VARIANT] = brdf(L, V, N, "CookTorrance1982", **ct)
    table[LS_VARIANT] = brdf(L, V, N, "LommelSeeliger", albedo=cfg["models"]["lunar"]["albedo"])
    # the turned light in its own plane of incidence: L and V turned about N together
    turn = np.radians(cfg["ward_turned_deg"])
    table[TURNED] = brdf(turned_about_normal(L, turn), turned_about_normal(V, turn), N, "Ward1992",
                         **cfg["models"]["ward"])
    # every curve (dashed ones too) stops at scale_to_deg from N, where its printed max is taken
    # (Ward's 1/sqrt(N.L N.V) grows without bound at the horizon): the largest value drawn is it
    peaks = {key: lobe_peak(f, theta_o, limit) for key, f in table.items() if key != "theta_o_deg"}
    top = cfg["scale_margin"] * max(peak for peak, _ in peaks.values())
    tops = {key: top / plot["lunar_zoom"] if key == "lunar" else top for key in MODELS}
    if max(peaks["lunar"][0], peaks[LS_VARIANT][0]) >= tops["lunar"]:
        raise ValueError(f"figures.lecture.brdf_lobes.plot_2d.lunar_zoom = {plot['lunar_zoom']:g} puts "
                         f"the lunar lobe ({peaks['lunar'][0]:.3g}) beyond its panel's rim ({tops['lunar']:.3g})")
    pd.DataFrame(table).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    seen = np.abs(theta_o) <= np.radians(limit) * (1 + 1e-12)  # as lobe_peak
    at = {key: np.degrees(theta_o[index]) for key, (_, index) in peaks.items()}

    # drawn at the print width: the angle diagram and the legend over two rows of three polar plots
    fig = new_figure(PRINT_WIDTH_IN, 7.1)
    grid = fig.add_gridspec(3, 3, height_ratios=[1.1, 1, 1], wspace=0.3, hspace=0.7,
                            left=0.03, right=0.97, top=0.92, bottom=0.03)
    g = cfg["geometry"]
    ax = fig.add_subplot(grid[0, :2])
    draw_brdf_angles(ax, g["light"]["theta_deg"], g["light"]["phi_deg"], g["view"]["theta_deg"],
                     g["view"]["phi_deg"])
    ax.text(0.5, -0.01, "BRDF = f(\u03bb, \u03c6\u1d62, \u03b8\u1d62, \u03c6\u1d65, \u03b8\u1d65) = f(\u03bb, L, V)",
            fontsize=TEXT_SIZE["symbol"], transform=ax.transAxes, ha="center", va="top")  # under the disc
    dashed = {"cook_torrance": [(CT_VARIANT, OKABE_ITO[1], f"Cook-Torrance variant, {plot['cook_torrance_variant']}:\n"
                                 "s DGF/(4(N\u00b7L)(N\u00b7V)) + d R$_d$")],
              "ward": [(TURNED, OKABE_ITO[2], f"Ward, light L\u2032 turned {cfg['ward_turned_deg']:g}\u00b0 about N,\n"
                        "in its own plane (across the grain)")],
              "lunar": [(LS_VARIANT, OKABE_ITO[3], "lunar variant: Lommel-Seeliger\n(same w, no back-scatter)")]}
    for i, (key, (method, title)) in enumerate(MODELS.items()):
        zoom = f"\n(radius \u00d7{plot['lunar_zoom']:g}: its own rings)" if key == "lunar" else ""
        ax = lobe_axes(fig.add_subplot(grid[1 + i // 3, i % 3], projection="polar"), tops[key])
        ax.set_title(f"{title}{zoom}\n" + parameters_text(cfg["models"][key]),
                     fontsize=TEXT_SIZE["annotation"], pad=0, linespacing=1.25)
        f = np.where(seen, table[key], 0.0)
        ax.plot(theta_o, f, color=OKABE_ITO[0], lw=1.6, zorder=4)
        ax.fill(theta_o, f, color=OKABE_ITO[0], alpha=0.15, zorder=2)
        for column, colour, label in dashed.get(key, []):
            ax.plot(theta_o, np.where(seen, table[column], 0.0), color=colour, lw=1.4, ls=DASHED, zorder=5,
                    label=label)
        # the light and the mirror direction thin and behind the lobes, so a lobe along them reads
        ax.plot([-theta_i, -theta_i], [0, tops[key]], color=OKABE_ITO[4], lw=0.9, zorder=1,
                label="towards the light L")
        ax.plot([theta_i, theta_i], [0, tops[key]], color="0.45", lw=0.8, ls="--", zorder=1, label="mirror direction")
        if key == "ward":  # the turned light's own L' and mirror: the same angles in its own plane
            for sign, name in ((-1, "L\u2032"), (1, "mirror\u2032")):
                ax.plot([sign * theta_i] * 2, [0.86 * top, 1.06 * top], color=OKABE_ITO[2], lw=1.6, ls=(0, (2, 1)),
                        clip_on=False, zorder=5)
                ax.text(sign * (theta_i + np.radians(17)), 0.9 * top, name, ha="center", va="center",
                        color=OKABE_ITO[2], fontsize=TEXT_SIZE["annotation"], clip_on=False)
        peak = peaks[key][0]
        flat = np.ptp(f[seen]) <= 1e-9 * peak  # Lambert's: no one direction
        text = f"max f = {peak:.3g} sr$^{{-1}}$" + ("" if flat else f" at \u03b8 = {at[key]:.0f}\u00b0")
        for column, _, _ in dashed.get(key, []):
            text += f";\ndashed: {peaks[column][0]:.3g} at {at[column]:.0f}\u00b0"
            text += ", the limit" if np.isclose(abs(at[column]), limit) else ""
        ax.text(0.5, 0.02, text, transform=ax.transAxes, ha="center", va="top", fontsize=TEXT_SIZE["annotation"])
        log.info("%s: max f %.6g at theta_o = %.2f deg (up to %g deg from N)", key, peak, at[key], limit)
    handles, labels = [], []
    for panel in fig.axes[1:]:
        for handle, label in zip(*panel.get_legend_handles_labels()):
            if label not in labels:
                handles.append(handle)
                labels.append(label)
    fig.legend(handles, labels, loc="center left", bbox_to_anchor=(0.64, 0.8),
               title=f"incidence {cfg['incidence_deg']:g}\u00b0, light on the left;\nradius f(L, V) in sr$^{{-1}}$, "
               f"one scale\nfor all panels (lunar: \u00d7{plot['lunar_zoom']:g});\nmax f: largest up to {limit:g}\u00b0 from N",
               alignment="left")
    fig.suptitle("Lecture (Russin, Module 3B), the BRDF's angles\nand sample BRDFs in the plane of "
                 "incidence", y=0.995, va="top", linespacing=1.3)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    # the caption's numbers, from the table just written
    mirror = int(np.argmin(np.abs(theta_o - theta_i)))
    base = cfg["models"]["cook_torrance"]["d"] * cfg["models"]["cook_torrance"]["R_d"]
    gap = np.where(seen, table["lunar"] - table[LS_VARIANT], -np.inf)
    write_caption_values(snakemake.output.values, {
        "scale": f"{top:.3g}", "lunar_scale": f"{tops['lunar']:.3g}",
        "ct_max": f"{peaks['cook_torrance'][0]:.3g}", "ct_max_at": f"{at['cook_torrance']:.2f}",
        "ct_variant_max": f"{peaks[CT_VARIANT][0]:.3g}", "ct_variant_max_at": f"{at[CT_VARIANT]:.2f}",
        "ct_specular_ratio": f"{(table['cook_torrance'][mirror] - base) / (table[CT_VARIANT][mirror] - base):.3f}",
        "pi_cos_theta_i": f"{np.pi * np.cos(theta_i):.3f}",
        "ward_mirror": f"{table['ward'][mirror]:.3g}", "ward_turned_max": f"{peaks[TURNED][0]:.3g}",
        "ward_turned_max_at": f"{at[TURNED]:.2f}",
        "lunar_max": f"{peaks['lunar'][0]:.3g}", "lunar_max_at": f"{at['lunar']:.2f}",
        "lunar_ls_there": f"{table[LS_VARIANT][peaks['lunar'][1]]:.3g}",
        "lunar_gap": f"{gap.max():.3g}", "lunar_gap_at": f"{np.degrees(theta_o[np.argmax(gap)]):.2f}",
    })
