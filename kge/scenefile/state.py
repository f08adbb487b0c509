"""What a world remembers of the files it was loaded from (the ``SceneState`` resource).

Entity keys (the ``id`` strings of a file) live here, not in components, so
components stay the game's data: saving writes each entity under the key it was
loaded with, and references between entities by those keys, whatever ids the
entities got. Prefab instances are remembered too (which prefab, where, which
fields the instance overrides), so saving writes the instance back as one entry
and a changed prefab file reaches every instance.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

Pose = tuple[float, float, float]

_KEY_TAIL = re.compile(r"^(.*?)(?:-(\d+))?$")


@dataclass(slots=True)
class Instance:
    """One prefab placed in a scene."""

    key: str  #: the instance's id in the scene ("car1")
    prefab: Path  #: the prefab file (resolved)
    at: Pose | None  #: the pose of the prefab's root (None: placed as authored)
    #: member key -> {component name -> {field -> raw value as written}}
    overrides: dict[str, dict[str, dict[str, Any]]] = field(default_factory=dict)
    #: member key -> entity id
    members: dict[str, int] = field(default_factory=dict)
    root: str | None = None  #: the member whose Transform is the instance's pose
    #: the root's pose as the prefab file places it (where an instance without ``at`` is)
    authored: Pose = (0.0, 0.0, 0.0)


@dataclass(slots=True)
class MapRef:
    """A Tiled map a scene file loads (and the options it loads it with)."""

    source: str  #: as the component holds it: an absolute path or an asset name
    options: dict[str, Any] = field(default_factory=dict)
    handle: Any = None  #: the loaded TileMap


@dataclass(slots=True)
class SceneState:
    """Per world: the file it came from, entity keys, prefab instances and map references."""

    source: Path | None = None
    keys: dict[int, str] = field(default_factory=dict)
    instances: dict[str, Instance] = field(default_factory=dict)
    #: entity -> (instance key, member key)
    members: dict[int, tuple[str, str]] = field(default_factory=dict)
    maps: list[MapRef] = field(default_factory=list)
    #: the text of every file the world was loaded from (scene, prefabs), by path
    files: dict[Path, str] = field(default_factory=dict)

    def key_of(self, entity: int) -> str | None:
        return self.keys.get(entity)

    def entity(self, key: str) -> int | None:
        for e, k in self.keys.items():
            if k == key:
                return e
        return None

    def new_key(self, base: str, taken: set[str] | None = None) -> str:
        """A key not used yet, made from ``base`` ("Crate" -> "crate", "crate-2"...)."""
        used = set(self.keys.values()) if taken is None else taken
        stem = re.sub(r"[^A-Za-z0-9_-]+", "-", base.strip().lower()).strip("-") or "entity"
        m = _KEY_TAIL.match(stem)
        stem = m.group(1) if m and m.group(1) else stem
        if stem not in used:
            return stem
        n = 2
        while f"{stem}-{n}" in used:
            n += 1
        return f"{stem}-{n}"


def compose(a: Pose, b: Pose) -> Pose:
    """The pose ``b`` (given in ``a``'s frame) in ``a``'s parent frame."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2])


def inverse(a: Pose) -> Pose:
    c, s = math.cos(a[2]), math.sin(a[2])
    return (-(c * a[0] + s * a[1]), s * a[0] - c * a[1], -a[2])


def apply(a: Pose, p: tuple[float, float]) -> tuple[float, float]:
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * p[0] - s * p[1], a[1] + s * p[0] + c * p[1])


IDENTITY: Pose = (0.0, 0.0, 0.0)
