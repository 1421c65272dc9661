"""Caption values: the numbers a report caption states, written by the job that computed them.

A figure's job writes ``<figure>.values.rst`` beside its table: one reStructuredText substitution
definition per number (``.. |onset_deg| replace:: 89.24``), taken from the table the job wrote.
Its caption (``workflow/report/*.rst``) includes the file first, ``.. include:: {{
snakemake.output.values }}``, and writes ``|onset_deg|`` where the number goes; Docutils replaces
it when Snakemake renders the report. So a caption types in only what the paper prints and its
parameters (templated from ``snakemake.params``), and a rebuild with other parameters cannot leave
a stale number in it.
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from pathlib import Path

from reflectance.io.atomic import atomic_write

__all__ = ["write_caption_values", "read_caption_values"]

#: a substitution name a caption can write as ``|name|`` (reStructuredText reference names that
#: need no quoting)
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_DEFINITION = re.compile(r"\.\. \|(?P<name>[^|]+)\| replace:: (?P<text>.+)")


def write_caption_values(path: str | os.PathLike[str], values: Mapping[str, str]) -> None:
    """Write ``values`` ({name: text}) to ``path`` as substitution definitions, in one rename.

    Each text is what the caption shows, formatted by the caller from its own table (``f"{x:.2f}"``
    of a cell as the CSV holds it). A name that is not a plain identifier, or a text that is empty,
    spans lines or reads as a missing number (``nan``, ``inf``), raises ``ValueError``: the caption
    would show it.

    Examples
    --------
    >>> import tempfile
    >>> path = Path(tempfile.mkdtemp()) / "fig.values.rst"
    >>> write_caption_values(path, {"onset_deg": f"{89.239248:.2f}", "material": "Cu"})
    >>> print(path.read_text(), end="")
    .. |onset_deg| replace:: 89.24
    .. |material| replace:: Cu
    >>> read_caption_values(path)
    {'onset_deg': '89.24', 'material': 'Cu'}
    >>> write_caption_values(path, {"ratio": f"{float('nan'):.2f}"})
    Traceback (most recent call last):
    ...
    ValueError: caption value ratio is 'nan'
    """
    lines = []
    for name, text in values.items():
        text = str(text)
        if not _NAME.match(name):
            raise ValueError(f"caption value name {name!r} is not an identifier")
        if (not text.strip() or "\n" in text
                or text.strip().lstrip("+-").lower() in ("nan", "inf", "infinity")):
            raise ValueError(f"caption value {name} is {text!r}")
        lines.append(f".. |{name}| replace:: {text}\n")
    with atomic_write(path) as tmp:
        Path(tmp).write_text("".join(lines))


def read_caption_values(path: str | os.PathLike[str]) -> dict[str, str]:
    """{name: text} of a file :func:`write_caption_values` wrote."""
    values = {}
    for line in Path(path).read_text().splitlines():
        found = _DEFINITION.fullmatch(line)
        if found is None:
            raise ValueError(f"{path}: not a caption value: {line!r}")
        values[found["name"]] = found["text"]
    return values
