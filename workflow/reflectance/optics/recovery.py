"""Spectral recovery: the smoothest non-negative reflectance with given tristimulus values.

Meng et al. (2015) recover a reflectance from XYZ as the smoothest spectrum that has those
values: the least sum of squared first differences subject to ``W r = XYZ`` and ``r >= 0``.
colour-science's ``XYZ_to_sd_Meng2015`` hands that problem to scipy's SLSQP with gradients by
finite differences and ``ftol = 1e-10``. It stops up to 3e-3 (in reflectance) short of the
minimum, and where it stops depends on the CPU's BLAS kernels (OpenBLAS's Haswell and SkylakeX
kernels gave answers 3.7e-4 apart on one Munsell colour): the committed derived spectra could
not be re-derived on another machine.

The problem is a convex quadratic programme with a unique minimum (the objective is strictly
convex on the plane ``W r = XYZ``: its only flat direction, a constant offset, changes Y). This
module solves it exactly by its optimality (Karush-Kuhn-Tucker) conditions on an active set of
wavelengths held at zero. The answer is the one minimum whatever the summation order, and
agrees across OpenBLAS's kernels to about 1e-14, eight orders below the 6 significant digits the
CSVs are written at (tests/test_recovery.py checks the optimality conditions, colour-science's
own solver approaching this answer, and the derived files under several kernels).

References
----------
- Meng, J., Simon, F., Hanika, J., & Dachsbacher, C. (2015). Physically Meaningful Rendering
  using Tristimulus Colours. Computer Graphics Forum, 34(4), 31-40. doi:10.1111/cgf.12676
- Nocedal, J., & Wright, S. J. (2006). Numerical Optimization, 2nd ed., Springer: sect. 16.5,
  active-set methods for convex quadratic programmes.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["reflectance_Meng2015", "RecoveryError"]


class RecoveryError(ValueError):
    """The recovery found no spectrum (tristimulus values no non-negative spectrum has)."""


def _first_difference_gram(n):
    # D^T D for the first differences D (n - 1 by n): the objective is r^T (D^T D) r
    D = np.diff(np.eye(n), axis=0)
    return D.T @ D


def reflectance_Meng2015(XYZ: npt.ArrayLike, weights: npt.ArrayLike,
                         max_rounds: int | None = None) -> npt.NDArray[np.float64]:
    """The smoothest non-negative spectrum ``r`` with ``weights @ r == XYZ`` (Meng et al. 2015).

    Minimises ``sum(diff(r) ** 2)`` subject to ``weights @ r = XYZ`` and ``r >= 0`` exactly:
    the Karush-Kuhn-Tucker system of the wavelengths not held at zero is solved, wavelengths
    whose value came out negative are held at zero, and a held one whose multiplier is negative
    is freed again, until every condition holds.

    Parameters
    ----------
    XYZ : array_like
        Tristimulus values, shape (3,), on the scale of ``weights @ r``.
    weights : array_like
        Tristimulus weights, shape (3, n): ``weights @ r`` are the XYZ of the spectrum ``r``
        sampled at the n wavelengths (e.g. colour-science's ``sd_to_XYZ_integration`` of each
        unit spectrum).
    max_rounds : int, optional
        Bound on the active-set rounds; default ``2 n + 10``.

    Returns
    -------
    numpy.ndarray
        The spectrum, shape (n,), with exact zeros where the bound ``r >= 0`` is active.

    Raises
    ------
    RecoveryError
        If ``XYZ`` is not finite, or no non-negative spectrum has it (the rounds run out or the
        system is singular, as for an XYZ outside the spectral locus).

    Examples
    --------
    Three box-shaped weights: the smoothest spectrum with equal values is flat.

    >>> W = np.kron(np.eye(3), np.ones(4)) / 4
    >>> reflectance_Meng2015([0.5, 0.5, 0.5], W).round(12).tolist()
    [0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5]

    A colour with no third channel holds the last wavelengths at zero:

    >>> r = reflectance_Meng2015([0.5, 0.25, 0.0], W)
    >>> bool((r >= 0).all() and r[8:].max() == 0.0), np.allclose(W @ r, [0.5, 0.25, 0.0])
    (True, True)
    """
    W = np.asarray(weights, dtype=np.float64)
    target = np.asarray(XYZ, dtype=np.float64)
    if W.ndim != 2 or target.shape != (W.shape[0],):
        raise ValueError(f"XYZ of shape {target.shape} does not fit weights of shape {W.shape}")
    if not np.isfinite(target).all():
        raise RecoveryError(f"XYZ {target.tolist()} is not finite")
    constraints, n = W.shape
    Q2 = 2.0 * _first_difference_gram(n)  # the objective's Hessian
    held = np.zeros(n, dtype=bool)
    rounds = 2 * n + 10 if max_rounds is None else max_rounds
    for _ in range(rounds):
        free = ~held
        m = int(free.sum())
        if m < constraints:  # fewer free wavelengths than values to meet: no spectrum
            break
        # Stationarity on the free wavelengths and the constraints (Nocedal & Wright eq. 16.5):
        # [2 Q_ff  -W_f^T] [r_f]   [0  ]
        # [W_f      0    ] [lam] = [XYZ]
        K = np.zeros((m + constraints, m + constraints))
        K[:m, :m] = Q2[np.ix_(free, free)]
        K[:m, m:] = -W[:, free].T
        K[m:, :m] = W[:, free]
        try:
            solution = np.linalg.solve(K, np.concatenate([np.zeros(m), target]))
        except np.linalg.LinAlgError:
            break
        r = np.zeros(n)
        r[free] = solution[:m]
        negative = free & (r < 0.0)
        if negative.any():
            held |= negative
            continue
        # the multipliers of the held bounds r_i >= 0: each must be >= 0 at the minimum
        multipliers = Q2 @ r - W.T @ solution[m:]
        wrong = held & (multipliers < 0.0)
        if wrong.any():
            held[np.argmin(np.where(wrong, multipliers, np.inf))] = False
            continue
        # a nearly singular system (a colour at the edge of the locus) solves to a spectrum
        # that misses the XYZ: that is no answer
        if np.abs(W @ r - target).max() > 1e-9 * max(np.abs(target).max(), 1e-300):
            break
        return r
    raise RecoveryError(f"no non-negative spectrum has XYZ {target.tolist()} (the smoothest one "
                        f"was not found in {rounds} rounds)")
