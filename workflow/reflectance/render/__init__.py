"""Render: a spectral renderer that takes a scene and knows nothing of papers or the CLI.

Modules: Read top-down: rays (exact ray tests) and primitives (the scene as flat arrays) under
camera and lights; idbuffer (VTK chooses the triangle), samples, visibility, shadows; shading
(spectral, per-angle Fresnel table); parallel (the per-sample work on threads); adaptive (which
pixels get more samples); tracing (a band's visibility and shadows, and the kept trace);
session (what one render holds while it runs); integrator (shade and box-filter band by band,
refine); rgb (a scene also rendered as a three-channel RGB renderer would); scene (scene
files); memory (a render's memory, estimated from its size before it starts); pipeline
(render, write); composite (grids with one exposure). The bench of its speed
and accuracy, and the path tracer's cross-check, are :mod:`reflectance.bench`.

Public names are loaded on first use (``from reflectance.render import name``), so importing
the package stays cheap.
"""

from reflectance.lazy import attach

#: this package's modules (a name equal to a module's is the module)
_MODULES = ("adaptive", "camera", "composite", "idbuffer", "integrator", "lights", "memory",
            "parallel",
            "pipeline", "primitives", "rays", "rgb", "samples", "scene", "session", "shading",
            "shadows", "tracing", "visibility")

#: public name -> module of this package that defines it
_EXPORTS = {
    "Refinement": "adaptive",
    "pixel_spread": "adaptive",
    "refine_mask": "adaptive",
    "refinement_bands": "adaptive",
    "REFINE_BAND_SAMPLES": "adaptive",
    "REFINE_BAND_ID_PIXELS": "adaptive",
    "render_spectral_and_rgb": "rgb",
    "display_exposure": "rgb",
    "Camera": "camera",
    "common_exposure": "composite",
    "covered_rows": "composite",
    "image_grid": "composite",
    "appearance": "composite",
    "part_pixels": "composite",
    "MAX_TRIANGLES": "idbuffer",
    "MAX_BUFFER_SIDE": "camera",
    "render_memory_bytes": "memory",
    "render_size_problem": "memory",
    "encode_ids": "idbuffer",
    "decode_ids": "idbuffer",
    "id_buffer": "idbuffer",
    "DirectionalLight": "lights",
    "PointLight": "lights",
    "LIGHT_TYPES": "lights",
    "as_light": "lights",
    "light_vectors": "lights",
    "THREADS_VARIABLE": "parallel",
    "render_threads": "parallel",
    "COMPONENTS": "integrator",
    "shade_samples": "integrator",
    "Integrator": "integrator",
    "RenderSession": "session",
    "tiles": "tracing",
    "light_map_size": "tracing",
    "trace": "tracing",
    "trace_key": "tracing",
    "trace_once": "tracing",
    "render_to_files": "pipeline",
    "RenderResult": "pipeline",
    "render": "pipeline",
    "display_image": "pipeline",
    "automatic_exposure": "pipeline",
    "display_linear_RGB": "pipeline",
    "write_linear_RGB_from_XYZ": "pipeline",
    "software_versions": "pipeline",
    "write_render": "pipeline",
    "render_warnings": "pipeline",
    "BACK_FRACTION_WARNING": "pipeline",
    "ray_triangle_MollerTrumbore1997": "rays",
    "ray_sphere": "rays",
    "SurfaceSamples": "samples",
    "SceneError": "scene",
    "SCENE_SCHEMA_PATH": "scene",
    "GEOMETRY_BUILDERS": "scene",
    "GEOMETRY_PARTS": "scene",
    "Display": "scene",
    "SceneObject": "scene",
    "Scene": "scene",
    "validate_scene": "scene",
    "scene_from_dict": "scene",
    "load_scene": "scene",
    "scene_from_text": "scene",
    "write_scene_file": "scene",
    "constant_index_material": "scene",
    "SHADING_MODELS": "shading",
    "SHADOWING_NAMES": "shading",
    "SPECTRAL_METHODS": "shading",
    "AMBIENT_REFERENCES": "shading",
    "RoughnessTexture": "shading",
    "ShadingMaterial": "shading",
    "Light": "shading",
    "Ambient": "shading",
    "ambient_intensity": "shading",
    "white_card_luminance": "shading",
    "emission_XYZ": "shading",
    "fresnel_XYZ_table": "shading",
    "fresnel_XYZ_table_rgb": "shading",
    "lookup_table": "shading",
    "shade": "shading",
    "shadow_mask": "shadows",
    "shadow_masks": "shadows",
}

__getattr__, __dir__, __all__ = attach(__name__, _MODULES, _EXPORTS)
