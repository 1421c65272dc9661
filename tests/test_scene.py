"""Tests of reflectance.render.scene: scene files, validation errors by key, resolution."""

import copy

import numpy as np
import pandas as pd
import pytest
import yaml

from reflectance.geometry.shapes import analytic_spheres
from reflectance.render.scene import SceneError, load_scene, scene_from_dict, validate_scene


def minimal(**changes):
    doc = {
        "camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "fov_deg": 30, "width": 8,
                   "height": 6},
        "objects": [{"geometry": {"type": "sphere", "radius": 1.0},
                     "material": {"name": "Cu", "m": 0.3}}],
        "lights": [{"type": "directional", "direction": [0, -1, 1]}],
    }
    doc.update(changes)
    return doc


@pytest.fixture
def spectra(root):
    return root / "spectra"


def errors_of(doc, spectra, **kwargs):
    with pytest.raises(SceneError) as info:
        scene_from_dict(doc, source="s.yaml", spectra_dir=spectra, **kwargs)
    return str(info.value)


def test_defaults_are_filled_in(spectra):
    scene = scene_from_dict(minimal(), spectra_dir=spectra)
    doc = scene.document
    assert doc["spectral"] == "table" and doc["shadows"] is True
    assert doc["wavelengths"] == {"start_nm": 360, "end_nm": 830, "step_nm": 5}
    assert doc["camera"]["up"] == [0, 0, 1] and doc["camera"]["supersample"] == 1
    assert doc["lights"][0] == {"type": "directional", "direction": [0, -1, 1],
                                "spectrum": "D65", "intensity": 1.0, "solid_angle": 1.0,
                                "shadows": True}
    assert doc["ambient"] == {"fraction": 0.0, "reference": "intensity"}
    assert doc["display"]["gamut_clip"] == "dominant-wavelength"
    m = doc["objects"][0]["material"]
    assert (m["model"], m["convention"], m["fresnel"], m["shadowing"]) == (
        "CookTorrance1982", "paper", "exact", "v-cavity")
    material = scene.objects[0].material
    assert (material.s, material.d) == (1.0, 0.0)
    # diffuse albedo defaults to the F0 of `name` (C&T Fig. 7, R_d = F0/pi), from Cu.csv here
    data = np.loadtxt(spectra / "Cu.csv", delimiter=",", skiprows=1)
    N = (np.interp(scene.wavelengths, data[:, 0], data[:, 1])
         + 1j * np.interp(scene.wavelengths, data[:, 0], data[:, 2]))
    assert np.allclose(material.albedo, abs((N - 1) / (N + 1)) ** 2, rtol=1e-12)
    assert len(scene.wavelengths) == 95 and scene.ambient.spectrum == "D65"
    # the caller's document is not modified
    assert "spectral" not in minimal()


def test_schema_errors_name_each_key_and_the_file(spectra):
    doc = minimal()
    doc["camera"]["height"] = -2
    doc["objects"][0]["geometry"]["colour"] = "red"
    doc["objects"][0]["material"]["s"] = 1.5
    doc["lights"][0]["type"] = "spot"
    doc["bogus"] = 1
    text = errors_of(doc, spectra)
    for key in ("s.yaml: camera.height:", "s.yaml: objects[0].geometry: Additional properties",
                "s.yaml: objects[0].material.s: 1.5", "s.yaml: lights[0].type:",
                "s.yaml: (top level): Additional properties are not allowed ('bogus'"):
        assert key in text, text


def test_missing_required_keys(spectra):
    assert "(top level): 'camera' is a required property" in errors_of(
        {k: v for k, v in minimal().items() if k != "camera"}, spectra)
    doc = minimal()
    del doc["objects"][0]["geometry"]["radius"]
    assert "objects[0].geometry: 'radius' is a required property" in errors_of(doc, spectra)


