"""Errata of the four texts: the computed consequence of each, one function per erratum.

The text of each erratum (which paper, where, what is printed, what is correct, the test that
shows it) lives in ``workflow/report/errata.yaml`` under the erratum's id; the numbers live here,
in a function registered under the same id in :data:`ERRATA`. The YAML is read as text only: an
id that is not registered here, or a row with any key but the text ones, is refused
(:func:`errata_rows`), so no data file can make the workflow run code.

Each function takes the settings of config.yaml ``figures.errata`` (``n``, ``theta_deg``, ``m``,
``s``) as keywords and returns a :class:`Consequence`: the sentence with its numbers, the headline
number, and every number computed. Numbers written in the functions are the texts' own (their
printed examples) or plain geometry.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures.
- Cook, R. L., & Torrance, K. E. (1982). A reflectance model for computer graphics.
- Russin, Advanced reflection models (lecture, Module 3B).
- Wikipedia, "Specular highlight", oldid 793299363.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["Consequence", "ERRATA", "KINDS", "TEXT_KEYS", "errata_rows", "errata_table", "ErrataError"]

#: the keys an errata row may hold: all text, none of it evaluated
TEXT_KEYS = ("id", "text", "kind", "location", "printed", "correct", "test")
#: what a row is: an error of the text; two texts' conventions that differ; two texts' names for
#: one thing that differ; or a reading that may come from the transcription of the text (a symbol
#: or a built-up fraction lost), not from the text as printed
KINDS = ("erratum", "convention mismatch", "naming", "possibly a transcription artefact")
#: the columns of the errata table
COLUMNS = ["text", "kind", "location", "printed", "correct", "consequence", "value", "test"]


class ErrataError(ValueError):
    """A malformed errata file: the message names the file and the row."""


@dataclass(frozen=True)
class Consequence:
    """What an erratum changes, computed: ``text`` (a sentence with the numbers), ``value`` (the
    headline number) and ``numbers`` (every number computed, by name)."""

    text: str
    value: float
    numbers: dict = field(default_factory=dict)


#: erratum id -> ``function(**settings) -> Consequence``; filled by :func:`_erratum`
ERRATA: dict[str, Callable[..., Consequence]] = {}


def _erratum(erratum_id):
    def register(function):
        if erratum_id in ERRATA:
            raise RuntimeError(f"erratum {erratum_id!r} registered twice")
        ERRATA[erratum_id] = function
        return function
    return register


def _result(text, value, **numbers):
    return Consequence(text, float(value), {k: np.asarray(v).tolist() for k, v in numbers.items()})


# -- Blinn 1977 ---------------------------------------------------------------------------------

@_erratum("blinn-fresnel-half")
def blinn_fresnel_half(*, n, theta_deg, **_):
    """Blinn's F in terms of g and c lacks Cook & Torrance's 1/2."""
    from reflectance.optics.fresnel import fresnel_Blinn1977, fresnel_conductor

    c = np.cos(np.radians(theta_deg))
    printed_F = fresnel_Blinn1977(c, n)
    exact_F = fresnel_conductor(c, n, 0.0)
    ratio = printed_F / exact_F
    return _result(f"at theta = {theta_deg:g} deg, n = {n:g}: F = {printed_F:.4f} as printed, "
                   f"{exact_F:.4f} exact: {ratio:.4g} times too large", ratio,
                   c=c, printed_F=printed_F, exact_F=exact_F, ratio=ratio)


@_erratum("blinn-c2-inverse-width")
def blinn_c2_inverse_width(**_):
    """Blinn calls c2 a standard deviation with large values dull; it is an inverse width."""
    from reflectance.optics.microfacet import distribution_TorranceSparrow1967

    a = np.radians(10.0)
    D_c2_1 = distribution_TorranceSparrow1967(np.cos(a), 1.0)
    D_c2_10 = distribution_TorranceSparrow1967(np.cos(a), 10.0)
    beta_1 = np.degrees(np.sqrt(np.log(2.0)) / 1.0)  # Blinn: D2 = 1/2 at beta = sqrt(ln 2)/c2
    beta_10 = np.degrees(np.sqrt(np.log(2.0)) / 10.0)
    return _result(f"D2 at alpha = 10 deg: {D_c2_1:.3f} for c2 = 1, {D_c2_10:.3f} for c2 = 10; "
                   f"half-angles {beta_1:.1f} and {beta_10:.2f} deg: large c2 is the narrow, "
                   f"shiny lobe", beta_10,
                   D_c2_1=D_c2_1, D_c2_10=D_c2_10, beta_1=beta_1, beta_10=beta_10)


def _direction(polar_deg, azimuth_deg=0.0):
    t, p = np.radians(polar_deg), np.radians(azimuth_deg)
    return np.array([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])


@_erratum("blinn-triangle-2pi")
def blinn_triangle_2pi(**_):
    """Blinn's triangle 'must sum to 2 pi'; it sums to pi."""
    from reflectance.optics.shadowing import shadowing_VCavity_Blinn1977
    from reflectance.papers.vgroove import simulate_vgroove

    L = np.array([-np.sin(np.radians(10.0)), 0.0, np.cos(np.radians(10.0))])
    E = np.array([np.sin(np.radians(85.0)), 0.0, np.cos(np.radians(85.0))])
    N = np.array([0.0, 0.0, 1.0])
    H = (L + E) / np.linalg.norm(L + E)
    G_b = shadowing_VCavity_Blinn1977(N @ L, N @ E, N @ H, E @ H)
    simulated = simulate_vgroove(L, E, n_rays=20000).G_masking
    with_2pi = 2 - G_b  # f = 2 pi - (b + c): sin f = -sin(b + c), 1 - m/l = 2 - G_b
    return _result(f"Blinn's case b (light 10 deg, eye 85 deg from N): G_b = {G_b:.4f}, ray "
                   f"simulation {simulated:.4f}; the 2 pi reading gives {with_2pi:.4f} > 1",
                   with_2pi, G_b=G_b, simulated=simulated, with_2pi=with_2pi)


