"""Blinn 1977: the figures that render nothing (Figs. 1-6, D1/D2/D3 at equal beta, the cost of
each term), one declaration each (:class:`Figure`). Figs. 1 and 2-4 share ``fig1_4``, Figs. 5
and 6 share ``fig5_6``: each declares only the keys it reads, so an edit of one reruns only that
one."""

from __future__ import annotations

from reflectance.papers.figures.declaration import Figure

_B77, _OUT = "figures.blinn_1977", "results/blinn_1977"


def _keys(parent, *keys):
    return tuple(f"{_B77}.{parent}.{key}" for key in keys)


DEFINITIONS = {figure.RULE: figure for figure in (
    Figure("blinn77_fig1", _OUT, {"fig": _keys("fig1_4", "n_rays", "n_drawn_rays", "cases")},
           {"png": "fig1.png", "pdf": "fig1.pdf", "csv": "fig1.csv"}),
    Figure("blinn77_fig2_4", _OUT, {"fig": _keys("fig1_4", "n_rays", "n_drawn_rays", "cases",
                                                 "construction_case")},
           {"png": "fig2_4.png", "pdf": "fig2_4.pdf", "csv": "fig2_4.csv"}),
    # one rule, one job per figure ({fig}); the rule hands each job its own incidence angle
    # the default figure draws the chosen set; {fig}_fig7_materials, Fig. 7's measured sets
    # (fig carries both angles: Figs. 5 and 6 share one radial scale)
    Figure("blinn77_fig5_6", _OUT, {"fig": _keys("fig5_6", "n_directions", "corner_min_fraction",
                                                 "zoom_half_width_deg", "typical_c1", "incidence_deg",
                                                 "chosen", "parameter_sets"),
                                    "incidence_deg": f"{_B77}.fig5_6.incidence_deg"},
           {"png": "{fig}.png", "pdf": "{fig}.pdf", "variant_png": "{fig}_fig7_materials.png",
            "variant_pdf": "{fig}_fig7_materials.pdf", "csv": "{fig}.csv",
            "summary": "{fig}_summary.csv", "values": "{fig}.values.rst"},
           WILDCARDS={"fig": ("fig5", "fig6")}),
    Figure("blinn77_distributions", _OUT, {"fig": f"{_B77}.distributions"},
           {"png": "distributions.png", "pdf": "distributions.pdf", "csv": "distributions.csv",
            "summary": "distributions_max_difference.csv"}),
    # Blinn's "no increase in computation time": the counts (deterministic), then the times (a
    # measurement, its own rule: the counts never wait for, nor change with, a timing)
    Figure("blinn77_cost_counts", _OUT, {"fig": _keys("cost", "panel"),
                                         "panels": f"{_B77}.fig7.panels"},
           {"csv": "cost_counts.csv", "values": "cost_counts.values.rst"}),
    Figure("blinn77_cost_timing", _OUT, {"fig": _keys("cost", "panel", "n_samples", "repeats",
                                                      "seed", "verdict"),
                                         "panels": f"{_B77}.fig7.panels"},
           {"csv": "cost_timing.csv", "measurement": "cost_timing.yaml",
            "values": "cost_timing.values.rst"}),
)}
