"""Output: deterministic, atomic files.

Modules: atomic (write-then-rename), images (PNG, EXR), tables (CSV), figures (the shared matplotlib
style and saving), paths (paths from data: inside the project; names that are names).

Public names are loaded on first use (``from reflectance.io import name``), so importing
the package stays cheap.
"""

from importlib import import_module

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("atomic", "figures", "images", "paths", "tables")

#: public name -> module of this package that defines it
_EXPORTS = {
    "atomic_write": "atomic",
    "remove_stale_temporaries": "atomic",
    "write_csv": "tables",
    "savefig": "figures",
    "new_figure": "figures",
    "off_screen_plotter": "figures",
    "save_plotter": "figures",
    "PNG_BIT_DEPTHS": "images",
    "write_png": "images",
    "XYZ_CHROMATICITIES": "images",
    "write_exr_XYZ": "images",
    "read_exr": "images",
    "project_file": "paths",
    "check_name": "paths",
}

__all__ = [*_MODULES, *_EXPORTS]


def __getattr__(name):
    if name in _EXPORTS:
        return getattr(import_module(f"{__name__}.{_EXPORTS[name]}"), name)
    if name in _MODULES:
        return import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
