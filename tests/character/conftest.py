"""Helpers for the character tests: small scenes and a headless App with physics,
characters and behaviours only."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import pytest

from kge import (
    App,
    BehaviourPlugin,
    Box,
    CharacterBody,
    CharacterPlugin,
    Circle,
    Collider,
    Edge,
    PhysicsPlugin,
    Transform,
    World,
    collision,
)
from kge.character.shapes import character_core

PLUGINS = (PhysicsPlugin, CharacterPlugin, BehaviourPlugin)


def make_app(scene: Callable[..., None], **kwargs: Any) -> App:
    return App(scene, headless=True, plugins=[p() for p in PLUGINS], **kwargs)


@pytest.fixture
def app_of():
    made: list[App] = []

    def build(scene: Callable[..., None], **kwargs: Any) -> App:
        app = make_app(scene, **kwargs)
        made.append(app)
        return app

    yield build
    for app in made:
        app.close()


def ground(world: World, y: float = 0.0, half_width: float = 50.0, angle: float = 0.0) -> int:
    """A static box whose top face passes through (0, y) (rotated about that point)."""
    c, s = math.cos(angle), math.sin(angle)
    return world.spawn(Transform(0.5 * s, y - 0.5 * c, angle), Collider(Box(half_width, 0.5)))


def gap_to(world: World, character: int, collider: int) -> float:
    """The separation between a character's shape and a collider, measured by Box2D's
    GJK (kge.collision) on the cores minus both radii (the collider's skin included):
    negative when they overlap."""
    body = world.get(character, CharacterBody)
    t = world.get(character, Transform)
    col = world.get(collider, Collider)
    ct = world.get(collider, Transform)
    core, radius = character_core(body.shape)
    if len(core) == 1:
        shape: Any = Circle(0.1, (float(core[0][0]), float(core[0][1])))
    elif len(core) == 2:
        shape = Edge(tuple(core[0].tolist()), tuple(core[1].tolist()))
    else:
        shape = body.shape
    other = (ct.x, ct.y, ct.angle)
    out = collision.distance(shape, (t.x, t.y, 0.0), col.shape, other, use_radii=False)
    skin = collision.geometry.convex(col.shape).radius
    return out.distance - radius - skin
