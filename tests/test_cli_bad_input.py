"""Bad command-line input: each is refused with one line naming the option (or the file), exit
status 1, no traceback, and no file written. Issue 12, "Command line"."""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from reflectance.cli import main

SCENE = """\
camera: {position: [0, -5, 0], look_at: [0, 0, 0], fov_deg: 30, width: 8, height: 6}
objects:
  - geometry: {type: sphere, radius: 1.0}
    material: {name: Cu, m: 0.3}
lights: [{type: directional, direction: [0, -1, 1]}]
"""

CT = ["cook-torrance", "--m", "0.3", "--incidence", "30", "--angles", "0"]
PHONG = ["phong", "--incidence", "30", "--angles", "0"]

# (arguments, what the message must name)
BAD = [
    # reflectance colour
    (["colour", "Cu", "--angle", "nan"], "--angle"),
    (["colour", "Cu", "--angle", "inf"], "--angle"),
    (["colour", "Cu", "--angle", "-1"], "--angle"),
    (["colour", "Cu", "--angle", "91"], "--angle"),
    (["colour", "Cu", "--angle", "ten"], "--angle"),
    (["colour", "Cu", "--angle", "0", "--average-range", "nan", "780"], "--average-range"),
    (["colour", "Cu", "--angle", "0", "--average-range", "700", "400"], "--average-range"),
    (["colour", "Cu", "--angle", "0", "--average-range", "-5", "780"], "--average-range"),
    (["colour", "../x/Cu", "--angle", "0"], "material '../x/Cu' is not a name"),
    (["colour", "/etc/passwd", "--angle", "0"], "material '/etc/passwd' is not a name"),
    (["colour", "..", "--angle", "0"], "material '..' is not a name"),
    (["colour", "sub\\Cu", "--angle", "0"], "is not a name"),
    # reflectance brdf
    (["brdf", *CT, "--n", "nan"], "--n"),
    (["brdf", *CT, "--n", "1e160"], "--n"),
    (["brdf", *CT, "--n", "0"], "--n"),
    (["brdf", *CT, "--n", "-1.5"], "--n"),
    (["brdf", *CT, "--n", "1.5", "--k", "nan"], "--k"),
    (["brdf", *CT, "--n", "1.5", "--k", "-1"], "--k"),
    (["brdf", *CT, "--n", "1.5", "--s", "1.5"], "--s"),
    (["brdf", *CT, "--n", "1.5", "--s", "-0.1"], "--s"),
    (["brdf", *CT, "--n", "1.5", "--s", "nan"], "--s"),
    (["brdf", *CT, "--n", "1.5", "--d", "2"], "--d"),
    (["brdf", "cook-torrance", "--n", "1.5", "--m", "nan", "--incidence", "30", "--angles", "0"], "--m"),
    (["brdf", "cook-torrance", "--n", "1.5", "--m", "0", "--incidence", "30", "--angles", "0"], "--m"),
    (["brdf", "cook-torrance", "--n", "1.5", "--m", "1e300", "--incidence", "30", "--angles", "0"], "--m"),
    (["brdf", "cook-torrance", "--n", "1.5", "--c3", "0", "--incidence", "30", "--angles", "0"], "--c3"),
    (["brdf", "cook-torrance", "--n", "1.5", "--c3", "1.5", "--incidence", "30", "--angles", "0"], "--c3"),
    (["brdf", *PHONG, "--c1", "-5"], "--c1"),
    (["brdf", *PHONG, "--c1", "nan"], "--c1"),
    (["brdf", *PHONG, "--c1", "inf"], "--c1"),
    (["brdf", *PHONG, "--beta", "0"], "--beta"),
    (["brdf", *PHONG, "--beta", "90"], "--beta"),
    (["brdf", *PHONG, "--beta", "-inf"], "--beta"),
    (["brdf", "lambert", "--incidence", "nan", "--angles", "0"], "--incidence"),
    (["brdf", "lambert", "--incidence", "90", "--angles", "0"], "--incidence"),
    (["brdf", "lambert", "--incidence", "30", "--angles", "0", "nan"], "--angles"),
    (["brdf", "lambert", "--incidence", "30", "--angles", "95"], "--angles"),
    (["brdf", *PHONG, "--azimuth", "inf"], "--azimuth"),
    (["brdf", "heidrich-seidel", "--incidence", "30", "--angles", "0", "--fibre-azimuth", "nan"],
     "--fibre-azimuth"),
    (["brdf", "lambert", "--incidence", "30", "--angles", "0", "--material", "../spectra/Cu"],
     "is not a name"),
    # reflectance render (numbers; output paths below)
    (["render", "s.yaml", "-o", "out.exr", "--width", "0"], "--width"),
    (["render", "s.yaml", "-o", "out.exr", "--height", "-1"], "--height"),
    (["render", "s.yaml", "-o", "out.exr", "--width", "2.5"], "--width"),
    (["render", "s.yaml", "-o", "out.exr", "--supersample", "0"], "--supersample"),
    (["render", "s.yaml", "-o", "out.exr", "--supersample", "100"], "--supersample"),
    (["render", "s.yaml", "-o", "afile/out.exr"], "-o afile/out.exr: afile is a file"),
    (["render", "s.yaml", "-o", "out.exr", "--png", "afile/out.png"], "--png afile/out.png"),
    (["render", "s.yaml", "-o", "out.exr", "--png", "s.yaml/sub/out.png"], "--png"),
    (["render", "s.yaml", "-o", "folder.exr"], "is a folder"),
    # reflectance bench
    (["bench", "--sizes", "0"], "--sizes"),
    (["bench", "--sizes", "64", "nan"], "--sizes"),
    (["bench", "--runs", "0"], "--runs"),
    (["bench", "--supersample", "-2"], "--supersample"),
    (["bench", "--brute-force-runs", "-1"], "--brute-force-runs"),
    (["bench", "--grids", "0"], "--grids"),
    (["bench", "--grids", "nan"], "--grids"),
    (["bench", "--grid-size", "0"], "--grid-size"),
    # issue 25: sizes counted before anything is made, one line naming the option
    (["audit", "Cu", "--wavelengths", "360", "830", "1e-7"], "--wavelengths: 1e-07 nm from 360 to 830 nm makes"),
    (["audit", "Cu", "--angle", "0", "10", "--wavelengths", "400", "700", "1e-8"], "--wavelengths: 1e-08 nm"),
    (["bench", "--grids", "5", "1e-6"], "--grids: 1e-06 nm at --grid-size 512 makes"),
    # a grid short of the blue: the white has no Z (CIE 1931 z-bar is 0 past 650 nm) and X/Y near
    # x-bar/y-bar at 700 nm (0.011359/0.004102 = 2.77); it printed a raw array, naming no option
    (["audit", "Cu", "--wavelengths", "700", "830", "1", "--average-range", "700", "780"],
     "--wavelengths 700-830 nm: the illuminant's white is X, Y, Z = 2.77, 1, 0"),
    (["bench", "--sizes", "64", "16384"], "--sizes 16384, --supersample 2: the ID buffer would be"),
    # --spectra-dir, a folder that does not exist, in every command that looks a material up
    *[(args + ["--spectra-dir", "nope"], "--spectra-dir: no such folder 'nope'")
      for args in (["colour", "Cu", "--angle", "0"], ["spectra"],
                   ["brdf", "lambert", "--material", "Cu", "--incidence", "0", "--angles", "0"],
                   ["render", "s.yaml", "-o", "out.exr"], ["bench", "--sizes", "8"],
                   ["audit", "Cu", "--angle", "0"])],
]

