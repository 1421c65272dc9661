"""Speed and memory of the renderer: ``reflectance bench``.

For a scene (a scene file, or a scene document as :func:`reflectance.render.scene.scene_from_dict`
takes it; ``reflectance bench`` passes the copper vase of Cook & Torrance 1982, Fig. 6b, built
from config.yaml by the papers' scene builder) rendered square at several sizes with n x n
supersampling,
each size runs in its own Python process (so that its peak resident memory, ``ru_maxrss``, which
includes VTK's, belongs to that size alone) and reports:

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

With Mitsuba 3 installed (``pip install .[crosscheck]``), at one size (``crosscheck_size``, if
benchmarked) a path tracer is a second, independent reference
(:mod:`reflectance.render.crosscheck`): our render and Mitsuba's at a ladder of sample counts,
and ours at a ladder of supersamplings (``crosscheck_supersamples``), their seconds and their
CIEDE2000 against the same converged references, and the two compared at the accuracy goal
(equal error). Without it the
report says in one line that the cross-check is skipped.

Speed targets are measured here, never asserted in tests.
"""

from __future__ import annotations

import resource
import time

from reflectance.io.progress import run_worker, worker_main

__all__ = ["load_bench_scene", "scene_difference", "bench_size", "run_bench", "format_report",
           "crosscheck_status"]

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


def scene_difference(XYZ, XYZ_reference, scene):
    """(mean, 95th percentile) CIEDE2000 of two renders of ``scene`` on the reference's
    Cook & Torrance exposure, in the scene's display illuminant, observer and wavelengths
    (:func:`reflectance.colour.difference.difference_statistics_CIEDE2000`); (0, 0) when no
    pixel is lit."""
    from reflectance.colour.difference import difference_statistics_CIEDE2000

    return difference_statistics_CIEDE2000(XYZ, XYZ_reference, scene.display.illuminant,
                                           scene.observer, scene.wavelengths)


