"""Render a scene: trace, shade, box filter, refine; EXR and display PNG.

:func:`render` runs the steps on a :class:`reflectance.render.scene.Scene`, band by band of
pixel rows (:func:`reflectance.render.tracing.tiles`):

1. a :class:`reflectance.render.session.RenderSession` traces each band: which surface each
   camera sample sees and which lights each sample sees (:mod:`reflectance.render.tracing`),
   all with one set of the scene's primitives and ID-buffer window, released at the end;
2. an :class:`reflectance.render.integrator.Integrator` shades every object's samples with its
   material (background black) and averages the n x n samples of each pixel in linear XYZ (box
   filter);
3. with the scene's adaptive supersampling on (``camera.adaptive``,
   :mod:`reflectance.render.adaptive`), the integrator then traces, shades and box-filters the
   pixels on a silhouette or whose shading curves within them again on a finer N x N grid, in
   bands.

An image of more than :data:`~reflectance.render.camera.SINGLE_TILE_SAMPLES` samples has bands
of at most :data:`~reflectance.render.camera.TILE_SAMPLES` samples, so that memory does not grow
with the image beyond the image itself. Every sample is traced and shaded as in one pass (the
same rays, the same exact tests); only the light maps that propose occluders are drawn per band
(over that band's samples, at the whole image's map size).

:func:`write_render` writes the linear XYZ image as OpenEXR (the validated scene and the package
versions in its header) and, optionally, the display PNG (Cook & Torrance exposure over the image,
gamut clipping, transfer function: :mod:`reflectance.colour.exposure`). Everything is
deterministic: the same scene gives byte-identical files.
"""

from __future__ import annotations

import contextlib
import functools
import json
import os
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.colour.exposure import exposure_scale, image_display_RGB
from reflectance.io.atomic import atomic_write
from reflectance.io.images import write_exr_XYZ, write_png
from reflectance.render.integrator import Integrator
from reflectance.render.parallel import render_threads
from reflectance.render.session import RenderSession
from reflectance.render.shading import white_card_luminance
from reflectance.render.tracing import tiles

if TYPE_CHECKING:
    from reflectance.optics.spectra import SpectraDirs
    from reflectance.render.scene import Scene

__all__ = [
    "render_to_files",
    "RenderResult",
    "render",
    "display_image",
    "automatic_exposure",
    "display_linear_RGB",
    "write_linear_RGB_from_XYZ",
    "software_versions",
    "write_render",
    "render_warnings",
    "BACK_FRACTION_WARNING",
]


@dataclass
class RenderResult:
    """A rendered image.

    Attributes
    ----------
    XYZ : ndarray, shape (height, width, 3)
        Linear CIE XYZ (a light's white has Y = intensity; background 0).
    components : dict or None
        ``{name: (height, width, 3)}`` for :data:`reflectance.render.integrator.COMPONENTS`
        when asked for.
    timings : dict
        Wall seconds of ``visibility``, ``shadows``, ``shading`` and ``total`` (and, with adaptive
        supersampling, ``refinement``: the refinement's share of those three).
    stats : dict
        Visibility statistics, the fraction of samples hit and the fraction of hit samples in
        each light's shadow (of the first pass, n x n per pixel); ``refined``, the fraction of
        pixels the adaptive supersampling refined, and ``samples_per_pixel``, the mean number
        of camera samples spent per pixel (n^2 plus N^2 per refined pixel: the budget).
    scene : Scene
    refined : ndarray of bool, shape (height, width), or None
        The pixels sampled again at N x N (:mod:`reflectance.render.adaptive`); None when the
        scene's adaptive supersampling is off.
    display : tuple or None
        ``(encoded RGB, exposure scale)`` as :func:`render_to_files` wrote them (what
        :func:`display_image` gives for the result), so that a figure need not compute them
        again; None for a result not written by it.
    """

    XYZ: np.ndarray
    components: dict | None
    timings: dict
    stats: dict
    scene: Scene = field(repr=False)
    refined: np.ndarray | None = field(default=None, repr=False)
    display: tuple | None = field(default=None, repr=False)


