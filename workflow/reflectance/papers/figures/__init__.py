"""One definition per rendered figure: the config keys it reads, its outputs and its scenes.

Each module of this package is one figure, named after its Snakemake rule, and defines:

- ``PARAMS``: ``{name: dotted config key}`` (or a tuple of dotted keys under one parent, giving
  that parent with only those keys), or a function of the config returning that mapping (where a
  key depends on another, as Blinn's Fig. 8 reads the index of the panel it names). The rule's ``params`` are exactly these values
  (:func:`params_of`), so Snakemake's params trigger reruns the figure when one of them changes
  and for no other key; the figure's code is handed nothing else, so a key it reads without
  declaring it fails the config check at once (a ``KeyError`` naming it).
- ``spectra(params)``: the materials whose ``spectra/<name>.csv`` the job reads.
- ``outputs(params)``: ``{name: path or list of paths}``, what the rule writes.
- ``scenes(params, spectra_dir)``: every scene the job renders, as :class:`FigureScene`; the
  config check validates these (:func:`figure_scenes`) and the job renders these, so the two
  cannot differ.

References
----------
The texts in ``../shared/papers/``: Cook & Torrance 1982 Figs. 6-8, Blinn 1977 Figs. 7 and 8,
the Wikipedia article "Specular highlight" (its pair of spheres).
"""

from __future__ import annotations

import copy
from typing import NamedTuple

__all__ = ["FIGURES", "READERS", "FigureScene", "figure", "param_keys", "params_of", "select",
           "config_value", "figure_scenes", "reader_params", "rule_keys"]

#: the rendered figures, by rule name (each a module of this package)
FIGURES = ("ct82_fig6", "ct82_fig7", "ct82_fig8", "blinn77_fig7", "blinn77_fig7_sweep",
           "blinn77_fig8", "article_spheres")


#: rules that are no figure module but read figure keys: {rule: (module, its declaration)}
READERS = {"audit_rgb_rendering": ("ct82_fig7", "RGB_AUDIT_PARAMS")}


class FigureScene(NamedTuple):
    """One scene a figure renders.

    ``name`` names the render in messages (its file's name where it is written); ``source`` is the config key it comes
    from, for messages; ``document`` is the scene mapping (reflectance/data/scene.schema.yaml);
    ``file`` is the ``.scene.yaml`` among the figure's outputs that the job writes it to, or None
    (a close-up, a frame of the sweep or a departure's printed twin is only rendered); ``tags``
    carry what the job needs to place it (panel, light, model, ...).
    """

    name: str
    source: str
    document: dict
    file: str | None = None
    tags: dict = {}

    @property
    def written(self):
        """Whether the job writes this scene (and its images) to files."""
        return self.file is not None


def figure(name):
    """The module of the rendered figure ``name`` (one of :data:`FIGURES`)."""
    # imported here, by name in the code (never a name read from data): they import this module
    from reflectance.papers.figures import (article_spheres, blinn77_fig7, blinn77_fig7_sweep,
                                            blinn77_fig8, ct82_fig6, ct82_fig7, ct82_fig8)

    modules = {module.RULE: module for module in (ct82_fig6, ct82_fig7, ct82_fig8, blinn77_fig7,
                                                  blinn77_fig7_sweep, blinn77_fig8,
                                                  article_spheres)}
    if name not in modules:
        raise ValueError(f"no rendered figure {name!r}; known: {', '.join(FIGURES)}")
    return modules[name]


def config_value(config, key):
    """The value at a dotted ``key`` of ``config``; KeyError naming the key if it is absent."""
    node = config
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            raise KeyError(f"config.yaml has no {key} (needed by a figure)")
        node = node[part]
    return node


def _parent(keys):
    """The longest common dotted prefix strictly above every key of ``keys``, as parts."""
    parts = [key.split(".") for key in keys]
    common = []
    for level in zip(*(p[:-1] for p in parts)):
        if len(set(level)) != 1:
            break
        common.append(level[0])
    return common


def param_keys(module, config):
    """``{param name: dotted key or tuple of keys}`` of a figure module for ``config``."""
    return module.PARAMS(config) if callable(module.PARAMS) else module.PARAMS


def params_of(module, config):
    """The rule params of a figure module: each ``PARAMS`` entry's value from ``config``, copied
    (a tuple of keys: their common parent holding only those keys)."""
    return select(param_keys(module, config), config)


def select(declared, config):
    """``{name: value}`` of a ``{name: dotted key or tuple of keys}`` declaration (a rule that is
    not a figure module, such as an audit, declares its keys so too).

    Examples
    --------
    >>> config = {"a": {"b": 1, "c": {"d": 2, "e": 3}}}
    >>> select({"x": "a.b", "y": ("a.c.d", "a.b")}, config)
    {'x': 1, 'y': {'c': {'d': 2}, 'b': 1}}
    """
    params = {}
    for name, keys in declared.items():
        if isinstance(keys, str):
            params[name] = copy.deepcopy(config_value(config, keys))
            continue
        parent = _parent(keys)
        value = {}
        for key in keys:
            node = value
            rest = key.split(".")[len(parent):]
            for part in rest[:-1]:
                node = node.setdefault(part, {})
            node[rest[-1]] = copy.deepcopy(config_value(config, key))
        params[name] = value
    return params


def reader_params(rule, config):
    """The params of a rule of :data:`READERS`, selected as a figure's are."""
    name, attribute = READERS[rule]
    return select(getattr(figure(name), attribute), config)


def rule_keys(rule, config):
    """Every dotted config key the rule ``rule`` (a figure of :data:`FIGURES` or a rule of
    :data:`READERS`) declares it reads from ``config``."""
    if rule in READERS:
        name, attribute = READERS[rule]
        declared = getattr(figure(name), attribute)
    else:
        declared = param_keys(figure(rule), config)
    return [key for value in declared.values()
            for key in ([value] if isinstance(value, str) else value)]


def figure_scenes(config, spectra_dir="spectra"):
    """Every scene the rendered figures of ``config`` render, without rendering anything.

    Yields ``(key, label, document)``: the config key the scene comes from, the render's name
    (its file's, where it is written: ``fig6a``, ``fig7/Cu``), and the scene mapping. Each
    figure sees only its declared keys (:func:`params_of`), as its job does.
    """
    for name in FIGURES:
        module = figure(name)
        for scene in module.scenes(params_of(module, config), str(spectra_dir)):
            yield scene.source, scene.name, scene.document
