"""Value checks shared by the UI components (sizes, anchors, text, lists that notice edits).

Every pixel quantity a UI component holds is finite and at most :data:`MAX_PIXELS`
(ten million pixels) in size, so no sum of them in a layout can overflow to an
infinite or NaN box:

>>> px(1e308, "UINode", "padding")
Traceback (most recent call last):
...
kge.errors.ValidationError: UINode.padding must be a number of pixels in 0..1e+07, got 1e+308

Lists held by widgets (a dropdown's options, a list's items) are
:class:`WatchedList`\\ s: editing one in place (``options.append("Hard")``) is
noticed like an assignment, so the UI redraws it, and each new item is checked.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterable, Sequence
from typing import Any, ClassVar, SupportsIndex

from kge.components.color import Color, rgba
from kge.components.text import font_points
from kge.components.tracked import Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import finite, integer, within

#: the largest pixel size, offset or padding a UI component accepts
MAX_PIXELS = 1e7
#: the largest magnitude of a slider's or bar's min, max and value (max - min stays finite)
MAX_RANGE = 1e300

Size = float | str

ANCHORS: dict[str, tuple[float, float]] = {
    "center": (0.5, 0.5),
    "top_left": (0.0, 1.0),
    "top": (0.5, 1.0),
    "top_right": (1.0, 1.0),
    "left": (0.0, 0.5),
    "right": (1.0, 0.5),
    "bottom_left": (0.0, 0.0),
    "bottom": (0.5, 0.0),
    "bottom_right": (1.0, 0.0),
}

Check = Callable[[Any, str, str], Any]


def touch(component: Any) -> None:
    """Mark ``component`` changed for the systems mirroring it (as a field write does)."""
    try:
        binding = component._binding
    except AttributeError:
        return
    if binding is not None:
        binding.dirty.add(binding.entity)


def known(key: Any, names: Sequence[str], where: str, what: str = "field") -> str:
    """``key`` if it is one of ``names``; otherwise a ValidationError suggesting the
    nearest (``Style has no field 'backgruond' (did you mean 'background'?)``)."""
    if key in names:
        return str(key)
    near = difflib.get_close_matches(str(key), names, n=1)
    hint = f" (did you mean {near[0]!r}?)" if near else ""
    raise ValidationError(f"{where} has no {what} {key!r}{hint}")


def choice(options: tuple[str, ...]) -> Check:
    """A check accepting one of ``options``."""

    def check(value: Any, owner: str, name: str) -> str:
        if value not in options:
            raise ValidationError(
                f"{owner}.{name} must be one of {', '.join(options)}, got {value!r}"
            )
        return str(value)

    return check


def px(value: Any, owner: str, name: str) -> float:
    """Pixels in ``0..MAX_PIXELS``."""
    v = finite(value, owner, name)
    if not 0.0 <= v <= MAX_PIXELS:
        raise ValidationError(
            f"{owner}.{name} must be a number of pixels in 0..{MAX_PIXELS:g}, got {v!r}"
        )
    return v


def ranged(value: Any, owner: str, name: str) -> float:
    """A slider's or bar's min, max or value: finite, within +-:data:`MAX_RANGE`."""
    return within(value, MAX_RANGE, owner, name)


def scroll_px(value: Any, owner: str, name: str) -> float:
    """A scroll offset: pixels in ``0..1e12`` (a virtual list of millions of rows)."""
    v = finite(value, owner, name)
    if not 0.0 <= v <= 1e12:
        raise ValidationError(f"{owner}.{name} must be a number of pixels in 0..1e12, got {v!r}")
    return v


def opt_px(value: Any, owner: str, name: str) -> float | None:
    return None if value is None else px(value, owner, name)


def offset(value: Any, owner: str, name: str) -> tuple[float, float]:
    """An (x, y) offset in pixels, each within ``MAX_PIXELS``."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise ComponentTypeError(f"{owner}.{name} must be an (x, y) pair, got {value!r}")
    x, y = finite(value[0], owner, f"{name}[0]"), finite(value[1], owner, f"{name}[1]")
    for v in (x, y):
        if abs(v) > MAX_PIXELS:
            raise ValidationError(
                f"{owner}.{name} must lie within {MAX_PIXELS:g} pixels, got {tuple(value)!r}"
            )
    return (x, y)


