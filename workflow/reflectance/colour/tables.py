"""colour-science's tables, computed by colour-science once and then read with numpy only.

Importing colour-science takes seconds; the colour path needs only a few of its tables: the CIE
standard observers' colour matching functions, the CIE illuminants' SPDs (both on their own
tabulation and aligned to a caller's wavelength grid), the names colour-science knows them by, the
primaries of the display colourspaces, the chromatic adaptation matrices, the display transfer
functions' decoding of the 256 8-bit codes and (for the config check) the Munsell value and luminance factor of a notation. Each is computed by
colour-science itself on first use and stored as a ``.npy`` (or ``.json``) file in a small cache,

    ``$REFLECTANCE_CACHE`` or ``${XDG_CACHE_HOME:-~/.cache}/reflectance``,
    in a folder ``colour-science-<version>`` of the installed colour-science,

so later calls (and later processes) read the very same float64 values back: the values are
bit-identical to colour-science's. Files are written atomically (temporary file, then rename); an
unwritable or unreadable cache is ignored (the values are then recomputed by colour-science on every
call). Each file name carries a hash of what it holds (kind, name, grid), so different grids or
names never collide; a newer colour-science gets a new folder.

Name lookup follows colour-science's ``CanonicalMapping``: a name matches a key exactly, or in
lower case, or as its slug, or as its canonical (slug without dashes and underscores) variant; the
three variant tables are colour-science's own (``lower_keys``, ``slugified_keys``,
``canonical_keys``), cached like the arrays.
"""

from __future__ import annotations

import functools
import io
import json
from collections.abc import Iterable
from pathlib import Path

import numpy as np
import numpy.typing as npt

from reflectance.io.cache import (CACHE_ENVIRONMENT_VARIABLE, cache_root, distribution_version,
                                  file_name)
from reflectance.io.cache import load as _load
from reflectance.io.cache import store as _store

__all__ = [
    "CACHE_ENVIRONMENT_VARIABLE",
    "cache_directory",
    "observer_names",
    "illuminant_names",
    "resolve_observer",
    "resolve_illuminant",
    "cmfs_tabulated",
    "cmfs_aligned",
    "illuminant_tabulated",
    "illuminant_aligned",
    "rgb_colourspace_matrix",
    "chromatic_adaptation_matrix",
    "munsell_value_and_Y",
    "transfer_decoding_8bit",
    "forget",
]

_FORMAT = 2
"""Version of this module's file layout; part of every file name. 2: aligned tables are evaluated
at the grid's own points (:func:`_align`); a file of 1 may hold colour-science's samples off the
grid."""


@functools.lru_cache(maxsize=1)
def _colour_science_version():
    """The installed colour-science's version (:func:`reflectance.io.cache.distribution_version`:
    no import of colour)."""
    return distribution_version("colour", "colour_science")


def cache_directory() -> Path:
    """The folder of the cached tables for the installed colour-science (may not exist yet)."""
    return cache_root() / f"colour-science-{_colour_science_version()}"


def _path(kind, parts, suffix):
    return cache_directory() / file_name(_FORMAT, kind, parts, suffix)


def _array(kind, parts, compute, ndim):
    """The float64 array ``compute()`` (a colour-science computation), cached under (kind, parts)."""
    path = _path(kind, parts, ".npy")
    try:
        value = np.load(io.BytesIO(_load(path)), allow_pickle=False)  # checked: issue 25
        if value.dtype == np.float64 and value.ndim == ndim:
            value.setflags(write=False)
            return value
    except (OSError, ValueError, EOFError):
        pass
    value = np.ascontiguousarray(compute(), dtype=np.float64)
    _store(path, lambda file: np.save(file, value, allow_pickle=False))
    value.setflags(write=False)
    return value


def _colour():
    import colour

    return colour


# -- names ---------------------------------------------------------------------------------------

def _mapping(kind):
    colour = _colour()
    if kind == "observers":
        return colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER
    return colour.SDS_ILLUMINANTS


@functools.lru_cache(maxsize=None)
def _names(kind):
    """colour-science's keys of ``kind`` and its lower / slug / canonical variant -> key tables."""
    path = _path(f"names-{kind}", [], ".json")
    try:
        names = json.loads(_load(path))
        if isinstance(names, dict) and set(names) == {"keys", "lower", "slug", "canonical"}:
            return names
    except (OSError, ValueError):
        pass
    mapping = _mapping(kind)
    keys = list(mapping.keys())
    # As colour.utilities.CanonicalMapping.__getitem__ builds them (later keys win on a clash).
    names = {
        "keys": keys,
        "lower": dict(zip(mapping.lower_keys(), keys)),
        "slug": dict(zip(mapping.slugified_keys(), keys)),
        "canonical": dict(zip(mapping.canonical_keys(), keys)),
    }
    _store(path, lambda file: file.write(json.dumps(names).encode()))
    return names


def _resolve(kind, name):
    """colour-science's key for ``name`` (CanonicalMapping lookup order), or None if unknown."""
    if not isinstance(name, str):
        return None
    names = _names(kind)
    if name in names["keys"]:
        return name
    for variant, table in ((name.lower(), "lower"), (name, "slug"), (name, "canonical")):
        if variant in names[table]:
            return names[table][variant]
    return None


