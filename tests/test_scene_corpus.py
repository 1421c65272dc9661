"""A corpus of bad scene files (issue 25): sizes nobody checked, YAML that grows when read, keys
given twice, mesh paths that leave the scene file's folder.

Each case is a scene file written into a fresh folder (beside a folder ``outside/`` it must not
reach) and loaded as ``reflectance render`` loads it (:func:`reflectance.render.scene.load_scene`).
Each asserts: refused within seconds (sizes are counted, nothing is made), with one problem line
naming the file and the key, no line of a file outside, and no file written or changed.
"""

import re
import time

import pytest
import yaml

from reflectance.render.scene import SceneError, load_scene

BASE = {
    "camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "fov_deg": 30, "width": 8,
               "height": 6},
    "objects": [{"geometry": {"type": "sphere", "radius": 1.0},
                 "material": {"name": "Cu", "m": 0.3}}],
    "lights": [{"type": "directional", "direction": [0, -1, 1]}],
}
SIZE = r"makes .* about .*(GiB|h)"
WORK = r"makes .* about \d+ h of work"


def scene(**changes):
    """BASE with top-level keys replaced and dotted keys set (``camera__width``)."""
    doc = yaml.safe_load(yaml.safe_dump(BASE))
    for key, value in changes.items():
        *path, last = key.split("__")
        node = doc
        for part in path:
            node = node[int(part)] if part.isdigit() else node[part]
        node[last] = value
    return yaml.safe_dump(doc, sort_keys=False)


def geometry(**g):
    return scene(objects=[{"geometry": g, "material": {"name": "Cu", "m": 0.3}}])


def mesh(path):
    return geometry(type="mesh", path=path)


def laughs(levels, width):
    text, previous = 'x-l0: &l0 ["lol"]\n', "l0"
    for i in range(1, levels + 1):
        text += f"x-l{i}: &l{i} [{', '.join([f'*{previous}'] * width)}]\n"
        previous = f"l{i}"
    return text


# (id, scene text, what the problem line says after 's.yaml: ')
CASES = [
    # sizes: the wavelength grid with the Fresnel table, brute force, meshes, the render
    ("fine-wavelengths-and-table",
     scene(wavelengths={"start_nm": 360, "end_nm": 830, "step_nm": 0.001},
           fresnel_table_size=1048577),
     rf"wavelengths\.step_nm, fresnel_table_size: 0\.001 nm from 360 to 830 nm and 1048577 cosines {WORK}"),
    ("fine-wavelengths", scene(wavelengths={"start_nm": 360, "end_nm": 830, "step_nm": 1e-6}),
     rf"wavelengths\.step_nm, fresnel_table_size: 1e-06 nm .* {WORK}"),
    ("brute-force-large", scene(spectral="brute-force", camera__width=4096, camera__height=4096,
                                camera__supersample=2,
                                wavelengths={"start_nm": 360, "end_nm": 830, "step_nm": 1}),
     rf"wavelengths\.step_nm, spectral: 1 nm from 360 to 830 nm, brute force {WORK}"),
    ("sphere-mesh", geometry(type="sphere", radius=1.0, n_theta=4096, n_phi=4096),
     rf"objects\[0\]\.geometry: a sphere of 16,777,216 vertices {SIZE}"),
    ("torus-mesh", geometry(type="torus", major_radius=1.0, minor_radius=0.3, n_u=4096, n_v=4096),
     rf"objects\[0\]\.geometry: a torus of 16,777,216 vertices {SIZE}"),
    ("superellipsoid-mesh", geometry(type="superellipsoid", radii=[1, 1, 1], exponents=[1, 1],
                                     n_u=4096, n_v=4096),
     rf"objects\[0\]\.geometry: a superellipsoid of 16,777,216 vertices {SIZE}"),
    ("vase-mesh", geometry(type="vase", profile=[[0.3, 0], [0.5, 1], [0.3, 2]], n_theta=4096,
                           n_profile_samples=4096),
     rf"objects\[0\]\.geometry: a vase of [\d,]+ vertices {SIZE}"),
    ("id-buffer", scene(camera__width=16384, camera__height=16384, camera__supersample=2),
     r"camera\.width, \.height, \.supersample: the ID buffer would be 32768 x 32768 pixels"),
    ("render-memory", scene(camera__width=16384, camera__height=16384, camera__supersample=1),
     r"camera\.width, \.height, \.supersample: a 16384 x 16384 render with 1 x 1 samples needs about \d+\.\d GiB"),
    ("adaptive-memory", scene(camera__width=8192, camera__height=8192, camera__supersample=1,
                              camera__adaptive={"enabled": True, "supersample": 8}),
     r"camera\.width, \.height, \.supersample: a 8192 x 8192 render with 1 x 1 samples and adaptive refinement needs about"),
    # YAML that grows when read, and keys given twice
    ("alias-bomb", laughs(9, 9) + scene(), r"line \d+: its aliases expand it to more than 1,000,000 nodes"),
    ("alias-mapping-bomb", "x-m: &m {" + ", ".join(f"k{i}: {i}" for i in range(2000)) + "}\nx-r: ["
     + ", ".join(["*m"] * 600) + "]\n" + scene(), r"its aliases expand it"),
    ("deep-nesting", "x: " + "[" * 5000 + "]" * 5000 + "\n" + scene(), r"line 1: nested more than 64 levels deep"),
    ("deep-mappings", "x: " + "{a: " * 200 + "1" + "}" * 200 + "\n" + scene(), r"nested more than 64 levels deep"),
    ("camera-twice", scene() + "camera: {position: [0, -9, 0], look_at: [0, 0, 0], fov_deg: 20}\n",
     r"line \d+, column 1: not valid YAML: key 'camera' given twice \(first on line 1\)"),
    ("nested-key-twice", scene().replace("    m: 0.3\n", "    m: 0.3\n    m: 0.5\n"),
     r"line \d+, column \d+: not valid YAML: key 'm' given twice"),
    ("lights-twice", scene() + "lights: []\n", r"line \d+, column 1: not valid YAML: key 'lights' given twice"),
    # mesh paths: inside the scene file's folder only
    ("mesh-dotdot", mesh("../outside/m.obj"), r"objects\[0\]\.geometry: '\.\./outside/m\.obj' leaves the scene file's folder"),
    ("mesh-dotdot-inside", mesh("sub/../../outside/m.obj"), r"objects\[0\]\.geometry: .* leaves the scene file's folder"),
    ("mesh-absolute", mesh("OUTSIDE/m.obj"), r"objects\[0\]\.geometry: '.*/outside/m\.obj' is absolute"),
    ("mesh-etc", mesh("/etc/hosts"), r"objects\[0\]\.geometry: '/etc/hosts' is absolute"),
    ("mesh-file-link", mesh("link.obj"), r"objects\[0\]\.geometry: 'link\.obj' leaves the scene file's folder"),
    ("mesh-folder-link", mesh("linked/m.obj"), r"objects\[0\]\.geometry: 'linked/m\.obj' leaves the scene file's folder"),
    ("material-file-link", scene(objects=[{"geometry": {"type": "sphere", "radius": 1.0},
                                           "material": {"file": "link.csv", "m": 0.3}}]),
     r"objects\[0\]\.material\.file: 'link\.csv' leaves the scene file's folder"),
]