@pytest.mark.parametrize("material, key, message", [
    ({"name": "Unobtainium", "m": 0.3}, "objects[0].material.name", "known: Ag, Al, Au"),
    ({"name": "Cu", "s": 0.7, "d": 0.7, "m": 0.3}, "objects[0].material.s", "s + d = 1"),
    ({"name": "Cu"}, "objects[0].material", "needs 'm' (or 'lobes')"),
    ({"name": "Cu", "lobes": [{"m": 0.4, "w": 0.4}, {"m": 0.2, "w": 0.5}]},
     "objects[0].material.lobes", "sum to 1"),
    ({"name": "Cu", "lobes": [{"c3": 0.4, "w": 1.0}]}, "objects[0].material.lobes[0]",
     "needs 'm'"),
    ({"name": "Cu", "lobes": [{"m": 0.4, "w": 1.0}], "shadowing": "smith"},
     "objects[0].material.shadowing", "one Beckmann"),
    ({"model": "Lambert", "s": 0.5}, "objects[0].material.s", "no specular part"),
    ({"model": "Lambert"}, "objects[0].material", "needs 'diffuse_material', 'albedo'"),
    ({"model": "CookTorrance1982", "m": 0.3}, "objects[0].material", "needs 'name'"),
    ({"name": "Cu", "albedo": 0.5, "diffuse_material": "Au", "m": 0.3},
     "objects[0].material.albedo", "not both"),
    ({"name": "Cu", "distribution": "TrowbridgeReitz1975", "convention": "physical",
      "roughness_texture": {"method": "sinusoid", "min": 0.2}},
     "objects[0].material.convention", "only as printed"),
    ({"name": "Cu", "m": 0.3, "roughness_texture": {"method": "spots", "min": 0.1,
                                                    "parameters": {"period": 3}}},
     "objects[0].material.roughness_texture.parameters", "unknown parameters ['period']"),
    ({"name": "Cu", "m": 0.3, "roughness_texture": {"method": "marble", "min": 0.1}},
     "objects[0].material.roughness_texture.method", "is not one of"),
    ({"model": "BlinnPhong1977", "albedo": 0.5}, "objects[0].material", "needs the exponent"),
    ({"name": "Cu", "m": 0.3, "emission": {"dominant_wavelength_nm": 640, "luminance": 1,
                                           "white": "D99"}},
     "objects[0].material.emission.white", "unknown illuminant 'D99'"),
])
def test_material_errors_name_the_key(material, key, message, spectra):
    text = errors_of(minimal(objects=[{"geometry": {"type": "sphere", "radius": 1.0},
                                       "material": material}]), spectra)
    assert f"s.yaml: {key}: " in text and message in text, text


def test_other_semantic_errors_name_the_key(spectra, tmp_path):
    doc = minimal(lights=[{"type": "directional", "direction": [0, 0, 0], "spectrum": "D99"}],
                  ambient={"fraction": 0.1, "spectrum": "XYZ"},
                  display={"illuminant": "Q"})
    doc["objects"].append({"geometry": {"type": "mesh", "path": "nothere.obj"},
                           "material": {"model": "Lambert", "albedo": 0.5}})
    doc["objects"].append({"geometry": {"type": "vase", "profile": [[0.5, 0], [0.6, 1],
                                                                     [0.5, 2]],
                                        "wall_thickness": 5.0},
                           "material": {"model": "Lambert", "albedo": 0.5}})
    doc["camera"]["look_at"] = [0, -5, 0]
    text = errors_of(doc, spectra, base_dir=tmp_path)
    for expected in ("s.yaml: camera: camera position and look_at must differ",
                     "s.yaml: lights[0]: light direction must be a non-zero",
                     "s.yaml: lights[0].spectrum: illuminant: unknown illuminant 'D99'",
                     "s.yaml: ambient.spectrum: ", "s.yaml: display.illuminant: ",
                     "s.yaml: objects[1].geometry: ", "mesh file not found",
                     "s.yaml: objects[2].geometry: "):
        assert expected in text, (expected, text)


def test_wavelength_grid_outside_a_material_names_it(spectra):
    doc = minimal(wavelengths={"start_nm": 300, "end_nm": 830, "step_nm": 5})
    text = errors_of(doc, spectra)
    assert "objects[0].material.name: " in text and "leaves the data range" in text


def test_missing_spectra_folder_is_reported(tmp_path, monkeypatch):
    text = errors_of(minimal(), tmp_path / "none")
    assert f"s.yaml: spectra_dir: no such folder '{tmp_path / 'none'}'" in text
    monkeypatch.chdir(tmp_path)  # the scene's own spectra_dir, relative to the working directory
    text = errors_of(minimal(spectra_dir="spectra"), [])
    assert "s.yaml: spectra_dir: no such folder 'spectra' (relative to the working" in text


