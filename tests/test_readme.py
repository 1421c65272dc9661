"""README's quick start runs as written: every ```python block, each on its own, in an empty
folder (one interpreter, so the imports are paid once), and every ```bash block marked
``<!-- runs as written ... -->`` (the scene rendered in "Rendering scenes"), each in an empty
folder with the ``reflectance`` command of this environment.

The helpers here serve tests/test_audit_cli.py too, which runs the same blocks from an installed
wheel in a fresh environment."""

import os
import re
import subprocess
import sys
from pathlib import Path

RUN_ALL = """
import os, runpy, sys
for path in sys.argv[1:]:
    print(f"=== {path}", flush=True)
    os.chdir(os.path.dirname(path))
    runpy.run_path(path, run_name="__main__")
"""

#: the line that marks a ```bash block of README.md as one the tests run
RUNS_AS_WRITTEN = "<!-- runs as written"


def python_blocks(readme):
    return re.findall(r"^```python\n(.*?)^```$", readme.read_text(), re.S | re.M)


def shell_blocks(readme):
    """The ```bash blocks right after a line starting with :data:`RUNS_AS_WRITTEN`."""
    return re.findall(rf"^{re.escape(RUNS_AS_WRITTEN)}[^\n]*\n```bash\n(.*?)^```$",
                      readme.read_text(), re.S | re.M)


def quick_start(readme, folder, python=sys.executable):
    """Each python block written into an empty folder of its own below ``folder``: (the
    scripts, the command that runs them all in one ``python``)."""
    paths = []
    for i, code in enumerate(python_blocks(readme)):
        block = folder / f"block{i}"  # each block starts in an empty folder of its own
        block.mkdir()
        (block / "snippet.py").write_text(code)
        paths.append(block / "snippet.py")
    return paths, [python, "-c", RUN_ALL, *map(str, paths)]


def check_quick_start(paths, proc):
    """What the prose around the python blocks promises, checked from their output and files
    (``proc``: the finished command of :func:`quick_start`)."""
    from PIL import Image

    assert len(paths) >= 4  # a material, its colour against angle, a BRDF, a scene from a dict
    assert proc.returncode == 0, proc.stdout + proc.stderr
    outputs = proc.stdout.split("=== ")[1:]
    assert len(outputs) == len(paths)
    rendered = [p.parent for p in paths if (p.parent / "copper.png").exists()]
    assert rendered, "the scene block wrote no copper.png"
    with Image.open(rendered[0] / "copper.png") as im:
        assert im.size == (96, 64)
    assert (rendered[0] / "copper.exr").stat().st_size > 0
    brdf_out = next(o for o in outputs if "(5, 95)" in o)
    values = [float(v) for v in re.search(r"\[([^\]]*)\]\s*$", brdf_out).group(1).split()]
    assert max(range(5), key=values.__getitem__) == 3  # the mirror direction, +30 degrees
    material = next(o for o in outputs if "my_glaze" in o).splitlines()
    assert material[1].startswith("measured [")  # the bundled copper's F0
    assert material[2].startswith("my_glaze derived [") and material[-1] == "derived"


def shell_commands(readme, folder):
    """Each marked bash block written into an empty folder of its own below ``folder``: a list
    of (that folder, the command that runs it, stopping at the first failure)."""
    commands = []
    for i, code in enumerate(shell_blocks(readme)):
        block = folder / f"shell{i}"
        block.mkdir()
        (block / "block.sh").write_text(code)
        commands.append((block, ["bash", "-e", str(block / "block.sh")]))
    return commands


def check_render_block(block, proc):
    """"Rendering scenes": the scene of two spheres, copper by name and a red paint from its
    own file, rendered to the EXR and a 120 x 80 PNG."""
    import numpy as np
    from PIL import Image

    from reflectance.io.images import read_exr

    assert proc.returncode == 0, proc.stdout + proc.stderr
    with Image.open(block / "my_scene.png") as im:
        assert im.size == (120, 80)
    XYZ, _ = read_exr(block / "my_scene.exr")
    assert XYZ.shape == (80, 120, 3)
    # the right half holds the paint sphere and the grey floor: only the paint (its file: a
    # reflectance rising past 600 nm) makes pixels far redder than the D65 white (x = 0.3127)
    right = XYZ[:, 60:].reshape(-1, 3)
    lit = right[right[:, 1] > 1e-3 * XYZ[..., 1].max()]
    x = lit[:, 0] / lit.sum(axis=1)
    assert np.count_nonzero(x > 0.45) > 20, np.sort(x)[-5:]


def this_environment():
    """The environment with this interpreter's scripts folder (its `reflectance`) first on
    PATH."""
    bin_dir = str(Path(sys.executable).parent)
    return dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))


def test_readme_quick_start_runs(root, tmp_path):
    paths, command = quick_start(root / "README.md", tmp_path)
    proc = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True)
    check_quick_start(paths, proc)


def test_readme_render_block_runs(root, tmp_path):
    (block, command), = shell_commands(root / "README.md", tmp_path)
    proc = subprocess.run(command, cwd=block, capture_output=True, text=True,
                          env=this_environment(), timeout=600)
    check_render_block(block, proc)
