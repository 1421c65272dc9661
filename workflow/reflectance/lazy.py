"""The subpackages' public faces: each public name is loaded with its module on first use.

A subpackage lists its modules and, for each public name, the module that defines it; ``attach``
turns that into the package's ``__getattr__``, ``__dir__`` and ``__all__`` (PEP 562), so that
``import reflectance.optics`` stays cheap and ``from reflectance.render import render`` loads
only what it needs. It imports nothing of the project: every layer may use it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from importlib import import_module
from typing import Any

__all__ = ["attach"]


def attach(package: str, modules: Sequence[str], exports: Mapping[str, str]
           ) -> tuple[Callable[[str], Any], Callable[[], list[str]], list[str]]:
    """``(__getattr__, __dir__, __all__)`` for ``package``.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    modules : tuple of str
        Its modules; a name equal to a module's name is the module.
    exports : dict
        Public name -> the module of ``package`` that defines it.
    """
    names = [*modules, *exports]

    def __getattr__(name: str) -> Any:
        if name in exports:
            return getattr(import_module(f"{package}.{exports[name]}"), name)
        if name in modules:
            return import_module(f"{package}.{name}")
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__() -> list[str]:
        return sorted(names)

    return __getattr__, __dir__, names
