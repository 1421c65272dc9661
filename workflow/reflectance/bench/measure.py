"""Speed and memory of the renderer at one image size: what ``reflectance bench`` measures.

For a scene (a scene file, or a scene document as :func:`reflectance.render.scene.scene_from_dict`
takes it; ``reflectance bench`` passes the copper vase of Cook & Torrance 1982, Fig. 6b, built
from config.yaml by the papers' scene builder) rendered square at several sizes with n x n
supersampling,
each size runs in its own Python process (:func:`reflectance.bench.run.run_bench`; so that its
peak resident memory, ``ru_maxrss``, which includes VTK's, belongs to that size alone), and
:func:`bench_size` reports:

- median wall seconds over ``runs`` renders (:func:`reflectance.render.pipeline.render`, in
  bands of rows for large images) of visibility (camera ID buffer + exact hits), cast shadows
  (every light) and shading (table path), and samples per second of each;
- the peak resident memory of those renders; the samples per pixel actually spent (the
  budget: n x n everywhere plus N x N in each pixel the adaptive supersampling refined,
  :mod:`reflectance.render.adaptive`, when the scene's ``camera.adaptive`` is on or
  ``adaptive`` says so) and the fraction of pixels refined;
- the error of the image against a converged reference: the same scene rendered with
  ``reference_supersample`` x ``reference_supersample`` samples per pixel everywhere
  (brute-force supersampling of the same shading, no adaptive refinement; box filter), as
  CIEDE2000 mean and 95th percentile over the lit pixels on the reference's exposure;
- brute-force per-wavelength shading of the same samples: its seconds, its speed ratio to the
  table and the CIEDE2000 (mean, max over the lit pixels) between the two images (images of
  one band only);
- at one size, the table and brute-force shading times on wavelength grids of different steps
  (5 nm and 1 nm by default): the table's time does not grow with the number of wavelengths.

Its defaults are the command's (the CLI reads them at parse: this module imports nothing heavy
at import), the path-tracer cross-check's too (:mod:`reflectance.bench.crosscheck`).

Speed targets are measured here, never asserted in tests.
"""

from __future__ import annotations

import os
import resource
import time
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from reflectance.io.progress import worker_main

if TYPE_CHECKING:
    import numpy.typing as npt

    from reflectance.optics.spectra import SpectraDirs
    from reflectance.render.scene import Scene

__all__ = ["load_bench_scene", "scene_difference", "bench_size"]

#: default samples per pixel side of the converged reference (twice the adaptive refinement's
#: default 8, so that a refined pixel is not compared with itself)
REFERENCE_SUPERSAMPLE = 16
#: the reference is skipped at sizes where it would exceed this many samples (512 px at 16 x 16)
REFERENCE_MAX_SAMPLES = 1 << 26
#: the size of the path-tracer cross-check (the issue's 512-px vase)
CROSSCHECK_SIZE = 512
#: samples per pixel of Mitsuba's converged reference in the cross-check (stratified)
CROSSCHECK_SPP = 1024
#: our supersamplings (n x n) timed in the cross-check, our ladder beside Mitsuba's
CROSSCHECK_SUPERSAMPLES = (1, 2)


def _peak_MiB():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: KiB


def scene_difference(XYZ: npt.ArrayLike, XYZ_reference: npt.ArrayLike,
                     scene: Scene) -> tuple[float, float]:
    """(mean, 95th percentile) CIEDE2000 of two renders of ``scene`` on the reference's
    Cook & Torrance exposure, in the scene's display illuminant, observer and wavelengths
    (:func:`reflectance.colour.difference.difference_statistics_CIEDE2000`); (0, 0) when no
    pixel is lit."""
    from reflectance.colour.difference import difference_statistics_CIEDE2000

    return difference_statistics_CIEDE2000(XYZ, XYZ_reference, scene.display.illuminant,
                                           scene.observer, scene.wavelengths)


