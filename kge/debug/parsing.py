"""Typed console arguments: text to ``int``, ``float``, ``bool``, enums, tuples."""

from __future__ import annotations

import enum
import inspect
import types
import typing
from typing import Any

from kge.errors import KgeError


class ConsoleError(KgeError, ValueError):
    """A console line that cannot run: an unknown command, a bad or missing argument."""


_TRUE = frozenset({"1", "true", "on", "yes"})
_FALSE = frozenset({"0", "false", "off", "no"})


def parse_value(text: str, kind: Any, what: str) -> Any:
    """``text`` as a value of ``kind`` (the annotation); ConsoleError when it is not.

    >>> parse_value("3", int, "n"), parse_value("on", bool, "b"), parse_value("1,2", tuple, "v")
    (3, True, (1.0, 2.0))
    """
    if kind in (inspect.Parameter.empty, Any, str):
        return text
    origin = typing.get_origin(kind)
    if origin in (typing.Union, types.UnionType):
        args = [a for a in typing.get_args(kind) if a is not type(None)]
        if text.lower() in ("none", "-") and len(args) < len(typing.get_args(kind)):
            return None
        return parse_value(text, args[0] if args else str, what)
    if kind is bool:
        low = text.lower()
        if low in _TRUE:
            return True
        if low in _FALSE:
            return False
        raise ConsoleError(f"{what}: {text!r} is not true/false (on/off, 1/0)")
    if kind is int:
        try:
            return int(text)
        except ValueError:
            raise ConsoleError(f"{what}: {text!r} is not a whole number") from None
    if kind is float:
        try:
            v = float(text)
        except ValueError:
            raise ConsoleError(f"{what}: {text!r} is not a number") from None
        if v != v or v in (float("inf"), float("-inf")):
            raise ConsoleError(f"{what}: {text!r} is not a finite number")
        return v
    if kind is tuple or origin is tuple:
        try:
            return tuple(float(p) for p in text.strip("()").split(","))
        except ValueError:
            raise ConsoleError(f"{what}: {text!r} is not numbers separated by commas") from None
    if isinstance(kind, type) and issubclass(kind, enum.Enum):
        for member in kind:
            if member.name.lower() == text.lower() or str(member.value) == text:
                return member
        names = ", ".join(m.name for m in kind)
        raise ConsoleError(f"{what}: {text!r} is not one of {names}")
    raise ConsoleError(f"{what}: a parameter of type {kind!r} cannot be typed in")


