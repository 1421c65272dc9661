"""Cast shadows: which surface samples see each light.

The same idea as the visibility, from each light's point of view: an ID map (orthographic for
a directional light, perspective or a six-face cube for a point light) proposes, for each
surface sample, the primitives seen in the 3 x 3 map pixels around the sample's projection, and
an exact float64 ray from the sample to the light is tested against each of them. Every point of
that ray projects onto the same spot of the light's map, so the surface the light meets first
there is seen at or next to those pixels; when the ray misses a proposed triangle but crosses
its plane within reach, the test walks across the edge beyond which the crossing lies (point
location on the occluding mesh), which recovers triangles hidden in a vertex's fan or thinner
than a map pixel. A reported shadow is always a real occluder; a missed one needs an occluder
that the map shows nowhere near the sample's projection (smaller than a map pixel and farther
than the walk reaches).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.render.camera import View
from reflectance.render.primitives import Primitives
from reflectance.render.idbuffer import distinct_keys, key_image, neighbour_keys, renderer_for
from reflectance.render.lights import DirectionalLight, as_light, light_vectors
from reflectance.render.parallel import Tasks, pieces
from reflectance.geometry.vectors import dot, normalize
from reflectance.render.samples import SurfaceSamples

if TYPE_CHECKING:
    from reflectance.render.lights import PointLight
    import pyvista as pv

    from reflectance.render.idbuffer import IdRenderer

__all__ = ["shadow_mask", "shadow_masks"]


def _any_up(forward):
    """A view-up not parallel to ``forward``: the world axis least aligned with it."""
    return np.eye(3)[int(np.argmin(np.abs(forward)))]


def _light_views(light, points, scene, size):
    """[(view, member indices)] of light views covering the light's rays to ``points`` (n, 3)."""
    margin = 4.0 / size  # keeps every 3 x 3 neighbourhood inside the map
    if isinstance(light, DirectionalLight):
        forward = -np.asarray(light.direction)
        probe = View.look(np.zeros(3), forward, _any_up(forward), size, size, False, 1.0)
        a, b = points @ probe.right, points @ probe.up
        ca, cb = 0.5 * (a.min() + a.max()), 0.5 * (b.min() + b.max())
        half = 0.5 * max(np.ptp(a), np.ptp(b), 1e-9 * scene.radius) * (1.0 + 2 * margin)
        centre = (scene.center + (ca - scene.center @ probe.right) * probe.right
                  + (cb - scene.center @ probe.up) * probe.up)
        eye = centre - 2.0 * scene.radius * forward
        return [(View.look(eye, forward, probe.up, size, size, False, half),
                 np.arange(len(points)))]
    origin = np.asarray(light.position)
    d = normalize(points - origin)
    axis = d.mean(axis=0)
    if np.linalg.norm(axis) > 1e-6:
        axis = axis / np.linalg.norm(axis)
        if (d @ axis).min() > np.cos(np.radians(60.0)):  # one perspective map suffices
            probe = View.look(origin, axis, _any_up(axis), size, size, True, 1.0)
            spread = np.maximum(np.abs(d @ probe.right), np.abs(d @ probe.up)) / (d @ axis)
            half = float(spread.max()) * (1.0 + 2 * margin) + 1e-12
            return [(View.look(origin, axis, probe.up, size, size, True, half),
                     np.arange(len(points)))]
    views = []  # a cube map: each sample on the face of its dominant axis
    dominant = np.argmax(np.abs(d), axis=1)
    for k in range(3):
        for sign in (1.0, -1.0):
            members = np.nonzero((dominant == k) & (np.sign(d[np.arange(len(d)), k]) == sign))[0]
            if len(members):
                views.append((View.look(origin, sign * np.eye(3)[k], np.eye(3)[(k + 1) % 3],
                                         size, size, True, 1.0 + 2 * margin), members))
    return views


def _terminator_offset(scene, samples, idx, P):
    """Lift shadow-ray origins P (3, n) of smooth-shaded triangles off the facets.

    Hanika 2021: a point below the tangent plane of a vertex (plane through the vertex, normal
    its shading normal) is moved up to it, weighted by the barycentric weight of that vertex, so
    the facets around a point do not shadow what the smooth surface would have lit. Sphere
    samples already lie on the exact surface.
    """
    tri = samples.triangle[idx]
    sub = np.nonzero(scene.key[tri] < scene.n)[0]
    if len(sub) == 0:
        return P
    corner = np.take(scene.T, tri[sub], axis=1)
    b = samples.barycentric[idx[sub]]
    w = (1.0 - b[:, 0] - b[:, 1], b[:, 0], b[:, 1])
    flipped = np.nonzero(samples.flipped[idx[sub]])[0]
    Q = P[:, sub]
    lift = np.zeros_like(Q)
    for j in range(3):  # in place, the same operations in the same order as written out
        V, Nv = np.take(scene.P, corner[j], axis=1), np.take(scene.N, corner[j], axis=1)
        if len(flipped):  # the normal of the side seen
            Nv[:, flipped] = -Nv[:, flipped]
        np.subtract(Q, V, out=V)
        V *= Nv
        below = V[0] + V[1]
        below += V[2]  # (Q - V) . Nv
        np.minimum(below, 0.0, out=below)  # Hanika 2021, Listing 1
        below *= w[j]
        Nv *= below
        lift -= Nv  # lift -= w below Nv
    P = P.copy()
    P[:, sub] += lift
    return P