def render(scene: Scene, spectral: str | None = None, components: bool = False,
           fresnel_table: Callable[..., Any] | None = None,
           progress: Callable[[str], None] | None = None, keep_trace: bool = False,
           threads: int | None = None,
           tally: Callable[[int, int], None] | None = None) -> RenderResult:
    """Render a :class:`reflectance.render.scene.Scene` into a :class:`RenderResult`.

    Parameters
    ----------
    scene : Scene
    spectral : str, optional
        Overrides ``scene.spectral`` (``"table"`` or ``"brute-force"``).
    components : bool
        Also return the ambient, diffuse, specular and emitted parts (table shading only).
    fresnel_table : callable, optional
        How the Fresnel table is made (:func:`reflectance.render.shading.shade`; e.g.
        :func:`reflectance.render.shading.fresnel_XYZ_table_rgb` for an RGB renderer's F).
    progress : callable, optional
        Called with the name of each phase (``"visibility"``, ``"shadows"``, ``"shading"``) as it
        starts, after where it is (``"rows 0-31: shading"``; e.g.
        :meth:`reflectance.io.progress.Progress.update` through a small adapter).
    keep_trace : bool
        Look the trace up in the process's trace memo
        (:func:`reflectance.render.tracing.trace_once`), and keep it there, for renders of
        scenes that differ only in what :func:`reflectance.render.tracing.trace` does not look at
        (materials, spectra, intensities, ambient: Cook & Torrance's Fig. 7 vases): an image
        traced in one band is traced once; the result is the same, bit for bit. Images of
        several bands are not kept (memory).
    threads : int, optional
        Threads of the per-sample work (:func:`reflectance.render.parallel.render_threads`:
        default the environment variable ``REFLECTANCE_RENDER_THREADS``, else
        ``OMP_NUM_THREADS``, else the cores this process may use; 1 is the serial path). The
        image is the same, bit for bit, at any count.
    tally : callable, optional
        Called with ``(done, total)`` samples as the work is planned and each band is shaded:
        the first pass's samples, then the adaptive refinement's, added to ``total`` when its
        pixels are picked (the units of a progress bar's estimate of the time left).
    """
    spectral = scene.spectral if spectral is None else spectral
    if components and spectral != "table":
        raise ValueError("components are available with spectral='table' only")
    threads = render_threads(threads)
    t0 = time.perf_counter()
    n = scene.camera.supersample
    bands = tiles(scene.camera)
    integrator = Integrator(scene, spectral, components, fresnel_table, threads)
    cols = scene.camera.shape[1]
    with RenderSession(scene, threads, progress, keep_trace, tally) as session, \
            np.errstate(over="ignore", invalid="ignore"):  # (an overflow: refused below, by name)
        session.plan(sum(stop - start for start, stop in bands) * cols)
        for start, stop in bands:
            where = "" if len(bands) == 1 else f"rows {start // n}-{stop // n}: "
            samples, shadowed, traced = session.trace((start, stop), where)
            session.tell(where + "shading")
            integrator.add_band((start, stop), samples, shadowed, traced)
            session.finished((stop - start) * cols)
            del samples, shadowed  # before the next band is traced: one band's at a time
        if integrator.adaptive:
            integrator.refine(session, lambda image: exposure_scale(image, *_shown(scene)))
    timings = {**integrator.timings, "total": time.perf_counter() - t0}
    _check_finite(integrator.image, scene)
    return RenderResult(integrator.image, integrator.parts, timings, integrator.stats(), scene,
                        integrator.refined)


#: an object more than this fraction of whose visible surface is seen from the back is reported
#: as possibly enclosing the camera
BACK_FRACTION_WARNING = 0.5


def render_warnings(result: RenderResult) -> list[str]:
    """Plain-language warnings about a render that worked but is probably not what was meant:
    an empty view (no object in the image) and a camera inside an object (most of the object's
    visible surface seen from its back). Each names the camera (position and look_at)."""
    camera = result.scene.camera
    where = (f"the camera at position {list(camera.position)} looking at {list(camera.look_at)} "
             f"(scene {result.scene.source})")
    warnings = []
    if result.stats["hit"] == 0.0:
        warnings.append(f"{where} sees no object: the image is empty (black)")
    for obj, back in zip(result.scene.objects, result.stats["seen_from_back"]):
        if back is not None and back > BACK_FRACTION_WARNING:
            warnings.append(f"{where} sees {100 * back:.0f} % of object {obj.name!r} from the back "
                            f"of its surface: the camera is probably inside it")
    return warnings


