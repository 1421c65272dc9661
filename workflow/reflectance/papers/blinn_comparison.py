"""Blinn 1977, Figs. 5 and 6: the Phong and Torrance-Sparrow intensities of one parameter set over
the plane of incidence, and the numbers that say how alike the two pictures are.

Blinn prints one ``p_s`` for both models, but only the Torrance-Sparrow highlight carries F; the
"matched" Phong reading scales ``p_s`` by F(0), under which the two agree for light and eye along
the normal.
"""

from __future__ import annotations

from typing import Any, Mapping

import numpy as np
import numpy.typing as npt

from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982
from reflectance.optics.microfacet import beta_to_c1_Blinn1977, c3_to_beta_Blinn1977
from reflectance.optics.shadowing import vcavity_terms_Blinn1977
from reflectance.papers.polar import intensity_in_plane_of_incidence, plane_of_incidence_vectors

__all__ = ["compare_in_plane_Blinn1977"]


def compare_in_plane_Blinn1977(s: Mapping[str, Any], theta_i: float, theta_r: npt.NDArray[np.float64],
                               corner_min_fraction: float = 0.0
                               ) -> tuple[dict[str, npt.NDArray[np.float64]], dict[str, Any]]:
    """Phong (as printed and matched) and Torrance-Sparrow over the plane of incidence, and a summary.

    Parameters
    ----------
    s : mapping
        ``label``, ``p_s``, ``p_d``, ``n`` (Fresnel index) and ``c3`` (D3); Phong's ``c1`` follows
        from Blinn's equal-beta rule.
    theta_i : float
        Angle of incidence (radians).
    theta_r : numpy.ndarray
        Signed viewing angles (radians), inside the horizon.
    corner_min_fraction : float, optional
        A corner of G goes into ``G_corners_marked`` only where the Torrance-Sparrow specular term
        is at least this fraction of its peak (elsewhere the corner is invisible).

    Returns
    -------
    values : dict
        ``phong_as_printed``, ``phong_matched`` (``p_s F(0)``) and ``torrance_sparrow`` intensities.
    row : dict
        The parameters, beta, c1, F(0); each curve's peak, its direction and its mirror value; the
        peaks' and bumps' ratios; the curves' largest difference against the Phong peak; each bump
        against the hemisphere ``p_d cos theta_i``; ``G_corners``, the indices where
        ``G = min(1, G_b, G_c)`` changes term, and ``G_corners_marked``, those of them where the
        specular term is not negligible.

    References
    ----------
    - Blinn 1977, Figs. 5 and 6 and "Facet distribution functions" (the equal-beta rule).

    Examples
    --------
    >>> import numpy as np
    >>> s = {"label": "a", "p_s": 0.4, "p_d": 0.6, "n": 200.0, "c3": 0.1}
    >>> values, row = compare_in_plane_Blinn1977(s, np.radians(30), np.radians([0.0, 30.0]))
    >>> print(f"{row['phong_matched_mirror'] - 0.6 * np.cos(np.radians(30)):.4f}")  # p_s F(0)
    0.3921
    """
    beta = c3_to_beta_Blinn1977(s["c3"])
    c1 = beta_to_c1_Blinn1977(beta)  # Blinn's equal-beta rule: D1 and D3 halve at the same angle
    F0 = float(fresnel_dielectric_CookTorrance1982(1.0, s["n"]))
    models = {  # Blinn 1977, i = p_d (N.L) + p_s s; "matched": Phong's p_s times F at E.H = 1
        "phong_as_printed": ("BlinnPhong1977", dict(c1=c1, p_s=s["p_s"])),
        "phong_matched": ("BlinnPhong1977", dict(c1=c1, p_s=s["p_s"] * F0)),
        "torrance_sparrow": ("TorranceSparrow_Blinn1977", dict(
            F=lambda c, n=s["n"]: fresnel_dielectric_CookTorrance1982(c, n),
            distribution="TrowbridgeReitz1975", c3=s["c3"], p_s=s["p_s"])),
    }
    values: dict[str, npt.NDArray[np.float64]] = {}
    row: dict[str, Any] = {"parameter_set": s["label"], **{k: s[k] for k in ("p_s", "p_d", "n", "c3")},
                           "beta_deg": np.degrees(beta), "c1": c1, "F0": F0,
                           "theta_i_deg": np.degrees(theta_i)}
    for key, (method, extra) in models.items():
        kwargs = dict(p_d=s["p_d"], **extra)
        values[key] = np.asarray(intensity_in_plane_of_incidence(theta_i, theta_r, method, **kwargs))
        peak = int(np.argmax(values[key]))
        row.update({f"{key}_max": values[key][peak], f"{key}_max_deg": np.degrees(theta_r[peak]),
                    f"{key}_mirror": float(intensity_in_plane_of_incidence(
                        theta_i, theta_i, method, **kwargs))})
    hemisphere = s["p_d"] * np.cos(theta_i)  # the diffuse part: the same in every direction
    bump = {k: row[f"{k}_max"] - hemisphere for k in values}
    row["peak_ratio_ts_to_matched"] = row["torrance_sparrow_max"] / row["phong_matched_max"]
    row["peak_ratio_ts_to_as_printed"] = row["torrance_sparrow_max"] / row["phong_as_printed_max"]
    row["bump_ratio_ts_to_matched"] = bump["torrance_sparrow"] / bump["phong_matched"]
    # how alike the two pictures are: the curves' largest difference against the Phong peak, and
    # each bump's height against the hemisphere's radius
    row["max_difference_ts_matched"] = (np.abs(values["torrance_sparrow"] - values["phong_matched"]).max()
                                        / row["phong_matched_max"])
    row["bump_to_hemisphere_matched"] = bump["phong_matched"] / hemisphere
    row["bump_to_hemisphere_ts"] = bump["torrance_sparrow"] / hemisphere
    # Blinn 1977, G = min(1, G_b, G_c): where the term in force changes, the Torrance-Sparrow
    # curve has a corner (marked, so that it does not read as an artefact)
    L, E, N = plane_of_incidence_vectors(theta_i, theta_r)
    H = (L + E) / np.linalg.norm(L + E, axis=-1, keepdims=True)
    G_b, G_c = vcavity_terms_Blinn1977(L @ N, E @ N, H @ N, np.sum(E * H, axis=-1))
    term = np.argmin(np.stack([np.ones_like(G_b), G_b, G_c]), axis=0)
    row["G_corners"] = np.flatnonzero(np.diff(term)) + 1
    specular = values["torrance_sparrow"] - hemisphere
    row["G_corners_marked"] = row["G_corners"][
        specular[row["G_corners"]] >= corner_min_fraction * specular.max()]
    return values, row
