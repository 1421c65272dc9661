"""README.md fits a screen or two and keeps its promises; the guides it points to (the Sphinx
site's pages in workflow/docs/guides/, where README's longer text moved) run as written.

The guide's quick start runs as written: every ``.. code-block:: python`` of
workflow/docs/guides/python.rst, each on its own, in an empty folder (one interpreter, so the
imports are paid once), and every ``.. code-block:: bash`` of a guide marked with the comment
``.. runs as written ...`` (the scene rendered in workflow/docs/guides/rendering.rst), each in an
empty folder with the ``reflectance`` command of this environment.

The helpers here serve tests/test_audit_cli.py too, which runs the same blocks from an installed
wheel in a fresh environment."""

import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

#: the guides of the Sphinx site (workflow/docs), where README's longer text lives
GUIDES = Path("workflow") / "docs" / "guides"
#: the guide whose python blocks are the quick start
QUICK_START = GUIDES / "python.rst"
#: the guide whose marked bash block renders a scene
RENDER_GUIDE = GUIDES / "rendering.rst"

RUN_ALL = """
import os, runpy, sys
for path in sys.argv[1:]:
    print(f"=== {path}", flush=True)
    os.chdir(os.path.dirname(path))
    runpy.run_path(path, run_name="__main__")
"""

#: the comment that marks a ``.. code-block:: bash`` of a guide as one the tests run
RUNS_AS_WRITTEN = ".. runs as written"


def _code_blocks(text, language, after=None):
    """The bodies of the ``.. code-block:: <language>`` directives of the reStructuredText
    ``text``, dedented; with ``after``, only those whose directive comes right after a line
    starting with ``after`` (and a blank line)."""
    lead = rf"^{re.escape(after)}[^\n]*\n\n" if after else r"^"
    blocks = re.findall(rf"{lead}\.\. code-block:: {language}\n((?:[ \t]+:[^\n]*\n)*)\n"
                        r"((?:(?:[ \t]+[^\n]*)?\n)+)", text, re.M)
    return [textwrap.dedent(body).strip("\n") + "\n" for _, body in blocks]


def python_blocks(page):
    return _code_blocks(Path(page).read_text(encoding="utf-8"), "python")


def shell_blocks(page):
    """The ``.. code-block:: bash`` blocks right after a comment starting with
    :data:`RUNS_AS_WRITTEN`."""
    return _code_blocks(Path(page).read_text(encoding="utf-8"), "bash", after=RUNS_AS_WRITTEN)


def quick_start(page, folder, python=sys.executable):
    """Each python block written into an empty folder of its own below ``folder``: (the
    scripts, the command that runs them all in one ``python``)."""
    paths = []
    for i, code in enumerate(python_blocks(page)):
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


def shell_commands(page, folder):
    """Each marked bash block written into an empty folder of its own below ``folder``: a list
    of (that folder, the command that runs it, stopping at the first failure)."""
    commands = []
    for i, code in enumerate(shell_blocks(page)):
        block = folder / f"shell{i}"
        block.mkdir()
        (block / "block.sh").write_text(code)
        commands.append((block, ["bash", "-e", str(block / "block.sh")]))
    return commands


