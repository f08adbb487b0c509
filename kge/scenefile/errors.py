"""``SceneFileError``: what a scene, prefab or save file got wrong, and where.

Every refusal names what is known of the place: the file, the line, the entity
(its key in the file and its name), the component or resource, and the field, so
the message reads like a compiler's::

    levels/one.scene.toml:14: entity 'crate' ("Crate"), Collider.density: must be
    >= 0, got -1.0
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from kge.errors import KgeError


@dataclass(slots=True)
class Where:
    """A place in a scene file (every part optional)."""

    path: Path | None = None
    line: int | None = None
    entity: str | None = None
    entity_name: str | None = None
    component: str | None = None
    field: str | None = None

    def describe(self) -> str:
        head = "" if self.path is None else str(self.path)
        if self.line is not None:
            head += f":{self.line}"
        parts: list[str] = []
        if self.entity is not None:
            who = f"entity {self.entity!r}"
            if self.entity_name and self.entity_name != self.entity:
                who += f" ({self.entity_name!r})"
            parts.append(who)
        if self.component is not None:
            parts.append(self.component if self.field is None else f"{self.component}.{self.field}")
        elif self.field is not None:
            parts.append(self.field)
        details = ", ".join(parts)
        return f"{head}: {details}" if head and details else head or details


class SceneFileError(KgeError, ValueError):
    """A scene, prefab or save file (or a world being saved) that kge refuses.

    ``path``, ``line``, ``entity``, ``component`` and ``field`` hold the place
    (None where unknown); the message says it in one line, then the reason.
    """

    def __init__(self, where: Where, reason: str) -> None:
        self.where = where
        named = f"{where.component}.{where.field} "
        if where.field is not None and reason.startswith(named):
            reason = reason[len(named):]  # the place already says which field
        self.reason = reason
        place = where.describe()
        super().__init__(f"{place}: {reason}" if place else reason)

    @property
    def path(self) -> Path | None:
        return self.where.path

    @property
    def line(self) -> int | None:
        return self.where.line

    @property
    def entity(self) -> str | None:
        return self.where.entity

    @property
    def component(self) -> str | None:
        return self.where.component

    @property
    def field(self) -> str | None:
        return self.where.field