@pytest.fixture
def folder(tmp_path, monkeypatch):
    """tmp_path/scenes (the scene's folder, with links out) beside tmp_path/outside (a mesh and a
    spectrum whose first lines are secrets); a machine of 2 GiB, whatever this one has."""
    from reflectance.io import limits
    from reflectance.render import memory

    for module in (limits, memory):
        monkeypatch.setattr(module, "physical_memory_bytes", lambda: 2 * 2**30)
    outside, scenes = tmp_path / "outside", tmp_path / "scenes"
    outside.mkdir()
    scenes.mkdir()
    (outside / "m.obj").write_text("# secret-mesh-line\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    (outside / "m.csv").write_text("secret-header,x\n1,2\n")
    (scenes / "link.obj").symlink_to(outside / "m.obj")
    (scenes / "link.csv").symlink_to(outside / "m.csv")
    (scenes / "linked").symlink_to(outside)
    return scenes


def listing(root):
    return sorted((str(p.relative_to(root)), p.lstat().st_size, p.lstat().st_mtime_ns)
                  for p in root.rglob("*"))


def test_corpus_is_large_and_distinct():
    ids = [c[0] for c in CASES]
    assert len(ids) >= 20 and len(set(ids)) == len(ids)


@pytest.mark.parametrize("case_id, text, expected", CASES, ids=[c[0] for c in CASES])
def test_bad_scene_is_refused_in_one_line_naming_file_and_key(folder, root, case_id, text,
                                                              expected):
    path = folder / "s.yaml"
    path.write_text(text.replace("OUTSIDE", str(folder.parent / "outside")))
    before = listing(folder.parent)
    start = time.perf_counter()
    with pytest.raises(SceneError) as info:
        load_scene(path, spectra_dir=root / "spectra")
    seconds = time.perf_counter() - start
    message = str(info.value)
    problems = [line.strip() for line in message.splitlines() if line != "invalid scene:"]
    assert len(problems) == 1, message
    assert re.search(rf"^{re.escape(str(path))}(: |, )(line \d+: )?{expected}", problems[0]), message
    assert "secret" not in message
    assert listing(folder.parent) == before
    assert seconds < 10, seconds


def test_spectra_dir_is_the_deliberate_exception(folder, root):
    """README: a scene's ``spectra_dir`` (like the CLI's --spectra-dir) is a folder the user
    chooses, anywhere: a material there loads; but only ``<name>.csv`` of a plain name is read in
    it, so no name reaches another file."""
    outside = folder.parent / "outside"
    (outside / "Mine.csv").write_text("wavelength_nm,n,k\n350,0.5,2.5\n850,0.3,4.0\n")
    path = folder / "s.yaml"
    path.write_text(scene(spectra_dir=str(outside), objects=[
        {"geometry": {"type": "sphere", "radius": 1.0}, "material": {"name": "Mine", "m": 0.3}}]))
    assert load_scene(path).objects[0].material.name == "Mine"
    for name in ("../outside/Mine", "/etc/hosts", "m.csv/.."):
        path.write_text(scene(spectra_dir=str(outside), objects=[
            {"geometry": {"type": "sphere", "radius": 1.0}, "material": {"name": name, "m": 0.3}}]))
        with pytest.raises(SceneError, match=r"objects\[0\]\.material\.name: .* is not a name"):
            load_scene(path)
