"""How much memory a render takes, estimated from its size before it starts.

:func:`render_memory_bytes` (the figures' renders in config.yaml, a scene file's camera and the
command line's overrides): measured peaks of ``reflectance render``, a line through them in the
number of samples (one pass) or of pixels (bands), plus adaptive refinement and the mesh.
"""

from __future__ import annotations

from reflectance.io.limits import physical_memory_bytes

__all__ = ["RENDER_PEAK_MEMORY", "ADAPTIVE_PEAK_MEMORY", "MESH_ELEMENTS_PER_VERTEX",
           "render_memory_bytes", "render_size_problem"]

#: Peak resident memory (bytes) of ``reflectance render`` of the Fig. 6b vase, square (side in
#: pixels), 2 x 2 samples per pixel, two lights, its EXR and PNG written: VTK, the mesh and the
#: images included (workflow/docs/guides/rendering.rst, "Memory at large sizes"; measured 2026-12-02 with ``/usr/bin/time``).
RENDER_PEAK_MEMORY = {256: 606904 * 2**10, 512: 835764 * 2**10, 1024: 855748 * 2**10,
                      2048: 1142600 * 2**10, 4096: 1557504 * 2**10}

#: Peak resident memory (bytes) of the same renders of ``workflow/scenes/bench_hard.yaml`` with
#: its adaptive refinement (2 x 2, refined to 8 x 8) against without it, side -> extra bytes:
#: measured 2026-12-05 with ``/usr/bin/time`` (CHANGELOG), and at 4096 px issue 25's report of
#: an adaptive Fig. 6 that grew past 6 GB where the estimate without refinement said 1.49 GiB.
ADAPTIVE_PEAK_MEMORY = {512: (1223180 - 835764) * 2**10, 1024: (1455744 - 855748) * 2**10,
                        2048: (1932796 - 1142600) * 2**10, 4096: 6e9 - 1557504 * 2**10}


#: A mesh's cost per vertex in :data:`reflectance.io.limits.ELEMENT_BYTES` elements: a 256 px
#: render of a vase of 2.1 million vertices peaked 4.1 GiB above one of 0.11 million (2215 bytes
#: per vertex: the mesh, its normals, VTK's copies, the flat primitives; measured 2026-12-05,
#: CHANGELOG), rounded up.
MESH_ELEMENTS_PER_VERTEX = 36


def render_memory_bytes(width: int, height: int, supersample: int, whole: bool = False,
                        adaptive: bool = False) -> float:
    """Estimated peak memory (bytes) of rendering an image of this size and writing it.

    An image of at most :data:`~reflectance.render.camera.SINGLE_TILE_SAMPLES` samples is traced
    in one pass, and its per-sample arrays (ID buffer, float64 positions, normals, the shadow
    pass's candidates) set the peak: a line in the number of samples through the measured 256
    and 512 px peaks (:data:`RENDER_PEAK_MEMORY`; 0.51 GiB fixed, 298 bytes per sample); so is
    any image of a figure that traces it ``whole`` besides its render (C&T Fig. 8's part table,
    Blinn's light sweep). A larger image is traced in bands of at most
    :data:`~reflectance.render.camera.TILE_SAMPLES` samples, so what grows is the image itself
    (XYZ, display, EXR and PNG buffers): a line in the number of pixels through the 2048 and
    4096 px peaks (0.96 GiB fixed, 34 bytes per pixel), and never below the one-pass line at its
    largest image, so that the estimate grows with the image across the two (it over-estimates
    the 1024 px peak: 1.09 against 0.82 GiB).

    With ``adaptive`` refinement (the camera's ``adaptive.enabled`` with more samples than its
    own), the refinement's bands and whole-image masks add a line in the number of pixels
    through the 1024 px and 4096 px extra (:data:`ADAPTIVE_PEAK_MEMORY`: 0.57 GiB, then 241
    bytes per pixel), never below the 512 px extra: the most that was seen (it over-estimates the
    2048 px extra, 1.27 against 0.74 GiB).
    """
    from reflectance.render.camera import SINGLE_TILE_SAMPLES

    def line(x0, m0, x1, m1, x):
        return m0 + (m1 - m0) * (x - x0) / (x1 - x0)

    def one_pass(samples):
        return line(256**2 * 4, m[256], 512**2 * 4, m[512], samples)

    m, pixels = RENDER_PEAK_MEMORY, width * height
    samples = pixels * supersample**2
    if whole or samples <= SINGLE_TILE_SAMPLES:
        need = one_pass(samples)
    else:
        need = max(one_pass(SINGLE_TILE_SAMPLES), line(2048**2, m[2048], 4096**2, m[4096],
                                                        pixels))
    if adaptive:
        a = ADAPTIVE_PEAK_MEMORY
        need += max(a[512], line(1024**2, a[1024], 4096**2, a[4096], pixels))
    return need


def render_size_problem(keys: str, width: int, height: int, supersample: int, whole: bool = False,
                        adaptive: bool = False, memory: float | None = None) -> str | None:
    """One line naming ``keys`` if the render cannot fit in ``memory`` bytes (default: this
    machine's physical memory) or its ID buffer exceeds
    :data:`~reflectance.render.camera.MAX_BUFFER_SIDE`; else None."""
    from reflectance.render.camera import MAX_BUFFER_SIDE

    memory = physical_memory_bytes() if memory is None else memory
    if max(width, height) * supersample > MAX_BUFFER_SIDE:
        return (f"{keys}: the ID buffer would be {width * supersample} x {height * supersample} "
                f"pixels; at most {MAX_BUFFER_SIDE} per side: lower the size or supersample")
    need = render_memory_bytes(width, height, supersample, whole, adaptive)
    if memory is not None and need > memory:
        refined = " and adaptive refinement" if adaptive else ""
        return (f"{keys}: a {width} x {height} render with {supersample} x {supersample} "
                f"samples{refined} needs about {need / 2**30:.1f} GiB; this machine has "
                f"{memory / 2**30:.1f} GiB: lower the size or supersample")
    return None
