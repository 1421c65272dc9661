"""The library's architecture, read from its import statements (every one, at any depth).

The folders are the design: data flows one way, from ``io`` up to ``papers`` and the command
line. A module may import its own subpackage and the ones listed below it here; nothing imports
upward or sideways, and no module reaches for another module's underscore names.
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
    # the analytic spheres it exports and its worker processes; the CLI hands it the papers'
    # scene, so that it knows nothing of papers, and nothing but the CLI uses it
    "bench": {"render", "colour", "geometry", "io"},
    "papers": {"render", "audit", "optics", "colour", "geometry", "io"},
}
TOP_LEVEL = {"cli", "config", "scripting", "resume", "lazy", "__init__", "__main__"}


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


def where(path):
    rel = path.relative_to(PACKAGE)
    return rel.parts[0] if len(rel.parts) > 1 else rel.stem


def test_every_module_lives_in_a_known_place():
    for path in modules():
        assert where(path) in ALLOWED or where(path) in TOP_LEVEL, path


@pytest.mark.parametrize("path", modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_follow_the_one_way_flow(path):
    home = where(path)
    if home in TOP_LEVEL:
        return
    for module, _ in imports(path):
        if module == "reflectance.lazy":  # the public faces' loader imports nothing of ours
            continue
        parts = module.split(".")
        assert len(parts) >= 2 and parts[1] in ALLOWED, f"{path}: imports {module}"
        target = parts[1]
        assert target == home or target in ALLOWED[home], (
            f"{path.relative_to(PACKAGE)} ({home}) imports {module}: {home} may import only "
            f"{sorted(ALLOWED[home] | {home})}")


@pytest.mark.parametrize("path", modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_imports_another_modules_private_names(path):
    for module, names in imports(path):
        private = [n for n in names if n.startswith("_") and not n.endswith("__")]
        assert not private, f"{path.relative_to(PACKAGE)} imports {private} from {module}"


def test_the_checks_see_a_violation(tmp_path):
    """The walker finds imports inside functions, and the rules reject an upward import."""
    bad = tmp_path / "m.py"
    bad.write_text("def f():\n    from reflectance.papers.scenes import _x\n")
    (module, names), = imports(bad)
    assert module == "reflectance.papers.scenes" and names == ["_x"]
    assert "papers" not in ALLOWED["render"] and "render" not in ALLOWED["optics"]


def test_each_subpackage_has_a_public_face():
    import importlib

    for name in ALLOWED:
        package = importlib.import_module(f"reflectance.{name}")
        assert package.__all__, name
        for public in package.__all__:
            assert getattr(package, public) is not None, f"reflectance.{name}.{public}"
