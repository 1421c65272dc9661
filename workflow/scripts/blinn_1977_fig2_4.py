"""Blinn 1977, Figs. 2-4 for one case of Fig. 1: (2) the top view, L and E off the plane of N and H
and their projections; (3) the escaping fraction 1 - m/l; (4) the law-of-sines construction with
Blinn's angles a..f. Every point and number comes from the ray simulation of the groove."""

import numpy as np
import pandas as pd
from matplotlib.lines import Line2D

from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.papers.vgroove_derivation import groove_angles_Blinn1977, vgroove_case
from reflectance.papers.vgroove_plot import (COLOURS, draw_angle, draw_arrow, draw_dimension, draw_groove,
                                      draw_top_view)
from reflectance.io.tables import write_csv

# Per case: what is blocked, along which direction, Blinn's closed form, the simulated fraction.
SPEC = {"b": ("masking", "E", "eye", "G_b", "G_masking_simulated", "escapes"),
        "c": ("shadowing", "L", "light", "G_c", "G_shadowing_simulated", "is lit")}

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    name = cfg["construction_case"]
    case = cfg["cases"][name]
    blocked, V, colour, G_name, sim_name, verb = SPEC[name]
    sim, r = vgroove_case(case["light"], case["eye"], n_rays=cfg["n_rays"], n_keep=cfg["n_drawn_rays"])
    if r["case"] != name:
        raise ValueError(f"config.yaml: figures.blinn_1977.fig1_4.cases.{name} gives Blinn's case "
                         f"{r['case']!r}, not {name!r}.")
    g = groove_angles_Blinn1977(sim, blocked)
    axis = sim.basis[1]  # g, along the groove
    deg = {k: np.degrees(getattr(g, k)) for k in "abcdef"}
    ratio_3d = r[f"N{V}"] / r["EH"]                     # (N.E)/(E.H) with E itself
    V2 = g.direction
    ratio_2d = V2[1] / (sim.H2 @ V2)                    # the same with its projection E'
    text = {
        "fig2": f"L\u00b7g = {r['L'] @ axis:+.4f}, E\u00b7g = {r['E'] @ axis:+.4f}: equal and opposite, "
                f"so H is perpendicular to the groove g, in the plane of the figure\n(N\u00b7{V})/(H\u00b7{V}) = {ratio_3d:.4f};  with the "
                f"projection {V}': {ratio_2d:.4f}",
        "fig3": f"1 \u2212 m/l = 1 \u2212 {g.m_over_l_lengths:.4f} = {1 - g.m_over_l_lengths:.4f}\n"
                f"simulated ({cfg['n_rays']:,} points on the facet): {r[sim_name]:.4f}\n"
                f"closed form {G_name} = {r[G_name]:.4f}",
        "fig4": f"m/l = sin f / sin b = sin {deg['f']:.2f}\u00b0 / sin {deg['b']:.2f}\u00b0 = "
                f"{g.m_over_l_sines:.4f}\nsin b = {np.sin(g.b):.4f}, cos e = {np.cos(g.e):.4f};  "
                f"c = {deg['c']:.2f}\u00b0 = 2d = 2 \u00d7 {deg['d']:.2f}\u00b0\n"
                f"d + a = {deg['d']:.2f}\u00b0 + {deg['a']:.2f}\u00b0 = {deg['d'] + deg['a']:.2f}\u00b0",
    }

    # On the figure the same numbers as text[...] (the CSV), broken into lines that fit a third of the page.
    shown = {
        "fig2": f"L\u00b7g = {r['L'] @ axis:+.4f}, E\u00b7g = {r['E'] @ axis:+.4f}:\nequal and opposite, "
                f"so H \u22a5 g\n(N\u00b7{V})/(H\u00b7{V}) = {ratio_3d:.4f}; with {V}': {ratio_2d:.4f}",
        "fig3": f"1 \u2212 m/l = 1 \u2212 {g.m_over_l_lengths:.4f} = {1 - g.m_over_l_lengths:.4f}\n"
                f"simulated, {cfg['n_rays']:,} points: {r[sim_name]:.4f}\n"
                f"closed form ${G_name}$ = {r[G_name]:.4f}",
        "fig4": f"m/l = sin f / sin b = {g.m_over_l_sines:.4f}\n"
                f"(f = {deg['f']:.2f}\u00b0, b = {deg['b']:.2f}\u00b0)\n"
                f"sin b = {np.sin(g.b):.4f} = cos e = {np.cos(g.e):.4f}\n"
                f"c = {deg['c']:.2f}\u00b0 = 2d;  d + a = {deg['d'] + deg['a']:.2f}\u00b0",
    }

    fig = new_figure(PRINT_WIDTH_IN, 0.5 * PRINT_WIDTH_IN)
    ax2, ax3, ax4 = fig.subplots(1, 3, gridspec_kw={"width_ratios": [1, 1.1, 1.1]})
    draw_top_view(ax2, sim, r["L"], r["E"], r["H"])  # Fig. 2: looking down N
    titles = {"fig2": "Fig. 2 \u2014 top view (along N)", "fig3": f"Fig. 3 \u2014 1 \u2212 m/l {verb}",
              "fig4": "Fig. 4 \u2014 m/l, law of sines"}
    # Fig. 3: the part of the facet whose light escapes.
    draw_groove(ax3, sim, names=False, normal_label_offset=(0.06, 0.0))
    for P, label, dx, dy in ((g.A, "A", 0.0, 0.08), (g.B, "B", 0.14, -0.03), (g.C, "C", 0.0, 0.08)):
        ax3.text(P[0] + dx, P[1] + dy, label, ha="center", va="center", fontsize=TEXT_SIZE["symbol"])
    draw_dimension(ax3, g.A, g.B, -sim.H2 * 0.13, "l")
    draw_dimension(ax3, g.P, g.B, -sim.H2 * 0.3, "m")
    key = [Line2D([], [], color=COLOURS["light"], label="incident on AB"),
           Line2D([], [], color=COLOURS["other"], label="incident on BC"),
           Line2D([], [], color=COLOURS["eye"], label="reflected, escapes"),
           Line2D([], [], color=COLOURS["masked"], marker="x", label="reflected, blocked")]
    ax3.legend(handles=key, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=2, frameon=False,
               fontsize=TEXT_SIZE["annotation"], handlelength=1.4, columnspacing=0.8, borderaxespad=0.2)
    # Fig. 4: the triangle B, C, P and Blinn's angles.
    draw_groove(ax4, sim, rays=False, vectors=False, names=True)
    ax4.plot(*np.column_stack([g.P, g.C]), color=COLOURS[colour], lw=1.4)
    up = np.array([0.0, 1.0])
    top = g.P[1] + (g.B[0] - g.P[0]) * (g.C[1] - g.P[1]) / (g.C[0] - g.P[0])  # the vertical at B meets PC
    ax4.plot([g.B[0], g.B[0]], [g.B[1], top], color="0.4", ls="--", lw=0.8)
    ax4.text(*(g.P + [-0.09, 0.07]), "P", ha="center", va="center", fontsize=TEXT_SIZE["symbol"])
    draw_arrow(ax4, g.P, 0.45 * up, "N", COLOURS["normal"], ls="--")
    draw_arrow(ax4, g.P, 0.45 * sim.H2, "H", "k")
    draw_arrow(ax4, g.P, 0.55 * V2, f"{V}'", COLOURS[colour], label_offset=(0.0, 0.08))  # off line PC
    # Blinn: c is the triangle's angle at B (PBC, its whole arc), d the angle from the vertical to BC
    # (c = 2d by the groove's symmetry), each on an arc of its own; b's and c's labels off the lines.
    for vertex, u, v, radius, label, at, out in (
            (g.P, up, sim.H2, 0.3, "a", 0.5, 1.45), (g.P, sim.H2, V2, 0.22, "e", 0.5, 1.45),
            (g.P, g.B - g.P, V2, 0.14, "b", 0.5, 1.35), (g.B, g.A - g.B, g.C - g.B, 0.1, "c", 0.8, 1.75),
            (g.B, up, g.C - g.B, 0.21, "d", 0.5, 1.35), (g.C, g.B - g.C, g.P - g.C, 0.35, "f", 0.5, 1.45)):
        draw_angle(ax4, vertex, u, v, radius, label, label_radius=out, label_at=at)
    side = np.array([np.sin(sim.alpha), -np.cos(sim.alpha)]) * 0.16  # outside BC
    draw_dimension(ax4, g.B, g.C, side, "l")
    draw_dimension(ax4, g.P, g.B, -sim.H2 * 0.16, "m")
    ax4.set(xlim=(g.A[0] - 0.1, g.C[0] + 0.25), ylim=(g.B[1] - 0.4, 0.6))
    fig.subplots_adjust(left=0.03, right=0.995, top=0.84, bottom=0.32, wspace=0.1)
    for ax, key in ((ax2, "fig2"), (ax3, "fig3"), (ax4, "fig4")):  # aligned across the panels
        box = ax.get_position()  # titles and notes on common lines (equal-aspect drawings differ in height)
        fig.text((box.x0 + box.x1) / 2, 0.86, titles[key], ha="center", va="bottom",
                 size=STYLE["axes.titlesize"])
        fig.text((box.x0 + box.x1) / 2, 0.25, shown[key], ha="center", va="top",
                 fontsize=TEXT_SIZE["annotation"], linespacing=1.4)
    fig.suptitle(f"Blinn 1977, Figs. 2\u20134 \u2014 Blinn's case {name} ({blocked}): L (\u03b8, \u03c6) = "
                 f"({case['light']['theta_deg']:g}\u00b0, {case['light']['phi_deg']:g}\u00b0), E = "
                 f"({case['eye']['theta_deg']:g}\u00b0, {case['eye']['phi_deg']:g}\u00b0)", y=0.99)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    row = {"case": name, "blocked": blocked, **{f"{k}_deg": v for k, v in deg.items()},
           "m": g.m, "l": g.l, "m_over_l_lengths": g.m_over_l_lengths,
           "m_over_l_sines": g.m_over_l_sines, G_name: r[G_name], "G_simulated": r[sim_name],
           "L_dot_g": r["L"] @ axis, "E_dot_g": r["E"] @ axis, "ratio_3d": ratio_3d,
           "ratio_projected": ratio_2d, **{f"printed_{k}": v.replace("\n", "; ") for k, v in text.items()}}
    pd.DataFrame([row]).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    log.info("m/l: lengths %.6f, law of sines %.6f, 1 - %s %.6f", g.m_over_l_lengths,
             g.m_over_l_sines, G_name, 1 - r[G_name])