def size(value: Any, owner: str, name: str) -> Size:
    """A size: pixels in ``0..MAX_PIXELS``, ``"NN%"`` (0..1000) or ``"auto"``."""
    bad = ValidationError(
        f"{owner}.{name} must be >= 0 pixels, a percent like '50%' or 'auto', got {value!r}"
    )
    if isinstance(value, str):
        if value == "auto":
            return value
        if value.endswith("%"):
            try:
                pct = float(value[:-1])
            except ValueError:
                raise bad from None
            if 0.0 <= pct <= 1000.0:
                return value
        raise bad
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise bad
    v = float(value)
    if not 0.0 <= v <= MAX_PIXELS:  # NaN fails too
        raise bad
    return v


def weight(value: Any, owner: str, name: str) -> float:
    """A grow or shrink weight: finite, 0..1e6."""
    v = finite(value, owner, name)
    if not 0.0 <= v <= 1e6:
        raise ValidationError(f"{owner}.{name} must be in 0..1e6, got {v!r}")
    return v


def anchor(value: Any, owner: str, name: str) -> str:
    if value not in ANCHORS:
        raise ValidationError(f"{owner}.{name} must be one of {', '.join(ANCHORS)}, got {value!r}")
    return str(value)


def entity_ref(value: Any, owner: str, name: str) -> int | None:
    return None if value is None else integer(value, owner, name)


def opt_int(value: Any, owner: str, name: str) -> int | None:
    return None if value is None else integer(value, owner, name)


def text(value: Any, owner: str, name: str) -> str:
    if not isinstance(value, str):
        raise ComponentTypeError(
            f"{owner}.{name} must be a str, got {type(value).__name__} {value!r}"
        )
    return value


def at_least_one(value: Any, owner: str, name: str) -> int:
    v = integer(value, owner, name)
    if v < 1:
        raise ValidationError(f"{owner}.{name} must be >= 1, got {v}")
    return v


def font_size(value: Any, owner: str, name: str) -> float | None:
    """None (the theme's) or points in (0, 1000], as for Text."""
    return None if value is None else font_points(value, owner, name)


def opt_color(value: Any, owner: str, name: str) -> Color | None:
    return None if value is None else rgba(value, owner, name)


def image(value: Any, owner: str, name: str) -> Any:
    """An asset name, a :class:`kge.render.images.PixelImage` or a pyglet image."""
    if isinstance(value, str) or (hasattr(value, "width") and hasattr(value, "height")):
        return value
    raise ComponentTypeError(
        f"{owner}.{name} must be an asset name, a PixelImage or an image, got {value!r}"
    )


def opt_image(value: Any, owner: str, name: str) -> Any:
    return None if value is None else image(value, owner, name)


def index_in(value: Any, count: int, owner: str, name: str, what: str,
             none: int | None = -1) -> int:  # fmt: skip
    """``value`` as an index of ``count`` items (or ``none`` for "no selection")."""
    v = integer(value, owner, name)
    if v != none and not 0 <= v < count:
        raise ValidationError(
            f"{owner}.{name} {v} is not an index of its {count} {what}"
            + (f" (or {none} for none)" if none is not None else "")
        )
    return v