@_erratum("blinn-projection-of-B")
def blinn_projection_of_B(**_):
    """Blinn: 'E_p is the projection of B onto the N,H plane'; no B is defined: it is E (his
    Fig. 4 text: 'project E onto the plane containing N and H ... Calling this projection E''),
    most likely a bold E lost in the transcription. Computed: projecting E keeps N.E and H.E."""
    from reflectance.optics.shadowing import shadowing_VCavity_Blinn1977
    from reflectance.papers.vgroove import simulate_vgroove

    # light 30 deg from N, eye 80 deg from N and 100 deg round from the light's side: E off the
    # N,H plane (Blinn Fig. 2), masking (case b)
    L, E, N = _direction(30.0, 180.0), _direction(80.0, 100.0), np.array([0.0, 0.0, 1.0])
    H = (L + E) / np.linalg.norm(L + E)
    axis = np.cross(N, H) / np.linalg.norm(np.cross(N, H))  # the groove's direction
    E_p = E - (E @ axis) * axis  # the projection of E onto the N,H plane
    off_plane_deg = np.degrees(np.arcsin(abs(E @ axis)))
    NE_p, HE_p = N @ E_p, H @ E_p
    error = max(abs(NE_p - N @ E), abs(HE_p - H @ E))
    G_b = shadowing_VCavity_Blinn1977(N @ L, N @ E, N @ H, E @ H)
    simulated = simulate_vgroove(L, E, n_rays=20000).G_masking
    return _result(f"eye {off_plane_deg:.1f} deg off the N,H plane (light 30 deg, eye 80 deg from "
                   f"N): with E_p the projection of E, N.E_p = {NE_p:.4f} = N.E and H.E_p = "
                   f"{HE_p:.4f} = H.E; G_b = 2(N.H)(N.E)/(E.H) = {G_b:.4f}, ray simulation in the "
                   f"N,H plane {simulated:.4f}", G_b, off_plane_deg=off_plane_deg, NE_p=NE_p,
                   HE_p=HE_p, error=error, G_b=G_b, simulated=simulated)