def load_bench_scene(scene: str | os.PathLike[str] | dict[str, Any],
                     spectra_dir: SpectraDirs = None, width: int | None = None,
                     height: int | None = None, supersample: int | None = None,
                     spectral: str | None = None, wavelengths: Mapping[str, float] | None = None,
                     adaptive: bool | None = None, base_dir: str | os.PathLike[str] = ".") -> Scene:
    """The benchmarked scene: a scene file's path, or a scene document (dict, with its
    ``source`` description under the key ``"_source"`` if any; its mesh paths and material
    files relative to ``base_dir``), with overrides as
    :func:`reflectance.render.scene.load_scene` takes them; ``adaptive`` (True or False)
    switches the camera's adaptive supersampling on or off (None: the scene's)."""
    import copy
    import dataclasses

    from reflectance.render.scene import load_scene, scene_from_dict

    overrides: dict[str, Any] = {"width": width, "height": height, "supersample": supersample,
                 "spectral": spectral, "wavelengths": wavelengths}
    if not isinstance(scene, dict):
        out = load_scene(scene, spectra_dir=spectra_dir, **overrides)
        if adaptive is None:
            return out
        return dataclasses.replace(out, refinement=dataclasses.replace(out.refinement,  # type: ignore[type-var]
                                                                      enabled=bool(adaptive)))
    doc = copy.deepcopy(scene)
    source = doc.pop("_source", "scene document")
    doc["camera"].update({k: v for k, v in overrides.items()
                          if k in ("width", "height", "supersample") and v is not None})
    if spectral is not None:
        doc["spectral"] = spectral
    if wavelengths is not None:
        doc["wavelengths"] = dict(wavelengths)
    if adaptive is not None:
        doc["camera"].setdefault("adaptive", {})["enabled"] = bool(adaptive)
    return scene_from_dict(doc, source=source, base_dir=base_dir, spectra_dir=spectra_dir)


