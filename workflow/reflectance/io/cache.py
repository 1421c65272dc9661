"""The library's caches, each named and bounded, and the one way to clear them (:func:`clear`).

In this process, a :class:`Memo` keeps at most its ``limit`` of values by key, the least recently
used dropped first. The library's memos, all of them here (:data:`MEMOS` by name):

- :data:`BUILT_MESHES`, the meshes built from a scene's geometry keys
  (:mod:`reflectance.render.scene`): a figure that renders many scenes of one object (Cook &
  Torrance's thirteen Fig. 7 vases) builds it once;
- :data:`COMPOSED_MESHES`, the scenes' composed meshes by their objects' geometry and
  transform keys: scenes that differ only in materials, lights or camera compose them once;
- :data:`TRACES`, camera visibility and shadow masks by what they depend on
  (:func:`reflectance.render.tracing.trace_key`): renders of scenes that differ only in
  materials, spectra, intensities or the ambient term, which ask for it, trace once.

On disk, the cache's folder is ``$REFLECTANCE_CACHE`` or
``${XDG_CACHE_HOME:-~/.cache}/reflectance``; each user of it (:mod:`reflectance.colour.tables`,
the meshes of :mod:`reflectance.geometry.shapes`) keeps a folder of its own there
(:data:`DISK_FOLDERS`), named after what its values depend on, and names each file by a hash of
what it holds; a folder for a code or library version no longer in use is pruned
(:func:`prune`). Files are written atomically (a temporary file, then a rename), so a reader sees
a whole file or none; each ends with the SHA-256 of what it holds, checked by :func:`load`, so a
file changed after it was written (by hand, a disk error, another program) is computed again, never
used (issue 25); an unwritable or unreadable cache is ignored (the values are computed again).
"""

from __future__ import annotations

import collections
import hashlib
import importlib.util
import os
import tempfile
from collections.abc import Callable, Hashable
from pathlib import Path
from typing import IO, Any, TypeVar

__all__ = ["Memo", "MEMOS", "BUILT_MESHES", "COMPOSED_MESHES", "TRACES", "clear",
           "CACHE_ENVIRONMENT_VARIABLE", "DISK_FOLDERS", "cache_root", "file_name", "store", "load",
           "distribution_version", "source_digest", "prune"]

_Value = TypeVar("_Value")

MEMOS: dict[str, Memo] = {}
"""Every :class:`Memo` of this process, by name."""


class Memo:
    """Values kept in this process by key: at most ``limit``, the least recently used dropped
    first.

    Parameters
    ----------
    name : str
        What it keeps (its key in :data:`MEMOS`; one memo per name).
    limit : int
        How many values it keeps.

    Examples
    --------
    >>> squares = Memo("squares, for this example", 2)
    >>> [squares.get(n, lambda: n * n) for n in (2, 3, 2, 4)], 3 in squares, len(squares)
    ([4, 9, 4, 16], False, 2)
    >>> del MEMOS[squares.name]
    """

    def __init__(self, name: str, limit: int) -> None:
        if name in MEMOS:
            raise ValueError(f"a memo named {name!r} exists already")
        if int(limit) < 1:
            raise ValueError(f"memo {name!r}: limit must be at least 1, got {limit!r}")
        self.name, self.limit = name, int(limit)
        # oldest use first; a memo keeps whatever its user makes (meshes, traces): any value
        self._values: collections.OrderedDict[Hashable, Any] = collections.OrderedDict()
        MEMOS[name] = self

    def get(self, key: Hashable, make: Callable[[], _Value]) -> _Value:
        """The value kept under ``key``; the first time, ``make()``'s, kept."""
        if key in self._values:
            self._values.move_to_end(key)
            return self._values[key]
        value = make()
        self._values[key] = value
        while len(self._values) > self.limit:
            self._values.popitem(last=False)
        return value

    def __contains__(self, key: object) -> bool:
        return key in self._values

    def __len__(self) -> int:
        return len(self._values)

    def clear(self) -> None:
        """Forget every value."""
        self._values.clear()

    def __repr__(self) -> str:
        return f"Memo({self.name!r}, {self.limit}: {len(self)} kept)"


BUILT_MESHES = Memo("built meshes", 4)
"""Meshes built from a scene's geometry (canonical JSON of its keys): the undeformed, unplaced
mesh of each geometry type but ``mesh`` (a file may change), shared by the scenes that copy it."""

COMPOSED_MESHES = Memo("composed meshes", 4)
"""Composed scene meshes by their objects' geometry and transform keys (canonical JSON)."""

TRACES = Memo("traces", 4)
"""``(samples, shadowed)`` of one-band images by :func:`reflectance.render.tracing.trace_key`:
at most 4 of at most :data:`reflectance.render.camera.SINGLE_TILE_SAMPLES` camera samples each
(the most any figure asks for, three: Blinn's Fig. 7, one per camera and light)."""


def clear(disk: bool = False) -> None:
    """Empty every memo of this process (:data:`MEMOS`); with ``disk``, remove the cache's
    folders on disk too (those named as :data:`DISK_FOLDERS` name them, nothing else of the
    cache's folder), so that every value is computed again. Best effort on disk."""
    import re
    import shutil

    for memo in MEMOS.values():
        memo.clear()
    if not disk:
        return
    ours = re.compile("|".join(f"(?:{pattern})" for pattern in DISK_FOLDERS.values())).fullmatch
    try:
        folders = [p for p in cache_root().iterdir() if ours(p.name) and p.is_dir()]
    except OSError:
        return
    for folder in folders:
        shutil.rmtree(folder, ignore_errors=True)