@_erratum("blinn-nonnormalized-vectors")
def blinn_nonnormalized_vectors(**_):
    """Blinn: the Torrance-Sparrow function 'in terms of the vectors N, L, H and E, all of which
    are assumed to be nonnormalized'; his derivation reads N.H as cos(alpha) and E.H as c, true of
    unit vectors only (his introduction normalises them 'to a length of 1'): most likely
    'normalized'. Computed: G_b = 2(N.H)(N.E)/(E.H) of unit vectors, and of the same directions
    with N and E twice as long (H = (L + E)/len(L + E) stays unit)."""
    from reflectance.optics.shadowing import shadowing_VCavity_Blinn1977

    L, E, N = _direction(30.0, 180.0), _direction(75.0, 0.0), np.array([0.0, 0.0, 1.0])
    H = (L + E) / np.linalg.norm(L + E)

    def G_b(N, E):  # Blinn's masking term 2(N.H)(N.E)/(E.H), read with the vectors as given
        return 2 * (N @ H) * (N @ E) / (E @ H)

    long_N = 2 * N
    unit, long = G_b(N, E), G_b(long_N, 2 * E)  # (case b: the eye grazing)
    G = shadowing_VCavity_Blinn1977(N @ L, N @ E, N @ H, E @ H)
    return _result(f"light 30 deg, eye 75 deg from N: with unit vectors G_b = {unit:.4f} (G = "
                   f"{G:.4f}); with N and E of length 2, 'N.H' = {long_N @ H:.4f} is not cos(alpha) "
                   f"= {N @ H:.4f} and G_b = {long:.4f}, 4 times as large", long / unit,
                   unit=unit, long=long, G=G, cos_alpha=N @ H, long_NH=long_N @ H)


@_erratum("blinn-division-free-grouping")
def blinn_division_free_grouping(**_):
    """Blinn's last branch G := 2(N.H)(N.L)/(E.H)(N.E) read left to right (as transcribed; most
    likely a built-up fraction with (E.H)(N.E) below the bar)."""
    from reflectance.optics.shadowing import G_over_NE_Blinn1977

    NL, NE, NH, EH = 0.1, 0.6, 0.8, 0.7
    left_to_right = 2 * NH * NL / EH * NE
    grouped = G_over_NE_Blinn1977(NL, NE, NH, EH)
    ratio = left_to_right / grouped
    return _result(f"N.L = 0.1, N.E = 0.6, N.H = 0.8, E.H = 0.7: {left_to_right:.4f} left to "
                   f"right, {grouped:.4f} grouped: off by (N.E)^2 = {ratio:.4g}", ratio,
                   left_to_right=left_to_right, grouped=grouped, ratio=ratio)


@_erratum("blinn-phong-naming")
def blinn_phong_naming(*, theta_deg, **_):
    """Blinn's 'net Phong shading function' s = (N.H)^c1 is what the article calls Blinn-Phong;
    the article's (and Phong's) lobe is (R.V)^n. At Blinn's exponent 50 ('typically 50 or 60'):
    the view angles from the mirror direction, in the plane of incidence, at which each falls to
    1/2 (the light at theta_deg)."""
    from reflectance.optics.brdf import brdf
    from reflectance.papers.polar import plane_of_incidence_vectors

    c1 = 50.0
    theta_i = np.radians(theta_deg)
    offset = np.radians(np.linspace(0.0, 90.0 - theta_deg, 200001))  # towards the horizon
    L, E, N = plane_of_incidence_vectors(theta_i, theta_i + offset)
    halves = {}
    for method in ("BlinnPhong1977", "Phong1975"):
        s = (N @ L) * brdf(L, E, N, method, p_d=0.0, p_s=1.0, c1=c1)  # Blinn's s (p_s = 1)
        halves[method] = np.degrees(offset[np.argmax(s <= 0.5)])
    ratio = halves["BlinnPhong1977"] / halves["Phong1975"]
    return _result(f"c1 = 50, light at {theta_deg:g} deg: Blinn's (N.H)^c1 halves "
                   f"{halves['BlinnPhong1977']:.2f} deg from the mirror direction, Phong's (R.V)^c1 "
                   f"{halves['Phong1975']:.2f} deg: a lobe {ratio:.3g} times as wide at the same "
                   f"exponent", ratio, blinn_half_deg=halves["BlinnPhong1977"],
                   phong_half_deg=halves["Phong1975"], ratio=ratio)


