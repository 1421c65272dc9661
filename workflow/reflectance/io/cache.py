"""The small on-disk cache of values computed once and then read with numpy only.

Its folder is ``$REFLECTANCE_CACHE`` or ``${XDG_CACHE_HOME:-~/.cache}/reflectance``; each user of
it (:mod:`reflectance.colour.tables`, the meshes of :mod:`reflectance.geometry.shapes`) keeps a
folder of its own there, named after what its values depend on, and names each file by a hash of
what it holds. Files are written atomically (a temporary file, then a rename), so a reader sees a
whole file or none; an unwritable or unreadable cache is ignored (the values are computed again).
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import tempfile
from pathlib import Path

__all__ = ["CACHE_ENVIRONMENT_VARIABLE", "cache_root", "file_name", "store",
           "distribution_version", "source_digest", "prune"]

CACHE_ENVIRONMENT_VARIABLE = "REFLECTANCE_CACHE"
"""Environment variable naming the cache folder (default ``${XDG_CACHE_HOME:-~/.cache}/reflectance``)."""


def cache_root():
    """The cache's folder (may not exist yet)."""
    root = os.environ.get(CACHE_ENVIRONMENT_VARIABLE)
    if not root:
        root = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "reflectance"
    return Path(root)


def file_name(layout, kind, parts, suffix, default=None):
    """``KIND-HASH.SUFFIX``: the name of a cached value of ``kind``, HASH a digest of the JSON of
    ``[layout, kind, parts]`` (``layout``: the user's file-layout version; ``default`` as
    :func:`json.dumps` takes it, for values JSON does not know)."""
    import json

    digest = hashlib.sha256(json.dumps([layout, kind, parts], default=default).encode())
    return f"{kind}-{digest.hexdigest()[:24]}{suffix}"


def store(path, write):
    """Write ``path`` atomically with ``write(file)``; give up silently if the cache is unwritable."""
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        with os.fdopen(fd, "wb") as file:
            write(file)
        os.replace(tmp, path)
    except OSError:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def distribution_version(module, distribution):
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


def source_digest(*paths):
    """SHA-256 (hex, 16 digits) of these source files' bytes: a cached value keyed by it is
    computed again after any change of the code that computes it."""
    digest = hashlib.sha256()
    for path in paths:
        digest.update(Path(path).read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def prune(current, pattern, days):
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
