"""Lecture (Russin, Module 3B), "BRDF" slide: "Figure 9.18 (7.17 3rd edition) shows sample BRDFs" -
diffuse, Phong, the lecture's normalised Blinn-Phong and Cook-Torrance, as polar plots in the plane
of incidence. The radius is the BRDF f(L, V) itself along each outgoing direction V (not
f cos theta_o): a Lambertian surface is then "a simple hemisphere", as the slide says."""

import numpy as np
import pandas as pd
from matplotlib.ticker import MaxNLocator

from reflectance.optics.brdf import brdf
from reflectance.io.figures import new_figure, savefig
from reflectance.papers.polar import plane_of_incidence_vectors
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

# config key -> (reflectance.optics.brdf method, panel title)
MODELS = {
    "diffuse": ("Lambert", "Diffuse (Lambert)"),
    "phong": ("Phong1975", "Phong, (R\u00b7V)$^{c_1}$/(N\u00b7L)"),
    "blinn_phong": ("BlinnPhong_AkenineMoller2008", "Blinn-Phong, (m+8)/(8\u03c0) cos$^m\\theta_h$"),
    "cook_torrance": ("CookTorrance1982", "Cook-Torrance, DGF/(4(N\u00b7L)(N\u00b7V))"),
}


def parameters_text(params):
    return ", ".join(f"{k} = {v:g}" if not isinstance(v, str) else f"{v}" for k, v in params.items())


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    theta_i = np.radians(cfg["incidence_deg"])
    theta_o = np.radians(np.arange(-90.0, 90.0 + 1e-9, cfg["polar_step_deg"]))
    L, V, N = plane_of_incidence_vectors(theta_i, theta_o)  # light on the -x side (on the left)

    table = {"theta_o_deg": np.degrees(theta_o)}
    for key, (method, _) in MODELS.items():
        table[key] = brdf(L, V, N, method, **cfg["models"][key])
    pd.DataFrame(table).pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    fig = new_figure(15, 3.9)
    for i, (key, (method, title)) in enumerate(MODELS.items()):
        ax = fig.add_subplot(1, len(MODELS), i + 1, projection="polar")
        ax.set_theta_zero_location("N")
        ax.set_theta_direction(-1)
        ax.set_thetalim(-np.pi / 2, np.pi / 2)
        f = table[key]
        top = 1.15 * f.max()
        ax.plot(theta_o, f, color="#1f4e9c", lw=1.8)
        ax.fill(theta_o, f, color="#1f4e9c", alpha=0.15)
        ax.plot([-theta_i, -theta_i], [0, top], color="#d98c00", lw=1.5, label="towards light L")
        ax.plot([theta_i, theta_i], [0, top], color="0.4", lw=1, ls="--", label="mirror direction")
        ax.set_ylim(0, top)
        ax.set_title(f"{title}\n{parameters_text(cfg['models'][key])}", fontsize=8.5, pad=2)
        ax.tick_params(labelsize=7)
        ax.yaxis.set_major_locator(MaxNLocator(3))
        ax.text(0.5, 0.12, f"max f = {f.max():.3g} sr$^{{-1}}$", transform=ax.transAxes,
                ha="center", fontsize=8)
        log.info("%s: max f %.6g at theta_o = %.2f deg", key, f.max(),
                 np.degrees(theta_o[np.argmax(f)]))
    fig.axes[0].legend(loc="upper left", bbox_to_anchor=(-0.08, 1.02), fontsize=7, frameon=False)
    fig.suptitle(f"Lecture (Russin, Module 3B), sample BRDFs in the plane of incidence: radius = "
                 f"f(L, V) in sr$^{{-1}}$, incidence {cfg['incidence_deg']:g}\u00b0 "
                 f"(light on the left)", fontsize=11)
    fig.subplots_adjust(left=0.03, right=0.98, top=0.84, bottom=-0.12, wspace=0.25)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
