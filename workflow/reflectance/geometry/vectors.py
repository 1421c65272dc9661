"""Small 3-vector helpers shared by the camera, the lights, the ray tests and the papers' scenes."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["unit_vector", "normalize", "dot"]


def unit_vector(v: npt.ArrayLike, name: str) -> npt.NDArray[np.float64]:
    """``v`` scaled to length 1; a one-line error naming ``name`` if it is not a finite non-zero 3-vector."""
    v = np.asarray(v, dtype=np.float64)
    norm = np.linalg.norm(v)
    if v.shape != (3,) or not np.isfinite(norm) or norm == 0:
        raise ValueError(f"{name} must be a non-zero finite 3-vector, got {v!r}")
    return v / norm


def normalize(v: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Rows of ``v`` (..., 3) scaled to length 1; zero rows stay zero."""
    norm = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(norm > 0, norm, 1.0)


def dot(a: npt.NDArray[np.float64],
        b: npt.NDArray[np.float64]) -> npt.NDArray[np.float64] | np.float64:
    """Row-wise dot product of (..., 3) arrays."""
    return np.einsum("...i,...i->...", a, b)