CACHE_ENVIRONMENT_VARIABLE = "REFLECTANCE_CACHE"
"""Environment variable naming the cache folder (default ``${XDG_CACHE_HOME:-~/.cache}/reflectance``)."""

DISK_FOLDERS = {
    "colour tables": r"colour-science-[^/]+",
    "meshes": r"meshes-[0-9a-f]{16}-numpy-[^/]+-scipy-[^/]+-pyvista-[^/]+",
}
"""The names of the cache's folders (whole-name regular expressions), by their user: colour-science's
tables (:func:`reflectance.colour.tables.cache_directory`) and the built meshes
(:mod:`reflectance.geometry.shapes`), pruned by them and removed by :func:`clear`."""


def cache_root() -> Path:
    """The cache's folder (may not exist yet)."""
    root = os.environ.get(CACHE_ENVIRONMENT_VARIABLE)
    if not root:
        root = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "reflectance"
    return Path(root)


def file_name(layout: int, kind: str, parts: object, suffix: str,
              default: Callable[[Any], Any] | None = None) -> str:
    """``KIND-HASH.SUFFIX``: the name of a cached value of ``kind``, HASH a digest of the JSON of
    ``[layout, kind, parts]`` (``layout``: the user's file-layout version; ``default`` as
    :func:`json.dumps` takes it, for values JSON does not know)."""
    import json

    digest = hashlib.sha256(json.dumps([layout, kind, parts], default=default).encode())
    return f"{kind}-{digest.hexdigest()[:24]}{suffix}"


_CHECKSUM_MARK = b"\nreflectance-sha256:"
"""What precedes the SHA-256 (32 bytes) that ends every cached file."""


def store(path: Path, write: Callable[[IO[bytes]], object]) -> None:
    """Write ``path`` atomically with ``write(file)``, followed by the SHA-256 of what it wrote
    (:func:`load` checks it); give up silently if the cache is unwritable.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "value.txt"
    >>> store(path, lambda file: file.write(b"42"))
    >>> load(path)
    b'42'
    >>> _ = path.write_bytes(path.read_bytes().replace(b"42", b"43", 1))   # changed afterwards
    >>> load(path)
    Traceback (most recent call last):
    ...
    ValueError: ...value.txt: its content does not match its checksum
    """
    import io

    tmp = None
    try:
        buffer = io.BytesIO()
        write(buffer)
        payload = buffer.getvalue()
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        with os.fdopen(fd, "wb") as file:
            file.write(payload + _CHECKSUM_MARK + hashlib.sha256(payload).digest())
        os.replace(tmp, path)
    except OSError:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def load(path: str | os.PathLike[str]) -> bytes:
    """The bytes :func:`store` wrote to ``path``, once their SHA-256 matches the one stored
    after them.

    Raises
    ------
    OSError
        The file cannot be read (or is missing).
    ValueError
        Its content does not match its checksum (changed since it was written, or written
        without one): compute the value again.
    """
    data = Path(path).read_bytes()
    end = len(data) - 32 - len(_CHECKSUM_MARK)
    payload, mark, digest = data[:max(end, 0)], data[end:end + len(_CHECKSUM_MARK)], data[-32:]
    if end < 0 or mark != _CHECKSUM_MARK or hashlib.sha256(payload).digest() != digest:
        raise ValueError(f"{path}: its content does not match its checksum")
    return payload


def distribution_version(module: str, distribution: str) -> str:
    """The installed version of ``distribution`` (whose top-level package is ``module``), read from
    its dist-info folder: no import of the package and no importlib.metadata (which alone takes
    ~0.1 s); else a tag of the package's location and time; "missing" if it is not installed."""
    spec = importlib.util.find_spec(module)
    if spec is None or not spec.origin:
        return "missing"
    origin = Path(spec.origin)
    prefix = f"{distribution}-"
    found = sorted(origin.parent.parent.glob(f"{distribution}-*.dist-info"))
    if len(found) == 1:
        return found[0].name[len(prefix):-len(".dist-info")]
    stamp = f"{origin}:{origin.stat().st_mtime_ns}"
    return "unknown-" + hashlib.sha256(stamp.encode()).hexdigest()[:12]


def source_digest(*paths: str | os.PathLike[str]) -> str:
    """SHA-256 (hex, 16 digits) of these source files' bytes: a cached value keyed by it is
    computed again after any change of the code that computes it."""
    digest = hashlib.sha256()
    for path in paths:
        digest.update(Path(path).read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def prune(current: Path, pattern: str, days: float) -> None:
    """Remove the folders beside ``current`` whose whole names match ``pattern`` (a regular
    expression), other than ``current``, that have gone ``days`` days without a change: values
    of the same kind, cached for a code or library version no longer in use. Best effort."""
    import re
    import shutil
    import time

    matches = re.compile(pattern).fullmatch
    oldest = time.time() - days * 86400
    try:
        stale = [p for p in current.parent.iterdir()
                 if p.name != current.name and matches(p.name) and p.is_dir()
                 and p.stat().st_mtime < oldest]
    except OSError:
        return
    for folder in stale:
        shutil.rmtree(folder, ignore_errors=True)
