"""A path tracer as an independent reference: a scene exported to Mitsuba 3 and rendered there.

Mitsuba 3 (Jakob et al. 2022) is an optional extra (``pip install .[crosscheck]``); it is imported
inside the functions that need it, and :func:`mitsuba_available` says whether it is installed.

:func:`scene_to_mitsuba` translates a loaded :class:`reflectance.render.scene.Scene` into the
dictionary ``mitsuba.load_dict`` takes, and :func:`render_mitsuba` renders it into CIE XYZ
(:func:`mitsuba_renderer` loads it once for several renders):

- geometry: the composed triangles with the same vertex normals (a binary PLY in a temporary
  folder, Mitsuba interpolates them as we do), and analytic spheres as Mitsuba ``sphere`` shapes;
  every material is wrapped in ``twosided`` (our surfaces are two-sided);
- camera: the same position, look-at point, up vector, vertical field of view and resolution;
  Mitsuba's ``box`` reconstruction filter (radius half a pixel), so that a pixel is the plain
  mean of its samples, the box-filtered pixel integral our supersampling estimates (Mitsuba's
  default filter is a Gaussian);
- lights: a ``directional`` emitter per directional light, a ``point`` emitter per point light
  (given by its solid angle at unit distance or its area); its spectrum is the light's illuminant
  on our wavelength grid scaled so that its luminance is 1 (our
  :func:`reflectance.colour.colorimetry.tristimulus_weights`), times ``I d omega``: a white
  Lambertian card facing a directional light then has ``Y = I d omega / pi`` in both renderers;
- materials, only where Mitsuba implements our BRDF exactly: ``Lambert`` (and Cook & Torrance
  with s = 0) as ``diffuse`` with our albedo spectrum; Cook & Torrance 1982 in the ``physical``
  convention with one Beckmann distribution, Smith shadowing and the exact conductor Fresnel
  as ``roughconductor`` (``distribution: beckmann``, ``alpha = m``, our measured n, k spectra),
  blended with the diffuse part by ``blendbsdf`` with weight d when d > 0 (``R = s R_s + d R_d``
  with s + d = 1). Mitsuba's D is Beckmann's with 1/pi (our ``physical`` D, Walter et al. 2007
  eq. 25), its BRDF ``F D G / (4 (N.L)(N.V))``, F the unpolarised exact conductor Fresnel at
  V.H. One difference remains: Mitsuba's Smith G1 of a Beckmann surface is Walter et al.'s
  rational approximation, ours the exact erf form (both are
  :func:`reflectance.optics.shadowing.G1_Smith_Beckmann_Walter2007`, ``form="rational"`` and
  ``"exact"``; they differ by less than 0.35 %, near grazing only);
- film: ``hdrfilm`` with ``pixel_format: xyz`` in a ``*_spectral`` variant: Mitsuba integrates
  the spectrum against its CIE 1931 2-degree colour matching functions (360-830 nm) normalised
  so that a constant spectrum of 1 has Y = 1, as ours;
- integrator: ``direct`` with one emitter sample and no BSDF sample: our renderer computes direct
  light with hard shadows and no interreflection; with point and directional lights the direct
  integrator is the exact path tracer of that light transport (``path`` with ``max_depth: 2``
  gives the same image, more slowly); the ``stratified`` sampler.

Anything else (the ``paper`` convention, V-cavity shadowing, several lobes, other D, a
roughness texture, Fresnel approximations, ambient light, emission, part materials, lights of
other spectra) is refused with a one-line :class:`ValueError` naming it.

References
----------
- Jakob, W., Speierer, S., Roussel, N., Nimier-David, M., Vicini, D., Zeltner, T., Nicolet, B.,
  Crespo, M., Leroy, V., & Zhang, Z. (2022). Mitsuba 3 renderer. https://mitsuba-renderer.org
- Walter, B., Marschner, S. R., Li, H., & Torrance, K. E. (2007). Microfacet models for
  refraction through rough surfaces. EGSR 2007.
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from importlib.util import find_spec
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from reflectance.optics.spectra import folder_list
from reflectance.bench.measure import CROSSCHECK_SPP, CROSSCHECK_SUPERSAMPLES

if TYPE_CHECKING:
    from reflectance.optics.spectra import SpectraDirs
    from reflectance.render.scene import Scene

__all__ = ["mitsuba_available", "mitsuba_variant", "crosscheck_scene", "scene_to_mitsuba",
           "mitsuba_renderer", "render_mitsuba", "equal_error_seconds", "fastest_at_goal",
           "goal_comparison", "spp_at_goal", "whole_commands", "bench_crosscheck",
           "run_crosscheck", "format_crosscheck"]

#: Mitsuba variants tried in order: the LLVM one is much faster, the scalar one needs no LLVM
VARIANTS = ("llvm_ad_spectral", "scalar_spectral")


def mitsuba_available() -> bool:
    """Whether Mitsuba 3 is installed (without importing it)."""
    return find_spec("mitsuba") is not None


def mitsuba_variant(prefer: Sequence[str] = VARIANTS) -> str:
    """The first variant of ``prefer`` that works here (an LLVM variant needs the LLVM library,
    found by Dr.Jit or named by ``DRJIT_LIBLLVM_PATH``), set as Mitsuba's variant."""
    import mitsuba as mi

    for variant in prefer:
        if variant not in mi.variants():
            continue
        if variant.startswith("llvm"):
            import drjit as dr

            try:
                if not dr.has_backend(dr.JitBackend.LLVM):
                    continue
            except Exception:  # noqa: BLE001 - a missing libLLVM shows in several ways
                continue
        mi.set_variant(variant)
        return variant
    raise ValueError(f"none of the Mitsuba variants {', '.join(prefer)} works here")


