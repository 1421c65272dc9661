"""Output: deterministic, atomic files.

Modules: atomic (write-then-rename), images (PNG, EXR), tables (CSV: atomic, deterministic, its
columns' units and precision), captions (the numbers a report caption states, as substitution
definitions), progress (of long work, on standard error), figures (the shared matplotlib style and
saving), paths (paths from data: inside the project or the scene file's folder; names that are
names; the package's own data), cache (the small on-disk cache of values computed once: colour
tables, meshes), provenance (the build's manifest and the metadata file beside an audit's table).

Public names are loaded on first use (``from reflectance.io import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("atomic", "cache", "captions", "figures", "images", "paths", "progress", "provenance",
            "limits", "tables", "yamlfile")

#: public name -> module of this package that defines it
_EXPORTS = {
    "atomic_write": "atomic",
    "write_text": "atomic",
    "remove_stale_temporaries": "atomic",
    "write_csv": "tables",
    "write_caption_values": "captions",
    "read_caption_values": "captions",
    "Column": "tables",
    "csv_cell": "tables",
    "csv_text": "tables",
    "columns_metadata": "tables",
    "savefig": "figures",
    "new_figure": "figures",
    "off_screen_plotter": "figures",
    "save_plotter": "figures",
    "PNG_BIT_DEPTHS": "images",
    "write_png": "images",
    "XYZ_CHROMATICITIES": "images",
    "write_exr_XYZ": "images",
    "write_exr_RGB": "images",
    "ColourTag": "images",
    "SRGB_TAG": "images",
    "tag_png": "images",
    "icc_profile_v2": "images",
    "read_exr": "images",
    "Progress": "progress",
    "worker_main": "progress",
    "write_provenance": "provenance",
    "sha256_file": "provenance",
    "metadata_path": "provenance",
    "write_metadata": "provenance",
    "package_data": "paths",
    "file_inside": "paths",
    "project_file": "paths",
    "check_name": "paths",
    "YAMLFileError": "yamlfile",
    "size_problem": "limits",
    "grid_points": "limits",
    "physical_memory_bytes": "limits",
    "read_yaml": "yamlfile",
    "load_yaml_text": "yamlfile",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
