"""``PhysicsSystem``: runs the world's physics step; ``PhysicsEventDelivery`` hands out events.

Adding ``PhysicsSystem`` to a world (every App scene gets one) inserts three
resources: :class:`~kge.physics.settings.PhysicsSettings` (unless the scene
brings its own), :class:`~kge.physics.resource.Physics` and
:class:`~kge.physics.events.PhysicsEvents`. It registers world hooks so that
adding or removing a RigidBody, Collider, Transform, OneWayPlatform or joint is
mirrored at the next step, and validators so that a collider naming a body
that does not exist, or a joint of a body to itself, is refused by the
``spawn`` / ``add`` that made it, with the world unchanged.

Frame order (:mod:`kge.schedule`): FIXED stage, ``SCRIPTS`` (behaviours) ->
``PHYSICS`` (sync-in, step, sync-out, events recorded) -> flush ->
``PHYSICS_EVENTS`` (the step's events reach ``world.events`` and Behaviour hooks)
-> flush.
"""

from __future__ import annotations

from typing import Any

from kge.components.collider import Collider
from kge.components.joints import GearJoint, PrismaticJoint, RevoluteJoint
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import RigidBody
from kge.components.shapes import SHAPE_TYPES
from kge.components.transform import Transform
from kge.errors import ValidationError
from kge.physics import joint_api
from kge.physics.events import (
    ContactBegin,
    ContactEnd,
    Hit,
    JointBroken,
    JointDestroyed,
    PhysicsEvents,
    SensorBegin,
    SensorEnd,
)
from kge.physics.joint_bridge import body_fields, load_joint_modules
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.physics.simulation import Simulation
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.world import World, deprecate_handler, deprecate_resource, stored_resource

#: the event type of each PhysicsEvents list (``world.events(ContactBegin)``...)
EVENT_TYPES: dict[str, type] = {
    "contact_begin": ContactBegin,
    "contact_end": ContactEnd,
    "sensor_begin": SensorBegin,
    "sensor_end": SensorEnd,
    "hits": Hit,
    "joint_broken": JointBroken,
    "joint_destroyed": JointDestroyed,
}
deprecate_resource(
    PhysicsEvents,
    "read world.events(ContactBegin) (or ContactEnd, SensorBegin, SensorEnd, Hit, "
    "JointBroken, JointDestroyed), or the Behaviour hooks (on_contact_begin...)",
)
for _name, _type in EVENT_TYPES.items():
    deprecate_handler(_name, f"read world.events({_type.__name__}) or use the Behaviour hooks")


def _where(entity: int | None, what: str) -> str:
    return what if entity is None else f"entity {entity}, {what}"


