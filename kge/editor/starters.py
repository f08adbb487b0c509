"""What the inspector's **Add** puts on an entity: a component with its defaults, and a
starting value for each field that has none (a collider's shape, a sprite's image, a
joint's bodies), so every kge component can be added and then tuned.

>>> from kge.components import drawables as draw
>>> starter(draw.Circle, entity=1, assets=[]).radius
0.5
>>> starter(draw.Line, entity=1, assets=[]).end
(1.0, 0.0)
"""

from __future__ import annotations

import dataclasses
from typing import Any

from kge.editor.fields import IMAGE_SUFFIXES, SOUND_SUFFIXES
from kge.errors import ValidationError

_TRIANGLE = [(-0.5, -0.5), (0.5, -0.5), (0.0, 0.5)]


def _shape() -> Any:
    from kge.components.shapes import Box

    return Box(0.5, 0.5)


def _first(assets: list[str], suffixes: tuple[str, ...], what: str, cls: type) -> str:
    for a in assets:
        if a.lower().endswith(suffixes):
            return a
    raise ValidationError(f"{cls.__name__} needs {what}: put one in the scene's folder first")


def _value(cls: type, name: str, entity: int, assets: list[str]) -> Any:
    """A starting value for the required field ``name`` of ``cls``."""
    fixed: dict[str, Any] = {
        "shape": _shape, "radius": lambda: 0.5, "width": lambda: 1.0,
        "height": lambda: 1.0, "start": lambda: (0.0, 0.0), "end": lambda: (1.0, 0.0),
        "vertices": lambda: list(_TRIANGLE), "a": lambda: _TRIANGLE[0],
        "b": lambda: _TRIANGLE[1], "c": lambda: _TRIANGLE[2], "text": lambda: "Text",
        "value": lambda: cls.__name__, "body_a": lambda: None, "body_b": lambda: entity,
        "image": lambda: _first(assets, IMAGE_SUFFIXES, "an image", cls),
        "sound": lambda: _first(assets, SOUND_SUFFIXES, "a sound", cls),
    }  # fmt: skip
    make = fixed.get(name)
    if make is None:
        raise ValidationError(
            f"{cls.__name__} needs {name!r} and has no starting value: add it in the scene "
            "file (or from code), then tune it here"
        )
    return make()


def starter(cls: type, entity: int, assets: list[str]) -> Any:
    """A new ``cls`` for ``entity``: its defaults, and a starting value for each field
    without one (the first image or sound of ``assets`` for an asset field)."""
    if not dataclasses.is_dataclass(cls):
        return cls()
    required = [
        f.name for f in dataclasses.fields(cls)
        if f.init and f.default is dataclasses.MISSING
        and f.default_factory is dataclasses.MISSING
    ]  # fmt: skip
    return cls(**{name: _value(cls, name, entity, assets) for name in required})
