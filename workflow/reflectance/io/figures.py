"""Deterministic figure output for matplotlib (2-D plots) and pyvista (3-D scenes).

Same inputs give byte-identical PNG and PDF files: no creation dates, no software versions in
the metadata, fixed DPI, and the file is written atomically. Every PNG declares its colour space
(sRGB unless the figure shows pixels encoded for another display: :func:`savefig`'s ``tag``).

Every figure of the project shares one style, :data:`STYLE` (applied by :func:`new_figure`): text
sized for a figure printed about 7 inches wide (the figures are drawn at that size, so 9-10 pt
stays 9-10 pt on the page), no top and right spines, outward ticks, a light grid where a plot
asks for one (``ax.grid()``), the Okabe-Ito colour cycle (distinguishable with colour-vision
deficiencies), frameless legends, and files cropped to their content (:func:`savefig`), so no
canvas is wasted. Pyvista figures share :func:`off_screen_plotter` (white background, the same
font).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reflectance.io.atomic import atomic_write  # noqa: E402

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    import pyvista as pv
    from matplotlib.figure import Figure
    from vtkmodules.vtkRenderingCore import vtkTextProperty

    from reflectance.io.images import ColourTag

_Scalar = TypeVar("_Scalar", bound="np.generic")

__all__ = ["STYLE", "OKABE_ITO", "DARK_YELLOW", "DARK_ORANGE", "text_colour", "PRINT_WIDTH_IN", "TEXT_SIZE", "apply_style", "paper_name", "savefig", "new_figure", "off_screen_plotter", "trim_to_content",
           "save_plotter", "font_file", "set_vtk_font", "lines_under"]

OKABE_ITO = ("#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#f0e442", "#000000")
"""Okabe & Ito (2008), "Color universal design": eight colours told apart by every observer."""

DARK_YELLOW = "#a89600"
"""Okabe & Ito's yellow (#f0e442) darkened at the same hue for lines and text on white: the yellow
has a contrast of 1.3:1 against white, this 3.0:1 (WCAG 2.1 relative luminance); under a simulated
deuteranopia (Machado et al. 2009) it is a yellow 10 L* units darker than the palette's orange but
only 5 lighter than its vermilion: a figure that draws both tells them apart by line style too."""

DARK_ORANGE = "#9c6c00"
"""Okabe & Ito's orange (#e69f00) darkened at the same hue (each sRGB channel x 0.68) for text on
white: the orange has a contrast of 2.25:1 against white, this 4.6:1 (WCAG 2.1 asks 4.5:1 for text).
Lines and fills keep the palette's orange; text drawn in a line's colour goes through
:func:`text_colour`."""


def text_colour(colour: str) -> str:
    """The colour to write text in beside a line of ``colour``, on white: Okabe & Ito's orange and
    yellow give their darkened variants (:data:`DARK_ORANGE`, :data:`DARK_YELLOW`), others are kept.

    Examples
    --------
    >>> text_colour("#E69F00"), text_colour("#f0e442"), text_colour("#0072b2")
    ('#9c6c00', '#a89600', '#0072b2')
    """
    return {OKABE_ITO[4]: DARK_ORANGE, OKABE_ITO[6]: DARK_YELLOW}.get(str(colour).lower(), colour)


STYLE = {
    "font.family": "sans-serif",
    "font.sans-serif": ["DejaVu Sans"],
    "mathtext.fontset": "dejavusans",
    "font.size": 9.5,
    "axes.titlesize": 10,
    "axes.titleweight": "normal",
    "axes.titlepad": 5,
    "axes.labelsize": 9.5,
    "axes.labelpad": 3,
    "axes.linewidth": 0.8,
    "axes.edgecolor": "0.25",
    "axes.labelcolor": "0.1",
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.grid": False,
    "axes.axisbelow": True,
    "axes.prop_cycle": matplotlib.cycler(  # type: ignore[attr-defined]  # not in its stubs
        color=[OKABE_ITO[i] for i in (0, 1, 2, 3, 4, 5, 7)]
        + [DARK_YELLOW]),  # yellow last, darkened for white
    "axes.xmargin": 0.0,
    "grid.color": "0.9",
    "grid.linewidth": 0.6,
    "xtick.labelsize": 8.5,
    "ytick.labelsize": 8.5,
    "xtick.direction": "out",
    "ytick.direction": "out",
    "xtick.major.size": 3,
    "ytick.major.size": 3,
    "xtick.color": "0.25",
    "ytick.color": "0.25",
    "legend.fontsize": 8.5,
    "legend.frameon": False,
    "legend.handlelength": 1.8,
    "lines.linewidth": 1.5,
    "lines.solid_capstyle": "round",
    "figure.titlesize": 11,
    "figure.titleweight": "normal",
    "figure.facecolor": "white",
    "image.cmap": "cividis",
    "savefig.bbox": "tight",
    "savefig.pad_inches": 0.04,
}
"""The project's matplotlib style (see the module docstring)."""

