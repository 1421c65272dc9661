"""Lecture (Russin, Module 3B), "Distribution of microfacet orientations": the slide's own D's against
Cook & Torrance 1982's (the slide claims no error in its own; the title says only what is compared). (a) Its Gaussian D = exp(-(alpha m)^2), m in the numerator, against Torrance &
Sparrow's / Cook & Torrance's exp(-(alpha/m)^2); (b) its Beckmann D with 4 m^2 cos^4 in the denominator
against Cook & Torrance's printed m^2 cos^4 and the normalised pi m^2 cos^4, with the integral of
D cos(alpha) over the hemisphere of each (1 for a normalised distribution)."""

import numpy as np
import pandas as pd
from scipy.integrate import quad

from matplotlib.lines import Line2D

from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, lines_under, new_figure, savefig
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
    fig = new_figure(PRINT_WIDTH_IN, 4.0)  # the print width: its text prints at the figures' sizes
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
        names = {}
        # one colour per text in both panels: the slide vermilion, C&T blue, the normalised form green
        for key, colour, name in (("beckmann_slide", OKABE_ITO[1], "slide: 1/(4m\u00b2cos\u2074)"),
                                  ("beckmann_CookTorrance1982", OKABE_ITO[0], "C&T printed: 1/(m\u00b2cos\u2074)"),
                                  ("beckmann_normalised", OKABE_ITO[2], "normalised: 1/(\u03c0m\u00b2cos\u2074)")):
            axes[1].plot(np.degrees(alpha), curves[f"{key}_m{m:g}"], color=colour, ls=style,
                         label=f"{name}, m = {m:g}")
            names[name] = colour
    table = pd.DataFrame(rows)
    # (b)'s angle axis ends where every curve has fallen below its floor, to the next 10 degrees
    floor = 1e-3
    beckmann = np.array([v for k, v in curves.items() if k.startswith("beckmann")])
    last = np.degrees(alpha[(beckmann >= floor).any(axis=0)].max())
    for ax, title, ylabel, right in ((axes[0], "(a) Gaussian: m in the numerator\nor the denominator", "D", 90),
                                     (axes[1], "(b) Beckmann: the constant in front", "D (log scale)",
                                      min(90, 10 * np.ceil(last / 10)))):
        ax.set(xlim=(0, right), xticks=np.arange(0, right + 1, 30 if right > 60 else 20),
               xlabel="\u03b1 between N and H (\u00b0; in radians in D)", ylabel=ylabel, title=title)
        ax.grid(True)
    axes[1].set(yscale="log", ylim=(floor, 30))
    # the slide's point, "m near 0.2 ... nearly smooth": with m in the numerator the smallest m
    # is the flattest curve, said beside the curve (in the empty lower right, clear of every curve)
    smooth = min(cfg["m"])
    flat = curves[f"gaussian_slide_m{smooth:g}"][-1]
    # (the slide says "nearly smooth" of Cook & Torrance's m, not of this one: the note quotes
    # nothing; in the slide's Gaussian, m in the numerator, that m is the flattest: the erratum
    # lecture-gaussian-m, workflow/reflectance/papers/errata.py)
    note = axes[0].annotate(f"slide, m = {smooth:g}:\nD = {flat:.2f} at "
                            f"{np.degrees(alpha[-1]):.0f}\u00b0,\nnearly flat",
                            xy=(np.degrees(alpha[-1]) - 1, flat), xytext=(1.0, 0.16), textcoords="axes fraction",
                            ha="right", va="bottom", fontsize="small", color=OKABE_ITO[1], zorder=5,
                            arrowprops=dict(arrowstyle="->", color=OKABE_ITO[1], lw=0.8,
                                            connectionstyle="arc3,rad=0.25"))
    # colour says the text, line style says m (the same in both panels: the key sits under (a))
    axes[0].legend(handles=[Line2D([], [], color=OKABE_ITO[1], label="slide: e$^{-(\\alpha m)^2}$"),
                            Line2D([], [], color=OKABE_ITO[0], label="C&T: e$^{-(\\alpha/m)^2}$"),
                            Line2D([], [], color="0.3", label=f"m = {cfg['m'][0]:g}"),
                            Line2D([], [], color="0.3", ls=(0, (4, 2)), label=f"m = {cfg['m'][1]:g}")],
                   loc="upper left", bbox_to_anchor=(-0.15, -0.2), ncols=2, columnspacing=1.5)
    axes[1].legend(handles=[Line2D([], [], color=c, label=n) for n, c in names.items()],
                   loc="upper left", bbox_to_anchor=(-0.15, -0.2))
    fig.suptitle("\u201cDistribution of microfacet orientations\u201d (Russin's lecture): the slide's D's\n"
                 "beside Cook & Torrance 1982's and the normalised Beckmann", y=0.995, va="top", linespacing=1.3)
    fig.subplots_adjust(wspace=0.3, top=0.78, bottom=0.33, left=0.09, right=0.98)
    covered = lines_under(axes[0], note)
    if covered:
        raise RuntimeError(f"the annotation in (a) covers the curves {covered}")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)
    pd.DataFrame(curves).pipe(write_csv, snakemake.output.csv, float_format="%.6g")
    table.pipe(write_csv, snakemake.output.summary, float_format="%.8g")
    log.info("%s", table.to_string())
