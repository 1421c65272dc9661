"""Render a scene: visibility, cast shadows, spectral shading, box filter; EXR and display PNG.

:func:`render` runs the steps on a :class:`reflectance.render.scene.Scene`:

1. :func:`trace`: which surface each camera sample sees (:func:`reflectance.render.visibility.visibility`,
   VTK ID buffer + exact float64 hits) and which lights each sample sees
   (:func:`reflectance.render.visibility.shadow_masks`);
2. :func:`shade_samples`: every object's samples shaded with its material
   (:func:`reflectance.render.shading.shade`), background black;
3. the n x n samples of each pixel averaged in linear XYZ (box filter,
   :meth:`reflectance.render.visibility.SurfaceSamples.to_pixels`).
4. with the scene's adaptive supersampling on (``camera.adaptive``,
   :mod:`reflectance.render.adaptive`): the pixels on a silhouette or whose shading curves
   within them are traced, shaded and box-filtered again on a finer N x N grid, in bands.

An image of more than :data:`~reflectance.render.camera.SINGLE_TILE_SAMPLES` samples runs
these steps band by band of pixel rows (:func:`tiles`), each band at most
:data:`~reflectance.render.camera.TILE_SAMPLES` samples, so that memory does not grow with the
image beyond the image itself. Every sample is traced and shaded as in one
pass (the same rays, the same exact tests); only the light maps that propose occluders are
drawn per band (over that band's samples, at the whole image's map size).

:func:`write_render` writes the linear XYZ image as OpenEXR (the validated scene and the package
versions in its header) and, optionally, the display PNG (Cook & Torrance exposure over the image,
gamut clipping, transfer function: :mod:`reflectance.colour.exposure`). Everything is
deterministic: the same scene gives byte-identical files.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import json
import time
from dataclasses import dataclass, field

import numpy as np

from reflectance.colour.exposure import exposure_scale, image_display_RGB
from reflectance.io.atomic import atomic_write
from reflectance.io.cache import TRACES
from reflectance.io.images import write_exr_XYZ, write_png
from reflectance.render.adaptive import pixel_spread, refine_mask, refinement_bands
from reflectance.render.camera import SINGLE_TILE_SAMPLES, TILE_SAMPLES
from reflectance.render.idbuffer import IdRenderer
from reflectance.render.parallel import Tasks, render_threads
from reflectance.render.primitives import Primitives
from reflectance.render.shading import shade, white_card_luminance
from reflectance.render.shadows import shadow_masks
from reflectance.render.visibility import visibility

__all__ = [
    "render_to_files",
    "COMPONENTS",
    "RenderResult",
    "trace",
    "trace_key",
    "trace_once",
    "tiles",
    "shade_samples",
    "render",
    "display_image",
    "display_linear_RGB",
    "write_linear_RGB_from_XYZ",
    "software_versions",
    "write_render",
    "render_warnings",
    "BACK_FRACTION_WARNING",
]

COMPONENTS = ("ambient", "diffuse", "specular", "emission")
"""Parts of the reflected XYZ a render can return separately (table shading)."""


@dataclass
class RenderResult:
    """A rendered image.

    Attributes
    ----------
    XYZ : ndarray, shape (height, width, 3)
        Linear CIE XYZ (a light's white has Y = intensity; background 0).
    components : dict or None
        ``{name: (height, width, 3)}`` for :data:`COMPONENTS` when asked for.
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
    scene: object = field(repr=False)
    refined: np.ndarray | None = field(default=None, repr=False)
    display: tuple | None = field(default=None, repr=False)


# SINGLE_TILE_SAMPLES and TILE_SAMPLES come from reflectance.render.camera; tiles() reads them
# as this module's names (which tests patch)


def tiles(camera, single=None, tile=None):
    """Bands ``(start, stop)`` of rows of the camera's fine grid that :func:`render` traces one
    at a time: the whole grid if it has at most ``single`` samples (default
    :data:`~reflectance.render.camera.SINGLE_TILE_SAMPLES`), else bands of whole pixel rows of at
    most ``tile`` samples (default :data:`~reflectance.render.camera.TILE_SAMPLES`; at least one
    pixel row)."""
    single = SINGLE_TILE_SAMPLES if single is None else int(single)
    tile = TILE_SAMPLES if tile is None else int(tile)
    rows, cols = camera.shape
    if rows * cols <= single:
        return [(0, rows)]
    n = camera.supersample
    step = max(n, tile // cols // n * n)
    return [(start, min(start + step, rows)) for start in range(0, rows, step)]


def _map_size(camera, rows=None):
    """Light-map side: what :func:`shadow_masks` picks for the whole grid, and for a band of
    ``rows`` that side scaled by twice the square root of the band's share of the samples (the
    band's samples cover about that share of the whole map; twice as fine again, as a margin),
    at least 256 and at most the whole grid's."""
    whole = int(np.clip(max(camera.shape), 256, 4096))
    if rows is None or (rows[0], rows[1]) == (0, camera.shape[0]):
        return whole
    share = (rows[1] - rows[0]) / camera.shape[0]
    return int(np.clip(round(2.0 * whole * np.sqrt(share)), 256, whole))


def _silent(phase):
    pass


def trace(scene, rows=None, primitives=None, progress=None, select=None, map_size=None,
          renderer=None, threads=1):
    """(samples, shadowed, timings): camera visibility and each light's shadow mask, of the
    whole image or of the band ``rows`` of the fine grid (:func:`tiles`); ``primitives``
    (:class:`reflectance.render.primitives.Primitives` of ``scene.mesh``) are reused if given.

    ``select`` traces only those samples of the band (``visibility``'s); ``map_size`` sets the
    light maps' side (default: from the band's share of the grid). ``progress``, if given, is
    called with the name of each phase as it starts. ``renderer``, an open
    :class:`reflectance.render.idbuffer.IdRenderer` of ``primitives``, draws the camera's and the
    lights' ID buffers (one window, the scene uploaded once); default one per phase.
    ``threads``: of the per-sample work (:mod:`reflectance.render.parallel`; the same result at
    any count)."""
    progress = progress or _silent
    t0 = time.perf_counter()
    progress("visibility")
    samples = visibility(scene.mesh if primitives is None else primitives, scene.camera, rows,
                         select, renderer, threads)
    t1 = time.perf_counter()
    progress("shadows")
    if scene.shadows and scene.lights:
        shadowed = shadow_masks(samples, scene.mesh, [light.source for light in scene.lights],
                                map_size or _map_size(scene.camera, rows), renderer, threads)
    else:
        shadowed = np.zeros((len(scene.lights), len(samples.hit)), bool)
    t2 = time.perf_counter()
    return samples, shadowed, {"visibility": t1 - t0, "shadows": t2 - t1}


def shade_samples(scene, samples, shadowed, spectral=None, components=False, fresnel_table=None,
                  threads=1):
    """Per-sample XYZ (N, 3) of every object (and the parts, with ``components=True``);
    ``threads`` as for :func:`reflectance.render.shading.shade`."""
    spectral = scene.spectral if spectral is None else spectral
    N = len(samples.hit)
    XYZ = np.zeros((N, 3))
    parts = {name: np.zeros((N, 3)) for name in COMPONENTS} if components else None
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
            if components:
                out, got = out
                for name in COMPONENTS:
                    if name in got:
                        parts[name][idx] = got[name]
            XYZ[idx] = out
    return (XYZ, parts) if components else XYZ


def trace_key(scene, rows=None):
    """What :func:`trace` depends on, as a SHA-256 hex digest: the composed mesh (points, faces,
    every point and cell array), the camera, the lights' directions or positions, whether shadows
    are cast, and the band of rows (None: the whole grid, the same trace as its one band). Two
    scenes with the same key are traced identically (the trace never looks at materials,
    spectra, intensities or the ambient term)."""
    rows = (0, scene.camera.shape[0]) if rows is None else (int(rows[0]), int(rows[1]))
    digest = hashlib.sha256()
    mesh = scene.mesh
    arrays = [("points", mesh.points), ("faces", mesh.faces)]
    arrays += [(f"point_data.{name}", mesh.point_data[name]) for name in sorted(mesh.point_data)]
    arrays += [(f"cell_data.{name}", mesh.cell_data[name]) for name in sorted(mesh.cell_data)]
    for name, array in arrays:
        array = np.ascontiguousarray(array)
        digest.update(f"{name} {array.dtype.str} {array.shape}\n".encode())
        digest.update(array.tobytes())
    digest.update(repr((scene.camera, [light.source for light in scene.lights], bool(scene.shadows),
                        rows)).encode())
    return digest.hexdigest()


def trace_once(scene, keep=True, rows=None, tools=None, progress=None, threads=1):
    """:func:`trace` of ``scene`` (the band ``rows``; None: the whole grid), or, with ``keep``,
    the one the process's trace memo (:data:`reflectance.io.cache.TRACES`) keeps under its
    :func:`trace_key`, for scenes that differ only in what the trace does not look at (a new
    trace is kept there). Images of several bands (:func:`tiles`) are not kept (memory).
    ``tools``, if given, is called only when a trace is needed and returns ``(primitives,
    renderer)`` for :func:`trace`. Returns ``(samples, shadowed, timings)``, zero timings for a
    kept trace; ``threads`` as for :func:`trace`."""
    timings = {"visibility": 0.0, "shadows": 0.0}

    def traced():
        primitives, renderer = tools() if tools is not None else (None, None)
        samples, shadowed, t = trace(scene, rows, primitives, progress, renderer=renderer,
                                     threads=threads)
        timings.update(t)
        return samples, shadowed

    if keep and len(tiles(scene.camera)) == 1:
        samples, shadowed = TRACES.get(trace_key(scene, rows), traced)
    else:
        samples, shadowed = traced()
    return samples, shadowed, timings


def render(scene, spectral=None, components=False, fresnel_table=None, progress=None,
           keep_trace=False, threads=None):
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
        starts (e.g. :meth:`reflectance.io.progress.Progress.update` through a small adapter).
    keep_trace : bool
        Look the trace up in the process's trace memo (:func:`trace_once`), and keep it there,
        for renders of scenes that differ only in what :func:`trace` does not look at
        (materials, spectra, intensities, ambient: Cook & Torrance's Fig. 7 vases): an image
        traced in one band is traced once; the result is the same, bit for bit. Images of
        several bands are not kept (memory).
    threads : int, optional
        Threads of the per-sample work (:func:`reflectance.render.parallel.render_threads`:
        default the environment variable ``REFLECTANCE_RENDER_THREADS``, else
        ``OMP_NUM_THREADS``, else the cores this process may use; 1 is the serial path). The
        image is the same, bit for bit, at any count.
    """
    spectral = scene.spectral if spectral is None else spectral
    if components and spectral != "table":
        raise ValueError("components are available with spectral='table' only")
    threads = render_threads(threads)
    t0 = time.perf_counter()
    camera, n_ss = scene.camera, scene.camera.supersample
    bands = tiles(camera)
    image = np.zeros((camera.height, camera.width, 3))
    parts = {name: np.zeros_like(image) for name in COMPONENTS} if components else None
    timings = {"visibility": 0.0, "shadows": 0.0, "shading": 0.0}
    count = _Counts(len(scene.lights), len(scene.objects))
    refinement = getattr(scene, "refinement", None)
    adaptive = (refinement is not None and refinement.enabled
                and refinement.supersample > n_ss)
    if adaptive:  # per pixel of the first pass: its window's difference and silhouettes
        from reflectance.colour.colorimetry import white_XYZ

        difference = np.zeros((camera.height, camera.width, 3), np.float32)
        silhouette = np.zeros((camera.height, camera.width), bool)
    # the scene's primitives and one ID-buffer window for all of them (the camera's and the
    # light maps of every band), made on the first band that is traced (not for a cached trace)
    made = {}
    with contextlib.ExitStack() as stack:

        def tools():
            if not made:
                made["primitives"] = Primitives(scene.mesh)
                if threads > 1 and scene.shadows and scene.lights:  # the shadow walks' edge
                    # table, made on a worker while the camera's rays are traced
                    edges = Tasks(threads)
                    edges.submit(lambda: made["primitives"].neighbours)
                    stack.callback(edges.results)  # awaited (and its error raised) at the end
                made["renderer"] = stack.enter_context(IdRenderer(made["primitives"]))
            return made["primitives"], made["renderer"]

        for start, stop in bands:
            where = "" if len(bands) == 1 else f"rows {start // n_ss}-{stop // n_ss}: "
            samples, shadowed, t = trace_once(
                scene, keep_trace, (start, stop), tools,
                progress and (lambda phase: progress(where + phase)), threads)
            t1 = time.perf_counter()
            (progress or _silent)(where + "shading")
            shaded = shade_samples(scene, samples, shadowed, spectral, components, fresnel_table,
                                   threads)
            XYZ, got = shaded if components else (shaded, None)
            rows = slice(start // n_ss, stop // n_ss)
            image[rows] = samples.to_pixels(XYZ, threads)
            if components:
                for name, value in got.items():
                    parts[name][rows] = samples.to_pixels(value, threads)
            if adaptive:
                difference[rows], silhouette[rows] = pixel_spread(samples, XYZ)
            count.add(samples, shadowed)
            del samples, shadowed, shaded, XYZ, got
            timings["visibility"] += t["visibility"]
            timings["shadows"] += t["shadows"]
            timings["shading"] += time.perf_counter() - t1
        stats = count.stats()
        refined, mask = 0, None
        if adaptive:
            t1 = time.perf_counter()
            white = white_XYZ(scene.display.illuminant, scene.observer, scene.wavelengths)
            mask = refine_mask(difference, silhouette, image, exposure_scale(image, *_shown(scene)),
                               refinement.threshold, white)
            del difference, silhouette
            refined = _refine(scene, tools, mask, image, parts, spectral, components,
                              fresnel_table, timings, progress, threads)
            timings["refinement"] = time.perf_counter() - t1
    pixels = camera.height * camera.width
    # the sample budget: every pixel's n x n, and N x N more in each refined pixel
    stats.update(refined=refined / pixels, samples_per_pixel=n_ss**2 + (
        refined * refinement.supersample**2 / pixels if adaptive else 0.0))
    timings["total"] = time.perf_counter() - t0
    return RenderResult(image, parts, timings, stats, scene, mask)


def _refine(scene, tools, mask, image, parts, spectral, components, fresnel_table,
            timings, progress, threads=1):
    """Replace the pixels of ``mask`` in ``image`` (and ``parts``) by the box-filter mean of
    their N x N samples (:mod:`reflectance.render.adaptive`); return how many were refined.
    ``tools()`` gives the scene's primitives and their ID-buffer window."""
    import dataclasses

    N = scene.refinement.supersample
    fine = dataclasses.replace(scene, camera=dataclasses.replace(scene.camera, supersample=N))
    flat = image.reshape(-1, 3)
    map_size = _map_size(scene.camera)  # the whole first pass's light maps
    refined = 0
    for rows, select, pixels in refinement_bands(mask, N):
        where = f"refining rows {rows[0] // N}-{rows[1] // N}: "
        primitives, renderer = tools()
        samples, shadowed, t = trace(fine, rows, primitives,
                                     progress and (lambda phase: progress(where + phase)),
                                     select, map_size, renderer, threads)
        t1 = time.perf_counter()
        shaded = shade_samples(scene, samples, shadowed, spectral, components, fresnel_table,
                               threads)
        XYZ, got = shaded if components else (shaded, None)
        flat[pixels] = XYZ.reshape(len(pixels), N * N, 3).mean(axis=1)
        for name, value in (got or {}).items():
            parts[name].reshape(-1, 3)[pixels] = value.reshape(len(pixels), N * N, 3).mean(axis=1)
        refined += len(pixels)
        timings["visibility"] += t["visibility"]
        timings["shadows"] += t["shadows"]
        timings["shading"] += time.perf_counter() - t1
    return refined


class _Counts:
    """Sample counts over the bands of a render, and the fractions of :attr:`RenderResult.stats`
    (the same numbers whether the image was traced in one band or several)."""

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


#: an object more than this fraction of whose visible surface is seen from the back is reported
#: as possibly enclosing the camera
BACK_FRACTION_WARNING = 0.5


def render_warnings(result):
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


def display_linear_RGB(result, exposure=None, encoded=False):
    """(linear display RGB in [0, 1] of shape (H, W, 3), exposure scale) per the scene's display:
    exposed, highlights compressed, gamut clipped; the light the display emits, before the
    transfer function (:func:`reflectance.colour.exposure.image_display_RGB`, in bands of rows).

    ``exposure`` (a positive factor on XYZ) replaces the automatic exposure of the scene's
    display settings (Cook & Torrance's, the metered key or the white card); None keeps it.
    ``encoded`` applies the display's transfer function too (:func:`display_image`).
    """
    return image_display_RGB(result.XYZ, *_shown(result.scene), exposure=exposure,
                             encoded=encoded)


def display_image(result, exposure=None):
    """(encoded RGB in [0, 1] of shape (H, W, 3), exposure scale) per the scene's display (as
    :func:`reflectance.colour.display.XYZ_to_display`; ``exposure`` as for
    :func:`display_linear_RGB`)."""
    return display_linear_RGB(result, exposure, encoded=True)


def software_versions():
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


def write_render(result, exr_path=None, png_path=None, rgb_exr_path=None, exposure=None):
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
            write_exr_RGB(tmp["rgb"], linear, tag, attributes)
        if "png" in tmp:
            write_png(tmp["png"], rgb, bit_depth=scene.display.png_bit_depth, tag=tag)
    return rgb, scale


def write_linear_RGB_from_XYZ(exr_path, scene_path, rgb_exr_path, spectra_dir=None):
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


def render_to_files(scene, scene_path, exr_path, png_path=None, components=False,
                    rgb_exr_path=None, keep_trace=False):
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
