"""Colour: CIE colorimetry and display encoding, knowing nothing of optics or rendering.

Modules: appearance (CAM16 and CAM16-UCS, numpy only); colorimetry (CMFs, illuminants,
tristimulus weights, xy, CIELAB, dominant wavelength), difference (CIEDE2000, and its maps and
statistics over two images), display (RGB spaces, Cook & Torrance's exposure, gamut clipping,
transfer functions), exposure (a whole image's exposure scale and display RGB, in bands of rows),
tables (colour-science's tables, computed by colour-science once and cached, so that
the colour path reads them with numpy only).

Public names are loaded on first use (``from reflectance.colour import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("appearance", "colorimetry", "difference", "display", "exposure", "tables")

#: public name -> module of this package that defines it
_EXPORTS = {
    "CAM16_SURROUNDS": "appearance",
    "XYZ_to_CAM16": "appearance",
    "XYZ_to_CAM16UCS": "appearance",
    "OBSERVER_DEFAULT": "colorimetry",
    "cmfs": "colorimetry",
    "illuminant_sd": "colorimetry",
    "illuminant_range_nm": "colorimetry",
    "cmfs_wavelengths": "colorimetry",
    "tristimulus_weights": "colorimetry",
    "tristimulus_weights_spd": "colorimetry",
    "white_XYZ": "colorimetry",
    "spectrum_to_XYZ": "colorimetry",
    "XYZ_to_xy": "colorimetry",
    "XYZ_to_Lab": "colorimetry",
    "dominant_wavelength": "colorimetry",
    "delta_E_CIE2000": "difference",
    "dE2000_map": "difference",
    "dE2000_statistics": "difference",
    "pixel_difference_CIEDE2000": "difference",
    "difference_statistics_CIEDE2000": "difference",
    "image_difference_CIEDE2000": "difference",
    "DISPLAY_SPACES": "display",
    "CHROMATIC_ADAPTATION_TRANSFORM": "display",
    "DisplaySpace": "display",
    "display_space": "display",
    "XYZ_to_linear_RGB": "display",
    "linear_RGB_to_XYZ": "display",
    "expose_CookTorrance1982": "display",
    "expose_key": "display",
    "compress_highlights": "display",
    "HIGHLIGHT_ROLLOFFS": "display",
    "gamut_clip_CookTorrance1982": "display",
    "gamut_clip_channels": "display",
    "gamut_clip_CSSColor4": "display",
    "GAMUT_CLIP_METHODS": "display",
    "gamut_clip": "display",
    "encode": "display",
    "XYZ_to_display": "display",
    "fresnel_XYZ_rgb": "display",
    "display_tag": "display",
    "exposure_scale": "exposure",
    "image_display_RGB": "exposure",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
