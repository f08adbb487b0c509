"""pybox2d's testbed examples, run unmodified on kge.box2d (or on pybox2d, to compare).

The examples come from the installed pybox2d wheel (``Box2D/examples``; see
:mod:`kge.box2d.wheel`), or from any directory or file given. They import
``Box2D`` and ``Box2D.examples.framework``; :func:`bound` arranges
``sys.modules`` for the time of a run so that ``Box2D`` is the chosen engine
(``"kge"``: kge.box2d; ``"pybox2d"``: the real one), ``Box2D.examples`` is the
examples' directory, and ``Box2D.examples.framework`` / ``.settings`` are
kge's framework (:mod:`kge.box2d.testbed.framework`, loaded once per engine so
that both can run in one process) and settings. Everything is put back after.

:func:`run` executes an example file as ``__main__``, as ``python example.py``
would: its own ``main(TestClass)`` builds the test and hands it to the backend.
"""

from __future__ import annotations

import contextlib
import importlib.util
import re
import runpy
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import kge.box2d
from kge.box2d.testbed import settings
from kge.box2d.testbed.keys import key_code
from kge.box2d.wheel import pybox2d_dir

ENGINES = ("kge", "pybox2d")
_FRAMEWORKS: dict[str, ModuleType] = {}
_PYBOX2D: dict[str, ModuleType] = {}


def examples_dir() -> Path | None:
    """The installed pybox2d wheel's ``Box2D/examples``, or None."""
    return pybox2d_dir("examples")


def is_example(path: Path) -> bool:
    """A testbed example: a file that subclasses the framework and calls ``main``."""
    text = path.read_text(errors="replace")
    return "examples.framework import" in text and re.search(r"^\s*main\(", text, re.M) is not None


def names(folder: Path | None = None) -> list[str]:
    """The examples' names (file names without ``.py``), sorted."""
    folder = folder or examples_dir()
    if folder is None:
        return []
    return sorted(p.stem for p in folder.glob("*.py") if is_example(p))


def find(name: str, folder: Path | None = None) -> Path:
    """The example file for ``name``: a path, or a name in ``folder`` (the wheel's by
    default; ``one-sided-platform`` and ``one_sided_platform`` both work)."""
    given = Path(name)
    if given.suffix == ".py" and given.is_file():
        return given
    folder = folder or examples_dir()
    if folder is None:
        raise FileNotFoundError(
            "pybox2d's examples come from its wheel: pip install 'box2d>=2.3.10,<2.4' "
            "(or give the path of an example file)")
    path = folder / f"{name.replace('-', '_').lower()}.py"
    if not path.is_file():
        raise FileNotFoundError(f"no example {name!r} in {folder}; examples: "
                                f"{', '.join(names(folder))}")
    return path


def keys_handled(name: str) -> list[str]:
    """The keys example ``name``'s source handles (``Keys.K_*`` that exist), sorted."""
    found = []
    for key in sorted(set(re.findall(r"Keys\.K_(\w+)", find(name).read_text()))):
        with contextlib.suppress(KeyError):
            key_code(key)
            found.append(key)
    return found


def _pybox2d_modules() -> dict[str, ModuleType]:
    """The real pybox2d's modules, imported once (kge.box2d set aside meanwhile)."""
    if not _PYBOX2D:
        known = kge.box2d.real_pybox2d()  # pybox2d cannot be imported twice: reuse it
        if known:
            _PYBOX2D.update(known)
            return _PYBOX2D
        saved = _take_box2d()
        try:
            if importlib.util.find_spec("Box2D") is None:
                raise ModuleNotFoundError("pybox2d is not installed (pip install box2d)")
            importlib.import_module("Box2D")
            _PYBOX2D.update(_take_box2d())
        finally:
            _take_box2d()
            sys.modules.update(saved)
        kge.box2d.keep_real_pybox2d(_PYBOX2D)
    return _PYBOX2D


def pybox2d_module() -> ModuleType:
    """The real pybox2d's ``Box2D`` module, to compare with kge.box2d in one process (it is
    imported once and kept out of ``sys.modules``: ``import Box2D`` is not changed)."""
    return _pybox2d_modules()["Box2D"]


def _take_box2d() -> dict[str, ModuleType]:
    """Remove and return every ``Box2D`` / ``Box2D.*`` entry of ``sys.modules``."""
    keys = [k for k in sys.modules if k == "Box2D" or k.startswith("Box2D.")]
    return {k: sys.modules.pop(k) for k in keys}


def _framework(engine: str) -> ModuleType:
    """kge's framework module bound to the ``Box2D`` now in ``sys.modules`` (one per engine)."""
    if engine not in _FRAMEWORKS:
        # a private copy per engine, from the file (importing kge.box2d.testbed.framework
        # would bind that module to whichever Box2D happens to be installed now)
        spec = importlib.util.spec_from_file_location(
            f"kge.box2d.testbed._framework_{engine}", Path(__file__).with_name("framework.py"))
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        _FRAMEWORKS[engine] = module
    return _FRAMEWORKS[engine]


@contextlib.contextmanager
def bound(engine: str = "kge", folder: Path | None = None) -> Iterator[Any]:
    """``sys.modules`` arranged for running examples on ``engine`` (see the module notes);
    yields the framework module they will import."""
    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {ENGINES}, got {engine!r}")
    real = _pybox2d_modules() if engine == "pybox2d" else {}  # (before Box2D is taken)
    saved = _take_box2d()
    try:
        if engine == "kge":
            kge.box2d.install()
        else:
            sys.modules.update(real)
        framework = _framework(engine)
        package = ModuleType("Box2D.examples")
        package.__path__ = [str(folder or examples_dir() or ".")]
        sys.modules["Box2D.examples"] = package
        sys.modules["Box2D.examples.framework"] = framework
        sys.modules["Box2D.examples.settings"] = settings
        package.framework = framework  # type: ignore[attr-defined]
        package.settings = settings  # type: ignore[attr-defined]
        yield framework
    finally:
        _take_box2d()
        sys.modules.update(saved)
        if _PYBOX2D:
            kge.box2d.keep_real_pybox2d(_PYBOX2D)


def run(name: str, backend: Any, engine: str = "kge", argv: list[str] | None = None,
        apply: Any = None) -> None:
    """Run example ``name`` (a name or a file) on ``engine`` with ``backend``, from fresh
    settings (plus the parsed testbed options ``apply``, if given), as ``python example.py``
    runs it; ``argv`` becomes its ``sys.argv[1:]``."""
    path = find(name)
    settings.reset()
    if apply is not None:
        settings.apply(apply)
    old_argv = sys.argv
    with bound(engine, path.parent) as framework:
        vars(framework)["backend"] = backend
        sys.argv = [str(path), *(argv or [])]
        try:
            runpy.run_path(str(path), run_name="__main__")
        finally:
            sys.argv = old_argv
            vars(framework)["backend"] = None
            settings.reset()  # what the run changed does not leak into the next
