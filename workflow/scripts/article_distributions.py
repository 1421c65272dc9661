"""Wikipedia, "Specular highlight" (oldid 793299363), "Models of specular highlight": each model's
k_spec exactly as the article prints it, (top) as an image of the highlight on a flat plane lit by
a point light and seen from a point eye, (bottom) along the plane of incidence for a distant light.
The article's k_spec are not one quantity: Phong, Blinn-Phong, Heidrich-Seidel and Ward include the
N.L of the light, the Gaussian, Beckmann and mixture are bare facet distributions D(N.H), and its
Cook-Torrance k_spec is a BRDF. Each panel is scaled to its own maximum."""

import re

import numpy as np
import pandas as pd

from reflectance.optics.brdf import brdf
from reflectance.optics.microfacet import distribution
from reflectance.io.figures import PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.papers.polar import plane_of_incidence_vectors
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv


def unit(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def k_spec(key, q, L, V, N):
    """The article's k_spec of model ``key`` with parameters ``q`` (unit vectors, shape (..., 3))."""
    NL = np.maximum(np.sum(N * L, axis=-1), 0.0)
    NH = np.sum(N * unit(L + V), axis=-1)
    if key == "phong":  # (R.V)^n
        return brdf(L, V, N, "Phong1975", p_d=0.0, p_s=1.0, c1=q["n"]) * NL
    if key == "blinn_phong":  # (N.H)^n
        return brdf(L, V, N, "BlinnPhong1977", p_d=0.0, p_s=1.0, c1=q["n"]) * NL
    if key == "gaussian":  # exp(-(angle(N, H)/m)^2)
        return distribution(NH, "Gaussian_CookTorrance1982", m=q["m"])
    if key == "beckmann":  # exp(-tan^2(a)/m^2) / (pi m^2 cos^4 a)
        return distribution(NH, "Beckmann1963", m=q["m"], convention="physical")
    if key == "heidrich_seidel":  # (V.R)^s, with the fibre T = D projected into the plane
        return brdf(L, V, N, "HeidrichSeidel1998", T=q["thread_direction"], s=q["s"], k_d=0.0) * NL
    if key == "ward":  # rho_s / sqrt((N.L)(N.V)) (N.L) / (4 pi ax ay) exp(...)
        X = unit(q["tangent_x"])
        return brdf(L, V, N, "Ward1992", X=X, Y=np.cross(N, X), rho_s=q["rho_s"],
                    alpha_x=q["alpha_x"], alpha_y=q["alpha_y"]) * NL
    if key == "cook_torrance":  # D F G / (4 (V.N)(N.L)), Beckmann D, exact dielectric F
        return brdf(L, V, N, "CookTorrance1982", m=q["m"], n=q["n"], k=0.0, convention="physical")
    if key == "mixture":  # weighted average of Beckmann lobes
        return distribution(NH, "mixture", lobes=[tuple(lobe) for lobe in q["lobes"]],
                            base="Beckmann1963", convention="physical")
    raise ValueError(f"unknown model {key!r} in figures.article.distributions.models")


TITLES = {"phong": "Phong (R\u00b7V)$^n$", "blinn_phong": "Blinn-Phong (N\u00b7H)$^n$",
          "gaussian": "Gaussian", "beckmann": "Beckmann", "heidrich_seidel": "Heidrich-Seidel",
          "ward": "Ward", "cook_torrance": "Cook-Torrance", "mixture": "two Beckmann lobes"}

# solid and dashed in turn; the eighth (the dark yellow) dash-dotted: under deuteranopia it is
# near the dashed vermilion in lightness
LINESTYLES = ("-", "--", "-", "--", "-", "--", "-", "-.")

SYMBOLS = {"rho_s": "$\\rho_s$", "alpha_x": "$\\alpha_x$", "alpha_y": "$\\alpha_y$", "thread_direction": "fibre D",
           "tangent_x": "x axis", "lobes": "(w, m)"}


def number_text(value):
    """A parameter as the article writes it: 0.2, (1, 1, 0), or (0.4, 0.4), (0.6, 0.2) for lobes."""
    if isinstance(value, (list, tuple)):
        if value and isinstance(value[0], (list, tuple)):
            return ", ".join(number_text(v) for v in value)
        return "(" + ", ".join(f"{v:g}" for v in value) + ")"
    return f"{value:g}"


def parameters_text(q):
    items = [f"{SYMBOLS.get(k, k)} = {number_text(v)}" for k, v in q.items()]
    lines, line = [], ""
    for item in items:  # at most about 30 printed characters per line
        if line and len(re.sub(r"[$\\]|rho|alpha", "", line + item)) > 30:
            lines.append(line)
            line = item
        else:
            line = f"{line}, {item}" if line else item
    return "\n".join(lines + [line])


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    N = np.array([0.0, 0.0, 1.0])
    a = cfg["plane_half_size"]
    u = np.linspace(-a, a, cfg["resolution"])
    P = np.stack([*np.meshgrid(u, u, indexing="xy"), np.zeros((u.size, u.size))], axis=-1)
    L_img, V_img = unit(np.asarray(cfg["light_position"]) - P), unit(np.asarray(cfg["eye_position"]) - P)
    # open interval: at the horizon Ward's 1/sqrt(N.V) diverges (and cos(90 deg) is 6e-17, not 0)
    theta_o = np.radians(np.arange(-90.0 + cfg["polar_step_deg"], 90.0 - 1e-9, cfg["polar_step_deg"]))
    L_dir, V_dir, _ = plane_of_incidence_vectors(np.radians(cfg["incidence_deg"]), theta_o)  # light at -x

    fig = new_figure(PRINT_WIDTH_IN, 1.08 * PRINT_WIDTH_IN)
    grid = fig.add_gridspec(3, 4, height_ratios=[1, 1, 0.95], hspace=0.5, wspace=0.06, top=0.9,
                            bottom=0.07, left=0.01, right=0.99)
    curves = {"theta_o_deg": np.degrees(theta_o)}
    line_ax = fig.add_subplot(grid[2, :3])
    for i, (key, q) in enumerate(cfg["models"].items()):
        image = k_spec(key, q, L_img, V_img, N)
        ax = fig.add_subplot(grid[i // 4, i % 4])
        ax.imshow(image / image.max(), origin="lower", extent=(-a, a, -a, a), cmap="inferno",
                  vmin=0, vmax=1, interpolation="nearest")
        ax.set_title(TITLES[key], pad=3)
        ax.text(0.5, -0.03, f"{parameters_text(q)}\nmax k$_{{spec}}$ = {image.max():.3g}", transform=ax.transAxes,
                ha="center", va="top", fontsize=TEXT_SIZE["table"], linespacing=1.25)
        ax.set_xticks([])
        ax.set_yticks([])
        curves[key] = k_spec(key, q, L_dir, V_dir, N)
        line_ax.plot(np.degrees(theta_o), curves[key] / curves[key].max(), label=TITLES[key],
                     ls=LINESTYLES[i % len(LINESTYLES)])
        log.info("%s: image max %.6g, plane-of-incidence max %.6g at %.2f deg", key, image.max(),
                 curves[key].max(), np.degrees(theta_o[np.argmax(curves[key])]))
    pd.DataFrame(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    line_ax.axvline(cfg["incidence_deg"], color="0.6", ls="-", lw=0.8, zorder=0)
    line_ax.set(xlim=(0, 90), xticks=np.arange(0, 91, 15), ylim=(0, 1.05),
                xlabel="view angle $\\theta_o$ in the plane of incidence (\u00b0; light at "
                       f"\u2212{cfg['incidence_deg']:g}\u00b0; grey: the mirror direction)",
                ylabel="k$_{spec}$ / its maximum")
    line_ax.legend(ncol=1, loc="upper left", bbox_to_anchor=(1.03, 1.05), labelspacing=0.3)
    line_ax.grid(True)
    fig.suptitle("Wikipedia, \u201cSpecular highlight\u201d: the article's k$_{spec}$ as printed, on the plane z = 0\n"
                 f"lit from {number_text(cfg['light_position'])}, seen from {number_text(cfg['eye_position'])}; "
                 "each image and curve scaled to its maximum", y=0.995)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
