"""Blinn 1977's scalar shading models as scene materials (his rendered Figs. 7 and 8).

Blinn's models are scalar: ``i = p_a + d p_d + s p_s`` with ``d = N.L``, Phong's ``s = (N.H)^c1``
or the Torrance-Sparrow ``s = D3 G F / (N.E)``, F the dielectric Fresnel reflectance of one index
``n`` (n = 200 for his aluminium, 1.8 for magnesium oxide). The renderer
(:mod:`reflectance.scene`) takes F from a material CSV on the spectral grid, so
:func:`write_constant_index_spectrum` writes one with a wavelength-independent index (k = 0): F is
then the exact dielectric Fresnel reflectance, with the factor 1/2 that Blinn's printing lacks, at
every wavelength, and with a spectrally flat diffuse albedo of 1 a white light gives a grey image
whose luminance Y is Blinn's intensity i (a light of intensity 1 and solid angle 1 has Y = 1).

:func:`materials_Blinn1977` gives the two scene materials Blinn compares, Phong's c1 matched to
the half-value angle beta of D3 (his equal-beta rule). How large Phong's specular proportion is
has two readings (:data:`PHONG_SPECULAR_READINGS`): Blinn prints one ``p_s`` for both models, but
his Torrance-Sparrow highlight carries F, which for MgO is 0.08 at normal incidence, and yet he
calls the front-lit images of both models "essentially same".

:func:`light_direction` places a directional light at an angle from the direction toward the
viewer: 0 is a light at the eye ("front lit"), angles towards 180 light the object from behind
("edge lit", grazing on the surfaces the viewer sees).

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (Figs. 7a, 7b, 8; D3; c1, c3 of beta.)
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from reflectance.fresnel import fresnel_dielectric_CookTorrance1982
from reflectance.microfacet import beta_to_c1_Blinn1977, c3_to_beta_Blinn1977
from reflectance.spectra import write_spectrum_csv

__all__ = [
    "PHONG_SPECULAR_READINGS",
    "write_constant_index_spectrum",
    "light_direction",
    "materials_Blinn1977",
]

PHONG_SPECULAR_READINGS = {
    "as_printed": "Phong's s p_s with Blinn's p_s: the highlight of a white mirror (F = 1)",
    "matched": "Phong's p_s times F(n) at normal incidence, so that both models agree for a "
               "light at the eye (Blinn's 'both models essentially same', front lit)",
}
"""How large Phong's specular proportion is against Blinn's Torrance-Sparrow model."""


def write_constant_index_spectrum(path, n, wavelengths_nm):
    """Write a measured-material CSV (``wavelength_nm, n, k``) of constant index ``n``, k = 0.

    Parameters
    ----------
    path : str or Path
        The CSV (named ``<material>.csv`` for :func:`reflectance.spectra.load_material`).
    n : float
        Index of refraction, > 0 (Blinn 1977 Fig. 7a: 200, Fig. 7b: 1.8).
    wavelengths_nm : array_like
        Grid the CSV must cover (its first and last values are written).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from reflectance.spectra import load_material
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> write_constant_index_spectrum(folder / "MgO_Blinn.csv", 1.8, [360, 830])
    >>> print(f"{load_material('MgO_Blinn', [400.0, 700.0], folder).F0[0]:.6f}")
    0.081633
    """
    n = float(n)
    if not (np.isfinite(n) and n > 0):
        raise ValueError(f"index of refraction n must be a finite number > 0, got {n!r}")
    w = np.asarray(wavelengths_nm, dtype=np.float64)
    if w.ndim != 1 or w.size == 0 or not np.all(np.isfinite(w)):
        raise ValueError("wavelengths_nm must be a non-empty 1-d array of finite values")
    ends = np.unique([w.min(), w.max()])
    write_spectrum_csv(pd.DataFrame({"wavelength_nm": ends, "n": n, "k": 0.0}), path)


def _unit(v, name):
    v = np.asarray(v, dtype=np.float64)
    norm = np.linalg.norm(v)
    if v.shape != (3,) or not np.isfinite(norm) or norm == 0:
        raise ValueError(f"{name} must be a non-zero 3-vector, got {v!r}")
    return v / norm


def light_direction(position, look_at, up, angle_deg, azimuth_deg):
    """Unit vector toward a directional light at ``angle_deg`` from the direction to the viewer.

    ``L = cos(a) E + sin(a) (cos(b) X + sin(b) Y)`` with E the unit vector from ``look_at`` toward
    the camera ``position``, X the image's right and Y its up (``up`` made orthogonal to E), a the
    angle and b the azimuth in the image plane (0: from the right, 90: from above).

    Parameters
    ----------
    position, look_at, up : array_like, shape (3,)
        The camera (as in the scene's ``camera``).
    angle_deg : float
        Angle between L and E, in [0, 180]: 0 front lit, near 180 lit from behind.
    azimuth_deg : float

    Returns
    -------
    numpy.ndarray, shape (3,)

    Examples
    --------
    >>> (light_direction((0, -5, 0), (0, 0, 0), (0, 0, 1), 90, 0).round(12) + 0.0).tolist()
    [1.0, 0.0, 0.0]
    """
    E = _unit(np.subtract(position, look_at), "position - look_at")
    Y = np.asarray(up, dtype=np.float64) - np.dot(up, E) * E
    Y = _unit(Y, "up (orthogonal to the view direction)")
    X = np.cross(Y, E)  # the image's right: (right, up, toward the viewer) is right-handed
    if not 0.0 <= float(angle_deg) <= 180.0:
        raise ValueError(f"angle_deg must lie in [0, 180], got {angle_deg!r}")
    a, b = np.radians(float(angle_deg)), np.radians(float(azimuth_deg))
    return np.cos(a) * E + np.sin(a) * (np.cos(b) * X + np.sin(b) * Y)


def materials_Blinn1977(p_s, p_d, c3, n, index_material, phong_specular="as_printed"):
    """Scene materials of Blinn's Phong and Torrance-Sparrow models at equal beta.

    Both have a flat diffuse albedo 1 (so ``d p_d`` is the diffuse intensity). The
    Torrance-Sparrow material takes F from ``index_material`` (a CSV of constant index ``n``,
    :func:`write_constant_index_spectrum`) and Blinn's D3 with ``c3``; the Phong material has
    ``c1 = -ln 2 / ln cos(beta)`` with beta the half-value angle of that D3.

    Parameters
    ----------
    p_s, p_d : float
        Blinn's specular and diffuse proportions (Fig. 7a: 0.4, 0.6; Fig. 7b: 0.667, 0.333).
    c3 : float
        D3 eccentricity, in (0, 2^(-1/4)).
    n : float
        The index of ``index_material`` (for the ``matched`` reading).
    index_material : str
        Name of the constant-index CSV in the scene's ``spectra_dir``.
    phong_specular : str
        A key of :data:`PHONG_SPECULAR_READINGS`.

    Returns
    -------
    dict
        ``{"phong": material, "torrance_sparrow": material}`` (scene-file mappings) and
        ``"c1"``, ``"beta_deg"``, ``"phong_s"``.

    References
    ----------
    - Blinn 1977, "Comparison with Phong shading", Fig. 7; "Facet distribution functions".

    Examples
    --------
    >>> m = materials_Blinn1977(0.667, 0.333, 0.35, 1.8, "MgO_Blinn", "matched")
    >>> print(f"{m['beta_deg']:.4f} {m['c1']:.4f} {m['phong_s']:.5f}")
    13.9141 23.2741 0.05445
    """
    if phong_specular not in PHONG_SPECULAR_READINGS:
        raise ValueError(f"unknown phong_specular reading {phong_specular!r}; known: "
                         f"{', '.join(PHONG_SPECULAR_READINGS)}")
    beta = c3_to_beta_Blinn1977(c3)
    c1 = float(beta_to_c1_Blinn1977(beta))  # Blinn 1977, equal beta: D1 and D3 halve together
    phong_s = float(p_s)
    if phong_specular == "matched":
        # Blinn 1977, s = D G F / (N.E) at a light at the eye: D = G = N.E = 1 at the highlight
        phong_s *= float(fresnel_dielectric_CookTorrance1982(1.0, n))
    return {
        "phong": {"model": "BlinnPhong1977", "c1": c1, "s": phong_s, "d": float(p_d),
                  "albedo": 1.0},  # Blinn 1977, s = (N.H)^c1
        "torrance_sparrow": {"name": index_material, "model": "TorranceSparrow_Blinn1977",
                             "distribution": "TrowbridgeReitz1975", "c3": float(c3),
                             "s": float(p_s), "d": float(p_d), "albedo": 1.0,
                             "fresnel": "exact", "convention": "paper"},  # s = D G F / (N.E)
        "c1": c1, "beta_deg": float(np.degrees(beta)), "phong_s": phong_s,
    }
