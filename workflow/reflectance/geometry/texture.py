"""Texture functions t(u, v) in [0, 1] for surface shininess varying over a surface.

Blinn 1977 ("Varying surface shininess", Fig. 8) maps a texture t(u, v) onto the local
roughness, ``C3 = C_min + (1 - C_min) t(u, v)`` (:func:`reflectance.optics.microfacet.c3_texture_Blinn1977`),
and normalises D3 by the constant C_min
(:func:`reflectance.optics.microfacet.distribution_TrowbridgeReitz_texture_Blinn1977`). The paper shows
"two different texture patterns" without defining them; these are three patterns of the kind:

- ``"sinusoid"``: a product of sines, from a smooth egg-crate (``sharpness`` 0) to a
  near-checkerboard (large ``sharpness``);
- ``"spots"``: round smooth-edged spots on a regular lattice (raised-cosine profile);
- ``"value_noise"``: fractal value noise, a sum of octaves of smoothly interpolated random
  lattice values (Ebert et al. 2003), bumpy and irregular.

Every function takes (u, v) of any broadcastable shapes and returns float64 values in [0, 1] of
the broadcast shape. All are periodic with period 1 in u and in v (the frequencies are whole
numbers of cycles or lattice cells per unit), so they wrap seamlessly around a surface of
revolution. The noise is a pure function of (u, v, parameters, seed): its lattice values come
from an integer hash, not from a random-number stream, so it is the same on every machine and
for any evaluation order.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198 ("Varying surface shininess", Fig. 8).
- Ebert, D. S., Musgrave, F. K., Peachey, D., Perlin, K., & Worley, S. (2003). Texturing and
  Modeling: A Procedural Approach (3rd ed.). Morgan Kaufmann. (Ch. 2: lattice value noise,
  fractal sums of octaves.)
- Perlin, K. (2002). Improving noise. ACM Transactions on Graphics, 21(3), 681-682. (The
  quintic fade 6 t^5 - 15 t^4 + 10 t^3.)
- Steele, G. L., Lea, D., & Flood, C. H. (2014). Fast splittable pseudorandom number generators.
  OOPSLA '14, 453-472. (The SplitMix64 finaliser used as the lattice hash.)
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = [
    "texture_sinusoid",
    "texture_spots",
    "texture_value_noise",
    "TEXTURE_METHODS",
    "texture",
]


def _uv(u: npt.ArrayLike, v: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], ...]:
    u = np.asarray(u, dtype=np.float64)
    v = np.asarray(v, dtype=np.float64)
    if not (np.all(np.isfinite(u)) and np.all(np.isfinite(v))):
        raise ValueError("texture coordinates u and v must be finite")
    return np.broadcast_arrays(u, v)


def _cycles(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise ValueError(f"{name} must be a whole number >= 1 (so that the texture is periodic), "
                         f"got {value!r}")
    return int(value)


def _unit_interval(x):
    return np.clip(x, 0.0, 1.0)[()]  # numpy scalar for scalar input


def texture_sinusoid(u: npt.ArrayLike, v: npt.ArrayLike, cycles_u: int = 8, cycles_v: int = 4,
                     sharpness: float = 0.0) -> npt.NDArray[np.float64] | np.float64:
    """Product of sines: ``t = (1 + S(sin(2 pi a u) sin(2 pi b v))) / 2``.

    ``S(s) = tanh(k s) / tanh(k)`` with ``k = sharpness`` (``S(s) = s`` for k = 0) steepens the
    transitions: k = 0 is a smooth egg-crate, large k a checkerboard of 2a x 2b squares.

    Parameters
    ----------
    u, v : array_like
        Texture coordinates (period 1 in each).
    cycles_u, cycles_v : int, optional
        Whole periods across u and v.
    sharpness : float, optional
        k >= 0.

    Returns
    -------
    numpy.ndarray
        t in [0, 1], the broadcast shape of u and v.

    Examples
    --------
    >>> print(f"{texture_sinusoid(1 / 32, 1 / 16):.4f}")
    1.0000
    """
    u, v = _uv(u, v)
    a, b = _cycles(cycles_u, "cycles_u"), _cycles(cycles_v, "cycles_v")
    k = float(sharpness)
    if not np.isfinite(k) or k < 0:
        raise ValueError(f"sharpness must be a finite number >= 0, got {sharpness!r}")
    # reduce the arguments modulo 1 first, so that u and u + 1 give bit-identical values
    s = np.sin(2.0 * np.pi * np.mod(a * u, 1.0)) * np.sin(2.0 * np.pi * np.mod(b * v, 1.0))
    if k > 0:
        s = np.tanh(k * s) / np.tanh(k)
    return _unit_interval(0.5 * (1.0 + s))


def texture_spots(u: npt.ArrayLike, v: npt.ArrayLike, cells_u: int = 8, cells_v: int = 4,
                  radius: float = 0.35) -> npt.NDArray[np.float64] | np.float64:
    """Round spots on a lattice: 1 at each cell centre, falling as a raised cosine to 0.

    In cell units (each cell 1 x 1), with d the distance from the cell centre,
    ``t = (1 + cos(pi d / radius)) / 2`` for d < radius and 0 beyond: continuous with a
    continuous gradient, the spots never touching (radius <= 1/2).

    Parameters
    ----------
    u, v : array_like
        Texture coordinates (period 1 in each).
    cells_u, cells_v : int, optional
        Lattice cells across u and v.
    radius : float, optional
        Spot radius in cell units, in (0, 0.5].

    Returns
    -------
    numpy.ndarray
        t in [0, 1], the broadcast shape of u and v.

    Examples
    --------
    >>> print(f"{texture_spots(1 / 16, 1 / 8):.1f} {texture_spots(0.0, 0.0):.1f}")
    1.0 0.0
    """
    u, v = _uv(u, v)
    a, b = _cycles(cells_u, "cells_u"), _cycles(cells_v, "cells_v")
    r = float(radius)
    if not (np.isfinite(r) and 0.0 < r <= 0.5):
        raise ValueError(f"radius must lie in (0, 0.5] (cell units), got {radius!r}")
    du = np.mod(a * u, 1.0) - 0.5
    dv = np.mod(b * v, 1.0) - 0.5
    d = np.minimum(np.hypot(du, dv) / r, 1.0)
    return _unit_interval(0.5 * (1.0 + np.cos(np.pi * d)))


def _splitmix64(x):
    """SplitMix64 finaliser (Steele, Lea & Flood 2014) on 1-d uint64 arrays.

    Array arithmetic on uint64 wraps modulo 2^64 silently, which is what the hash needs (numpy
    scalars would warn, hence 1-d arrays only).
    """
    x = x + np.uint64(0x9E3779B97F4A7C15)
    x = (x ^ (x >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    x = (x ^ (x >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return x ^ (x >> np.uint64(31))


def _lattice_value(i, j, octave, seed):
    """Uniform value in [0, 1) for lattice points (i, j) (1-d) of an octave: a pure hash."""
    key = np.full(i.shape, seed, np.uint64) * np.uint64(0x100000001B3) + np.uint64(octave)
    key = _splitmix64(key)
    key = _splitmix64(key ^ i.astype(np.uint64))
    key = _splitmix64(key ^ j.astype(np.uint64))
    return (key >> np.uint64(11)).astype(np.float64) * 2.0**-53


def _fade(t):
    return t * t * t * (t * (6.0 * t - 15.0) + 10.0)  # Perlin 2002, quintic fade (C2)


def _value_octave(u, v, nu, nv, octave, seed):
    x, y = np.mod(u, 1.0) * nu, np.mod(v, 1.0) * nv
    i0, j0 = np.floor(x), np.floor(y)
    fx, fy = _fade(x - i0), _fade(y - j0)
    i0, j0 = i0.astype(np.int64) % nu, j0.astype(np.int64) % nv  # wrap: period 1 in u and v
    i1, j1 = (i0 + 1) % nu, (j0 + 1) % nv
    c00 = _lattice_value(i0, j0, octave, seed)
    c10 = _lattice_value(i1, j0, octave, seed)
    c01 = _lattice_value(i0, j1, octave, seed)
    c11 = _lattice_value(i1, j1, octave, seed)
    # bilinear blend with faded weights: a convex combination, so it stays in [0, 1]
    return (c00 * (1 - fx) + c10 * fx) * (1 - fy) + (c01 * (1 - fx) + c11 * fx) * fy


def texture_value_noise(u: npt.ArrayLike, v: npt.ArrayLike, cells_u: int = 8, cells_v: int = 4,
                        octaves: int = 3, persistence: float = 0.5,
                        seed: int = 0) -> npt.NDArray[np.float64] | np.float64:
    """Fractal value noise: octaves of interpolated random lattice values, normalised to [0, 1].

    Octave o has (cells_u 2^o) x (cells_v 2^o) lattice cells, each lattice point a hashed
    uniform value in [0, 1), blended with the quintic fade; the octaves are summed with
    amplitudes ``persistence^o`` and divided by the sum of the amplitudes (Ebert et al. 2003).
    Each octave is a convex combination of values in [0, 1], and so is the sum.

    Parameters
    ----------
    u, v : array_like
        Texture coordinates (period 1 in each).
    cells_u, cells_v : int, optional
        Lattice cells of the first octave across u and v.
    octaves : int, optional
        Number of octaves, >= 1.
    persistence : float, optional
        Amplitude ratio between successive octaves, > 0.
    seed : int, optional
        Non-negative; a different seed gives an unrelated pattern.

    Returns
    -------
    numpy.ndarray
        t in [0, 1], the broadcast shape of u and v.

    Examples
    --------
    >>> t = texture_value_noise([0.0, 0.3, 1.0], 0.5)
    >>> bool(t[0] == t[2]), bool(0.0 <= t.min() and t.max() <= 1.0)
    (True, True)
    """
    u, v = _uv(u, v)
    nu, nv = _cycles(cells_u, "cells_u"), _cycles(cells_v, "cells_v")
    n_oct = _cycles(octaves, "octaves")
    p = float(persistence)
    if not (np.isfinite(p) and p > 0):
        raise ValueError(f"persistence must be a finite number > 0, got {persistence!r}")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) \
            or not 0 <= seed < 2**64:
        raise ValueError(f"seed must be an integer in [0, 2^64), got {seed!r}")
    shape = u.shape
    u, v = u.ravel(), v.ravel()  # 1-d for the wrapping integer hash
    total = np.zeros(u.shape)
    weight = 0.0
    for o in range(n_oct):
        amplitude = p**o
        total += amplitude * _value_octave(u, v, nu * 2**o, nv * 2**o, o, int(seed))
        weight += amplitude
    return _unit_interval(total / weight).reshape(shape)


TEXTURE_METHODS: dict[str, Callable[..., Any]] = {
    "sinusoid": texture_sinusoid,
    "spots": texture_spots,
    "value_noise": texture_value_noise,
}
"""Texture functions t(u, v) in [0, 1], by name."""


def texture(u: npt.ArrayLike, v: npt.ArrayLike, method: str = "sinusoid",
            **params: Any) -> npt.NDArray[np.float64] | np.float64:
    """Texture value t(u, v) in [0, 1] by one of :data:`TEXTURE_METHODS`.

    Parameters
    ----------
    u, v : array_like
        Texture coordinates.
    method : str, optional
        ``"sinusoid"``, ``"spots"`` or ``"value_noise"``.
    **params
        Keyword parameters of the chosen function.

    Returns
    -------
    numpy.ndarray

    References
    ----------
    - Blinn 1977, "Varying surface shininess", Fig. 8.

    Examples
    --------
    >>> print(f"{texture(0.25, 0.25, 'sinusoid', cycles_u=1, cycles_v=1):.2f}")
    1.00
    """
    if method not in TEXTURE_METHODS:
        raise ValueError(f"unknown texture method {method!r}; known: {', '.join(TEXTURE_METHODS)}")
    function = TEXTURE_METHODS[method]
    known = [name for name in inspect.signature(function).parameters if name not in ("u", "v")]
    unknown = sorted(set(params) - set(known))
    if unknown:
        raise ValueError(f"texture method {method!r}: unknown parameters {unknown}; "
                         f"known: {known}")
    return function(u, v, **params)