# --config files: (file content, what the message must name besides the file)
BAD_CONFIGS = [
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 0}\n", "wavelengths.step_nm"),
    ("wavelengths: {start_nm: 360, end_nm: 830}\n", "step_nm"),
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: five}\n", "wavelengths.step_nm"),
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: .nan}\n", "wavelengths.step_nm"),
    ("wavelengths: {start_nm: 830, end_nm: 360, step_nm: 5}\n", "start_nm"),
    ("wavelengths: [360, 830, 5]\n", "wavelengths"),
    ("colour: {space: sRGB}\n", "wavelengths"),
    ("- just\n- a list\n", "wavelengths"),
    ("wavelengths: {start_nm: 360\n", "not valid YAML"),
    # issue 25: a grid too fine to make; YAML that grows when read; a key given twice
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 1.0e-8}\n", "wavelengths.step_nm: 1e-08 nm"),
    ('x0: &a ["lol"]\n' + "".join(f"x{i}: &{chr(97 + i)} [{', '.join([f'*{chr(96 + i)}'] * 9)}]\n"
                                   for i in range(1, 9))
     + "wavelengths: {start_nm: 360, end_nm: 830, step_nm: 5}\n", "its aliases expand it"),
    ("x: " + "[" * 3000 + "]" * 3000 + "\nwavelengths: {start_nm: 360, end_nm: 830, step_nm: 5}\n",
     "nested more than 64 levels deep"),
    ("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 5}\nwavelengths: {start_nm: 400}\n",
     "key 'wavelengths' given twice"),
]


@pytest.fixture
def workdir(tmp_path, monkeypatch, root):
    """A folder holding a scene, a regular file 'afile' and a folder 'folder.exr'; the spectra
    are the project's (by --spectra-dir)."""
    (tmp_path / "s.yaml").write_text(SCENE)
    (tmp_path / "afile").write_text("x")
    (tmp_path / "folder.exr").mkdir()
    monkeypatch.chdir(tmp_path)
    return tmp_path


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def refused(args, root):
    """Run the command in-process; return its message. A traceback would fail the test here."""
    with_spectra = args + (["--spectra-dir", str(root / "spectra")] if args[0] != "bench" else [])
    with pytest.raises(SystemExit) as info:
        main(with_spectra)
    code = info.value.code
    assert isinstance(code, str), f"exit code {code!r}: a refusal exits with status 1 and a message"
    return code


