"""``reflectance bench``: every size in a process of its own, the cross-check, the report.

:func:`run_bench` measures a scene (a scene file, or a scene document) at each size in a fresh
Python process (:func:`reflectance.bench.measure.bench_size` there: its peak resident memory then
belongs to that size alone). With Mitsuba 3 installed (``pip install .[crosscheck]``), at one
size (``crosscheck_size``, if benchmarked) a path tracer is a second, independent reference
(:mod:`reflectance.bench.crosscheck`, in a process of its own too): our render and Mitsuba's at
a ladder of sample counts, and ours at a ladder of supersamplings (``crosscheck_supersamples``),
their seconds and their CIEDE2000 against the same converged references, and the two compared at
the accuracy goal (equal error). :func:`format_report` prints the results; without Mitsuba it
says in one line that the cross-check is skipped (:func:`crosscheck_status`).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from reflectance.io.progress import run_worker
from reflectance.bench.measure import (CROSSCHECK_SIZE, CROSSCHECK_SPP, CROSSCHECK_SUPERSAMPLES,
                                      REFERENCE_SUPERSAMPLE)

if TYPE_CHECKING:
    from reflectance.io.progress import Progress
    from reflectance.optics.spectra import SpectraDirs

__all__ = ["run_bench", "format_report", "crosscheck_status"]


def crosscheck_status(results: Sequence[Mapping[str, Any]] = ()) -> str:
    """The report's lines on the path-tracer cross-check (Mitsuba 3): its table
    (:func:`reflectance.bench.crosscheck.format_crosscheck`) where it ran, else one line saying
    why it was skipped."""
    from reflectance.bench.crosscheck import format_crosscheck, mitsuba_available

    done = [r["crosscheck"] for r in results if "crosscheck" in r]
    if done:
        return "\n".join(line for r in done for line in format_crosscheck(r))
    if not mitsuba_available():
        return ("path tracer (Mitsuba 3): not installed (pip install .[crosscheck]); "
                "cross-check skipped")
    return (f"path tracer (Mitsuba 3): installed; cross-check skipped (it runs at "
            f"--crosscheck-size, default {CROSSCHECK_SIZE}, when that size is benchmarked)")


def run_bench(scene: str | os.PathLike[str] | dict[str, Any],
              sizes: Sequence[int] = (256, 512, 1024), supersample: int = 2, runs: int = 5,
              brute_force_runs: int = 1, grids_nm: Sequence[float] = (5, 1), grid_size: int = 512,
              spectra_dir: SpectraDirs = None, reference_supersample: int = REFERENCE_SUPERSAMPLE,
              progress: Progress | None = None, adaptive: bool | None = None,
              crosscheck_size: int = CROSSCHECK_SIZE, crosscheck_spp: int = CROSSCHECK_SPP,
              crosscheck_supersamples: Sequence[int] = CROSSCHECK_SUPERSAMPLES
             ) -> list[dict[str, Any]]:
    """Run :func:`reflectance.bench.measure.bench_size` for each size in a fresh subprocess;
    return the list of results.

    ``scene`` is a scene file's path or a scene document (dict). ``progress``, if given, is a
    :class:`reflectance.io.progress.Progress` of ``sum(size**2)`` units told the pixels of the
    sizes measured and each size and phase under way. ``adaptive``
    (True, False; None: the scene's) switches the adaptive supersampling. With Mitsuba
    installed and ``crosscheck_size`` among ``sizes``, that size's result gets the path-tracer
    cross-check under ``"crosscheck"`` (Mitsuba's reference at ``crosscheck_spp`` samples per
    pixel; ours at ``reference_supersample``, or
    :data:`reflectance.bench.measure.REFERENCE_SUPERSAMPLE` where that is 0; our own ladder at
    the supersamplings ``crosscheck_supersamples``)."""
    from reflectance.optics.spectra import folder_list

    spectra_dir = folder_list(spectra_dir)  # (JSON for the workers)
    results = []
    done = 0  # pixels of the sizes measured (the work the bar counts: a size's costs scale so)
    for i, size in enumerate(sizes):
        where = f"size {size} ({i + 1}/{len(sizes)})"
        if progress is not None:
            progress.update(done, where)
        tell = None if progress is None else (lambda phase: progress.update(
            message=f"{where}: {phase}"))
        job = {"scene": scene if isinstance(scene, dict) else str(scene),
               "size": int(size), "supersample": supersample,
               "runs": runs, "brute_force_runs": brute_force_runs,
               "grids_nm": list(grids_nm) if size == grid_size else [],
               "spectra_dir": spectra_dir, "reference_supersample": reference_supersample,
               "adaptive": adaptive}
        try:
            results.append(run_worker(
                "reflectance.bench.measure", job, failure=f"benchmark of size {size} failed",
                progress=tell))
        except RuntimeError:
            if progress is not None:
                progress.close(f"size {size} failed", complete=False)
            raise
        if size == crosscheck_size:  # the path-tracer cross-check (reflectance.bench.crosscheck)
            from reflectance.bench.crosscheck import mitsuba_available, run_crosscheck

            if mitsuba_available():
                results[-1]["crosscheck"] = run_crosscheck(
                    scene, size, supersample, max(1, min(runs, 3)),
                    reference_supersample or REFERENCE_SUPERSAMPLE,
                    crosscheck_spp, spectra_dir=spectra_dir, progress=tell,
                    our_supersamples=crosscheck_supersamples)
        done += size * size
    if progress is not None:
        progress.close()
    return results


def format_report(results: Sequence[Mapping[str, Any]]) -> str:
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