def _shown(scene):
    """The scene's display as :mod:`reflectance.colour.exposure` takes it: (settings, observer,
    wavelengths, the white card's luminance where the display is metered on one)."""
    d = scene.display
    white = white_card_luminance(scene.lights) if d.expose and d.white is not None else None
    return d, scene.observer, scene.wavelengths, white


def display_linear_RGB(result: RenderResult, exposure: float | None = None,
                       encoded: bool = False) -> tuple[npt.NDArray[np.float64], float]:
    """(linear display RGB in [0, 1] of shape (H, W, 3), exposure scale) per the scene's display:
    exposed, highlights compressed, gamut clipped; the light the display emits, before the
    transfer function (:func:`reflectance.colour.exposure.image_display_RGB`, in bands of rows).

    ``exposure`` (a positive factor on XYZ) replaces the automatic exposure of the scene's
    display settings (Cook & Torrance's, the metered key or the white card); None keeps it.
    ``encoded`` applies the display's transfer function too (:func:`display_image`).
    """
    return image_display_RGB(result.XYZ, *_shown(result.scene), exposure=exposure,  # type: ignore[misc]
                             encoded=encoded)


def automatic_exposure(result: RenderResult) -> float:
    """The factor on XYZ the scene's display settings choose for this render (Cook & Torrance's
    exposure, the metered key or the white card; 1 where the display does not expose): what
    ``reflectance render --exposure-stops S`` multiplies by 2**S."""
    return float(exposure_scale(result.XYZ, *_shown(result.scene)))


def display_image(result: RenderResult,
                  exposure: float | None = None) -> tuple[npt.NDArray[np.float64], float]:
    """(encoded RGB in [0, 1] of shape (H, W, 3), exposure scale) per the scene's display (as
    :func:`reflectance.colour.display.XYZ_to_display`; ``exposure`` as for
    :func:`display_linear_RGB`)."""
    return display_linear_RGB(result, exposure, encoded=True)


def software_versions() -> dict[str, str]:
    """Versions of the packages an image depends on (for the EXR header)."""
    return dict(_software_versions())  # a copy: the caller may change it


@functools.lru_cache(maxsize=1)
def _software_versions():
    # looked up once per process (12 to 17 ms each time; C&T Fig. 7 writes 39 images)
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for name in ("reflectance", "numpy", "scipy", "colour-science", "vtk", "pyvista", "OpenEXR"):
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = "unknown"
    return out


def write_render(result: RenderResult, exr_path: str | os.PathLike[str] | None = None,
                 png_path: str | os.PathLike[str] | None = None,
                 rgb_exr_path: str | os.PathLike[str] | None = None,
                 exposure: float | None = None) -> tuple[npt.NDArray[np.float64], float]:
    """Write the linear XYZ image (EXR), the display PNG and the display-referred linear RGB EXR,
    each if its path is given (at least one), atomically: all files or none.

    The XYZ EXR header holds the validated scene (``scene``, JSON), its file (``scene_file``), the
    display exposure scale, the visibility statistics and the package versions (``software``).
    The PNG is tagged with its display space (:func:`reflectance.colour.display.display_tag`:
    the sRGB chunk, or an ICC profile for SMPTE-C). The RGB EXR holds
    :func:`display_linear_RGB` with channels R, G, B and the display's ``chromaticities`` (the
    same header attributes). ``exposure`` overrides the automatic exposure (a factor on XYZ).
    Every image is computed before any file is written. Returns the display image and its
    exposure scale (:func:`display_image`).
    """
    from reflectance.colour.display import display_tag
    from reflectance.io.images import write_exr_RGB

    if exr_path is None and png_path is None and rgb_exr_path is None:
        raise ValueError("write_render: give at least one of exr_path, png_path, rgb_exr_path")
    scene = result.scene
    rgb, scale = display_image(result, exposure)  # (banded: small temporaries at any size)
    linear = None if rgb_exr_path is None else display_linear_RGB(result, exposure)[0]
    tag = display_tag(scene.display.space)
    attributes = {
        "scene": scene.to_json(),
        "scene_file": str(scene.source),
        "display_exposure_scale": float(scale),
        "visibility_stats": json.dumps(result.stats, sort_keys=True),
        "software": json.dumps(software_versions(), sort_keys=True),
    }
    # every file is written to a temporary file first and moved into place only when all
    # succeeded: a failed PNG leaves no EXR (and no earlier file is replaced)
    with contextlib.ExitStack() as stack:
        tmp = {key: stack.enter_context(atomic_write(path))
               for key, path in (("exr", exr_path), ("png", png_path), ("rgb", rgb_exr_path))
               if path is not None}
        if "exr" in tmp:
            write_exr_XYZ(tmp["exr"], result.XYZ, attributes)
        if "rgb" in tmp:
            write_exr_RGB(tmp["rgb"], linear, tag, attributes)  # type: ignore[arg-type]  # with rgb
        if "png" in tmp:
            write_png(tmp["png"], rgb, bit_depth=scene.display.png_bit_depth, tag=tag)
    return rgb, scale


