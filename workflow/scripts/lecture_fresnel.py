"""Lecture (Russin, Module 3B), "Fresnel reflectance" slide: F against incidence angle for dielectrics
(exact equation with a real index) and metals (exact complex-index equation from measured n, k,
plotted as the reflectance of the illuminant's luminance Y), with Schlick's approximation dashed; and,
for the slide's "you can get color changes in specular regions", (c) the colour of each metal's F(theta)
against the angle: the XYZ of F(lambda, theta) under the illuminant, through the project's display
pipeline (gamut clip, transfer; the display white is a perfect reflector)."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.lines import Line2D

from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.display import XYZ_to_display, display_tag
from reflectance.optics.fresnel import fresnel, fresnel_slide_Russin
from reflectance.io.figures import PRINT_WIDTH_IN, lines_under, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.optics.spectra import load_material, wavelength_grid
from reflectance.io.tables import write_csv

with script_log(snakemake) as log:
    cfg, colour_cfg = snakemake.params.fig, snakemake.params.colour
    grid = wavelength_grid(**snakemake.params.wavelengths)
    # Y weights: Y = F @ W_Y is the luminance reflected, relative to the illuminant's (Y_white = 1)
    W = tristimulus_weights(grid, colour_cfg["illuminant"], colour_cfg["observer"])
    W_Y = W[:, 1]
    angles = np.arange(0.0, 90.0 + 1e-9, cfg["angle_step_deg"])
    c = np.clip(np.cos(np.radians(angles)), 0.0, 1.0)
    spectra_dir = Path(snakemake.input.spectra[0]).parent

    curves = {}  # (group, name, label) -> {method: F(angle)}
    for name, d in cfg["dielectrics"].items():
        curves[("dielectric", name, f"{name} {d['n']:g}")] = {
            **{method: fresnel(c, d["n"], 0.0, method=method) for method in ("exact", "schlick")},
            # the slide's printed equation, c(g - c) - 1 in its denominator: plotted as printed
            "slide": fresnel_slide_Russin(c, d["n"])}
    # (c) one exposure for every metal: XYZ times band_exposure, so a perfect mirror (F = 1, the
    # first band) shows below white and silver and aluminium stay apart from the page and each other
    exposure = cfg["band_exposure"]
    to_display = lambda XYZ: XYZ_to_display(exposure * XYZ, colour_cfg["space"], colour_cfg["gamut_clip"],
                                            expose=False, illuminant=colour_cfg["illuminant"],
                                            observer=colour_cfg["observer"], wavelengths=grid)
    bands = {"mirror (F = 1)": to_display(np.ones((len(c), len(grid))) @ W)}
    for name in cfg["materials"]:
        material = load_material(name, grid, spectra_dir=spectra_dir)
        F = {method: fresnel(c[:, None], material.n, material.k, method=method) for method in ("exact", "schlick")}
        curves[("metal", name, name)] = {method: F[method] @ W_Y for method in F}
        # the colour of the reflected light: XYZ of F under the illuminant (white Y = 1), exposed as above
        bands[name] = to_display(F["exact"] @ W)

    table = {"angle_deg": angles}
    for (_, name, _), F in curves.items():
        table[f"{name}_exact"], table[f"{name}_schlick"] = F["exact"], F["schlick"]
        if "slide" in F:
            table[f"{name}_slide"] = F["slide"]
    for name, rgb in list(bands.items())[1:]:
        for i, channel in enumerate("RGB"):
            table[f"{name}_display_{channel}"] = rgb[:, i]
    pd.DataFrame(table).pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    fig = new_figure(PRINT_WIDTH_IN, 0.5 * PRINT_WIDTH_IN + 0.22 * len(bands) + 0.9)
    grid_spec = fig.add_gridspec(2, 2, height_ratios=[0.5 * PRINT_WIDTH_IN, 0.22 * len(bands) + 0.25])
    axes = {"dielectric": fig.add_subplot(grid_spec[0, 0]), "metal": fig.add_subplot(grid_spec[0, 1])}
    for (group, name, label), F in curves.items():
        error = np.max(np.abs(F["schlick"] - F["exact"]))
        (line,) = axes[group].plot(angles, F["exact"], label=f"{label}{';' if group == 'dielectric' else ':'} {error:.3f}")
        axes[group].plot(angles, F["schlick"], color=line.get_color(), lw=1.0, ls="--")
        if "slide" in F:
            axes[group].plot(angles, F["slide"], color=line.get_color(), lw=1.0, ls=":", label=f"_{name}, the slide's F")
        log.info("%s: F(0) = %.5f, max |Schlick - exact| = %.5f at %.2f deg", name, F["exact"][0],
                 error, angles[np.argmax(np.abs(F["schlick"] - F["exact"]))])
    axes["dielectric"].set_title("(a) dielectrics (real index, k = 0)")
    axes["metal"].set_title(f"(b) metals (measured n, k; Y under {colour_cfg['illuminant']})")
    for ax in axes.values():
        ax.set(xlabel="incidence angle \u03b8 (degrees)", ylabel="reflectance F", xlim=(0, 90),
               ylim=(0, 1.01), xticks=np.arange(0, 91, 15))
        ax.grid(True)
    # the line styles in the legends, beside each material's max |Schlick - exact|
    styles = {"dielectric": [("exact Fresnel", "-"), ("Schlick 1994", "--"),
                             ("the slide\u2019s printed F", ":")],
              "metal": [("exact Fresnel", "-"), ("Schlick 1994", "--")]}
    # two keys per panel: the materials with their max |Schlick - exact|, and the line styles
    for group, where, style_where in (("dielectric", "upper left", (0.0, 0.32)), ("metal", "lower left", (0.5, 0.3))):
        ax = axes[group]
        title = ("n; " if group == "dielectric" else "") + "max |Schlick \u2212 exact|"
        legends = [ax.legend(loc=where, handlelength=1.4, labelspacing=0.25, title=title, borderpad=0.2,
                             alignment="left", title_fontsize="small", fontsize="small")]
        ax.add_artist(legends[0])
        legends.append(ax.legend(handles=[Line2D([], [], color="0.3", lw=1.0 if ls != "-" else 1.5, ls=ls, label=label)
                                          for label, ls in styles[group]],
                                 loc="lower left", bbox_to_anchor=style_where, handlelength=2.0,
                                 labelspacing=0.25, fontsize="small"))
        for legend in legends:
            covered = lines_under(ax, legend)
            if covered:
                raise RuntimeError(f"a legend of the {group}s covers the curves {covered}")
    ax = fig.add_subplot(grid_spec[1, :])  # (c) one band per metal: its colour at each angle
    # the angle axis is linear in 1 - cos(theta), so the grazing range, where the colour changes,
    # takes half the band (60 to 90 degrees); ticks in degrees
    ax.set_xscale("function", functions=(lambda t: 1 - np.cos(np.radians(np.clip(t, 0, 90))),
                                         lambda u: np.degrees(np.arccos(np.clip(1 - u, -1, 1)))))
    ax.set_facecolor("0.5")  # mid grey: the brightest bands (silver, aluminium) read against it
    edges = np.concatenate([[angles[0]], (angles[1:] + angles[:-1]) / 2, [angles[-1]]])
    for i, rgb in enumerate(bands.values()):
        ax.pcolormesh(edges, [i - 0.34, i + 0.34], rgb[None], shading="flat", rasterized=True)
    ax.set(yticks=range(len(bands)), yticklabels=list(bands), xlim=(0, 90), xticks=[0, 30, 45, 60, 70, 80, 90],
           xlabel="incidence angle \u03b8 (degrees; the axis is linear in cos \u03b8)",
           title=f"(c) metals: the colour of F(\u03bb, \u03b8) under {colour_cfg['illuminant']} "
                 f"({colour_cfg['space']}; every band's XYZ \u00d7 {exposure:g})")
    ax.set_ylim(len(bands) - 0.5, -0.5)
    ax.tick_params(left=False)
    for spine in ax.spines.values():
        spine.set_visible(False)
    fig.suptitle("Lecture (Russin, Module 3B), \u201cFresnel reflectance\u201d: unpolarised F against the incidence angle")
    fig.tight_layout(w_pad=1.5)
    savefig(fig, snakemake.output.png, snakemake.output.pdf, tag=display_tag(colour_cfg["space"]))
