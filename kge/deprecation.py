"""Renamed names keep working for one release, with a :class:`DeprecationWarning`.

Three kinds of rename, one helper each:

* a module-level name (``kge.Sequence`` -> ``kge.TweenSequence``): :func:`moved`
  builds a module ``__getattr__`` that warns and returns the new object;
* a dataclass field (``ParticleEmitter.alpha`` -> ``opacity``): :func:`renamed_fields`
  makes the constructor accept the old keyword and adds a property for the old
  attribute, both converting the value when the unit changed too;
* a string where an enum is now expected: :func:`enum_value` converts it, warning.

>>> import warnings
>>> from dataclasses import dataclass
>>> @renamed_fields(metres=("meters", None, None))
... @dataclass
... class Rope:
...     meters: float = 1.0
>>> with warnings.catch_warnings(record=True) as caught:
...     warnings.simplefilter("always")
...     rope = Rope(metres=2.0)
>>> rope.meters, caught[0].category.__name__
(2.0, 'DeprecationWarning')
"""

from __future__ import annotations

import functools
import sys
import warnings
from collections.abc import Callable
from enum import Enum
from typing import Any, TypeVar

from kge.errors import ValidationError

T = TypeVar("T")
E = TypeVar("E", bound=Enum)

#: the release that removes what this module keeps alive
REMOVED_IN = "kge 2.1"


def warn(message: str) -> None:
    """A DeprecationWarning pointing at the first line outside kge (the user's)."""
    warnings.warn(
        f"{message} (deprecated; removed in {REMOVED_IN})",
        DeprecationWarning,
        stacklevel=_outside_kge(),
    )


def _outside_kge() -> int:
    """The stack level of the innermost frame that is not kge's own code."""
    level, frame = 2, sys._getframe(2)
    while frame.f_back is not None and (
        frame.f_globals.get("__name__", "").startswith("kge.")
        or frame.f_code.co_filename.startswith("<")  # a dataclass's generated __init__
    ):
        frame, level = frame.f_back, level + 1
    return level


def moved(module: str, names: dict[str, tuple[Callable[[], Any], str]]) -> Callable[[str], Any]:
    """A module ``__getattr__`` for renamed names: ``{old: (load_new, "new name")}``."""

    def __getattr__(name: str) -> Any:
        entry = names.get(name)
        if entry is None:
            raise AttributeError(f"module {module!r} has no attribute {name!r}")
        load, new = entry
        warn(f"{module}.{name} is now {new}")
        return load()

    return __getattr__


Convert = Callable[[Any], Any] | None


def renamed_fields(**renames: tuple[str, Convert, Convert]) -> Callable[[type[T]], type[T]]:
    """Keep old field names of a dataclass: ``old=(new, old_to_new, new_to_old)``.

    ``old_to_new`` / ``new_to_old`` convert values when the unit changed (None: same
    value). The constructor takes ``old=`` (warning, converted); ``obj.old`` reads and
    writes ``obj.new`` (warning, converted). Passing both names is a TypeError.
    """

    def decorate(cls: type[T]) -> type[T]:
        init = cls.__init__

        @functools.wraps(init)
        def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
            for old, (new, to_new, _) in renames.items():
                if old in kwargs:
                    if new in kwargs:
                        raise TypeError(
                            f"{cls.__name__}() got both {old}= and {new}= ({old} is the "
                            f"deprecated name of {new})"
                        )
                    warn(f"{cls.__name__}({old}=...) is now {new}=")
                    value = kwargs.pop(old)
                    kwargs[new] = value if to_new is None else to_new(value)
            init(self, *args, **kwargs)

        setattr(cls, "__init__", __init__)  # noqa: B010 (mypy refuses assigning a method)
        for old, (new, to_new, to_old) in renames.items():
            setattr(cls, old, _alias(cls.__name__, old, new, to_new, to_old))
        return cls

    return decorate


def _alias(owner: str, old: str, new: str, to_new: Convert, to_old: Convert) -> property:
    def get(self: Any) -> Any:
        warn(f"{owner}.{old} is now {owner}.{new}")
        value = getattr(self, new)
        return value if to_old is None else to_old(value)

    def set_(self: Any, value: Any) -> None:
        warn(f"{owner}.{old} is now {owner}.{new}")
        setattr(self, new, value if to_new is None else to_new(value))

    return property(get, set_, doc=f"Deprecated: {new}.")


def enum_value(kind: type[E], value: Any, owner: str, field: str) -> E:
    """``value`` as a member of ``kind``; its string value is accepted, warning."""
    if isinstance(value, kind):
        return value
    try:
        member = kind(value)
    except ValueError:
        choices = ", ".join(f"{kind.__name__}.{m.name}" for m in kind)
        raise ValidationError(f"{owner}.{field} must be one of {choices}, got {value!r}") from None
    warn(f"{owner}.{field}={value!r} is now {kind.__name__}.{member.name}")
    return member