def check_render_block(block, proc):
    """The rendering guide's "Rendering scenes": the scene of two spheres, copper by name and a red paint from its
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


def test_guide_quick_start_runs(root, tmp_path):
    paths, command = quick_start(root / QUICK_START, tmp_path)
    proc = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True)
    check_quick_start(paths, proc)


def test_guide_render_block_runs(root, tmp_path):
    (block, command), = shell_commands(root / RENDER_GUIDE, tmp_path)
    proc = subprocess.run(command, cwd=block, capture_output=True, text=True,
                          env=this_environment(), timeout=600)
    check_render_block(block, proc)


# --- README: one screen or two, the rest in the guides ---------------------------------------

#: README's two set-up blocks, as a new user types them: the build, then the tests
BUILD_BLOCK = """python3 -m venv .venv && . .venv/bin/activate
pip install -c workflow/envs/constraints.txt -e .
snakemake --cores 2
"""
TEST_BLOCK = """python3 -m venv .venv && . .venv/bin/activate
pip install -c workflow/envs/constraints.txt -e '.[test]'
pytest
"""


def _markdown_bash_blocks(text):
    return re.findall(r"^```bash\n(.*?)^```$", text, re.S | re.M)


def _guides(root):
    return sorted((root / GUIDES).glob("*.rst"))


def test_readme_fits_two_screens(root):
    """What it is, the picture, the two set-up commands, one result, the audit, the guides; no
    more than two screens of text."""
    readme = (root / "README.md").read_text(encoding="utf-8")
    lines = readme.splitlines()
    assert len(lines) <= 100, len(lines)
    assert lines[2].startswith("![") and "(workflow/docs/strip.png)" in lines[2]
    headings = re.findall(r"^## (.*)$", readme, re.M)
    assert headings == ["Set up and run", "One result", "The audit", "Guides"], headings
    audit = re.search(r"^## The audit\n\n```bash\n(.*?)^```$", readme, re.S | re.M).group(1)
    assert [line.split()[:2] for line in audit.splitlines()] == [["reflectance", "audit"]] * 3


def test_readme_set_up_blocks_are_the_two_commands(root):
    """The build installs the package alone and builds every figure; the tests install the test
    extra and run pytest (the hook before a session ends, and .ci/run, look for both). The
    building guide shows the same two blocks."""
    blocks = _markdown_bash_blocks((root / "README.md").read_text(encoding="utf-8"))
    assert blocks[:2] == [BUILD_BLOCK, TEST_BLOCK]
    guide = _code_blocks((root / GUIDES / "building.rst").read_text(encoding="utf-8"), "bash")
    strip = [re.sub(r"[ \t]+#[^\n]*", "", block) for block in guide[:2]]
    assert strip == [BUILD_BLOCK, TEST_BLOCK]


def test_readme_types_no_computed_number(root):
    """A number the build computes is stated by the build (a results file), never typed into
    README, where it would go stale. The decimals README may hold: the Python version and the
    lecture's course number. Nor do the guides type the results the README once typed (the
    figures' CSVs state them); their measurements carry their dates (next test)."""
    readme = (root / "README.md").read_text(encoding="utf-8")
    decimals = set(re.findall(r"(?<![\w.])\d+\.\d+(?![\w.])", readme))
    assert decimals <= {"3.10", "605.767"}, decimals
    for page in [root / "README.md", *_guides(root)]:
        text = page.read_text(encoding="utf-8")
        for computed in ("89.24", "13.4 ", "166.9", "2,127"):
            assert computed not in text, (page.name, computed)


def test_guide_measurements_keep_their_date(root):
    """Every measurement in the guides (a table or paragraph closed by the ``.. measured``
    comment) carries its date: an ISO date in the text since the section's heading."""
    for page in _guides(root):
        text = page.read_text(encoding="utf-8")
        sections = re.split(r"^.+\n[=\-~]{3,}\n", text, flags=re.M)
        for section in sections:
            for before in section.split(".. measured")[:-1]:
                assert re.search(r"\b20\d\d-\d\d-\d\d\b", before), (page.name, before[-300:])
    # the measured parts README had are all in the guides
    measured = sum(p.read_text(encoding="utf-8").count(".. measured") for p in _guides(root))
    assert measured >= 6, measured


def test_readme_links_and_guides_are_one_set(root):
    """Every relative link of README resolves; every guide is linked from README and listed in
    the site's table of contents (Sphinx -W refuses a page that is in none)."""
    readme = (root / "README.md").read_text(encoding="utf-8")
    links = re.findall(r"\]\(([^)#\s]+)\)", readme)
    assert links
    for link in links:
        assert not link.startswith("http"), link
        assert (root / link).exists(), link
    guides = {p.relative_to(root).as_posix() for p in _guides(root)}
    assert guides and guides <= set(links), guides - set(links)
    index = (root / "workflow" / "docs" / "index.rst").read_text(encoding="utf-8")
    toc = set(re.findall(r"^   (guides/\S+)$", index, re.M))
    assert {f"guides/{Path(g).stem}" for g in guides} == toc


def test_guides_name_files_that_exist(root):
    """Each file or folder of the repository a guide or README names (a test module, a
    profile, a script, a scene, a schema) exists: the text moved with its references intact."""
    pages = [root / "README.md", *_guides(root)]
    named = set()
    for page in pages:
        text = page.read_text(encoding="utf-8")
        named |= set(re.findall(r"(?<![\w/.])((?:tests|workflow|\.ci)/[\w./-]*[\w])", text))
        named |= set(re.findall(r"--profile (\S+)", text))
    named = {n for n in named if not re.search(r"[<>*{}]", n)}
    assert len(named) > 20, named
    missing = sorted(n for n in named if not (root / n).exists())
    assert missing == [], missing