# -- Cook & Torrance 1982 -----------------------------------------------------------------------

@_erratum("ct-rs-factor-4")
def ct_rs_factor_4(*, theta_deg, m, **_):
    """C&T's R_s with their D (no 1/pi) against the normalised BRDF: a factor 4."""
    from reflectance.optics.brdf import directional_albedo

    L = np.array([np.sin(np.radians(theta_deg)), 0.0, np.cos(np.radians(theta_deg))])
    paper = directional_albedo(L, "CookTorrance1982", F=1.0, m=m)
    physical = directional_albedo(L, "CookTorrance1982", F=1.0, m=m, convention="physical")
    ratio = paper / physical
    return _result(f"white furnace (F = 1, V-cavity G), incidence {theta_deg:g} deg, m = {m:g}: "
                   f"albedo {paper:.4f} as printed (reflects more than it receives), "
                   f"{physical:.4f} normalised; ratio {ratio:.4g}", ratio,
                   paper=paper, physical=physical, ratio=ratio)


# -- the lecture --------------------------------------------------------------------------------

@_erratum("lecture-fresnel-denominator")
def lecture_fresnel_denominator(*, n, **_):
    """The slide's Fresnel has c(g-c) - 1 where Cook & Torrance have + 1."""
    from reflectance.optics.fresnel import fresnel_dielectric_CookTorrance1982

    c = 1.0
    g = np.sqrt(n**2 + c**2 - 1)
    # the slide 'Fresnel Reflectance' as printed
    slide = 0.5 * (g - c) ** 2 / (g + c) ** 2 * (1 + (c * (g + c) - 1) ** 2 / (c * (g - c) - 1) ** 2)
    paper = fresnel_dielectric_CookTorrance1982(c, n)
    ratio = slide / paper
    return _result(f"at normal incidence, n = {n:g}: the slide gives F0 = {slide:.4f}, the paper "
                   f"{paper:.4f} ({ratio:.3g} x); both reach 1 at grazing", ratio,
                   g=g, slide=slide, paper=paper, ratio=ratio)


@_erratum("lecture-gaussian-m")
def lecture_gaussian_m(*, m, **_):
    """The slide's Torrance-Sparrow Gaussian exp(-(alpha m)^2) with 'm is standard deviation'."""
    from reflectance.optics.microfacet import (distribution_Gaussian_CookTorrance1982,
                                               distribution_TorranceSparrow1967)

    lecture_90 = distribution_TorranceSparrow1967(0.0, m)  # exp(-(alpha m)^2) at alpha = 90 deg
    ct_90 = distribution_Gaussian_CookTorrance1982(0.0, m)
    beta_lecture = np.degrees(np.sqrt(np.log(2.0)) / m)
    beta_ct = np.degrees(m * np.sqrt(np.log(2.0)))
    return _result(f"the same m = {m:g} in both: the lecture's D is still {lecture_90:.3f} at "
                   f"alpha = 90 deg (half-angle {beta_lecture:.0f} deg, past the horizon); C&T's "
                   f"is {ct_90:.1e} there and halves at {beta_ct:.1f} deg", lecture_90,
                   lecture_90=lecture_90, ct_90=ct_90, beta_lecture=beta_lecture, beta_ct=beta_ct)


