"""Spectral against three-channel RGB rendering of one scene (colour-accuracy audit 2).

The spectral renderer integrates ``F(lambda, V.H)`` against the light and the colour matching
functions (:func:`reflectance.render.shading.fresnel_XYZ_table`); a three-channel renderer stores
a metal as the display-RGB colour of its normal reflectance F0 and applies Schlick 1994 to each
channel (:func:`reflectance.render.shading.fresnel_XYZ_table_rgb`). Both renders share one
visibility pass, so they differ only in F;
:func:`reflectance.colour.difference.dE2000_map` compares them pixel by pixel as the figure's
display shows them, on the spectral image's exposure (:func:`display_exposure`).

References
----------
- Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM TOG 1(1):
  Figs. 6b and 7 (the metal vases), "Spectral composition" (F per wavelength).
- Schlick, C. (1994). An Inexpensive BRDF Model for Physically-based Rendering. CGF 13(3).
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    from reflectance.render.pipeline import RenderResult
    from reflectance.render.scene import Scene

__all__ = ["render_spectral_and_rgb", "display_exposure"]


def render_spectral_and_rgb(scene: Scene, space: str = "sRGB",
                            keep_trace: bool = False) -> tuple[RenderResult, RenderResult]:
    """(spectral XYZ image, RGB-renderer XYZ image) of ``scene``, one visibility pass for both.

    Parameters
    ----------
    scene : reflectance.render.scene.Scene
        Shaded with ``spectral="table"`` (the RGB renderer replaces the Fresnel table only).
    space : str
        Display space of the RGB renderer's channels (:data:`reflectance.colour.display.DISPLAY_SPACES`).
    keep_trace : bool
        Keep the trace for scenes that differ only in materials, as
        :func:`reflectance.render.pipeline.render` does.
    """
    from reflectance.render.integrator import shade_samples
    from reflectance.render.tracing import trace_once
    from reflectance.render.shading import fresnel_XYZ_table_rgb

    samples, shadowed, _ = trace_once(scene, keep_trace)
    images = []
    for table in (None, functools.partial(fresnel_XYZ_table_rgb, space=space)):
        images.append(samples.to_pixels(
            shade_samples(scene, samples, shadowed, "table", fresnel_table=table)))
    return images[0], images[1]


def display_exposure(XYZ: npt.NDArray[np.float64], scene: Scene) -> float:
    """The exposure scale the scene's display applies to the image ``XYZ`` (its PNG's scale)."""
    from reflectance.render.pipeline import RenderResult, display_image

    return display_image(RenderResult(XYZ, None, {}, {}, scene))[1]
