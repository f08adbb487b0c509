"""Every error kge raises on purpose is a KgeError, and every one is exported from kge
(those of the optional extras from their package: kge.gym, kge.box2d)."""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import warnings

import kge

#: errors that live in an optional extra's package, exported there
EXTRA_PACKAGES = ("kge.gym", "kge.box2d")


def _kge_modules() -> list[str]:
    names = []
    for info in pkgutil.walk_packages(kge.__path__, "kge."):
        if info.name.startswith(EXTRA_PACKAGES) or info.name.startswith(("kge.testbed",)):
            continue
        names.append(info.name)
    return names


def _defined_exceptions() -> dict[str, type[BaseException]]:
    found: dict[str, type[BaseException]] = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name in _kge_modules():
            try:
                module = importlib.import_module(name)
            except ImportError:  # a module needing an optional dependency
                continue
            for obj in vars(module).values():
                if (
                    inspect.isclass(obj)
                    and issubclass(obj, BaseException)
                    and obj.__module__.startswith("kge.")
                    and not obj.__module__.startswith(EXTRA_PACKAGES)
                ):
                    found[obj.__name__] = obj
    return found


def test_every_error_is_a_kge_error_and_exported() -> None:
    defined = _defined_exceptions()
    assert {"ScheduleError", "SnapshotError", "DisplayError", "ScaffoldError"} <= set(defined)
    for name, exc in defined.items():
        if issubclass(exc, Warning):
            continue
        assert issubclass(exc, kge.KgeError), f"{exc.__module__}.{name} is not a KgeError"
    not_exported = sorted(n for n in defined if n not in kge.__all__)
    assert not_exported == [], f"errors missing from kge.__all__: {not_exported}"


def test_scaffold_errors_are_value_errors_and_kge_errors() -> None:
    from kge.scaffold import ScaffoldError, package_name

    try:
        package_name("9lives")
    except kge.KgeError as err:
        assert isinstance(err, ScaffoldError) and isinstance(err, ValueError)
    else:
        raise AssertionError("a digit-first name was accepted")
