"""Sizes read from data, bounded before any work: what an array or a loop of that size would cost.

Every size that sets an array or a loop (a step, a count, a grid; in config.yaml, a scene file or
on the command line) is checked against an estimate made before any work starts: the number of
elements it makes (its points times the other dimensions of the same arrays), at
:data:`ELEMENT_BYTES` and :data:`ELEMENT_SECONDS` each, against this machine's memory and
:data:`MAX_SECONDS`. :func:`size_problem` says, in one line naming the key, what the size makes
and what it would cost. The renders' own estimate (measured peaks) is
:func:`reflectance.render.memory.render_memory_bytes`.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence

__all__ = ["ELEMENT_BYTES", "ELEMENT_SECONDS", "MAX_SECONDS", "physical_memory_bytes",
           "grid_points", "size_problem", "describe_bytes", "describe_seconds"]

#: Bytes per element of a computed array: the float64 value and the temporaries numpy makes
#: beside it (a complex Fresnel evaluation holds about eight float64 arrays of its size at once).
ELEMENT_BYTES = 64

#: Seconds per element: numpy's exact Fresnel of a metal (the costliest per-element formula of
#: the figures and audits) took 0.75 microseconds per element on the project's machine under
#: load (CHANGELOG, 2026-12-05); rounded up.
ELEMENT_SECONDS = 1e-6

#: Longest estimated computation of one size (one job's arrays): an hour.
MAX_SECONDS = 3600.0


def physical_memory_bytes() -> int | None:
    """This machine's physical memory (None where the system does not tell)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        return None


def grid_points(span: float, step: float, ends: int = 1) -> int:
    """Points of a grid of ``step`` over ``span`` (counted: no array is made), plus ``ends``.

    Examples
    --------
    >>> grid_points(90.0, 0.25)
    361
    >>> grid_points(90.0, 1e-9) > 1e10
    True
    """
    return math.floor(span / step + 1e-9) + ends


def describe_bytes(n: float) -> str:
    """'74.5 GiB', '12 MiB'."""
    return f"{n / 2**30:.1f} GiB" if n >= 2**30 else f"{n / 2**20:.0f} MiB"


def describe_seconds(t: float) -> str:
    """'13 h', '25 min', '4 s'."""
    return (f"{t / 3600:.0f} h" if t >= 3600 else f"{t / 60:.0f} min" if t >= 60
            else f"{t:.0f} s")


def size_problem(key: str, value: str, dims: Sequence[tuple[float, str]],
                 memory: float | None = None, max_seconds: float = MAX_SECONDS,
                 streamed: bool = False) -> str | None:
    """One line if the arrays a size makes cannot fit or take too long, else None.

    Parameters
    ----------
    key : str
        What names the size (``figures.x.step_deg``, ``scene.yaml: fresnel_table_size``).
    value : str
        The size as given (``1e-09 degrees``).
    dims : sequence of (count, noun)
        The dimensions of the arrays it makes, the size's own first (``(1e10, "angles")``).
    memory : float, optional
        Bytes available (default: this machine's physical memory).
    streamed : bool
        The work goes through its elements in chunks of bounded size (a Fresnel table, brute
        force shading, one angle at a time): only its time counts.

    Examples
    --------
    >>> size_problem("a.step", "1e-09 degrees", [(9e10, "angles"), (95, "wavelengths")],
    ...              memory=8 * 2**30)
    'a.step: 1e-09 degrees makes 9e+10 angles x 95 wavelengths: about 509619.7 GiB and 2375 h (this machine: 8.0 GiB, at most 1 h); choose a coarser step or a smaller count'
    >>> size_problem("a.step", "0.25 degrees", [(361, "angles")]) is None
    True
    """
    memory = physical_memory_bytes() if memory is None else memory
    elements = math.prod(float(n) for n, _ in dims)
    need, seconds = elements * ELEMENT_BYTES, elements * ELEMENT_SECONDS
    if (streamed or memory is None or need <= memory) and seconds <= max_seconds:
        return None
    made = " x ".join(f"{n:.3g} {noun}" for n, noun in dims)
    if streamed:
        return (f"{key}: {value} makes {made}: about {describe_seconds(seconds)} of work (at "
                f"most {describe_seconds(max_seconds)}); choose a coarser step or a smaller "
                f"count")
    limit = f"{describe_bytes(memory)}, " if memory is not None else ""
    return (f"{key}: {value} makes {made}: about {describe_bytes(need)} and "
            f"{describe_seconds(seconds)} (this machine: {limit}at most "
            f"{describe_seconds(max_seconds)}); choose a coarser step or a smaller count")