def write_linear_RGB_from_XYZ(exr_path: str | os.PathLike[str], scene_path: str | os.PathLike[str],
                              rgb_exr_path: str | os.PathLike[str],
                              spectra_dir: SpectraDirs = None) -> None:
    """Write the display-referred linear RGB EXR of a rendered XYZ EXR (:func:`write_render`'s)
    and its scene file, exposed as the render was (the header's ``display_exposure_scale``).

    The same as rendering with ``rgb_exr_path`` except that the XYZ come from the file (float32,
    not the render's float64): the RGB agree to float32 rounding.
    """
    from reflectance.io.images import read_exr
    from reflectance.render.scene import load_scene

    XYZ, header = read_exr(exr_path)
    for key in ("display_exposure_scale", "visibility_stats"):
        if key not in header:
            raise ValueError(f"{exr_path}: no {key!r} attribute: not an EXR written by a render")
    scene = load_scene(scene_path, spectra_dir=spectra_dir)
    if XYZ.shape[:2] != (scene.camera.height, scene.camera.width):
        raise ValueError(f"{exr_path}: {XYZ.shape[1]} x {XYZ.shape[0]} pixels, but its scene "
                         f"{scene_path} renders {scene.camera.width} x {scene.camera.height}")
    result = RenderResult(XYZ.astype(np.float64), None, {}, json.loads(header["visibility_stats"]),
                          scene)
    write_render(result, rgb_exr_path=rgb_exr_path,
                 exposure=float(header["display_exposure_scale"]))


def render_to_files(scene: Scene, scene_path: str | os.PathLike[str],
                    exr_path: str | os.PathLike[str],
                    png_path: str | os.PathLike[str] | None = None, components: bool = False,
                    rgb_exr_path: str | os.PathLike[str] | None = None,
                    keep_trace: bool = False) -> RenderResult:
    """Write the scene file, render it and write its EXR (and PNG, and linear RGB EXR); return
    the result.

    What every rendered figure does, in one place: the scene written beside the images can be
    rendered again alone with ``reflectance render``. ``keep_trace``: as in :func:`render`. The
    result keeps the display image written (:attr:`RenderResult.display`).
    """
    from reflectance.render.scene import write_scene_file

    write_scene_file(scene, scene_path)
    result = render(scene, components=components, keep_trace=keep_trace)
    result.display = write_render(result, exr_path, png_path, rgb_exr_path)
    return result


def _check_finite(image, scene):
    """Refuse an image with values that are not finite (a material's or light's numbers that
    overflow the shading), naming the scene and the first such pixel (issue 25)."""
    bad = ~np.isfinite(image).all(axis=-1)
    if bad.any():
        row, column = (int(v[0]) for v in np.nonzero(bad))
        raise ValueError(f"{scene.source}: the render is not finite at {int(bad.sum())} pixels "
                         f"(first at row {row}, column {column}): a material's or light's "
                         f"numbers overflow the shading")
