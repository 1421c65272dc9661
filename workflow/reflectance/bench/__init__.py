"""Bench: the renderer's speed, memory and accuracy, and a path tracer's cross-check of it.

Modules: measure (one image size: the render's seconds, memory and error against a converged
reference; the bench's defaults); crosscheck (a scene exported to the path tracer Mitsuba 3, an
optional extra, against our renders); mitsuba_command (Mitsuba's whole command, timed by the
cross-check); run (``reflectance bench``: every size in a process of its own, the cross-check,
the report).

Public names are loaded on first use (``from reflectance.bench import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("crosscheck", "measure", "mitsuba_command", "run")

#: public name -> module of this package that defines it
_EXPORTS = {
    "load_bench_scene": "measure",
    "scene_difference": "measure",
    "bench_size": "measure",
    "mitsuba_available": "crosscheck",
    "crosscheck_scene": "crosscheck",
    "scene_to_mitsuba": "crosscheck",
    "mitsuba_renderer": "crosscheck",
    "render_mitsuba": "crosscheck",
    "bench_crosscheck": "crosscheck",
    "format_crosscheck": "crosscheck",
    "run_bench": "run",
    "format_report": "run",
    "crosscheck_status": "run",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
