"""The lecture (Russin, Module 3B): its figures, one declaration each (:class:`Figure`). The 2-D
and 3-D lobes share ``brdf_lobes``: each declares only the keys it reads."""

from __future__ import annotations

from reflectance.papers.figures.declaration import Figure

_LECTURE, _OUT = "figures.lecture", "results/lecture"


def _lobes(*keys):
    return tuple(f"{_LECTURE}.brdf_lobes.{key}" for key in ("incidence_deg", "models",
                                                            "scale_to_deg", "scale_margin",
                                                            "ward_turned_deg", *keys))


DEFINITIONS = {figure.RULE: figure for figure in (
    Figure("lecture_distributions", _OUT, {"fig": f"{_LECTURE}.distributions"},
           {"png": "distributions.png", "pdf": "distributions.pdf", "csv": "distributions.csv",
            "summary": "distributions_normalisation.csv"}),
    Figure("lecture_brdf_lobes_2d", _OUT, {"fig": _lobes("geometry", "polar_step_deg", "plot_2d")},
           {"png": "brdf_lobes_2d.png", "pdf": "brdf_lobes_2d.pdf", "csv": "brdf_lobes_2d.csv",
            "values": "brdf_lobes_2d.values.rst"}),
    Figure("lecture_brdf_lobes_3d", _OUT, {"fig": _lobes("hemisphere_samples", "polar_step_deg",
                                                         "render_3d")},
           {"png": "brdf_lobes_3d.png", "values": "brdf_lobes_3d.values.rst"}),
    Figure("lecture_fresnel", _OUT, {"fig": f"{_LECTURE}.fresnel", "wavelengths": "wavelengths",
                                     "colour": "colour"},
           {"png": "fresnel.png", "pdf": "fresnel.pdf", "csv": "fresnel.csv"},
           lambda params: params["fig"]["materials"]),
    Figure("lecture_shadowing_masking", _OUT, {"fig": f"{_LECTURE}.shadowing_masking"},
           {"png": "shadowing_masking.png", "pdf": "shadowing_masking.pdf",
            "g1": "shadowing_masking_g1.csv", "by_slope": "shadowing_masking_by_slope.csv"}),
)}
