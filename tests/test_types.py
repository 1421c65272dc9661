"""The public API is typed (PEP 561: the package ships ``py.typed``).

Two checks: every function and method that a module of the package (a subpackage, one of its
modules, a top-level module; not ``__main__``) names in its ``__all__`` has an annotation on each
parameter and its return, read with ``inspect.signature`` (a class's public methods, ``__init__``,
``__call__`` and its properties' accessors; a function behind ``functools.lru_cache``); and mypy,
with pyproject.toml's ``[tool.mypy]``, finds no error in the package, so the annotations agree
with the bodies that use them.
"""

import functools
import importlib
import inspect
import os
import pkgutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _modules_with_all():
    """Every module of the package (subpackages, their modules, the top-level modules) that
    declares an ``__all__``, by dotted name below ``reflectance``; not ``__main__``, which
    runs the command line when imported."""
    import reflectance

    names = []
    for info in pkgutil.walk_packages(reflectance.__path__, "reflectance."):
        if info.name.rpartition(".")[2] == "__main__":
            continue
        if hasattr(importlib.import_module(info.name), "__all__"):
            names.append(info.name.removeprefix("reflectance."))
    return names


#: the public faces whose ``__all__`` is checked: every module that has one
MODULES = _modules_with_all()


def _function_of(value):
    """The plain function behind a module's or class's attribute, or None: a function, one
    wrapped by a decorator that says so (``functools.lru_cache``, ``functools.wraps``), a
    static or class method, a ``functools.cached_property``; a property is handled by the
    caller."""
    if isinstance(value, (staticmethod, classmethod)):
        value = value.__func__
    elif isinstance(value, functools.cached_property):
        value = value.func
    if callable(value) and hasattr(value, "__wrapped__"):
        value = inspect.unwrap(value)
    return value if inspect.isfunction(value) else None


def _own_functions(cls):
    """The functions defined in ``cls``'s body (not generated, e.g. by ``dataclass``) that a
    user calls: the public methods, ``__init__`` and ``__call__``; a property's getter, setter
    and deleter."""
    module_file = inspect.getsourcefile(sys.modules[cls.__module__])
    for name, value in vars(cls).items():
        if name.startswith("_") and name not in ("__init__", "__call__"):
            continue
        if isinstance(value, property):
            accessors = [(name, value.fget), (f"{name}.setter", value.fset),
                         (f"{name}.deleter", value.fdel)]
        else:
            accessors = [(name, _function_of(value))]
        for label, function in accessors:
            if function is not None and function.__code__.co_filename == module_file:
                yield f"{cls.__qualname__}.{label}", function


def public_functions(module_name):
    """(qualified name, function) of every function and class method named in the
    ``__all__`` of ``reflectance.<module_name>``."""
    module = importlib.import_module(f"reflectance.{module_name}")
    for name in module.__all__:
        value = getattr(module, name)
        if inspect.isclass(value):
            if value.__module__.startswith("reflectance."):
                for qualified, function in _own_functions(value):
                    yield f"{module_name}.{qualified}", function
        elif (function := _function_of(value)) is not None:
            yield f"{module_name}.{name}", function


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


def test_the_walk_reaches_every_module_with_an_all():
    assert {"optics", "render", "cli", "config", "scripting", "render.shading", "io.cache",
            "papers.scenes", "papers.figures", "papers.figures.declaration",
            "bench.crosscheck"} <= set(MODULES)
    assert not [name for name in MODULES if name.endswith("__main__")]

def test_the_walk_sees_properties_static_methods_and_cached_functions():
    class Probe:
        def __init__(self, size: int) -> None:
            self._size = size

        @property
        def size(self) -> int:
            return self._size

        @size.setter
        def size(self, value):
            self._size = value

        @functools.cached_property
        def area(self):
            return self._size ** 2

        @staticmethod
        def make(size: int) -> "Probe":
            return Probe(size)

        def _private(self, x):
            return x

    found = {name.rpartition("Probe.")[2]: missing_annotations(function)
             for name, function in _own_functions(Probe)}
    assert found == {"__init__": [], "size": [], "size.setter": ["value", "return"],
                     "area": ["return"], "make": []}

    @functools.lru_cache(maxsize=None)
    def cached(x):
        return x

    assert missing_annotations(_function_of(cached)) == ["x", "return"]
    assert _function_of(42) is None

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