PRINT_WIDTH_IN = 7.0
"""Width (inches) at which a full-width figure is drawn, and printed: a two-column page's text width."""

TEXT_SIZE = {
    "symbol": 9.5,       # a vector or angle name drawn on a diagram (N, H, L', a, b, ...)
    "annotation": 8.0,   # numbers and notes written on or under a plot
    "table": 7.5,        # the body of a table drawn as a figure (the smallest text of the project)
}
"""Font sizes (points, at :data:`PRINT_WIDTH_IN`) of the text a figure writes itself, beyond :data:`STYLE`'s
axis, tick, legend and title sizes; every figure script takes them from here, never a literal."""


def paper_name(name: str) -> str:
    """A material's name as the papers print it: ``"LunarDust"`` -> ``"Lunar dust"``.

    CamelCase words after the first are lower-cased; a name of capitals and digits (a chemical
    symbol such as ``"Cu"`` or ``"MgO"``) is left as it is.

    Examples
    --------
    >>> paper_name("OliveDrab"), paper_name("Cu"), paper_name("RustBody")
    ('Olive drab', 'Cu', 'Rust body')
    """
    import re

    words = re.findall(r"[A-Z][a-z]+|[A-Z]+(?![a-z])|[a-z]+|\d+", str(name))
    if len(words) < 2 or not all(w[0].isupper() and w[1:].islower() for w in words):
        return str(name)
    return " ".join([words[0]] + [w.lower() for w in words[1:]])


def apply_style() -> None:
    """Make :data:`STYLE` matplotlib's defaults (each figure script is its own process)."""
    matplotlib.rcParams.update(STYLE)

_METADATA = {
    ".png": {"Software": None},
    ".pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
}


def new_figure(width_in: float = 7.0, height_in: float = 4.0, **kwargs: Any) -> Figure:
    """A matplotlib figure in the project's style (:data:`STYLE`, applied to this process)."""
    apply_style()
    fig = plt.figure(figsize=(width_in, height_in), **kwargs)
    return fig


def savefig(fig: Figure, *paths: str | os.PathLike[str], dpi: int = 200, tight: bool = True,
            tag: ColourTag | None = None) -> None:
    """Save ``fig`` to each path (.png or .pdf) deterministically and atomically, then close it.

    ``tight`` crops the file to its content (a small margin); pass ``False`` for layouts placed
    to the pixel (rendered images at ``dpi`` pixels per inch).

    A PNG carries its colour space (:func:`reflectance.io.images.tag_png`): ``tag``, a
    :class:`reflectance.io.images.ColourTag`, or by default sRGB
    (:data:`reflectance.io.images.SRGB_TAG`), the space matplotlib's colours are given in. A
    figure that shows display-encoded pixels (renders, colour swatches) passes the display's tag
    (:func:`reflectance.colour.display.display_tag`): its lines and text are then read in that
    space too, which moves their greys slightly off sRGB's but shows the colours the figure is
    about as computed.
    """
    import io

    from reflectance.io.images import SRGB_TAG, tag_png

    files = [Path(p) for p in paths]
    for path in files:
        if path.suffix.lower() not in _METADATA:
            raise ValueError(f"figure path {path}: suffix must be one of {sorted(_METADATA)}")
    os.environ.setdefault("SOURCE_DATE_EPOCH", "0")
    try:
        for path in files:
            suffix = path.suffix.lower()
            buffer = io.BytesIO()
            fig.savefig(buffer, dpi=dpi, metadata=_METADATA[suffix], format=suffix[1:],
                        bbox_inches="tight" if tight else None)
            data = buffer.getvalue()
            if suffix == ".png":
                data = tag_png(data, SRGB_TAG if tag is None else tag)
            with atomic_write(path) as tmp:
                Path(tmp).write_bytes(data)
    finally:
        plt.close(fig)


