"""Blinn 1977, Fig. 1: the three cases of the V-groove, (a) no attenuation, (b) reflected light
partly masked, (c) incident light partly shadowed; each drawn from a ray simulation, with the
simulated escaping fraction beside Blinn's closed form G = min(1, G_b, G_c)."""

import pandas as pd

from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.papers.vgroove_derivation import vgroove_case
from reflectance.papers.vgroove_plot import COLOURS, draw_groove
from reflectance.io.tables import write_csv

TITLES = {"a": "(a) no attenuation", "b": "(b) reflected light masked",
          "c": "(c) incident light shadowed"}

with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    fig = new_figure(PRINT_WIDTH_IN, 0.5 * PRINT_WIDTH_IN)
    axes = fig.subplots(1, 3)
    rows = []
    for ax, name in zip(axes, sorted(cfg["cases"])):
        light, eye = cfg["cases"][name]["light"], cfg["cases"][name]["eye"]
        sim, r = vgroove_case(light, eye, n_rays=cfg["n_rays"], n_keep=cfg["n_drawn_rays"])
        if r["case"] != name:
            raise ValueError(
                f"config.yaml: figures.blinn_1977.fig1_4.cases.{name}: these L and E give Blinn's "
                f"case {r['case']!r}, not {name!r}; choose directions that show case {name}.")
        printed_sim = f"{r['G_simulated']:.4f}"
        printed_closed = f"{r['G_closed']:.4f}"
        draw_groove(ax, sim, names=True)
        ax.set_title(TITLES[name])
        ax.text(0.5, -0.02,
                f"L (\u03b8, \u03c6) = ({light['theta_deg']:g}\u00b0, {light['phi_deg']:g}\u00b0), "
                f"E = ({eye['theta_deg']:g}\u00b0, {eye['phi_deg']:g}\u00b0)\n"
                f"\u03b1 = {r['alpha_deg']:.1f}\u00b0;  $G_b$ = {r['G_b']:.3f}, $G_c$ = {r['G_c']:.3f}\n"
                f"min(1, $G_b$, $G_c$) = {printed_closed}\n"
                f"simulated ({cfg['n_rays']:,} rays): {printed_sim}",
                transform=ax.transAxes, ha="center", va="top", fontsize=TEXT_SIZE["annotation"],
                linespacing=1.4)
        rows.append({
            "case": name, "L_theta_deg": light["theta_deg"], "L_phi_deg": light["phi_deg"],
            "E_theta_deg": eye["theta_deg"], "E_phi_deg": eye["phi_deg"],
            **{f"{v}{axis}": r[v][i] for v in ("L", "E", "H") for i, axis in enumerate("xyz")},
            **{k: r[k] for k in ("alpha_deg", "NL", "NE", "NH", "EH", "G_b", "G_c", "G_closed",
                                 "G_simulated", "G_masking_simulated", "G_shadowing_simulated")},
            "n_rays": cfg["n_rays"], "printed_G_simulated": printed_sim,
            "printed_G_closed": printed_closed,
        })
        log.info("case %s: simulated %.6f, closed form %.6f", name, r["G_simulated"], r["G_closed"])
    # one entry per colour drawn: the masked part of the facet orange, the shadowed part purple
    # (not black: the groove's outline is black)
    handles = [axes[0].plot([], [], color=COLOURS.get(k, k), lw=w)[0] for k, w in
               (("light", 1), ("eye", 1), ("masked", 1), ("other", 1), ("facet", 4), ("masked", 4),
                ("shadowed", 4))]
    fig.legend(handles, ["incident ray (along L')", "reflected ray, escapes (along E')",
                         "reflected ray, masked", "ray landing on the other side",
                         "facet with normal H", "part of the facet masked",
                         "part of the facet shadowed"],
               loc="lower center", ncol=2, bbox_to_anchor=(0.5, 0.0))
    fig.suptitle("Blinn 1977, Fig. 1 \u2014 the three cases of the V-groove, in the plane of N and H",
                 y=0.99)
    fig.subplots_adjust(left=0.005, right=0.995, top=0.88, bottom=0.40, wspace=0.04)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    pd.DataFrame(rows).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