def test_transform_places_the_object(spectra):
    doc = minimal()
    doc["objects"][0]["transform"] = {"offset": [1, 2, 3], "scale": 2.0,
                                      "rotation_deg": [0, 0, 90]}
    doc["objects"][0]["geometry"]["center"] = [1, 0, 0]
    scene = scene_from_dict(doc, spectra_dir=spectra)
    centres, radii = analytic_spheres(scene.mesh)
    # x -> 2 Rz(90) x + offset: (1, 0, 0) -> (0, 2, 0) + (1, 2, 3)
    assert np.allclose(centres[0], [1, 4, 3]) and np.allclose(radii, [2.0])


def test_load_scene_reads_files_and_applies_overrides(root, tmp_path, spectra):
    path = tmp_path / "scene.yaml"
    path.write_text(yaml.safe_dump(minimal()))
    scene = load_scene(path, spectra_dir=spectra, width=20, height=10, supersample=3,
                       spectral="brute-force",
                       wavelengths={"start_nm": 380, "end_nm": 780, "step_nm": 10})
    cam = scene.camera
    assert (cam.width, cam.height, cam.supersample) == (20, 10, 3)
    assert scene.spectral == "brute-force" and len(scene.wavelengths) == 41
    assert scene.source == str(path)
    example = load_scene(root / "workflow" / "scenes" / "example_spheres.yaml",
                         spectra_dir=spectra)
    assert len(example.objects) == 4 and len(example.lights) == 2
    with pytest.raises(SceneError, match="no such scene file"):
        load_scene(tmp_path / "missing.yaml")
    bad = tmp_path / "bad.yaml"
    bad.write_text("camera: [unclosed")
    with pytest.raises(SceneError, match=r"bad.yaml, line 1, column \d+: not valid YAML"):
        load_scene(bad)
    bad.write_text("- just\n- a list\n")
    with pytest.raises(SceneError, match="a scene must be a mapping"):
        load_scene(bad)


def test_validate_scene_leaves_its_input_alone():
    doc = minimal()
    before = copy.deepcopy(doc)
    out = validate_scene(doc)
    assert doc == before and out["spectral"] == "table"


def test_parts_get_their_own_materials(spectra):
    doc = minimal(objects=[{
        "geometry": {"type": "vase", "profile": [[0.5, 0], [0.6, 0.5], [0.4, 1.0]],
                     "n_theta": 32, "n_profile_samples": 16},
        "material": {"name": "Cu", "m": 0.3},
        "parts": {"inner": {"model": "Lambert", "albedo": 0.2}}}])
    scene = scene_from_dict(doc, spectra_dir=spectra)
    (code, material), = scene.objects[0].part_materials.items()
    assert code == 2 and material.model == "Lambert"  # VASE_PARTS["inner"]
    doc["objects"][0]["parts"] = {"lid": {"model": "Lambert", "albedo": 0.2}}
    assert "objects[0].parts.lid: no part 'lid' in a vase; known: outer, rim" in errors_of(
        doc, spectra)


def test_watch_geometry_takes_the_builder_parameters(spectra):
    doc = minimal(objects=[{"geometry": {"type": "watch", "parameters": {"dial": 3}},
                            "material": {"name": "Au", "m": 0.2}}])
    assert "objects[0].geometry: " in errors_of(doc, spectra)


# --- constant complex index materials (scene key `index`) -------------------------------------

@pytest.mark.parametrize("n, k", [(1.8, 0.0), (200.0, 0.0), (0.27, 3.4)])
def test_index_material_equals_a_flat_spectrum_file(tmp_path, n, k):
    """`index: {n, k}` gives the material that a CSV of the same n, k at every wavelength gives."""
    from reflectance.optics.spectra import write_spectrum_csv

    write_spectrum_csv(pd.DataFrame({"wavelength_nm": [300.0, 900.0], "n": n, "k": k}),
                       tmp_path / "flat.csv")
    base = {"camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "fov_deg": 30, "width": 8,
                       "height": 8},
            "lights": [{"type": "directional", "direction": [0, -1, 1]}]}
    scenes = [scene_from_dict({**base, "spectra_dir": str(tmp_path), "objects": [
        {"geometry": {"type": "sphere", "radius": 1}, "material": dict(material, s=0.5, m=0.2)}]})
        for material in ({"name": "flat"}, {"index": {"n": n, "k": k}})]
    a, b = (s.objects[0].material for s in scenes)
    for key in ("n", "k", "albedo"):
        np.testing.assert_array_equal(getattr(a, key), getattr(b, key))
    assert np.all(b.n == n) and np.all(b.k == k)
    # F0 = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) at normal incidence (Fresnel)
    np.testing.assert_allclose(b.albedo, ((n - 1) ** 2 + k**2) / ((n + 1) ** 2 + k**2), rtol=1e-12)