@pytest.mark.parametrize("args, named", BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_option_is_refused_naming_it(args, named, workdir, root):
    before = listing(workdir)
    message = refused(args, root)
    assert named in message
    assert "\n" not in message.strip()
    assert listing(workdir) == before  # nothing written


@pytest.mark.parametrize("content, named", BAD_CONFIGS, ids=[c[:60] for c, _ in BAD_CONFIGS])
def test_bad_config_is_refused_naming_file_and_key(content, named, workdir, root):
    (workdir / "bad.yaml").write_text(content)
    before = listing(workdir)
    message = refused(["colour", "Cu", "--angle", "0", "--config", "bad.yaml"], root)
    assert "--config bad.yaml" in message and named in message
    assert "\n" not in message.strip()
    assert listing(workdir) == before


def test_missing_and_binary_config_files(workdir, root):
    assert "no such file" in refused(["colour", "Cu", "--angle", "0", "--config", "nope.yaml"], root)
    (workdir / "bin.yaml").write_bytes(b"\xff\xfe\x00\x81binary")
    message = refused(["colour", "Cu", "--angle", "0", "--config", "bin.yaml"], root)
    assert "--config bin.yaml" in message and "\n" not in message.strip()


def test_the_checks_do_not_refuse_good_values(workdir, root, capsys):
    """The ranges' ends that are allowed give finite numbers (the types are not too strict)."""
    import io

    import numpy as np
    import pandas as pd

    for args in (["brdf", "cook-torrance", "--n", "1000", "--k", "1000", "--m", "0.001",
                  "--incidence", "0", "--angles", "-90", "0", "90"],
                 ["brdf", "cook-torrance", "--n", "1.5", "--c3", "0.001", "--incidence", "89.9",
                  "--angles", "-90", "0", "90"],
                 ["brdf", "torrance-sparrow", "--n", "1.5", "--beta", "0.1", "--incidence", "30",
                  "--angles", "-90", "30", "90"],
                 ["brdf", "phong", "--beta", "0.1", "--incidence", "30", "--angles", "30"],
                 ["brdf", "phong", "--c1", "10000", "--s", "0", "--d", "1", "--incidence", "30",
                  "--angles", "30"]):
        assert main(args) in (0, None)
        table = pd.read_csv(io.StringIO(capsys.readouterr().out))
        assert np.isfinite(table.drop(columns="theta_out_deg").to_numpy()).all(), args


def test_failed_png_leaves_no_exr(workdir, root, monkeypatch):
    """A PNG that cannot be written: one line naming the file, and neither image is left (nor an
    earlier EXR replaced)."""
    import reflectance.render.pipeline as pipeline

    def fail(path, *args, **kwargs):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(pipeline, "write_png", fail)
    (workdir / "old.exr").write_bytes(b"earlier")
    before = listing(workdir)
    for exr in ("out.exr", "old.exr"):
        message = refused(["render", "s.yaml", "-o", exr, "--png", "out.png", "--quiet"], root)
        assert "cannot write" in message and "--png out.png" in message and "nothing written" in message
        assert listing(workdir) == before
    assert (workdir / "old.exr").read_bytes() == b"earlier"


#: the command line, in a process that first makes sure it is not root (root may write anywhere)
AS_A_USER = ("import os, sys\n"
             "assert os.geteuid() != 0, 'still root: the refusal would not be tested'\n"
             "from reflectance.cli import main\n"
             "sys.exit(main())\n")


def unprivileged(command):
    """``command`` as an unprivileged user runs it: unchanged unless the tests run as root (CI
    does), else under setpriv (util-linux) as the user nobody, with no supplementary groups."""
    if os.geteuid() != 0:
        return command
    import pwd
    import shutil

    setpriv = shutil.which("setpriv")
    if setpriv is None:
        if os.environ.get("CI"):  # as tests/conftest.py reads it: CI must not skip this quietly
            pytest.fail("the tests run as root, and setpriv (util-linux), which runs the check "
                        "as the user nobody, is not installed")
        pytest.skip("root may write into any folder, and setpriv is not installed")
    nobody = pwd.getpwnam("nobody")
    return [setpriv, f"--reuid={nobody.pw_uid}", f"--regid={nobody.pw_gid}", "--clear-groups",
            *command]


def test_unwritable_folder_is_refused_before_rendering():
    """An output in a folder the user may not write into is refused, naming the option and the
    folder, before the scene is read: one line, exit status 1, no progress (nothing rendered),
    nothing written. An unprivileged process of its own (as root: the user nobody), in a folder
    outside pytest's (which only root may enter)."""
    import shutil
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix="reflectance-unwritable-"))
    try:
        folder.chmod(0o755)  # nobody may enter it and read the scene, not write
        (folder / "s.yaml").write_text(SCENE)
        (folder / "ro").mkdir()
        (folder / "ro").chmod(0o555)
        proc = subprocess.run(unprivileged([sys.executable, "-c", AS_A_USER, "render", "s.yaml",
                                            "-o", "ro/out.exr"]),
                              cwd=folder, capture_output=True, text=True, timeout=300,
                              env=dict(os.environ, HOME=str(folder)))
        assert proc.returncode == 1, proc.stderr
        # the refusal itself: not the failed write that rendering first would end in
        assert proc.stderr == "reflectance: -o ro/out.exr: cannot write in folder ro\n"
        assert proc.stdout == "" and listing(folder / "ro") == []
    finally:
        if (folder / "ro").exists():
            (folder / "ro").chmod(0o755)  # (a folder of its own user may be removed only so)
        shutil.rmtree(folder)