def bench_size(scene: str | os.PathLike[str] | dict[str, Any], size: int, supersample: int = 2,
               runs: int = 5, brute_force_runs: int = 1, grids_nm: Sequence[float] = (),
               spectra_dir: SpectraDirs = None, reference_supersample: int = REFERENCE_SUPERSAMPLE,
               reference_max_samples: int = REFERENCE_MAX_SAMPLES,
               progress: Callable[[str], None] | None = None,
               adaptive: bool | None = None) -> dict[str, Any]:
    """Measurements for one image size, in this process (see :func:`reflectance.bench.run.run_bench`); ``progress``, if
    given, is called with the name of each phase as it starts; ``adaptive`` as for
    :func:`load_bench_scene`."""
    import statistics  # here, not at the top: the CLI reads this module's defaults at parse

    import numpy as np

    from reflectance.colour.colorimetry import tristimulus_weights
    from reflectance.colour.difference import image_difference_CIEDE2000
    from reflectance.render.integrator import shade_samples
    from reflectance.render.pipeline import render
    from reflectance.render.tracing import tiles, trace
    from reflectance.render.shading import fresnel_XYZ_table

    progress = progress or (lambda phase: None)
    document = scene  # the file or document: the reference and the grids load it again
    t0 = time.perf_counter()
    progress("scene")
    scene = load_bench_scene(document, spectra_dir=spectra_dir, width=size, height=size,
                             supersample=supersample, spectral="table", adaptive=adaptive)
    load_s = time.perf_counter() - t0
    times: dict[str, list[float]] = {"visibility": [], "shadows": [], "shading": []}
    for run in range(runs):
        result = render(scene, progress=lambda phase: progress(f"run {run + 1}/{runs}: {phase}"))
        for key, value in times.items():
            value.append(result.timings[key])
    peak = _peak_MiB()
    n_samples = size * size * supersample**2
    n_hit = round(result.stats["hit"] * n_samples)
    median = {k: statistics.median(v) for k, v in times.items()}
    out = {
        "size": size, "supersample": supersample, "spp": supersample**2, "runs": runs,
        "samples": n_samples, "hit_samples": n_hit, "bands": len(tiles(scene.camera)),
        "triangles": int(scene.mesh.n_cells), "lights": len(scene.lights),
        "wavelengths": len(scene.wavelengths), "load_s": load_s, "peak_MiB": peak,
        **{f"{k}_s": v for k, v in median.items()},
        "total_s": sum(median.values()),
        # the budget actually spent (adaptive supersampling: n^2 + N^2 x the refined fraction)
        "spp_spent": result.stats["samples_per_pixel"], "refined": result.stats["refined"],
        "visibility_samples_per_s": n_samples / median["visibility"],
        "shadows_samples_per_s": n_hit * len(scene.lights) / max(median["shadows"], 1e-12),
        "shading_samples_per_s": n_hit / median["shading"],
    }
    if reference_supersample and n_samples / supersample**2 * reference_supersample**2 \
            <= reference_max_samples:
        progress(f"reference at {reference_supersample} x {reference_supersample} samples")
        t1 = time.perf_counter()
        reference = render(load_bench_scene(document, spectra_dir=spectra_dir, width=size,
                                            height=size, supersample=reference_supersample,
                                            spectral="table", adaptive=False)).XYZ
        mean, p95 = scene_difference(result.XYZ, reference, scene)
        out.update(reference_supersample=reference_supersample,
                   reference_s=time.perf_counter() - t1,
                   dE_reference_mean=mean, dE_reference_p95=p95)
    del result
    if len(tiles(scene.camera)) > 1:  # the sample-level comparisons need the whole image
        brute_force_runs, grids_nm = 0, ()
    if brute_force_runs or grids_nm:
        samples, shadowed, _ = trace(scene)
        XYZ = shade_samples(scene, samples, shadowed, "table")
    if brute_force_runs:
        brute_times = []
        progress("brute-force shading")
        for _ in range(brute_force_runs):
            t1 = time.perf_counter()
            brute = shade_samples(scene, samples, shadowed, "brute-force")
            brute_times.append(time.perf_counter() - t1)
        dE_mean, dE_max = image_difference_CIEDE2000(
            samples.to_pixels(XYZ), samples.to_pixels(brute), scene.display.illuminant,
            scene.observer, scene.wavelengths)
        out.update(brute_force_s=statistics.median(brute_times),
                   brute_over_table=statistics.median(brute_times) / median["shading"],
                   dE2000_mean=dE_mean, dE2000_max=dE_max)
    grid_rows = []
    for step in grids_nm:
        progress(f"{step:g} nm wavelength grid")
        w = scene.document["wavelengths"]
        other = load_bench_scene(document, spectra_dir=spectra_dir, width=size, height=size,
                                 supersample=supersample, adaptive=False,
                                 wavelengths={"start_nm": w["start_nm"], "end_nm": w["end_nm"],
                                              "step_nm": step})
        row = {"step_nm": step, "wavelengths": len(other.wavelengths)}
        W = tristimulus_weights(other.wavelengths, other.lights[0].spectrum, other.observer)
        t1 = time.perf_counter()
        for obj in other.objects:
            fresnel_XYZ_table(obj.material, W, other.table_size)
        row["table_build_s"] = time.perf_counter() - t1  # per light spectrum and object
        for method, repeat in (("table", max(1, min(runs, 3))), ("brute-force", 1)):
            t = []
            for _ in range(repeat):
                t1 = time.perf_counter()
                shade_samples(other, samples, shadowed, method)
                t.append(time.perf_counter() - t1)
            row[f"{method}_s"] = statistics.median(t)
        grid_rows.append(row)
    out["grids"] = grid_rows
    return out


if __name__ == "__main__":  # pragma: no cover - run by run_bench in a subprocess
    worker_main(bench_size)
