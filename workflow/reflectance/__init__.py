"""reflectance: spectral reproduction and audit of the classic reflectance papers.

The physics and colour science are re-exported here (colour-science style, explicit ``__all__``);
the renderer's modules (geometry, visibility, scene, shading, render), which load VTK, are
imported from their own modules: ``from reflectance.render import render``.
"""

import importlib as _importlib

from .brdf import *  # noqa: F401,F403
from .colorimetry import *  # noqa: F401,F403
from .display import *  # noqa: F401,F403
from .fresnel import *  # noqa: F401,F403
from .microfacet import *  # noqa: F401,F403
from .shadowing import *  # noqa: F401,F403
from .spectra import *  # noqa: F401,F403

__version__ = "0.1.0"

# Some public functions share their module's name (fresnel, brdf, shadowing): take each
# module's __all__ from the module object itself.
__all__ = [
    name
    for module in ("spectra", "fresnel", "microfacet", "shadowing", "brdf", "colorimetry",
                   "display")
    for name in _importlib.import_module(f"{__name__}.{module}").__all__
]
