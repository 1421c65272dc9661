"""The colour of light reflected by a smooth surface as a function of incidence angle.

Cook & Torrance 1982 (section "Spectral composition of the reflected light", Figs. 4 and 5): the
reflected spectral energy distribution is the light's SPD times the Fresnel reflectance
F(lambda, theta); its XYZ follow by integration against the CMFs. Because XYZ is linear in the
spectrum, ``XYZ(theta) = F(., theta) @ W`` with the tristimulus weights ``W`` that already hold the
illuminant and the CMFs (see :func:`reflectance.colour.colorimetry.tristimulus_weights`).

The module also holds the paper's cheap approximation of the colour shift (Fig. 5c) and the audit
table that compares every Fresnel shortcut with the exact spectral answer.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from reflectance.optics.fresnel import fresnel, fresnel_dielectric_CookTorrance1982, n_from_F0_CookTorrance1982

if TYPE_CHECKING:
    import pandas as pd

    from reflectance.optics.spectra import Material

__all__ = [
    "COLOUR_METHODS",
    "reflected_XYZ",
    "colour_interpolation_CookTorrance1982",
    "reflected_XYZ_approximation_CookTorrance1982",
    "approximation_onset_CookTorrance1982",
    "colour_XYZ",
    "COLOUR_TABLE_COLUMNS",
    "colour_columns",
    "colour_table",
]


def reflected_XYZ(material: Material, cos_theta: npt.ArrayLike, W: npt.NDArray[np.float64],
                  method: str = "exact") -> npt.NDArray[np.float64]:
    """XYZ of the light a smooth ``material`` reflects at incidence cosine ``cos_theta``.

    Cook & Torrance 1982, Fig. 4b and 5b: reflected SPD = I(lambda) F(lambda, theta), integrated
    against the CMFs; ``W`` carries I(lambda) and the CMFs, so the light's white has Y = 1.

    Parameters
    ----------
    material : reflectance.optics.spectra.Material
    cos_theta : array_like
        Cosines of the incidence angle, any shape.
    W : ndarray, shape (n_wavelengths, 3)
    method : str
        A Fresnel method of :data:`reflectance.optics.fresnel.FRESNEL_METHODS`.

    Returns
    -------
    ndarray, shape cos_theta.shape + (3,)
    """
    c = np.asarray(cos_theta, dtype=float)[..., None]
    F = fresnel(c, material.n, material.k, method=method)
    return F @ W


def colour_interpolation_CookTorrance1982(XYZ_0: npt.ArrayLike, XYZ_90: npt.ArrayLike,
                                          F_theta: npt.ArrayLike,
                                          F_0: float | npt.NDArray[np.float64],
                                          F_90: float | npt.NDArray[np.float64] = 1.0
                                         ) -> npt.NDArray[np.float64]:
    """Cook & Torrance 1982's colour-shift approximation ("Spectral composition", equation for Red_theta).

    ``Red_theta = Red_0 + (Red_pi/2 - Red_0) max(0, F_theta - F_0) / (F_pi/2 - F_0)``, applied to
    each component. The paper writes it for RGB; RGB is a linear map of XYZ, so interpolating XYZ
    gives the same colour before the display's non-linear steps.
    """
    # Cook & Torrance 1982, "Spectral composition": Red_theta = Red_0 + (Red_90 - Red_0) max(0, F_theta - F_0)/(F_90 - F_0)
    t = np.maximum(0.0, np.asarray(F_theta) - F_0) / (F_90 - F_0)
    XYZ_0 = np.asarray(XYZ_0, dtype=float)
    XYZ_90 = np.asarray(XYZ_90, dtype=float)
    return XYZ_0 + (XYZ_90 - XYZ_0) * np.asarray(t)[..., None]


def reflected_XYZ_approximation_CookTorrance1982(material: Material, cos_theta: npt.ArrayLike,
                                                 W: npt.NDArray[np.float64],
                                                 average_range_nm: Sequence[float]
                                                ) -> npt.NDArray[np.float64]:
    """The colour of Fig. 5c: the paper's approximation of the colour shift.

    F is computed once, for the index n that corresponds to the material's average normal
    reflectance over ``average_range_nm`` (k = 0); it interpolates between the colour at normal
    incidence (exact) and the light's colour at grazing incidence, where F = 1 at every wavelength.

    ``material`` may hold several materials on one grid (``F0`` of shape (..., L)); then
    ``cos_theta`` is 1-D and the result has shape (..., len(cos_theta), 3).
    """
    F0_average: Any = material.mean_F0(average_range_nm)  # a float, or an array of several
    XYZ_0 = material.F0 @ W  # the colour at theta = 0 (C&T 1982, Fig. 4b)
    if np.ndim(material.F0) > 1:  # several materials: an axis for the angles
        F0_average, XYZ_0 = F0_average[..., None], XYZ_0[..., None, :]
    n_average = n_from_F0_CookTorrance1982(F0_average)  # C&T 1982: n = (1 + sqrt F0)/(1 - sqrt F0)
    c = np.asarray(cos_theta, dtype=float)
    F_theta = fresnel_dielectric_CookTorrance1982(c, n_average)
    XYZ_90 = W.sum(axis=0)  # F_pi/2 = 1: the light's colour
    return colour_interpolation_CookTorrance1982(XYZ_0, XYZ_90, F_theta, F0_average)


def approximation_onset_CookTorrance1982(material: Material, average_range_nm: Sequence[float],
                                         fractions: Sequence[float] = (0.5,)) -> dict[str, float]:
    """Why Fig. 5c's approximation keeps the normal-incidence colour until close to grazing.

    The approximation's weight is ``t = max(0, F_theta - F_0) / (1 - F_0)`` with F of the
    dielectric index ``n`` fitted to the average F0 (k = 0). For a metal's large F0 that index is
    large (copper: n near 13), and the unpolarised dielectric F of a large index dips below F0
    towards its Brewster angle before it rises to 1, so the ``max(0, ...)`` clamp holds t at 0 --
    the colour at 0 degrees -- until F_theta climbs back to F0 a degree or less from grazing.

    Returns
    -------
    dict
        ``F0_average``, ``n_average``, ``dip`` (the least F_theta - F0) and ``dip_deg`` (its
        angle), ``onset_deg`` (the angle beyond which t > 0) and ``t_<fraction>_deg`` for each of
        ``fractions`` (the angle where t reaches it). Angles from bisection (``brentq``).
    """
    from scipy.optimize import brentq, minimize_scalar

    F0 = float(material.mean_F0(average_range_nm))
    n = float(n_from_F0_CookTorrance1982(F0))  # C&T 1982: n = (1 + sqrt F0)/(1 - sqrt F0)

    def excess(angle_deg):  # F_theta - F_0, Cook & Torrance's max(0, ...) argument
        return float(fresnel_dielectric_CookTorrance1982(np.cos(np.radians(angle_deg)), n)) - F0

    dip = minimize_scalar(excess, bounds=(0.0, 90.0), method="bounded",
                          options={"xatol": 1e-9})
    out = {"F0_average": F0, "n_average": n, "dip": float(dip.fun), "dip_deg": float(dip.x)}
    if dip.fun >= 0:  # no dip: t grows from 0 degrees on
        out["onset_deg"] = 0.0
    else:
        out["onset_deg"] = float(brentq(excess, dip.x, 90.0, xtol=1e-12))
    for fraction in fractions:
        out[f"t_{fraction:g}_deg"] = float(brentq(
            lambda a: excess(a) / (1.0 - F0) - fraction, out["onset_deg"], 90.0, xtol=1e-12))
    return out


def approximation_agreement(strip: pd.DataFrame, bound_dE00: float,
                            method: str = "approximation") -> dict[str, float]:
    """Where a row of a colour table (:func:`colour_table`, over an angle sweep) stays "similar"
    to the exact row, C&T 1982's word for Fig. 5c against 5b, read as CIEDE2000 below ``bound_dE00``.

    Returns
    -------
    dict
        ``agree_deg``: the largest swept angle up to which every sample's
        ``dE2000_vs_exact`` is below the bound (from 0 degrees on); ``worst_dE00`` and
        ``worst_deg``: the largest difference of the sweep and its angle.
    """
    rows = strip[strip.method == method].sort_values("angle_deg")
    if rows.empty:
        raise ValueError(f"colour table holds no {method!r} row")
    angles, dE = rows.angle_deg.to_numpy(float), rows.dE2000_vs_exact.to_numpy(float)
    above = np.flatnonzero(dE >= bound_dE00)
    last = len(angles) - 1 if above.size == 0 else above[0] - 1
    if last < 0:
        raise ValueError(f"{method!r} differs from the exact row by {dE[0]:.3g} >= {bound_dE00:g} "
                         f"at {angles[0]:g} degrees already")
    worst = int(np.argmax(dE))
    return {"agree_deg": float(angles[last]), "worst_dE00": float(dE[worst]),
            "worst_deg": float(angles[worst])}


#: How the colour of each row of Fig. 5 and of ``reflectance colour`` is obtained.
COLOUR_METHODS = {
    "exact": "exact complex-index Fresnel per wavelength (C&T 1982 Fig. 5b)",
    "approximation": "C&T 1982's interpolation with F of the average-F0 index (Fig. 5c)",
    "fitted": "C&T 1982's per-wavelength k = 0 fit of n to F0, then the Fresnel equation",
    "schlick": "Schlick 1994 from the exact F0 per wavelength",
    "f82": "F82-tint model (Hoffman 2019; Kutz et al. 2021) from exact F0 and F(82 deg)",
}


def colour_XYZ(material: Material, cos_theta: npt.ArrayLike, W: npt.NDArray[np.float64],
               method: str = "exact",
               average_range_nm: Sequence[float] = (380, 780)) -> npt.NDArray[np.float64]:
    """XYZ of the reflected light for any of :data:`COLOUR_METHODS`."""
    if method not in COLOUR_METHODS:
        raise ValueError(f"unknown colour method {method!r}; known: {', '.join(COLOUR_METHODS)}")
    if method == "approximation":
        return reflected_XYZ_approximation_CookTorrance1982(material, cos_theta, W, average_range_nm)
    return reflected_XYZ(material, cos_theta, W, method=method)


#: Columns of :func:`colour_columns` and :func:`colour_table`, in order.
COLOUR_TABLE_COLUMNS = ("method", "angle_deg", "X", "Y", "Z", "x", "y", "dominant_nm", "purity",
                        "R", "G", "B", "dE2000_vs_exact")


def colour_columns(material: Material, angles_deg: npt.ArrayLike, W: npt.NDArray[np.float64],
                   methods: Sequence[str] = ("exact"), space: str = "sRGB",
                   clip: str = "dominant-wavelength", illuminant: str = "D65",
                   average_range_nm: Sequence[float] = (380, 780), expose: bool = True,
                   observer: str = "CIE 1931 2 Degree Standard Observer"
                  ) -> dict[str, npt.NDArray[np.float64]]:
    """The audit table as columns: one row per (method, angle), with display RGB and dE2000 vs exact.

    With ``expose=True`` all rows form one scene for Cook & Torrance's exposure: they are scaled
    together (with 90 degrees among the angles, the light's own colour, F = 1, sets the scale).
    With ``expose=False`` the light's white is displayed at Y = 1 and nothing is rescaled.

    Returns a dict of :data:`COLOUR_TABLE_COLUMNS` -> 1-D array (``method`` of str, the rest
    float64): method, angle_deg, X, Y, Z, x, y, dominant_nm, purity, R, G, B, dE2000_vs_exact.
    R, G, B are display values (transfer function applied) after gamut clipping. ``illuminant``
    is not used: the white is that of ``W`` (``W.sum(0)``).
    """
    from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy, dominant_wavelength
    from reflectance.colour.difference import delta_E_CIE2000
    from reflectance.colour.display import XYZ_to_display

    angles = np.asarray(angles_deg, dtype=float)
    if angles.ndim != 1 or np.any(angles < 0) or np.any(angles > 90):
        raise ValueError(f"angles must be a list of degrees in [0, 90], got {angles_deg!r}")
    cos_theta = np.clip(np.cos(np.radians(angles)), 0.0, 1.0)
    white = W.sum(axis=0)
    white_xy = XYZ_to_xy(white)
    exact = colour_XYZ(material, cos_theta, W, "exact")
    lab_exact = XYZ_to_Lab(exact, white_xy)

    XYZ_all = np.concatenate(
        [colour_XYZ(material, cos_theta, W, m, average_range_nm) for m in methods]
    ).reshape(len(methods), len(angles), 3)
    # The white of this grid (W.sum), not the 1 nm table's, maps to display white exactly.
    RGB_all = XYZ_to_display(XYZ_all, space=space, clip=clip, expose=expose, illuminant=white,
                             observer=observer)
    blocks = []
    for i, method in enumerate(methods):
        XYZ = XYZ_all[i]
        xy = XYZ_to_xy(XYZ)
        wl, purity = dominant_wavelength(XYZ, white, observer=observer)
        dE = delta_E_CIE2000(XYZ_to_Lab(XYZ, white_xy), lab_exact)
        blocks.append([
            np.full(len(angles), method, dtype=object), angles,
            XYZ[:, 0], XYZ[:, 1], XYZ[:, 2], xy[:, 0], xy[:, 1], wl, purity,
            RGB_all[i, :, 0], RGB_all[i, :, 1], RGB_all[i, :, 2], dE,
        ])
    return {name: np.concatenate([np.asarray(block[j]) for block in blocks])
            for j, name in enumerate(COLOUR_TABLE_COLUMNS)}


def colour_table(material: Material, angles_deg: npt.ArrayLike, W: npt.NDArray[np.float64],
                 methods: Sequence[str] = ("exact"), space: str = "sRGB",
                 clip: str = "dominant-wavelength", illuminant: str = "D65",
                 average_range_nm: Sequence[float] = (380, 780), expose: bool = True,
                 observer: str = "CIE 1931 2 Degree Standard Observer") -> pd.DataFrame:
    """:func:`colour_columns` as a pandas DataFrame (same arguments, same columns)."""
    import pandas as pd

    return pd.DataFrame(colour_columns(material, angles_deg, W, methods, space, clip, illuminant,
                                       average_range_nm, expose, observer))
