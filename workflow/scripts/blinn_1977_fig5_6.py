"""Blinn 1977, Figs. 5 and 6: Phong vs Torrance-Sparrow reflection in the plane of incidence as
polar plots (distance from the centre = intensity reflected in that direction), light from the
right at the configured angle; one row per parameter set: Phong (matched p_s F(0), and p_s as
printed), Torrance-Sparrow on the same scale, and the three as Cartesian curves i(theta).
Blinn prints no parameters for these figures: the default figure draws the ``chosen`` set (a
narrow bump on the hemisphere, as his text describes), a variant figure Fig. 7's measured sets."""

import numpy as np
import pandas as pd
from matplotlib.lines import Line2D
from matplotlib.ticker import MaxNLocator

from reflectance.io.captions import write_caption_values
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.optics.microfacet import beta_to_c3_Blinn1977, c1_to_beta_Blinn1977
from reflectance.papers.blinn_comparison import compare_in_plane_Blinn1977
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

LINE_PT = 1.6  # the solid curves' width (points)
CURVES = {  # key: (legend, colour, line style); drawn in this order (as printed on top: it shows
    # where it lies on the matched curve)
    "phong_matched": ("Phong, p_s F(0) (matched)", OKABE_ITO[0], "-"),
    "phong_as_printed": ("Phong, p_s as printed", OKABE_ITO[5], (0, (3, 2))),
    "torrance_sparrow": ("Torrance-Sparrow, p_s D\u2083 G F / (N\u00b7E)", OKABE_ITO[1], "-"),
}
# Blinn's words on each figure (his text under Figs. 5 and 6), beside the numbers that test them
BLINN_SAYS = {"5": "Blinn at 30\u00b0: \u201cthe functions are almost identical\u201d.",
              "6": "Blinn at 70\u00b0: \u201cthe specular bump is much larger for the Torrance Sparrow "
                   "function\nand not in quite the same direction\u201d."}


def plot_curve(ax, x, y, key):
    """One curve in its style; Phong as printed thin and dashed over the matched curve, so that it
    shows where it lies on it (open circles there read as beads: reviews of issue 28)."""
    label, colour, style = CURVES[key]
    ax.plot(x, y, color=colour, ls=style, lw=LINE_PT if style == "-" else 1.0, label=label)


def rings(top):
    """The polar panels' rings: round steps from 0 up to the first ring at or beyond ``top``."""
    ticks = [t for t in MaxNLocator(3).tick_values(0, top) if t > 0]
    return ticks[:next(i for i, t in enumerate(ticks) if t >= top) + 1]


def zoom_window(row, half_width):
    """The inset's views (degrees): the mirror direction +- ``half_width``, where it holds both
    peaks; None where a peak lies outside (its direction then drawn in the polar panel)."""
    window = row["theta_i_deg"] - half_width, row["theta_i_deg"] + half_width
    inside = all(window[0] <= row[f"{k}_max_deg"] <= window[1]
                 for k in ("phong_matched", "torrance_sparrow"))
    return window if inside else None


def polar_top(values, row, theta_i, theta_r, R):
    """The highest point drawn in a row's polar panels: curves and arrows (the rest is cropped)."""
    peak = np.radians(row["torrance_sparrow_max_deg"])
    return max(max((v * np.cos(theta_r)).max() for v in values.values()),
               R * np.cos(theta_i), R * np.cos(peak))


