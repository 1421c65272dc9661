"""Reading and checking config.yaml: every problem is reported, by key, before any work starts."""

from __future__ import annotations

from pathlib import Path

import yaml

__all__ = ["ConfigError", "SCHEMA_PATH", "load_config", "validate_schema", "check_config",
           "wavelengths_from_config"]

#: The JSON schema of config.yaml (also used by the Snakefile's ``validate()``).
SCHEMA_PATH = Path(__file__).resolve().parents[1] / "schemas" / "config.schema.yaml"


class ConfigError(ValueError):
    """config.yaml holds a value the workflow cannot use; the message names each key."""


def _key(path_parts):
    return ".".join(str(p) for p in path_parts) or "(top level)"


def validate_schema(config, schema_path=SCHEMA_PATH, source="config.yaml"):
    """Validate against the JSON schema, reporting every violation with its key path."""
    import jsonschema

    schema = yaml.safe_load(Path(schema_path).read_text())
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(config), key=lambda e: list(map(str, e.absolute_path)))
    if errors:
        lines = [f"{source}: {_key(e.absolute_path)}: {e.message}" for e in errors]
        raise ConfigError("invalid configuration:\n  " + "\n  ".join(lines))


def wavelengths_from_config(config):
    """The spectral grid of ``config['wavelengths']`` (inclusive, in nm)."""
    from reflectance.optics.spectra import wavelength_grid

    w = config["wavelengths"]
    return wavelength_grid(w["start_nm"], w["end_nm"], w["step_nm"])


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
    readings = list(ct["fig6"]["ambient_readings"]) + ["published"]
    if ct["fig8"]["ambient_reading"] not in readings:
        problems.append(f"figures.cook_torrance_1982.fig8.ambient_reading: "
                        f"{ct['fig8']['ambient_reading']!r} is not a key of fig6.ambient_readings; "
                        f"known: {', '.join(readings)}")
    return problems


def check_config(config, check_spectra=True):
    """Checks the schema cannot express; raises :class:`ConfigError` listing every problem.

    - the illuminant and observer are names colour-science knows;
    - every material a figure names is defined under ``materials``;
    - the wavelength grid is ordered and inside every material's data range (taken from the
      data source, see :func:`reflectance.optics.spectra.coverage_nm`).
    """
    import colour

    problems = []
    c = config.get("colour", {})
    if c.get("illuminant") not in colour.SDS_ILLUMINANTS:
        problems.append(
            f"colour.illuminant: {c.get('illuminant')!r} is not an illuminant colour-science "
            f"knows; e.g. {', '.join(sorted(k for k in colour.SDS_ILLUMINANTS if len(k) <= 4))}"
        )
    if c.get("observer") not in colour.MSDS_CMFS:
        problems.append(
            f"colour.observer: {c.get('observer')!r} is not a colour-science CMFS; known: "
            + ", ".join(k for k in colour.MSDS_CMFS if "Standard Observer" in k)
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
    problems += _table1_references(config)
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
    if problems:
        raise ConfigError("invalid configuration:\n  " + "\n  ".join(problems))


def load_config(path="config.yaml", check_spectra=True):
    """Read, schema-validate and check a config file; return the dict."""
    path = Path(path)
    if not path.exists():
        raise ConfigError(f"no config file at {path}")
    config = yaml.safe_load(path.read_text()) or {}
    validate_schema(config, source=str(path))
    check_config(config, check_spectra=check_spectra)
    return config
