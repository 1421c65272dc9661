"""Visibility: VTK finds the surface, float64 numpy computes where exactly.

VTK rasterises an *ID buffer* off-screen (:mod:`reflectance.render.idbuffer`): every triangle of the
scene is drawn flat, unlit, without anti-aliasing or multisampling, in a colour that encodes its
index in 24 bits (0 is the background). The buffer is only used to *choose* which triangle a
sample sees; the sample's position, normal and (u, v) then come from intersecting its exact
camera ray with that triangle (Moller-Trumbore, float64), or with the exact sphere when the
triangle belongs to an analytic sphere (:func:`reflectance.geometry.shapes.sphere`). No 8-bit quantity
limits the shading.

Where the raster and the exact ray disagree (silhouettes, shared edges), the triangles of the
3 x 3 neighbouring ID pixels are tested and the nearest exact hit wins; a sample whose ray meets
none of them is background. :attr:`SurfaceSamples.stats` reports how often this happens.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.geometry.vectors import dot, normalize
from reflectance.render.camera import Camera
from reflectance.render.idbuffer import (IdRenderer, dilate, distinct_keys, key_image,
                                         neighbour_keys, renderer_for)
from reflectance.render.parallel import Tasks, pieces
from reflectance.render.primitives import Primitives
from reflectance.render.samples import SurfaceSamples

if TYPE_CHECKING:
    import pyvista as pv

__all__ = ["visibility"]


def visibility(meshes: pv.PolyData | Sequence[tuple[pv.PolyData, int]] | Primitives,
               camera: Camera, rows: tuple[int, int] | None = None,
               select: npt.ArrayLike | None = None, renderer: IdRenderer | None = None,
               threads: int | None = 1) -> SurfaceSamples:
    """Which surface each camera sample sees, with exact float64 position, normal and (u, v).

    Parameters
    ----------
    meshes : pyvista.PolyData, sequence of (mesh, object_id) or Primitives
        A scene from :func:`reflectance.geometry.shapes.compose`, the pairs to compose, or their
        :class:`reflectance.render.primitives.Primitives` (reused as they are).
    camera : Camera
    rows : (int, int), optional
        A band ``(start, stop)`` of rows of the fine grid, each a multiple of the camera's
        supersampling: only those samples are traced (a tile; the ID buffer drawn is that band
        and one row around it). Default: the whole image.
    select : array_like of int, optional
        Only these samples of the band (row-major indices on its fine grid, each at most once,
        in any order) are traced, each exactly as in the whole band (the same ray, the same
        ID buffer and candidates): the adaptive refinement's samples
        (:mod:`reflectance.render.adaptive`).
    renderer : IdRenderer, optional
        An open :class:`reflectance.render.idbuffer.IdRenderer` of these primitives to draw
        with (left open); default a new window for this call.
    threads : int or None
        Threads of the per-sample work (:mod:`reflectance.render.parallel`; None: the default
        count); the samples are the same at any count.

    Returns
    -------
    SurfaceSamples
        Of shape (stop - start, columns) for a band, (len(select), 1) for a selection (in its
        order); ``pixel`` indexes the whole image.

    Examples
    --------
    >>> from reflectance.geometry.shapes import sphere
    >>> cam = Camera((0, 0, 5), (0, 0, 0), (0, 1, 0), 30.0, 8, 8)
    >>> s = visibility([(sphere((0, 0, 0), 1.0, 32, 16), 1)], cam)
    >>> bool(s.hit[s.pixel == 3 * 8 + 4][0]), bool(s.hit[0])
    (True, False)
    """
    if not isinstance(camera, Camera):
        raise ValueError(f"camera must be a Camera, got {type(camera).__name__}")
    scene = meshes if isinstance(meshes, Primitives) else Primitives(meshes)
    view = camera.view()
    height, cols = camera.shape
    start, stop = (0, height) if rows is None else (int(rows[0]), int(rows[1]))
    n_ss = camera.supersample
    if not (0 <= start < stop <= height and start % n_ss == 0 and stop % n_ss == 0):
        raise ValueError(f"rows {start}..{stop} are not a band of whole pixels of the "
                         f"{height}-row sample grid")
    tasks = Tasks(threads)
    if select is None:  # the camera rays, on a worker while VTK draws the ID buffer
        N = (stop - start) * cols
        tasks.submit(view.pixel_rays, start, stop)
    else:  # the rays through the selected samples' centres, as pixel_rays makes them
        select = np.asarray(select, np.int64)
        N = len(select)
        tasks.submit(view.rays, select % cols + 0.5, select // cols + start + 0.5)
    # the ID buffer of the band and one row around it (the 3 x 3 neighbourhoods below)
    top, bottom = max(start - 1, 0), min(stop + 1, height)
    with renderer_for(scene, renderer) as ids:
        keys = key_image(scene, ids.render(
            view if (top, bottom) == (0, height) else view.band(top, bottom)))
    raster = keys[start - top:stop - top].ravel()
    if select is not None:
        raster = raster[select]
    [(eye, d)] = tasks.results()
    where = np.arange(N) if select is None else select  # position of each sample in the band
    best_t, best_key = np.full(N, np.inf), np.full(N, -1, np.int32)
    barycentric = np.zeros((N, 2))  # (b1, b2) of the best hit so far, written in place
    best_b1, best_b2 = barycentric[:, 0], barycentric[:, 1]

    def offer(sel, k):  # each sample at most once per call: the pieces write disjoint samples
        def piece(p):  # (pieces also bound the temporaries)
            sc, kc = sel[p], k[p]
            t, b1, b2, hit = scene.intersect(eye, np.take(d, sc, axis=1), kc, 0.0, np.inf)
            better = hit & (t < best_t[sc])
            s = sc[better]
            best_t[s], best_key[s], best_b1[s], best_b2[s] = (t[better], kc[better],
                                                              b1[better], b2[better])

        tasks.map(piece, pieces(len(sel), tasks.threads, _CHUNK))

    surface = np.nonzero(raster >= 0)[0]
    offer(surface, raster[surface])
    missed = surface[best_key[surface] < 0]
    del surface
    # where raster and exact rays disagree: retry with the neighbouring pixels' primitives
    beside = dilate(keys >= 0)[start - top:stop - top].ravel()
    near = np.nonzero((raster < 0) & (beside if select is None else beside[select]))[0]
    del beside
    retry = np.concatenate([missed, near])
    at = where[retry]
    candidates = distinct_keys(neighbour_keys(keys, at // cols + (start - top), at % cols),
                               raster[retry])
    del at
    del keys, raster, near
    for j in range(candidates.shape[1]):
        m = candidates[:, j] >= 0
        if m.any():
            offer(retry[m], candidates[m, j])
    del candidates
    # Last resort, still exact: a sample the raster covers whose ray meets none of the nearby
    # primitives (its true triangle is smaller than a pixel and never reached the ID buffer) is
    # tested against every primitive whose projected bounding box contains it.
    lost = missed[best_key[missed] < 0]
    if len(lost):
        _search_projected_boxes(scene, view, eye, d, lost, cols, start, best_t, best_key,
                                best_b1, best_b2, where, n_ss)
    hit = best_key >= 0
    stats = {
        "raster_miss": len(missed) / N,
        "recovered": float(np.count_nonzero(hit[retry])) / N,
        "searched": len(lost) / N,
        "dropped": float(np.count_nonzero(~hit[missed])) / N,
    }
    del retry, missed, lost
    towards_camera = np.empty((N, 3))
    np.negative(d.T, out=towards_camera)  # V = -d, sample-major
    del d
    # best_t is inf and barycentric 0 wherever nothing was hit: they are the final arrays
    return _samples(scene, camera, (start, stop), eye, towards_camera, hit, best_t, best_key,
                    barycentric, stats, select, tasks)


_CHUNK = 1 << 18  # camera rays tested at once (bounds the memory of the ray-test temporaries)


def _search_projected_boxes(scene, view, eye, d, samples, cols, first_row, best_t, best_key,
                            best_b1, best_b2, where, group=1):
    """Exact nearest hit of each sample's ray among the primitives whose screen-space bounding
    box holds the sample (updates the ``best_*`` arrays in place); sample s sits at
    ``where[s]`` of the band (row-major), whose first row is row ``first_row`` of the view.

    The samples are taken ``group`` x ``group`` cells of the grid at a time (a pixel's): the
    primitives whose boxes meet the cell are found once, and each sample's among them."""
    x, y, _ = view.project(scene.P)
    tx, ty = x[scene.T], y[scene.T]  # (3, n) corners of every triangle on the fine grid
    x0, x1, y0, y1 = tx.min(axis=0), tx.max(axis=0), ty.min(axis=0), ty.max(axis=0)
    at = where[samples]
    sx, sy = at % cols + 0.5, at // cols + first_row + 0.5
    cell = (at // cols + first_row) // group * (cols // group + 1) + at % cols // group
    order = np.argsort(cell, kind="stable")
    cuts = np.flatnonzero(np.diff(cell[order])) + 1
    for members in np.split(order, cuts):
        mx, my = sx[members], sy[members]
        box = np.nonzero((x0 <= mx.max()) & (mx.min() <= x1) & (y0 <= my.max())
                         & (my.min() <= y1))[0]
        for m in members:
            s, px, py = samples[m], sx[m], sy[m]
            near = box[(x0[box] <= px) & (px <= x1[box]) & (y0[box] <= py) & (py <= y1[box])]
            keys = np.unique(scene.key[near])
            if not len(keys):
                continue
            t, b1, b2, h = scene.intersect(eye, np.repeat(d[:, s:s + 1], len(keys), axis=1),
                                           keys, 0.0, np.inf)
            if h.any():
                j = int(np.argmin(np.where(h, t, np.inf)))
                best_t[s], best_key[s], best_b1[s], best_b2[s] = t[j], keys[j], b1[j], b2[j]


def _samples(scene, camera, band, eye, view, hit, t, key, barycentric, stats, select=None,
             tasks=None):
    """SurfaceSamples of the rows ``band`` (start, stop), or of the samples ``select`` of it,
    from the best exact hits; ``view`` (N, 3) is the unit V = -d. ``tasks``
    (:class:`reflectance.render.parallel.Tasks`) interpolate the mesh samples in pieces."""
    N = len(hit)
    position, normal, geometric = np.zeros((N, 3)), np.zeros((N, 3)), np.zeros((N, 3))
    uv = np.zeros((N, 2))
    triangle = np.full(N, -1, np.int32)

    mesh = np.nonzero(hit & (key < scene.n))[0]  # mesh triangles: barycentric interpolation

    def piece(p):  # disjoint samples; pieces bound the temporaries
        m = mesh[p]
        tri = key[m]
        triangle[m] = tri
        corner = np.take(scene.T, tri, axis=1)
        b1, b2 = barycentric[m, 0], barycentric[m, 1]
        w = ((1.0 - b1 - b2)[:, None], b1[:, None], b2[:, None])

        def blend(A):  # barycentric interpolation of a vertex attribute (rows: vertices)
            return sum(w[j] * np.take(A, corner[j], axis=0) for j in range(3))

        position[m] = blend(scene.points)
        uv[m] = blend(scene.uv_rows)
        n = blend(scene.normal_rows)
        length = np.sqrt(n[:, 0] ** 2 + n[:, 1] ** 2 + n[:, 2] ** 2)
        good = length > 1e-6
        inv = 1.0 / np.where(good, length, 1.0)
        g = np.take(scene.face_normal, tri, axis=0)
        geometric[m] = g
        n *= inv[:, None]
        normal[m] = np.where(good[:, None], n, g)

    tasks = tasks or Tasks(1)
    tasks.map(piece, pieces(len(mesh), tasks.threads, _CHUNK))
    del mesh

    s = np.nonzero(hit & (key >= scene.n))[0]  # analytic spheres: exact
    if len(s):
        sphere = key[s] - scene.n
        triangle[s] = scene.first_triangle[sphere]
        p = eye - t[s] * view[s].T  # = eye + t d, exactly
        position[s] = p.T
        n = normalize((p - scene.C[:, sphere]).T)
        normal[s] = geometric[s] = n
        uv[s, 0] = np.mod(np.arctan2(n[:, 1], n[:, 0]) / (2.0 * np.pi), 1.0)
        uv[s, 1] = np.arccos(np.clip(-n[:, 2], -1.0, 1.0)) / np.pi

    flipped = hit & (dot(geometric, view) < 0)  # seen from the back: two-sided surface
    normal[flipped] *= -1.0
    geometric[flipped] *= -1.0
    _, cols = camera.shape
    start, stop = band
    n_ss = camera.supersample
    # final-image pixel of each sample, row * width + col (< 2**28: int32 suffices)
    if select is None:
        pixel = ((np.arange(start, stop, dtype=np.int32) // n_ss * np.int32(camera.width))[:, None]
                 + (np.arange(cols, dtype=np.int32) // n_ss)[None, :]).ravel()
    else:
        pixel = ((select // cols + start) // n_ss * camera.width
                 + select % cols // n_ss).astype(np.int32)
    object_id = np.full(N, -1, np.int32)
    object_id[hit] = scene.object_id[triangle[hit]]
    return SurfaceSamples(
        shape=(stop - start, cols) if select is None else (N, 1), supersample=n_ss, hit=hit,
        object_id=object_id,
        triangle=triangle, barycentric=barycentric, position=position, normal=normal,
        geometric_normal=geometric, flipped=flipped, uv=uv, view=view, depth=t, pixel=pixel,
        stats=stats, scene=scene,
    )
