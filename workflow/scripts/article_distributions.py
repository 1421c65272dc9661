"""Wikipedia, "Specular highlight" (oldid 793299363), "Models of specular highlight": each model's
k_spec exactly as the article prints it, (top) as an image of the highlight on a flat plane lit by
a point light and seen from a point eye, (bottom) along the plane of incidence for a distant light.
The article's k_spec are not one quantity: Phong, Blinn-Phong, Heidrich-Seidel and Ward include the
N.L of the light, the Gaussian, Beckmann and mixture are bare facet distributions D(N.H), and its
Cook-Torrance k_spec is a BRDF. Each panel is scaled to its own maximum."""

import numpy as np
import pandas as pd

from reflectance.optics.brdf import brdf
from reflectance.optics.microfacet import distribution
from reflectance.io.figures import new_figure, savefig
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

    fig = new_figure(12, 10.2)
    grid = fig.add_gridspec(3, 4, height_ratios=[1, 1, 0.72], hspace=0.3, wspace=0.04, top=0.92,
                            bottom=0.06, left=0.01, right=0.99)
    curves = {"theta_o_deg": np.degrees(theta_o)}
    line_ax = fig.add_subplot(grid[2, :3])
    for i, (key, q) in enumerate(cfg["models"].items()):
        image = k_spec(key, q, L_img, V_img, N)
        ax = fig.add_subplot(grid[i // 4, i % 4])
        ax.imshow(image / image.max(), origin="lower", extent=(-a, a, -a, a), cmap="inferno",
                  vmin=0, vmax=1, interpolation="nearest")
        items = [f"{k} = {v}" for k, v in q.items()]
        half = (len(items) + 1) // 2 if len(", ".join(items)) > 34 else len(items)
        params = ", ".join(items[:half]) + ("\n" + ", ".join(items[half:]) if items[half:] else "")
        ax.set_title(f"{TITLES[key]}\n{params}\nmax k$_{{spec}}$ = {image.max():.3g}", fontsize=8.5, pad=3)
        ax.set_xticks([])
        ax.set_yticks([])
        curves[key] = k_spec(key, q, L_dir, V_dir, N)
        line_ax.plot(np.degrees(theta_o), curves[key] / curves[key].max(), lw=1.4, label=TITLES[key],
                     ls="-" if i % 2 == 0 else "--")
        log.info("%s: image max %.6g, plane-of-incidence max %.6g at %.2f deg", key, image.max(),
                 curves[key].max(), np.degrees(theta_o[np.argmax(curves[key])]))
    pd.DataFrame(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    line_ax.axvline(cfg["incidence_deg"], color="0.5", ls="--", lw=1)
    line_ax.set(xlim=(0, 90), xticks=np.arange(0, 91, 15), ylim=(0, 1.05),
                xlabel="viewing direction in the plane of incidence \u03b8o, mirror side (\u00b0; light at "
                       f"\u2212{cfg['incidence_deg']:g}\u00b0, dashed: mirror direction)",
                ylabel="k$_{spec}$ / its maximum")
    line_ax.legend(ncol=1, fontsize=8.5, loc="upper left", bbox_to_anchor=(1.02, 1.02))
    line_ax.grid(True)
    fig.suptitle("Wikipedia, \u201cSpecular highlight\u201d: the article's k$_{spec}$ as printed, on a plane "
                 f"z = 0 lit from {cfg['light_position']} and seen from {cfg['eye_position']} "
                 "(each image scaled to its maximum)", fontsize=11)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
