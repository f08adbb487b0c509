"""kge's data about pymunk objects lives in kge's own tables, never on the objects.

The shape table (:mod:`kge.physics.shape_table`) holds what kge knows about each
shape and the body records (:class:`kge.physics.bodies.BodyRecord`) what it knows
about each body. A ``kge_*`` attribute hung on a pymunk Shape or Body would be a
second home for that data, pickled and copied with pymunk's objects and invisible
to the tables' bulk reads. Checked twice: in the source (no code writes one) and
in a running world that uses every physics feature with per-shape or per-body
state (chains, one-way platforms, sensors, filters, hooks, hit thresholds,
bullets, damping and gravity scale, sleeping, joints).
"""

from __future__ import annotations

import re
from pathlib import Path

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.joints.revolute import RevoluteJoint
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Chain, Circle
from kge.components.transform import Transform
from kge.physics.resource import Physics
from kge.schedule import Stage
from kge.systems.physics import PhysicsSystem
from kge.world import World

KGE = Path(__file__).resolve().parents[2] / "kge"
#: the packages that hold pymunk objects
PYMUNK_USERS = (KGE / "physics", KGE / "box2d", KGE / "collision")

#: a kge_* attribute written, set or read with a default on some object
WRITE = re.compile(
    r"""vars\([^)]*\)\s*(?:\[\s*["']kge_|\.update\([^)]*\bkge_)"""
    r"""|\.__dict__\s*\[\s*["']kge_"""
    r"""|(?:set|get)attr\([^,]+,\s*["']kge_"""
    r"""|\.kge_\w+\s*=(?!=)"""
)


def kge_attribute_writes(roots: tuple[Path, ...] = PYMUNK_USERS) -> list[str]:
    """``path:line: text`` for every line under ``roots`` that hangs a kge_* attribute."""
    found = []
    for root in roots:
        for path in sorted(root.rglob("*.py")):
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                if WRITE.search(line):
                    found.append(f"{path.relative_to(KGE.parent)}:{number}: {line.strip()}")
    return found


def test_no_code_hangs_kge_attributes_on_objects() -> None:
    assert kge_attribute_writes() == []


def test_the_pattern_catches_each_way_of_writing_one() -> None:
    for line in (
        'vars(shape)["kge_child"] = 0',
        "vars(body).update(kge_bullet=False)",
        "shape.kge_filter = collider.filter",
        'getattr(body, "kge_entity", None)',
        'setattr(s, "kge_oneway", spec)',
        'd.__dict__["kge_hit"] = 1.0',
    ):
        assert WRITE.search(line), line
    for line in ("if a.kge_rank == b.kge_rank:", "table.collider[i] = e"):
        assert not WRITE.search(line), line


def _busy_world() -> World:
    world = World()
    world.add_system(PhysicsSystem())
    ground = world.spawn(Transform(0.0, 0.0),
                         Collider(Chain([(-20.0, 0.0), (0.0, -1.0), (20.0, 0.0)])))
    world.spawn(Transform(0.0, 3.0), Collider(Box(3.0, 0.1)), OneWayPlatform())
    world.spawn(Transform(5.0, 1.0), Collider(Box(1.0, 1.0), sensor=True))
    for i in range(12):
        world.spawn(
            Transform(-6.0 + i, 2.0 + 0.3 * i),
            RigidBody(linear_damping=0.5, gravity_scale=0.8, bullet=i % 4 == 0),
            Collider(Circle(0.3) if i % 2 else Box(0.3, 0.3), restitution=0.3,
                     hit_threshold=0.5, contact_hooks=i % 3 == 0,
                     filter=Filter(group_index=1 + i % 2)),
        )
    a = world.spawn(Transform(8.0, 5.0), RigidBody(), Collider(Box(0.4, 0.4)))
    b = world.spawn(Transform(9.0, 5.0), RigidBody(), Collider(Circle(0.4)))
    world.spawn(RevoluteJoint(body_a=a, body_b=b, anchor=(8.5, 5.0)))
    physics = world.resource(Physics)
    physics.on_pre_solve(lambda c: None)
    physics.on_post_solve(lambda c: None)
    physics.contact_filter = lambda ca, cb: ca != ground or cb > 0
    return world


def test_a_running_world_hangs_nothing_on_pymunk_objects() -> None:
    world = _busy_world()
    try:
        for _ in range(120):
            world.schedule.run(Stage.FIXED, 1.0 / 60.0)
        sim = world.resource(Physics)._sim
        space = sim.space
        objects = [space.static_body, *space.bodies, *space.shapes, *space.constraints]
        for rec in sim.bodies.values():
            objects += [rec.body, *rec.body.shapes]
        assert len(objects) > 30
        hung = sorted({f"{type(o).__name__}.{k}" for o in objects for k in vars(o)
                       if k.startswith("kge")})
        assert hung == []
    finally:
        world.close()
