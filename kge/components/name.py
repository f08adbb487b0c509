"""``Name``: a human label for an entity (debug overlays, finding things in tests)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(slots=True)
class Name:
    """A label; several entities may share one."""

    value: str

    def __str__(self) -> str:
        return self.value