_CHUNK = 1 << 15  # ray-primitive pairs (and lifted samples) at once: temporaries that stay in cache
_WALK_STEPS = 8  # edges crossed from a missed candidate toward the shadow ray's crossing


def _block(scene, r, k, lifted, L, t_max, eps, planes, own, blocked):
    """Set ``blocked[r]`` where the shadow ray of sample r meets primitive k (or a triangle
    reached from k by walking); L is (3, 1) for a directional light, else one per sample."""
    o = np.take(lifted, r, axis=1)
    # cheap necessary condition first: origin and light on opposite sides of the triangle's
    # plane (spheres always go on to the exact test)
    spheres = len(scene.radii) > 0
    pl = np.take(planes, np.minimum(k, scene.n - 1) if spheres else k, axis=1)
    crosses = pl[0] * o[0] + pl[1] * o[1] + pl[2] * o[2] + pl[3] < 0
    sel = np.nonzero(crosses | (k >= scene.n) if spheres else crosses)[0]
    r, k, o = r[sel], k[sel], np.take(o, sel, axis=1)
    d = L if L.shape[1] == 1 else np.take(L, r, axis=1)
    tm = t_max if np.ndim(t_max) == 0 else np.take(t_max, r)
    t, b1, b2, hit = scene.intersect(o, d, k, eps, tm)
    blocked[r[hit]] = True
    # a missed triangle whose plane the ray crosses within reach: walk across the edge beyond
    # which the crossing lies (point location on the occluder); this finds the triangles hidden
    # in a vertex's fan or thinner than a map pixel
    neighbours = scene.neighbours.ravel()  # (3 n,): triangle k's edge e at 3 k + e
    for _ in range(_WALK_STEPS):
        walk = ~hit
        walk &= t > eps
        walk &= t < tm
        if k.max(initial=-1) >= scene.n:  # only the first step can hold spheres
            walk &= k < scene.n
        if not walk.any():
            break
        walk &= ~blocked[r]
        go = np.nonzero(walk)[0]
        if len(go) == 0:
            break
        b1, b2 = b1[go], b2[go]
        b0 = 1.0 - b1 - b2
        # the edge opposite the smallest barycentric weight (the first of equal ones), as
        # np.argmin over (b0, b1, b2) picks it (no NaN here: t is finite)
        edge = np.where((b0 <= b1) & (b0 <= b2), 0, np.where(b1 <= b2, 1, 2))
        nk = np.take(neighbours, 3 * k[go].astype(np.int64) + edge)
        ok = nk >= 0
        nk_ok = nk[ok]
        ok[ok] = (np.take(scene.key, nk_ok) == nk_ok) & (nk_ok != own[r[go[ok]]])
        go, k = go[ok], nk[ok].astype(np.int32)
        r, o = r[go], np.take(o, go, axis=1)
        d = d if d.shape[1] == 1 else np.take(d, go, axis=1)
        tm = tm if np.ndim(tm) == 0 else np.take(tm, go)
        t, b1, b2, hit = scene.intersect(o, d, k, eps, tm)
        blocked[r[hit]] = True


