"""Blinn's derivation of G from the V-groove (Blinn 1977, Figs. 1-4), measured on a simulation.

- :func:`vgroove_case`: the light and eye directions of one case of Fig. 1, the ray simulation
  of :func:`reflectance.papers.vgroove.simulate_vgroove`, and the closed forms ``G_b``, ``G_c``
  (:func:`reflectance.optics.shadowing.vcavity_terms_Blinn1977`) and ``G = min(1, G_b, G_c)``
  (:func:`reflectance.optics.shadowing.shadowing_VCavity_Blinn1977`) side by side.
- :func:`groove_angles_Blinn1977`: the law-of-sines construction of Fig. 4.

Blinn derives ``G_b = 1 - m/l`` from the triangle formed by the bottom B of the groove, the top C
of the side opposite the reflecting facet AB, and the point P where the ray through C along E'
(the projection of E onto the plane of N and H) meets AB: ``m = |BP|`` is the part of the facet
whose reflection is masked, ``l = |AB| = |BC|`` the facet length, and the law of sines gives
``m/l = sin f / sin b``. His angles (Fig. 4) are

- ``a``: between N and H (the facet tilt, alpha);
- ``b``: the triangle's angle at P (between PB and PC);
- ``c``: the angle at B, the groove's opening angle;
- ``d``: between a side and the vertical through B (half of c, complementary to a);
- ``e``: between H and E' (the angle of reflection on the facet);
- ``f``: the triangle's angle at C (between CB and CP).

:func:`groove_angles_Blinn1977` measures each of them from the points of a
:class:`reflectance.papers.vgroove.VGrooveSimulation` (with ``atan2``, not from Blinn's trigonometric
relations), so that the relations ``sin b = cos e``, ``c = 2 d``, ``d = pi/2 - a`` and
``m/l = sin f / sin b = 1 - G_b`` can be checked against them. For shadowing (case c) the roles
of L and E are exchanged, as Blinn says.

References
----------
- Blinn, J. F. (1977). Models of light reflection for computer synthesized pictures. Computer
  Graphics (SIGGRAPH '77), 11(2), 192-198. (Figs. 1-4, G_b, G_c.)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, TYPE_CHECKING

import numpy as np

from reflectance.papers.polar import direction_from_angles
from reflectance.optics.shadowing import shadowing_VCavity_Blinn1977, vcavity_terms_Blinn1977
from reflectance.papers.vgroove import simulate_vgroove

if TYPE_CHECKING:
    from reflectance.papers.vgroove import VGrooveSimulation

__all__ = ["vgroove_case", "GrooveAngles", "groove_angles_Blinn1977"]


def vgroove_case(light: Mapping[str, Any], eye: Mapping[str, Any], n_rays: int = 100_000,
                 n_keep: int = 24) -> tuple[VGrooveSimulation, dict[str, Any]]:
    """One case of Blinn's Fig. 1: simulate the groove and evaluate the closed forms.

    Parameters
    ----------
    light, eye : mapping
        ``{"theta_deg": ..., "phi_deg": ...}``: angle from N and azimuth of L and E (degrees).
    n_rays, n_keep : int
        Passed to :func:`reflectance.papers.vgroove.simulate_vgroove`.

    Returns
    -------
    simulation : reflectance.papers.vgroove.VGrooveSimulation
    row : dict
        ``L``, ``E``, ``H`` (3-vectors), the cosines ``NL``, ``NE``, ``NH``, ``EH``, the closed forms
        ``G_b``, ``G_c``, ``G_closed`` (``min(1, G_b, G_c)``) and the simulated ``G_simulated``,
        ``G_masking_simulated``, ``G_shadowing_simulated``, ``alpha_deg`` and ``case``.

    Examples
    --------
    >>> sim, row = vgroove_case({"theta_deg": 75, "phi_deg": 0}, {"theta_deg": 15, "phi_deg": 180},
    ...                         n_rays=20000)
    >>> print(row["case"], f"{row['G_closed']:.4f}", f"{row['G_simulated']:.4f}")
    c 0.6340 0.6340
    """
    L = direction_from_angles(np.radians(light["theta_deg"]), np.radians(light["phi_deg"]))
    E = direction_from_angles(np.radians(eye["theta_deg"]), np.radians(eye["phi_deg"]))
    N = np.array([0.0, 0.0, 1.0])
    H = (L + E) / np.linalg.norm(L + E)  # Blinn 1977, H = (L + E) / len(L + E)
    simulation = simulate_vgroove(L, E, N, n_rays=n_rays, n_keep=n_keep)
    NL, NE, NH, EH = L @ N, E @ N, N @ H, E @ H
    G_b, G_c = vcavity_terms_Blinn1977(NL, NE, NH, EH)
    row = {
        "L": L, "E": E, "H": H, "NL": NL, "NE": NE, "NH": NH, "EH": EH,
        "G_b": float(G_b), "G_c": float(G_c),
        "G_closed": float(shadowing_VCavity_Blinn1977(NL, NE, NH, EH)),
        "G_simulated": simulation.G, "G_masking_simulated": simulation.G_masking,
        "G_shadowing_simulated": simulation.G_shadowing,
        "alpha_deg": float(np.degrees(simulation.alpha)), "case": simulation.case,
    }
    return simulation, row


@dataclass(frozen=True)
class GrooveAngles:
    """Blinn's Fig. 4 construction (angles in radians, points in groove-plane coordinates (u, w)).

    Attributes
    ----------
    a, b, c, d, e, f : float
        Blinn's angles (see the module docstring).
    A, B, C, P : numpy.ndarray
        (2,) the groove vertices and the point where the ray through C meets the facet AB.
    direction : numpy.ndarray
        (2,) unit E' (masking) or L' (shadowing).
    m, l : float
        ``|BP|`` and ``|AB|``.
    m_over_l_lengths, m_over_l_sines : float
        ``m / l`` from the two lengths and from Blinn's law of sines ``sin f / sin b``.
    """

    a: float
    b: float
    c: float
    d: float
    e: float
    f: float
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    P: np.ndarray
    direction: np.ndarray
    m: float
    l: float  # noqa: E741 (Blinn's name for the facet length)
    m_over_l_lengths: float
    m_over_l_sines: float


def _angle(u, v):
    """Unsigned angle between 2-D vectors u and v, by atan2 (accurate near 0 and pi)."""
    return float(np.arctan2(abs(u[0] * v[1] - u[1] * v[0]), u @ v))


def groove_angles_Blinn1977(simulation: VGrooveSimulation,
                            blocked: str = "masking") -> GrooveAngles:
    """Measure Blinn's Fig. 4 angles a..f and m/l on a simulated groove.

    Parameters
    ----------
    simulation : reflectance.papers.vgroove.VGrooveSimulation
        A result of :func:`reflectance.papers.vgroove.simulate_vgroove`.
    blocked : str
        ``"masking"`` (Blinn's case b, the ray along E') or ``"shadowing"`` (case c, along L').

    Returns
    -------
    GrooveAngles

    Raises
    ------
    ValueError
        For an unknown ``blocked``, or when nothing of the facet is blocked that way (the triangle
        of Fig. 4 does not exist).

    References
    ----------
    - Blinn 1977, Fig. 4 and the derivation of G_b.

    Examples
    --------
    >>> import numpy as np
    >>> from reflectance.papers.vgroove import simulate_vgroove
    >>> L = np.array([-np.sin(0.3), 0.0, np.cos(0.3)]); E = np.array([np.sin(1.3), 0.0, np.cos(1.3)])
    >>> g = groove_angles_Blinn1977(simulate_vgroove(L, E, n_rays=1000))
    >>> print(f"{g.m_over_l_sines:.6f} {g.m_over_l_lengths:.6f}")  # 1 - G_b, G_b = 2 cos(.5) cos(1.3) / cos(.8)
    0.326109 0.326109
    """
    if blocked == "masking":
        direction, m, P = simulation.E2, simulation.m_masking, simulation.masking_point
    elif blocked == "shadowing":
        direction, m, P = simulation.L2, simulation.m_shadowing, simulation.shadowing_point
    else:
        raise ValueError(f"Unknown 'blocked' {blocked!r}; known: masking, shadowing.")
    if not m > 0:
        raise ValueError(
            f"No {blocked} in this geometry (Blinn case {simulation.case!r}): the triangle of "
            "Blinn's Fig. 4 does not exist."
        )
    A, B, C = (np.asarray(v, dtype=np.float64) for v in simulation.vertices)
    P = np.asarray(P, dtype=np.float64)
    up = np.array([0.0, 1.0])  # N in groove-plane coordinates
    a = _angle(up, simulation.H2)          # between N and H
    b = _angle(B - P, C - P)               # at P
    c = _angle(A - B, C - B)               # at B
    d = _angle(A - B, up)                  # side against the vertical through B
    e = _angle(simulation.H2, direction)   # between H and E' (or L')
    f = _angle(B - C, P - C)               # at C
    length = float(np.linalg.norm(B - A))
    m = float(np.linalg.norm(P - B))
    return GrooveAngles(
        a, b, c, d, e, f, A, B, C, P, np.asarray(direction, dtype=np.float64), m, length,
        m / length, np.sin(f) / np.sin(b),  # Blinn 1977, Fig. 4: m/l = sin f / sin b
    )
