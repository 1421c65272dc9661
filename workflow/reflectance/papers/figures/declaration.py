"""The pieces of a figure's definition: its scenes, and the config keys it reads.

:mod:`reflectance.papers.figures` says what a figure module defines; this module holds what those
modules share, so that they need not import the package that lists them.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterable, Mapping, Sequence
from types import ModuleType
from typing import Any, NamedTuple

__all__ = ["Figure", "FigureScene", "config_value", "param_keys", "params_of", "select"]


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
    def written(self) -> bool:
        """Whether the job writes this scene (and its images) to files."""
        return self.file is not None


def config_value(config: Mapping[str, Any], key: str) -> Any:  # any value YAML holds
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


def param_keys(module: ModuleType | Figure,
               config: Mapping[str, Any]) -> dict[str, str | tuple[str, ...]]:
    """``{param name: dotted key or tuple of keys}`` of a figure module for ``config``."""
    return module.PARAMS(config) if callable(module.PARAMS) else module.PARAMS


def params_of(module: ModuleType | Figure,
              config: Mapping[str, Any]) -> dict[str, Any]:  # config values: any YAML value
    """The rule params of a figure module: each ``PARAMS`` entry's value from ``config``, copied
    (a tuple of keys: their common parent holding only those keys)."""
    return select(param_keys(module, config), config)


def select(declared: Mapping[str, str | Sequence[str]],
           config: Mapping[str, Any]) -> dict[str, Any]:  # config values: any YAML value
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
        value: dict[str, Any] = {}
        for key in keys:
            node = value
            rest = key.split(".")[len(parent):]
            for part in rest[:-1]:
                node = node.setdefault(part, {})
            node[rest[-1]] = copy.deepcopy(config_value(config, key))
        params[name] = value
    return params


class Figure(NamedTuple):
    """The definition of a figure that renders nothing (an analytic figure): the same interface
    as a rendered figure's module (``RULE``, ``PARAMS``, ``spectra``, ``outputs``, ``scenes``),
    declared in one line per figure by its text's module.

    ``PARAMS`` is ``{param name: dotted key or tuple of keys}`` (:func:`select`), or a function of
    the config giving it (where a key depends on another's value); ``OUTPUTS`` is
    ``{output name: file name}`` under ``folder`` (a file name may hold a Snakemake wildcard, e.g.
    ``{fig}.png``, whose values ``WILDCARDS`` lists); ``SPECTRA`` is a function of the params
    giving the materials whose CSV the job reads.
    """

    RULE: str
    folder: str
    PARAMS: dict | Callable[[Mapping[str, Any]], dict]
    OUTPUTS: dict
    SPECTRA: Callable[[Mapping[str, Any]], Iterable[str]] | None = None
    WILDCARDS: dict = {}

    def spectra(self, params: Mapping[str, Any]) -> list[str]:
        """The materials whose ``spectra/<name>.csv`` the job reads."""
        return list(self.SPECTRA(params)) if self.SPECTRA else []

    def outputs(self, params: Mapping[str, Any]) -> dict[str, str]:
        """``{name: path}``, what the rule writes (wildcards left in)."""
        return {name: f"{self.folder}/{file}" for name, file in self.OUTPUTS.items()}

    def targets(self, params: Mapping[str, Any]) -> list[str]:
        """Every file the rule writes, each wildcard filled with each of its values."""
        paths = list(self.outputs(params).values())
        for wildcard, values in self.WILDCARDS.items():
            paths = [p.replace(f"{{{wildcard}}}", v) for v in values for p in paths]
        return paths

    def scenes(self, params: Mapping[str, Any], spectra_dir: str = "spectra") -> list[FigureScene]:
        """An analytic figure renders no scene."""
        return []
