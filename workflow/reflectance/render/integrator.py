"""The pixel integral: each pixel the box-filter mean of its samples' shaded XYZ.

:class:`Integrator` builds a render's image band by band: each band's samples (a trace,
:mod:`reflectance.render.tracing`) shaded with their objects' materials (:func:`shade_samples`,
:func:`reflectance.render.shading.shade`; background black) and their n x n samples per pixel
averaged in linear XYZ (:meth:`reflectance.render.samples.SurfaceSamples.to_pixels`). With the
scene's adaptive supersampling on (``camera.adaptive``, :mod:`reflectance.render.adaptive`) it
notes each pixel's spread and silhouettes as it goes, and :meth:`Integrator.refine` then replaces
the pixels on a silhouette or whose shading curves within them by the mean of N x N samples.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable
from typing import Any, Literal, TYPE_CHECKING, overload

import numpy as np
import numpy.typing as npt

from reflectance.render.adaptive import pixel_spread, refine_mask, refinement_bands
from reflectance.render.shading import shade
from reflectance.render.tracing import light_map_size

if TYPE_CHECKING:
    from reflectance.render.samples import SurfaceSamples
    from reflectance.render.scene import Scene
    from reflectance.render.session import RenderSession

__all__ = ["COMPONENTS", "shade_samples", "Integrator"]

COMPONENTS = ("ambient", "diffuse", "specular", "emission")
"""Parts of the reflected XYZ a render can return separately (table shading)."""


@overload
def shade_samples(scene: Scene, samples: SurfaceSamples, shadowed: npt.NDArray[np.bool_],
                  spectral: str | None = None, components: Literal[False] = False,
                  fresnel_table: Callable[..., Any] | None = None,
                  threads: int | None = 1) -> npt.NDArray[np.float64]: ...
@overload
def shade_samples(scene: Scene, samples: SurfaceSamples, shadowed: npt.NDArray[np.bool_],
                  spectral: str | None = None, *, components: Literal[True],
                  fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1
                  ) -> tuple[npt.NDArray[np.float64], dict[str, npt.NDArray[np.float64]]]: ...
@overload
def shade_samples(scene: Scene, samples: SurfaceSamples, shadowed: npt.NDArray[np.bool_],
                  spectral: str | None = None, components: bool = False,
                  fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1
                  ) -> npt.NDArray[np.float64] | tuple[npt.NDArray[np.float64],
                                                       dict[str, npt.NDArray[np.float64]]]: ...
def shade_samples(scene: Scene, samples: SurfaceSamples, shadowed: npt.NDArray[np.bool_],
                  spectral: str | None = None, components: bool = False,
                  fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1
                  ) -> npt.NDArray[np.float64] | tuple[npt.NDArray[np.float64],
                                                       dict[str, npt.NDArray[np.float64]]]:
    """Per-sample XYZ (N, 3) of every object (and the parts, with ``components=True``);
    ``threads`` as for :func:`reflectance.render.shading.shade`."""
    spectral = scene.spectral if spectral is None else spectral
    N = len(samples.hit)
    XYZ = np.zeros((N, 3))
    parts: Any = {name: np.zeros((N, 3)) for name in COMPONENTS} if components else None
    part_of_triangle = np.asarray(scene.mesh.cell_data["part"])
    for i, obj in enumerate(scene.objects):
        members = np.nonzero(samples.object_id == i)[0]
        groups = [(obj.material, members)]
        if obj.part_materials:  # named parts with their own materials
            code = part_of_triangle[samples.triangle[members]]
            rest = ~np.isin(code, list(obj.part_materials))
            groups = [(obj.material, members[rest])] + [
                (material, members[code == c]) for c, material in obj.part_materials.items()]
        for material, idx in groups:
            if len(idx) == 0:
                continue
            out = shade(samples.position[idx], samples.normal[idx], samples.view[idx],
                        samples.uv[idx], material, scene.lights, shadowed[:, idx],
                        scene.ambient, scene.wavelengths, scene.observer, spectral,
                        scene.table_size, components=components,
                        fresnel_table=fresnel_table, threads=threads)
            if isinstance(out, tuple):  # components=True
                out, got = out
                for name in COMPONENTS:
                    if name in got:
                        parts[name][idx] = got[name]
            XYZ[idx] = out
    return (XYZ, parts) if components else XYZ


class _Counts:
    """Sample counts over the bands of a render, and the fractions of its ``stats`` (the same
    numbers whether the image was traced in one band or several)."""

    VISIBILITY = ("raster_miss", "recovered", "searched", "dropped")

    def __init__(self, n_lights, n_objects):
        self.samples, self.hit = 0, 0
        self.visibility = dict.fromkeys(self.VISIBILITY, 0)
        self.shadowed = [0] * n_lights
        self.visible, self.back = [0] * n_objects, [0] * n_objects

    def add(self, samples, shadowed):
        n, hit = len(samples.hit), samples.hit
        self.samples += n
        self.hit += int(np.count_nonzero(hit))
        for key in self.VISIBILITY:  # the band's fractions are counts / n, exactly
            self.visibility[key] += round(samples.stats[key] * n)
        for i, s in enumerate(shadowed):
            self.shadowed[i] += int(np.count_nonzero(s & hit))
        for i in range(len(self.visible)):
            mine = hit & (samples.object_id == i)
            self.visible[i] += int(np.count_nonzero(mine))
            self.back[i] += int(np.count_nonzero(samples.flipped & mine))

    def stats(self):
        out = {key: value / self.samples for key, value in self.visibility.items()}
        out.update(hit=self.hit / self.samples,
                   shadowed=[s / self.hit if self.hit else 0.0 for s in self.shadowed],
                   # per object: the fraction of its visible samples seen from the back of the
                   # surface (None where it is not visible)
                   seen_from_back=[b / v if v else None for b, v in zip(self.back, self.visible)])
        return out


class Integrator:
    """A render's image, integrated band by band (see the module docstring).

    Parameters
    ----------
    scene : reflectance.render.scene.Scene
    spectral : str
        ``"table"`` or ``"brute-force"`` (:func:`reflectance.render.shading.shade`).
    components : bool
        Also integrate the ambient, diffuse, specular and emitted parts (:data:`COMPONENTS`).
    fresnel_table : callable, optional
        How the Fresnel table is made (:func:`reflectance.render.shading.shade`).
    threads : int
        Of the shading and the box filter (:mod:`reflectance.render.parallel`).

    Attributes
    ----------
    image : ndarray, shape (height, width, 3)
        Linear XYZ.
    parts : dict or None
        ``{name: (height, width, 3)}`` with ``components``.
    timings : dict
        Wall seconds of ``visibility``, ``shadows`` and ``shading`` summed over the bands (and
        ``refinement`` once refined: its share of those three).
    adaptive : bool
        Whether the scene's adaptive supersampling refines pixels (:meth:`refine`).
    refined : ndarray of bool or None
        The pixels :meth:`refine` sampled again (None before).
    """

    def __init__(self, scene: Scene, spectral: str | None, components: bool = False,
                 fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1) -> None:
        self.scene, self.spectral, self.components = scene, spectral, components
        self.fresnel_table, self.threads = fresnel_table, threads
        camera = scene.camera
        self.image = np.zeros((camera.height, camera.width, 3))
        self.parts: Any = ({name: np.zeros_like(self.image) for name in COMPONENTS} if components
                      else None)
        self.timings = {"visibility": 0.0, "shadows": 0.0, "shading": 0.0}
        self._count = _Counts(len(scene.lights), len(scene.objects))
        refinement = getattr(scene, "refinement", None)
        self.adaptive = (refinement is not None and refinement.enabled
                         and refinement.supersample > camera.supersample)
        if self.adaptive:  # per pixel of the first pass: its window's difference and silhouettes
            self._difference = np.zeros((camera.height, camera.width, 3), np.float32)
            self._silhouette = np.zeros((camera.height, camera.width), bool)
        self.refined: npt.NDArray[np.bool_] | None = None
        self._n_refined = 0

    def _shade(self, samples, shadowed):
        """(XYZ, parts or None) of the samples."""
        shaded = shade_samples(self.scene, samples, shadowed, self.spectral, self.components,
                               self.fresnel_table, self.threads)
        return shaded if self.components else (shaded, None)

    def _spent(self, traced, since):
        """Add a trace's timings, and the shading's since ``since``, to :attr:`timings`."""
        self.timings["visibility"] += traced["visibility"]
        self.timings["shadows"] += traced["shadows"]
        self.timings["shading"] += time.perf_counter() - since

    def add_band(self, rows: tuple[int, int], samples: SurfaceSamples,
                 shadowed: npt.NDArray[np.bool_], traced: Any) -> None:
        """Shade the band ``rows`` ``(start, stop)`` of the fine grid (its trace: ``samples``,
        ``shadowed``, ``traced`` its timings) and box-filter it into its pixel rows."""
        t0 = time.perf_counter()
        XYZ, got = self._shade(samples, shadowed)
        n = self.scene.camera.supersample
        band = slice(rows[0] // n, rows[1] // n)
        self.image[band] = samples.to_pixels(XYZ, self.threads)
        for name, value in (got or {}).items():
            self.parts[name][band] = samples.to_pixels(value, self.threads)
        if self.adaptive:
            self._difference[band], self._silhouette[band] = pixel_spread(samples, XYZ)
        self._count.add(samples, shadowed)
        self._spent(traced, t0)

    def refine(self, session: RenderSession,
               exposure: Callable[[npt.NDArray[np.float64]], float]) -> None:
        """Replace the pixels the adaptive supersampling picks (:attr:`refined`:
        :func:`reflectance.render.adaptive.refine_mask` of the first pass, differences judged as
        shown at the factor ``exposure(image)`` of the image's display) by the box-filter mean
        of their N x N samples, traced band by band by ``session``
        (:class:`reflectance.render.session.RenderSession`)."""
        from reflectance.colour.colorimetry import white_XYZ

        t0 = time.perf_counter()
        scene = self.scene
        white = white_XYZ(scene.display.illuminant, scene.observer, scene.wavelengths)
        self.refined = refine_mask(self._difference, self._silhouette, self.image,
                                   exposure(self.image), scene.refinement.threshold,  # type: ignore[union-attr]
                                   white)
        del self._difference, self._silhouette
        N = scene.refinement.supersample  # type: ignore[union-attr]  # adaptive: it is set
        fine = dataclasses.replace(scene, camera=dataclasses.replace(scene.camera, supersample=N))
        flat = self.image.reshape(-1, 3)
        map_size = light_map_size(scene.camera)  # the whole first pass's light maps
        bands = refinement_bands(self.refined, N)
        session.plan(sum(len(pixels) for _, _, pixels in bands) * N * N)
        for rows, select, pixels in bands:
            where = f"refining rows {rows[0] // N}-{rows[1] // N}: "
            samples, shadowed, traced = session.trace_selected(fine, rows, select, map_size,
                                                               where)
            t1 = time.perf_counter()
            XYZ, got = self._shade(samples, shadowed)
            flat[pixels] = XYZ.reshape(len(pixels), N * N, 3).mean(axis=1)
            for name, value in (got or {}).items():
                self.parts[name].reshape(-1, 3)[pixels] = value.reshape(
                    len(pixels), N * N, 3).mean(axis=1)
            self._n_refined += len(pixels)
            session.finished(len(pixels) * N * N)
            self._spent(traced, t1)
        self.timings["refinement"] = time.perf_counter() - t0

    def stats(self) -> dict[str, Any]:
        """The render's ``stats`` (:class:`reflectance.render.pipeline.RenderResult`): the first
        pass's visibility and shadow fractions, the fraction of pixels refined and the samples
        spent per pixel."""
        out = self._count.stats()
        pixels = self.image.shape[0] * self.image.shape[1]
        n, refined = self.scene.camera.supersample, self._n_refined
        # the sample budget: every pixel's n x n, and N x N more in each refined pixel
        out.update(refined=refined / pixels, samples_per_pixel=n**2 + (
            refined * self.scene.refinement.supersample**2 / pixels  # type: ignore[union-attr]
            if self.adaptive else 0.0))
        return out