def observer_names() -> tuple[str, ...]:
    """Names of ``colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER``, in colour-science's order."""
    return tuple(_names("observers")["keys"])


def illuminant_names() -> tuple[str, ...]:
    """Names of ``colour.SDS_ILLUMINANTS``, in colour-science's order."""
    return tuple(_names("illuminants")["keys"])


def resolve_observer(name: object) -> str | None:
    """The key of standard observer ``name`` as colour-science would find it, or None."""
    return _resolve("observers", name)


def resolve_illuminant(name: object) -> str | None:
    """The key of illuminant ``name`` as colour-science would find it, or None."""
    return _resolve("illuminants", name)


# -- spectral tables -----------------------------------------------------------------------------

def _spectral_shape(grid):
    colour = _colour()
    shape = colour.SpectralShape(grid[0], grid[-1], (grid[-1] - grid[0]) / (len(grid) - 1))
    if len(shape.wavelengths) != len(grid):
        raise ValueError(
            f"wavelengths: colour.SpectralShape{(shape.start, shape.end, shape.interval)} gives "
            f"{len(shape.wavelengths)} samples, the grid has {len(grid)}"
        )
    if np.max(np.abs(shape.wavelengths - np.asarray(grid))) > 1e-9 * shape.interval:
        raise ValueError("wavelengths: must be uniformly spaced (colour-science's SpectralShape "
                         "is a uniform grid)")
    return shape


def _on_grid(sd, grid):
    """One spectral distribution as colour-science's ``align`` makes it, evaluated at ``grid``.

    Inside the data's range, the interpolator ``SpectralDistribution.interpolate`` chooses (the
    distribution's own, unless it is Sprague or cubic spline: then Sprague for uniform data, else
    cubic spline); outside, ``extrapolate``'s default, the constant value at the data's end.
    """
    from colour.algebra import CubicSplineInterpolator, SpragueInterpolator

    sd = sd.copy()
    if sd.interpolator in (SpragueInterpolator, CubicSplineInterpolator):
        sd.interpolator = SpragueInterpolator if sd.is_uniform() else CubicSplineInterpolator
        sd.interpolator_kwargs = {}
    lo, hi = float(sd.wavelengths[0]), float(sd.wavelengths[-1])
    values = np.empty(len(grid), dtype=np.float64)
    inside = (grid >= lo) & (grid <= hi)
    if inside.any():
        values[inside] = sd[grid[inside]]
    first, last = np.asarray(sd[np.array([max(lo, grid[0]), min(hi, grid[-1])])], np.float64)
    values[grid < lo], values[grid > hi] = first, last
    return values


def _align(spectral_data, grid, what):
    """colour-science's ``spectral_data.copy().align(shape)``, evaluated at exactly ``grid``.

    colour-science 0.4's ``align`` evaluates at samples of its own, which miss a grid whose step
    does not fit the data's range: ``interpolate`` spreads its samples evenly over the part of the
    grid the data covers (np.linspace), ``extrapolate`` continues past the data's end by np.arange
    with the data's measured interval. D65 (tabulated to 780 nm) on 360-830 nm then gets one
    sample too many at a 0.001 nm step and samples up to 1.9 nm off the grid at 4.7 nm (issue 25).
    Here the same interpolator and extrapolation are evaluated at the grid's own points; where
    colour-science's samples are the grid, the values are its values bit for bit.
    """
    try:
        _spectral_shape(grid)  # refuses a grid that is not uniform
        points = np.asarray(grid, dtype=np.float64)
        signals = getattr(spectral_data, "signals", None)
        if signals is None:
            return _on_grid(spectral_data, points)
        return np.column_stack([_on_grid(sd, points) for sd in signals.values()])
    except (AssertionError, ValueError) as error:
        raise ValueError(f"wavelengths: cannot align {what} onto the grid: {error}") from error


def _tabulated(kind, key):
    data = _mapping(kind)[key]
    values = np.array(data.values, dtype=np.float64).reshape(len(data.wavelengths), -1)
    return np.column_stack([np.asarray(data.wavelengths, dtype=np.float64), values])


@functools.lru_cache(maxsize=None)
def cmfs_tabulated(observer_key: str) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """colour-science's own tabulation of a standard observer: ``(wavelengths, xyz_bar (n, 3))``.

    ``observer_key`` is a key of :func:`observer_names` (see :func:`resolve_observer`).
    """
    table = _array("cmfs", [observer_key], lambda: _tabulated("observers", observer_key), 2)
    return table[:, 0], table[:, 1:]


def _aligned(kind, key, grid, what, ndim):
    """colour-science's ``mapping[key]`` of ``kind`` aligned to ``grid``, cached."""
    grid = [float(w) for w in grid]
    return _array(f"{kind}-aligned", [key, grid],
                  lambda: _align(_mapping(kind)[key], grid, what), ndim)


