"""The shared figure style (reflectance.io.figures): text colours legible on white and one typeface
for matplotlib and VTK text. Contrast and hue are computed here from their definitions (WCAG 2.1,
CIELAB through colour-science), not with the module's own numbers."""

from pathlib import Path

import colour
import numpy as np
import pytest

from reflectance.io import figures


def relative_luminance(hex_colour):
    """WCAG 2.1 relative luminance of an sRGB colour ``#rrggbb``."""
    c = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255
    linear = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return float(linear @ [0.2126, 0.7152, 0.0722])


def contrast_on_white(hex_colour):
    return 1.05 / (relative_luminance(hex_colour) + 0.05)


def hue(hex_colour):
    rgb = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255
    Lab = colour.XYZ_to_Lab(colour.sRGB_to_XYZ(rgb))
    return np.degrees(np.arctan2(Lab[2], Lab[1])) % 360


def test_orange_text_is_legible_on_white_and_still_orange():
    orange = figures.OKABE_ITO[4]
    assert contrast_on_white(orange) < 3  # why it needs a text variant (2.25:1)
    assert contrast_on_white(figures.DARK_ORANGE) >= 4.5  # WCAG 2.1 AA for text
    assert abs(hue(figures.DARK_ORANGE) - hue(orange)) < 6  # the same hue, darker


@pytest.mark.parametrize("line, text", [("#e69f00", "DARK_ORANGE"), ("#E69F00", "DARK_ORANGE"),
                                        ("#f0e442", "DARK_YELLOW")])
def test_text_colour_of_light_palette_colours(line, text):
    assert figures.text_colour(line) == getattr(figures, text)


@pytest.mark.parametrize("line", ["#0072b2", "#d55e00", "0.3", "k"])
def test_text_colour_keeps_dark_colours(line):
    assert figures.text_colour(line) == line
    if line.startswith("#"):
        assert contrast_on_white(line) >= 3


def test_vtk_text_uses_the_figures_typeface():
    path = Path(figures.font_file())
    assert path.is_file() and path.name == "DejaVuSans.ttf"
    vtk = pytest.importorskip("vtk")
    prop = vtk.vtkTextProperty()
    figures.set_vtk_font(prop)
    assert prop.GetFontFamily() == vtk.VTK_FONT_FILE and prop.GetFontFile() == str(path)
