"""Lecture (Russin, Module 3B), "Distribution of microfacet orientations": the slide's own D's against
Cook & Torrance 1982's (the slide claims no error in its own; the title says only what is compared). (a) Its Gaussian D = exp(-(alpha m)^2), m in the numerator, against Torrance &
Sparrow's / Cook & Torrance's exp(-(alpha/m)^2); (b) its Beckmann D with 4 m^2 cos^4 in the denominator
against Cook & Torrance's printed m^2 cos^4 and the normalised pi m^2 cos^4, with the integral of
D cos(alpha) over the hemisphere of each (1 for a normalised distribution)."""

import numpy as np
import pandas as pd
from scipy.integrate import quad

from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, new_figure, savefig
from reflectance.optics.microfacet import distribution_Beckmann1963, distribution_Gaussian_CookTorrance1982
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv


def projected_integral(D):
    """integral of D(alpha) cos(alpha) d omega over the hemisphere (2 pi sin cos d alpha)."""
    return quad(lambda a: D(np.cos(a)) * np.cos(a) * np.sin(a) * 2 * np.pi, 0, np.pi / 2,
                limit=200, epsabs=1e-12)[0]


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    alpha = np.radians(np.arange(0.0, 90.0 + 1e-9, cfg["alpha_step_deg"]))[:-1]
    curves, rows = {"alpha_deg": np.degrees(alpha)}, []
    fig = new_figure(PRINT_WIDTH_IN, 4.6)  # the print width: its text prints at the figures' sizes
    axes = fig.subplots(1, 2)
    for m, style in zip(cfg["m"], ("-", (0, (4, 2)))):
        forms = {  # name -> D(cos alpha), each from its text
            # the slide: "Torrance and Sparrow (1967) used a simple Gaussian: D = e^{-(alpha m)^2}"
            "gaussian_slide": lambda c, m=m: np.exp(-(np.arccos(c) * m) ** 2),
            # Cook & Torrance 1982 eq. for the Gaussian model: D = c e^{-(alpha/m)^2}, c = 1
            "gaussian_correct": lambda c, m=m: distribution_Gaussian_CookTorrance1982(c, m),
            # the slide's Beckmann: e^{-(tan d / m)^2} / (4 m^2 cos^4 d)
            "beckmann_slide": lambda c, m=m: distribution_Beckmann1963(c, m) / 4.0,
            # Cook & Torrance 1982 as printed: 1/(m^2 cos^4) e^{...}; normalised: with 1/pi
            "beckmann_CookTorrance1982": lambda c, m=m: distribution_Beckmann1963(c, m),
            "beckmann_normalised": lambda c, m=m: distribution_Beckmann1963(c, m, "physical"),
        }
        for key, D in forms.items():
            curves[f"{key}_m{m:g}"] = D(np.cos(alpha))
            rows.append({"form": key, "m": m, "D_at_0": float(D(1.0)),
                         "integral_D_cos_domega": projected_integral(D)})
        label = {"gaussian_slide": "slide: e$^{-(\\alpha m)^2}$", "gaussian_correct": "C&T: e$^{-(\\alpha/m)^2}$"}
        for key, colour in (("gaussian_slide", OKABE_ITO[1]), ("gaussian_correct", OKABE_ITO[0])):
            axes[0].plot(np.degrees(alpha), curves[f"{key}_m{m:g}"], color=colour, ls=style,
                         label=f"{label[key]}, m = {m:g}")
        # one colour per text in both panels: the slide vermilion, C&T blue, the normalised form green
        for key, colour, name in (("beckmann_slide", OKABE_ITO[1], "slide: 1/(4m\u00b2cos\u2074)"),
                                  ("beckmann_CookTorrance1982", OKABE_ITO[0], "C&T printed: 1/(m\u00b2cos\u2074)"),
                                  ("beckmann_normalised", OKABE_ITO[2], "normalised: 1/(\u03c0m\u00b2cos\u2074)")):
            axes[1].plot(np.degrees(alpha), curves[f"{key}_m{m:g}"], color=colour, ls=style,
                         label=f"{name}, m = {m:g}")
    table = pd.DataFrame(rows)
    for ax, title, ylabel in ((axes[0], "(a) Gaussian: m in the\nnumerator or the denominator", "D"),
                              (axes[1], "(b) Beckmann:\nthe constant in front", "D (log scale)")):
        ax.set(xlim=(0, 90), xticks=np.arange(0, 91, 30),
               xlabel="\u03b1 between N and H (\u00b0; in radians in D)",
               ylabel=ylabel, title=title)
        ax.grid(True)
    # the slide's point, "m near 0.2 ... nearly smooth": with m in the numerator the smallest m
    # is the flattest curve, said on the curve, from the curve (alpha in radians in the exponent)
    smooth = min(cfg["m"])
    flat = curves[f"gaussian_slide_m{smooth:g}"][-1]
    axes[0].annotate(f"slide, \"nearly smooth\" m = {smooth:g}:\nD = {flat:.2f} at "
                     f"{np.degrees(alpha[-1]):.0f}\u00b0, the flattest",
                     xy=(np.degrees(alpha[-1]), flat), xytext=(31, 0.49), ha="left",
                     fontsize="small", color=OKABE_ITO[1], zorder=5,
                     bbox=dict(facecolor="white", edgecolor="none", alpha=0.9, pad=1.5),
                     arrowprops=dict(arrowstyle="->", color=OKABE_ITO[1], lw=0.8))
    axes[1].set(yscale="log", ylim=(1e-3, 30))
    axes[0].legend(loc="upper left", bbox_to_anchor=(-0.15, -0.22))
    axes[1].legend(loc="upper left", bbox_to_anchor=(-0.15, -0.22))
    fig.suptitle("\u201cDistribution of microfacet orientations\u201d (Russin's lecture): the slide's D's\n"
                 "beside Cook & Torrance 1982's and the normalised Beckmann", y=0.995, va="top", linespacing=1.3)
    fig.subplots_adjust(wspace=0.32, top=0.8, bottom=0.42, left=0.09, right=0.98)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    pd.DataFrame(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    table.pipe(write_csv, snakemake.output.summary, float_format="%.8g")
    log.info("%s", table.to_string())