def cmfs_aligned(observer_key: str, grid: Iterable[float]) -> npt.NDArray[np.float64]:
    """A standard observer's CMFs aligned to the uniform ``grid`` (a tuple of nm) by colour-science:
    ``MSDS_CMFS_STANDARD_OBSERVER[key].copy().align(SpectralShape(...)).values``, shape (n, 3)."""
    return _aligned("observers", observer_key, grid, f"the {observer_key} CMFs", 2)


@functools.lru_cache(maxsize=None)
def illuminant_tabulated(illuminant_key: str
                         ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """colour-science's own tabulation of an illuminant: ``(wavelengths, SPD (n,))``."""
    table = _array("illuminant", [illuminant_key],
                   lambda: _tabulated("illuminants", illuminant_key), 2)
    return table[:, 0], table[:, 1]


def illuminant_aligned(illuminant_key: str, grid: Iterable[float]) -> npt.NDArray[np.float64]:
    """An illuminant's SPD aligned to the uniform ``grid`` by colour-science, shape (n,)."""
    return _aligned("illuminants", illuminant_key, grid, f"illuminant {illuminant_key}", 1)


# -- display constants ---------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def rgb_colourspace_matrix(colourspace: str
                           ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """``(normalised primary matrix (3, 3), whitepoint XYZ (3,))`` of an RGB colourspace.

    Both by colour-science: ``colour.normalised_primary_matrix(cs.primaries, cs.whitepoint)``
    (SMPTE RP 177 derivation) and ``colour.xy_to_XYZ(cs.whitepoint)`` for
    ``cs = colour.RGB_COLOURSPACES[colourspace]``.
    """
    def compute():
        colour = _colour()
        cs = colour.RGB_COLOURSPACES[colourspace]
        M = colour.normalised_primary_matrix(cs.primaries, cs.whitepoint)
        return np.vstack([M, colour.xy_to_XYZ(cs.whitepoint)])

    table = _array("rgb-colourspace", [colourspace], compute, 2)
    return table[:3], table[3]


@functools.lru_cache(maxsize=None)
def chromatic_adaptation_matrix(transform: str) -> npt.NDArray[np.float64]:
    """colour-science's ``CHROMATIC_ADAPTATION_TRANSFORMS[transform]`` (XYZ -> sharpened RGB)."""
    return _array(
        "chromatic-adaptation", [transform],
        lambda: _colour().adaptation.CHROMATIC_ADAPTATION_TRANSFORMS[transform], 2,
    )


@functools.lru_cache(maxsize=None)
def transfer_decoding_8bit(function: str) -> npt.NDArray[np.float64]:
    """The 256 linear values of the 8-bit codes ``0..255`` decoded by colour-science:
    ``colour.cctf_decoding(codes / 255, function="sRGB")`` for ``"sRGB"`` (IEC 61966-2-1 EOTF),
    ``colour.models.eotf_BT1886(codes / 255, L_B=0, L_W=1)`` for ``"BT.1886"``. Indexing it
    with a code gives the very float colour-science gives for that code."""
    def compute():
        colour = _colour()
        V = np.arange(256) / 255
        if function == "sRGB":
            return colour.cctf_decoding(V, function="sRGB")
        return colour.models.eotf_BT1886(V, L_B=0, L_W=1)

    if function not in ("sRGB", "BT.1886"):
        raise ValueError(f"transfer function {function!r}: known are 'sRGB', 'BT.1886'")
    return _array("transfer-decoding-8bit", [function], compute, 1)


# -- Munsell notations ---------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def munsell_value_and_Y(notation: str) -> tuple[float, float | None]:
    """``(V, Y)`` of a Munsell notation by colour-science, cached like the tables.

    ``V = munsell_colour_to_munsell_specification(notation)[1]`` (the Munsell value) and, if
    ``0 <= V <= 10``, ``Y = munsell_colour_to_xyY(notation)[2]`` (the luminance factor), else
    ``Y = None``. A notation colour-science cannot read raises colour-science's own error
    (ValueError, AssertionError, KeyError or IndexError), which is not cached; its warnings are
    silenced.
    """
    path = _path("munsell", [notation], ".json")
    try:
        stored = json.loads(_load(path))
        V, Y = stored["V"], stored["Y"]
        if isinstance(V, float) and (Y is None or isinstance(Y, float)):
            return V, Y
    except (OSError, ValueError, KeyError, TypeError):
        pass
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from colour.notation.munsell import munsell_colour_to_munsell_specification

        V = float(munsell_colour_to_munsell_specification(notation)[1])
        Y = float(_colour().munsell_colour_to_xyY(notation)[2]) if 0.0 <= V <= 10.0 else None
    _store(path, lambda file: file.write(json.dumps({"V": V, "Y": Y}).encode()))
    return V, Y


def forget() -> None:
    """Forget the tables held in this process's memory (the cache files stay); for tests."""
    for function in (_colour_science_version, _names, cmfs_tabulated, illuminant_tabulated,
                     rgb_colourspace_matrix, chromatic_adaptation_matrix, munsell_value_and_Y,
                     transfer_decoding_8bit):
        function.cache_clear()
