"""Table output: CSV written atomically, the same bytes on every run."""

from __future__ import annotations

from reflectance.io.atomic import atomic_write

__all__ = ["write_csv"]


def write_csv(table, path, **options):
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
