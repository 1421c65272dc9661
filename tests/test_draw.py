"""The rendered figures' scripts are one call each (issue 24, part 1): the drawing lives in
reflectance.papers.draw, one module per figure; its rule's params carry the SHA-256 of that
module's file, so an edit of the drawing reruns exactly that figure (Snakemake's code trigger
watches the script alone); the config check and the Snakefile's parse never import it."""

from __future__ import annotations

import ast
import hashlib
import os
import re
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from reflectance.papers.figures import FIGURES
from test_architecture import _python_of_rules
from test_figures import AGGREGATING, READ_BY, _copy, _dry_run
from test_types import missing_annotations
from test_workflow import _planned_jobs

ROOT = Path(__file__).resolve().parents[1]
RULES = ROOT / "workflow" / "rules"
DRAW = ROOT / "workflow" / "reflectance" / "papers" / "draw"


def rule_blocks(path=RULES / "renders.smk"):
    """{rule name: its text} of a rules file."""
    blocks = re.split(r"(?m)^(?=rule )", path.read_text())[1:]
    return {re.match(r"rule (\w+):", block).group(1): block for block in blocks}


def script_of(block):
    """The script a rule's block runs (workflow/scripts/...)."""
    relative = re.search(r'(?ms)^    script:\n\s+"([^"]+)"', block).group(1)
    return (RULES / relative).resolve()


def problems_of_a_call(text, name):
    """What keeps a script's ``text`` from being a call of figure ``name``'s drawing: a module
    docstring, then imports only, then one expression, ``run_job(snakemake, run)`` with ``run``
    from ``reflectance.papers.draw.<name>``."""
    body = ast.parse(text).body
    problems = []
    if not (body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant)
            and isinstance(body[0].value.value, str)):
        problems.append("no module docstring first")
        body = [None, *body]
    *imports, last = body[1:] or [None]
    if not all(isinstance(node, (ast.Import, ast.ImportFrom)) for node in imports):
        problems.append("statements other than imports before the call")
    if not (isinstance(last, ast.Expr) and isinstance(last.value, ast.Call)
            and ast.unparse(last.value) == "run_job(snakemake, run)"):
        problems.append("the last statement is not run_job(snakemake, run)")
    sources = {alias.asname or alias.name: node.module for node in imports
               if isinstance(node, ast.ImportFrom) for alias in node.names}
    if sources.get("run") != f"reflectance.papers.draw.{name}":
        problems.append(f"run is not reflectance.papers.draw.{name}'s")
    if sources.get("run_job") != "reflectance.scripting":
        problems.append("run_job is not reflectance.scripting's")
    return problems


def draw_digest(name, basedir=ROOT):
    """workflow/rules/common.smk's ``draw_digest``, run as the Snakefile's parse runs it (with
    ``workflow.basedir``), taken from the rules file itself."""
    tree = ast.parse((RULES / "common.smk").read_text())
    functions = [node for node in tree.body if isinstance(node, ast.FunctionDef)
                 and node.name in ("_file_digest", "draw_digest")]
    namespace = {"hashlib": hashlib, "os": os, "workflow": SimpleNamespace(basedir=str(basedir))}
    exec(compile(ast.Module(functions, []), "common.smk", "exec"), namespace)  # noqa: S102
    return namespace["draw_digest"](name)


def test_every_figure_has_one_drawing():
    """A module of reflectance.papers.draw per rendered figure, of the same name, and no other;
    each exposes one public function, ``run(snakemake, log)``, annotated."""
    import importlib

    import reflectance.papers.draw as package

    assert {p.stem for p in DRAW.glob("*.py")} - {"__init__"} == set(FIGURES)
    assert sorted(package.__all__) == sorted(FIGURES)
    for name in FIGURES:
        module = importlib.import_module(f"reflectance.papers.draw.{name}")
        assert module.__all__ == ["run"], name
        assert list(__import__("inspect").signature(module.run).parameters) == ["snakemake", "log"]
        assert missing_annotations(module.run) == [], name


@pytest.mark.parametrize("name", FIGURES)
def test_the_script_is_a_call_and_the_rule_carries_its_drawings_digest(name):
    block = rule_blocks()[name]
    assert problems_of_a_call(script_of(block).read_text(), name) == [], script_of(block)
    params = re.search(r"(?ms)^    params:\n(.*?)^    \w", block).group(1)
    assert f'code=draw_digest("{name}"),' in params, name
    expected = hashlib.sha256((DRAW / f"{name}.py").read_bytes()).hexdigest()
    assert draw_digest(name) == expected