@_erratum("lecture-specular-term")
def lecture_specular_term(*, theta_deg, m, **_):
    """The slides' 'Cook & Torrance' R_s = DGF/(N.V) is Blinn's s."""
    from reflectance.optics.brdf import brdf
    from reflectance.optics.microfacet import distribution_Beckmann1963
    from reflectance.optics.shadowing import shadowing_VCavity_Blinn1977

    mu = np.cos(np.radians(theta_deg))
    L = np.array([-np.sqrt(1 - mu * mu), 0.0, mu])
    V = np.array([np.sqrt(1 - mu * mu), 0.0, mu])
    N = np.array([0.0, 0.0, 1.0])
    ct = brdf(L, V, N, "CookTorrance1982", F=1.0, m=m)
    G = shadowing_VCavity_Blinn1977(mu, mu, 1.0, mu)
    lecture = distribution_Beckmann1963(1.0, m) * G * 1.0 / mu  # DGF/(N.V), C&T's D
    # the same with the lecture's own D, printed with 4 m^2 below the bar (slide 'Distribution of
    # Microfacet Orientations'): a quarter of C&T's D at every angle
    own_D = lecture / 4
    ratio = lecture / ct
    return _result(f"mirror direction, incidence {theta_deg:g} deg, m = {m:g}, F = 1: "
                   f"DGF/(N.V) {lecture:.4g} with C&T's D against their R_s {ct:.4g}: a factor "
                   f"{ratio:.4g} = pi cos(theta_i), which changes with the light; with the "
                   f"lecture's own D (4 m^2) {own_D:.4g}, pi cos(theta_i)/4 of C&T's R_s", ratio,
                   ct=ct, lecture=lecture, own_D=own_D, ratio=ratio)


@_erratum("lecture-blinn-phong-factor")
def lecture_blinn_phong_factor(**_):
    """The slide's (m+8)/m is (m+8)/8 against its own normalised shading equation."""
    from reflectance.optics.brdf import brdf_BlinnPhong_AkenineMoller2008

    exponent = 50.0
    normalised_over_blinn_phong = np.pi * brdf_BlinnPhong_AkenineMoller2008(1.0, 1.0, 1.0, 0.0, 1.0,
                                                                            exponent)
    printed_factor = (exponent + 8) / exponent
    ratio = normalised_over_blinn_phong / printed_factor
    return _result(f"m = 50 (Blinn's typical exponent), normal incidence: normalised / "
                   f"Blinn-Phong = {normalised_over_blinn_phong:.4g} = (m+8)/8, the printed "
                   f"(m+8)/m = {printed_factor:.4g}: {ratio:.4g} x too small", ratio,
                   normalised_over_blinn_phong=normalised_over_blinn_phong,
                   printed_factor=printed_factor, ratio=ratio)


@_erratum("lecture-glare-inverse-angle")
def lecture_glare_inverse_angle(*, theta_deg, **_):
    """The slide's 'inversely proportional to the angle' is to its cosine."""
    t = np.radians(theta_deg)
    inverse_cosine, inverse_angle = 1 / np.cos(t), 1 / t
    return _result(f"viewed {theta_deg:g} deg from N: area factor 1/cos = {inverse_cosine:.4g}; "
                   f"1/angle would give {inverse_angle:.4g} (per radian), and infinity at normal "
                   f"view", inverse_cosine, inverse_cosine=inverse_cosine, inverse_angle=inverse_angle)


# -- the article --------------------------------------------------------------------------------

# Wikipedia, "Specular highlight", "Phong distribution": the worked example's vectors.
_L_ART = np.array([-0.6, 0.8, 0.0])
_E_ART = np.array([np.sqrt(3) / 2, 0.5, 0.0])
_N_ART = np.array([0.0, 1.0, 0.0])


def _phong_k(L, E, N, exponent):
    from reflectance.optics.brdf import brdf

    return N @ L * brdf(L, E, N, "Phong1975", p_d=0.0, p_s=1.0, c1=exponent)


@_erratum("article-phong-example-cube")
def article_phong_example_cube(**_):
    """The article's (-0.5196 - 0.4)^3 = 0.9196."""
    L, E, N = _L_ART, _E_ART, _N_ART
    base = L @ (E - 2 * N * (N @ E))
    cubed = base**3
    return _result(f"the printed vectors give ({base:.4f})^3 = {cubed:.4f}, not 0.9196", cubed,
                   base=base, cubed=cubed)


