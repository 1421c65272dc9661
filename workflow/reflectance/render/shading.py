"""Spectral shading of surface samples: the reflectance models per sample, lights, ambient, emission.

Cook & Torrance 1982, "The reflectance model": the intensity reaching the viewer is

    I_r = I_ia R_a + sum_l I_il (N.L_l) d omega_il (s R_s + d R_d),

summed here per wavelength and integrated against the CIE colour matching functions into XYZ. A
light's spectrum is the relative SPD of a colour-science illuminant scaled so that its white has
Y = 1, times the light's intensity (:func:`reflectance.colour.colorimetry.tristimulus_weights`): a
``physical`` Lambertian white of albedo 1 lit head-on by a directional light of intensity I and
solid angle w has ``Y = I w / pi``.

Two ways to integrate over wavelength (:data:`SPECTRAL_METHODS`), both exact to the grid:

- ``"brute-force"``: the model is evaluated per sample and per wavelength, with F(lambda, V.H) from
  the material's n, k, and the reflected spectrum is summed against each light's weights.
- ``"table"`` (default): in these models only F depends on both wavelength and angle (through
  ``c = V.H``); the BRDF is linear in F and in the diffuse colour, ``f = s g F + d h R``, with
  ``g`` (the BRDF with F = 1) and ``h`` (with a unit diffuse colour) scalars per sample. So
  ``XYZ_F(c) = sum_lambda F(lambda, c) W(lambda)`` is tabulated once per light spectrum over a
  uniform grid of c (Cook & Torrance's "lookup table", conclusion 4) and interpolated linearly;
  the diffuse colour integrates to one XYZ per light. Per-sample work no longer depends on the
  number of wavelengths. The tests hold the table within CIEDE2000 0.01 of brute force.

Models (:data:`SHADING_MODELS`) are those of :mod:`reflectance.optics.brdf` a renderer needs: Cook &
Torrance (any D, weighted lobes, V-cavity or Smith G, ``paper`` or ``physical``), Blinn's
Torrance-Sparrow (his D3 with a roughness texture), Blinn-Phong, Phong and Lambert. Roughness may
vary over a surface with a texture ``t(u, v)`` (:mod:`reflectance.geometry.texture`); Blinn's D3 then uses
``C3 = C_min + (1 - C_min) t`` and his ``C_min`` normalisation.

References
----------
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM
  Transactions on Graphics, 1(1), 7-24.
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. ("Varying surface shininess".)
- CIE 15:2004 Colorimetry, §7.1 (tristimulus integration), §9.1 (dominant wavelength, purity).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal, overload

import numpy as np
import numpy.typing as npt

from reflectance.optics.brdf import (brdf_BlinnPhong1977, brdf_CookTorrance1982, brdf_Lambert,
                              brdf_Phong1975, brdf_TorranceSparrow_Blinn1977)
from reflectance.colour.colorimetry import (OBSERVER_DEFAULT, cmfs, cmfs_wavelengths,
                                            tristimulus_weights, white_XYZ)
from reflectance.optics.fresnel import fresnel, fresnel_Schlick1994
from reflectance.optics.microfacet import ROUGHNESS_PARAMETERS, c3_texture_Blinn1977
from reflectance.geometry.texture import texture
from reflectance.render.lights import DirectionalLight, PointLight, light_vectors
from reflectance.render.parallel import Tasks, pieces

__all__ = [
    "SHADING_MODELS",
    "SHADOWING_NAMES",
    "SPECTRAL_METHODS",
    "AMBIENT_REFERENCES",
    "RoughnessTexture",
    "ShadingMaterial",
    "Light",
    "Ambient",
    "ambient_intensity",
    "white_card_luminance",
    "emission_XYZ",
    "fresnel_XYZ_table",
    "fresnel_XYZ_table_rgb",
    "lookup_table",
    "shade",
]

SPECTRAL_METHODS = {
    "table": "per-angle table of the integrated Fresnel XYZ over c = V.H, interpolated linearly",
    "brute-force": "the model per sample and per wavelength, summed against the light's weights",
}
"""How shading integrates over wavelength (see the module docstring)."""

SHADOWING_NAMES = {"v-cavity": "VCavity_Blinn1977", "smith": "Smith_Beckmann_Walter2007"}
"""Scene names of the shadowing-masking methods of :mod:`reflectance.optics.shadowing`."""

AMBIENT_REFERENCES = {
    "intensity": "I_ia = fraction x the lights' mean intensity (Cook & Torrance 1982 as printed: "
                 "I_ia = 0.01 I_i)",
    "irradiance": "I_ia = fraction x sum_l I_l d omega_l / pi: the ambient irradiance pi I_ia "
                  "is that fraction of the lights' normal irradiance",
    "weighted": "I_ia = fraction x sum_l I_l d omega_l: the printed 'I_ia = 0.01 I_i' with I_i "
                "read as each light as it enters the model, weighted by its d omega",
}
"""What the ambient ``fraction`` is a fraction of."""

_SAMPLE_CHUNK = 1 << 18
"""Samples shaded at once by the table path (bounds the memory of the temporaries)."""

_SPECTRAL_CHUNK = 1 << 20
"""Sample x wavelength values evaluated at once by the brute-force path."""


# --------------------------------------------------------------------------------------------
# Roughness varying over a surface
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class RoughnessTexture:
    """Roughness ``low + (high - low) t(u, v)``; for Blinn's D3, ``C3 = C_min + (1 - C_min) t``.

    ``method`` and ``parameters`` name a texture of :data:`reflectance.geometry.texture.TEXTURE_METHODS`.
    """

    method: str
    low: float
    high: float = 1.0
    parameters: dict = field(default_factory=dict)

    def values(self, uv: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        """t(u, v) at texture coordinates ``uv`` (n, 2)."""
        uv = np.asarray(uv, dtype=np.float64)
        return np.asarray(texture(uv[..., 0], uv[..., 1], self.method, **self.parameters),
                          dtype=np.float64)


# --------------------------------------------------------------------------------------------
# Materials, lights, ambient
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class ShadingMaterial:
    """A material resolved onto the wavelength grid.

    Attributes
    ----------
    model : str
        A key of :data:`SHADING_MODELS`.
    s, d : float
        Specular and diffuse fractions (Cook & Torrance's s, d; Blinn's p_s and the weight of p_d).
    n, k : ndarray or None
        Complex index of the specular material on the grid (F from :func:`reflectance.optics.fresnel
        .fresnel`); None for models without F.
    albedo : ndarray or float
        Diffuse albedo on the grid, ``pi R_d`` (Cook & Torrance: the normal reflectance F0 of the
        diffuse material, R_d = F0 / pi); also the ambient reflectance R_a = pi R_d.
    distribution : str
        A method of :data:`reflectance.optics.microfacet.DISTRIBUTION_METHODS` (not ``"mixture"``).
    roughness : float or None
        Its roughness parameter (:data:`reflectance.optics.microfacet.ROUGHNESS_PARAMETERS`).
    lobes : tuple of (weight, roughness) or None
        Several roughness scales, ``D = sum w_j D(m_j)``.
    texture : RoughnessTexture or None
    shadowing : str
        A key of :data:`SHADOWING_NAMES`.
    emission : ndarray (3,) or None
        Constant emitted XYZ (:func:`emission_XYZ`).
    """

    model: str = "CookTorrance1982"
    convention: str = "paper"
    s: float = 1.0
    d: float = 0.0
    n: np.ndarray | None = None
    k: np.ndarray | None = None
    fresnel: str = "exact"
    albedo: np.ndarray | float = 0.0
    distribution: str = "Beckmann1963"
    roughness: float | None = None
    lobes: tuple | None = None
    texture: RoughnessTexture | None = None
    shadowing: str = "v-cavity"
    emission: np.ndarray | None = None
    name: str = ""

    def __post_init__(self):
        if self.model not in SHADING_MODELS:
            raise ValueError(f"unknown shading model {self.model!r}; known: "
                             f"{', '.join(SHADING_MODELS)}")
        if self.shadowing not in SHADOWING_NAMES:
            raise ValueError(f"unknown shadowing {self.shadowing!r}; known: "
                             f"{', '.join(SHADOWING_NAMES)}")
        if SHADING_MODELS[self.model]["fresnel"] and self.s > 0 and self.n is None:
            raise ValueError(f"model {self.model} with s > 0 needs the specular material's n, k")
        if (SHADING_MODELS[self.model]["roughness"] is True and self.s > 0
                and self.roughness is None and self.lobes is None and self.texture is None):
            raise ValueError(f"model {self.model} with s > 0 needs a roughness (or lobes)")


@dataclass(frozen=True)
class Light:
    """A light: where it is (:mod:`reflectance.render.visibility`), its spectrum, intensity and size.

    ``solid_angle`` is Cook & Torrance's d omega, constant over the scene ("can be treated as a
    constant for a distant light source"); a point light may give ``area`` instead, and then
    ``d omega = area / distance^2`` per sample. ``shadows``: whether the scene's objects shadow
    this light (False: a fill light that stands for light the scene does not model, such as a
    floor's bounce, which the floor itself would otherwise block; N.L still clips it).
    """

    source: DirectionalLight | PointLight
    spectrum: str = "D65"
    intensity: float = 1.0
    solid_angle: float | None = 1.0
    area: float | None = None
    shadows: bool = True

    def __post_init__(self):
        if not isinstance(self.source, (DirectionalLight, PointLight)):
            raise ValueError("light source must be a DirectionalLight or a PointLight")
        if (self.solid_angle is None) == (self.area is None):
            raise ValueError("a light needs exactly one of solid_angle and area")
        if self.area is not None and isinstance(self.source, DirectionalLight):
            raise ValueError("a directional light has a solid angle, not an area")
        if not self.intensity >= 0:
            raise ValueError(f"light intensity must be >= 0, got {self.intensity!r}")

    def solid_angles(self, distance: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        """d omega at samples at ``distance`` from the light."""
        if self.area is not None:
            return self.area / np.maximum(distance, 1e-300) ** 2
        return np.full(np.shape(distance), float(self.solid_angle))


@dataclass(frozen=True)
class Ambient:
    """Cook & Torrance's ambient illumination ``I_ia`` (``f = 1``); see :data:`AMBIENT_REFERENCES`."""

    fraction: float = 0.0
    reference: str = "intensity"
    spectrum: str = "D65"

    def __post_init__(self):
        if self.reference not in AMBIENT_REFERENCES:
            raise ValueError(f"unknown ambient reference {self.reference!r}; known: "
                             f"{', '.join(AMBIENT_REFERENCES)}")
        if not self.fraction >= 0:
            raise ValueError(f"ambient fraction must be >= 0, got {self.fraction!r}")


def ambient_intensity(ambient: Ambient | None, lights: Sequence[Light]) -> float:
    """``I_ia`` (in units of the ambient spectrum with Y = 1) for the scene's lights.

    ``"intensity"``: Cook & Torrance 1982, Figs. 6 and 7, "I_ia = 0.01 I_i", with I_i the lights'
    mean intensity (their lights share one). ``"irradiance"``: ``fraction sum_l I_l d omega_l / pi``,
    so that the irradiance of a uniform ambient over the hemisphere, ``pi I_ia``, is that fraction
    of the lights' normal irradiance ``sum_l I_l d omega_l``. ``"weighted"``: ``fraction sum_l I_l
    d omega_l`` (pi times the irradiance reading): I_i of "I_ia = 0.01 I_i" read as the light as
    it enters the sum of Cook & Torrance's model, I_il d omega_il.

    Examples
    --------
    >>> lights = [Light(DirectionalLight((0, 0, 1)), solid_angle=1e-4),
    ...           Light(DirectionalLight((0, 1, 1)), solid_angle=2e-4)]
    >>> print(f"{ambient_intensity(Ambient(0.01, 'intensity'), lights):.4f}")
    0.0100
    >>> print(f"{ambient_intensity(Ambient(0.01, 'irradiance'), lights) * np.pi:.1e}")
    3.0e-06
    """
    if ambient is None or ambient.fraction == 0 or not lights:
        return 0.0
    if ambient.reference == "intensity":
        return ambient.fraction * float(np.mean([light.intensity for light in lights]))
    if any(light.area is not None for light in lights):
        raise ValueError(f"ambient reference {ambient.reference!r} needs every light's "
                         "solid_angle (a light given by its area has no single d omega)")
    weighted = ambient.fraction * sum(light.intensity * light.solid_angle for light in lights)
    return weighted if ambient.reference == "weighted" else weighted / np.pi


def white_card_luminance(lights: Iterable[Light]) -> float:
    """Luminance Y of a white Lambertian card (albedo 1) turned to face each light in turn, summed.

    A light of intensity I and solid angle d omega with a spectrum of Y = 1 gives a surface facing
    it the irradiance I d omega; a perfect diffuser shows it as radiance I d omega / pi. Summed over
    the lights, ``sum_l I_l d omega_l / pi``: the reference white a photographer's incident-light
    meter reads, independent of the object (the exposure of ``display.white``).

    Examples
    --------
    >>> lights = [Light(DirectionalLight((0, 0, 1)), solid_angle=1e-4),
    ...           Light(DirectionalLight((0, 1, 1)), solid_angle=2e-4)]
    >>> print(f"{white_card_luminance(lights) * np.pi:.1e}")
    3.0e-04
    """
    if any(light.area is not None for light in lights):
        raise ValueError("a white card needs every light's solid_angle (a light given by its "
                         "area has no single d omega)")
    return float(sum(light.intensity * light.solid_angle for light in lights)) / np.pi


def emission_XYZ(dominant_wavelength_nm: float, luminance: float, purity: float = 1.0,
                 white: str = "D65", observer: str = OBSERVER_DEFAULT) -> npt.NDArray[np.float64]:
    """XYZ of luminance Y on the line from a white to the spectral locus at a dominant wavelength.

    The chromaticity is ``xy_w + purity (xy_lambda - xy_w)`` with ``xy_lambda`` the spectral locus
    (the observer's CMFs, linearly interpolated between their 1 nm samples): excitation purity
    ``purity`` and dominant wavelength ``dominant_wavelength_nm`` relative to the white (CIE
    15:2004 §9.1). Cook & Torrance 1982, Fig. 8: the LEDs' "color was approximated by using a color
    with the same dominant wavelength".

    Examples
    --------
    >>> XYZ = emission_XYZ(640.0, 0.5)
    >>> print(f"{XYZ[1]:.3f}")
    0.500
    """
    table = cmfs(observer)
    grid = np.asarray(cmfs_wavelengths(observer))
    if not grid[0] <= dominant_wavelength_nm <= grid[-1]:
        raise ValueError(f"dominant wavelength {dominant_wavelength_nm} nm is outside the "
                         f"observer's {grid[0]:g}-{grid[-1]:g} nm")
    if not 0 <= purity <= 1:
        raise ValueError(f"purity must lie in [0, 1], got {purity!r}")
    bar = np.array([np.interp(dominant_wavelength_nm, grid, table[:, j]) for j in range(3)])
    xy_locus = bar[:2] / bar.sum()
    w = white_XYZ(white, observer)
    xy_white = w[:2] / w.sum()
    x, y = xy_white + purity * (xy_locus - xy_white)  # CIE 15:2004 §9.1: purity along the line
    Y = float(luminance)
    return np.array([x * Y / y, Y, (1.0 - x - y) * Y / y])


# --------------------------------------------------------------------------------------------
# The models as linear functions of F and of the diffuse colour
# --------------------------------------------------------------------------------------------

def _cook_torrance(c, F, s, d, colour, material, dist):
    if material.roughness is None and material.lobes is None and material.texture is None:
        # Cook & Torrance 1982, Table I: m "not used" (s = 0): R = d R_d, the Lambertian R_d
        return brdf_Lambert(c["NL"], c["NV"], rho_d=d * colour, convention="physical")
    return brdf_CookTorrance1982(
        c["NL"], c["NV"], c["NH"], c["VH"], F=F, s=s, d=d, R_d=colour / np.pi,  # R_d = F0/pi
        shadowing_method=SHADOWING_NAMES[material.shadowing], convention=material.convention,
        **dist)


def _torrance_sparrow(c, F, s, d, colour, material, dist):
    return brdf_TorranceSparrow_Blinn1977(c["NL"], c["NV"], c["NH"], c["VH"], F=F,
                                          p_d=d * colour, p_s=s, **dist)


def _blinn_phong(c, F, s, d, colour, material, dist):
    return brdf_BlinnPhong1977(c["NL"], c["NV"], c["NH"], p_d=d * colour, p_s=s * F,
                               c1=dist["c1"])


def _phong(c, F, s, d, colour, material, dist):
    return brdf_Phong1975(c["NL"], c["NV"], c["RV"], p_d=d * colour, p_s=s * F, c1=dist["c1"])


def _lambert(c, F, s, d, colour, material, dist):
    return brdf_Lambert(c["NL"], c["NV"], rho_d=d * colour, convention=material.convention)


SHADING_MODELS = {
    "CookTorrance1982": {"call": _cook_torrance, "fresnel": True, "roughness": True},
    "TorranceSparrow_Blinn1977": {"call": _torrance_sparrow, "fresnel": True, "roughness": True},
    "BlinnPhong1977": {"call": _blinn_phong, "fresnel": False, "roughness": "c1"},
    "Phong1975": {"call": _phong, "fresnel": False, "roughness": "c1"},
    "Lambert": {"call": _lambert, "fresnel": False, "roughness": False},
}
"""Models of :mod:`reflectance.optics.brdf` used for shading: ``call(cosines, F, s, d, colour, material,
distribution_kwargs)`` returns the BRDF, linear in ``s F`` and in ``d colour``. ``fresnel``: whether
the model has an F (models without one reflect the light's colour, F = 1); ``roughness``: whether
it takes a microfacet distribution (True), one exponent (``"c1"``) or none (False)."""


def _distribution_kwargs(material, uv, shape):
    """Keyword arguments of the model's distribution; per-sample arrays of ``shape``."""
    kind = SHADING_MODELS[material.model]["roughness"]
    if kind is False:
        return {}
    if kind == "c1":
        value = material.roughness
        if material.texture is not None:
            t = material.texture.values(uv).reshape(shape)
            value = material.texture.low + (material.texture.high - material.texture.low) * t
        return {"c1": value}
    name = material.distribution
    if material.lobes is not None:
        return {"distribution": "mixture", "base": name, "lobes": list(material.lobes)}
    if material.texture is None:
        return {"distribution": name, ROUGHNESS_PARAMETERS[name]: material.roughness}
    t = material.texture.values(uv).reshape(shape)
    if name == "TrowbridgeReitz1975":
        # Blinn 1977, "Varying surface shininess": C3 = C_min + (1 - C_min) t(u, v), and D3
        # normalised by C_min
        c_min = material.texture.low
        return {"distribution": "TrowbridgeReitz_texture_Blinn1977",
                "c3": c3_texture_Blinn1977(t, c_min), "c_min": c_min}
    low, high = material.texture.low, material.texture.high
    return {"distribution": name, ROUGHNESS_PARAMETERS[name]: low + (high - low) * t}


def _samples_of(dist, idx, n):
    """The distribution keywords of the samples ``idx`` (per-sample arrays of length n indexed,
    shared values kept)."""
    return {key: value[idx] if isinstance(value, np.ndarray) and value.ndim and len(value) == n
            else value for key, value in dist.items()}


def _cosines(N, V, L):
    """NL, NV, NH, VH, RV of unit vectors (n, 3); H = (L + V) / |L + V| (N where L = -V)."""
    Hs = L + V
    norm = np.sqrt(np.einsum("ij,ij->i", Hs, Hs))
    ok = norm > 0
    H = np.where(ok[:, None], Hs / np.where(ok, norm, 1.0)[:, None], N)
    NL = np.einsum("ij,ij->i", N, L)
    NV = np.einsum("ij,ij->i", N, V)
    LV = np.einsum("ij,ij->i", L, V)
    return {"NL": NL, "NV": NV, "NH": np.einsum("ij,ij->i", N, H),
            "VH": np.einsum("ij,ij->i", V, H), "RV": 2.0 * NL * NV - LV}


# --------------------------------------------------------------------------------------------
# The per-angle table of the integrated Fresnel term
# --------------------------------------------------------------------------------------------

def fresnel_XYZ_table(material: ShadingMaterial, W: npt.NDArray[np.float64],
                      size: int = 1025) -> npt.NDArray[np.float64]:
    """``XYZ_F(c) = sum_lambda F(lambda, c) W(lambda)`` on ``size`` equally spaced c in [0, 1].

    Parameters
    ----------
    material : ShadingMaterial
        Its n, k and Fresnel method (a model without F gives F = 1: the light's white).
    W : ndarray, shape (n_wl, 3)
        Tristimulus weights of the light (its spectrum with Y = 1, times its intensity if wanted).
    size : int

    Returns
    -------
    ndarray, shape (size, 3)
    """
    c = np.linspace(0.0, 1.0, int(size))
    if not SHADING_MODELS[material.model]["fresnel"] or material.n is None:
        return np.broadcast_to(np.sum(W, axis=0), (len(c), 3)).copy()
    rows = []
    step = max(1, _SPECTRAL_CHUNK // len(W))
    for start in range(0, len(c), step):
        F = fresnel(c[start:start + step, None], material.n, material.k, method=material.fresnel)
        rows.append(F @ W)  # Cook & Torrance 1982, "Determining the RGB values": F S x CMFs
    return np.concatenate(rows)


def fresnel_XYZ_table_rgb(material: ShadingMaterial, W: npt.NDArray[np.float64], size: int = 1025,
                          space: str = "sRGB") -> npt.NDArray[np.float64]:
    """:func:`fresnel_XYZ_table` as a three-channel RGB renderer makes it: F0 per display channel
    and Schlick 1994 per channel (:func:`reflectance.colour.display.fresnel_XYZ_rgb`) from the
    material's exact F0 under the light ``W``; same arguments and result."""
    from reflectance.colour.display import fresnel_XYZ_rgb

    c = np.linspace(0.0, 1.0, int(size))
    white = np.sum(W, axis=0)
    if not SHADING_MODELS[material.model]["fresnel"] or material.n is None:
        return np.broadcast_to(white, (len(c), 3)).copy()
    F0_XYZ = fresnel(np.ones(1), material.n, material.k, method="exact") @ W
    return fresnel_XYZ_rgb(F0_XYZ, c, white, space, fresnel=fresnel_Schlick1994)


def lookup_table(table: npt.NDArray[np.float64], c: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Linear interpolation of a table over equally spaced c in [0, 1] at cosines ``c`` (n,)."""
    last = len(table) - 1
    x = np.clip(np.asarray(c, dtype=np.float64), 0.0, 1.0) * last
    i = np.minimum(x.astype(np.int64), last - 1)
    f = (x - i)[:, None]
    return table[i] * (1.0 - f) + table[i + 1] * f


# --------------------------------------------------------------------------------------------
# Shading
# --------------------------------------------------------------------------------------------

def _light_terms(light, position, shadowed):
    """L (n, 3) and the incident energy per unit BRDF, I_l d omega (N.L is applied later)."""
    L, distance = light_vectors(light.source, position)
    energy = light.intensity * light.solid_angles(distance)
    if shadowed is not None:
        energy = np.where(shadowed, 0.0, energy)
    return L, energy


@overload
def shade(position: npt.ArrayLike, normal: npt.ArrayLike, view: npt.ArrayLike, uv: npt.ArrayLike,
          material: ShadingMaterial, lights: Sequence[Light] = (),
          shadowed: npt.ArrayLike | None = None, ambient: Ambient | None = None,
          wavelengths: npt.ArrayLike | None = None, observer: str = OBSERVER_DEFAULT,
          spectral: str = "table", table_size: int = 1025, components: Literal[False] = False,
          fresnel_table: Callable[..., Any] | None = None,
          threads: int | None = 1) -> npt.NDArray[np.float64]: ...
@overload
def shade(position: npt.ArrayLike, normal: npt.ArrayLike, view: npt.ArrayLike, uv: npt.ArrayLike,
          material: ShadingMaterial, lights: Sequence[Light] = (),
          shadowed: npt.ArrayLike | None = None, ambient: Ambient | None = None,
          wavelengths: npt.ArrayLike | None = None, observer: str = OBSERVER_DEFAULT,
          spectral: str = "table", table_size: int = 1025, *, components: Literal[True],
          fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1
          ) -> tuple[npt.NDArray[np.float64], dict[str, npt.NDArray[np.float64]]]: ...
@overload
def shade(position: npt.ArrayLike, normal: npt.ArrayLike, view: npt.ArrayLike, uv: npt.ArrayLike,
          material: ShadingMaterial, lights: Sequence[Light] = (),
          shadowed: npt.ArrayLike | None = None, ambient: Ambient | None = None,
          wavelengths: npt.ArrayLike | None = None, observer: str = OBSERVER_DEFAULT,
          spectral: str = "table", table_size: int = 1025, components: bool = False,
          fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1
          ) -> npt.NDArray[np.float64] | tuple[npt.NDArray[np.float64],
                                               dict[str, npt.NDArray[np.float64]]]: ...
def shade(position: npt.ArrayLike, normal: npt.ArrayLike, view: npt.ArrayLike, uv: npt.ArrayLike,
          material: ShadingMaterial, lights: Sequence[Light] = (),
          shadowed: npt.ArrayLike | None = None, ambient: Ambient | None = None,
          wavelengths: npt.ArrayLike | None = None, observer: str = OBSERVER_DEFAULT,
          spectral: str = "table", table_size: int = 1025, components: bool = False,
          fresnel_table: Callable[..., Any] | None = None, threads: int | None = 1
          ) -> npt.NDArray[np.float64] | tuple[npt.NDArray[np.float64],
                                               dict[str, npt.NDArray[np.float64]]]:
    """XYZ reflected (and emitted) toward the viewer by surface samples of one material.

    ``I_r = I_ia R_a + sum_l I_il (N.L_l) d omega_il R_l(lambda)`` (Cook & Torrance 1982) with
    ``R_a = pi R_d`` (the material's albedo), integrated against each light's tristimulus weights,
    plus the material's emission.

    Parameters
    ----------
    position, normal, view : array_like, shape (n, 3)
        Sample positions, unit shading normals and unit vectors toward the viewer.
    uv : array_like, shape (n, 2)
        Texture coordinates (for a roughness texture).
    material : ShadingMaterial
    lights : sequence of Light
    shadowed : array_like of bool, shape (n_lights, n), optional
        True where a light does not reach a sample (:func:`reflectance.render.visibility.shadow_masks`).
    ambient : Ambient, optional
    wavelengths : array_like
        The grid the material is resolved on (uniform, nm).
    observer : str
    spectral : str
        A key of :data:`SPECTRAL_METHODS`.
    table_size : int
        Number of c values of the Fresnel table (``spectral="table"``).
    components : bool
        Also return the parts ``{"ambient", "diffuse", "specular", "emission"}`` (brute force:
        only ``"ambient"`` and ``"emission"``).
    fresnel_table : callable, optional
        ``f(material, W, size)`` giving the Fresnel table (``spectral="table"`` only); default
        :func:`fresnel_XYZ_table`, e.g. :func:`fresnel_XYZ_table_rgb` for an RGB renderer's F.
    threads : int or None
        Threads of the table path's per-sample work (:mod:`reflectance.render.parallel`; None:
        the default count): pieces of samples, each shaded as alone; the same result at any
        count.

    Returns
    -------
    ndarray (n, 3), or (ndarray, dict) with ``components=True``
    """
    if spectral not in SPECTRAL_METHODS:
        raise ValueError(f"unknown spectral method {spectral!r}; known: "
                         f"{', '.join(SPECTRAL_METHODS)}")
    if wavelengths is None:
        raise ValueError("shade needs the wavelength grid the material is resolved on")
    if fresnel_table is not None and spectral != "table":
        raise ValueError("fresnel_table needs spectral='table'")
    fresnel_table = fresnel_XYZ_table if fresnel_table is None else fresnel_table
    position, normal, view = (np.asarray(a, dtype=np.float64).reshape(-1, 3)
                              for a in (position, normal, view))
    uv = np.asarray(uv, dtype=np.float64).reshape(-1, 2)
    n = len(position)
    lights = list(lights)
    if shadowed is not None:
        shadowed = np.asarray(shadowed, dtype=bool).reshape(len(lights), n)
    # each light's spectrum with Y = 1 (its intensity and d omega enter through the energy)
    W = [tristimulus_weights(wavelengths, light.spectrum, observer) for light in lights]
    albedo = np.broadcast_to(np.asarray(material.albedo, dtype=np.float64), (len(wavelengths),))
    call = SHADING_MODELS[material.model]["call"]
    total, direct = np.zeros((n, 3)), None

    # Cook & Torrance 1982: I_ia R_a with R_a = pi R_d = the albedo, f = 1; and the emission:
    # the same XYZ for every sample, added at the end
    ambient_XYZ, emitted = np.zeros(3), np.zeros(3)
    I_ia = ambient_intensity(ambient, lights)
    if I_ia > 0:
        ambient_XYZ = I_ia * (albedo @ tristimulus_weights(wavelengths, ambient.spectrum,
                                                           observer))
    if material.emission is not None:
        emitted = np.asarray(material.emission, dtype=np.float64)

    if spectral == "table":
        direct = {"diffuse": np.zeros((n, 3)), "specular": np.zeros((n, 3))} if components \
            else None
        by_spectrum = {}  # one table per light spectrum (intensities enter through the energy)
        for light, w in zip(lights, W):
            if material.s > 0 and light.spectrum not in by_spectrum:
                by_spectrum[light.spectrum] = fresnel_table(material, w, table_size)
        tables = [by_spectrum.get(light.spectrum) for light in lights]
        diffuse_XYZ = [albedo @ w for w in W]

        def shade_piece(sl):  # every sample's value depends on that sample alone
            dist = _distribution_kwargs(material, uv[sl], (sl.stop - sl.start,))
            for i, light in enumerate(lights):
                L, energy = _light_terms(light, position[sl],
                                         None if shadowed is None else shadowed[i, sl])
                c = _cosines(normal[sl], view[sl], L)
                energy = energy * np.maximum(c["NL"], 0.0)  # E_i = I_i (N.L) d omega_i
                # a sample the light does not reach (shadowed, or N.L <= 0) adds 0 x the
                # (finite) BRDF, i.e. nothing: the model is evaluated where the light arrives
                lit = np.flatnonzero(energy != 0.0)
                at, c_lit, dist_lit = sl, c, dist
                if len(lit) < len(energy):
                    at, energy = lit + sl.start, energy[lit]
                    c_lit = {key: value[lit] for key, value in c.items()}
                    dist_lit = _samples_of(dist, lit, len(c["NL"]))
                if material.s > 0:
                    g = call(c_lit, 1.0, 1.0, 0.0, 0.0, material, dist_lit)  # the BRDF for F = 1
                    value = ((material.s * energy * g)[:, None]
                             * lookup_table(tables[i], c_lit["VH"]))
                    total[at] += value
                    if components:
                        direct["specular"][at] += value
                if material.d > 0:
                    h = call(c_lit, 0.0, 0.0, 1.0, 1.0, material, dist_lit)  # for a unit colour
                    value = (material.d * energy * h)[:, None] * diffuse_XYZ[i]
                    total[at] += value
                    if components:
                        direct["diffuse"][at] += value

        tasks = Tasks(threads)  # the pieces write disjoint rows
        tasks.map(shade_piece, pieces(n, tasks.threads, _SAMPLE_CHUNK))
    else:
        # brute force: the model per wavelength, F(lambda, V.H) from n, k, summed against W
        step = max(1, _SPECTRAL_CHUNK // len(wavelengths))
        has_F = SHADING_MODELS[material.model]["fresnel"] and material.n is not None
        for start in range(0, n, step):
            sl = slice(start, min(n, start + step))
            dist = _distribution_kwargs(material, uv[sl], (sl.stop - sl.start, 1))
            for i, light in enumerate(lights):
                L, energy = _light_terms(light, position[sl],
                                         None if shadowed is None else shadowed[i, sl])
                c = {k: v[:, None] for k, v in _cosines(normal[sl], view[sl], L).items()}
                F = (fresnel(c["VH"], material.n, material.k, method=material.fresnel) if has_F
                     else 1.0)
                R = call(c, F, material.s, material.d, albedo, material, dist)  # (m, n_wl)
                E = energy[:, None] * np.maximum(c["NL"], 0.0)  # I_l d omega_l (N.L)
                total[sl] += (E * R) @ W[i]  # CIE 15:2004 §7.1: sum over wavelength
    total += ambient_XYZ + emitted
    if not components:
        return total
    parts = {"ambient": np.broadcast_to(ambient_XYZ, (n, 3)).copy(),
             "emission": np.broadcast_to(emitted, (n, 3)).copy()}
    parts.update(direct if direct is not None else {})
    return total, parts
