"""The public API is typed (PEP 561: the package ships ``py.typed``).

Two checks: every function and method the subpackages (and the top-level modules with an
``__all__``) name in ``__all__`` has an annotation on each parameter and its return, read with
``inspect.signature``; and mypy, with pyproject.toml's ``[tool.mypy]``, finds no error in the
package, so the annotations agree with the bodies that use them.
"""

import importlib
import inspect
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: the public faces whose ``__all__`` is checked: the subpackages and the top-level modules
#: that have an ``__all__``
MODULES = ("optics", "colour", "geometry", "render", "audit", "io", "papers", "bench",
           "cli", "config", "lazy", "resume", "scripting")


def _own_functions(cls):
    """The functions defined in ``cls``'s body (not generated, e.g. by ``dataclass``) that a
    user calls: the public methods, ``__init__`` and ``__call__``; property getters too."""
    module_file = inspect.getsourcefile(sys.modules[cls.__module__])
    for name, value in vars(cls).items():
        if name.startswith("_") and name not in ("__init__", "__call__"):
            continue
        if isinstance(value, (staticmethod, classmethod)):
            value = value.__func__
        elif isinstance(value, property):
            value = value.fget
        if inspect.isfunction(value) and value.__code__.co_filename == module_file:
            yield f"{cls.__qualname__}.{name}", value


def public_functions(module_name):
    """(qualified name, function) of every function and class method named in the
    ``__all__`` of ``reflectance.<module_name>``."""
    module = importlib.import_module(f"reflectance.{module_name}")
    for name in module.__all__:
        value = getattr(module, name)
        if inspect.isfunction(value):
            yield f"{module_name}.{name}", value
        elif inspect.isclass(value) and value.__module__.startswith("reflectance."):
            for qualified, function in _own_functions(value):
                yield f"{module_name}.{qualified}", function


def missing_annotations(function):
    """The parameters of ``function`` (not ``self``/``cls``) without an annotation, and
    ``"return"`` if its return has none."""
    signature = inspect.signature(function)
    missing = [p.name for i, p in enumerate(signature.parameters.values())
               if p.annotation is inspect.Parameter.empty
               and not (i == 0 and p.name in ("self", "cls"))]
    if signature.return_annotation is inspect.Signature.empty:
        missing.append("return")
    return missing


@pytest.mark.parametrize("module_name", MODULES)
def test_public_api_is_annotated(module_name):
    functions = list(public_functions(module_name))
    assert functions, module_name
    bare = {name: missing for name, function in functions
            if (missing := missing_annotations(function))}
    assert not bare, f"{len(bare)} of {len(functions)} public functions lack annotations: {bare}"


def test_the_check_itself_sees_a_missing_annotation():
    def half(x: float, y) -> float:
        return x / 2

    def whole(self, x: int) -> int:
        return x

    def nothing(x: int):
        return x

    assert missing_annotations(half) == ["y"]
    assert missing_annotations(whole) == []
    assert missing_annotations(nothing) == ["return"]


def test_mypy_finds_no_error():
    """mypy with pyproject.toml's configuration (the files: workflow/reflectance); its cache
    in .pytest_cache (git-ignored): a rerun takes a second, the first half a minute."""
    pytest.importorskip("mypy")
    env = {k: v for k, v in os.environ.items() if k != "MYPYPATH"}
    checked = subprocess.run(
        [sys.executable, "-m", "mypy", "--cache-dir", str(ROOT / ".pytest_cache" / "mypy"),
         "--config-file", str(ROOT / "pyproject.toml")],
        cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "Success: no issues found" in checked.stdout