@_erratum("article-phong-reflection-sign")
def article_phong_reflection_sign(**_):
    """The article's eye reflection vector E - 2N(N.E) is the mirror image of E pointing at the
    surface (the view ray); its example's E points away from it (N.E = 1/2 > 0): a convention
    mismatch, which flips the sign of L.R."""
    L, E, N = _L_ART, _E_ART, _N_ART
    printed_k = (L @ (E - 2 * N * (N @ E))) ** 3
    towards_k = (L @ (-E - 2 * N * (N @ -E))) ** 3  # E reversed: pointing from the eye at the surface
    phong_k = _phong_k(L, E, N, 3.0)
    return _result(f"the article's example (n = 3): E as printed (N.E = {N @ E:g}, towards the eye) "
                   f"gives {printed_k:.4f}; the same E pointing at the surface gives {towards_k:.4f} "
                   f"= Phong's (R.V)^n = {phong_k:.4f}", phong_k, printed_k=printed_k,
                   towards_k=towards_k, phong_k=phong_k)


@_erratum("article-phong-h-norm")
def article_phong_h_norm(**_):
    """The article's |(0.133, 0.65)| printed as 0.668."""
    length = np.linalg.norm(np.array([0.133, 0.65]))
    x_with_printed_norm = 0.133 / 0.668
    return _result(f"|(0.133, 0.65)| = {length:.5f}; dividing by the printed 0.668 would give "
                   f"x = {x_with_printed_norm:.5f}, not the printed 0.20048", length,
                   length=length, x_with_printed_norm=x_with_printed_norm)


@_erratum("article-half-vector-exponent")
def article_half_vector_exponent(**_):
    """The article's (N.H)^n approximates (R.V)^n only with about 4n."""
    L, E, N = _L_ART, _E_ART, _N_ART
    H = (L + E) / np.linalg.norm(L + E)
    k_half, k_half_4n = (N @ H) ** 3, (N @ H) ** 12
    k_phong = _phong_k(L, E, N, 3.0)
    return _result(f"(N.H)^3 = {k_half:.4f} against (R.V)^3 = {k_phong:.4f}; (N.H)^12 = "
                   f"{k_half_4n:.4f}", k_half, k_half=k_half, k_half_4n=k_half_4n, k_phong=k_phong)


@_erratum("article-heidrich-seidel-r")
def article_heidrich_seidel_r(*, s, **_):
    """The article's Heidrich-Seidel R mirrors -L; the condition 0 < R.V zeroes the highlight."""
    from reflectance.optics.brdf import brdf

    L = np.array([np.sin(0.7) * np.cos(0.5), np.sin(0.7) * np.sin(0.5), np.cos(0.7)])
    T = np.array([1.0, 0.0, 0.0])
    N = np.array([0.0, 0.0, 1.0])
    V = -(L @ T) * T + (L - (L @ T) * T)  # on the mirror cone V.T = -L.T
    R = (-L + 2 * (L @ T) * T) / np.linalg.norm(-L + 2 * (L @ T) * T)
    VR = V @ R
    printed_k = N @ L * brdf(L, V, N, "HeidrichSeidel1998", s=s, T=T, form="as_printed")
    optimised_k = N @ L * brdf(L, V, N, "HeidrichSeidel1998", s=s, T=T)
    return _result(f"V on the mirror cone, s = {s}: V.R = {VR:.3g} and k_spec = {printed_k:.3g} "
                   f"as printed; the optimised form gives {optimised_k:.3g}", printed_k,
                   VR=VR, printed_k=printed_k, optimised_k=optimised_k)


@_erratum("article-heidrich-seidel-sign")
def article_heidrich_seidel_sign(*, s, **_):
    """The article's last optimisation step drops a minus sign."""
    a_plus_b = np.pi
    correct_k = (-np.cos(a_plus_b)) ** s
    printed_k = np.cos(a_plus_b) ** s
    return _result(f"on the mirror cone (a + b = pi), s = {s}: {printed_k:.3g} as printed, "
                   f"{correct_k:.3g} correct", printed_k, correct_k=correct_k, printed_k=printed_k)