def draw_zoom(cart, values, row, tr_deg, window):
    """The peaks' directions magnified: an inset over the flat right of the i(theta) panel."""
    inset = cart.inset_axes([0.45, 0.42, 0.52, 0.4])
    near = (tr_deg >= window[0]) & (tr_deg <= window[1])
    for key in ("phong_matched", "torrance_sparrow"):
        plot_curve(inset, tr_deg[near], values[key][near], key)
        inset.plot([row[f"{key}_max_deg"]], [row[f"{key}_max"]], "o", color=CURVES[key][1], ms=3.5)
    low = min(values[k][near].min() for k in ("phong_matched", "torrance_sparrow"))
    high = max(row[f"{k}_max"] for k in ("phong_matched", "torrance_sparrow"))
    # a margin below as above, so a peak at the window's lowest value is not cut by the frame
    inset.set(xlim=window[::-1], ylim=(low - 0.08 * (high - low), high + 0.1 * (high - low)), yticks=[],
              xticks=[round(row["theta_i_deg"] + d) for d in (-0.4, 0, 0.4) * np.diff(window)])
    inset.tick_params(labelsize=TEXT_SIZE["table"], pad=1)
    inset.axvline(row["theta_i_deg"], color="0.5", lw=0.8, ls=(0, (3, 2)))
    ts = row["torrance_sparrow_max_deg"]
    inset.axvline(ts, color=CURVES["torrance_sparrow"][1], lw=0.8)
    # the two labels over the inset, on either side of their lines (the larger angle on the left)
    side = ts >= row["theta_i_deg"]
    for x, text, colour, ha in ((row["theta_i_deg"], f"mirror {row['theta_i_deg']:g}\u00b0", "0.35",
                                 "left" if side else "right"),
                                (ts, f"peak {ts:.1f}\u00b0", CURVES["torrance_sparrow"][1],
                                 "right" if side else "left")):
        inset.text(x, 1.02, f" {text} ", transform=inset.get_xaxis_transform(), ha=ha, va="bottom",
                   fontsize=TEXT_SIZE["table"], color=colour)
    zoom = cart.indicate_inset_zoom(inset, edgecolor="0.4", alpha=0.8)
    for i, line in enumerate(zoom.connectors):  # one line, below the labels over the inset
        line.set_visible(i == 0)