def shadow_masks(samples: SurfaceSamples, meshes: pv.PolyData | Sequence[tuple[pv.PolyData, int]],
                 lights: Sequence[DirectionalLight | PointLight | Mapping[str, Any]],
                 map_size: int | None = None, renderer: IdRenderer | None = None,
                 threads: int | None = 1) -> npt.NDArray[np.bool_]:
    """True where a surface sample does not see a light (cast shadow or facing away).

    Samples whose shading normal faces away from the light (N.L <= 0) are in shadow without a
    test. For the others an exact float64 ray from the sample toward the light (lifted off the
    facets, Hanika 2021, and offset by 1e-9 of the scene size along the normal) is tested
    against every primitive the light's ID map shows in the 3 x 3 pixels around the sample's
    projection, except the sample's own triangle or sphere, which cannot occlude it; any hit
    closer than the light shadows the sample. Background samples are False. All lights share
    one scene and one VTK window.

    Parameters
    ----------
    samples : SurfaceSamples
        From :func:`visibility` on the same scene.
    meshes : pyvista.PolyData or sequence of (mesh, object_id)
    lights : sequence of DirectionalLight, PointLight or mapping
        ``{"type": "directional", "direction": [...]}`` (toward the light) or
        ``{"type": "point", "position": [...]}``.
    map_size : int, optional
        Side of each light's ID map in pixels; default the larger side of the sample grid,
        clipped to [256, 4096].
    renderer : IdRenderer, optional
        An open :class:`reflectance.render.idbuffer.IdRenderer` of the samples' primitives to
        draw the light maps with (left open); default a new window for this call.
    threads : int or None
        Threads of the per-sample work (:func:`reflectance.render.parallel.render_threads`;
        None: the default count); the mask is the same at any count.

    Returns
    -------
    ndarray of bool, shape (n_lights, N)

    References
    ----------
    Hanika, J. (2021). Hacking the shadow terminator. In Ray Tracing Gems II (pp. 65-76).
    Apress.
    """
    lights = [as_light(light) for light in lights]
    if not isinstance(samples, SurfaceSamples):
        raise ValueError(f"samples must be SurfaceSamples, got {type(samples).__name__}")
    scene = samples.scene
    if scene is None or not scene.made_from(meshes):
        scene = Primitives(meshes)
    if map_size is None:
        map_size = int(np.clip(max(samples.shape), 256, 4096))
    elif isinstance(map_size, bool) or not isinstance(map_size, (int, np.integer)) \
            or map_size < 16:
        raise ValueError(f"map_size must be an integer >= 16, got {map_size!r}")
    shadow = np.zeros((len(lights), len(samples.hit)), bool)
    surface = np.nonzero(samples.hit)[0]
    if len(surface) == 0 or not lights:
        return shadow
    if samples.triangle[surface].max() >= scene.n:
        raise ValueError("samples do not belong to this scene (triangle index out of range)")
    eps = 1e-9 * scene.radius
    position = samples.position[surface]
    normal = samples.normal[surface]
    # the per-sample work in pieces on the render's threads (:mod:`reflectance.render.parallel`):
    # the lifted origins while the first light's map is drawn, each light's ray tests while the
    # next light's map is drawn; every piece computes its samples as the serial path does
    lifting, testing = Tasks(threads), Tasks(threads)
    origins = np.ascontiguousarray(position.T)
    for piece in pieces(len(surface), lifting.threads, _CHUNK):
        lifting.submit(_terminator_offset, scene, samples, surface[piece], origins[:, piece])
    planning = Tasks(threads)  # each light's occluder planes (they need no sample)
    planning.submit(lambda: [scene.light_planes(light) for light in lights])
    lifted = plane_sets = None
    own = scene.key[samples.triangle[surface]]
    blocked_of = []
    with renderer_for(scene, renderer) as maps:
        for i, light in enumerate(lights):
            L, distance = light_vectors(light, position)
            facing = np.nonzero(dot(normal, L) > 0)[0]
            blocked = np.ones(len(surface), bool)
            blocked[facing] = False
            blocked_of.append(blocked)
            if isinstance(light, DirectionalLight):
                Ld, t_max = np.asarray(light.direction)[:, None], np.inf  # one for all rays
            else:
                Ld, t_max = np.ascontiguousarray(L.T), distance * (1.0 - 1e-12) - eps
            # (no sample facing the light: all in shadow, no map to draw)
            views = _light_views(light, position[facing], scene, int(map_size)) \
                if len(facing) else []
            for view, members in views:
                members = facing[members]
                ids = maps.render(view)
                x, y, _ = view.project(np.take(position, members, axis=0).T)
                col = np.clip(np.floor(x), 0, view.width - 1).astype(np.int64)
                row = np.clip(np.floor(y), 0, view.height - 1).astype(np.int64)
                # the keys of the 3 x 3 ids around each projection (off the map: id 0, -1)
                near = key_image(scene, neighbour_keys(ids, row, col, fill=0))
                del ids
                candidates = distinct_keys(near, own[members])
                local, j = np.nonzero(candidates >= 0)
                ray, prim = members[local], candidates[local, j]
                if lifted is None:  # Hanika 2021's lift, then the offset along the normal
                    lifted = np.concatenate(lifting.results(), axis=1)
                    lifted += eps * normal.T
                    [plane_sets] = planning.results()
                planes = plane_sets[i]  # type: ignore[index]  # set with lifted
                # a sample is blocked if any of its tests hits: the pieces' order does not
                # change the mask (a piece only skips walks of samples already blocked)
                for chunk in pieces(len(ray), testing.threads, _CHUNK):
                    testing.submit(_block, scene, ray[chunk], prim[chunk], lifted, Ld, t_max,
                                   eps, planes, own, blocked)
        testing.results()
    lifting.results(), planning.results()  # (no map drawn: nothing waited for them)
    for i, blocked in enumerate(blocked_of):
        shadow[i, surface[blocked]] = True
    return shadow


def shadow_mask(samples: SurfaceSamples, meshes: pv.PolyData | Sequence[tuple[pv.PolyData, int]],
                light: DirectionalLight | PointLight | Mapping[str, Any],
                map_size: int | None = None) -> npt.NDArray[np.bool_]:
    """:func:`shadow_masks` for one light: (N,) bool, True where the light is not seen."""
    return shadow_masks(samples, meshes, [light], map_size)[0]