class PhysicsSystem(System):
    """Owns the world's :class:`~kge.physics.simulation.Simulation` and steps it."""

    stage = Stage.FIXED
    in_set = SystemSet.PHYSICS
    sim: Simulation
    physics: Physics
    #: the last step raised (a user hook failed) before its events were delivered
    _undelivered = False

    def attach(self, world: World) -> None:
        super().attach(world)
        if not world.has_resource(PhysicsSettings):
            world.insert_resource(PhysicsSettings())
        events = stored_resource(world, PhysicsEvents)
        if events is None:
            events = world.insert_resource(PhysicsEvents())
        dt = 1.0 / 60.0
        time = _fixed_dt(world)
        if time is not None:
            dt = time
        self.sim = sim = Simulation(world, lambda: world.resource(PhysicsSettings), events, dt)
        self.events = events
        self.physics = world.insert_resource(Physics(world, sim))
        world.on_add(RigidBody, sim.on_rigidbody_added)
        world.on_remove(RigidBody, sim.on_rigidbody_removed)
        world.on_add(Collider, sim.on_collider_added)
        world.on_remove(Collider, sim.on_collider_removed)
        world.on_add(Transform, sim.on_transform_added)
        world.on_remove(Transform, sim.on_transform_removed)
        world.on_add(OneWayPlatform, sim.on_platform_changed)
        world.on_remove(OneWayPlatform, sim.on_platform_changed)
        world.validator(Collider, self._check_collider)
        load_joint_modules()
        for jtype in joint_api.joint_types():
            world.on_add(jtype, sim.joints.added)
            world.on_remove(jtype, sim.joints.removed_hook)
            world.validator(jtype, self._check_joint)
        if world.get_system(PhysicsEventDelivery) is None:
            world.add_system(PhysicsEventDelivery())

    # -- validators (run before spawn/add changes anything) ----------------------------------
    def _check_collider(self, entity: int | None, col: Collider) -> None:
        b = col.body
        if b is None:
            return
        world = self.world
        if not world.exists(b):
            raise ValidationError(
                f"{_where(entity, 'Collider.body')}: body entity {b} does not exist"
            )
        if world.try_get(b, RigidBody) is None:
            raise ValidationError(
                f"{_where(entity, 'Collider.body')}: entity {b} has no RigidBody "
                "(give it one, or leave body=None for a static collider)"
            )

    def _check_joint(self, entity: int | None, joint: Any) -> None:
        name = type(joint).__name__
        a, b = body_fields(joint)
        world = self.world
        for field, ref in (("body_a", a), ("body_b", b)):
            if ref is None:
                continue
            if isinstance(ref, bool) or not isinstance(ref, int):
                raise ValidationError(
                    f"{_where(entity, f'{name}.{field}')} must be an entity id, got {ref!r}"
                )
            if not world.exists(ref):
                raise ValidationError(
                    f"{_where(entity, f'{name}.{field}')}: body entity {ref} does not exist"
                )
            if world.try_get(ref, RigidBody) is None and world.try_get(ref, Collider) is None:
                raise ValidationError(
                    f"{_where(entity, f'{name}.{field}')}: entity {ref} has no RigidBody "
                    "or Collider, so there is no body to join"
                )
        if a is None and b is None and not isinstance(joint, GearJoint):
            raise ValidationError(
                f"{_where(entity, name)}: body_a and body_b are both None (the ground); "
                "a joint needs at least one body"
            )
        if a is not None and a == b:
            raise ValidationError(
                f"{_where(entity, name)}: body_a and body_b are both entity {a}; "
                "a joint needs two different bodies"
            )
        if isinstance(joint, GearJoint):
            self._check_gear(entity, joint)

    def _check_gear(self, entity: int | None, gear: GearJoint) -> None:
        """A gear must name two live revolute/prismatic joints (else every step would fail)
        that move two different bodies: a gear's bodies are its joints' ``body_b``, as
        in Box2D, which asserts that a joint's two bodies differ."""
        world = self.world
        moved: list[int | None] = []
        for field in ("joint_a", "joint_b"):
            ref = getattr(gear, field)
            if not world.exists(ref):
                raise ValidationError(
                    f"{_where(entity, f'GearJoint.{field}')}: joint entity {ref} does not exist"
                )
            joint = world.try_get(ref, RevoluteJoint) or world.try_get(ref, PrismaticJoint)
            if joint is None:
                held = ", ".join(type(c).__name__ for c in world.components(ref)) or "nothing"
                raise ValidationError(
                    f"{_where(entity, f'GearJoint.{field}')}: entity {ref} must hold a "
                    f"RevoluteJoint or PrismaticJoint (it holds {held})"
                )
            moved.append(joint.body_b)
        if moved[0] == moved[1]:
            body = "the ground (None)" if moved[0] is None else f"entity {moved[0]}"
            raise ValidationError(
                f"{_where(entity, 'GearJoint.joint_b')}: joints {gear.joint_a} and "
                f"{gear.joint_b} both move {body} (their body_b); a gear needs two "
                "different bodies"
            )

    # -- running -------------------------------------------------------------------------------
    def process(self, dt: float) -> None:
        sim = self.sim
        if dt != sim.dt:
            sim.dt = dt
            sim.joints.dt = dt
            sim.rb_dirty.update(e for e, r in sim.bodies.items() if not r.implicit)
        if self._undelivered:
            # the step that raised recorded real contacts; hooks and lists get them now,
            # with this step's, so every begin still reaches them before its end
            self._undelivered = False
        else:
            self.events.clear()
        self.physics._take_carried(self.events)  # ends recorded by syncs between steps
        self.world.flush()  # changes queued since the last flush take part in this step
        try:
            sim.step()
        except Exception:
            self._undelivered = True
            raise

    def detach(self) -> None:
        self.sim.close()


def _fixed_dt(world: World) -> float | None:
    from kge.scene import Time

    t = world.try_resource(Time)
    return None if t is None else t.fixed_dt


