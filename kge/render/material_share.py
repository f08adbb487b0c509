"""Drawables whose Materials are alike share one draw call.

Each Material is its own component, so a thousand crates spawned with
``Material(shader, {"wave": 2.0})`` hold a thousand equal materials. Drawn one group
each, they cost a draw call and a vertex domain apiece. :class:`SharedMaterials` gives
drawables whose material has the same shader and equal uniform values one
:class:`~kge.render.programs.MaterialGroup`, set from a copy of those values.

Uniforms may change at any time without a tracked write (a tween, ``material.set``),
so every frame :meth:`SharedMaterials.diverged` compares each sharing material with
its group's copy (a dict comparison each); one that differs leaves for good and is
drawn alone, reading its own uniforms as it is drawn (what an animated material
needs). A group nobody uses any more is dropped.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from kge.components.material import Material, Shader
from kge.render.programs import MaterialGroup


@dataclass(slots=True)
class _Values:
    """The uniform values a shared group sets (a copy, so members can be compared)."""

    shader: Shader
    uniforms: dict[str, Any]


def _freeze(value: Any) -> Any:
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (tuple, list)):
        return tuple(_freeze(v) for v in value)
    return ("object", id(value))  # an image: the group's copy keeps it alive


def signature(material: Material) -> tuple[Any, ...]:
    """What makes two materials draw alike: the shader and the uniform values."""
    return (hash(material.shader),
            tuple(sorted((k, _freeze(v)) for k, v in material.uniforms.items())))  # fmt: skip


class SharedMaterials:
    """Material groups shared by alike materials (see the module docstring)."""

    def __init__(self) -> None:
        self._groups: dict[tuple[Any, ...], MaterialGroup] = {}
        self._users: dict[tuple[Any, ...], set[Any]] = {}
        #: drawable key -> (its material, the group key it shares)
        self._members: dict[Any, tuple[Material, tuple[Any, ...]]] = {}
        #: drawables whose material changed after sharing: drawn alone from now on
        self.alone: set[Any] = set()

    def group(self, key: Any, material: Material, prog: Any, parent: Any,
              textures: Any) -> MaterialGroup | None:  # fmt: skip
        """The shared group of drawable ``key`` (None: it is drawn alone)."""
        self.forget(key)
        if key in self.alone:
            return None
        gkey = (id(prog), parent, signature(material))
        group = self._groups.get(gkey)
        if group is None:
            values = _Values(material.shader, dict(material.uniforms))
            group = self._groups[gkey] = MaterialGroup(values, prog, textures, parent)
            self._users[gkey] = set()
        self._users[gkey].add(key)
        self._members[key] = (material, gkey)
        return group

    def diverged(self) -> list[Any]:
        """Drawables whose material no longer matches its group's values; they are moved
        to :attr:`alone` (the caller draws them again)."""
        moved = [key for key, (m, gkey) in self._members.items()
                 if m.uniforms != self._groups[gkey].material.uniforms
                 or m.shader is not self._groups[gkey].material.shader]  # fmt: skip
        for key in moved:
            self.forget(key)
            self.alone.add(key)
        return moved

    def forget(self, key: Any, gone: bool = False) -> None:
        """``key`` shares no group now (``gone``: the drawable was removed)."""
        if gone:
            self.alone.discard(key)
        found = self._members.pop(key, None)
        if found is None:
            return
        users = self._users[found[1]]
        users.discard(key)
        if not users:
            del self._users[found[1]], self._groups[found[1]]

    def __len__(self) -> int:
        """How many shared groups there are."""
        return len(self._groups)
