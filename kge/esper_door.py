"""The door to esper's private layer: the only module in kge that names it.

esper 3.9 keeps each world's state in module globals that :func:`esper.switch_world`
swaps: ``_entities`` (entity -> {component type: component}) and ``_entity_count``
(the iterator that hands out entity ids). kge's :class:`~kge.world.World` fills the
table in bulk (validated spawns, snapshot restores) and reserves ids ahead, which
esper's public API has no call for. Every function here acts on esper's *current*
world: switch to the right one first (``World._use``).
``tests/core/test_esper_door.py`` pins each function to esper's public behaviour;
an esper upgrade touches this module only (see docs/architecture.md).

>>> import esper
>>> before = esper.current_world
>>> esper.switch_world("esper-door-doctest")
>>> e = esper.create_entity(3.5)
>>> entity_table()[e] == {float: 3.5}, next_entity_id() == e + 1
(True, True)
>>> esper.switch_world(before)
>>> esper.delete_world("esper-door-doctest")
"""

from __future__ import annotations

import copy
import itertools
from typing import Any

import esper


def entity_table() -> dict[int, dict[type, Any]]:
    """esper's live entity table of the current world (entity -> {type: component}).

    Writes go straight into esper: clear its query cache (``esper.clear_cache()``)
    after changing which entities hold which types.
    """
    table: dict[int, dict[type, Any]] = esper._entities
    return table


def next_entity_id() -> int:
    """The id ``esper.create_entity()`` will hand out next, without taking it."""
    return int(next(copy.copy(esper._entity_count)))


def set_next_entity_id(entity: int) -> None:
    """Make ``entity`` the id ``esper.create_entity()`` hands out next (ids below it
    are reserved: restored or spawned through :func:`entity_table`)."""
    esper._entity_count = itertools.count(start=entity)
