"""The library's architecture, read from its import statements (every one, at any depth).

The folders are the design: data flows one way, from ``io`` up to ``papers``, ``bench`` and the
command line. A module may import its own subpackage and the ones listed below it here; nothing
imports upward or sideways, no module reaches for another module's underscore names, and the
modules of a subpackage import one another without a cycle. The top-level modules each have
their own list. The rendered figures' drawing, ``papers.draw``, is a place of its own above
``papers``: the workflow's scripts import it, nothing in the library does.
"""

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "workflow" / "reflectance"

#: subpackage -> the subpackages it may import besides itself
ALLOWED = {
    "io": set(),
    "colour": {"io"},
    "optics": {"io"},
    "geometry": {"io"},
    "render": {"optics", "colour", "geometry", "io"},
    "audit": {"optics", "colour", "io"},
    # the bench measures the renderer (and exports its scenes to a path tracer): what it needs of
    # the layers below comes through render's scenes, but for the colour differences it reports,
    # the analytic spheres it exports, its worker processes and the material folders it hands
    # them (optics.spectra's one lookup); the CLI hands it the papers' scene, so that it knows
    # nothing of papers, and nothing but the CLI uses it
    "bench": {"render", "optics", "colour", "geometry", "io"},
    "papers": {"render", "audit", "optics", "colour", "geometry", "io"},
    # the rendered figures' drawing (one module per figure, its script's body): the figure's
    # definition (papers), the renderer, the tables and plots, and the scripts' params_dict;
    # no place lists it, so nothing in the library imports it (the config check and the
    # Snakefile's parse then load no matplotlib for it)
    "papers.draw": {"papers", "render", "optics", "colour", "geometry", "io", "scripting"},
}

#: the place of reflectance.papers.draw, inside papers' folder
DRAW = "papers.draw"

#: top-level module -> the subpackages and top-level modules it may import ("__init__": the
#: package itself, ``from reflectance import __version__``); reflectance.lazy, which imports
#: nothing of ours, every module may import
TOP_LEVEL = {
    "__init__": set(),  # loads the subpackages by name on first use (import_module)
    "__main__": {"cli"},
    "lazy": set(),  # the public faces' loader
    # the workflow scripts' logging and parameters, and their audits' metadata files (the version)
    "scripting": {"__init__", "io"},
    "resume": {"io"},  # what a killed run left (the Snakefile clears it)
    # config.yaml's checks build every figure's scene, without rendering
    "config": {"papers", "render", "audit", "geometry", "optics", "colour", "io"},  # audit: audit 8's keys
    # the command: every layer, and the version; not the workflow's support modules
    "cli": {"__init__", "bench", "papers", "audit", "render", "geometry", "optics", "colour",
            "io"},
}


def modules():
    return sorted(p for p in PACKAGE.rglob("*.py"))


