"""Table output: CSV written atomically, the same bytes on every run; columns that say their unit
and are printed to the precision they carry."""

from __future__ import annotations

import math
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from reflectance.io.atomic import atomic_write

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["write_csv", "Column", "csv_cell", "csv_text", "columns_metadata"]


def write_csv(table: pd.DataFrame, path: str | os.PathLike[str], **options: Any) -> None:
    """Write a pandas DataFrame to ``path`` as CSV (no index, ``\\n`` line ends) in one rename.

    Usable as ``table.pipe(write_csv, path, float_format="%.6g")``; ``options`` go to
    ``DataFrame.to_csv``. An interrupted or failed write leaves any previous file untouched.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> import pandas as pd
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "t.csv"
    >>> pd.DataFrame({"a": [1.0 / 3]}).pipe(write_csv, path, float_format="%.3g")
    >>> path.read_text()
    'a\\n0.333\\n'
    """
    with atomic_write(path) as tmp:
        table.to_csv(tmp, index=False, lineterminator="\n", **options)


@dataclass(frozen=True)
class Column:
    """One column of a CSV: its name, unit, meaning and how its numbers are printed.

    A number is printed with ``decimals`` digits after the point (for a quantity whose precision
    is absolute: a colour difference, CIELAB, an angle on a grid), or with ``significant`` digits
    (for one whose precision is relative: XYZ, n, k); a column with neither holds text. Rounding
    removes the floating-point noise below that precision (``6.0e-15`` prints as ``0.0000``;
    ``-0`` as ``0``); NaN prints as an empty field.

    Examples
    --------
    >>> Column("dE", "", "CIEDE2000", decimals=4).format(6.0e-15)
    '0.0000'
    >>> Column("X", "", "tristimulus X", significant=7).format(0.123456789)
    '0.1234568'
    >>> Column("angle_deg", "deg", "angle", decimals=1).format(float("nan"))
    ''
    """

    name: str
    unit: str
    description: str
    decimals: int | None = None
    significant: int | None = None

    @property
    def precision(self) -> str:
        """How the column is printed, in words (for metadata and help texts)."""
        if self.decimals is not None:
            return f"{self.decimals} decimals"
        if self.significant is not None:
            return f"{self.significant} significant digits"
        return "text"

    def format(self, value: Any) -> str:
        if self.decimals is None and self.significant is None:
            return csv_cell(value)
        value = float(value)
        if not math.isfinite(value):
            return ""
        if self.decimals is not None:
            return f"{round(value, self.decimals) + 0.0:.{self.decimals}f}"
        return f"{float(f'{value:.{self.significant}g}') + 0.0:.{self.significant}g}"


def csv_cell(text: str) -> str:
    """A text field of a CSV: quoted only if it holds a comma, a quote or a line break."""
    text = "" if text is None else str(text)
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def csv_text(table: Mapping[str, Sequence[Any]], columns: Sequence[Column]) -> str:
    """CSV text of ``table`` (column name -> sequence) in the order of ``columns`` (:class:`Column`
    each), ``\\n`` line endings, each value printed as its column says."""
    lines = [",".join(c.name for c in columns)]
    for row in zip(*(table[c.name] for c in columns)):
        lines.append(",".join(c.format(v) for c, v in zip(columns, row)))
    return "\n".join(lines) + "\n"


def columns_metadata(columns: Iterable[Column]) -> dict[str, dict[str, str]]:
    """``{name: {"unit", "precision", "description"}}`` of ``columns``, for a metadata file."""
    return {c.name: {"unit": c.unit or "1", "precision": c.precision,
                     "description": c.description} for c in columns}