@pytest.mark.parametrize("given", [("name", "index"), ("name", "file"), ("file", "index")])
def test_two_spectra_for_one_material_are_an_error(spectra, tmp_path, given):
    (tmp_path / "mine.csv").write_text("wavelength_nm,n,k\n300,1.5,0\n900,1.5,0\n")
    keys = {"name": "Cu", "index": {"n": 1.5}, "file": "mine.csv"}
    document = {"camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "fov_deg": 30,
                           "width": 8, "height": 8}, "lights": [],
                "objects": [{"geometry": {"type": "sphere", "radius": 1},
                             "material": {**{k: keys[k] for k in given}, "m": 0.2}}]}
    with pytest.raises(SceneError, match=f"give one of 'name'.*'file'.*'index'.*, not "
                                         f"'{given[0]}' and '{given[1]}'"):
        scene_from_dict(document, spectra_dir=spectra, base_dir=tmp_path)


# --- where a material comes from: the lookup of names, a scene's own files ---------------------

def F0_of(path, grid, micrometres=False):
    """Independent: the normal-incidence reflectance of a spectrum CSV on the grid, read with
    numpy (n, k: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2); a reflectance: itself)."""
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    wl = data[:, 0] * (1000.0 if micrometres else 1.0)
    if data.shape[1] == 2:
        return np.interp(grid, wl, data[:, 1])
    n, k = np.interp(grid, wl, data[:, 1]), np.interp(grid, wl, data[:, 2])
    return ((n - 1) ** 2 + k**2) / ((n + 1) ** 2 + k**2)


def flat(folder, name, n):
    folder.mkdir(exist_ok=True)
    (folder / f"{name}.csv").write_text(f"wavelength_nm,n,k\n300,{n},0\n900,{n},0\n")


def sphere_of(material):
    return [{"geometry": {"type": "sphere", "radius": 1.0}, "material": {**material, "m": 0.3}}]


def test_names_are_looked_up_in_the_given_folders_then_spectra_dir_then_bundled(root,
                                                                                tmp_path):
    first, second, own = tmp_path / "first", tmp_path / "second", tmp_path / "own"
    flat(first, "Cu", 1.5)           # hides the bundled copper
    flat(second, "Cu", 2.0)          # hidden by first
    flat(second, "Mine", 3.0)
    flat(own, "Mine", 4.0)           # the scene's spectra_dir: after the folders given
    flat(own, "Theirs", 2.5)
    objects = [o for name in ("Cu", "Mine", "Theirs", "Au") for o in sphere_of({"name": name})]
    scene = scene_from_dict(minimal(objects=objects, spectra_dir=str(own)),
                            spectra_dir=[first, str(second)])
    F0 = [obj.material.albedo for obj in scene.objects]  # the albedo is the F0 of `name`
    for got, n in zip(F0[:3], (1.5, 3.0, 2.5)):
        np.testing.assert_allclose(got, ((n - 1) / (n + 1)) ** 2, rtol=1e-12)
    # Au is in none of them: the bundled one, i.e. the project's spectra/Au.csv
    np.testing.assert_allclose(F0[3], F0_of(root / "spectra" / "Au.csv", scene.wavelengths),
                               rtol=1e-12)
    assert "spectra_dir" not in scene_from_dict(minimal(), spectra_dir=first).document


