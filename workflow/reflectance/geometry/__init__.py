"""Geometry: the shapes the renderer and the papers" figures draw.

Modules: vectors (3-vector helpers), shapes (vase of revolution, sphere, torus, superellipsoid,
plane, mesh files), mesh_files (mesh files checked before VTK reads them), watch (C&T 1982
Fig. 8), texture (Blinn 1977's texture patterns).

Public names are loaded on first use (``from reflectance.geometry import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("mesh_files", "shapes", "texture", "vectors", "watch")

#: public name -> module of this package that defines it
_EXPORTS = {
    "VASE_PARTS": "shapes",
    "VASE_INTERPOLATION_METHODS": "shapes",
    "vase": "shapes",
    "sphere": "shapes",
    "torus": "shapes",
    "superellipsoid_Barr1981": "shapes",
    "plane": "shapes",
    "MESH_FILE_SUFFIXES": "shapes",
    "mesh_from_file": "shapes",
    "check_mesh_file": "mesh_files",
    "place": "shapes",
    "compose": "shapes",
    "analytic_spheres": "shapes",
    "texture_sinusoid": "texture",
    "texture_spots": "texture",
    "texture_value_noise": "texture",
    "TEXTURE_METHODS": "texture",
    "unit_vector": "vectors",
    "normalize": "vectors",
    "dot": "vectors",
    "WATCH_PARTS": "watch",
    "SEVEN_SEGMENT_DIGITS": "watch",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
