"""Scene files: read, validate against the scene schema (``reflectance/data/scene.schema.yaml``,
package data), resolve.

A scene (YAML) names a camera, objects (a geometry and a material each), lights, the ambient
term and the display; the schema documents every key and its default. :func:`load_scene` checks
everything before anything is rendered: the schema (every violation, by key), then what a schema
cannot say (materials that exist, illuminant names, ``s + d = 1`` for Cook & Torrance, the
roughness a distribution needs, geometry the builders accept). Each error names the file and the
key, e.g. ``scene.yaml: objects[0].material.s: ...``. The result is a :class:`Scene` with meshes
built and spectra resolved onto the wavelength grid, ready for :func:`reflectance.render.pipeline.render`.

A material ``name`` is looked up as :func:`reflectance.optics.spectra.find_material` does: in the
caller's folders (``--spectra-dir``), then the scene's ``spectra_dir``, then the spectra that ship
with the package; a material ``file`` is read from beside the scene file.
"""

from __future__ import annotations

import copy
import functools
import json
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt
import yaml

from reflectance.colour.colorimetry import cmfs, illuminant_sd
from reflectance.io.cache import BUILT_MESHES, COMPOSED_MESHES
from reflectance.optics.fresnel import F0_from_nk
from reflectance.geometry.shapes import (VASE_PARTS, compose, mesh_from_file, place, plane, sphere,
                                  superellipsoid_Barr1981, torus, vase)
from reflectance.optics.microfacet import ROUGHNESS_PARAMETERS
from reflectance.render.shading import (SHADING_MODELS, Ambient, Light, RoughnessTexture,
                                 ShadingMaterial, emission_XYZ)
from reflectance.geometry.texture import texture
from reflectance.optics.spectra import (Material, find_material, folder_list, material_from_file,
                                        spectra_folders, wavelength_grid)
from reflectance.render.adaptive import Refinement
from reflectance.render.camera import Camera
from reflectance.render.lights import as_light
from reflectance.geometry.watch import WATCH_PARTS, watch
from reflectance.io.paths import file_inside, package_data
from reflectance.io.yamlfile import MAX_BYTES, YAMLFileError, load_yaml_text
from reflectance.io.limits import grid_points, size_problem
from reflectance.render.memory import MESH_ELEMENTS_PER_VERTEX, render_size_problem

if TYPE_CHECKING:
    import pyvista as pv

if TYPE_CHECKING:
    from reflectance.optics.spectra import SpectraDirs

__all__ = [
    "SceneError",
    "SCENE_SCHEMA_PATH",
    "GEOMETRY_BUILDERS",
    "GEOMETRY_PARTS",
    "Display",
    "SceneObject",
    "Scene",
    "validate_scene",
    "scene_from_dict",
    "load_scene",
    "scene_from_text",
    "write_scene_file",
    "constant_index_material",
    "size_problems",
    "GEOMETRY_VERTICES",
]

SCENE_SCHEMA_PATH = package_data("scene.schema.yaml")
"""The JSON schema of scene files (package data: the workflow's config check reads it too)."""


class SceneError(ValueError):
    """A scene file holds something the renderer cannot use; the message names file and key."""


def _scene_error(problems):
    """One problem: its line (which names the scene file and key); several: a line each, under
    a heading."""
    if len(problems) == 1:
        return SceneError(problems[0])
    return SceneError("invalid scene:\n  " + "\n  ".join(problems))


def _key(parts):
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out or "(top level)"


def _with_defaults(validator_class):
    """A validator class that fills in the schema's ``default`` values while validating."""
    from jsonschema import validators

    check_properties = validator_class.VALIDATORS["properties"]

    def properties(validator, props, instance, schema):
        if isinstance(instance, dict):
            for name, sub in props.items():
                if isinstance(sub, dict) and "default" in sub:
                    instance.setdefault(name, copy.deepcopy(sub["default"]))
        yield from check_properties(validator, props, instance, schema)

    return validators.extend(validator_class, {"properties": properties})


