"""One definition per figure: the config keys it reads, its outputs and its scenes.

Each rendered figure is a module of this package, named after its Snakemake rule; the figures
that render nothing are one :class:`Figure` line each in their text's module
(:mod:`.cook_torrance_1982`, :mod:`.blinn_1977`, :mod:`.lecture`, :mod:`.article`, whose
``DEFINITIONS`` map rule names to them). Each defines:

- ``PARAMS``: ``{name: dotted config key}`` (or a tuple of dotted keys under one parent, giving
  that parent with only those keys), or a function of the config returning that mapping (where a
  key depends on another, as Blinn's Fig. 8 reads the index of the panel it names). The rule's
  ``params`` are exactly these values (:func:`params_of`), so Snakemake's params trigger reruns
  the figure when one of them changes and for no other key; the figure's code is handed nothing else, so a key it reads without
  declaring it fails the config check at once (a ``KeyError`` naming it).
- ``spectra(params)``: the materials whose ``spectra/<name>.csv`` the job reads.
- ``outputs(params)``: ``{name: path or list of paths}``, what the rule writes.
- ``scenes(params, spectra_dir)``: every scene the job renders, as :class:`FigureScene`; the
  config check validates these (:func:`figure_scenes`) and the job renders these, so the two
  cannot differ.

What the modules share (:class:`FigureScene`, :func:`params_of`, :func:`select`) lives in
:mod:`reflectance.papers.figures.declaration`.

References
----------
The texts in ``../shared/papers/``: Cook & Torrance 1982, Blinn 1977, the lecture (Russin,
Module 3B), the Wikipedia article "Specular highlight".
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Mapping
from types import ModuleType
from typing import Any

from reflectance.papers.figures import article, blinn_1977, cook_torrance_1982, lecture
from reflectance.papers.figures.declaration import (Figure, FigureScene, config_value, param_keys,
                                                    params_of, select)

__all__ = ["ANALYTIC", "FIGURES", "READERS", "Figure", "FigureScene", "figure", "param_keys",
           "params_of", "select", "config_value", "declared_key_problems", "figure_scenes", "reader_params", "rule_keys"]

#: the rendered figures, by rule name (each a module of this package)
FIGURES = ("ct82_fig6", "ct82_fig7", "ct82_fig8", "blinn77_fig7", "blinn77_fig7_sweep",
           "blinn77_fig8", "article_spheres")

#: the texts' modules of the figures that render nothing: {rule name: Figure}
_TEXTS = (cook_torrance_1982, blinn_1977, lecture, article)
_ANALYTIC = {rule: definition for text in _TEXTS for rule, definition in text.DEFINITIONS.items()}
#: the figures that render nothing, by rule name (each one line of its text's module)
ANALYTIC = tuple(_ANALYTIC)


#: rules that are no figure module but read figure keys: {rule: (module, its declaration)}
READERS = {"audit_rgb_rendering": ("ct82_fig7", "RGB_AUDIT_PARAMS")}


def figure(name: str) -> ModuleType | Figure:
    """The definition of the figure ``name``: a rendered figure's module (one of
    :data:`FIGURES`) or an analytic figure's :class:`Figure` (one of :data:`ANALYTIC`)."""
    if name in _ANALYTIC:
        return _ANALYTIC[name]
    # imported by name in the code (never a name read from data), and only when asked for
    import reflectance.papers.figures.article_spheres as article_spheres
    import reflectance.papers.figures.blinn77_fig7 as blinn77_fig7
    import reflectance.papers.figures.blinn77_fig7_sweep as blinn77_fig7_sweep
    import reflectance.papers.figures.blinn77_fig8 as blinn77_fig8
    import reflectance.papers.figures.ct82_fig6 as ct82_fig6
    import reflectance.papers.figures.ct82_fig7 as ct82_fig7
    import reflectance.papers.figures.ct82_fig8 as ct82_fig8

    modules = {module.RULE: module for module in (ct82_fig6, ct82_fig7, ct82_fig8, blinn77_fig7,
                                                  blinn77_fig7_sweep, blinn77_fig8,
                                                  article_spheres)}
    if name not in modules:
        raise ValueError(f"no figure {name!r}; known: {', '.join(FIGURES + ANALYTIC)}")
    return modules[name]


def reader_params(rule: str, config: Mapping[str, Any]) -> dict[str, Any]:  # YAML values
    """The params of a rule of :data:`READERS`, selected as a figure's are."""
    name, attribute = READERS[rule]
    return select(getattr(figure(name), attribute), config)


def rule_keys(rule: str, config: Mapping[str, Any]) -> list[str]:
    """Every dotted config key the rule ``rule`` (a figure of :data:`FIGURES` or
    :data:`ANALYTIC`, or a rule of :data:`READERS`) declares it reads from ``config``."""
    if rule in READERS:
        name, attribute = READERS[rule]
        declared = getattr(figure(name), attribute)
    else:
        declared = param_keys(figure(rule), config)
    return [key for value in declared.values()
            for key in ([value] if isinstance(value, str) else value)]


def figure_scenes(config: Mapping[str, Any], spectra_dir: str | os.PathLike[str] = "spectra"
                  ) -> Iterator[tuple[str, str, dict[str, Any]]]:
    """Every scene the rendered figures of ``config`` render, without rendering anything.

    Yields ``(key, label, document)``: the config key the scene comes from, the render's name
    (its file's, where it is written: ``fig6a``, ``fig7/Cu``), and the scene mapping. Each
    figure sees only its declared keys (:func:`params_of`), as its job does.
    """
    for name in FIGURES:
        module = figure(name)
        for scene in module.scenes(params_of(module, config), str(spectra_dir)):
            yield scene.source, scene.name, scene.document


def declared_key_problems(config: Mapping[str, Any]) -> list[str]:
    """One line per figure whose declared keys are not all in ``config`` (naming the key and the
    figure): the config check's, before any rule takes its params."""
    problems = []
    for name in FIGURES + ANALYTIC:
        try:
            params_of(figure(name), config)
        except KeyError as err:
            problems.append(err.args[0].replace("by a figure", f"by figure {name}, "
                                                "reflectance.papers.figures"))
    return problems