@pytest.mark.parametrize("move, warning", [
    ("position: [0, -0.2, 0]", "probably inside it"),  # inside the unit sphere
    ("look_at: [0, -10, 0]", "sees no object"),        # looking away from it
])
def test_camera_inside_an_object_or_empty_view_warns(workdir, root, capsys, move, warning):
    key = move.split(":")[0]
    original = "position: [0, -5, 0]" if key == "position" else "look_at: [0, 0, 0]"
    (workdir / "odd.yaml").write_text(SCENE.replace(original, move))
    assert main(["render", "odd.yaml", "-o", "odd.exr", "--quiet", "--spectra-dir",
                 str(root / "spectra")]) == 0
    err = capsys.readouterr().err
    assert warning in err and "camera at position" in err and "odd.yaml" in err
    assert main(["render", "s.yaml", "-o", "ok.exr", "--quiet", "--spectra-dir",
                 str(root / "spectra")]) == 0
    assert "warning" not in capsys.readouterr().err  # the ordinary view does not warn


@pytest.mark.parametrize("args, named", [
    (["colour", "Cu", "--angle", "nan"], "--angle"),
    (["colour", "../x/Cu", "--angle", "0"], "is not a name"),
    (["brdf", *PHONG, "--c1", "-5"], "--c1"),
    (["render", "s.yaml", "-o", "afile/out.exr"], "-o afile/out.exr"),
])
def test_as_a_process_exit_status_1_and_one_line(args, named, workdir, root):
    proc = subprocess.run([sys.executable, "-m", "reflectance.cli", *args, "--spectra-dir",
                           str(root / "spectra")], capture_output=True, text=True, cwd=workdir,
                          env=dict(os.environ, PYTHONPATH=str(root / "workflow")))
    assert proc.returncode == 1
    assert named in proc.stderr and "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and proc.stdout == ""


def test_implicit_config_yaml(workdir, root, capsys):
    """./config.yaml is used when present: someone else's file without ``wavelengths`` falls back
    to the built-in grid (as documented), a broken grid in it is refused naming it."""
    (workdir / "config.yaml").write_text("other: 1\n")
    assert main(["colour", "Cu", "--angle", "0", "--spectra-dir", str(root / "spectra")]) in (0, None)
    assert capsys.readouterr().out.startswith("angle_deg,")
    (workdir / "config.yaml").write_text("wavelengths: {start_nm: 360, end_nm: 830, step_nm: 0}\n")
    message = refused(["colour", "Cu", "--angle", "0"], root)
    assert "--config config.yaml: wavelengths.step_nm" in message


# --- issue 25: mesh files VTK would crash on, answers that are not finite, late or raw errors ----

#: a tetrahedron: four vertices, four faces (0-based)
TET_POINTS = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
TET_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def _obj(points=TET_POINTS, faces=None, extra=""):
    faces = faces or [" ".join(str(i + 1) for i in f) for f in TET_FACES]
    return ("".join(f"v {x} {y} {z}\n" for x, y, z in points) + extra
            + "".join(f"f {f}\n" for f in faces)).encode()