#: event list -> (which begin/end pair it belongs to, True for the begin side); hits
#: are begins without an end
_PAIRED = {
    "contact_begin": ("contact", True),
    "contact_end": ("contact", False),
    "sensor_begin": ("sensor", True),
    "sensor_end": ("sensor", False),
    "hits": (None, True),
}


class PhysicsEventDelivery(System):
    """Deliver the step's physics events: to ``world.events`` and the Behaviour hooks.

    Every list of the step's record goes to the world's events at once (readers
    see them from here until the same point of the next step, see :mod:`kge.events`).
    Then each contact event goes to the scripts of collider A, collider B and (if
    different) their body entities; a script is called at most once per event.
    The esper events named like the lists (``world.set_handler("contact_begin",
    fn)``) are still sent, deprecated, for one release.

    A begin (contact, sensor, hit) that names an entity despawned earlier in the
    same delivery (by a hook or handler reacting to an earlier event) is not sent
    to handlers and hooks: that contact is gone with the entity, as Box2D destroys
    a body's contacts. Its end, which the despawn brings at the next step, is held
    back from them too, so they still see every end after its begin. The step's
    record (``world.events``, the ``PhysicsEvents`` lists) keeps everything.
    """

    stage = Stage.FIXED
    in_set = SystemSet.PHYSICS_EVENTS

    #: (pair kind, collider_a, collider_b, child_a, child_b) of begins not delivered
    _withheld: set[tuple[str, int, int, int, int]]

    def attach(self, world: World) -> None:
        super().attach(world)
        self._withheld = set()

    def process(self, dt: float) -> None:
        world = self.world
        events = stored_resource(world, PhysicsEvents)
        if events is None or not len(events):
            return
        from kge.systems.behaviour import runner

        log = world.eventlog
        for name, _ in PhysicsEvents.CHANNELS:
            log.extend(EVENT_TYPES[name], getattr(events, name))
        run = runner(world)
        exists = world.exists
        withheld = self._withheld
        for name, hook in PhysicsEvents.CHANNELS:
            lst = getattr(events, name)
            if not lst:
                continue
            pair, begin = _PAIRED.get(name, (None, False))
            for ev in list(lst):
                if pair is not None or begin:
                    key = (pair or "", ev.collider_a, ev.collider_b, ev.child_a, ev.child_b)
                    if begin:
                        if not (
                            exists(ev.collider_a) and exists(ev.collider_b)
                            and (ev.body_a is None or exists(ev.body_a))
                            and (ev.body_b is None or exists(ev.body_b))
                        ):
                            if pair is not None:
                                withheld.add(key)
                            continue
                    elif withheld and key in withheld:
                        withheld.discard(key)
                        continue
                world.dispatch(name, ev)
                # no script anywhere (an env's scenes): no hook to look for; asked per
                # event, as a handler may have added a Behaviour meanwhile
                if hook is None or not run.scripted:
                    continue
                seen: list[int] = []
                for ent in (ev.collider_a, ev.collider_b, ev.body_a, ev.body_b):
                    if ent is not None and ent not in seen:
                        seen.append(ent)
                        run.call_one(ent, hook, ev)


class PhysicsPlugin(Plugin):
    """Box2D-style physics: :class:`PhysicsSystem` (FIXED stage) and, through it, the
    ``Physics`` and ``PhysicsSettings`` resources, and the contact and joint events
    (``world.events(ContactBegin)``, Behaviour hooks)."""

    def build(self, world: World) -> None:
        world.add_system(PhysicsSystem())
        for shape_type in SHAPE_TYPES:
            world.validator(shape_type, _shape_is_not_a_component)


def _shape_is_not_a_component(entity: int | None, shape: Any) -> None:
    """``world.spawn(Transform(), Circle(1))`` draws nothing and collides with nothing."""
    name = type(shape).__name__
    drawable = {"Box": "Rect", "Edge": "Line"}.get(name, name)
    drawable_hint = f" or, to draw one, kge.draw.{drawable}(...)" if name != "Chain" else ""
    raise ValidationError(
        f"{_where(entity, name)}: kge.{name} is a physics shape, not a component: "
        f"put it in a Collider (Collider({name}(...))){drawable_hint}"
    )