def lines_under(ax: Any, artist: Any) -> list[str]:
    """The labels of the lines of ``ax`` with a drawn point inside ``artist``'s box on the canvas
    (an annotation's text box, a legend): empty when the artist covers no curve. Draws the figure.

    Examples
    --------
    >>> fig = new_figure(3, 2); ax = fig.subplots()
    >>> _ = ax.plot([0, 1], [0, 1], label="rising"); box = ax.text(0.8, 0.1, "note")
    >>> lines_under(ax, box), lines_under(ax, ax.text(0.4, 0.4, "on it"))
    ([], ['rising'])
    >>> plt.close(fig)
    """
    import numpy as np

    renderer = ax.figure.canvas.get_renderer()
    ax.figure.draw_without_rendering()
    from matplotlib.text import Annotation, Text

    patch = getattr(artist, "get_bbox_patch", lambda: None)()
    # an annotation's own extent takes in its arrow, which may cross a curve: its text box only
    box = (patch.get_window_extent(renderer) if patch is not None
           else Text.get_window_extent(artist, renderer) if isinstance(artist, Annotation)
           else artist.get_window_extent(renderer))
    hits = []
    for line in ax.get_lines():
        x, y = (np.asarray(v, float) for v in line.get_data())
        # the polyline resampled finely, so a segment crossing the box between its samples counts
        t = np.linspace(0, len(x) - 1, 20 * len(x))
        xy = ax.transData.transform(np.column_stack([np.interp(t, np.arange(len(x)), x),
                                                     np.interp(t, np.arange(len(y)), y)]))
        xy = xy[np.isfinite(xy).all(axis=1)]
        frame = ax.get_window_extent(renderer)  # lines are clipped to the axes
        inside = ((xy[:, 0] >= frame.x0) & (xy[:, 0] <= frame.x1) & (xy[:, 1] >= frame.y0) & (xy[:, 1] <= frame.y1)
                  & (xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) & (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1))
        if inside.any():
            hits.append(line.get_label())
    return hits


def off_screen_plotter(width: int, height: int, shape: Sequence[int] = (1, 1),
                       **layout: Any) -> pv.Plotter:
    """A pyvista plotter that renders off-screen (EGL on a machine without a display).

    ``shape = (rows, columns)`` makes a grid of subplots (select one with ``plotter.subplot(i, j)``),
    drawn without borders between them; ``layout`` passes pyvista's ``col_weights``,
    ``row_weights`` and ``groups`` (e.g. a narrow column for a colour key).
    """
    import pyvista as pv

    pv.OFF_SCREEN = True
    return pv.Plotter(off_screen=True, window_size=(int(width), int(height)),
                      shape=tuple(int(n) for n in shape), border=False, **layout)


def font_file() -> str:
    """The file of the figures' typeface (:data:`STYLE`'s DejaVu Sans, the copy matplotlib ships), so
    that VTK text (pyvista's ``font_file``, :func:`set_vtk_font`) is set in the same face."""
    from matplotlib import font_manager

    return font_manager.findfont(STYLE["font.sans-serif"][0], fallback_to_default=False)


def set_vtk_font(*text_properties: vtkTextProperty) -> None:
    """Set VTK text properties (a scalar bar's title and labels, ...) in :func:`font_file`."""
    # the constant from the module pyvista has loaded already: ``import vtk`` loads every VTK
    # module (about 0.5 s of CPU per process)
    from vtkmodules.vtkCommonCore import VTK_FONT_FILE

    for prop in text_properties:
        prop.SetFontFamily(VTK_FONT_FILE)
        prop.SetFontFile(font_file())


def trim_to_content(img: npt.NDArray[_Scalar], margin: int) -> npt.NDArray[_Scalar]:
    """``img`` (H, W, C) cropped to the pixels that differ from its top-left pixel (the
    background), then padded with that background by ``margin`` pixels on every side: no empty
    canvas, nothing touching the frame. An image of background only is returned as it is.

    >>> import numpy as np
    >>> img = np.zeros((10, 12, 3), np.uint8); img[4:6, 3:9] = 255
    >>> trim_to_content(img, 2).shape
    (6, 10, 3)
    """
    import numpy as np

    img = np.asarray(img)
    content = np.any(img != img[0, 0], axis=-1)
    if not content.any():
        return img
    rows, cols = np.flatnonzero(content.any(axis=1)), np.flatnonzero(content.any(axis=0))
    inner = img[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1]
    out = np.empty((inner.shape[0] + 2 * margin, inner.shape[1] + 2 * margin) + img.shape[2:],
                   img.dtype)
    out[...] = img[0, 0]
    out[margin:margin + inner.shape[0], margin:margin + inner.shape[1]] = inner
    return out


def save_plotter(plotter: pv.Plotter, path: str | os.PathLike[str],
                 margin: int | None = None) -> None:
    """Screenshot a pyvista plotter to a deterministic PNG (through the project's PNG writer),
    tagged sRGB: VTK's colours are sRGB values, written to the screen as they are. With
    ``margin`` (pixels), the screenshot is trimmed to its content and given that margin
    (:func:`trim_to_content`)."""
    from reflectance.io.images import SRGB_TAG, write_png

    img = plotter.screenshot(return_img=True)
    plotter.close()
    if margin is not None:
        img = trim_to_content(img[..., :3], int(margin))
    write_png(path, img[..., :3] / 255.0, bit_depth=8, tag=SRGB_TAG)
