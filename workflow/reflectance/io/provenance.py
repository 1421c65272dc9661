"""The provenance manifest of a build: what made ``results/``, in one YAML file.

``results/provenance.yaml`` (rule ``provenance``) records the git commit of the checkout (and
whether tracked files differed from it), the SHA-256 of config.yaml and of the configuration the
workflow ran with, of every spectrum, the Python and package versions of the environment, and the
SHA-256 of every output but a measurement (a timing, which differs from run to run: listed by path). Someone holding an archive of the results can check each file against it,
and rebuild in the environment it names (``workflow/envs/constraints.txt`` pins the same versions).

Beside each audit table, a smaller file of the same kind (:func:`write_metadata`) says what that
one table was computed from: the illuminant, the observer, the grids, the input's SHA-256, the
versions, each column's unit and precision; a table read on its own then still says what it is.

The manifest is deterministic: no timestamps, no host names, keys sorted; the same checkout,
environment and outputs give the same bytes, so byte-identical reruns stay byte-identical. It is
the input of no rule: it hashes the outputs, nothing hashes it.
"""

from __future__ import annotations

import hashlib
import json
import os
import platform
import subprocess
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import yaml

from reflectance.io.atomic import atomic_write

__all__ = ["sha256_file", "git_state", "package_versions", "provenance", "write_provenance",
           "METADATA_FORMAT", "metadata_path", "write_metadata"]

FORMAT = "reflectance provenance 1"
#: the first key of the metadata file beside an audit's table (:func:`write_metadata`)
METADATA_FORMAT = "reflectance audit metadata 1"


def sha256_file(path: str | os.PathLike[str]) -> str:
    """Hex SHA-256 of a file's bytes.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> _ = p.write_bytes(b"abc")
    >>> sha256_file(p)[:16]
    'ba7816bf8f01cfea'
    """
    digest = hashlib.sha256()
    with open(path, "rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def git_state(root: str | os.PathLike[str] = ".") -> dict[str, str | bool | None]:
    """``{"commit": sha or None, "dirty": bool or None}`` of the checkout whose top folder is
    ``root``: None where there is no git or no repository of its own (an unpacked archive, a
    copy); dirty when tracked files differ from the commit (results/ and logs/ are ignored by
    git)."""
    def git(*args: str) -> str | None:
        try:
            proc = subprocess.run(["git", *args], cwd=root, capture_output=True, text=True,
                                  timeout=60)
        except (OSError, subprocess.SubprocessError):
            return None
        return proc.stdout.strip() if proc.returncode == 0 else None

    top = git("rev-parse", "--show-toplevel")
    # a copy of the project inside some other repository is not that repository's commit
    if top is None or Path(top).resolve() != Path(root).resolve():
        return {"commit": None, "dirty": None}
    commit = git("rev-parse", "--verify", "HEAD")
    if commit is None:
        return {"commit": None, "dirty": None}
    status = git("status", "--porcelain", "--untracked-files=no")
    return {"commit": commit, "dirty": None if status is None else bool(status)}


def package_versions() -> dict[str, str]:
    """``{name: version}`` of every distribution installed in this Python (names lower case)."""
    from importlib.metadata import distributions

    out = {}
    for dist in distributions():
        name = (dist.metadata["Name"] or "").strip().lower()
        if name and name not in out:
            out[name] = dist.version
    return dict(sorted(out.items()))


def _canonical_sha256(value):
    text = json.dumps(value, sort_keys=True, separators=(",", ":"), ensure_ascii=True)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def provenance(outputs: Iterable[str | os.PathLike[str]], spectra: Iterable[str | os.PathLike[str]],
               config: Mapping[str, Any], config_file: str | None = "config.yaml",
               git: Mapping[str, str | bool | None] | None = None,
               root: str | os.PathLike[str] = ".",
               measurements: Iterable[str | os.PathLike[str]] = ()
               ) -> dict[str, Any]:  # JSON: values of all kinds
    """The manifest as a dict (see the module's description).

    Parameters
    ----------
    outputs, spectra : iterable of str
        Files (relative to ``root``) hashed under ``outputs`` and ``spectra``.
    measurements : iterable of str
        Outputs that differ from run to run (timings): listed by path under ``measurements``,
        not hashed, so that the manifest of a rerun stays the same bytes.
    config : mapping
        The configuration the workflow ran with (Snakemake's ``config``: config.yaml, defaults
        and any ``--config``); hashed as canonical JSON.
    config_file : str
        Hashed as bytes (None: left out).
    git : mapping, optional
        :func:`git_state`'s answer (default: asked of ``root``).
    """
    root = Path(root)
    files = lambda names: {str(n): sha256_file(root / n) for n in sorted(set(map(str, names)))}  # noqa: E731
    return {
        "format": FORMAT,
        "git": dict(git) if git is not None else git_state(root),
        "config": {
            "file": config_file,
            "file_sha256": None if config_file is None else sha256_file(root / config_file),
            "resolved_sha256": _canonical_sha256(config),
        },
        "python": {"version": platform.python_version(),
                   "implementation": platform.python_implementation(),
                   "platform": f"{sys.platform}-{platform.machine()}"},
        "packages": package_versions(),
        "spectra": files(spectra),
        "outputs": files(outputs),
        "measurements": sorted(set(map(str, measurements))),
    }


def write_provenance(path: str | os.PathLike[str], manifest: Mapping[str, Any]) -> None:
    """Write a :func:`provenance` manifest as YAML (keys in order, atomically)."""
    text = ("# Provenance of this build (reflectance.io.provenance): check a file with\n"
            "#   sha256sum <file>   against its entry under outputs.\n"
            + yaml.safe_dump(manifest, sort_keys=False, default_flow_style=False, width=100))
    with atomic_write(path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")


def metadata_path(table: str | os.PathLike[str]) -> Path:
    """The metadata file beside a table: ``audit.csv`` -> ``audit_metadata.yaml``.

    Examples
    --------
    >>> metadata_path("out/audit.csv").as_posix()
    'out/audit_metadata.yaml'
    """
    table = Path(table)
    return table.with_name(f"{table.stem}_metadata.yaml")


def write_metadata(path: str | os.PathLike[str], document: Mapping[str, Any],
                   tables: Iterable[str | os.PathLike[str]] = ()) -> None:
    """Write an audit table's metadata ``document`` (a mapping, in the order to be read) as YAML,
    atomically; with ``tables`` (paths), their SHA-256 under ``tables`` at the end.

    Deterministic: no timestamps or host names, so a rerun with the same inputs writes the same
    bytes (the tables it hashes are deterministic too).
    """
    document = {"format": METADATA_FORMAT, **document}
    if tables:
        document["tables"] = {Path(t).name: sha256_file(t) for t in tables}
    text = ("# What the table beside this file was computed from (reflectance.io.provenance): "
            "check it with\n#   sha256sum <table>   against its entry under tables.\n"
            + yaml.safe_dump(document, sort_keys=False, default_flow_style=False, width=100,
                             allow_unicode=True))
    with atomic_write(path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
