"""Render a scene: visibility, cast shadows, spectral shading, box filter; EXR and display PNG.

:func:`render` runs the steps on a :class:`reflectance.render.scene.Scene`:

1. :func:`trace`: which surface each camera sample sees (:func:`reflectance.render.visibility.visibility`,
   VTK ID buffer + exact float64 hits) and which lights each sample sees
   (:func:`reflectance.render.visibility.shadow_masks`);
2. :func:`shade_samples`: every object's samples shaded with its material
   (:func:`reflectance.render.shading.shade`), background black;
3. the n x n samples of each pixel averaged in linear XYZ (box filter,
   :meth:`reflectance.render.visibility.SurfaceSamples.to_pixels`).

:func:`write_render` writes the linear XYZ image as OpenEXR (the validated scene and the package
versions in its header) and, optionally, the display PNG (Cook & Torrance exposure over the image,
gamut clipping, transfer function: :mod:`reflectance.colour.display`). Everything is deterministic: the
same scene gives byte-identical files.
"""

from __future__ import annotations

import contextlib
import json
import time
from dataclasses import dataclass, field

import numpy as np

from reflectance.colour.display import expose_CookTorrance1982, expose_key
from reflectance.io.atomic import atomic_write
from reflectance.io.images import write_exr_XYZ, write_png
from reflectance.render.shading import shade
from reflectance.render.shadows import shadow_masks
from reflectance.render.visibility import visibility

