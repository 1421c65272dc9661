"""The rendered figures, drawn: one module per figure of :mod:`reflectance.papers.figures`, of
the same name (``ct82_fig8`` draws the figure ``ct82_fig8`` defines), each with one public
function, ``run(snakemake, log)``: its rule's job, which renders the scenes its definition gives,
writes the tables, draws the figure and writes the caption's values.

Only the workflow's scripts import these modules, each its own (``run_job(snakemake, run)``,
:func:`reflectance.scripting.run_job`); nothing in the library does, so the config check and the
Snakefile's parse, which import the definitions, never load matplotlib or the renderer for them.
A rule's params carry the SHA-256 of its drawing's file (workflow/rules/common.smk,
``draw_digest``): an edit of the drawing reruns exactly that figure.

The modules are loaded on first use (``reflectance.papers.draw.ct82_fig8``).
"""

from reflectance.lazy import attach

#: this package's modules: one per rendered figure (reflectance.papers.figures.FIGURES)
_MODULES = ("ct82_fig6", "ct82_fig7", "ct82_fig8", "blinn77_fig7", "blinn77_fig7_sweep",
            "blinn77_fig8", "article_spheres")

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, {})
