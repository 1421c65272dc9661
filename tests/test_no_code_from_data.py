"""No data file can make the workflow run code (issue 12, "Security"): the errata rows are text
checked against a registry of Python functions; config paths stay in the project; a material is
a name; and neither the library, the scripts nor the rules evaluate, execute or import anything
named by data."""

import ast
import re
import subprocess
import sys

import pytest
import yaml

from reflectance.io.paths import check_name, project_file
from reflectance.optics.spectra import SpectraError, load_material, read_spectrum_csv
from reflectance.papers.errata import ERRATA, ErrataError, errata_rows, errata_table

SETTINGS = {"n": 1.5, "theta_deg": 60, "m": 0.3, "s": 5}
MARKER = "pwned_marker"
SHELL = f"__import__('os').system('touch {MARKER}')"


def good_row(**changes):
    row = {"id": "article-phong-h-norm", "text": "article", "kind": "erratum", "location": "here",
           "printed": "p", "correct": "c", "test": "tests/test_errata.py::x"}
    row.update(changes)
    return row


def document(rows, **top):
    return {"texts": {"article": "Article"}, "rows": rows, **top}


# (document, what the one-line message must say besides the file)
BAD_ROWS = [
    (document([good_row(id="os.system")]), "row 1 ('os.system'): unknown erratum id"),
    (document([good_row(id=SHELL)]), "unknown erratum id"),
    (document([good_row(), good_row(id="nope")]), "row 2 ('nope'): unknown erratum id"),
    (document([good_row(let={"x": SHELL})]), "row 1 ('article-phong-h-norm'): unknown key(s) ['let']"),
    (document([good_row(consequence="{x}", value="x")]), "unknown key(s) ['consequence', 'value']"),
    (document([good_row()], imports=["os.system"]), "top level: must be a mapping with exactly"),
    (document([good_row(id=["os", "system"])]), "id must be text"),
    (document([good_row(printed={"eval": SHELL})]), "printed must be text"),
    (document([{k: v for k, v in good_row().items() if k != "test"}]), "missing test"),
    (document([good_row(), good_row()]), "row 2 ('article-phong-h-norm'): erratum id 'article-phong-h-norm' appears twice"),
    (document([good_row(text="blog")]), "unknown text 'blog'"),
    (document([good_row(kind="typo")]), "row 1 ('article-phong-h-norm'): unknown kind 'typo'; known: erratum, "),
    (document(["just a string"]), "row 1: must be a mapping"),
    (document([]), "rows: must be a non-empty list"),
    ([good_row()], "top level"),
]