@functools.lru_cache(maxsize=1)
def _validator():
    """The schema's validator (that fills in defaults), read once per process."""
    import jsonschema

    schema = yaml.load(SCENE_SCHEMA_PATH.read_text(),  # libyaml's safe loader where available
                       Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    return _with_defaults(jsonschema.Draft202012Validator)(schema)


def validate_scene(document: Any, source: str = "<scene>") -> dict[str, Any]:
    """A copy of ``document`` with the schema's defaults filled in; SceneError listing every
    violation by key."""
    if not isinstance(document, dict):
        raise SceneError(f"{source}: a scene must be a mapping of keys, got "
                         f"{type(document).__name__}")
    document = copy.deepcopy(document)
    validator = _validator()
    errors = list(validator.iter_errors(document))
    if errors:
        # the deepest (most specific) errors first; if/then wrappers add nothing
        lines = sorted({f"{source}: {_key(list(e.absolute_path))}: {e.message}"
                        for e in errors})
        raise _scene_error(lines)
    return document


# --------------------------------------------------------------------------------------------
# Resolved scene
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Display:
    """How the linear XYZ image becomes a display PNG (:func:`reflectance.colour.display.XYZ_to_display`)."""

    space: str = "sRGB"
    gamut_clip: str = "dominant-wavelength"
    expose: bool = True
    illuminant: str = "D65"
    png_bit_depth: int = 8
    key: tuple | None = None  # (percentile, luminance): reflectance.colour.display.expose_key
    highlight_knee: float | None = None  # reflectance.colour.display.compress_highlights
    white: float | None = None  # display luminance of a white card: shading.white_card_luminance
    transfer: str = "display"  # reflectance.colour.display.TRANSFERS: encode's transfer
    highlight_rolloff: str = "tanh"  # reflectance.colour.display.HIGHLIGHT_ROLLOFFS


@dataclass(frozen=True, eq=False)
class SceneObject:
    """One object: its placed mesh, its material and the materials of named parts.

    ``part_materials`` maps codes of the mesh's ``cell_data["part"]`` to the material used there
    instead of ``material``.
    """

    name: str
    mesh: pv.PolyData  # placed
    material: ShadingMaterial
    part_materials: dict = field(default_factory=dict)


@dataclass(frozen=True, eq=False)
class Scene:
    """A validated scene with its meshes and spectra resolved (see :func:`load_scene`).

    ``document`` is the scene as validated, with every default filled in (it goes into the EXR
    header); ``mesh`` the composed scene (object id = index in ``objects``); ``refinement`` the
    camera's adaptive supersampling (:class:`reflectance.render.adaptive.Refinement`; None:
    none).
    """

    camera: Camera
    objects: tuple
    lights: tuple
    ambient: Ambient
    display: Display
    wavelengths: np.ndarray
    observer: str
    spectral: str
    table_size: int
    shadows: bool
    mesh: pv.PolyData
    source: str = "<scene>"
    document: dict = field(default_factory=dict)
    refinement: Refinement | None = None

    def to_json(self) -> str:
        """The validated document as canonical JSON (sorted keys)."""
        return json.dumps(self.document, sort_keys=True, separators=(",", ":"))


def _rotation(degrees):
    from scipy.spatial.transform import Rotation

    return Rotation.from_euler("xyz", degrees, degrees=True).as_matrix()  # extrinsic x, y, z


GEOMETRY_BUILDERS = {
    "sphere": lambda g, base: sphere(g["center"], g["radius"], g["n_theta"], g["n_phi"]),
    "vase": lambda g, base: vase(g["profile"], g["n_theta"], g["n_profile_samples"],
                                 g["wall_thickness"], g["n_rim_samples"], g["interpolation"]),
    "torus": lambda g, base: torus(g["major_radius"], g["minor_radius"], g["n_u"], g["n_v"],
                                   g["center"]),
    "superellipsoid": lambda g, base: superellipsoid_Barr1981(g["radii"], g["exponents"],
                                                              g["n_u"], g["n_v"], g["center"]),
    "plane": lambda g, base: plane(g["center"], g["normal"], g["size"], g["resolution"],
                                   g.get("u_direction")),
    "mesh": lambda g, base: mesh_from_file(
        Path(base) / file_inside(g["path"], base, "the scene file's folder"), g["feature_angle"]),
    "watch": lambda g, base: watch(**g["parameters"]),
}
"""Scene geometry types and how each is built from its keys (``base``: the scene's folder)."""

GEOMETRY_PARTS = {"vase": VASE_PARTS, "watch": WATCH_PARTS}
"""Named parts (codes of ``cell_data["part"]``) of the geometry types that have them."""


class _Checker:
    """Collects problems by key so that one run reports them all."""

    def __init__(self, source):
        self.source, self.problems = source, []

    def add(self, path, message):
        self.problems.append(f"{self.source}: {_key(path)}: {message}")

    def run(self, path, function, *args, **kwargs):
        try:
            return function(*args, **kwargs)
        except (ValueError, TypeError, FileNotFoundError) as err:
            text = str(err)
            # a message given as a quoted repr loses its quotes; one that merely starts or ends
            # with a quoted path ("'../x.csv' leaves ...", "no such folder 'x'") keeps them
            if len(text) > 1 and text[0] == text[-1] and text[0] in "'\"":
                text = text[1:-1]
            self.add(path, text)
            return None

    def raise_if_any(self):
        if self.problems:
            raise _scene_error(self.problems)


def _illuminant(check, path, name):
    if check.run(path, illuminant_sd, name) is not None:
        return name
    return None


def _spectral_material(check, path, name, grid, spectra_dirs, cache):
    if name not in cache:
        cache[name] = check.run(path, find_material, name, grid, spectra_dirs)
    return cache[name]


def _file_material(check, path, value, grid, base, cache):
    """The material of a scene's ``file``: a CSV beside the scene file (inside its folder)."""
    relative = check.run(path, file_inside, value, base, "the scene file's folder")
    if relative is None:
        return None
    key = ("file", str((Path(base) / relative).resolve()))  # a tuple: never a material's name
    if key not in cache:
        cache[key] = check.run(path, material_from_file, Path(base) / relative, grid)
    return cache[key]


#: The keys that give a material's specular spectrum (one at most).
_SPECULAR_KEYS = ("name", "file", "index")


def index_label(index):
    """The name of a constant-index material, e.g. ``"n = 1.8, k = 0"``."""
    return f"n = {index['n']:g}, k = {index['k']:g}"


def constant_index_material(n: float, k: float, grid: npt.ArrayLike) -> Material:
    """A :class:`reflectance.optics.spectra.Material` of wavelength-independent index ``n + i k``.

    What a material CSV with the same ``n, k`` at every wavelength gives (scene key ``index``:
    e.g. Blinn 1977's scalar n = 200 for aluminium, 1.8 for magnesium oxide).
    """
    grid = np.asarray(grid, dtype=np.float64)
    n_, k_ = np.full(grid.shape, float(n)), np.full(grid.shape, float(k))
    for a in (grid, n_, k_):
        a.setflags(write=False)
    F0 = np.asarray(F0_from_nk(n_, k_), dtype=np.float64)
    F0.setflags(write=False)
    return Material(index_label({"n": n, "k": k}), "measured", grid, n_, k_, F0)


def _material(check, path, m, grid, spectra_dirs, base, cache, observer):
    """A ShadingMaterial from a validated material mapping (None if something is wrong);
    ``spectra_dirs`` the folders names are looked up in before the bundled spectra, ``base`` the
    scene file's folder."""
    model = m["model"]
    spec = SHADING_MODELS[model]
    s, d = m.get("s"), m.get("d")
    if s is None and d is None:
        s, d = (0.0, 1.0) if model == "Lambert" else (1.0, 0.0)
    elif s is None:
        s = 1.0 - d
    elif d is None:
        d = 1.0 - s
    if model == "CookTorrance1982" and abs(s + d - 1.0) > 1e-9:
        check.add(path + ["s"], f"Cook & Torrance 1982 require s + d = 1, got s = {s}, d = {d}")
    if model == "Lambert" and s > 0:
        check.add(path + ["s"], "a Lambert material has no specular part: s must be 0")
    ok = True

    # the specular material: a named material (name), the scene's own file (file) or a constant
    # complex index (index)
    specular = None
    given = [key for key in _SPECULAR_KEYS if key in m]
    if len(given) > 1:
        check.add(path, f"give one of 'name' (a material), 'file' (its CSV file) or 'index' "
                        f"(a constant n, k), not {' and '.join(map(repr, given))}")
        ok = False
    elif "index" in m and m["index"]["k"] == 0 and m["index"]["n"] < 1:
        check.add(path + ["index", "n"], f"{m['index']['n']:g}: a dielectric's index (k = 0) "
                  f"must be at least 1 (the light comes from air); a metal's n < 1 needs its k")
        ok = False
    elif "index" in m:
        specular = constant_index_material(m["index"]["n"], m["index"]["k"], grid)
    elif "name" in m:
        specular = _spectral_material(check, path + ["name"], m["name"], grid, spectra_dirs,
                                      cache)
        ok &= specular is not None
    elif "file" in m:
        specular = _file_material(check, path + ["file"], m["file"], grid, base, cache)
        ok &= specular is not None
    n = k = None
    if spec["fresnel"] and s > 0:
        if not given:
            check.add(path, f"model {model} with s > 0 needs 'name' (the material whose n, k "
                            "give F), 'file' or 'index'")
            ok = False
        elif specular is not None:
            n, k = specular.n, specular.k

    albedo = 0.0
    if "albedo" in m:
        if "diffuse_material" in m:
            check.add(path + ["albedo"], "give either albedo or diffuse_material, not both")
            ok = False
        albedo = float(m["albedo"])
    else:
        if "diffuse_material" in m:
            found = _spectral_material(check, path + ["diffuse_material"], m["diffuse_material"],
                                       grid, spectra_dirs, cache)
        else:
            found = specular  # the specular material's own F0 (name, file or index)
        if found is not None:
            albedo = found.F0  # Cook & Torrance 1982, Fig. 7: R_d = F0 / pi
        elif "diffuse_material" in m:
            ok = False
        elif d > 0 and not given:
            check.add(path, "a diffuse part (d > 0) needs 'diffuse_material', 'albedo', 'name', "
                            "'file' or 'index'")
            ok = False

    distribution, roughness, lobes, rough_texture = m["distribution"], None, None, None
    kind = spec["roughness"]
    if kind is True:
        key = ROUGHNESS_PARAMETERS[distribution]
        if "lobes" in m:
            lobes = []
            for j, lobe in enumerate(m["lobes"]):
                if key not in lobe:
                    check.add(path + ["lobes", j], f"distribution {distribution} needs '{key}'")
                    ok = False
                else:
                    lobes.append((lobe["w"], lobe[key]))
            weights = [lobe["w"] for lobe in m["lobes"]]
            if abs(sum(weights) - 1.0) > 1e-9:
                check.add(path + ["lobes"], f"weights must sum to 1 (Cook & Torrance 1982), got "
                                            f"{weights}")
                ok = False
            lobes = tuple(lobes)
            if "roughness_texture" in m:
                check.add(path + ["roughness_texture"], "a roughness texture needs a single "
                                                        "distribution, not lobes")
                ok = False
        elif "roughness_texture" not in m:
            # Cook & Torrance 1982, Table I: m "not used" where s = 0 (no specular part)
            if key not in m and s > 0:
                check.add(path, f"distribution {distribution} needs '{key}' (or 'lobes')")
                ok = False
            roughness = m.get(key)
        if m["shadowing"] == "smith" and (distribution != "Beckmann1963" or lobes is not None):
            check.add(path + ["shadowing"], "smith shadowing is the Smith G of one Beckmann "
                                            "distribution (no lobes)")
            ok = False
        if model == "TorranceSparrow_Blinn1977" and m["convention"] != "paper":
            check.add(path + ["convention"], "Blinn's Torrance-Sparrow model exists only as "
                                             "printed (paper)")
            ok = False
    elif kind == "c1":
        if "c1" not in m and "roughness_texture" not in m:
            check.add(path, f"model {model} needs the exponent 'c1'")
            ok = False
        roughness = m.get("c1")
    if "roughness_texture" in m:
        t = m["roughness_texture"]
        if kind is False:
            check.add(path + ["roughness_texture"], f"model {model} has no roughness")
            ok = False
        elif distribution == "TrowbridgeReitz1975" and kind is True:
            if m["convention"] != "paper":
                check.add(path + ["convention"], "Blinn's texture-modulated D3 exists only as "
                                                 "printed (paper)")
                ok = False
            if t["max"] != 1.0:
                check.add(path + ["roughness_texture", "max"], "Blinn's C3 = C_min + (1 - "
                                                               "C_min) t has max 1")
                ok = False
        if check.run(path + ["roughness_texture", "parameters"], texture, np.zeros(1),
                     np.zeros(1), t["method"], **t["parameters"]) is None:
            ok = False
        rough_texture = RoughnessTexture(t["method"], float(t["min"]), float(t["max"]),
                                         dict(t["parameters"]))

    emission = None
    if "emission" in m:
        e = m["emission"]
        if _illuminant(check, path + ["emission", "white"], e["white"]) is None:
            ok = False
        else:
            emission = check.run(path + ["emission"], emission_XYZ,
                                 e["dominant_wavelength_nm"], e["luminance"], e["purity"],
                                 e["white"], observer)
            ok &= emission is not None
    if not ok:
        return None
    return check.run(path, ShadingMaterial, model=model, convention=m["convention"], s=s, d=d,
                     n=n, k=k, fresnel=m["fresnel"], albedo=albedo, distribution=distribution,
                     roughness=roughness, lobes=lobes, texture=rough_texture,
                     shadowing=m["shadowing"], emission=emission,
                     name=m.get("name", index_label(m["index"]) if "index" in m
                                else Path(m["file"]).stem if "file" in m
                                else m.get("diffuse_material", "")))


#: Meshes built in this process, by their geometry keys (JSON): a figure that renders many scenes
#: of one object builds it once and composes it once (reflectance.io.cache's BUILT_MESHES and
#: COMPOSED_MESHES). Each scene gets a deep copy, so that a scene that changes its mesh changes
#: no other; meshes read from files are not kept (the file may change).


def _kept(memo, key, build):
    """A deep copy of the mesh ``memo`` keeps under ``key`` (JSON), ``build()`` the first time."""
    return memo.get(key, build).copy(deep=True)


def _build_geometry(g, base):
    if g["type"] == "mesh":
        return GEOMETRY_BUILDERS["mesh"](g, base)
    return _kept(BUILT_MESHES, json.dumps(g, sort_keys=True, default=str),
                 lambda: GEOMETRY_BUILDERS[g["type"]](g, base))


def _compose(objects, documents):
    """:func:`compose` of ``objects`` (SceneObjects in the order of ``documents``, the scene's
    object mappings), or a deep copy of the mesh composed earlier from the same documents."""
    meshes = [(o.mesh, i) for i, o in enumerate(objects)]
    if len(objects) != len(documents) or any(obj["geometry"]["type"] == "mesh"
                                             for obj in documents):
        return compose(meshes)
    key = json.dumps([(obj["geometry"], obj.get("transform")) for obj in documents],
                     sort_keys=True, default=str)
    return _kept(COMPOSED_MESHES, key, lambda: compose(meshes))


def _geometry(check, path, g, transform, base):
    mesh = check.run(path + ["geometry"], _build_geometry, g, base)
    if mesh is None or transform is None:
        return mesh
    return check.run(path + ["transform"], place, mesh, transform["offset"], transform["scale"],
                     _rotation(transform["rotation_deg"]))


#: vertices of a geometry type, from its validated keys (the mesh it builds; a mesh file's and a
#: watch's are bounded where they are read or by their own parameters' schema)
GEOMETRY_VERTICES = {
    "sphere": lambda g: g["n_theta"] * g["n_phi"],
    "vase": lambda g: 2 * g["n_theta"] * (g["n_profile_samples"] + g["n_rim_samples"]),
    "torus": lambda g: g["n_u"] * g["n_v"],
    "superellipsoid": lambda g: g["n_u"] * g["n_v"],
    "plane": lambda g: (g["resolution"][0] + 1) * (g["resolution"][1] + 1),
}


def size_problems(doc: Mapping[str, Any], memory: float | None = None) -> list[str]:
    """One line (key: what it makes, the estimate) per size of a validated scene mapping that
    cannot fit in ``memory`` bytes (default: this machine's) or would take more than an hour
    (:func:`reflectance.io.limits.size_problem`): the wavelength grid with the Fresnel table
    (and with every sample, brute force), each object's mesh, and the render itself, adaptive
    refinement included (:func:`reflectance.render.memory.render_size_problem`). Counted from
    the numbers: nothing is made."""
    problems = []
    w, c = doc["wavelengths"], doc["camera"]
    n_wl = grid_points(max(w["end_nm"] - w["start_nm"], 0.0), w["step_nm"])
    given = f"{w['step_nm']:g} nm from {w['start_nm']:g} to {w['end_nm']:g} nm"
    dims = [(n_wl, "wavelengths"), (doc["fresnel_table_size"], "Fresnel table cosines"),
            (max(1, len(doc["lights"])), "lights")]
    problems.append(size_problem("wavelengths.step_nm, fresnel_table_size",
                                 f"{given} and {doc['fresnel_table_size']} cosines", dims,
                                 memory, streamed=True))
    if doc["spectral"] == "brute-force":
        samples = c["width"] * c["height"] * c["supersample"] ** 2
        problems.append(size_problem("wavelengths.step_nm, spectral", f"{given}, brute force",
                                     [(samples, "samples"), (n_wl, "wavelengths"),
                                      (max(1, len(doc["lights"])), "lights")], memory,
                                     streamed=True))
    for i, obj in enumerate(doc["objects"]):
        g = obj["geometry"]
        if g["type"] in GEOMETRY_VERTICES:
            vertices = GEOMETRY_VERTICES[g["type"]](g)
            problems.append(size_problem(f"objects[{i}].geometry", f"a {g['type']} of "
                                         f"{vertices:,} vertices",
                                         [(vertices, "vertices"),
                                          (MESH_ELEMENTS_PER_VERTEX, "values per vertex")],
                                         memory))
    adaptive = c["adaptive"]
    problems.append(render_size_problem(
        "camera.width, .height, .supersample", c["width"], c["height"], c["supersample"],
        adaptive=adaptive["enabled"] and adaptive["supersample"] > c["supersample"],
        memory=memory))
    return [p for p in problems if p is not None]


def scene_from_dict(document: Mapping[str, Any], source: str = "<scene>",
                    base_dir: str | os.PathLike[str] = ".",
                    spectra_dir: SpectraDirs = None) -> Scene:
    """A :class:`Scene` from a scene mapping (as a scene file holds it).

    Parameters
    ----------
    document : dict
        The scene; validated against the schema (defaults filled in on a copy).
    source : str
        Name used in error messages (the file).
    base_dir : str or Path
        Folder that mesh paths and material files are relative to (the scene file's).
    spectra_dir : str or Path or sequence of them, optional
        Folders of ``<name>.csv`` materials searched first (``--spectra-dir``), before the
        scene's own ``spectra_dir`` and the bundled spectra.

    Raises
    ------
    SceneError
        Listing every problem with its key.
    """
    doc = validate_scene(document, source)
    check = _Checker(source)
    for problem in size_problems(doc):
        check.problems.append(f"{source}: {problem}")
    check.raise_if_any()  # nothing is made of a size that cannot fit
    w = doc["wavelengths"]
    grid = check.run(["wavelengths"], wavelength_grid, w["start_nm"], w["end_nm"], w["step_nm"])
    observer = doc["observer"]
    if check.run(["observer"], cmfs, observer) is None:
        observer = None
    given = folder_list(spectra_dir)
    check.run(["spectra_dir"], spectra_folders, given)  # each folder given must exist
    if "spectra_dir" in doc and not Path(doc["spectra_dir"]).is_dir():
        check.add(["spectra_dir"], f"no such folder {doc['spectra_dir']!r} (relative to the "
                                   "working directory: run from the folder it is in, or leave "
                                   "the key out for the bundled spectra)")
    check.raise_if_any()
    spectra_dirs = given + ([doc["spectra_dir"]] if "spectra_dir" in doc else [])

    c = doc["camera"]
    camera = check.run(["camera"], Camera, c["position"], c["look_at"], c["up"], c["fov_deg"],
                       c["width"], c["height"], c["supersample"])
    refinement = check.run(["camera", "adaptive"], Refinement, **c["adaptive"])

    lights = []
    for i, spec in enumerate(doc["lights"]):
        path = ["lights", i]
        _illuminant(check, path + ["spectrum"], spec["spectrum"])
        source_light = check.run(path, as_light, spec)
        if source_light is None:
            continue
        solid_angle = spec.get("solid_angle", None if "area" in spec else 1.0)
        light = check.run(path, Light, source_light, spec["spectrum"], spec["intensity"],
                          solid_angle, spec.get("area"), spec["shadows"])
        if light is not None:
            lights.append(light)

    first = doc["lights"][0]["spectrum"] if doc["lights"] else "D65"
    a = doc["ambient"]
    a_spectrum = a.get("spectrum", first)
    if "spectrum" in a:  # (a light's spectrum is checked with the light)
        _illuminant(check, ["ambient", "spectrum"], a_spectrum)
    ambient = check.run(["ambient"], Ambient, a["fraction"], a["reference"], a_spectrum)
    if ambient is not None and ambient.reference != "intensity" and ambient.fraction > 0 \
            and any(light.area is not None for light in lights):
        check.add(["ambient", "reference"], f"{ambient.reference!r} needs every light's solid_angle")

    d = doc["display"]
    display_white = d.get("illuminant", first)
    if "illuminant" in d:
        _illuminant(check, ["display", "illuminant"], display_white)
    key = (float(d["key"]["percentile"]), float(d["key"]["luminance"])) if "key" in d else None
    white = float(d["white"]["luminance"]) if "white" in d else None
    if white is not None and any(light.area is not None for light in lights):
        check.add(["display", "white"], "a white card needs every light's solid_angle")
    display = Display(d["space"], d["gamut_clip"], d["expose"], display_white,
                      d["png_bit_depth"], key, d.get("highlight_knee"), white, d["transfer"],
                      d.get("highlight_rolloff", "tanh"))

    cache: dict[str, Any] = {}
    objects: list[SceneObject] = []
    for i, obj in enumerate(doc["objects"]):
        path = ["objects", i]
        material = _material(check, path + ["material"], obj["material"], grid, spectra_dirs,
                             base_dir, cache, observer)
        names = GEOMETRY_PARTS.get(obj["geometry"]["type"], {})
        parts, ok = {}, material is not None
        for part, spec in obj.get("parts", {}).items():
            if part not in names:
                check.add(path + ["parts", part], f"no part {part!r} in a "
                          f"{obj['geometry']['type']}; known: {', '.join(names) or 'none'}")
                ok = False
                continue
            parts[names[part]] = _material(check, path + ["parts", part], spec, grid,
                                           spectra_dirs, base_dir, cache, observer)
            ok &= parts[names[part]] is not None
        mesh = _geometry(check, path, obj["geometry"], obj.get("transform"), base_dir)
        if ok and mesh is not None:
            objects.append(SceneObject(obj.get("name", f"object {i}"), mesh, material, parts))
    check.raise_if_any()
    emitters = [m for o in objects for m in (o.material, *o.part_materials.values())
                if m is not None and m.emission is not None]
    if not lights and not emitters:
        # (the ambient term is a fraction of the lights: with none, the image would be black)
        check.add(["lights"], "no light, and no object emits: the render would be black; "
                  "give at least one light")
        check.raise_if_any()
    composed = check.run(["objects"], _compose, objects, doc["objects"])
    check.raise_if_any()
    return Scene(camera=camera, objects=tuple(objects), lights=tuple(lights), ambient=ambient,
                 display=display, wavelengths=grid,
                 observer=observer,  # type: ignore[arg-type]  # checked above
                 spectral=doc["spectral"],
                 table_size=doc["fresnel_table_size"], shadows=doc["shadows"], mesh=composed,
                 source=source, document=doc, refinement=refinement)


def load_scene(path: str | os.PathLike[str], spectra_dir: SpectraDirs = None,
               width: int | None = None, height: int | None = None, supersample: int | None = None,
               spectral: str | None = None,
               wavelengths: Mapping[str, float] | None = None) -> Scene:
    """Read a scene file, validate it and resolve it (see :func:`scene_from_dict`).

    Parameters
    ----------
    path : str or Path
        YAML scene file.
    spectra_dir : str or Path or sequence of them, optional
        Folders searched first for material names (see :func:`scene_from_dict`).
    width, height, supersample : int, optional
        Override the camera's.
    spectral : str, optional
        Overrides the scene's ``spectral`` (``"table"`` or ``"brute-force"``).
    wavelengths : dict, optional
        Overrides the scene's ``wavelengths`` ({start_nm, end_nm, step_nm}).

    Raises
    ------
    SceneError
        Naming the file and the key of each problem.
    """
    path = Path(path)
    if not path.is_file():
        raise SceneError(f"{path}: no such scene file")
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:  # not read at all (reflectance.io.yamlfile's bound)
            raise SceneError(f"{path}: {size:,} bytes; a YAML file read here holds at most "
                             f"{MAX_BYTES:,}")
        text = path.read_bytes()
    except OSError as err:
        raise SceneError(f"{path}: cannot read: {err.strerror}") from None
    return scene_from_text(text, str(path), path.parent, spectra_dir=spectra_dir, width=width,
                           height=height, supersample=supersample, spectral=spectral,
                           wavelengths=wavelengths)


def scene_from_text(text: str | bytes, source: str, base_dir: str | os.PathLike[str],
                    spectra_dir: SpectraDirs = None, width: int | None = None,
                    height: int | None = None, supersample: int | None = None,
                    spectral: str | None = None,
                    wavelengths: Mapping[str, float] | None = None) -> Scene:
    """A scene from the bytes of a scene file (``reflectance render -`` reads them from standard
    input), named ``source`` in messages, its relative paths taken from ``base_dir``; the other
    parameters as for :func:`load_scene`."""
    try:
        if isinstance(text, bytes):
            text = text.decode("utf-8-sig")
        # bounded (aliases, depth, size) and no key twice: reflectance.io.yamlfile
        document = load_yaml_text(text, source)
    except UnicodeDecodeError as err:
        raise SceneError(f"{source}: not a UTF-8 text file (byte {err.start})") from None
    except YAMLFileError as err:
        raise SceneError(str(err)) from None
    if isinstance(document, dict):
        camera = document.get("camera")
        for key, value in (("width", width), ("height", height), ("supersample", supersample)):
            if value is not None and isinstance(camera, dict):
                camera[key] = value
        if spectral is not None:
            document["spectral"] = spectral
        if wavelengths is not None:
            document["wavelengths"] = dict(wavelengths)
    return scene_from_dict(document, source=source, base_dir=Path(base_dir),
                           spectra_dir=spectra_dir)


def write_scene_file(scene: Scene, path: str | os.PathLike[str]) -> None:
    """Write the validated scene (defaults filled in) as YAML, atomically; ``reflectance render``
    re-renders it."""
    from reflectance.io.atomic import atomic_write

    with atomic_write(path) as tmp:
        Path(tmp).write_text(yaml.safe_dump(scene.document, sort_keys=False))
