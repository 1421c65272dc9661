"""README's Python quick start runs as written: every ```python block, each on its own, in an
empty folder (one interpreter, so the imports are paid once)."""

import re
import subprocess
import sys

RUN_ALL = """
import os, runpy, sys
for path in sys.argv[1:]:
    print(f"=== {path}", flush=True)
    os.chdir(os.path.dirname(path))
    runpy.run_path(path, run_name="__main__")
"""


def python_blocks(readme):
    return re.findall(r"^```python\n(.*?)^```$", readme.read_text(), re.S | re.M)


def test_readme_quick_start_runs(root, tmp_path):
    blocks = python_blocks(root / "README.md")
    assert len(blocks) >= 4  # a material, its colour against angle, a BRDF, a scene from a dict
    paths = []
    for i, code in enumerate(blocks):
        folder = tmp_path / f"block{i}"  # each block starts in an empty folder of its own
        folder.mkdir()
        (folder / "snippet.py").write_text(code)
        paths.append(folder / "snippet.py")
    proc = subprocess.run([sys.executable, "-c", RUN_ALL, *map(str, paths)], cwd=tmp_path,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    outputs = proc.stdout.split("=== ")[1:]
    assert len(outputs) == len(blocks)

    # what the prose around the blocks promises, checked from their output and files
    from PIL import Image

    rendered = [p.parent for p in paths if (p.parent / "copper.png").exists()]
    assert rendered, "the scene block wrote no copper.png"
    with Image.open(rendered[0] / "copper.png") as im:
        assert im.size == (96, 64)
    assert (rendered[0] / "copper.exr").stat().st_size > 0
    brdf_out = next(o for o in outputs if "(5, 95)" in o)
    values = [float(v) for v in re.search(r"\[([^\]]*)\]\s*$", brdf_out).group(1).split()]
    assert max(range(5), key=values.__getitem__) == 3  # the mirror direction, +30 degrees