def test_without_any_folder_the_bundled_spectra_serve(root, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # no ./spectra, no spectra_dir: nothing but the bundled ones
    scene = scene_from_dict(minimal())
    np.testing.assert_allclose(scene.objects[0].material.albedo,
                               F0_of(root / "spectra" / "Cu.csv", scene.wavelengths),
                               rtol=1e-12)


def test_an_unknown_name_lists_the_folders_and_every_known_name(tmp_path):
    flat(tmp_path / "mine", "Mine", 1.5)
    text = errors_of(minimal(objects=sphere_of({"name": "Unobtainium"})), tmp_path / "mine")
    assert "objects[0].material.name: unknown material 'Unobtainium' in " in text
    assert f"{tmp_path / 'mine'}, the bundled spectra; known: " in text
    known = text.split("known: ")[1].split(", ")
    assert {"Mine", "Cu", "Au"} <= set(known) and known == sorted(known)


@pytest.mark.parametrize("form", ["nk", "reflectance", "refractiveindex.info"])
def test_a_material_file_beside_the_scene_file_in_each_form(root, tmp_path, monkeypatch, form):
    scenes, mats = tmp_path / "scenes", tmp_path / "scenes" / "mats"
    mats.mkdir(parents=True)
    wl, n, k = np.loadtxt(root / "spectra" / "Cu.csv", delimiter=",", skiprows=1).T
    text = {"nk": "wavelength_nm,n,k\n" + "".join(f"{a},{b},{c}\n" for a, b, c in zip(wl, n, k)),
            "reflectance": "wavelength_nm,reflectance\n350,0.05\n550,0.30\n850,0.60\n",
            "refractiveindex.info": "wl,n,k\n" + "".join(f"{a / 1000:.9g},{b},{c}\n"
                                                          for a, b, c in zip(wl, n, k))}[form]
    (mats / "my_metal.csv").write_text(text)
    (scenes / "s.yaml").write_text(yaml.safe_dump(minimal(
        objects=sphere_of({"file": "mats/my_metal.csv"}))))
    monkeypatch.chdir(tmp_path)  # the file is found beside the scene file, not here
    scene = load_scene(scenes / "s.yaml")
    material = scene.objects[0].material
    expected = F0_of(mats / "my_metal.csv", scene.wavelengths,
                     micrometres=form == "refractiveindex.info")
    np.testing.assert_allclose(material.albedo, expected, rtol=1e-9)
    assert material.name == "my_metal"
    if form == "reflectance":  # no k: Cook & Torrance's k = 0 and n from F0
        root_F0 = np.sqrt(expected)
        np.testing.assert_allclose(material.n, (1 + root_F0) / (1 - root_F0), rtol=1e-12)
        assert np.all(material.k == 0)
    else:  # the file's own n, k: copper's, as the bundled Cu gives them
        np.testing.assert_allclose(material.k, np.interp(scene.wavelengths, wl, k), rtol=1e-9)


@pytest.mark.parametrize("value, files, says", [
    ("none.csv", {}, ["none.csv: no such file"]),
    ("bad.csv", {"bad.csv": "lambda,n,k\n400,1,1\n500,1,1\n"},
     ["bad.csv, line 1 (header)", "'wavelength_nm,n,k'", "'wl,n,k'"]),
    ("bad.csv", {"bad.csv": "wavelength_nm,n,k\n400,1,1\n500,one,1\n"},
     ["bad.csv, data row 2 (line 3)", "'one' is not a number"]),
    ("bad.csv", {"bad.csv": "wavelength_nm,n,k\n400,1,1\n700,1,1\n"},
     ["360-830 nm leaves the data range 400-700 nm"]),
    ("../outside.csv", {"../outside.csv": "wavelength_nm,n,k\n300,1.5,0\n900,1.5,0\n"},
     ["'../outside.csv' leaves the scene file's folder"]),
    ("/etc/passwd", {}, ["'/etc/passwd' is absolute; give a path inside the scene file's folder"]),
])
def test_a_bad_material_file_is_named_with_its_key(tmp_path, value, files, says):
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    for name, text in files.items():
        (scenes / name).write_text(text)
    (scenes / "s.yaml").write_text(yaml.safe_dump(minimal(objects=sphere_of({"file": value}))))
    with pytest.raises(SceneError) as info:
        load_scene(scenes / "s.yaml")
    text = str(info.value)
    assert f"s.yaml: objects[0].material.file: " in text
    for part in says:
        assert part in text, text


def test_cook_torrance_with_s_0_needs_no_m(spectra):
    """Cook & Torrance 1982 Table I: m "not used" for a material with s = 0."""
    document = {"camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "fov_deg": 30,
                           "width": 8, "height": 8},
                "lights": [{"type": "directional", "direction": [0, -1, 1]}],
                "objects": [{"geometry": {"type": "sphere", "radius": 1},
                             "material": {"name": "Cu", "s": 0.0, "d": 1.0}}]}
    assert scene_from_dict(document, spectra_dir=spectra).objects[0].material.roughness is None
    document["objects"][0]["material"].update(s=0.5, d=0.5)
    with pytest.raises(SceneError, match="needs 'm'"):
        scene_from_dict(document, spectra_dir=spectra)