@_erratum("article-heidrich-seidel-t")
def article_heidrich_seidel_t(**_):
    """The article's T divides by |D + (-D.T) N|, using T before it is known."""
    D = np.array([0.6, 0.0, 0.8])
    N = np.array([0.0, 0.0, 1.0])
    T_unit = (D - (D @ N) * N) / np.linalg.norm(D - (D @ N) * N)
    T_printed = (D - (D @ N) * N) / np.linalg.norm(D - (D @ T_unit) * N)
    length = np.linalg.norm(T_printed)
    return _result(f"D = (0.6, 0, 0.8), N = (0, 0, 1): with the true unit T put in its own "
                   f"denominator, the printed T has length {length:.4f}, not 1", length, length=length)


# -- the table ----------------------------------------------------------------------------------

def _bad(path, where, message):
    return ErrataError(f"{path}: {where}: {message}")


def errata_rows(path: str | os.PathLike[str]) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """The errata file's texts and rows, checked: every row holds only text keys, has a
    registered id, and names one of the file's texts. Raises :class:`ErrataError` naming the file
    and the row otherwise."""
    from reflectance.io.yamlfile import YAMLFileError, read_yaml

    try:  # bounded (aliases, depth, size), no key twice
        data = read_yaml(path, encoding="utf-8-sig")
    except YAMLFileError as err:
        raise ErrataError(f"cannot read the errata rows: {err}") from None
    if not isinstance(data, dict) or set(data) != {"texts", "rows"}:
        keys = sorted(data) if isinstance(data, dict) else type(data).__name__
        raise _bad(path, "top level", f"must be a mapping with exactly 'texts' and 'rows', "
                                      f"got {keys}")
    texts, rows = data["texts"], data["rows"]
    if not isinstance(texts, dict) or not all(isinstance(v, str) for v in texts.values()):
        raise _bad(path, "texts", "must map each text's key to its name (a string)")
    if not isinstance(rows, list) or not rows:
        raise _bad(path, "rows", "must be a non-empty list")
    seen = set()
    for i, row in enumerate(rows, start=1):
        where = f"row {i}" + (f" ({row.get('id')!r})" if isinstance(row, dict) else "")
        if not isinstance(row, dict):
            raise _bad(path, where, "must be a mapping")
        unknown = sorted(set(row) - set(TEXT_KEYS), key=str)
        if unknown:
            raise _bad(path, where, f"unknown key(s) {unknown}; a row holds only text: "
                                    f"{', '.join(TEXT_KEYS)}")
        missing = [k for k in TEXT_KEYS if k not in row]
        if missing:
            raise _bad(path, where, f"missing {', '.join(missing)}")
        not_text = [k for k in TEXT_KEYS if not isinstance(row[k], str)]
        if not_text:
            raise _bad(path, where, f"{', '.join(not_text)} must be text")
        if row["id"] not in ERRATA:
            raise _bad(path, where, f"unknown erratum id {row['id']!r}; known: "
                                    f"{', '.join(ERRATA)}")
        if row["id"] in seen:
            raise _bad(path, where, f"erratum id {row['id']!r} appears twice")
        seen.add(row["id"])
        if row["kind"] not in KINDS:
            raise _bad(path, where, f"unknown kind {row['kind']!r}; known: {', '.join(KINDS)}")
        if row["text"] not in texts:
            raise _bad(path, where, f"unknown text {row['text']!r}; known: {', '.join(texts)}")
    return texts, rows


def errata_table(path: str | os.PathLike[str], settings: Mapping[str, Any]) -> pd.DataFrame:
    """The errata as a DataFrame (columns :data:`COLUMNS`): the text of each row of ``path`` with
    the consequence computed by its registered function from ``settings`` (config.yaml
    ``figures.errata`` without ``rows``)."""
    import pandas as pd

    texts, rows = errata_rows(path)
    records = []
    for row in rows:
        result = ERRATA[row["id"]](**settings)
        records.append({"text": texts[row["text"]], "kind": row["kind"], "location": row["location"],
                        "printed": row["printed"], "correct": row["correct"],
                        "consequence": result.text, "value": result.value, "test": row["test"]})
    return pd.DataFrame(records, columns=COLUMNS)
