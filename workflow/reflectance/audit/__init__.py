"""Audit: how far each shortcut of the papers lies from the exact spectral answer.

Modules: colour_shift (a smooth material's colour against angle, per Fresnel method); shortcuts
(the `reflectance audit` table: every shortcut against exact, CIEDE2000 and CAM16-UCS);
database (the same for every refractiveindex.info dataset at once: `reflectance audit
--database`); gamut (what each gamut clip does to a rendered figure's colours).

Public names are loaded on first use (``from reflectance.audit import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("colour_shift", "shortcuts", "database", "gamut")

#: public name -> module of this package that defines it
_EXPORTS = {
    "COLOUR_METHODS": "colour_shift",
    "reflected_XYZ": "colour_shift",
    "colour_interpolation_CookTorrance1982": "colour_shift",
    "reflected_XYZ_approximation_CookTorrance1982": "colour_shift",
    "colour_XYZ": "colour_shift",
    "COLOUR_TABLE_COLUMNS": "colour_shift",
    "colour_columns": "colour_shift",
    "colour_table": "colour_shift",
    "AUDIT_METHODS": "shortcuts",
    "AUDIT_TABLE_COLUMNS": "shortcuts",
    "AUDIT_COLUMNS": "shortcuts",
    "SMOOTH_F0_LIMITS": "shortcuts",
    "smooth_F0_warnings": "shortcuts",
    "audit_metadata": "shortcuts",
    "OBSERVERS": "shortcuts",
    "CAM16_VIEWING_CONDITIONS": "shortcuts",
    "DEFAULT_ANGLES_DEG": "shortcuts",
    "DE2000_LEVELS": "shortcuts",
    "default_angles_deg": "shortcuts",
    "looks_like_path": "shortcuts",
    "resolve_material": "shortcuts",
    "observer_name": "shortcuts",
    "audit_weights": "shortcuts",
    "shortcut_XYZ": "shortcuts",
    "shortcuts_XYZ": "shortcuts",
    "audit_table": "shortcuts",
    "dE2000_against_angle": "shortcuts",
    "first_angle_above": "shortcuts",
    "format_audit_csv": "shortcuts",
    "write_audit": "shortcuts",
    "KINDS": "database",
    "STATUSES": "database",
    "COUNT_COLUMNS": "database",
    "check_parameters": "database",
    "database_grid": "database",
    "angle_grid": "database",
    "select_entries": "database",
    "shard_entries": "database",
    "dataset_kinds": "database",
    "audit_datasets": "database",
    "method_columns": "database",
    "table_columns": "database",
    "format_tables": "database",
    "merge_tables": "database",
    "database_metadata": "database",
    "exr_display_RGB": "gamut",
    "GAMUT_TOLERANCE": "gamut",
    "out_of_gamut": "gamut",
    "hue_difference_deg": "gamut",
    "clip_differences": "gamut",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