def test_display_meters_on_the_object_or_a_white_card_not_both(spectra):
    doc = minimal(display={"key": {"percentile": 50, "luminance": 0.18},
                           "white": {"luminance": 1.0}})
    assert "display" in errors_of(doc, spectra)
    scene_from_dict(minimal(display={"white": {"luminance": 2.0}}), spectra_dir=spectra)


def test_display_transfer_none_writes_the_linear_RGB_as_the_codes(spectra):
    """display.transfer: 'display' by default (the space's transfer function); 'none' makes the
    encoded image the linear display RGB itself; another value is refused by its key."""
    from reflectance.colour.exposure import image_display_RGB

    assert scene_from_dict(minimal(), spectra_dir=spectra).display.transfer == "display"
    scene = scene_from_dict(minimal(display={"transfer": "none", "expose": False}),
                            spectra_dir=spectra)
    assert scene.display.transfer == "none"
    XYZ = np.random.default_rng(3).uniform(0, 1.2, (4, 5, 3))
    linear, _ = image_display_RGB(XYZ, scene.display)
    encoded, _ = image_display_RGB(XYZ, scene.display, encoded=True)
    np.testing.assert_array_equal(encoded, linear)
    assert "display" in errors_of(minimal(display={"transfer": "gamma"}), spectra)


def test_composed_mesh_is_kept_per_geometry_and_copied_per_scene(spectra):
    """Scenes that differ only in material share one composition (a deep copy each, so a scene
    that changes its mesh changes no other); another transform or object is composed anew."""
    from reflectance.geometry.shapes import compose, sphere
    from reflectance.io import cache

    def arrays(mesh):
        return {**{f"p.{k}": np.asarray(mesh.point_data[k]) for k in mesh.point_data},
                **{f"c.{k}": np.asarray(mesh.cell_data[k]) for k in mesh.cell_data},
                **{f"f.{k}": np.asarray(mesh.field_data[k]) for k in mesh.field_data},
                "points": np.asarray(mesh.points), "faces": np.asarray(mesh.faces)}

    cache.clear()
    two = [{"geometry": {"type": "sphere", "radius": 1.0}, "material": {"name": "Cu", "m": 0.3}},
           {"geometry": {"type": "sphere", "radius": 0.5, "center": [2, 0, 0]},
            "material": {"name": "Au", "m": 0.2}}]
    first = scene_from_dict(minimal(objects=two), spectra_dir=spectra)
    other = copy.deepcopy(two)
    other[0]["material"], other[1]["material"] = {"name": "Ag", "m": 0.1}, {"name": "Cu", "m": 0.4}
    second = scene_from_dict(minimal(objects=other), spectra_dir=spectra)
    assert len(cache.COMPOSED_MESHES) == 1 and second.mesh is not first.mesh
    # the same bytes as composing the objects directly
    direct = compose([(sphere((0, 0, 0), 1.0, 96, 48), 0), (sphere((2, 0, 0), 0.5, 96, 48), 1)])
    expected = arrays(direct)
    for scene in (first, second):
        got = arrays(scene.mesh)
        assert got.keys() == expected.keys()
        for key, value in expected.items():
            assert got[key].dtype == value.dtype and np.array_equal(got[key], value), key
    first.mesh.points[:] = 0.0  # a copy: the next scene's mesh is untouched
    third = scene_from_dict(minimal(objects=two), spectra_dir=spectra)
    assert np.array_equal(np.asarray(third.mesh.points), expected["points"])
    moved = copy.deepcopy(two)
    moved[1]["transform"] = {"offset": [0, 0, 1]}
    placed = scene_from_dict(minimal(objects=moved), spectra_dir=spectra)
    assert len(cache.COMPOSED_MESHES) == 2
    assert not np.array_equal(np.asarray(placed.mesh.points), expected["points"])
