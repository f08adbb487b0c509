"""No public kge call hands out a pymunk object.

pymunk aborts the interpreter on a few misuses (``body.sleep()`` with sleeping
off, a body removed while its arbiters are parked, a constraint between one
body and itself). kge makes them unreachable by never giving user code the
pymunk objects: everything goes through components, ``Physics`` calls and
events, which validate first. This test walks the public surface that could
leak one: every public property and method annotation of ``Physics``, every
field of the event records and query results.
"""

from __future__ import annotations

import dataclasses
import inspect
import typing

import pymunk

from kge.physics import contacts, events, queries
from kge.physics.resource import Physics
from kge.systems.physics import PhysicsSystem
from kge.world import World

PYMUNK_TYPES = (pymunk.Space, pymunk.Body, pymunk.Shape, pymunk.Constraint, pymunk.Arbiter)


def _mentions_pymunk(annotation: object) -> bool:
    return "pymunk" in str(annotation)


def test_physics_methods_and_properties_return_no_pymunk_object() -> None:
    world = World()
    world.add_system(PhysicsSystem())
    physics = world.resource(Physics)
    for name, member in inspect.getmembers(Physics):
        if name.startswith("_"):
            continue
        if isinstance(member, property):
            assert not isinstance(getattr(physics, name), PYMUNK_TYPES), f"Physics.{name}"
            assert not _mentions_pymunk(typing.get_type_hints(member.fget).get("return"))
        elif callable(member):
            hints = typing.get_type_hints(member)
            assert not _mentions_pymunk(hints.get("return")), f"Physics.{name} returns pymunk"
    world.close()


def test_event_and_query_records_carry_ids_and_numbers_only() -> None:
    records = [
        obj for module in (contacts, events, queries) for obj in vars(module).values()
        if dataclasses.is_dataclass(obj) and isinstance(obj, type)
        and obj.__module__ == module.__name__
    ]
    assert len(records) >= 8  # begin/end, sensor begin/end, hit, ray hit, pre/post-solve...
    for record in records:
        for field, hint in typing.get_type_hints(record).items():
            assert not _mentions_pymunk(hint), f"{record.__name__}.{field}: {hint}"
