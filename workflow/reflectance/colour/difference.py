"""Colour differences: CIEDE2000, per colour and over images.

:func:`delta_E_CIE2000` is the formula; the rest compare two XYZ images as a display shows them
(both scaled by one exposure, in CIELAB of the display white): :func:`dE2000_map` per pixel, and
the statistics the renderer's checks report over the lit pixels (:func:`dE2000_statistics`,
:func:`pixel_difference_CIEDE2000` and its mean with the 95th percentile or the maximum).

References
----------
-   CIE 142:2001 / CIE 15:2004 §8.3.4, Improvement to industrial colour-difference evaluation
    (CIEDE2000).
-   Sharma, G., Wu, W., & Dalal, E. N. (2005). The CIEDE2000 color-difference formula:
    Implementation notes, supplementary test data, and mathematical observations. Color Research &
    Application, 30(1), 21-30. doi:10.1002/col.20070
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["delta_E_CIE2000", "dE2000_map", "dE2000_statistics", "pixel_difference_CIEDE2000",
           "difference_statistics_CIEDE2000", "image_difference_CIEDE2000"]


def delta_E_CIE2000(Lab_1: npt.ArrayLike, Lab_2: npt.ArrayLike,
                    textiles: bool = False) -> npt.NDArray[np.float64]:
    """CIEDE2000 colour difference of CIE L*a*b* colours (L* 0-100), element-wise.

    Follows Sharma, Wu & Dalal (2005), equations (1)-(22), with their conventions for the
    hue angle of a neutral colour (h' = 0 where a' = b = 0) and for the mean hue and hue
    difference when a chroma is 0. The order of operations is colour-science's
    (``colour.difference.delta_E_CIE2000``), which this reproduces to float precision.

    Parameters
    ----------
    Lab_1, Lab_2 : array_like
        Shape ``(..., 3)``, broadcastable.
    textiles : bool
        Use k_L = 2 (textiles) instead of 1 (graphic arts, the default).

    Returns
    -------
    numpy.ndarray
        Shape of the broadcast ``(...)``.

    References
    ----------
    Sharma, Wu & Dalal (2005), section "The CIEDE2000 color-difference formula".

    Examples
    --------
    >>> float(delta_E_CIE2000([50.0, 2.6772, -79.7751], [50.0, 0.0, -82.7485]).round(4))
    2.0425
    """
    L_1, a_1, b_1 = np.moveaxis(np.asarray(Lab_1, dtype=np.float64), -1, 0)
    L_2, a_2, b_2 = np.moveaxis(np.asarray(Lab_2, dtype=np.float64), -1, 0)

    # Sharma et al. 2005, eq. (2)-(3): mean chroma and the a* scaling G.
    C_1_ab = np.hypot(a_1, b_1)
    C_2_ab = np.hypot(a_2, b_2)
    C_bar_ab = (C_1_ab + C_2_ab) / 2
    C_bar_ab_7 = C_bar_ab**7
    G = 0.5 * (1 - np.sqrt(C_bar_ab_7 / (C_bar_ab_7 + 25**7)))

    # Eq. (4)-(7): a', C', h' (degrees in [0, 360); 0 for a neutral colour).
    a_p_1 = (1 + G) * a_1
    a_p_2 = (1 + G) * a_2
    C_p_1 = np.hypot(a_p_1, b_1)
    C_p_2 = np.hypot(a_p_2, b_2)
    h_p_1 = np.where((b_1 == 0) & (a_p_1 == 0), 0, np.degrees(np.arctan2(b_1, a_p_1)) % 360)
    h_p_2 = np.where((b_2 == 0) & (a_p_2 == 0), 0, np.degrees(np.arctan2(b_2, a_p_2)) % 360)

    # Eq. (8)-(11): differences in L', C', h' and H'.
    delta_L_p = L_2 - L_1
    delta_C_p = C_p_2 - C_p_1
    h_p_2_s_1 = h_p_2 - h_p_1
    C_p_1_m_2 = C_p_1 * C_p_2
    delta_h_p = np.select(
        [C_p_1_m_2 == 0, np.fabs(h_p_2_s_1) <= 180, h_p_2_s_1 > 180, h_p_2_s_1 < -180],
        [0, h_p_2_s_1, h_p_2_s_1 - 360, h_p_2_s_1 + 360],
    )
    delta_H_p = 2 * np.sqrt(C_p_1_m_2) * np.sin(np.deg2rad(delta_h_p / 2))

    # Eq. (12)-(14): means of L', C' and h'.
    L_bar_p = (L_1 + L_2) / 2
    C_bar_p = (C_p_1 + C_p_2) / 2
    a_h_p_1_s_2 = np.fabs(h_p_1 - h_p_2)
    h_p_1_a_2 = h_p_1 + h_p_2
    h_bar_p = np.select(
        [
            C_p_1_m_2 == 0,
            a_h_p_1_s_2 <= 180,
            (a_h_p_1_s_2 > 180) & (h_p_1_a_2 < 360),
            (a_h_p_1_s_2 > 180) & (h_p_1_a_2 >= 360),
        ],
        [h_p_1_a_2, h_p_1_a_2 / 2, (h_p_1_a_2 + 360) / 2, (h_p_1_a_2 - 360) / 2],
    )

    # Eq. (15)-(21): T, the rotation term and the weighting functions.
    T = (
        1
        - 0.17 * np.cos(np.deg2rad(h_bar_p - 30))
        + 0.24 * np.cos(np.deg2rad(2 * h_bar_p))
        + 0.32 * np.cos(np.deg2rad(3 * h_bar_p + 6))
        - 0.20 * np.cos(np.deg2rad(4 * h_bar_p - 63))
    )
    delta_theta = 30 * np.exp(-(((h_bar_p - 275) / 25) ** 2))
    C_bar_p_7 = C_bar_p**7
    R_C = 2 * np.sqrt(C_bar_p_7 / (C_bar_p_7 + 25**7))
    L_bar_p_2 = (L_bar_p - 50) ** 2
    S_L = 1 + ((0.015 * L_bar_p_2) / np.sqrt(20 + L_bar_p_2))
    S_C = 1 + 0.045 * C_bar_p
    S_H = 1 + 0.015 * C_bar_p * T
    R_T = -np.sin(np.deg2rad(2 * delta_theta)) * R_C

    # Eq. (22).
    k_L, k_C, k_H = (2 if textiles else 1), 1, 1
    return np.sqrt(
        (delta_L_p / (k_L * S_L)) ** 2
        + (delta_C_p / (k_C * S_C)) ** 2
        + (delta_H_p / (k_H * S_H)) ** 2
        + R_T * (delta_C_p / (k_C * S_C)) * (delta_H_p / (k_H * S_H))
    )


def dE2000_map(XYZ: npt.ArrayLike, XYZ_reference: npt.ArrayLike, scale: float,
               white: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """CIEDE2000 per pixel of two XYZ images, both scaled by ``scale``, in CIELAB of ``white``.

    Parameters
    ----------
    XYZ, XYZ_reference : array_like, shape (..., 3)
    scale : float
        Exposure (the reference's display scale: the difference as the figure shows it).
    white : array_like, shape (3,)
        The display white, Y = 1.
    """
    from reflectance.colour.colorimetry import XYZ_to_Lab

    white = np.asarray(white, dtype=np.float64)
    xy = white[:2] / white.sum()
    lab = [XYZ_to_Lab(np.asarray(x, dtype=np.float64) * scale, xy) for x in (XYZ, XYZ_reference)]
    return delta_E_CIE2000(lab[0], lab[1])


def dE2000_statistics(dE: npt.ArrayLike, mask: npt.ArrayLike,
                      percentile: float = 95.0) -> dict[str, float]:
    """``{"mean", "p<percentile>", "max"}`` of ``dE`` over ``mask`` (NaN if the mask is empty)."""
    values = np.asarray(dE)[np.asarray(mask, dtype=bool)]
    if values.size == 0:
        return {"mean": np.nan, f"p{percentile:g}": np.nan, "max": np.nan}
    return {"mean": float(values.mean()), f"p{percentile:g}": float(np.percentile(values, percentile)),
            "max": float(values.max())}


def pixel_difference_CIEDE2000(XYZ: npt.ArrayLike, XYZ_reference: npt.ArrayLike,
                               illuminant: str = "D65", observer: str | None = None,
                               wavelengths: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
    """CIEDE2000 of each pixel of two XYZ images that is not black in either, on the
    reference's Cook & Torrance exposure (as :func:`image_difference_CIEDE2000`): a 1-D array."""
    from reflectance.colour.colorimetry import OBSERVER_DEFAULT, white_XYZ
    from reflectance.colour.display import expose_CookTorrance1982

    observer = observer or OBSERVER_DEFAULT
    _, scale = expose_CookTorrance1982(XYZ_reference, "sRGB", illuminant, observer, wavelengths)
    dE = dE2000_map(XYZ, XYZ_reference, scale, white_XYZ(illuminant, observer, wavelengths))
    lit = (np.asarray(XYZ)[..., 1] > 0) | (np.asarray(XYZ_reference)[..., 1] > 0)
    return dE[lit]


def _mean_and(dE, statistic):
    """(mean, ``statistic``) of the differences ``dE``; (0, 0) when there are none."""
    if not len(dE):
        return 0.0, 0.0
    return float(dE.mean()), float(statistic(dE))


def difference_statistics_CIEDE2000(XYZ: npt.ArrayLike, XYZ_reference: npt.ArrayLike,
                                    illuminant: str = "D65", observer: str | None = None,
                                    wavelengths: npt.ArrayLike | None = None
                                   ) -> tuple[float, float]:
    """(mean, 95th percentile) of :func:`pixel_difference_CIEDE2000`; (0, 0) when no pixel is
    lit."""
    return _mean_and(pixel_difference_CIEDE2000(XYZ, XYZ_reference, illuminant, observer,
                                                wavelengths), lambda dE: np.percentile(dE, 95))


def image_difference_CIEDE2000(XYZ: npt.ArrayLike, XYZ_reference: npt.ArrayLike,
                               illuminant: str = "D65", observer: str | None = None,
                               wavelengths: npt.ArrayLike | None = None) -> tuple[float, float]:
    """(mean, max) CIEDE2000 of two XYZ images on the reference's Cook & Torrance exposure.

    Both images are scaled by the exposure of ``XYZ_reference`` (so that its brightest colour
    sits at the display maximum, as it would be shown), then compared in CIELAB relative to the
    illuminant's white (Y = 1). The mean is over the pixels where either image is not black.
    """
    return _mean_and(pixel_difference_CIEDE2000(XYZ, XYZ_reference, illuminant, observer,
                                                wavelengths), np.max)