def test_the_checks_see_a_script_that_is_no_call(tmp_path):
    """A body left in the script, a drawing of another figure, a missing docstring; and a
    digest of another file."""
    call = ('"""Doc."""\n\nfrom reflectance.papers.draw.ct82_fig8 import run\n'
            "from reflectance.scripting import run_job\n\nrun_job(snakemake, run)\n")
    assert problems_of_a_call(call, "ct82_fig8") == []
    assert problems_of_a_call(call.replace("\nrun_job", "\nx = 1\nrun_job"), "ct82_fig8") == [
        "statements other than imports before the call"]
    assert problems_of_a_call(call, "ct82_fig7") == ["run is not reflectance.papers.draw."
                                                     "ct82_fig7's"]
    assert problems_of_a_call(call.replace('"""Doc."""', ""), "ct82_fig8") == [
        "no module docstring first"]
    assert problems_of_a_call(call + "print(1)\n", "ct82_fig8") == [
        "statements other than imports before the call",
        "the last statement is not run_job(snakemake, run)"]
    folder = tmp_path / "workflow" / "reflectance" / "papers" / "draw"
    folder.mkdir(parents=True)
    (folder / "ct82_fig8.py").write_text("# another file\n")
    assert draw_digest("ct82_fig8", tmp_path) != draw_digest("ct82_fig8")


def test_the_parse_and_the_config_check_import_no_drawing():
    """What the Snakefile and its rules import, every figure's definition and the whole config
    check (scenes included), in a fresh interpreter: matplotlib and reflectance.papers.draw
    stay unloaded (the drawing is the jobs' alone)."""
    imports = "\n".join(_python_of_rules(path) for path in
                        [ROOT / "Snakefile", *sorted(RULES.glob("*.smk"))])
    program = f"""{imports}
import sys
import yaml
from reflectance.config import check_config
from reflectance.papers.figures import ANALYTIC, FIGURES, figure, params_of

config = yaml.safe_load(open("config.yaml"))
for name in FIGURES + ANALYTIC:
    figure(name).outputs(params_of(figure(name), config))
check_config(config)
print(sorted(m for m in sys.modules
             if m.split(".")[0] == "matplotlib" or m.startswith("reflectance.papers.draw")))
"""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(ROOT / "workflow"), *filter(None, [os.environ.get("PYTHONPATH")])])}
    proc = subprocess.run([sys.executable, "-c", program], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


# --- an edit of one drawing reruns its figure ---------------------------------------------------

#: the drawings edited, one after another in one copy of the session's build: a figure no other
#: rule reads, and one that the gamut-mapping audit reads
EDITED = ("blinn77_fig7_sweep", "ct82_fig8")


def after_build(runs, built, tmp_path_factory, items):
    """tests/conftest.py's ``early`` calls this when the session's build is done: a dry run in
    a copy of the build after appending a comment to each drawing of EDITED (each undone before
    the next)."""
    if not any(item.originalname == "test_an_edit_of_a_drawing_reruns_its_figure"
               for item in items):
        return []
    cwd = _copy(built, tmp_path_factory)
    return [(5 * len(EDITED), "drawing edits", _edited_dry_runs, (runs, cwd))]


def _edited_dry_runs(runs, cwd):
    procs = []
    for name in EDITED:
        path = cwd / "workflow" / "reflectance" / "papers" / "draw" / f"{name}.py"
        original = path.read_text()
        path.write_text(original + "# an edit that changes nothing the figure does\n")
        procs.append(_dry_run(runs, cwd))
        path.write_text(original)
    return procs


@pytest.mark.parametrize("edit", range(len(EDITED)), ids=EDITED)
def test_an_edit_of_a_drawing_reruns_its_figure(after_build, edit):
    """After a comment is appended to one drawing module, `snakemake -n` plans exactly its
    figure, the rules that read the figure's files and the aggregating rules."""
    proc = after_build("drawing edits")[edit]
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    name = EDITED[edit]
    assert set(_planned_jobs(text)) == {name} | READ_BY[name] | AGGREGATING | {"all"}, text
