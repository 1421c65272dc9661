"""CAM16 and CAM16-UCS with numpy only (Li et al. 2017), for the shortcut audit's start-up time.

colour-science has both (``colour.XYZ_to_CAM16``, ``colour.XYZ_to_CAM16UCS``); importing it takes
seconds, which dominated ``reflectance audit``. The forward model here follows Li et al. 2017,
Part II, steps 1-7, as colour-science implements it (its tests hold the two within 1e-9), and
keeps only what the audit needs: J, C, h, M and the UCS coordinates J', a', b'.

References
----------
Li, C., Li, Z., Wang, Z., Xu, Y., Luo, M. R., Cui, G., Melgosa, M., Brill, M. H., & Pointer, M.
(2017). Comprehensive color solutions: CAM16, CAT16, and CAM16-UCS. Color Research & Application,
42(6), 703-718.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["CAM16_SURROUNDS", "XYZ_to_CAM16", "XYZ_to_CAM16UCS"]

#: Li et al. 2017, Table 1 (as CIECAM02): surround -> (F, c, N_c)
CAM16_SURROUNDS = {"Average": (1.0, 0.69, 1.0), "Dim": (0.9, 0.59, 0.9), "Dark": (0.8, 0.525, 0.8)}

#: Li et al. 2017, eq. 1: the CAT16 matrix M_16
M_16 = np.array([[0.401288, 0.650173, -0.051461],
                 [-0.250268, 1.204414, 0.045854],
                 [-0.002079, 0.048952, 0.953127]])


def _compress(RGB, F_L):
    """Li et al. 2017, step 3: post-adaptation non-linear response compression."""
    F_L_RGB = (F_L[..., None] * np.abs(RGB) / 100.0) ** 0.42
    return 400.0 * np.sign(RGB) * F_L_RGB / (27.13 + F_L_RGB) + 0.1


def XYZ_to_CAM16(XYZ: npt.ArrayLike, XYZ_w: npt.ArrayLike, L_A: float, Y_b: float,
                 surround: str = "Average") -> dict[str, npt.NDArray[np.float64]]:
    """CAM16 lightness J, chroma C, hue angle h (degrees) and colourfulness M.

    Parameters
    ----------
    XYZ : array_like, shape (..., 3)
        Stimulus, Y of the white = 100 scale.
    XYZ_w : array_like, shape (3,)
        Adopted white, same scale.
    L_A : float
        Adapting field luminance, cd/m^2.
    Y_b : float
        Relative luminance of the background.
    surround : str
        A key of :data:`CAM16_SURROUNDS`.

    Returns
    -------
    dict
        ``{"J", "C", "h", "M"}``, arrays of shape ``XYZ.shape[:-1]``.
    """
    if surround not in CAM16_SURROUNDS:
        raise ValueError(f"unknown surround {surround!r}; known: {', '.join(CAM16_SURROUNDS)}")
    F, c, N_c = CAM16_SURROUNDS[surround]
    XYZ = np.asarray(XYZ, dtype=np.float64)
    XYZ_w = np.asarray(XYZ_w, dtype=np.float64)
    Y_w = XYZ_w[1]
    # Step 0: viewing-condition dependent parameters
    k = 1.0 / (5.0 * L_A + 1.0)
    F_L = np.asarray(0.2 * k ** 4 * (5.0 * L_A) + 0.1 * (1.0 - k ** 4) ** 2 * (5.0 * L_A) ** (1 / 3))
    n = Y_b / Y_w
    z = 1.48 + np.sqrt(n)
    N_bb = 0.725 * (1.0 / n) ** 0.2
    D = np.clip(F * (1.0 - (1.0 / 3.6) * np.exp((-L_A - 42.0) / 92.0)), 0.0, 1.0)
    RGB_w = M_16 @ XYZ_w
    D_RGB = D * Y_w / RGB_w + 1.0 - D
    RGB_aw = _compress(D_RGB * RGB_w, F_L)
    A_w = (2.0 * RGB_aw[0] + RGB_aw[1] + 0.05 * RGB_aw[2] - 0.305) * N_bb
    # Steps 1-3: CAT16, complete adaptation, compression
    RGB_a = _compress(D_RGB * (XYZ @ M_16.T), F_L)
    R, G, B = RGB_a[..., 0], RGB_a[..., 1], RGB_a[..., 2]
    # Step 4: opponent coordinates and hue angle
    a = R - 12.0 * G / 11.0 + B / 11.0
    b = (R + G - 2.0 * B) / 9.0
    h = np.degrees(np.arctan2(b, a)) % 360.0
    # Step 5: eccentricity
    e_t = 0.25 * (np.cos(np.radians(h) + 2.0) + 3.8)
    # Steps 6-7: achromatic response, lightness, chroma, colourfulness
    A = (2.0 * R + G + 0.05 * B - 0.305) * N_bb
    with np.errstate(invalid="ignore", divide="ignore"):
        J = 100.0 * np.abs(A / A_w) ** (c * z) * np.sign(A / A_w)
        t = (50000.0 / 13.0 * N_c * N_bb * e_t * np.hypot(a, b)) / (R + G + 21.0 / 20.0 * B)
        C = t ** 0.9 * np.sqrt(J / 100.0) * (1.64 - 0.29 ** n) ** 0.73
    return {"J": J, "C": C, "h": h, "M": C * F_L ** 0.25}


def XYZ_to_CAM16UCS(XYZ: npt.ArrayLike, XYZ_w: npt.ArrayLike, L_A: float, Y_b: float,
                    surround: str = "Average") -> npt.NDArray[np.float64]:
    """CAM16-UCS J', a', b' (Li et al. 2017, eqs. 24-26; Luo et al. 2006's UCS constants).

    Same arguments as :func:`XYZ_to_CAM16`; the CAM16-UCS colour difference is the Euclidean
    distance of two results.
    """
    cam = XYZ_to_CAM16(XYZ, XYZ_w, L_A, Y_b, surround)
    J_p = 1.7 * cam["J"] / (1.0 + 0.007 * cam["J"])
    M_p = np.log1p(0.0228 * cam["M"]) / 0.0228
    h = np.radians(cam["h"])
    return np.stack([J_p, M_p * np.cos(h), M_p * np.sin(h)], axis=-1)