class WatchedList(list[Any]):
    """A list that marks its owner component changed when edited in place.

    ``check(item, owner_name, field)`` validates each item added and ``whole(items,
    owner_name, field)`` the list an edit would make, so a bad edit is refused at the
    call that made it and the list is left as it was.
    """

    __slots__ = ("check", "field", "owner", "whole")

    def __init__(self, items: Iterable[Any] = (), owner: Any = None, field: str = "",
                 check: Check | None = None, whole: Check | None = None) -> None:  # fmt: skip
        self.owner, self.field, self.check, self.whole = owner, field, check, whole
        super().__init__(items)

    def _name(self) -> str:
        return self.owner._owner() if self.owner is not None else ""

    def _checked(self, items: Iterable[Any]) -> list[Any]:
        got = list(items)
        if self.check is not None:
            got = [self.check(item, self._name(), self.field) for item in got]
        return got

    def _commit(self, edit: Callable[[list[Any]], Any]) -> Any:
        if self.whole is not None:
            trial = list(self)
            edit(trial)
            self.whole(trial, self._name(), self.field)
        out = edit(self)
        if self.owner is not None:
            touch(self.owner)
            hook = getattr(self.owner, "_list_changed", None)
            if hook is not None:
                hook(self.field)
        return out

    def __reduce_ex__(self, protocol: SupportsIndex) -> Any:
        """Pickled as a plain list (a snapshot restores it through the component's check)."""
        return (list, (list(self),))

    def __copy__(self) -> list[Any]:
        return list(self)

    def __deepcopy__(self, memo: dict[int, Any]) -> list[Any]:
        import copy

        return [copy.deepcopy(v, memo) for v in self]

    def append(self, item: Any) -> None:
        (item,) = self._checked([item])
        self._commit(lambda lst: list.append(lst, item))

    def extend(self, items: Iterable[Any]) -> None:
        got = self._checked(items)
        self._commit(lambda lst: list.extend(lst, got))

    def insert(self, index: SupportsIndex, item: Any) -> None:
        (item,) = self._checked([item])
        self._commit(lambda lst: list.insert(lst, index, item))

    def __setitem__(self, index: Any, value: Any) -> None:
        got = self._checked(value) if isinstance(index, slice) else self._checked([value])[0]
        self._commit(lambda lst: list.__setitem__(lst, index, got))

    def __delitem__(self, index: Any) -> None:
        self._commit(lambda lst: list.__delitem__(lst, index))

    def __iadd__(self, items: Iterable[Any]) -> WatchedList:  # type: ignore[misc]
        self.extend(items)
        return self

    def pop(self, index: SupportsIndex = -1) -> Any:
        return self._commit(lambda lst: list.pop(lst, index))

    def remove(self, item: Any) -> None:
        self._commit(lambda lst: list.remove(lst, item))

    def clear(self) -> None:
        self._commit(list.clear)

    def sort(self, *args: Any, **kwargs: Any) -> None:
        self._commit(lambda lst: list.sort(lst, *args, **kwargs))

    def reverse(self) -> None:
        self._commit(list.reverse)


def watched(check: Check | None = None, whole: Check | None = None) -> Check:
    """A check turning any iterable of items (each passing ``check``, the whole passing
    ``whole``) into a WatchedList; the widget becomes its owner when it is assigned."""

    def convert(value: Any, owner: str, name: str) -> WatchedList:
        if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__"):
            raise ComponentTypeError(f"{owner}.{name} must be a list, got {value!r}")
        items = list(value)
        if check is not None:
            items = [check(item, owner, name) for item in items]
        if whole is not None:
            whole(items, owner, name)
        return WatchedList(items, None, name, check, whole)

    return convert


def strings(value: Any, owner: str, name: str) -> WatchedList:
    """A list of str (an ordinary list is copied into a :class:`WatchedList`)."""
    return _strings(value, owner, name)


_strings = watched(text)


def adopt(component: Any, *names: str) -> None:
    """Make ``component`` the owner of its WatchedList fields ``names`` (after a write)."""
    for name in names:
        value = getattr(component, name, None)
        if isinstance(value, WatchedList):
            value.owner = component


class Widget(Tracked):
    """Base of the UI widget components: its list fields are :class:`WatchedList`\\ s
    owned by the widget (``_lists`` names them), so in-place edits are noticed."""

    __slots__ = ()
    _lists: ClassVar[tuple[str, ...]] = ()

    def __setattr__(self, name: str, value: Any) -> None:
        Tracked.__setattr__(self, name, value)
        if name in self._lists:
            adopt(self, name)

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Unpickled (snapshots): plain lists become watched lists owned by the widget."""
        Tracked.__setstate__(self, state)
        for name in self._lists:
            value = getattr(self, name, None)
            if value is not None and not isinstance(value, WatchedList):
                self.__setattr__(name, value)