def load_bench_scene(scene, spectra_dir=None, width=None, height=None, supersample=None,
                     spectral=None, wavelengths=None, adaptive=None):
    """The benchmarked scene: a scene file's path, or a scene document (dict, with its
    ``source`` description under the key ``"_source"`` if any), with overrides as
    :func:`reflectance.render.scene.load_scene` takes them; ``adaptive`` (True or False)
    switches the camera's adaptive supersampling on or off (None: the scene's)."""
    import copy
    import dataclasses

    from reflectance.render.scene import load_scene, scene_from_dict

    overrides = {"width": width, "height": height, "supersample": supersample,
                 "spectral": spectral, "wavelengths": wavelengths}
    if not isinstance(scene, dict):
        out = load_scene(scene, spectra_dir=spectra_dir, **overrides)
        if adaptive is None:
            return out
        return dataclasses.replace(out, refinement=dataclasses.replace(out.refinement,
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
    return scene_from_dict(doc, source=source, spectra_dir=spectra_dir)


def bench_size(scene, size, supersample=2, runs=5, brute_force_runs=1, grids_nm=(),
               spectra_dir=None, reference_supersample=REFERENCE_SUPERSAMPLE,
               reference_max_samples=REFERENCE_MAX_SAMPLES, progress=None, adaptive=None):
    """Measurements for one image size, in this process (see :func:`run_bench`); ``progress``, if
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
    times = {"visibility": [], "shadows": [], "shading": []}
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


def crosscheck_status(results=()):
    """The report's lines on the path-tracer cross-check (Mitsuba 3): its table
    (:func:`reflectance.render.crosscheck.format_crosscheck`) where it ran, else one line saying
    why it was skipped."""
    from reflectance.render.crosscheck import format_crosscheck, mitsuba_available

    done = [r["crosscheck"] for r in results if "crosscheck" in r]
    if done:
        return "\n".join(line for r in done for line in format_crosscheck(r))
    if not mitsuba_available():
        return ("path tracer (Mitsuba 3): not installed (pip install .[crosscheck]); "
                "cross-check skipped")
    return (f"path tracer (Mitsuba 3): installed; cross-check skipped (it runs at "
            f"--crosscheck-size, default {CROSSCHECK_SIZE}, when that size is benchmarked)")


def run_bench(scene, sizes=(256, 512, 1024), supersample=2, runs=5, brute_force_runs=1,
              grids_nm=(5, 1), grid_size=512, spectra_dir=None,
              reference_supersample=REFERENCE_SUPERSAMPLE, progress=None, adaptive=None,
              crosscheck_size=CROSSCHECK_SIZE, crosscheck_spp=CROSSCHECK_SPP,
              crosscheck_supersamples=CROSSCHECK_SUPERSAMPLES):
    """Run :func:`bench_size` for each size in a fresh subprocess; return the list of results.

    ``scene`` is a scene file's path or a scene document (dict). ``progress``, if given, is a
    :class:`reflectance.io.progress.Progress` told each size and each phase of it. ``adaptive``
    (True, False; None: the scene's) switches the adaptive supersampling. With Mitsuba
    installed and ``crosscheck_size`` among ``sizes``, that size's result gets the path-tracer
    cross-check under ``"crosscheck"`` (Mitsuba's reference at ``crosscheck_spp`` samples per
    pixel; ours at ``reference_supersample``, or :data:`REFERENCE_SUPERSAMPLE` where that is
    0; our own ladder at the supersamplings ``crosscheck_supersamples``)."""
    spectra_dir = None if spectra_dir is None else str(spectra_dir)
    results = []
    for i, size in enumerate(sizes):
        where = f"size {size} ({i + 1}/{len(sizes)})"
        if progress is not None:
            progress.update(i, where)
        tell = None if progress is None else (lambda phase: progress.update(i, f"{where}: {phase}"))
        job = {"scene": scene if isinstance(scene, dict) else str(scene),
               "size": int(size), "supersample": supersample,
               "runs": runs, "brute_force_runs": brute_force_runs,
               "grids_nm": list(grids_nm) if size == grid_size else [],
               "spectra_dir": spectra_dir, "reference_supersample": reference_supersample,
               "adaptive": adaptive}
        try:
            results.append(run_worker(
                "reflectance.render.bench", job, failure=f"benchmark of size {size} failed",
                progress=tell))
        except RuntimeError:
            if progress is not None:
                progress.close(f"size {size} failed", done=i)
            raise
        if size == crosscheck_size:  # the path-tracer cross-check (reflectance.render.crosscheck)
            from reflectance.render.crosscheck import mitsuba_available, run_crosscheck

            if mitsuba_available():
                results[-1]["crosscheck"] = run_crosscheck(
                    scene, size, supersample, max(1, min(runs, 3)),
                    reference_supersample or REFERENCE_SUPERSAMPLE,
                    crosscheck_spp, spectra_dir=spectra_dir, progress=tell,
                    our_supersamples=crosscheck_supersamples)
    if progress is not None:
        progress.close()
    return results


def format_report(results):
    """A plain-text report of :func:`run_bench` results."""
    lines = []
    if results:
        r0 = results[0]
        lines.append(f"{r0['triangles']} triangles, {r0['lights']} lights, "
                     f"{r0['supersample']} x {r0['supersample']} samples per pixel, "
                     f"{r0['wavelengths']} wavelengths; median of {r0['runs']} runs; "
                     "peak = max resident memory of the process (VTK included)")
    head = (f"{'size':>6} {'spp':>4} {'spent':>6} {'refined':>7} {'samples':>9} {'bands':>5} "
            f"{'scene s':>8} {'visib. s':>9} {'shadow s':>9} {'shade s':>8} {'total s':>8} "
            f"{'vis Ms/s':>9} {'shd Ms/s':>9} "
            f"{'peak MiB':>9} {'ref spp':>7} {'dE ref mean':>11} {'dE ref p95':>10} "
            f"{'brute s':>8} {'brute/tab':>9} {'dE00 mean':>10} {'dE00 max':>9}")
    lines.append(head)
    for r in results:
        ref = (f"{r['reference_supersample']**2:>7} {r['dE_reference_mean']:11.3f} "
               f"{r['dE_reference_p95']:10.3f}" if "dE_reference_mean" in r
               else f"{'-':>7} {'-':>11} {'-':>10}")
        brute = (f"{r['brute_force_s']:8.3f} {r['brute_over_table']:9.1f} "
                 f"{r['dE2000_mean']:10.2e} {r['dE2000_max']:9.2e}"
                 if "brute_force_s" in r else f"{'-':>8} {'-':>9} {'-':>10} {'-':>9}")
        lines.append(
            f"{r['size']:>6} {r['spp']:>4} {r.get('spp_spent', r['spp']):6.2f} "
            f"{100 * r.get('refined', 0.0):6.2f}% {r['samples']:>9} {r['bands']:>5} "
            f"{r['load_s']:8.3f} "
            f"{r['visibility_s']:9.3f} "
            f"{r['shadows_s']:9.3f} {r['shading_s']:8.3f} {r['total_s']:8.3f} "
            f"{r['visibility_samples_per_s'] / 1e6:9.2f} {r['shading_samples_per_s'] / 1e6:9.2f} "
            f"{r['peak_MiB']:9.0f} {ref} {brute}")
    lines.append("(spp: n x n samples per pixel of the first pass; spent: the mean samples per "
                 "pixel actually traced, with the adaptive refinement's N x N in the refined "
                 "pixels; refined: the share of pixels refined; "
                 "scene s: reading the scene, building the mesh, resampling the spectra, once; "
                 "total s = visibility + shadows + shading; vis Ms/s: camera samples per second "
                 "of visibility; shd Ms/s: hit samples per second of table shading, all lights; "
                 "dE ref: CIEDE2000 of the image against the same render at 'ref spp' samples "
                 "per pixel, over the lit pixels; brute: per-wavelength shading of the same "
                 "samples against the table, images of one band only)")
    lines.append(crosscheck_status(results))
    for r in results:
        for g in r.get("grids", []):
            lines.append(f"size {r['size']}, {g['step_nm']:g} nm grid ({g['wavelengths']} "
                         f"wavelengths): table shading {g['table_s']:.3f} s (of which "
                         f"{g['table_build_s']:.3f} s building the Fresnel table), brute force "
                         f"{g['brute-force_s']:.3f} s")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover - run by run_bench in a subprocess
    worker_main(bench_size)