def imports(path):
    """(imported module, imported names) for every import of reflectance in ``path``."""
    tree = ast.parse(path.read_text(), str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                raise AssertionError(f"{path}: relative import; write reflectance.<package>...")
            if node.module and node.module.split(".")[0] == "reflectance":
                found.append((node.module, [a.name for a in node.names]))
        elif isinstance(node, ast.Import):
            found += [(a.name, []) for a in node.names if a.name.split(".")[0] == "reflectance"]
    return found


def where(path, package=PACKAGE):
    rel = path.relative_to(package)
    if rel.parts[:2] == ("papers", "draw") and len(rel.parts) > 2:
        return DRAW
    return rel.parts[0] if len(rel.parts) > 1 else rel.stem


def place(module, names=()):
    """The subpackage or top-level module an imported module (``reflectance...``) lives in;
    ``names``, those imported from it (``from reflectance.papers import draw``: papers.draw)."""
    parts = module.split(".")
    if parts[1:3] == ["papers", "draw"] or (parts[1:] == ["papers"] and "draw" in names):
        return DRAW
    return parts[1] if len(parts) > 1 else "__init__"


def module_name(path, package=PACKAGE):
    """``reflectance.<...>`` of a file of the package (a package's ``__init__.py``: the package)."""
    rel = path.relative_to(package).with_suffix("")
    parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
    return ".".join(("reflectance", *parts))


def import_graph(package=PACKAGE):
    """{module: the modules of the package it imports}: ``from a.b import c`` imports the module
    ``a.b.c`` where there is one, else ``a.b`` (a name it defines or its face loads)."""
    paths = {module_name(p, package): p for p in sorted(package.rglob("*.py"))}
    graph = {}
    for name, path in paths.items():
        edges = set()
        for module, names in imports(path):
            inner = {f"{module}.{n}" for n in names if f"{module}.{n}" in paths}
            edges |= inner | ({module} if len(inner) < len(names) or not names else set())
        graph[name] = {m for m in edges if m in paths and m != name}
    return graph


def cycles(graph):
    """The import cycles of ``graph`` ({node: nodes it imports}): each a sorted list of the
    nodes that reach one another (the strongly connected components of more than one node)."""
    index, low, stack, found = {}, {}, [], []

    def visit(node):  # Tarjan 1972
        index[node] = low[node] = len(index)
        stack.append(node)
        for other in sorted(graph.get(node, ())):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while not component or component[-1] != node:
                component.append(stack.pop())
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def cycles_inside_subpackages(package=PACKAGE):
    """{subpackage: its import cycles}, of its modules' imports of one another."""
    graph = import_graph(package)
    home = {name: place(name) for name in graph}
    out = {}
    for subpackage in sorted({home[n] for n in graph if n.count(".") > 1}):
        inside = {n: {m for m in edges if home[m] == subpackage}
                  for n, edges in graph.items() if home[n] == subpackage}
        out[subpackage] = cycles(inside)
    return out


def test_every_module_lives_in_a_known_place():
    for path in modules():
        assert where(path) in ALLOWED or where(path) in TOP_LEVEL, path
    # and every top-level module has its list (none left over for a module that is gone)
    assert {where(p) for p in modules() if p.parent == PACKAGE} == set(TOP_LEVEL)


def allowed(home):
    """What a module of ``home`` (a subpackage or a top-level module) may import."""
    return ALLOWED[home] | {home} if home in ALLOWED else TOP_LEVEL[home]


@pytest.mark.parametrize("path", modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_follow_the_one_way_flow(path):
    home = where(path)
    for module, names in imports(path):
        if module == "reflectance.lazy":  # the public faces' loader imports nothing of ours
            continue
        target = place(module, names)
        assert target in ALLOWED or target in TOP_LEVEL, f"{path}: imports {module}"
        assert target in allowed(home), (
            f"{path.relative_to(PACKAGE)} ({home}) imports {module}: {home} may import only "
            f"{sorted(allowed(home))}")


@pytest.mark.parametrize("subpackage", sorted(ALLOWED))
def test_no_import_cycle_inside_a_subpackage(subpackage):
    assert cycles_inside_subpackages().get(subpackage, []) == [], (
        f"{subpackage}: modules that import one another (at any depth)")


def test_the_rules_allow_no_cycle():
    """Between places the rules alone keep the flow one way: no two places may import each
    other, directly or through others."""
    rules = {home: allowed(home) - {home} for home in [*ALLOWED, *TOP_LEVEL]}
    assert cycles(rules) == []


@pytest.mark.parametrize("path", modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_imports_another_modules_private_names(path):
    for module, names in imports(path):
        private = [n for n in names if n.startswith("_") and not n.endswith("__")]
        assert not private, f"{path.relative_to(PACKAGE)} imports {private} from {module}"


def test_the_checks_see_a_violation(tmp_path):
    """The walker finds imports inside functions, and the rules reject an upward import, a
    subpackage's import of the command line and the command line's of the config checks."""
    bad = tmp_path / "m.py"
    bad.write_text("def f():\n    from reflectance.papers.scenes import _x\n")
    (module, names), = imports(bad)
    assert module == "reflectance.papers.scenes" and names == ["_x"]
    assert "papers" not in ALLOWED["render"] and "render" not in ALLOWED["optics"]
    assert place("reflectance.cli") not in allowed("bench") and "config" not in allowed("cli")
    assert place("reflectance") == "__init__" and "__init__" in allowed("cli")
    # the drawing: its own place, inside papers' folder, which papers may not import
    assert where(PACKAGE / "papers" / "draw" / "ct82_fig8.py") == DRAW
    assert where(PACKAGE / "papers" / "figures" / "ct82_fig8.py") == "papers"
    for module, names in (("reflectance.papers.draw.ct82_fig8", ["run"]),
                          ("reflectance.papers.draw", ["ct82_fig8"]),
                          ("reflectance.papers", ["scenes", "draw"])):
        assert place(module, names) == DRAW and DRAW not in allowed("papers"), module
    assert place("reflectance.papers", ["scenes"]) == "papers"


def test_nothing_in_the_library_imports_the_drawing():
    """Only the workflow's scripts import reflectance.papers.draw: no place of the library
    lists it (so test_imports_follow_the_one_way_flow refuses any import of it), and no module
    outside it names it."""
    assert [home for home in [*ALLOWED, *TOP_LEVEL] if home != DRAW and DRAW in allowed(home)] == []
    outside = [path for path in modules() if where(path) != DRAW]
    assert outside and not [path for path in outside
                            if any(place(m, n) == DRAW for m, n in imports(path))]


def test_the_checks_see_a_planted_cycle(tmp_path):
    """A cycle inside a subpackage, closed by an import inside a function (and through a name
    of a module's package), is found; the same modules without it are not reported; and a cycle
    in the rules is found too."""
    package = tmp_path / "reflectance"
    (package / "render").mkdir(parents=True)
    (package / "render" / "__init__.py").write_text("")
    (package / "render" / "a.py").write_text("from reflectance.render.b import g\n")
    (package / "render" / "b.py").write_text("import numpy\n\n\ndef g():\n"
                                             "    from reflectance.render import c\n")
    (package / "render" / "c.py").write_text("def h():\n    from reflectance.render.a import x\n")
    (package / "io.py").write_text("from reflectance.render import a\n")  # not inside one
    assert import_graph(package)["reflectance.render.b"] == {"reflectance.render.c"}
    assert cycles_inside_subpackages(package) == {
        "render": [["reflectance.render.a", "reflectance.render.b", "reflectance.render.c"]]}
    (package / "render" / "c.py").write_text("def h():\n    pass\n")
    assert cycles_inside_subpackages(package) == {"render": []}
    assert cycles({"render": {"io"}, "io": {"colour"}, "colour": {"render"}, "x": {"io"}}) == [
        ["colour", "io", "render"]]


def test_each_subpackage_has_a_public_face():
    import importlib

    for name in ALLOWED:
        package = importlib.import_module(f"reflectance.{name}")
        assert package.__all__, name
        for public in package.__all__:
            assert getattr(package, public) is not None, f"reflectance.{name}.{public}"


def _imported_top_names(text, filename):
    """The top-level names of every module ``text`` imports (absolute imports only)."""
    names = set()
    for node in ast.walk(ast.parse(text, filename)):
        if isinstance(node, ast.Import):
            names |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    return names


def _python_of_rules(path):
    """The Python lines of a Snakefile or .smk file (its import statements) as a module."""
    return "\n".join(line for line in path.read_text().splitlines()
                     if line.startswith(("import ", "from ")))


def test_the_build_needs_no_extra():
    """`pip install -e .` builds every figure (issue 27, part 3): everything the workflow's
    Snakefile, rules, scripts and the library they use import is the standard library, the
    package itself or a core dependency of pyproject.toml (or one of theirs), never a package
    only an extra brings (the test stack, Sphinx, Mitsuba, the SLURM plugin). reflectance.bench,
    which imports Mitsuba for its cross-check, is the `reflectance bench` command's alone: no
    rule or script imports it."""
    import re
    import sys
    from importlib.metadata import (PackageNotFoundError, distribution, packages_distributions,
                                    requires)

    tomllib = pytest.importorskip("tomllib")  # Python 3.11

    root = PACKAGE.parents[1]
    project = tomllib.loads((root / "pyproject.toml").read_text())["project"]
    name_of = lambda requirement: re.split(r"[\s<>=!~;\[(]", requirement, 1)[0].lower()  # noqa: E731
    core = {name_of(r) for r in project["dependencies"]}
    extra_only = {name_of(r) for rs in project["optional-dependencies"].values() for r in rs
                  if not r.startswith("reflectance")} - core
    # what the core dependencies bring with them (their own requirements, transitively)
    allowed, todo = set(core), list(core)
    while todo:
        try:
            needs = requires(todo.pop()) or []
        except PackageNotFoundError:
            continue
        for requirement in needs:
            if "extra ==" in requirement:
                continue
            name = name_of(requirement).replace("_", "-")
            if name not in allowed:
                allowed.add(name)
                todo.append(name)
    sources = [(p, p.read_text()) for p in sorted((root / "workflow" / "scripts").glob("*.py"))]
    sources += [(p, _python_of_rules(p)) for p in [root / "Snakefile",
                                                    *sorted((root / "workflow" / "rules").glob("*.smk"))]]
    sources += [(p, p.read_text()) for p in modules() if "bench" not in p.relative_to(PACKAGE).parts
                and p.name != "cli.py"]  # (the command line, not the build)
    names = set()
    for path, text in sources:
        found = _imported_top_names(text, str(path))
        if path.suffix in (".smk", "") or path.parent.name == "scripts":
            assert not re.search(r"reflectance\.bench|from reflectance import bench", text), path
        names |= found
    distributions = packages_distributions()
    problems = []
    for name in sorted(names - set(sys.stdlib_module_names) - {"reflectance", "__future__"}):
        dists = {d.lower().replace("_", "-") for d in distributions.get(name, [])}
        if not dists:  # a bare extension module (OpenEXR.so): its distribution has its name
            try:
                dists = {distribution(name).metadata["Name"].lower()}
            except PackageNotFoundError:
                pass
        if not dists:
            problems.append(f"{name}: no installed distribution provides it")
        elif not dists & allowed or dists & extra_only:
            problems.append(f"{name}: from {sorted(dists)}, not a core dependency")
    assert problems == []
