"""``Keys``: the key codes pybox2d's testbed examples compare with (``Keys.K_a``...).

pybox2d's default testbed backend is pygame's, so its examples see pygame's key
codes; these are the same numbers (letters and digits are their ASCII codes, so
``key - Keys.K_1`` gives a digit's value, as edge_shapes.py relies on).
:data:`FROM_KGE` maps kge's :class:`~kge.keys.Key` codes (what a kge window
reports) onto them.

>>> Keys.K_a, Keys.K_5 - Keys.K_1, Keys.K_SPACE
(97, 4, 32)
>>> from typing import TYPE_CHECKING

from kge.keys import Key
>>> FROM_KGE[Key.LEFT] == Keys.K_LEFT
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from kge.keys import Key

#: pygame 2's codes for the non-printing keys the examples and the framework use
_SPECIAL = {
    "BACKSPACE": (8, Key.BACKSPACE), "TAB": (9, Key.TAB), "RETURN": (13, Key.RETURN),
    "ESCAPE": (27, Key.ESCAPE), "DELETE": (127, Key.DELETE),
    "INSERT": (1073741897, Key.INSERT), "HOME": (1073741898, Key.HOME),
    "PAGEUP": (1073741899, Key.PAGEUP), "END": (1073741901, Key.END),
    "PAGEDOWN": (1073741902, Key.PAGEDOWN), "RIGHT": (1073741903, Key.RIGHT),
    "LEFT": (1073741904, Key.LEFT), "DOWN": (1073741905, Key.DOWN), "UP": (1073741906, Key.UP),
    "LCTRL": (1073742048, Key.LCTRL), "LSHIFT": (1073742049, Key.LSHIFT),
    "LALT": (1073742050, Key.LALT), "RCTRL": (1073742052, Key.RCTRL),
    "RSHIFT": (1073742053, Key.RSHIFT), "RALT": (1073742054, Key.RALT),
    **{f"F{i}": (1073741881 + i, getattr(Key, f"F{i}")) for i in range(1, 13)},
}
#: printing keys: pygame's name suffix -> the character
_PRINTING = {
    "SPACE": " ", "COMMA": ",", "PERIOD": ".", "MINUS": "-", "EQUALS": "=", "PLUS": "+",
    "SLASH": "/", "SEMICOLON": ";", "QUOTE": "'", "LEFTBRACKET": "[", "RIGHTBRACKET": "]",
    "BACKSLASH": "\\", "BACKQUOTE": "`",
    **{c: c for c in "0123456789"}, **{c: c for c in "abcdefghijklmnopqrstuvwxyz"},
}


class _KeyTable(type):
    if TYPE_CHECKING:  # the K_* names are set below, from the tables
        def __getattr__(cls, name: str) -> int: ...


class Keys(metaclass=_KeyTable):
    """``K_<name>`` for every key (pygame's names and codes)."""


FROM_KGE: dict[int, int] = {}
for _name, (_code, _kge) in _SPECIAL.items():
    setattr(Keys, f"K_{_name}", _code)
    FROM_KGE[_kge] = _code
for _name, _char in _PRINTING.items():
    setattr(Keys, f"K_{_name}", ord(_char))
    FROM_KGE[ord(_char)] = ord(_char)  # kge's printing keys are their ASCII codes too
del _name, _code, _kge, _char


def key_code(name: str) -> int:
    """The code of ``K_<name>`` (``"a"``, ``"space"``, ``"F1"``...), for scripted presses."""
    for candidate in (f"K_{name}", f"K_{name.upper()}", f"K_{name.lower()}"):
        code = getattr(Keys, candidate, None)
        if isinstance(code, int):
            return code
    raise KeyError(f"no key named {name!r} (Keys.K_{name})")
