"""Bench: the renderer's speed, memory and accuracy, and a path tracer's cross-check of it.

Modules: run (``reflectance bench``: every size in a process of its own, the cross-check, the
report).

Public names are loaded on first use (``from reflectance.bench import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("run",)

#: public name -> module of this package that defines it
_EXPORTS = {
    "run_bench": "run",
    "format_report": "run",
    "crosscheck_status": "run",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