def crosscheck_scene(document: dict[str, Any]) -> dict[str, Any]:
    """A scene document made exportable: the same geometry, camera and lights, with each
    Cook & Torrance material read in the ``physical`` convention with Smith shadowing, one
    Beckmann lobe (the narrowest of its lobes), the exact Fresnel, and no ambient light."""
    import copy

    doc = copy.deepcopy(document)
    for obj in doc.get("objects", []):
        m = obj.get("material", {})
        if m.get("model", "CookTorrance1982") != "CookTorrance1982":
            continue
        m.update(convention="physical", shadowing="smith", distribution="Beckmann1963",
                 fresnel="exact")
        lobes = m.pop("lobes", None)
        if lobes:
            m["m"] = min(lobe["m"] for lobe in lobes)
    doc.pop("ambient", None)
    return doc


def _spectrum(values, wavelengths):
    """A Mitsuba ``regular`` spectrum of values on our uniform grid."""
    values = np.broadcast_to(np.asarray(values, np.float64), np.shape(wavelengths))
    return {"type": "regular", "wavelength_min": float(wavelengths[0]),
            "wavelength_max": float(wavelengths[-1]),
            "values": ", ".join(f"{v:.9g}" for v in values)}


def _light_spectrum(scene, name):
    """The illuminant ``name`` on the scene's grid with luminance 1 (tristimulus_weights')."""
    from reflectance.colour.colorimetry import cmfs, illuminant_sd

    S = np.asarray(illuminant_sd(name, scene.wavelengths), np.float64)
    y_bar = np.asarray(cmfs(scene.observer, scene.wavelengths), np.float64)[:, 1]
    return S * y_bar.sum() / np.sum(S * y_bar)


def _refuse(where, what):
    raise ValueError(f"cross-check export: {where}: {what} has no exact Mitsuba counterpart")


def _bsdf(material, wavelengths, where):
    m = material
    if m.emission is not None:
        _refuse(where, "emission")
    if m.texture is not None:
        _refuse(where, "a roughness texture")
    diffuse = {"type": "diffuse", "reflectance": _spectrum(m.albedo, wavelengths)}
    if m.model == "Lambert" or (m.model == "CookTorrance1982" and m.roughness is None
                                and m.lobes is None):
        if m.model == "Lambert" and m.convention != "physical":
            _refuse(where, f"Lambert in the {m.convention!r} convention")
        # rho_d = d x albedo, f = rho_d / pi (brdf_Lambert, physical)
        scaled = np.asarray(m.albedo, np.float64) * float(m.d)
        return {"type": "twosided",
                "bsdf": {"type": "diffuse", "reflectance": _spectrum(scaled, wavelengths)}}
    if m.model != "CookTorrance1982":
        _refuse(where, f"shading model {m.model!r}")
    for name, value, wanted in (("convention", m.convention, "physical"),
                                ("shadowing", m.shadowing, "smith"),
                                ("distribution", m.distribution, "Beckmann1963"),
                                ("fresnel", m.fresnel, "exact")):
        if value != wanted:
            _refuse(where, f"{name} {value!r}")
    if m.lobes is not None:
        _refuse(where, "several lobes")
    conductor = {"type": "roughconductor", "distribution": "beckmann",
                 "alpha": float(m.roughness), "eta": _spectrum(m.n, wavelengths),
                 "k": _spectrum(m.k, wavelengths)}
    if m.d > 0:  # Cook & Torrance 1982: R = s R_s + d R_d, s + d = 1
        conductor = {"type": "blendbsdf", "weight": float(m.d), "bsdf_0": conductor,
                     "bsdf_1": diffuse}
    return {"type": "twosided", "bsdf": conductor}


