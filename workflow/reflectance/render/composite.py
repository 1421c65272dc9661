"""Figures composed of several renders: one exposure for all, a grid of images; per-part pixels.

- :func:`common_exposure`: Cook & Torrance's exposure over several renders shown as one scene
  ("all XYZ values in the scene are scaled equally");
- :func:`covered_rows`: the image rows any render covers (to crop a grid);
- :func:`image_grid`: a matplotlib figure of display images on a black ground, each at a
  (row, column) with a label beneath;
- :func:`part_pixels`: what each pixel of a render shows of each named part of a mesh, and the
  colour it is shown in (dominant wavelength of the scene and of the displayed colour);
- :func:`appearance`: how an object reads in its display image (how much of it is visible, its
  lightness range, how white its highlight is against its body, the highlight's hue).

References
----------
- Cook, R. L., & Torrance, K. E. (1982). A reflectance model for computer graphics. ACM
  Transactions on Graphics, 1(1), 7-24. ("Determining the RGB values": one scale for a scene.)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any, TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from reflectance.colour.display import (XYZ_to_linear_RGB, expose_CookTorrance1982,
                                 gamut_clip, linear_RGB_to_XYZ)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reflectance.render.samples import SurfaceSamples

__all__ = ["common_exposure", "covered_rows", "image_grid", "part_pixels", "appearance"]


def common_exposure(images: Sequence[npt.NDArray[np.float64]], space: str, illuminant: str,
                    observer: str, wavelengths: npt.ArrayLike | None) -> float:
    """The Cook & Torrance 1982 exposure scale of several XYZ images taken as one scene."""
    # Cook & Torrance 1982: "all XYZ values in the scene are scaled equally"
    _, scale = expose_CookTorrance1982(np.stack(images), space, illuminant=illuminant,
                                       observer=observer, wavelengths=wavelengths)
    return scale


def covered_rows(images: Sequence[npt.NDArray[np.float64]], margin: int = 4) -> slice:
    """A slice of the rows that any image covers (Y > 0), widened by ``margin`` pixels."""
    lit = np.flatnonzero(np.stack(images)[..., 1].max(axis=(0, 2)) > 0)
    if lit.size == 0:
        return slice(0, np.shape(images[0])[0])
    return slice(max(lit[0] - margin, 0), lit[-1] + margin + 1)


def image_grid(cells: Sequence[tuple[int, int, npt.NDArray[Any], str]], n_rows: int, n_cols: int,
               title: str, headings: Sequence[tuple[int, int, str, dict[str, Any]]] = (),
               crop: slice = slice(None), head: float = 0.25, foot: float = 0.4, top: float = 0.45,
               dpi: float = 100, label_size: float | None = None) -> Figure:
    """A figure of display images (encoded RGB) in a grid on a black ground.

    Parameters
    ----------
    cells : sequence of (row, col, RGB, label)
        The images (same size, encoded RGB in [0, 1]) and the text beneath each.
    n_rows, n_cols : int
    title : str
    headings : sequence of (row, col, text, style)
        Text over a cell; ``style`` holds matplotlib text keywords and ``x`` (figure fraction).
    crop : slice
        Rows of every image shown.
    head, foot, top : float
        Inches above each row of images (headings), below it (labels) and above the grid (title).
    dpi : float
        Image pixels per inch: the figure is ``n_cols`` images wide at this resolution (choose it so
        that the figure is :data:`reflectance.io.figures.PRINT_WIDTH_IN` wide, and save it at ``dpi``).
    label_size : float, optional
        Points of the labels (default ``TEXT_SIZE["annotation"]``); headings and title use the
        figures' symbol and title sizes.
    """
    from reflectance.io.figures import STYLE, TEXT_SIZE, new_figure

    label_size = TEXT_SIZE["annotation"] if label_size is None else label_size

    first = cells[0][2][crop]
    w, h = first.shape[1] / dpi, first.shape[0] / dpi
    fig_w, fig_h = n_cols * w * 1.04, top + n_rows * (head + h + foot)
    fig = new_figure(fig_w, fig_h, facecolor="black")
    for row, col, rgb, label in cells:
        y0 = fig_h - top - row * (head + h + foot) - head
        ax = fig.add_axes((col / n_cols + 0.02 / n_cols, (y0 - h) / fig_h, w / fig_w, h / fig_h))
        ax.imshow(rgb[crop], interpolation="nearest")
        ax.set_axis_off()
        ax.text(0.5, -0.01, label, transform=ax.transAxes, ha="center", va="top", color="white",
                fontsize=label_size, linespacing=1.15)
    for row, col, text, style in headings:
        style = dict(style)
        y0 = fig_h - top - row * (head + h + foot) - head
        fig.text(style.pop("x", col / n_cols + 0.01), (y0 + 0.07) / fig_h, text,
                 **{"color": "white", "fontsize": TEXT_SIZE["symbol"], "ha": "left", **style})
    fig.suptitle(title, color="white", fontsize=STYLE["figure.titlesize"], y=1 - 0.06 / fig_h,
                 va="top", linespacing=1.3)
    return fig


def part_pixels(samples: SurfaceSamples, part_codes: npt.ArrayLike, XYZ: npt.NDArray[np.float64],
                scale: float, space: str, gamut_clip_method: str,
                display: Mapping[str, Any]) -> Callable[[int], dict[str, Any]]:
    """Per named part: the pixels it covers and the colour they show.

    Parameters
    ----------
    samples : reflectance.render.visibility.SurfaceSamples
        The render's camera samples (``triangle``, ``hit``, ``to_pixels``).
    part_codes : array_like
        The mesh's ``cell_data["part"]``.
    XYZ : ndarray (H, W, 3)
        The rendered image.
    scale : float
        Its display exposure.
    space, gamut_clip_method : str
    display : dict
        ``illuminant``, ``observer``, ``wavelengths``.

    Returns
    -------
    callable
        ``stats(code) -> dict`` with ``pixels`` (sum of sample fractions), ``full_pixels``
        (pixels wholly on the part), ``mean_Y`` and the median dominant wavelength of the scene
        colour and of the shown (exposed, gamut-clipped) colour with its purity over the full
        pixels (NaN where the part covers none).
    """
    from reflectance.colour.colorimetry import dominant_wavelength

    code = np.where(samples.hit, np.asarray(part_codes)[np.maximum(samples.triangle, 0)], -1)
    shown = linear_RGB_to_XYZ(gamut_clip(XYZ_to_linear_RGB(XYZ * scale, space, **display),
                                         gamut_clip_method, space), space, **display)

    def over(values, statistic=np.nanmedian):
        return statistic(values) if np.size(values) else np.nan

    def stats(number):
        fraction = samples.to_pixels((code == number).astype(float))
        full = fraction == 1.0
        wl_scene = dominant_wavelength(XYZ[full], **display)[0]
        wl_shown, purity = dominant_wavelength(shown[full], **display)
        return {"pixels": fraction.sum(), "full_pixels": int(full.sum()),
                "mean_Y": over(XYZ[full][:, 1], np.mean),
                "dominant_wavelength_scene_nm": over(wl_scene),
                "dominant_wavelength_shown_nm": over(wl_shown),
                "purity_shown": over(purity)}

    return stats


def appearance(encoded: npt.NDArray[np.float64], XYZ: npt.NDArray[np.float64], space: str = "sRGB",
               highlight_percentile: float = 99.5) -> dict[str, float]:
    """How an object reads in its display image: visibility, lightness range, highlight colour.

    The object is the pixels with scene ``Y > 0`` less a one-pixel rim (partly covered, antialiased
    pixels). Colours are those the PNG shows: 8-bit codes decoded with the display's transfer
    function, taken to CIELAB relative to the display white.

    Returns
    -------
    dict
        ``visible``: fraction of object pixels with some channel >= 20/255; ``L10``, ``L50``,
        ``L99``: the 10th, 50th and 99th percentile of L*; ``body_chroma``: median C*ab;
        ``body_hue_deg``: CIELAB hue of the median a*, b*;
        ``highlight_chroma_ratio``: median C*ab of the pixels at or above the
        ``highlight_percentile`` of L*, over the body's (NaN where the body has no chroma);
        ``highlight_hue_deg``: CIELAB hue of the mean of the 1 % brightest pixels without a
        channel at 255 (NaN if none); ``clipped``: fraction of object pixels with a channel at 255.
    """
    from scipy import ndimage

    from reflectance.colour.colorimetry import XYZ_to_Lab, XYZ_to_xy
    from reflectance.colour.display import decode_8bit, display_space

    ds = display_space(space)
    on = ndimage.binary_erosion(np.asarray(XYZ)[..., 1] > 0)  # the object less its rim
    codes = np.round(np.asarray(encoded)[on] * 255)
    # the display's EOTF and CIELAB as colour-science computes them, to the bit (colour's values
    # for the 256 codes; colorimetry's XYZ_to_xy and XYZ_to_Lab), without importing it
    linear = decode_8bit(codes, space)
    white = XYZ_to_xy(ds.whitepoint_XYZ)
    Lab = XYZ_to_Lab(linear @ ds.matrix_RGB_to_XYZ.T, white)
    L, C = Lab[:, 0], np.hypot(Lab[:, 1], Lab[:, 2])
    highlight = L >= np.percentile(L, highlight_percentile)
    unclipped = codes.max(axis=-1) < 255
    hue = np.nan
    if unclipped.any():
        top = unclipped & (L >= np.percentile(L[unclipped], 99))
        a, b = Lab[top, 1].mean(), Lab[top, 2].mean()
        hue = float(np.degrees(np.arctan2(b, a)) % 360)
    body_chroma = float(np.median(C))
    return {"visible": float((codes.max(axis=-1) >= 20).mean()),
            "L10": float(np.percentile(L, 10)), "L50": float(np.percentile(L, 50)),
            "L99": float(np.percentile(L, 99)),
            "body_chroma": body_chroma,
            "body_hue_deg": float(np.degrees(np.arctan2(np.median(Lab[:, 2]),
                                                        np.median(Lab[:, 1]))) % 360),
            # NaN for a grey object (no body chroma to compare with), without a divide warning
            "highlight_chroma_ratio": (float(np.median(C[highlight])) / body_chroma
                                       if body_chroma > 0 else np.nan),
            "highlight_hue_deg": hue, "clipped": float((~unclipped).mean())}