@pytest.mark.parametrize("doc, message", BAD_ROWS, ids=[m for _, m in BAD_ROWS])
def test_bad_errata_rows_are_refused_naming_file_and_row(doc, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "rows.yaml"
    path.write_text(yaml.safe_dump(doc))
    with pytest.raises(ErrataError) as info:
        errata_table(path, SETTINGS)
    text = str(info.value)
    assert text.startswith(f"{path}: ") and message in text and "\n" not in text
    assert not (tmp_path / MARKER).exists()


def test_unreadable_errata_files_are_named(tmp_path):
    binary = tmp_path / "bin.yaml"
    binary.write_bytes(b"\x81\xff\x00rows")
    broken = tmp_path / "broken.yaml"
    broken.write_text("rows: [\n")
    for path in (binary, broken, tmp_path / "missing.yaml"):
        with pytest.raises(ErrataError, match=re.escape(str(path))) as info:
            errata_rows(path)
        assert "\n" not in str(info.value)


def test_code_like_text_is_shown_verbatim_never_run(tmp_path, monkeypatch):
    """Text fields are only text: a Python expression, a format field reaching for attributes
    and a YAML tag that would construct a Python object all come out as written (or are refused
    by the safe loader), and nothing runs."""
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "rows.yaml"
    row = good_row(location=SHELL, printed="{0.__class__.__mro__}", correct="{value!r}",
                   test="$(touch pwned_marker)")
    path.write_text(yaml.safe_dump(document([row])))
    table = errata_table(path, SETTINGS)
    assert list(table.location) == [SHELL]
    assert list(table.printed) == ["{0.__class__.__mro__}"]
    assert list(table.correct) == ["{value!r}"]
    assert list(table.test) == ["$(touch pwned_marker)"]
    tagged = tmp_path / "tagged.yaml"
    tagged.write_text(f"texts: {{article: Article}}\nrows:\n  - !!python/object/apply:os.system "
                      f"['touch {MARKER}']\n")
    with pytest.raises(ErrataError, match="tagged.yaml"):
        errata_rows(tagged)
    assert not (tmp_path / MARKER).exists()


def test_the_project_rows_are_all_registered(root):
    _, rows = errata_rows(root / "workflow" / "report" / "errata.yaml")
    assert [r["id"] for r in rows] and {r["id"] for r in rows} == set(ERRATA)


# --- paths from data ------------------------------------------------------------------------------

@pytest.mark.parametrize("value, message", [
    ("../x.yaml", "leaves the project folder"),
    ("workflow/../../x.yaml", "leaves the project folder"),
    ("/etc/passwd.yaml", "is absolute"),
    ("", "is not a file path"),
])
def test_config_paths_stay_in_the_project(value, message, root):
    with pytest.raises(ValueError, match=rf"^figures\.errata\.rows: .*{message}"):
        project_file(value, "figures.errata.rows", root)


def test_a_symbolic_link_out_of_the_project_is_refused(tmp_path):
    project = tmp_path / "project"
    project.mkdir()
    (tmp_path / "outside.yaml").write_text("x")
    (project / "link.yaml").symlink_to(tmp_path / "outside.yaml")
    assert project_file("inside.yaml", "k", project) == "inside.yaml"
    with pytest.raises(ValueError, match="^k: 'link.yaml' leaves the project folder"):
        project_file("link.yaml", "k", project)


@pytest.mark.parametrize("name", ["../x/Cu", "/etc/passwd", "..", ".", "a/b", "a\\b", ".hidden", ""])
def test_a_material_is_a_name(name, root, grid):
    with pytest.raises(ValueError, match="is not a name"):
        check_name(name)
    with pytest.raises(SpectraError, match="material .* is not a name.*known: .*Cu"):
        load_material(name, grid, spectra_dir=root / "spectra")


# Through the workflow: each config key that names a file, refused at parse time. The kinds of
# path refused (leaving the folder, absolute, empty, a link out) are checked on project_file
# itself above; one run per key shows the workflow applies it to that key.
PATH_CASES = [
    ("rows", "../errata.yaml", "figures.errata.rows: '../errata.yaml' leaves the project folder"),
    ("symbols", "../symbols.csv", "figures.cook_torrance_1982.fig1.symbols: '../symbols.csv' leaves"),
]


def _dry_run(root, configfile):
    return subprocess.run([sys.executable, "-m", "snakemake", "-n", "--configfile",
                           str(configfile)], cwd=root, capture_output=True, text=True)


@pytest.fixture(scope="module")
def dry_runs(root, tmp_path_factory):
    """The three `snakemake -n` runs below (a few seconds each, most of it the configuration's
    checks), side by side (tests/side_by_side.py); each test makes its own assertions on its
    run. {case: the finished process}, and "erratum" -> (process, the rows file's path)."""
    from side_by_side import SideBySide

    base = yaml.safe_load((root / "config.yaml").read_text())
    with SideBySide() as runs:
        for key, value, _ in PATH_CASES:
            config = yaml.safe_load(yaml.safe_dump(base))
            if key == "rows":
                config["figures"]["errata"]["rows"] = value
            else:
                config["figures"]["cook_torrance_1982"]["fig1"]["symbols"] = value
            override = tmp_path_factory.mktemp("path") / "config.yaml"
            override.write_text(yaml.safe_dump(config))
            runs.start((key, value), _dry_run, root, override)

        # an unknown erratum id in a rows file inside the project (removed when its run ends)
        tmp = tmp_path_factory.mktemp("erratum")
        doc = yaml.safe_load((root / "workflow" / "report" / "errata.yaml").read_text())
        doc["rows"][0]["id"] = SHELL
        inside = root / "workflow" / "report" / f"test_rows_{tmp.name}.yaml"
        config = yaml.safe_load(yaml.safe_dump(base))
        config["figures"]["errata"]["rows"] = str(inside.relative_to(root))
        (tmp / "config.yaml").write_text(yaml.safe_dump(config))

        def erratum():
            inside.write_text(yaml.safe_dump(doc))
            try:
                return _dry_run(root, tmp / "config.yaml"), inside
            finally:
                inside.unlink()

        runs.start("erratum", erratum)
        yield runs


@pytest.mark.workflow  # a Snakemake dry run each (several seconds; side by side)
@pytest.mark.parametrize("key, value, message", PATH_CASES)
def test_dry_run_refuses_paths_leaving_the_project(key, value, message, dry_runs):
    """At parse time, before any job: one message naming the key; exit status 1."""
    proc = dry_runs.result((key, value))
    assert proc.returncode == 1
    assert message in proc.stdout + proc.stderr


@pytest.mark.workflow
def test_dry_run_refuses_an_unknown_erratum_id(root, dry_runs):
    proc, inside = dry_runs.result("erratum")
    assert not inside.exists()
    assert proc.returncode == 1
    assert f"{inside.relative_to(root)}: row 1" in proc.stdout + proc.stderr
    assert "unknown erratum id" in proc.stdout + proc.stderr
    assert not (root / MARKER).exists()


# --- spectra files: text, with or without a byte-order mark ---------------------------------------

def test_spectrum_with_a_byte_order_mark_reads_as_without(root, tmp_path):
    text = (root / "spectra" / "Cu.csv").read_text()
    plain, bom = tmp_path / "plain.csv", tmp_path / "bom.csv"
    plain.write_text(text)
    bom.write_bytes(b"\xef\xbb\xbf" + text.encode())
    assert read_spectrum_csv(bom).equals(read_spectrum_csv(plain))


def test_binary_spectrum_is_named(tmp_path):
    path = tmp_path / "Cu.csv"
    path.write_bytes(b"wavelength_nm,n,k\n\x89PNG\r\n\x1a\n\xff")
    with pytest.raises(SpectraError, match=re.escape(f"{path}: not a UTF-8 text file")):
        read_spectrum_csv(path)


# --- no eval, exec or import of names from data anywhere in the project ---------------------------

SAFE_YAML_LOADERS = {"SafeLoader", "CSafeLoader"}


def _safe_yaml_load(f, node):
    """``yaml.load(..., Loader=...)`` whose Loader names only PyYAML's safe loaders (e.g.
    ``getattr(yaml, "CSafeLoader", yaml.SafeLoader)``): it builds no Python object from tags."""
    if (f.value.id, f.attr) != ("yaml", "load"):
        return False
    loader = [k.value for k in node.keywords if k.arg == "Loader"]
    if not loader:
        return False
    names = {n.attr for n in ast.walk(loader[0]) if isinstance(n, ast.Attribute)}
    names |= {n.value for n in ast.walk(loader[0]) if isinstance(n, ast.Constant)}
    calls = [n for n in ast.walk(loader[0]) if isinstance(n, ast.Call)]
    variables = {n.id for n in ast.walk(loader[0]) if isinstance(n, ast.Name)}
    return bool(names) and names <= SAFE_YAML_LOADERS and variables <= {"yaml", "getattr"} and all(
        getattr(c.func, "id", None) == "getattr" for c in calls)


FORBIDDEN_CALLS = {"eval", "exec", "compile", "__import__", "execfile", "breakpoint"}
FORBIDDEN_ATTRIBUTES = {("yaml", "load"), ("yaml", "unsafe_load"), ("yaml", "full_load"),
                        ("pickle", "load"), ("pickle", "loads"), ("pd", "read_pickle"),
                        ("importlib", "import_module"), ("importlib", "__import__"),
                        ("os", "system"), ("os", "popen")}


#: Where import_module may load a package's own modules by the names its __init__ lists in code.
LAZY_LOADERS = ("__init__.py", "reflectance/lazy.py")


def code_from_data(source, path):
    """Places in Python ``source`` that could run code named by data: calls of eval, exec,
    compile, __import__; unsafe YAML or pickle loading; import_module anywhere but a package's
    lazy loader (``import_module(f"{__name__}...")`` in an ``__init__.py``, or of the package's own
    module names in ``reflectance/lazy.py``, which its ``__init__`` lists in code); getattr with a
    computed name on a module or on what import_module returned; shell calls."""
    tree = ast.parse(source)
    modules = {alias.asname or alias.name.split(".")[0]
               for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        f = node.func
        where = f"{path}:{node.lineno}"
        if isinstance(f, ast.Name) and f.id in FORBIDDEN_CALLS:
            found.append(f"{where}: {f.id}()")
        if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name) and (
                (f.value.id, f.attr) in FORBIDDEN_ATTRIBUTES) and not _safe_yaml_load(f, node):
            found.append(f"{where}: {f.value.id}.{f.attr}()")
        if isinstance(f, ast.Name) and f.id == "import_module":
            argument = node.args[0] if node.args else None
            lazy = (path.endswith(LAZY_LOADERS) and isinstance(argument, ast.JoinedStr)
                    and isinstance(argument.values[0], ast.FormattedValue)
                    and isinstance(argument.values[0].value, ast.Name)
                    and argument.values[0].value.id in ("__name__", "package"))
            if not lazy:
                found.append(f"{where}: import_module of a computed name")
        if isinstance(f, ast.Name) and f.id in ("getattr", "setattr") and len(node.args) >= 2 \
                and not isinstance(node.args[1], ast.Constant):
            target = node.args[0]
            on_module = isinstance(target, ast.Name) and target.id in modules
            on_import = isinstance(target, ast.Call) and getattr(target.func, "id", "") == "import_module"
            if on_module or (on_import and not path.endswith(LAZY_LOADERS)):
                found.append(f"{where}: {f.id} with a computed name on a module")
        if isinstance(f, ast.Attribute) and f.attr in ("run", "Popen", "call", "check_output") \
                and isinstance(f.value, ast.Name) and f.value.id == "subprocess":
            if any(k.arg == "shell" for k in node.keywords):
                found.append(f"{where}: subprocess with shell=")
    return found


def project_sources(root):
    return sorted((root / "workflow").rglob("*.py")) + [root / "Snakefile"] + sorted(
        (root / "workflow" / "rules").glob("*.smk"))


def test_the_scanner_finds_what_it_looks_for():
    planted = [
        "eval(row['let'])",
        "exec(text)",
        "import importlib\nimportlib.import_module(name)",
        "from importlib import import_module\nimport_module(dotted)",
        "import numpy as np\ngetattr(np, name)",
        "import yaml\nyaml.load(stream)",
        "import yaml\nyaml.load(stream, Loader=yaml.Loader)",
        "import yaml\nyaml.load(stream, Loader=getattr(yaml, 'CSafeLoader', chosen))",
        "__import__(module)",
        "import subprocess\nsubprocess.run(cmd, shell=True)",
    ]
    for source in planted:
        assert code_from_data(source, "x.py"), source
    safe = 'import yaml\nyaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))'
    assert code_from_data(safe, "x.py") == []  # PyYAML's safe loaders only
    lazy = 'from importlib import import_module\nimport_module(f"{__name__}.{name}")'
    assert code_from_data(lazy, "pkg/__init__.py") == []
    assert code_from_data(lazy, "pkg/module.py")  # only a package's lazy loader may


def test_no_eval_exec_or_import_of_data_names_in_library_scripts_and_rules(root):
    found = []
    for path in project_sources(root):
        text = path.read_text()
        relative = str(path.relative_to(root))
        if path.suffix == ".py":
            found += code_from_data(text, relative)
        else:  # Snakefile and rules: Python with Snakemake's keywords; scan the words
            for number, line in enumerate(text.splitlines(), start=1):
                code = line.split("#")[0]
                if re.search(r"\b(eval|exec|compile|__import__|import_module)\s*\(", code):
                    found.append(f"{relative}:{number}: {line.strip()}")
    assert found == []


def test_a_scene_material_is_a_name_too(root):
    from reflectance.render.scene import SceneError, scene_from_dict

    doc = {"camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "fov_deg": 30, "width": 8,
                      "height": 6},
           "objects": [{"geometry": {"type": "sphere", "radius": 1.0},
                        "material": {"name": "../spectra/Cu", "m": 0.3}}],
           "lights": [{"type": "directional", "direction": [0, -1, 1]}]}
    with pytest.raises(SceneError, match=re.escape(
            "s.yaml: objects[0].material.name: material '../spectra/Cu' is not a name")):
        scene_from_dict(doc, source="s.yaml", spectra_dir=root / "spectra")