def _write_ply(path, points, normals, triangles):
    """A binary little-endian PLY of float32 positions and normals and int32 triangles."""
    vertex = np.empty(len(points), dtype=[(c, "<f4") for c in ("x", "y", "z", "nx", "ny", "nz")])
    for j, c in enumerate("xyz"):
        vertex[c] = points[:, j]
        vertex["n" + c] = normals[:, j]
    face = np.empty(len(triangles), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    face["n"] = 3
    face["i"] = triangles
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"element vertex {len(points)}\n"
              + "".join(f"property float {c}\n" for c in ("x", "y", "z", "nx", "ny", "nz"))
              + f"element face {len(triangles)}\nproperty list uchar int vertex_indices\n"
              "end_header\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(vertex.tobytes())
        f.write(face.tobytes())


def scene_to_mitsuba(scene: Scene, folder: str | os.PathLike[str], spp: int = 64,
                     seed: int = 0) -> dict[str, Any]:
    """The ``mitsuba.load_dict`` dictionary of a loaded scene (see the module docstring).

    ``folder`` receives the meshes (PLY files) the dictionary names. Raises ValueError, one
    line naming the feature, for what has no exact Mitsuba counterpart.
    """
    from reflectance.geometry.shapes import analytic_spheres
    from reflectance.render.lights import DirectionalLight

    if scene.ambient is not None and scene.ambient.fraction > 0:
        _refuse("ambient", "ambient light (Cook & Torrance's I_ia R_a)")
    if not scene.shadows:
        _refuse("shadows", "lights without cast shadows")
    for i, light in enumerate(scene.lights):
        if not light.shadows:
            _refuse(f"lights[{i}]", "a light the objects do not shadow (shadows: false)")
    if scene.observer != "CIE 1931 2 Degree Standard Observer":
        _refuse("observer", f"the observer {scene.observer!r} (Mitsuba's film: CIE 1931 "
                            "2-degree)")
    wl = scene.wavelengths
    if not np.allclose(np.diff(wl), wl[1] - wl[0]):
        _refuse("wavelengths", "a non-uniform wavelength grid")
    doc: dict[str, Any] = {"type": "scene",
           "integrator": {"type": "direct", "emitter_samples": 1, "bsdf_samples": 0}}
    mesh = scene.mesh
    tris = np.asarray(mesh.faces, np.int64).reshape(-1, 4)[:, 1:]
    object_id = np.asarray(mesh.cell_data["object_id"], np.int64)
    sphere_index = np.asarray(mesh.cell_data["sphere_index"], np.int64)
    points = np.asarray(mesh.points, np.float64)
    normals = np.asarray(mesh.point_data["Normals"], np.float64)
    centers, radii = analytic_spheres(mesh)
    for i, obj in enumerate(scene.objects):
        where = f"objects[{i}] ({obj.name})"
        if getattr(obj, "part_materials", None):
            _refuse(where, "materials of parts")
        bsdf = _bsdf(obj.material, wl, where + ".material")
        own = (object_id == i) & (sphere_index < 0)
        if own.any():
            used, inverse = np.unique(tris[own], return_inverse=True)
            path = Path(folder) / f"object{i}.ply"
            _write_ply(path, points[used], normals[used], inverse.reshape(-1, 3))
            doc[f"object{i}"] = {"type": "ply", "filename": str(path), "bsdf": bsdf}
        for j in np.unique(sphere_index[(object_id == i) & (sphere_index >= 0)]):
            doc[f"object{i}_sphere{j}"] = {"type": "sphere",
                                           "center": list(map(float, centers[j])),
                                           "radius": float(radii[j]), "bsdf": bsdf}
    for i, light in enumerate(scene.lights):
        where = f"lights[{i}]"
        if not isinstance(light.spectrum, str):
            _refuse(where, "a light spectrum that is not a named illuminant")
        S = _light_spectrum(scene, light.spectrum)
        if isinstance(light.source, DirectionalLight):
            # a directional emitter's irradiance: I d omega (Cook & Torrance's I_il d omega_il)
            doc[f"light{i}"] = {"type": "directional",
                                "direction": [-float(x) for x in light.source.direction],
                                "irradiance": _spectrum(S * light.intensity * light.solid_angle,
                                                        wl)}
        else:
            # radiant intensity at distance r gives I d omega = I_p / r^2: with d omega = area
            # / r^2, I_p = I area; with a constant solid angle a point light cannot match
            if light.area is None:
                _refuse(where, "a point light with a constant solid angle")
            doc[f"light{i}"] = {"type": "point",
                                "position": list(map(float, light.source.position)),
                                "intensity": _spectrum(S * light.intensity * light.area, wl)}
    import mitsuba as mi  # only now: what cannot be translated is refused without Mitsuba

    cam = scene.camera
    doc["sensor"] = {
        "type": "perspective", "fov_axis": "y", "fov": float(cam.fov_deg),
        "to_world": mi.ScalarTransform4f().look_at(origin=list(map(float, cam.position)),
                                                   target=list(map(float, cam.look_at)),
                                                   up=list(map(float, cam.up))),
        "sampler": {"type": "stratified", "sample_count": int(spp), "seed": int(seed)},
        "film": {"type": "hdrfilm", "width": int(cam.width), "height": int(cam.height),
                 "pixel_format": "xyz", "rfilter": {"type": "box"}},
    }
    return doc


def mitsuba_renderer(scene: Scene,
                     variant: str | None = None
                    ) -> Callable[..., tuple[npt.NDArray[np.float64], float]]:
    """Load a loaded scene into Mitsuba once; return ``render(spp, seed=0)``.

    ``render`` gives what :func:`render_mitsuba` gives, ``(XYZ, seconds)``, for any number of
    renders of the one loaded scene (its meshes, acceleration structure and BSDFs are built
    once). Mitsuba's sampler takes its base seed (``seed``) and sample count when it is
    loaded and adds the seed of ``mitsuba.render`` to that base, so each render loads a
    sensor of its own (camera, film and sampler only) with both: the images are those of a
    scene loaded anew with :func:`scene_to_mitsuba` at that ``spp`` and ``seed``.
    """
    import mitsuba as mi

    if variant is not None:
        mi.set_variant(variant)
    elif not mi.variant() or not mi.variant().endswith("spectral"):  # type: ignore[union-attr]
        mitsuba_variant()
    with tempfile.TemporaryDirectory(prefix="reflectance-mitsuba-") as folder:
        doc = scene_to_mitsuba(scene, folder)
        loaded = mi.load_dict(doc)

    def render(spp, seed=0):
        sensor = mi.load_dict({**doc["sensor"], "sampler": {
            **doc["sensor"]["sampler"], "sample_count": int(spp), "seed": int(seed)}})
        t0 = time.perf_counter()
        image = mi.render(loaded, sensor=sensor, spp=int(spp), seed=int(seed))
        XYZ = np.array(image, dtype=np.float64)
        seconds = time.perf_counter() - t0
        return XYZ[..., :3], seconds

    return render


def render_mitsuba(scene: Scene, spp: int, seed: int = 0,
                   variant: str | None = None) -> tuple[npt.NDArray[np.float64], float]:
    """Render a loaded scene with Mitsuba at ``spp`` samples per pixel.

    Returns ``(XYZ, seconds)``: the image, shape (height, width, 3), in our XYZ units, and the
    wall seconds of ``mitsuba.render`` alone (the scene's loading and the LLVM compilation of
    the first render of a scene are not counted; see :func:`mitsuba_variant`). Several renders
    of one scene: :func:`mitsuba_renderer`, which loads it once.
    """
    return mitsuba_renderer(scene, variant)(spp, seed)


# --------------------------------------------------------------------------------------------
# The cross-check of ``reflectance bench``
# --------------------------------------------------------------------------------------------

#: Mitsuba's sample counts whose time and error the bench measures
LADDER_SPP = (4, 16, 64, 256)
#: issue 9's accuracy goal: CIEDE2000 mean and 95th percentile against a converged reference
GOAL_DE = (0.3, 1.0)
#: issue 9's speed goal: ours at most a tenth of Mitsuba's time at the accuracy goal
GOAL_SPEEDUP = 10.0
#: a rung faster than this (seconds) is timed again, once its LLVM kernel is compiled and cached
RETIME_S = 5.0


def equal_error_seconds(error: float, ladder: Sequence[tuple[float, float, float]],
                        extrapolate: bool = False) -> float | None:
    """Mitsuba's seconds at ``error`` from the ladder's rungs ``[(spp, seconds, error), ...]``.

    Interpolated linearly in log(error), log(seconds) between rungs; below the smallest error,
    with ``extrapolate``, along the power law through the two slowest rungs (Monte Carlo noise
    falls as a power of the time); None otherwise.

    Examples
    --------
    >>> ladder = [(4, 1.0, 0.8), (16, 4.0, 0.4), (64, 16.0, 0.2)]  # error ~ seconds^(-1/2)
    >>> print(equal_error_seconds(0.4, ladder), equal_error_seconds(0.1, ladder, True))
    4.0 64.0
    """
    pts = sorted((e, s) for _, s, e in ladder if e > 0 and s > 0)
    for (e0, s0), (e1, s1) in zip(pts, pts[1:]):
        if e0 <= error <= e1:
            f = 0.0 if e1 == e0 else np.log(error / e0) / np.log(e1 / e0)
            return float(np.exp(np.log(s0) + f * np.log(s1 / s0)))
    slow = sorted((s, e) for _, s, e in ladder if e > 0 and s > 0)[-2:]
    if extrapolate and len(slow) == 2 and pts and 0 < error < pts[0][0]:
        (s0, e0), (s1, e1) = slow
        slope = np.log(e1 / e0) / np.log(s1 / s0) if s1 > s0 else 0.0
        if slope < 0:
            return float(s1 * (error / e1) ** (1.0 / slope))
    return None


def meets_goal(errors, goal=GOAL_DE):
    """Whether a CIEDE2000 (mean, p95) pair is within ``goal``'s, both of them."""
    return all(e <= g for e, g in zip(errors, goal))


def fastest_at_goal(our_ladder: Iterable[dict[str, Any]],  # a rung: numbers and lists
                    goal: Sequence[float] = GOAL_DE) -> dict[str, Any] | None:
    """Of our rungs ``[{"supersample", "seconds", "vs_ours", ...}, ...]``, the fastest whose
    error against our converged reference (O) meets ``goal`` in mean and p95; None if none."""
    meeting = [rung for rung in our_ladder if meets_goal(rung["vs_ours"], goal)]
    return min(meeting, key=lambda rung: rung["seconds"]) if meeting else None


def _at_goal(ladder, key, goal):
    """Mitsuba's ``key`` ("seconds" or "spp") at the goal's mean and at its p95 against O:
    :func:`equal_error_seconds` along its ``ladder``'s rungs, extrapolated past the slowest
    two; None for either the ladder cannot say."""
    return [equal_error_seconds(g, [(r["spp"], r[key], r["vs_ours"][j]) for r in ladder],
                                extrapolate=True) for j, g in enumerate(goal)]


def goal_comparison(ladder: Sequence[Mapping[str, Any]], our_ladder: Iterable[dict[str, Any]],
                    goal: Sequence[float] = GOAL_DE
                    ) -> dict[str, Any]:  # numbers, a list, None where a time cannot be had
    """Mitsuba's and our times at the accuracy ``goal`` against O, and their ratio.

    Mitsuba's seconds at the goal's mean and at its p95 come from its ``ladder`` (rungs
    ``{"spp", "seconds", "vs_ours"}``) by :func:`equal_error_seconds` (log-log between rungs,
    extrapolated past the slowest two), the larger of the two being its time at the goal; ours
    is the fastest of ``our_ladder`` that meets it (:func:`fastest_at_goal`). A time that
    cannot be had is None, and so is the ratio (Mitsuba's over ours) then.
    """
    need = _at_goal(ladder, "seconds", goal)
    mitsuba_s = None if None in need else max(need)
    ours = fastest_at_goal(our_ladder, goal)
    return {"goal_de": list(goal), "mitsuba_s": mitsuba_s, "mitsuba_mean_s": need[0],
            "mitsuba_p95_s": need[1],
            "ours_supersample": None if ours is None else ours["supersample"],
            "ours_s": None if ours is None else ours["seconds"],
            "ratio": None if ours is None or mitsuba_s is None else mitsuba_s / ours["seconds"]}


def spp_at_goal(ladder: Sequence[Mapping[str, Any]], goal: Sequence[float] = GOAL_DE) -> int | None:
    """Mitsuba's samples per pixel at the accuracy ``goal`` against O, from its ``ladder``
    (rungs ``{"spp", "vs_ours"}``): for the mean and for the p95, log-log interpolation of
    error against spp between rungs (past the slowest two, extrapolated along them:
    :func:`equal_error_seconds` with the spp in place of the seconds), the larger of the two,
    rounded up to a perfect square (the counts of the stratified sampler); None where the
    ladder cannot say.

    Examples
    --------
    >>> ladder = [{"spp": 16, "vs_ours": [0.6, 2.0]}, {"spp": 64, "vs_ours": [0.3, 1.0]}]
    >>> spp_at_goal(ladder), spp_at_goal(ladder, goal=(0.45, 2.0))
    (64, 36)
    """
    need = _at_goal(ladder, "spp", goal)
    if None in need:
        return None
    side = int(np.ceil(np.sqrt(max(need)) - 1e-9))
    return max(side, 1) ** 2


#: seconds a whole command may take before the bench gives up on it
COMMAND_TIMEOUT_S = 900

#: the least any render command of ours does before it renders: Python started, numpy and VTK's
#: OpenGL renderer (the ID buffers) imported; timed beside the two whole commands as their floor
FLOOR_COMMAND = "import numpy, vtkmodules.vtkRenderingCore, vtkmodules.vtkRenderingOpenGL2"


def whole_commands(document: dict[str, Any], scene: Scene, size: int, supersample: int, spp: int,
                   variant: str, reference: npt.NDArray[np.float64], runs: int = 3,
                   spectra_dir: SpectraDirs = None, base_dir: str | os.PathLike[str] | None = None,
                   progress: Callable[[str], None] | None = None
                   ) -> dict[str, Any]:  # seconds and (mean, p95) pairs, or {"error": str}
    """The two renderers' whole commands, each in a fresh process (Python's start-up, imports,
    the scene's loading, the render, the EXR written): wall seconds (median of ``runs``, the
    two run alternately) and the CIEDE2000 (mean, p95) of each image against ``reference``
    (XYZ; :func:`reflectance.bench.measure.scene_difference` over ``scene``).

    Ours is ``python -m reflectance render SCENE.yaml -o OUT.exr --quiet`` on ``document`` (a
    scene document as :func:`crosscheck_scene` gives it; table shading, ``spectra_dir`` and
    mesh and material files copied from ``base_dir``) at ``size`` x ``size`` pixels with
    ``supersample`` x ``supersample`` samples (its material files copied beside it), as the
    in-process rungs; Mitsuba's is
    :mod:`reflectance.bench.mitsuba_command` on ``scene`` (exported by
    :func:`scene_to_mitsuba`) at ``spp`` samples per pixel with ``variant``. Beside them, the
    floor of any render command of ours, ``python -c FLOOR_COMMAND`` (start-up and the imports it cannot
    do without, nothing rendered). Returns ``{"ours_s", "mitsuba_s", "floor_s", "ours_vs_ours",
    "mitsuba_vs_ours"}``; a command that fails or times out gives ``{"error": one line naming it
    and its last line of standard error}``.
    """
    import copy
    import statistics
    import subprocess
    import sys

    import yaml

    from reflectance.io.images import read_exr
    from reflectance.bench.mitsuba_command import save_scene
    from reflectance.bench.measure import scene_difference as errors

    progress = progress or (lambda phase: None)
    ours_doc = copy.deepcopy(document)
    ours_doc.pop("_source", None)
    ours_doc["camera"].update(width=int(size), height=int(size), supersample=int(supersample))
    ours_doc["spectral"] = "table"  # as the in-process rungs (load_bench_scene's spectral)
    with tempfile.TemporaryDirectory(prefix="reflectance-commands-") as folder:
        folder = Path(folder)
        (folder / "scene.yaml").write_text(yaml.safe_dump(ours_doc, sort_keys=False))
        # a mesh or material file must stay inside the scene file's folder (reflectance.io.paths;
        # the scene was loaded, so each is): copied there, as it lies
        for obj in ours_doc.get("objects", []):
            geometry = obj.get("geometry", {})
            if geometry.get("type") == "mesh":
                (folder / geometry["path"]).parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(Path(base_dir or ".") / geometry["path"], folder / geometry["path"])
            for material in [obj.get("material", {}), *obj.get("parts", {}).values()]:
                if "file" in material:
                    (folder / material["file"]).parent.mkdir(parents=True, exist_ok=True)
                    shutil.copyfile(Path(base_dir or ".") / material["file"],
                                    folder / material["file"])
        save_scene(scene_to_mitsuba(scene, folder, spp=spp), scene.camera, folder / "scene.json")
        ours = [sys.executable, "-m", "reflectance", "render", str(folder / "scene.yaml"),
                "-o", str(folder / "ours.exr"), "--quiet"]
        for extra in folder_list(spectra_dir):
            ours += ["--spectra-dir", str(Path(extra).resolve())]
        commands = {
            "ours": ours,
            "mitsuba": [sys.executable, "-m", "reflectance.bench.mitsuba_command",
                        str(folder / "scene.json"), variant, str(int(spp)),
                        str(folder / "mitsuba.exr")],
            "floor": [sys.executable, "-c", FLOOR_COMMAND]}
        times: dict[str, list[float]] = {key: [] for key in commands}
        for run in range(runs):
            for key, command in commands.items():
                progress(f"cross-check: whole command, {key} {run + 1}/{runs}")
                t0 = time.perf_counter()
                try:
                    subprocess.run(command, check=True, capture_output=True, text=True,
                                   timeout=COMMAND_TIMEOUT_S)
                except subprocess.TimeoutExpired:
                    return {"error": f"{key}'s whole command took over {COMMAND_TIMEOUT_S} s"}
                except subprocess.CalledProcessError as err:
                    last = (err.stderr or "").strip().splitlines()[-1:] or ["no message"]
                    return {"error": f"{key}'s whole command failed (exit {err.returncode}): "
                                     f"{last[0]}"}
                times[key].append(time.perf_counter() - t0)
        import mitsuba as mi

        XYZ = {"ours": read_exr(folder / "ours.exr")[0].astype(np.float64),
               "mitsuba": np.array(mi.Bitmap(str(folder / "mitsuba.exr")),
                                   dtype=np.float64)[..., :3]}
    out: dict[str, Any] = {f"{key}_s": statistics.median(value) for key, value in times.items()}
    out.update({f"{key}_vs_ours": list(errors(image, reference, scene))
                for key, image in XYZ.items()})
    return out


def bench_crosscheck(document: str | os.PathLike[str] | dict[str, Any], size: int,
                     supersample: int = 2, runs: int = 3, reference_supersample: int = 8,
                     reference_spp: int = CROSSCHECK_SPP, ladder_spp: Sequence[int] = LADDER_SPP,
                     spectra_dir: SpectraDirs = None, progress: Callable[[str], None] | None = None,
                     variants: Sequence[str] = VARIANTS,
                     our_supersamples: Sequence[int] = CROSSCHECK_SUPERSAMPLES) -> dict[str, Any]:
    """The bench's cross-check at one square size: our renderer and Mitsuba against the same
    converged references.

    ``document`` (a scene file or document, as :func:`reflectance.bench.measure.load_bench_scene`
    takes it) is read through :func:`crosscheck_scene`. Returns a dict: Mitsuba's variant; our
    render (``supersample`` x ``supersample``, median seconds of ``runs`` loads and renders) with
    its CIEDE2000 (mean, p95) against Mitsuba at ``reference_spp`` and against ours at
    ``reference_supersample`` squared; the two references against each other; per rung of
    ``ladder_spp``, Mitsuba's seconds (``mitsuba.render`` alone) and error against the same
    Mitsuba reference; and Mitsuba's interpolated seconds at our error over ours. ``variants``:
    Mitsuba's variants to try, in order (:func:`mitsuba_variant`).

    Our own ladder, ``our_ladder``: per supersampling n of ``our_supersamples``, our median
    seconds of ``runs`` loads and renders at n x n and its errors against both references; and
    ``goal`` (:func:`goal_comparison`): Mitsuba's time at issue 9's accuracy goal against O
    over that of our fastest rung meeting it, the comparison at equal error.
    """
    import statistics

    from reflectance.bench.measure import load_bench_scene
    from reflectance.bench.measure import scene_difference as errors
    from reflectance.render.pipeline import render

    progress = progress or (lambda phase: None)
    base_dir = None  # a scene file's folder: its mesh paths are relative to it
    if not isinstance(document, dict):  # a scene file: its validated document
        base_dir = Path(document).parent
        document = load_bench_scene(document, spectra_dir=spectra_dir).document
    doc = crosscheck_scene(document)

    def load(n):
        return load_bench_scene(doc, spectra_dir=spectra_dir, width=size, height=size,
                                supersample=n, spectral="table", base_dir=base_dir or ".")

    def timed(n):  # median seconds of runs loads and renders at n x n; the last image, scene
        times = []
        for run in range(runs):
            progress(f"cross-check: our render at {n} x {n}, {run + 1}/{runs}")
            t0 = time.perf_counter()
            scene = load(n)
            XYZ = render(scene).XYZ
            times.append(time.perf_counter() - t0)
        return statistics.median(times), XYZ, scene

    # all of ours timed before Mitsuba is loaded (its threads stay out of our times)
    ours_s, ours, scene = timed(supersample)
    our_images = {n: (ours_s, ours) if n == supersample else timed(n)[:2]
                  for n in dict.fromkeys(int(n) for n in our_supersamples)}
    progress(f"cross-check: our reference at {reference_supersample} x {reference_supersample}")
    our_reference = render(load(reference_supersample)).XYZ
    variant = mitsuba_variant(variants)
    progress(f"cross-check: Mitsuba {variant} reference at {reference_spp} spp")
    mitsuba = mitsuba_renderer(scene, variant)  # the scene loaded once for every render
    mitsuba(1, seed=0)  # compiles the kernels (LLVM) once, not timed
    mitsuba_reference, reference_s = mitsuba(reference_spp, seed=1)
    rungs: list[dict[str, Any]] = []
    for spp in ladder_spp:
        progress(f"cross-check: Mitsuba at {spp} spp")
        XYZ, seconds = mitsuba(spp, seed=2)
        if seconds < RETIME_S:  # again with the kernel compiled: the faster of the two
            seconds = min(seconds, mitsuba(spp, seed=2)[1])
        rungs.append({"spp": int(spp), "seconds": seconds,
                      "vs_mitsuba": list(errors(XYZ, mitsuba_reference, scene)),
                      "vs_ours": list(errors(XYZ, our_reference, scene))})
    our_ladder: list[dict[str, Any]] = [{"supersample": n, "seconds": seconds,
                   "vs_mitsuba": list(errors(XYZ, mitsuba_reference, scene)),
                   "vs_ours": list(errors(XYZ, our_reference, scene))}
                  for n, (seconds, XYZ) in our_images.items()]
    out: dict[str, Any] = {
        "size": size, "variant": variant, "supersample": supersample, "runs": runs,
        "material": scene.document["objects"][0]["material"],
        "reference_spp": reference_spp, "reference_supersample": reference_supersample,
        "mitsuba_reference_s": reference_s, "ours_s": ours_s,
        "ours_vs_mitsuba": list(errors(ours, mitsuba_reference, scene)),
        "ours_vs_ours": list(errors(ours, our_reference, scene)),
        "our_reference_vs_mitsuba": list(errors(our_reference, mitsuba_reference, scene)),
        "ladder": rungs, "our_ladder": our_ladder,
        "goal": goal_comparison(rungs, our_ladder),
    }
    # issue 9's "whole command": ours at our fastest rung meeting the goal (else our rung of
    # smallest mean error), Mitsuba at its spp at the goal (spp_at_goal, else its top rung);
    # each command's own image is judged against O again
    ours_at = out["goal"]["ours_supersample"] or min(
        our_ladder, key=lambda r: r["vs_ours"][0])["supersample"]
    theirs_spp = spp_at_goal(rungs) or max(r["spp"] for r in rungs)
    commands = whole_commands(doc, scene, size, ours_at, theirs_spp, variant, our_reference,
                              max(1, runs), spectra_dir, base_dir, progress)
    if "error" not in commands:
        commands.update(ours_meets_goal=meets_goal(commands["ours_vs_ours"]),
                        mitsuba_meets_goal=meets_goal(commands["mitsuba_vs_ours"]),
                        ratio=commands["mitsuba_s"] / commands["ours_s"])
    out["whole_commands"] = {**commands, "ours_supersample": ours_at, "mitsuba_spp": theirs_spp}
    for against, extrapolate in (("mitsuba", False), ("ours", True)):
        # Against Mitsuba's reference its own noise is a floor no renderer goes below, so
        # only interpolation (or a bound); against ours, extrapolation along the power law.
        error = out[f"ours_vs_{against}"][0]
        ladder = [(r["spp"], r["seconds"], r[f"vs_{against}"][0]) for r in rungs]
        equal = equal_error_seconds(error, ladder, extrapolate)
        best = min(rungs, key=lambda r: r[f"vs_{against}"][0])
        out[f"equal_error_vs_{against}"] = {
            "mitsuba_s": equal, "ratio": None if equal is None else equal / ours_s,
            "extrapolated": bool(equal is not None and error < best[f"vs_{against}"][0]),
            # below every rung: Mitsuba needs more than its best rung's time
            "ratio_above": best["seconds"] / ours_s
            if equal is None and error < best[f"vs_{against}"][0] else None,
            "best_spp": best["spp"]}
    return out


def format_crosscheck(result: Mapping[str, Any]) -> list[str]:
    """Lines of the bench's report for :func:`bench_crosscheck`'s result."""
    r = result

    def pair(e):
        return f"{e[0]:.3f} / {e[1]:.3f}"

    lines = [
        f"path tracer (Mitsuba 3 {r['variant']}), size {r['size']}, one Beckmann lobe m = "
        f"{r['material'].get('m')}, Smith G, physical, no ambient; CIEDE2000 mean / p95 over "
        "the lit pixels on the reference's exposure, against Mitsuba's reference (M) and ours (O):",
        f"  M: Mitsuba at {r['reference_spp']} spp (stratified, box filter), "
        f"{r['mitsuba_reference_s']:.1f} s; O: ours at {r['reference_supersample']}^2 spp; O "
        f"against M: {pair(r['our_reference_vs_mitsuba'])}",
        f"  ours ({r['supersample']}^2 spp): {r['ours_s']:.2f} s (load + render); against M "
        f"{pair(r['ours_vs_mitsuba'])}, against O {pair(r['ours_vs_ours'])}",
        f"  {'Mitsuba spp':>12} {'seconds':>8} {'against M':>15} {'against O':>15}",
    ]
    for rung in r["ladder"]:
        lines.append(f"  {rung['spp']:>12} {rung['seconds']:8.2f} {pair(rung['vs_mitsuba']):>15} "
                     f"{pair(rung['vs_ours']):>15}")
    for key, name in (("mitsuba", "M"), ("ours", "O")):
        q = r[f"equal_error_vs_{key}"]
        head = f"  Mitsuba's time at our mean error against {name}: "
        if q["ratio"] is not None:
            how = ("extrapolated along its two slowest rungs" if q["extrapolated"]
                   else "interpolated")
            lines.append(head + f"{q['mitsuba_s']:.3g} s ({how}) = {q['ratio']:.3g} x ours")
        elif q["ratio_above"] is not None:
            lines.append(head + f"more than its {q['best_spp']} spp time (our error is below "
                                f"all its rungs) = more than {q['ratio_above']:.3g} x ours")
        else:
            lines.append(head + "outside its ladder (no ratio)")
    # issue 9's accuracy goal: CIEDE2000 0.3 mean and 1.0 p95 against a converged reference
    goal = goal_comparison(r["ladder"], r.get("our_ladder", []))
    need = (goal["mitsuba_mean_s"], goal["mitsuba_p95_s"])
    at_goal = f"  at the goal CIEDE2000 {GOAL_DE[0]:g} mean / {GOAL_DE[1]:g} p95 against O: "
    if goal["mitsuba_s"] is not None:
        lines.append(at_goal + f"Mitsuba {goal['mitsuba_s']:.3g} s ({need[0]:.3g} s for the "
                     f"mean, {need[1]:.3g} s for the p95, log-log along its rungs) = "
                     f"{goal['mitsuba_s'] / r['ours_s']:.3g} x ours at "
                     f"{r['supersample']}^2 spp; that rung of ours "
                     f"{'meets' if meets_goal(r['ours_vs_ours']) else 'misses'} it")
    else:
        lines.append(at_goal + "Mitsuba's time outside its ladder (no ratio)")
    if not r.get("our_ladder"):
        return lines
    lines.append(f"  {'our spp':>12} {'seconds':>8} {'against M':>15} {'against O':>15}"
                 "  (ours at each supersampling, load + render)")
    for rung in r["our_ladder"]:
        n = rung["supersample"]
        lines.append(f"  {f'{n}^2':>12} {rung['seconds']:8.2f} {pair(rung['vs_mitsuba']):>15} "
                     f"{pair(rung['vs_ours']):>15}")
    rungs = ", ".join(f"{rung['supersample']}^2" for rung in r["our_ladder"])
    if goal["ours_s"] is None:
        lines.append(at_goal + f"no rung of ours ({rungs} spp) meets it (no ratio)")
    elif goal["ratio"] is None:
        lines.append(at_goal + f"ours fastest at {goal['ours_supersample']}^2 spp, "
                     f"{goal['ours_s']:.2f} s; Mitsuba's time outside its ladder (no ratio)")
    else:
        lines.append(at_goal + f"our fastest rung meeting it is {goal['ours_supersample']}^2 "
                     f"spp, {goal['ours_s']:.2f} s; Mitsuba's time there / ours = "
                     f"{goal['ratio']:.3g} x (issue 9's goal: {GOAL_SPEEDUP:g} x)")
    w = r.get("whole_commands")
    if w and "error" in w:
        lines.append(f"  whole commands: {w['error']}")
    elif w:
        def judged(errors, ok):
            return f"{pair(errors)} against O: {'meets' if ok else 'misses'} the goal"

        lines.append(
            f"  whole commands (each a fresh process: Python, imports, scene loading, render, "
            f"EXR; median of {r.get('runs', 3)}, the two alternately; each image judged against "
            f"O): ours (`reflectance render`) at {w['ours_supersample']}^2 spp "
            f"{w['ours_s']:.2f} s ({judged(w['ours_vs_ours'], w['ours_meets_goal'])}); Mitsuba "
            f"at {w['mitsuba_spp']} spp (its spp at the goal from the ladder, a square) "
            f"{w['mitsuba_s']:.2f} s ({judged(w['mitsuba_vs_ours'], w['mitsuba_meets_goal'])})"
            f" = {w['ratio']:.3g} x ours")
        if w.get("floor_s") is not None:
            tenth = w["mitsuba_s"] / GOAL_SPEEDUP
            left = tenth - w["floor_s"]
            lines.append(
                f"  the floor of any render command of ours (Python started, numpy and VTK's "
                f"OpenGL renderer imported, nothing rendered): {w['floor_s']:.2f} s; issue 9's "
                f"{GOAL_SPEEDUP:g} x needs ours within Mitsuba's / {GOAL_SPEEDUP:g} = "
                f"{tenth:.2f} s: "
                + (f"{left:.2f} s left for the scene and the render" if left > 0 else
                   "the floor alone takes it all"))
    return lines


def run_crosscheck(scene: str | os.PathLike[str] | dict[str, Any], size: int, supersample: int = 2,
                   runs: int = 3, reference_supersample: int = 8,
                   reference_spp: int = CROSSCHECK_SPP, ladder_spp: Sequence[int] = LADDER_SPP,
                   spectra_dir: SpectraDirs = None, progress: Callable[[str], None] | None = None,
                   our_supersamples: Sequence[int] = CROSSCHECK_SUPERSAMPLES
                   ) -> dict[str, Any]:  # bench_crosscheck's result, read back from JSON
    """:func:`bench_crosscheck` in a fresh Python process (Mitsuba's threads and memory stay
    there); ``progress``, if given, is called with each phase. Raises RuntimeError with the
    worker's standard error if it fails."""
    from reflectance.io.progress import run_worker

    job = {"document": scene if isinstance(scene, dict) else str(scene), "size": int(size),
           "supersample": supersample, "runs": runs,
           "reference_supersample": reference_supersample, "reference_spp": int(reference_spp),
           "ladder_spp": [int(n) for n in ladder_spp],
           "our_supersamples": [int(n) for n in our_supersamples],
           "spectra_dir": folder_list(spectra_dir)}
    return run_worker("reflectance.bench.crosscheck", job, progress,
                      failure=f"cross-check at size {size} failed")


if __name__ == "__main__":  # pragma: no cover - run by run_crosscheck in a subprocess
    from reflectance.io.progress import worker_main

    worker_main(bench_crosscheck)