def draw(sets, results, theta_i, theta_r, title, scales, number, half_width, every=None):
    """One row per parameter set: the two polar plots on one scale (``scales``, rings by label: the
    same for Figs. 5 and 6), cropped above the highest curve or arrow, and i(theta) with an inset at
    the peaks. Returns the figure, per row whether Phong as printed lies under the matched curve
    within a line width, and the inset's window (or None)."""
    tops = [polar_top(*r, theta_i, theta_r, scales[s["label"]][-1]) / scales[s["label"]][-1]
            for s, r in zip(sets, results)]
    # drawn at the print width (its text prints at the figures' sizes); each row's parameters over it
    # a row: the polar panels' height (2.1 in across at this width) and 1.7 in of text above and below
    fig = new_figure(PRINT_WIDTH_IN, 1.3 + sum(max(1.8, 1.7 + 2.1 * (t + 0.24) / 2.04) for t in tops))
    axes = np.atleast_2d(fig.subplots(len(sets), 3, gridspec_kw={"width_ratios": [1, 1, 0.82]}))
    windows = []
    for row_axes, s, (values, row), top in zip(axes, sets, results, tops):
        F0 = row["F0"]
        ticks = scales[s["label"]]
        R = ticks[-1]  # the outermost ring: the same scale for both polar plots, Figs. 5 and 6
        light = R * np.array([np.sin(theta_i), np.cos(theta_i)])
        peak = np.radians(row["torrance_sparrow_max_deg"])
        marked = row["G_corners_marked"]
        window = zoom_window(row, half_width)
        windows.append(window)
        for ax, keys, name in ((row_axes[0], ("phong_matched", "phong_as_printed"), "Phong model"),
                               (row_axes[1], ("torrance_sparrow",), "Torrance-Sparrow model")):
            ax.fill_between([-R, R], -0.07 * R, 0, color="0.88", lw=0)
            ax.axhline(0, color="0.2", lw=1.0)
            arc = np.linspace(0, np.pi, 181)
            for t in ticks:
                ax.plot(t * np.cos(arc), t * np.sin(arc), color="0.88", lw=0.6, zorder=0)
                # under the grey band, where no curve runs (the curves end on the baseline)
                ax.text(t, -0.085 * R, f"{t:g}", ha="center", va="top", fontsize=TEXT_SIZE["table"],
                        color="0.35")
            for key in keys:  # Blinn's light from the right: the plane seen from behind (x -> -x)
                plot_curve(ax, -values[key] * np.sin(theta_r), values[key] * np.cos(theta_r), key)
                if row[f"{key}_max_deg"] == np.degrees(theta_r[-1]):  # a peak at the horizon lies
                    # along the baseline: mark it above the line
                    edge, colour = -values[key][-1], CURVES[key][1]
                    ax.plot([edge], [0.0], "o", color=colour, ms=4, clip_on=False, zorder=4)
                    ax.annotate(f"{values[key][-1]:.2f} at the horizon", xy=(edge, 0.0),
                                xytext=(edge, 0.75 * top * R), ha="left", va="bottom", color=colour,
                                fontsize=TEXT_SIZE["annotation"],
                                arrowprops=dict(arrowstyle="-", color=colour, lw=0.8))
            if keys == ("torrance_sparrow",):  # the corners of G that show, and (where the inset
                # does not show it) the peak's direction
                ts = values["torrance_sparrow"][marked]
                ax.plot(-ts * np.sin(theta_r[marked]), ts * np.cos(theta_r[marked]), "v", color="0.2",
                        ms=4, zorder=4)
                if window is None:
                    ax.annotate("", xy=R * np.array([-np.sin(peak), np.cos(peak)]), xytext=(0, 0),
                                arrowprops=dict(arrowstyle="-|>", color=CURVES[keys[0]][1], lw=0.7))
            ax.annotate("", xy=0.03 * light, xytext=light,  # the incoming ray
                        arrowprops=dict(arrowstyle="-|>", color="0.15", lw=1.1, shrinkA=0, shrinkB=0))
            ax.annotate("", xy=light * [-1, 1], xytext=(0, 0),  # Blinn's reference vector
                        arrowprops=dict(arrowstyle="-|>", color="0.5", lw=0.9, ls=(0, (3, 2))))
            ax.set(xlim=(-1.02 * R, 1.02 * R), ylim=(-0.2 * R, (top + 0.04) * R), aspect="equal",
                   xticks=[], yticks=[])
            ax.set_title(name, pad=2)
            for side in ax.spines.values():
                side.set_visible(False)
        cart = row_axes[2]
        tr_deg = np.degrees(theta_r)
        for key in CURVES:
            plot_curve(cart, tr_deg, values[key], key)
        cart.plot(tr_deg[marked], values["torrance_sparrow"][marked], "v", color="0.2", ms=4,
                  zorder=4)
        cart.axvline(np.degrees(theta_i), color="0.5", lw=0.8, ls=(0, (3, 2)))
        if window is None:  # the word beside the line, inside the axes (+90 on the left); with an
            # inset, the inset says it
            cart.text(np.degrees(theta_i), 1.0, " mirror", transform=cart.get_xaxis_transform(),
                      fontsize=TEXT_SIZE["annotation"], color="0.35", va="top", ha="left")
        # the mirror side on the left, as in the polar plots (Blinn's light from the right)
        cart.set(xlim=(90, -90), ylim=(0, 1.05 * R), xticks=np.arange(-90, 91, 45),
                 xlabel="\u03b8 from N (\u00b0; mirror side +, left)", ylabel="intensity i")
        cart.grid(True)
        cart.set_title("the same, i(\u03b8)", pad=2)
        if window is not None:
            draw_zoom(cart, values, row, tr_deg, window)
        # Blinn's words, and the numbers that test them, under both polar plots
        beyond = row["torrance_sparrow_max_deg"] - row["theta_i_deg"]
        numbers = (f"Here the curves differ by at most {row['max_difference_ts_matched']:.0%} of the "
                   f"Phong peak; peaks' ratio {row['peak_ratio_ts_to_matched']:.2f}, bumps' "
                   f"{row['bump_ratio_ts_to_matched']:.2f}") if number == "5" else (
                   f"Here: bumps' ratio {row['bump_ratio_ts_to_matched']:.2f} (peaks' "
                   f"{row['peak_ratio_ts_to_matched']:.2f}); Torrance-Sparrow peak "
                   f"{beyond:.1f}\u00b0 beyond the mirror")
        base = [v for v in snakemake.params.fig["parameter_sets"]
                if all(v[k] == s[k] for k in ("p_s", "p_d", "n")) and v["c3"] != s["c3"]]
        name = (f"{base[0]['label']}, c\u2083 narrower; Blinn prints none for Figs. 5, 6:" if base
                else f"{s['label']}:")
        if base and every:  # why narrower: the printed c3's Torrance-Sparrow peak, from its results
            printed = every[base[0]["label"]][1]
            numbers += (f";\nprinted c\u2083 = {base[0]['c3']:g}: Torrance-Sparrow peak "
                        f"{printed['torrance_sparrow_max']:.2f} at \u03b8 = "
                        f"{printed['torrance_sparrow_max_deg']:.0f}\u00b0, no bump at the mirror")
        row_axes[0].annotate(f"{BLINN_SAYS[number]}\n{numbers}.".replace("%", " %"),
                             xy=(1.08, 0), xycoords="axes fraction", xytext=(0, -16),
                             textcoords="offset points", ha="center", va="top", linespacing=1.3,
                             fontsize=TEXT_SIZE["annotation"], color="0.2")
        row_axes[0].annotate(f"{name}\np_s = {s['p_s']:g}, p_d = {s['p_d']:g}, n = {s['n']:g}, "
                             f"F(0) = {F0:.3g}, c\u2083 = {s['c3']:g}, \u03b2 = {row['beta_deg']:.1f}"
                             f"\u00b0, c\u2081 = {row['c1']:.3g}",
                             xy=(0, 1), xycoords="axes fraction", xytext=(0, 22),
                             textcoords="offset points", ha="left", va="bottom",
                             fontsize=TEXT_SIZE["annotation"] + 0.5, linespacing=1.3)
        for ax, key in ((row_axes[0], "phong_matched"), (row_axes[1], "torrance_sparrow")):
            ax.annotate(f"peak {row[f'{key}_max']:.3f} at \u03b8 = {row[f'{key}_max_deg']:.1f}\u00b0",
                        xy=(0.5, 0), xycoords="axes fraction", xytext=(0, -3),
                        textcoords="offset points", ha="center", va="top",
                        fontsize=TEXT_SIZE["annotation"], color=CURVES[key][1])
    fig.suptitle(title, y=0.998, va="top", linespacing=1.3)
    # one row: its polar axes, wider than high, shrink about their centres (aspect 1): start higher
    # and per legend row fewer than three, a line less (the curves, the peak direction, corners)
    corners = any(np.size(row["G_corners_marked"]) for _, row in results)
    title_in = (1.3 if len(sets) == 1 else 1.55) - 0.17 * (3 - (len(CURVES) + 2 + corners) // 2)
    fig.subplots_adjust(left=0.01, right=0.99, top=1 - title_in / fig.get_figheight(),
                        bottom=0.75 / fig.get_figheight(), wspace=0.3, hspace=1.1)
    coincide = []  # Phong as printed within a line width of the matched curve, in the polar panel
    for row_axes, s, (values, row) in zip(axes, sets, results):
        row_axes[0].apply_aspect()
        width_pt = row_axes[0].get_position().width * fig.get_figwidth() * 72
        per_pt = 2.04 * scales[s["label"]][-1] / width_pt  # data units per point
        gap = np.abs(values["phong_as_printed"] - values["phong_matched"]).max()
        coincide.append(bool(gap <= LINE_PT * per_pt))
    handles, labels = axes[0, 2].get_legend_handles_labels()
    printed = labels.index(CURVES["phong_as_printed"][0])
    on = [(s["label"], row["F0"]) for s, (_, row), c in zip(sets, results, coincide) if c]
    if on:  # its dashes show it where it lies on the matched curve
        labels[printed] += ": on the p_s F(0) curve, " + "; ".join(
            (f"{name}, " if len(sets) > 1 else "") + f"F(0) = {F0:.2f}" for name, F0 in on)
    handles += [Line2D([], [], color=CURVES["torrance_sparrow"][1], lw=0.8)]
    labels += ["Torrance-Sparrow peak direction"]
    if corners:  # a key only for a mark drawn
        handles += [Line2D([], [], marker="v", ls="none", color="0.2", ms=4)]
        labels += ["corner: G = min(1, G_b, G_c) changes term"]
    fig.legend(handles, labels, loc="upper center", ncol=2,
               bbox_to_anchor=(0.5, 1 - 0.45 / fig.get_figheight()))
    return fig, coincide, windows


with script_log(snakemake) as log:
    cfg, number = snakemake.params.fig, snakemake.params.figure_number
    theta_i = np.radians(float(snakemake.params.incidence_deg))
    # n_directions from -90 to 90 degrees inclusive; the two horizon samples (i = 0) are dropped
    theta_r = np.radians(np.linspace(-90.0, 90.0, cfg["n_directions"])[1:-1])
    chosen, variants = [cfg["chosen"]], cfg["parameter_sets"]
    results = {s["label"]: compare_in_plane_Blinn1977(s, theta_i, theta_r, cfg["corner_min_fraction"])
               for s in chosen + variants}
    # one radial scale for Figs. 5 and 6 (the same rings): each set's largest value at either angle
    scales = {s["label"]: rings(max(max(v.max() for v in compare_in_plane_Blinn1977(
        s, np.radians(float(a)), theta_r)[0].values()) for a in cfg["incidence_deg"].values()))
        for s in chosen + variants}
    coincide, windows = {}, {}
    incidence = f"light at {np.degrees(theta_i):g}\u00b0 from the normal, from the right"
    for sets, title, png, pdf in (
            (chosen, f"Blinn 1977, Fig. {number} \u2014 Phong and Torrance-Sparrow reflection,\n"
             f"{incidence}", snakemake.output.png, snakemake.output.pdf),
            (variants, f"Blinn 1977, Fig. {number}, variant: Fig. 7's measured materials,\n{incidence}",
             snakemake.output.variant_png, snakemake.output.variant_pdf)):
        fig, flags, zooms = draw(sets, [results[s["label"]] for s in sets], theta_i, theta_r, title,
                                 scales, str(number), cfg["zoom_half_width_deg"], results)
        coincide.update({s["label"]: c for s, c in zip(sets, flags)})
        windows.update({s["label"]: w or (np.nan, np.nan) for s, w in zip(sets, zooms)})
        savefig(fig, png, pdf)
    curves, summary = [], []
    for role, s in [("default", s) for s in chosen] + [("variant", s) for s in variants]:
        values, row = results[s["label"]]
        corners, marked = (" ".join(f"{a:.1f}" for a in np.degrees(theta_r[row[k]]))
                           for k in ("G_corners", "G_corners_marked"))
        row = {"role": role, **{k: v for k, v in row.items() if not k.startswith("G_corners")},
               "G_corners_deg": corners, "G_corners_marked_deg": marked,
               "polar_scale": scales[s["label"]][-1],
               "polar_rings": " ".join(f"{t:g}" for t in scales[s["label"]]),
               "zoom_from_deg": windows[s["label"]][0], "zoom_to_deg": windows[s["label"]][1],
               "phong_as_printed_coincides": coincide[s["label"]]}
        log.info("%s: %s", s["label"], ", ".join(f"{k} = {v:.6g}" for k, v in row.items()
                                                   if not isinstance(v, str)))
        summary.append(row)
        curves.append(pd.DataFrame({"parameter_set": s["label"], "theta_r_deg": np.degrees(theta_r),
                                    **values}))
    pd.concat(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    pd.DataFrame(summary).pipe(write_csv, snakemake.output.summary, float_format="%.6g")

    # Blinn's "typically 50 or 60": the chosen set at typical_c1 (c3 of the same beta, Blinn's
    # equal-beta rule), at Fig. 5's and Fig. 6's incidences
    beta = c1_to_beta_Blinn1977(cfg["typical_c1"])
    typical = {**cfg["chosen"], "c3": float(beta_to_c3_Blinn1977(beta))}
    at = {k: compare_in_plane_Blinn1977(typical, np.radians(float(a)), theta_r,
                                         cfg["corner_min_fraction"])[1]
          for k, a in cfg["incidence_deg"].items()}

    # the caption's numbers (workflow/report/blinn77_fig5_6*.rst): the default set, then the
    # variants in config order, from the summary as written
    default, first, second = pd.read_csv(snakemake.output.summary).itertuples()
    write_caption_values(snakemake.output.values, {
        "typical_beta": f"{np.degrees(beta):.1f}", "typical_c3": f"{typical['c3']:.3f}",
        "typical_difference": f"{at['fig5']['max_difference_ts_matched']:.0%}".replace("%", " %"),
        "typical_beyond": f"{at['fig6']['torrance_sparrow_max_deg'] - at['fig6']['theta_i_deg']:.1f}",
        "typical_at_corner": "at a corner of G" if any(
            abs(at["fig6"]["torrance_sparrow_max_deg"] - np.degrees(theta_r[i])) < 0.2
            for i in at["fig6"]["G_corners"]) else "not at a corner of G",
        "chosen_difference": f"{default.max_difference_ts_matched:.0%}".replace("%", " %"),
        "chosen_bump_matched": f"{default.bump_to_hemisphere_matched:.2f}",
        "chosen_bump_ts": f"{default.bump_to_hemisphere_ts:.2f}",
        "chosen_ratio": f"{default.peak_ratio_ts_to_matched:.2f}",
        "chosen_bump_ratio": f"{default.bump_ratio_ts_to_matched:.2f}",
        "chosen_beta": f"{default.beta_deg:.1f}", "chosen_c1": f"{default.c1:.0f}",
        "chosen_F0": f"{default.F0:.2f}",
        "chosen_phong_matched_peak": f"{default.phong_matched_max:.3f}",
        "chosen_phong_matched_deg": f"{default.phong_matched_max_deg:.1f}",
        "chosen_torrance_sparrow_peak": f"{default.torrance_sparrow_max:.3f}",
        "chosen_torrance_sparrow_deg": f"{default.torrance_sparrow_max_deg:.1f}",
        "chosen_ts_beyond_mirror": f"{default.torrance_sparrow_max_deg - default.theta_i_deg:.1f}",
        # where the drawing marks the peak's direction: the inset's line, or (no inset) an arrow
        "chosen_peak_mark": (
            "the thin orange arrow in the Torrance-Sparrow panel" if np.isnan(default.zoom_from_deg)
            else f"the thin orange line in the inset over i(theta), which magnifies the views "
                 f"{default.zoom_from_deg:g} to {default.zoom_to_deg:g} degrees"),
        "chosen_outer_ring": str(default.polar_rings).split()[-1],
        "set1_difference": f"{first.max_difference_ts_matched:.0%}".replace("%", " %"),
        "set2_difference": f"{second.max_difference_ts_matched:.0%}".replace("%", " %"),
        "set1_F0": f"{first.F0:.2f}", "set2_F0": f"{second.F0:.3f}",
        "set2_bump_matched": f"{second.bump_to_hemisphere_matched:.2f}",
        "set1_ratio": f"{first.peak_ratio_ts_to_matched:.2f}",
        "set2_ratio": f"{second.peak_ratio_ts_to_matched:.2f}",
        "set1_ratio_printed": f"{first.peak_ratio_ts_to_as_printed:.2f}",
        "set2_ratio_printed": f"{second.peak_ratio_ts_to_as_printed:.2f}",
        "set1_phong_matched_peak": f"{first.phong_matched_max:.3f}",
        "set1_phong_matched_deg": f"{first.phong_matched_max_deg:.1f}",
        "set1_torrance_sparrow_peak": f"{first.torrance_sparrow_max:.3f}",
        "set1_torrance_sparrow_deg": f"{first.torrance_sparrow_max_deg:.1f}",
        "set2_phong_matched_peak": f"{second.phong_matched_max:.3f}",
        "set2_phong_matched_deg": f"{second.phong_matched_max_deg:.1f}",
        "set2_torrance_sparrow_peak": f"{second.torrance_sparrow_max:.3f}",
        "set2_torrance_sparrow_deg": f"{second.torrance_sparrow_max_deg:.1f}"})
