"""reflectance: spectral reproduction and audit of the classic reflectance papers."""

__version__ = "0.1.0"