__all__ = [
    "render_to_files",
    "COMPONENTS",
    "RenderResult",
    "trace",
    "shade_samples",
    "render",
    "display_image",
    "display_linear_RGB",
    "write_linear_RGB_from_XYZ",
    "software_versions",
    "write_render",
    "render_warnings",
    "BACK_FRACTION_WARNING",
    "image_difference_CIEDE2000",
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
        Wall seconds of ``visibility``, ``shadows``, ``shading`` and ``total``.
    stats : dict
        Visibility statistics, the fraction of samples hit and the fraction of hit samples in
        each light's shadow.
    scene : Scene
    """

    XYZ: np.ndarray
    components: dict | None
    timings: dict
    stats: dict
    scene: object = field(repr=False)


def _silent(phase):
    pass


def trace(scene, progress=None):
    """(samples, shadowed, timings): camera visibility and each light's shadow mask.

    ``progress``, if given, is called with the name of each phase as it starts."""
    progress = progress or _silent
    t0 = time.perf_counter()
    progress("visibility")
    samples = visibility(scene.mesh, scene.camera)
    t1 = time.perf_counter()
    progress("shadows")
    if scene.shadows and scene.lights:
        shadowed = shadow_masks(samples, scene.mesh, [light.source for light in scene.lights])
    else:
        shadowed = np.zeros((len(scene.lights), len(samples.hit)), bool)
    t2 = time.perf_counter()
    return samples, shadowed, {"visibility": t1 - t0, "shadows": t2 - t1}


def shade_samples(scene, samples, shadowed, spectral=None, components=False):
    """Per-sample XYZ (N, 3) of every object (and the parts, with ``components=True``)."""
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
                        scene.table_size, components=components)
            if components:
                out, got = out
                for name in COMPONENTS:
                    if name in got:
                        parts[name][idx] = got[name]
            XYZ[idx] = out
    return (XYZ, parts) if components else XYZ


def render(scene, spectral=None, components=False, progress=None):
    """Render a :class:`reflectance.render.scene.Scene` into a :class:`RenderResult`.

    Parameters
    ----------
    scene : Scene
    spectral : str, optional
        Overrides ``scene.spectral`` (``"table"`` or ``"brute-force"``).
    components : bool
        Also return the ambient, diffuse, specular and emitted parts (table shading only).
    progress : callable, optional
        Called with the name of each phase (``"visibility"``, ``"shadows"``, ``"shading"``) as it
        starts (e.g. :meth:`reflectance.io.progress.Progress.update` through a small adapter).
    """
    spectral = scene.spectral if spectral is None else spectral
    if components and spectral != "table":
        raise ValueError("components are available with spectral='table' only")
    t0 = time.perf_counter()
    samples, shadowed, timings = trace(scene, progress)
    t1 = time.perf_counter()
    (progress or _silent)("shading")
    shaded = shade_samples(scene, samples, shadowed, spectral, components)
    XYZ, parts = shaded if components else (shaded, None)
    image = samples.to_pixels(XYZ)
    if components:
        parts = {name: samples.to_pixels(value) for name, value in parts.items()}
    t2 = time.perf_counter()
    timings.update(shading=t2 - t1, total=t2 - t0)
    hit = samples.hit
    stats = dict(samples.stats, hit=float(hit.mean()),
                 shadowed=[float(s[hit].mean()) if hit.any() else 0.0 for s in shadowed],
                 seen_from_back=_seen_from_back(scene, samples))
    return RenderResult(image, parts, timings, stats, scene)


def _seen_from_back(scene, samples):
    """Per object: the fraction of its visible samples seen from the back of the surface (None
    where it is not visible)."""
    fractions = []
    for i in range(len(scene.objects)):
        mine = samples.hit & (samples.object_id == i)
        fractions.append(float(samples.flipped[mine].mean()) if mine.any() else None)
    return fractions


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


def display_linear_RGB(result, exposure=None):
    """(linear display RGB in [0, 1] of shape (H, W, 3), exposure scale) per the scene's display:
    exposed, highlights compressed, gamut clipped; the light the display emits, before the
    transfer function.

    ``exposure`` (a positive factor on XYZ) replaces the automatic exposure of the scene's
    display settings (Cook & Torrance's, or the metered key); None keeps it.
    """
    from reflectance.colour.display import XYZ_to_linear_RGB, compress_highlights, gamut_clip

    scene, d = result.scene, result.scene.display
    kwargs = {"illuminant": d.illuminant, "observer": scene.observer,
              "wavelengths": scene.wavelengths}
    XYZ, scale = result.XYZ, 1.0
    if exposure is not None:
        if isinstance(exposure, bool) or not np.isfinite(exposure) or exposure <= 0:
            raise ValueError(f"exposure: must be a positive finite factor, got {exposure!r}")
        XYZ, scale = XYZ * float(exposure), float(exposure)
    elif d.expose and d.key is not None:
        XYZ, scale = expose_key(XYZ, *d.key)  # the object metered, highlights compressed
    elif d.expose:
        # Cook & Torrance 1982: all XYZ of the scene scaled equally, the most luminous colour
        # at the maximum luminance of its chromaticity
        XYZ, scale = expose_CookTorrance1982(XYZ, d.space, **kwargs)
    RGB = XYZ_to_linear_RGB(XYZ, d.space, **kwargs)
    if d.highlight_knee is not None:
        RGB = compress_highlights(RGB, d.highlight_knee)
    return gamut_clip(RGB, d.gamut_clip, d.space), scale


def display_image(result, exposure=None):
    """(encoded RGB in [0, 1] of shape (H, W, 3), exposure scale) per the scene's display (as
    :func:`reflectance.colour.display.XYZ_to_display`; ``exposure`` as for
    :func:`display_linear_RGB`)."""
    from reflectance.colour.display import encode

    RGB, scale = display_linear_RGB(result, exposure)
    return encode(RGB, result.scene.display.space), scale


def software_versions():
    """Versions of the packages an image depends on (for the EXR header)."""
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
    Every image is computed before any file is written.
    """
    from reflectance.colour.display import display_tag, encode
    from reflectance.io.images import write_exr_RGB

    if exr_path is None and png_path is None and rgb_exr_path is None:
        raise ValueError("write_render: give at least one of exr_path, png_path, rgb_exr_path")
    scene = result.scene
    linear, scale = display_linear_RGB(result, exposure)
    rgb = encode(linear, scene.display.space)
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


def image_difference_CIEDE2000(XYZ, XYZ_reference, illuminant="D65", observer=None,
                               wavelengths=None):
    """(mean, max) CIEDE2000 of two XYZ images on the reference's Cook & Torrance exposure.

    Both images are scaled by the exposure of ``XYZ_reference`` (so that its brightest colour
    sits at the display maximum, as it would be shown), then compared in CIELAB relative to the
    illuminant's white (Y = 1). The mean is over the pixels where either image is not black.
    """
    from reflectance.colour.colorimetry import OBSERVER_DEFAULT, XYZ_to_Lab, white_XYZ
    from reflectance.colour.difference import delta_E_CIE2000

    observer = observer or OBSERVER_DEFAULT
    _, scale = expose_CookTorrance1982(XYZ_reference, "sRGB", illuminant, observer, wavelengths)
    white = white_XYZ(illuminant, observer, wavelengths)
    xy = white[:2] / white.sum()
    lab = [XYZ_to_Lab(np.asarray(x, np.float64) * scale, xy) for x in (XYZ, XYZ_reference)]
    dE = delta_E_CIE2000(lab[0], lab[1])
    lit = (np.asarray(XYZ)[..., 1] > 0) | (np.asarray(XYZ_reference)[..., 1] > 0)
    if not lit.any():
        return 0.0, 0.0
    return float(dE[lit].mean()), float(dE[lit].max())


def render_to_files(scene, scene_path, exr_path, png_path=None, components=False,
                    rgb_exr_path=None):
    """Write the scene file, render it and write its EXR (and PNG, and linear RGB EXR); return
    the result.

    What every rendered figure does, in one place: the scene written beside the images can be
    rendered again alone with ``reflectance render``.
    """
    from reflectance.render.scene import write_scene_file

    write_scene_file(scene, scene_path)
    result = render(scene, components=components)
    write_render(result, exr_path, png_path, rgb_exr_path)
    return result