def _ply_ascii(points=TET_POINTS, faces=TET_FACES, n_vertices=None):
    head = (f"ply\nformat ascii 1.0\nelement vertex {n_vertices or len(points)}\n"
            "property float x\nproperty float y\nproperty float z\n"
            f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    return (head + "".join(f"{x} {y} {z}\n" for x, y, z in points)
            + "".join(f"{len(f)} {' '.join(map(str, f))}\n" for f in faces)).encode()


def _ply_binary(points=TET_POINTS, faces=TET_FACES, order="<", n_vertices=None, n_faces=None,
                cut=0):
    import struct

    name = "binary_little_endian" if order == "<" else "binary_big_endian"
    head = (f"ply\nformat {name} 1.0\nelement vertex {n_vertices or len(points)}\n"
            "property float x\nproperty float y\nproperty float z\n"
            f"element face {n_faces or len(faces)}\nproperty list uchar int vertex_indices\n"
            "end_header\n").encode()
    body = b"".join(struct.pack(order + "3f", *p) for p in points)
    body += b"".join(struct.pack(order + "B3i", 3, *f) for f in faces)
    return head + (body[:-cut] if cut else body)


def _stl_binary(points=TET_POINTS, count=None, cut=0):
    import struct

    body = b"".join(struct.pack("<12fH", 0, 0, 0, *points[a], *points[b], *points[c], 0)
                    for a, b, c in TET_FACES)
    data = b"\0" * 80 + struct.pack("<I", len(TET_FACES) if count is None else count) + body
    return data[:-cut] if cut else data


def _stl_ascii(points=TET_POINTS, faces=TET_FACES):
    facets = "".join("facet normal 0 0 0\n outer loop\n"
                     + "".join(f"  vertex {' '.join(map(str, points[i]))}\n" for i in f)
                     + " endloop\nendfacet\n" for f in faces)
    return f"solid tet\n{facets}endsolid tet\n".encode()


def _vtk_ascii(points=TET_POINTS, faces=TET_FACES):
    return ("# vtk DataFile Version 4.2\ntet\nASCII\nDATASET POLYDATA\n"
            f"POINTS {len(points)} float\n" + "".join(f"{x} {y} {z}\n" for x, y, z in points)
            + f"POLYGONS {len(faces)} {4 * len(faces)}\n"
            + "".join(f"3 {' '.join(map(str, f))}\n" for f in faces)).encode()


def _vtk_binary_claiming(n_points):
    return (b"# vtk DataFile Version 4.2\ntet\nBINARY\nDATASET POLYDATA\n"
            + f"POINTS {n_points} float\n".encode() + b"\0" * 48)


def _vtp(points=TET_POINTS, faces=TET_FACES, n_points=None):
    flat = " ".join(str(v) for p in points for v in p)
    connectivity = " ".join(str(i) for f in faces for i in f)
    offsets = " ".join(str(3 * (i + 1)) for i in range(len(faces)))
    return (f'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" '
            f'byte_order="LittleEndian">\n<PolyData>\n<Piece NumberOfPoints='
            f'"{n_points or len(points)}" NumberOfPolys="{len(faces)}">\n'
            f'<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">{flat}'
            f'</DataArray></Points>\n<Polys><DataArray type="Int64" Name="connectivity" '
            f'format="ascii">{connectivity}</DataArray>\n<DataArray type="Int64" Name="offsets" '
            f'format="ascii">{offsets}</DataArray></Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n'
            ).encode()


NAN_POINTS = [(0.0, 0.0, 0.0), (1.0, float("nan"), 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
INF_POINTS = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (float("inf"), 1.0, 0.0), (0.0, 0.0, 1.0)]

#: (file name, its bytes, what the one line must say besides the file's name); none of them
#: may reach VTK's reader (several would crash it: exit -11, no message)
BAD_MESHES = [
    ("index.obj", _obj(faces=["1 2 3", "1 2 9"]), "v index 9 is out of range"),
    ("relative.obj", _obj(faces=["1 2 3", "-1 -2 -7"]), "v index -7 is out of range"),
    ("zero.obj", _obj(faces=["0 1 2"]), "v index 0 is out of range"),
    ("texture.obj", _obj(faces=["1/1 2/2 3/5"], extra="vt 0 0\nvt 1 0\nvt 0 1\n"),
     "vt index 5 is out of range"),
    ("nan.obj", _obj(points=NAN_POINTS), "vertex 1 has a coordinate that is not finite"),
    ("inf.obj", _obj(points=INF_POINTS), "vertex 2 has a coordinate that is not finite"),
    ("words.obj", _obj(faces=["1 2 three"]), "'three' is not an index"),
    ("negative.ply", _ply_ascii(faces=[(0, 1, 2), (0, -1, 3)]), "index -1 is out of range"),
    ("short.ply", _ply_ascii(n_vertices=400), "declares 404 element lines but the file holds"),
    ("count.ply", _ply_ascii().replace(b"3 1 2 3\n", b"4 1 2 3\n"), "says 4 indices, holds 3"),
    ("nan_ascii.ply", _ply_ascii(points=NAN_POINTS), "vertex 1 has a coordinate"),
    ("big_endian.ply", _ply_binary(faces=[(0, 1, 2), (0, 1, 70000)], order=">"),
     "face index 70000 is out of range: the file has 4 vertices"),
    ("faces.ply", _ply_binary(n_faces=2_000_000_000),
     "declares 2000000000 face elements but only"),
    ("inf.ply", _ply_binary(points=INF_POINTS), "vertex 2 has a coordinate that is not finite"),
    ("list_cut.ply", _ply_binary(cut=5), "lists run past the end of the file"),
    ("no_header_end.ply", b"ply\nformat ascii 1.0\nelement vertex 3\n", "no 'ply' ... 'end_header'"),
    ("cut.stl", _stl_binary(cut=30), "a binary STL of 4 triangles has 284 bytes, this file 254"),
    ("count.stl", _stl_binary(count=4_000_000_000), "a binary STL of 4000000000 triangles"),
    ("inf.stl", _stl_binary(points=INF_POINTS), "has a coordinate that is not finite"),
    ("nan_ascii.stl", _stl_ascii(points=NAN_POINTS), "has a coordinate that is not finite"),
    ("two.stl", _stl_ascii(faces=[(0, 1)]), "holds 2 vertices, not three per facet"),
    ("index.vtk", _vtk_ascii(faces=[(0, 1, 2), (0, 1, 12)]),
     "a cell's vertex index 12 is out of range: the file has 4 vertices"),
    ("nan.vtk", _vtk_ascii(points=NAN_POINTS), "vertex 1 has a coordinate that is not finite"),
    ("points.vtk", _vtk_binary_claiming(3_000_000_000), "POINTS declares 3000000000 entries"),
    ("index.vtp", _vtp(faces=[(0, 1, 2), (3, 1, 40)]), "connectivity index 40 is out of range"),
    ("cut.vtp", _vtp()[:200], "not well-formed XML"),
    ("points.vtp", _vtp(n_points=2_000_000_000), "declares 2000000000 points"),
]

MESH_SCENE = """\
camera: {{position: [3, -4, 2], look_at: [0.3, 0.3, 0.3], fov_deg: 30, width: 8, height: 6}}
objects:
  - geometry: {{type: mesh, path: {path}}}
    material: {{name: Cu, m: 0.3}}
lights: [{{type: directional, direction: [0, -1, 1]}}]
"""


@pytest.mark.parametrize("name, data, said", BAD_MESHES, ids=[c[0] for c in BAD_MESHES])
def test_bad_mesh_file_is_refused_before_vtk_reads_it(name, data, said, workdir, root):
    (workdir / name).write_bytes(data)
    (workdir / "mesh.yaml").write_text(MESH_SCENE.format(path=name))
    before = listing(workdir)
    message = refused(["render", "mesh.yaml", "-o", "out.exr", "--png", "out.png", "--quiet"],
                      root)
    assert f"{name}: " in message and said in message, message
    assert "mesh.yaml: objects[0].geometry" in message
    assert "\n" not in message.strip()
    assert listing(workdir) == before


@pytest.mark.parametrize("name, data", [
    ("tet.obj", _obj()), ("tet_ascii.ply", _ply_ascii()), ("tet_le.ply", _ply_binary()),
    ("tet_be.ply", _ply_binary(order=">")), ("tet.stl", _stl_binary()),
    ("tet_ascii.stl", _stl_ascii()), ("tet.vtk", _vtk_ascii()), ("tet.vtp", _vtp())])
def test_the_same_meshes_intact_are_read(name, data, workdir, root):
    """The writers above make readable files: each refusal is of its one defect."""
    from reflectance.geometry.shapes import mesh_from_file

    (workdir / name).write_bytes(data)
    mesh = mesh_from_file(workdir / name)
    assert mesh.n_cells == 4
    np.testing.assert_allclose(np.unique(np.asarray(mesh.points), axis=0),
                               np.unique(np.array(TET_POINTS), axis=0))


# scenes that read, but whose answer would be wrong or black (the mesh scene's header)
def _scene(objects="  - geometry: {type: sphere, radius: 1.0}\n    material: {name: Cu, m: 0.3}\n",
           lights="[{type: directional, direction: [0, -1, 1]}]"):
    return ("camera: {position: [0, -5, 0], look_at: [0, 0, 0], fov_deg: 30, width: 8, "
            f"height: 6}}\nobjects:\n{objects}lights: {lights}\n")


BAD_SCENES = [
    ("dark.yaml", _scene(lights="[]"), "dark.yaml: lights: no light, and no object emits"),
    ("dielectric.yaml", _scene(objects="  - geometry: {type: sphere, radius: 1.0}\n"
                                       "    material: {index: {n: 0.7}, m: 0.3}\n"),
     "dielectric.yaml: objects[0].material.index.n: 0.7: a dielectric's index (k = 0) must be "
     "at least 1"),
    ("huge_n.yaml", _scene(objects="  - geometry: {type: sphere, radius: 1.0}\n"
                                   "    material: {index: {n: 1.0e+300}, m: 0.3}\n"),
     "huge_n.yaml: objects[0].material.index.n: 1e+300 is greater than the maximum"),
    ("huge_k.yaml", _scene(objects="  - geometry: {type: sphere, radius: 1.0}\n"
                                   "    material: {index: {n: 1.5, k: 1.0e+160}, m: 0.3}\n"),
     "huge_k.yaml: objects[0].material.index.k: 1e+160 is greater than the maximum"),
    ("sky.yaml", _scene(lights="[{type: directional, direction: [0, -1, 1], solid_angle: 20}]"),
     "sky.yaml: lights[0].solid_angle: 20 is greater than the maximum of 12.566"),
]


@pytest.mark.parametrize("name, text, said", BAD_SCENES, ids=[c[0] for c in BAD_SCENES])
def test_scene_with_a_wrong_answer_is_refused(name, text, said, workdir, root):
    (workdir / name).write_text(text)
    before = listing(workdir)
    message = refused(["render", name, "-o", "out.exr", "--png", "out.png", "--quiet"], root)
    assert said in message, message
    assert "\n" not in message.strip()
    assert listing(workdir) == before


#: spectrum files whose numbers would overflow the Fresnel equations (NaN colours, exit 0 before)
BAD_SPECTRA = [
    ("huge_k", "wavelength_nm,n,k\n350,0.5,1e300\n850,0.5,1e300\n",
     "huge_k.csv, data row 1 (line 2): k = 1e+300 is above 1e+06"),
    ("huge_n", "wavelength_nm,n,k\n350,1.5,0\n600,2e7,0\n850,1.5,0\n",
     "huge_n.csv, data row 2 (line 3): n = 2e+07 is above 1e+06"),
]


@pytest.mark.parametrize("stem, text, said", BAD_SPECTRA, ids=[c[0] for c in BAD_SPECTRA])
@pytest.mark.parametrize("command", ["audit", "colour", "brdf"])
def test_spectrum_that_overflows_is_refused_by_every_command(stem, text, said, command, workdir,
                                                             root):
    (workdir / f"{stem}.csv").write_text(text)
    args = {"audit": ["audit", f"{stem}.csv", "--angle", "0", "60", "-o", "out"],
            "colour": ["colour", stem, "--angle", "0", "--spectra-dir", "."],
            "brdf": ["brdf", "cook-torrance", "--material", stem, "--m", "0.3", "--incidence",
                     "30", "--angles", "0", "--spectra-dir", "."]}[command]
    before = listing(workdir)
    message = refused(args, root)
    assert said in message, message
    assert "\n" not in message.strip()
    assert listing(workdir) == before  # (audit: no out/, not even audit.png alone)


def test_audit_output_is_all_files_or_none(workdir, root, monkeypatch):
    """The last of audit -o's files fails: none of them is left, and an earlier run's files
    stay as they were."""
    import reflectance.io.provenance as provenance

    def fail(*args, **kwargs):
        raise OSError(28, "No space left on device", "audit_metadata.yaml")

    assert main(["audit", "Cu", "--angle", "0", "60", "-o", "kept", "--spectra-dir",
                 str(root / "spectra")]) in (0, None)
    kept = {p.name: p.read_bytes() for p in (workdir / "kept").iterdir()}
    monkeypatch.setattr(provenance, "write_metadata", fail)
    before = listing(workdir)
    for out in ("new", "kept"):
        message = refused(["audit", "Au", "--angle", "0", "60", "-o", out], root)
        assert "No space left on device" in message and "\n" not in message.strip()
        assert listing(workdir) == before
    assert {p.name: p.read_bytes() for p in (workdir / "kept").iterdir()} == kept


@pytest.mark.parametrize("args, said", [
    (["brdf", "cook-torrance", "--n", "0.5", "--m", "0.3", "--incidence", "30", "--angles", "0"],
     "--n 0.5: a dielectric's index (--k 0) must be at least 1"),
    (["brdf", "torrance-sparrow", "--n", "0.99", "--incidence", "30", "--angles", "0"],
     "--n 0.99: a dielectric's index"),
    (["bench", "--scene", "nope.yaml", "--sizes", "8", "--runs", "1"],
     "nope.yaml: no such scene file"),
    (["bench", "--scene", "dark.yaml", "--sizes", "8", "--runs", "1"],
     "dark.yaml: lights: no light"),
])
def test_late_errors_come_first_as_one_line(args, said, workdir, root):
    (workdir / "dark.yaml").write_text(_scene(lights="[]"))
    before = listing(workdir)
    message = refused(args, root)
    assert said in message, message
    assert "\n" not in message.strip()
    assert listing(workdir) == before


def test_a_metal_may_have_n_below_1(workdir, root, capsys):
    """n < 1 is refused only for a dielectric: silver's n is about 0.05 in the visible."""
    assert main(["brdf", "cook-torrance", "--n", "0.05", "--k", "3.6", "--m", "0.3",
                 "--incidence", "30", "--angles", "0"]) in (0, None)
    assert capsys.readouterr().out.startswith("theta_out_deg,")


def test_a_fine_wavelength_step_that_fits_runs_and_agrees_with_1_nm(workdir, root, capsys,
                                                                   monkeypatch):
    """A fine step that divides the range and fits the size bound is a correct run, not a numpy
    broadcast error: colour-science's align gave D65 (tabulated to 780 nm) one sample more than
    the grid at 0.001 nm (issue 25). The rectangle rule converges: the 0.0025 nm integral of the
    same spectrum agrees with the 1 nm one (they differ by about 1e-6 here)."""
    import io

    import pandas as pd

    from reflectance.colour import tables

    monkeypatch.setenv(tables.CACHE_ENVIRONMENT_VARIABLE, str(workdir / "cache"))
    tables.forget()  # the tables computed here, not read from an earlier run's cache

    def exact_XYZ(step):
        args = ["audit", "Cu", "--angle", "0", "--wavelengths", "360", "830", step,
                "--spectra-dir", str(root / "spectra")]
        assert main(args) in (0, None)
        table = pd.read_csv(io.StringIO(capsys.readouterr().out))
        return table.loc[table["method"] == "exact", ["X", "Y", "Z"]].to_numpy()[0]

    fine = exact_XYZ("0.0025")  # 188001 wavelengths
    assert np.all(np.isfinite(fine))
    np.testing.assert_allclose(fine, exact_XYZ("1"), rtol=1e-4)


BUSY_SCENE = """\
camera: {position: [0, -5, 1], look_at: [0, 0, 0.3], fov_deg: 35, width: 800, height: 600,
         supersample: 3}
objects:
  - {geometry: {type: sphere, center: [0, 0, 0.5], radius: 0.5}, material: {name: Cu, m: 0.3}}
  - {geometry: {type: plane, center: [0, 0, 0], normal: [0, 0, 1], size: [6, 6]},
     material: {model: Lambert, albedo: 0.5}}
lights: [{type: directional, direction: [-0.4, -0.6, 0.7]}]
"""


def _command(*args):
    return [sys.executable, "-m", "reflectance.cli", *args]


def test_ctrl_c_during_render_is_one_line_and_exit_130(workdir, root):
    """SIGINT while the renderer works (after its first band's progress, on a terminal): one
    line, the shell's status for it (128 + 2), no traceback, no file."""
    import signal
    import time

    from terminal import read_rest, stderr_of

    (workdir / "busy.yaml").write_text(BUSY_SCENE)
    before = listing(workdir)
    proc, _ = stderr_of(_command("render", "busy.yaml", "-o", "busy.exr", "--png", "busy.png",
                                 "--spectra-dir", str(root / "spectra")), True,
                        until=lambda text: "visibility" in text,  # the render has begun
                        cwd=workdir, env=dict(os.environ, PYTHONPATH=str(root / "workflow")),
                        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    rest = read_rest(proc)
    assert proc.returncode == 130, rest
    assert "Traceback" not in rest and "KeyboardInterrupt" not in rest
    # its own line, after the bar's (a redraw is "\r"; the terminal ends a line with "\r\n")
    said = [line for line in rest.split("\r\n") if line.startswith("reflectance: ")]
    assert said == ["reflectance: render: interrupted; no file written"], rest
    assert rest.endswith("\r\nreflectance: render: interrupted; no file written\r\n"), rest
    assert listing(workdir) == before


#: run the command with its files limited to 64 KiB (as a disk that fills up: EFBIG, the signal
#: ignored), in a process of its own
SMALL_DISK = ("import os, resource, signal, sys\n"
              "signal.signal(signal.SIGXFSZ, signal.SIG_IGN)\n"
              "limit = int(os.environ['FILE_LIMIT'])\n"
              "resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))\n"
              "from reflectance.cli import main\n"
              "sys.exit(main())\n")


@pytest.mark.parametrize("output, limit", [(["-o", "full.exr"], 65536),
                                           (["--png", "full.png"], 1024)])
def test_a_full_disk_is_one_line_naming_the_file(output, limit, workdir, root):
    """An image that does not fit: one line naming the file (not OpenEXR's RuntimeError), exit
    status 1, no file (nor a hidden temporary) left."""
    (workdir / "big.yaml").write_text(SCENE.replace("width: 8, height: 6", "width: 256, height: 256"))
    before = listing(workdir)
    proc = subprocess.run([sys.executable, "-c", SMALL_DISK, "render", "big.yaml", *output,
                           "--quiet", "--spectra-dir", str(root / "spectra")],
                          cwd=workdir, capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, PYTHONPATH=str(root / "workflow"),
                                   FILE_LIMIT=str(limit)))
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    assert proc.stderr.startswith(f"reflectance: cannot write {output[-1]} ("), proc.stderr
    assert "nothing written" in proc.stderr and ".tmp-" not in proc.stderr, proc.stderr
    assert listing(workdir) == before


def test_a_jobs_write_error_is_one_line_in_its_log(tmp_path):
    """Inside a job (reflectance.scripting.script_log), a file that cannot be written is one
    line of the log naming it, and the job fails; other errors keep their traceback."""
    from types import SimpleNamespace

    from reflectance.io.atomic import write_text
    from reflectance.scripting import script_log

    job = SimpleNamespace(log=[str(tmp_path / "job.log")], rule="a_rule")
    real_replace = os.replace

    def full(src, dst):
        raise OSError(28, "No space left on device", str(src))

    os.replace = full
    try:
        with pytest.raises(SystemExit) as info, script_log(job):
            write_text(tmp_path / "out.csv", "a,b\n")
    finally:
        os.replace = real_replace
    assert info.value.code == 1
    log = (tmp_path / "job.log").read_text()
    assert log == f"ERROR cannot write {tmp_path / 'out.csv'}: No space left on device\n", log
    assert sorted(p.name for p in tmp_path.iterdir()) == ["job.log"]
    with pytest.raises(ZeroDivisionError), script_log(job):
        1 / 0
    assert "Traceback" in (tmp_path / "job.log").read_text()


def test_an_audit_colour_that_is_not_finite_names_the_material():
    """The last guard, behind the spectrum files' bound: a material built in code with k = 1e200
    (k^2 overflows) is refused by the audit, naming it, the method and the angle."""
    from reflectance.audit.shortcuts import audit_table
    from reflectance.colour.colorimetry import tristimulus_weights
    from reflectance.optics.spectra import wavelength_grid
    from reflectance.render.scene import constant_index_material

    grid = wavelength_grid(380, 780, 10)
    with np.errstate(over="ignore", invalid="ignore"):
        material = constant_index_material(1.5, 1e200, grid)
    with pytest.raises(ValueError, match=r"its exact colour at 0 degrees is not finite \(X, Y, Z = "
                                         r"nan, nan, nan\)"):
        audit_table(material, [0, 60], tristimulus_weights(grid, "D65"), methods=("exact",))
