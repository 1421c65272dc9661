"""Paths taken from data: a file named in config.yaml stays inside the project, one named in a
scene inside the scene file's folder; a material is a name, not a path. And where the package's
own data (``reflectance/data``) is."""

from __future__ import annotations

import os
import re
from importlib.resources.abc import Traversable
from pathlib import Path

__all__ = ["package_data", "file_inside", "project_file", "check_name"]

#: a name: no path separator ('/' or '\\'), no control character, not starting with '.'
_NAME = re.compile(r"[^/\\\x00-\x1f.][^/\\\x00-\x1f]*")


def package_data(*parts: str) -> Traversable:
    """The file or folder ``reflectance/data/<parts>`` of the installed package.

    Found with :mod:`importlib.resources`, so that it is the package's own copy wherever the
    package was installed (package data in a wheel; in a source checkout ``data/config.yaml``
    and ``data/spectra`` are links to the project's).

    Examples
    --------
    >>> package_data("scene.schema.yaml").name
    'scene.schema.yaml'
    """
    from importlib.resources import files

    return files("reflectance").joinpath("data", *parts)


def file_inside(value: str | os.PathLike[str], root: str | os.PathLike[str],
                where: str = "the project folder") -> str:
    """``value`` (a relative path read from data) as a POSIX path, if it stays inside ``root``.

    ValueError otherwise (an absolute path, or one that leaves ``root`` through ``..`` or a
    symbolic link), saying so with ``where``, the name of ``root`` in the message.

    Examples
    --------
    >>> file_inside("mats/my_metal.csv", ".", "the scene file's folder")
    'mats/my_metal.csv'
    >>> file_inside("/etc/passwd", ".", "the scene file's folder")
    Traceback (most recent call last):
    ...
    ValueError: '/etc/passwd' is absolute; give a path inside the scene file's folder
    """
    if not isinstance(value, str) or not value.strip():
        raise ValueError(f"{value!r} is not a file path")
    path = Path(value)
    if path.is_absolute() or path.drive:
        raise ValueError(f"{value!r} is absolute; give a path inside {where}")
    root = Path(root).resolve()
    if ".." in path.parts or not (root / path).resolve().is_relative_to(root):
        raise ValueError(f"{value!r} leaves {where}; give a path inside it")
    return path.as_posix()


def project_file(value: str | os.PathLike[str], key: str, root: str | os.PathLike[str]) -> str:
    """``value`` (a path from config ``key``) as a path relative to the project folder ``root``.

    Refuses, naming ``key``, an absolute path or one that leaves ``root`` (through ``..`` or a
    symbolic link): data files named in the config are the project's own.

    Examples
    --------
    >>> project_file("workflow/report/errata.yaml", "figures.errata.rows", ".")
    'workflow/report/errata.yaml'
    >>> project_file("../x.yaml", "figures.errata.rows", ".")
    Traceback (most recent call last):
    ...
    ValueError: figures.errata.rows: '../x.yaml' leaves the project folder; give a path inside it
    """
    try:
        return file_inside(value, root)
    except ValueError as err:
        raise ValueError(f"{key}: {err}") from None


def check_name(name: str, what: str = "material") -> str:
    """``name`` if it is a plain name (no path separator, not '.' or '..'), else ValueError.

    Examples
    --------
    >>> check_name("Cu")
    'Cu'
    >>> check_name("../x/Cu")
    Traceback (most recent call last):
    ...
    ValueError: material '../x/Cu' is not a name (a name has no path separators or leading '.')
    """
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise ValueError(f"{what} {name!r} is not a name (a name has no path separators or "
                         f"leading '.')")
    return name
