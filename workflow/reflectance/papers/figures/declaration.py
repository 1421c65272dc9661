"""The pieces of a figure's definition: its scenes, and the config keys it reads.

:mod:`reflectance.papers.figures` says what a figure module defines; this module holds what those
modules share, so that they need not import the package that lists them.
"""

from __future__ import annotations

import copy
from typing import NamedTuple

__all__ = ["FigureScene", "config_value", "param_keys", "params_of", "select"]


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
