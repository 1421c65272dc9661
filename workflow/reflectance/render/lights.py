"""Lights as geometry only: where the light comes from (direction or position).

The spectra and intensities of lights belong to the scene description
(:mod:`reflectance.render.scene`); here a light is a direction toward it or a position.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from reflectance.geometry.vectors import normalize, unit_vector

__all__ = ["DirectionalLight", "PointLight", "LIGHT_TYPES", "as_light", "light_vectors"]


@dataclass(frozen=True)
class DirectionalLight:
    """A light at infinity; ``direction`` points from the scene toward the light."""

    direction: tuple

    def __post_init__(self):
        object.__setattr__(self, "direction",
                           tuple(float(x) for x in unit_vector(self.direction, "light direction")))


@dataclass(frozen=True)
class PointLight:
    """A point light at ``position``."""

    position: tuple

    def __post_init__(self):
        p = np.asarray(self.position, np.float64)
        if p.shape != (3,) or not np.all(np.isfinite(p)):
            raise ValueError(f"light position must be 3 finite numbers, got {self.position!r}")
        object.__setattr__(self, "position", tuple(float(x) for x in p))


LIGHT_TYPES: dict[str, tuple[type[DirectionalLight] | type[PointLight], str]] = {
    "directional": (DirectionalLight, "direction"), "point": (PointLight, "position")}
"""Light types of a light mapping ``{type: ..., <key>: [x, y, z]}`` and their vector key."""


def as_light(light: DirectionalLight | PointLight | Mapping[str, Any]
            ) -> DirectionalLight | PointLight:
    """A :class:`DirectionalLight` or :class:`PointLight` from itself or a mapping.

    Examples
    --------
    >>> as_light({"type": "directional", "direction": [0, 0, 2]})
    DirectionalLight(direction=(0.0, 0.0, 1.0))
    """
    if isinstance(light, (DirectionalLight, PointLight)):
        return light
    if not hasattr(light, "get"):
        raise ValueError(f"a light must be a light object or a mapping, got {light!r}")
    kind = light.get("type")
    if kind not in LIGHT_TYPES:
        raise ValueError(f"unknown light type {kind!r}; known: {sorted(LIGHT_TYPES)}")
    cls, key = LIGHT_TYPES[kind]
    if key not in light:
        raise ValueError(f"a {kind} light needs the key {key!r}")
    return cls(light[key])


def light_vectors(light: DirectionalLight | PointLight | Mapping[str, Any],
                  positions: npt.NDArray[np.float64]
                 ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Unit vectors L from each position toward the light and the distance to it.

    Parameters
    ----------
    light : DirectionalLight, PointLight or mapping
    positions : array_like, shape (..., 3)

    Returns
    -------
    L : ndarray, shape (..., 3)
    distance : ndarray, shape (...)
        ``inf`` for a directional light.
    """
    light = as_light(light)
    positions = np.asarray(positions, np.float64)
    if isinstance(light, DirectionalLight):
        L = np.broadcast_to(np.asarray(light.direction), positions.shape).copy()
        return L, np.full(positions.shape[:-1], np.inf)
    d = np.asarray(light.position) - positions
    distance = np.linalg.norm(d, axis=-1)
    return normalize(d), distance
