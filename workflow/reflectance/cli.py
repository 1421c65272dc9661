"""The ``reflectance`` command: audits from the shell, printing CSV to standard output.

Each sub-command is registered once in :data:`COMMANDS` by a function that adds its parser.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

__all__ = ["main", "COMMANDS"]

DEFAULT_CONFIG = "config.yaml"


def _grid_and_colour(args):
    """Wavelength grid and colour defaults: from --config if it exists, else the built-in ones."""
    from .spectra import wavelength_grid

    grid = {"start_nm": 360, "end_nm": 830, "step_nm": 5}
    path = Path(args.config)
    if path.exists():
        import yaml

        grid = (yaml.safe_load(path.read_text()) or {}).get("wavelengths", grid)
    elif args.config != DEFAULT_CONFIG:
        raise SystemExit(f"reflectance: --config {args.config}: no such file")
    return wavelength_grid(grid["start_nm"], grid["end_nm"], grid["step_nm"])


def _common(parser):
    parser.add_argument("--config", default=DEFAULT_CONFIG,
                        help="config.yaml whose wavelength grid to use (default: ./config.yaml "
                             "if present, else 360-830 nm by 5 nm)")
    parser.add_argument("--spectra-dir", default="spectra",
                        help="folder of material CSVs and sources.csv (default: spectra)")


def _load(args, name, grid):
    from .spectra import load_material

    try:
        return load_material(name, grid, spectra_dir=args.spectra_dir)
    except (ValueError, FileNotFoundError) as err:
        raise SystemExit(f"reflectance: {err}") from None


# -- reflectance colour -------------------------------------------------------------------------

def _add_colour(sub):
    from .colour_shift import COLOUR_METHODS

    p = sub.add_parser(
        "colour", help="colour of a smooth material vs incidence angle (CSV)",
        description="The colour of the light a smooth MATERIAL reflects at each incidence angle "
                    "(Cook & Torrance 1982, Fig. 5), as CSV: angle_deg, X, Y, Z (reflected "
                    "light; the illuminant's white has Y = 1), x, y, dominant_nm, purity, R, G, "
                    "B (display values after gamut clipping; not rescaled: white is Y = 1), "
                    "dE2000_vs_exact (CIEDE2000 against the exact spectral Fresnel colour).")
    p.add_argument("material", help="a material of spectra/ (see `reflectance spectra`)")
    p.add_argument("--angle", nargs="+", type=float, required=True, metavar="DEG",
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
    p.add_argument("--average-range", nargs=2, type=float, default=(380.0, 780.0),
                   metavar=("LO", "HI"),
                   help="wavelength range (nm) of the average F0 for --fresnel approximation")
    _common(p)
    p.set_defaults(run=_run_colour)


def _run_colour(args):
    from .colorimetry import tristimulus_weights
    from .colour_shift import colour_table

    grid = _grid_and_colour(args)
    material = _load(args, args.material, grid)
    try:
        W = tristimulus_weights(grid, args.illuminant, args.observer)
        table = colour_table(material, args.angle, W, methods=(args.fresnel,), space=args.space,
                             clip=args.clip, illuminant=args.illuminant,
                             average_range_nm=args.average_range, expose=False,
                             observer=args.observer)
    except ValueError as err:
        raise SystemExit(f"reflectance: {err}") from None
    table.drop(columns="method").to_csv(sys.stdout, index=False, float_format="%.6g",
                                        lineterminator="\n")


# -- reflectance spectra ------------------------------------------------------------------------

def _add_spectra(sub):
    p = sub.add_parser("spectra", help="list the materials with their kind and source (CSV)",
                       description="List every material of spectra/sources.csv: material, kind "
                                   "(measured n,k or derived reflectance), dataset and reference.")
    _common(p)
    p.set_defaults(run=_run_spectra)


def _run_spectra(args):
    from .spectra import list_materials

    try:
        table = list_materials(args.spectra_dir)
    except (ValueError, FileNotFoundError) as err:
        raise SystemExit(f"reflectance: {err}") from None
    cols = [c for c in ("material", "kind", "dataset", "reference", "DOI") if c in table.columns]
    table[cols].to_csv(sys.stdout, index=False, lineterminator="\n")


#: Sub-command name -> function that adds its parser.
COMMANDS = {"colour": _add_colour, "spectra": _add_spectra}


def build_parser():
    parser = argparse.ArgumentParser(
        prog="reflectance",
        description="Spectral audits of the classic reflectance papers (Blinn 1977, Cook & "
                    "Torrance 1982). Each command prints CSV.")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for add in COMMANDS.values():
        add(sub)
    return parser


def main(argv=None):
    args = build_parser().parse_args(argv)
    return args.run(args) or 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
