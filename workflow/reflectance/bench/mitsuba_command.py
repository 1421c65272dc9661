"""Mitsuba's whole command, for the bench's comparison of whole commands.

Issue 9 compares the two renderers' *whole commands* at equal error: ours is
``reflectance render SCENE.yaml -o OUT.exr`` (Python's start-up, imports, the scene's loading,
the render, the EXR), and Mitsuba's is this module run in a fresh process,

    python -m reflectance.bench.mitsuba_command SCENE.json VARIANT SPP OUT.exr

which starts Python, imports Mitsuba, sets its variant, loads the scene (its PLY meshes and
BSDFs; Dr.Jit compiles or takes from its cache the kernels), renders it at ``SPP`` samples per
pixel and writes the image as OpenEXR: what a user of Mitsuba's Python API runs. It imports
nothing but Mitsuba and the standard library (``reflectance`` and ``reflectance.bench`` import
nothing heavy).

``SCENE.json`` is the dictionary :func:`reflectance.bench.crosscheck.scene_to_mitsuba` makes,
saved by :func:`save_scene` with its camera's transform as the look-at triple it was made from
(a Mitsuba transform is not JSON).
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from reflectance.render.camera import Camera

__all__ = ["save_scene", "main"]


def save_scene(doc: dict[str, Any],  # Mitsuba's nested dictionary of a scene: values of all kinds
               camera: Camera, path: str | os.PathLike[str]) -> None:
    """Write the ``mitsuba.load_dict`` dictionary ``doc`` as JSON to ``path``, its sensor's
    ``to_world`` replaced by the look-at triple of ``camera`` (a
    :class:`reflectance.render.camera.Camera`), which :func:`main` turns back into it."""
    sensor = {key: value for key, value in doc["sensor"].items() if key != "to_world"}
    sensor["look_at"] = {"origin": [float(x) for x in camera.position],
                         "target": [float(x) for x in camera.look_at],
                         "up": [float(x) for x in camera.up]}
    with open(path, "w", encoding="utf-8") as file:
        json.dump({**doc, "sensor": sensor}, file)


def main(argv: Sequence[str] | None = None) -> None:
    """Render ``SCENE.json`` with Mitsuba's ``VARIANT`` at ``SPP`` samples per pixel into
    ``OUT.exr`` (the film's channels, as Mitsuba writes them)."""
    scene_path, variant, spp, out = sys.argv[1:] if argv is None else argv
    spp = int(spp)
    import mitsuba as mi

    mi.set_variant(variant)
    with open(scene_path, encoding="utf-8") as file:
        doc = json.load(file)
    sensor = doc["sensor"]
    sensor["to_world"] = mi.ScalarTransform4f().look_at(**sensor.pop("look_at"))
    sensor["sampler"]["sample_count"] = spp
    image = mi.render(mi.load_dict(doc), spp=spp)
    mi.Bitmap(image).write(out)


if __name__ == "__main__":  # pragma: no cover - run by the bench in a fresh process
    main()
