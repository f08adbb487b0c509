"""Shared machinery of the joint compositions.

Each Box2D joint becomes a handful of pymunk constraints plus, where pymunk has
no equivalent, a custom velocity step. :class:`Composite` holds what they share:

* resolving world anchors and reference angles from the bodies' poses when the
  joint is built (Box2D's ``Initialize`` helpers), and writing the resolved local
  values back into the component so a rebuild never re-resolves them;
* ``collide_bodies = collide_connected`` on every constraint (pymunk's default is
  True, Box2D's False);
* staying inert, with no constraint at all, when neither body is dynamic or both
  ends are one body: pymunk refuses such constraints (and suspending the
  constraints when a body's type later makes both non-dynamic);
* ``self.constraints`` listing exactly the switched-on constraints (a disabled
  limit is kept aside), which is what the physics system puts in the space;
* custom velocity steps (:mod:`~kge.physics.joints.rows`: motors, limits,
  pulley, gear, rope, weld lock, mouse) that run from the ``pre_solve`` of a
  zero-force "carrier" spring, so they run once per substep inside
  ``space.step``, after positions and before gravity is integrated;
* a position pass after the step (:mod:`~kge.physics.joints.positions`);
* converting impulses to forces with the step that produced them
  (``space.current_time_step``, which is the substep when physics substeps);
* a reaction force *vector*: pymunk reports only impulse magnitudes, so the
  direction comes from the joint's geometry where it is known (rods, ropes,
  springs) and otherwise from body B's momentum balance over the step.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import pymunk

from kge.components.tracked import raw_set
from kge.physics.cp import body_handle, constraint_handle, lib, space_handle
from kge.physics.joint_api import JointContext, JointHandle, in_space
from kge.physics.joints.mechanics import is_dynamic
from kge.physics.joints.positions import MAX_ANGULAR_CORRECTION, MAX_CORRECTION

#: pymunk constraints acting on rotation only: with both bodies unable to rotate
#: (infinite moments: static ground plus a fixed-rotation or massless body) their
#: effective mass is 1/0 and Chipmunk turns the bodies' velocities into NaN.
ANGULAR = (
    pymunk.GearJoint,
    pymunk.RotaryLimitJoint,
    pymunk.DampedRotarySpring,
    pymunk.SimpleMotor,
    pymunk.RatchetJoint,
)

Vec2 = tuple[float, float]

_get_velocity = lib.cpBodyGetVelocity
_get_angular_velocity = lib.cpBodyGetAngularVelocity
_get_mass = lib.cpBodyGetMass
_get_moment = lib.cpBodyGetMoment
_get_gravity = lib.cpSpaceGetGravity
_get_step = lib.cpSpaceGetCurrentTimeStep
_get_impulse = lib.cpConstraintGetImpulse

#: fraction of a hard constraint's position error removed per 1/60 s step by
#: pymunk's velocity bias (pymunk's default), for constraints with no position pass.
RIGID_CORRECTION = 0.1
#: the same as pymunk's ``error_bias`` (error left after one second)
RIGID_ERROR_BIAS = (1.0 - RIGID_CORRECTION) ** 60.0
#: ``error_bias`` of rods and pivots: no velocity bias at all. Their drift is
#: removed by a position pass after the step instead (:meth:`Composite.project`,
#: Box2D's position solver), which moves the bodies without touching velocities.
#: Velocity bias turns position error into kinetic energy: a 30-plank bridge
#: pinned taut at both ends (Box2D's testbed) gained 5 kJ and threw planks about
#: at 10 m/s with it; without it, it loses energy and settles into a sag.
PROJECTED_ERROR_BIAS = 1.0


def correction_speed(constraint: pymunk.Constraint, dt: float) -> float:
    """``max_bias`` for a hard pymunk constraint: Box2D's correction limit per step.

    pymunk corrects a constraint's position error with a velocity bias that the
    bodies keep, proportional to the error and unbounded by default. A joint
    built or driven far from its pose (anchors metres apart, a body teleported
    away) then launches its bodies at hundreds of m/s, and a few steps of that
    put them 10^7 m away. Box2D's position solver moves a joint by at most
    ``b2_maxLinearCorrection`` (0.2 m) or ``b2_maxAngularCorrection`` (8°) per
    step; as a speed over the step that is the cap here (12 m/s, 8.4 rad/s at
    60 Hz). Everyday drift never reaches it: pymunk's bias is about 6 m/s per
    metre of error.
    """
    limit = MAX_ANGULAR_CORRECTION if isinstance(constraint, ANGULAR) else MAX_CORRECTION
    return limit / dt


#: the largest ω·h a pymunk spring is given. pymunk applies a spring's force
#: explicitly once per step (symplectic Euler), which diverges once ω·h exceeds 2:
#: a 100 Hz distance joint to the ground turned its body into NaN within two seconds.
#: Box2D's soft constraints are implicit and stable at any frequency; here a
#: frequency above 1/(2π·h) (38 Hz at kge's 1/240 s substeps) acts as that.
MAX_SPRING_OMEGA_H = 1.0


#: a position pass that finds more than this fraction of its per-step limit to
#: correct marks the joint ``jolted`` (see JointBridge.forget_impulses)
JOLT = 0.5


def can_join(a: pymunk.Body, b: pymunk.Body) -> bool:
    """Whether pymunk accepts a constraint between ``a`` and ``b``.

    pymunk asserts (a bare ``AssertionError`` from ``Constraint._set_bodies``)
    that the two bodies differ and that one of them is dynamic. kge refuses a
    joint of a body to itself at spawn, but a later write of ``body_a`` /
    ``body_b`` (or a gear whose joints end on one body) can still make them one;
    such a joint, like one between two non-dynamic bodies, stays inert.
    """
    return a is not b and (is_dynamic(a) or is_dynamic(b))


def body_of(ctx: JointContext, entity: int | None) -> pymunk.Body:
    """The pymunk body of ``entity``; None is the world's static ground."""
    return ctx.space.static_body if entity is None else ctx.body(entity)

class Composite(JointHandle):
    """Base of every joint handle in this package."""

    def __init__(self, ctx: JointContext, entity: int, component: Any) -> None:
        self.ctx = ctx
        self.space = ctx.space
        self.entity = entity
        self.component = component
        self.body_a = component.body_a if component.body_a is not None else -1
        self.body_b = component.body_b if component.body_b is not None else -1
        self.a = body_of(ctx, component.body_a)
        self.b = body_of(ctx, component.body_b)
        self.constraints: list[pymunk.Constraint] = []
        #: every constraint this joint owns, switched on or not
        self.parts: list[pymunk.Constraint] = []
        #: the switched-on constraints while neither body is dynamic (see before_step)
        self.suspended: list[pymunk.Constraint] | None = None
        #: angular constraints switched off while neither body can rotate
        self.rotation_off: list[pymunk.Constraint] = []
        self.collide = bool(component.collide_connected)
        #: False when neither body is dynamic, or both ends are one body: the joint
        #: exists but does nothing (see can_join)
        self.active = can_join(self.a, self.b)
        self._force = 0.0  # |reaction force| of the last step, N
        self._torque = 0.0  # |reaction torque| of the last step, N·m
        self._momentum: tuple[float, float, float] | None = None
        self._pre: list[Callable[[float], None]] = []
        self._carrier: pymunk.Constraint | None = None
        #: constraints to the world (not between A and B) keep their own collide flag
        self.own_collide: set[pymunk.Constraint] = set()
        #: the last position pass found the joint far off (see JOLT)
        self.jolted = False
        #: the context's structure epoch when before_step last checked body types
        #: and rotation (None: check again; see before_step)
        self._epoch: Any = None

    # -- building ----------------------------------------------------------------------
    def add(
        self,
        *constraints: pymunk.Constraint,
        enabled: bool = True,
        error_bias: float = RIGID_ERROR_BIAS,
        capped: bool = True,
    ) -> None:
        """Own ``constraints``; switch them on now unless ``enabled`` is False.

        ``self.constraints`` lists exactly the switched-on ones: the physics system
        keeps those in the space while both bodies are (a disabled body takes them
        out), so a switched-off limit or motor must not be listed there.

        ``capped``: bound the velocity pymunk may add to correct a position error
        (:func:`correction_speed`); a joint whose correction is its purpose (the
        motor joint, bounded by its force) passes False.
        """
        for c in constraints:
            c.collide_bodies = self.collide
            c.error_bias = error_bias
            if capped and math.isinf(c.max_bias):
                c.max_bias = correction_speed(c, self.ctx.dt)
            self.parts.append(c)
            if enabled:
                self.enable(c, True)

    def enable(self, constraint: pymunk.Constraint, on: bool) -> None:
        """Switch one owned constraint on or off (a limit, motor or spring)."""
        if not on and constraint in self.rotation_off:  # the joint itself turns it off
            self.rotation_off.remove(constraint)
        if self.suspended is not None:  # remembered for when a body is dynamic again
            if on and constraint not in self.suspended:
                self.suspended.append(constraint)
            elif not on and constraint in self.suspended:
                self.suspended.remove(constraint)
            return
        listed = constraint in self.constraints
        present = in_space(self.space, constraint)
        if on and not listed:
            self.constraints.append(constraint)
            bodies_in = constraint.a.space is self.space and constraint.b.space is self.space
            if not present and bodies_in:
                self.space.add(constraint)
        elif not on and listed:
            self.constraints.remove(constraint)
            if present:
                self.space.remove(constraint)

    def is_on(self, constraint: pymunk.Constraint | None) -> bool:
        return constraint is not None and constraint in self.constraints

    def every_substep(self, fn: Callable[[float], None]) -> None:
        """Run ``fn(h)`` inside every (sub)step, after positions, before gravity."""
        if self._carrier is None:
            carrier = pymunk.DampedSpring(self.a, self.b, (0, 0), (0, 0), 0.0, 0.0, 0.0)
            carrier.pre_solve = self._run_pre
            self.add(carrier)
            self._carrier = carrier
        self._pre.append(fn)

    def run_substeps(self, on: bool) -> None:
        """Switch the custom steps off while they have nothing to do (saves a Python
        call per substep for, say, each plain hinge of a 100-plank bridge)."""
        if self._carrier is not None:
            self.enable(self._carrier, on)

    def _run_pre(self, constraint: pymunk.Constraint, space: pymunk.Space) -> None:
        h = space.current_time_step
        if h > 0:
            try:
                for fn in self._pre:
                    fn(h)
            except Exception as exc:  # pymunk called this from C: raised after the step
                self.ctx.errors.keep(exc)

    def local_anchors(self, component: Any, world_field: str = "anchor") -> None:
        """Resolve a world ``anchor`` into both local anchors (and forget the world one)."""
        anchor = getattr(component, world_field)
        if anchor is not None:
            raw_set(component, "local_anchor_a", tuple(self.a.world_to_local(anchor)))
            raw_set(component, "local_anchor_b", tuple(self.b.world_to_local(anchor)))
            raw_set(component, world_field, None)

    def split_anchors(self, component: Any) -> None:
        """Resolve ``anchor_a`` / ``anchor_b`` world points into the local anchors."""
        for side, body in (("a", self.a), ("b", self.b)):
            world = getattr(component, f"anchor_{side}")
            if world is not None:
                raw_set(component, f"local_anchor_{side}", tuple(body.world_to_local(world)))
                raw_set(component, f"anchor_{side}", None)

    def reference_angle(self, component: Any) -> float:
        if component.reference_angle is None:
            raw_set(component, "reference_angle", float(self.b.angle - self.a.angle))
        return float(component.reference_angle)

    def spring_omega(self, frequency_hz: float) -> float:
        """ω = 2π·frequency_hz for a pymunk spring, capped where it stays stable."""
        return min(2.0 * math.pi * frequency_hz, MAX_SPRING_OMEGA_H / self.ctx.substep)

    def world_anchors(self, la: Vec2, lb: Vec2) -> tuple[pymunk.Vec2d, pymunk.Vec2d]:
        return self.a.local_to_world(la), self.b.local_to_world(lb)

    # -- per step ------------------------------------------------------------------------
    def can_act(self) -> bool:
        """Whether the joint can have constraints now (see :func:`can_join`)."""
        return can_join(self.a, self.b)

    def before_step(self, dt: float) -> None:
        """Suspend or resume with the bodies' types; remember B's momentum.

        Body types and moments change only through the physics system, which
        counts such changes (``ctx.epoch``: type changes, mass updates); the
        checks below run again only when that count moved or this joint was
        changed (``apply``). A context without the count checks every step.
        """
        epoch = getattr(self.ctx, "epoch", None)
        if epoch is None or epoch != self._epoch:
            if not self.active and not self.parts and self.can_act():
                # built while neither body was dynamic (pymunk refuses such
                # constraints): one is now, so build for real
                type(self).__init__(self, self.ctx, self.entity, self.component)
                if self.active:
                    self.apply(self.component)
            self.track_body_types()
            self.track_rotation()
            self._epoch = epoch
        self.before_step_momentum()

    def track_rotation(self) -> None:
        """Keep rotation-only constraints out while neither body can rotate.

        Box2D gives such a constraint a zero effective mass and skips it (a prismatic
        joint between the ground and a fixed-rotation body simply has nothing to
        lock); pymunk would divide by zero. They come back when a body can rotate.
        """
        if self.suspended is not None:
            return
        if math.isinf(self.a.moment) and math.isinf(self.b.moment):
            for rot in [c for c in self.constraints if isinstance(c, ANGULAR)]:
                self.enable(rot, False)
                self.rotation_off.append(rot)
        elif self.rotation_off:
            back, self.rotation_off = self.rotation_off, []
            for c in back:
                self.enable(c, True)

    def before_step_momentum(self) -> None:
        """Remember body B's momentum (for the reaction direction)."""
        body = self.b if is_dynamic(self.b) else self.a
        if is_dynamic(body):
            cb = body_handle(body)
            v = _get_velocity(cb)
            self._momentum = (v.x, v.y, _get_angular_velocity(cb))
        else:
            self._momentum = None

    def track_body_types(self) -> None:
        """Take the constraints out while neither body is dynamic, put them back after.

        A body's type can change at run time (a platform frozen to static). pymunk
        has no rule for a constraint between two non-dynamic bodies: solving one
        divides by a zero mass and the NaN spreads to the bodies once they move
        again. Box2D simply does nothing for such a joint, and so does kge.
        """
        if not self.parts:
            return
        live = is_dynamic(self.a) or is_dynamic(self.b)
        if not live and self.suspended is None:
            on = list(self.constraints)
            for c in on:
                self.enable(c, False)
            self.suspended = on
        elif live and self.suspended is not None:
            on, self.suspended = self.suspended, None
            for c in on:
                self.enable(c, True)

    def balance(self, dt: float) -> tuple[float, float, float]:
        """Impulse (x, y, angular) body B received over the step beyond gravity.

        An estimate of what all its constraints and contacts applied; used only for
        the sign or direction of reactions whose size pymunk gives exactly.
        """
        if self._momentum is None or dt <= 0:
            return 0.0, 0.0, 0.0
        body, sign = (self.b, 1.0) if is_dynamic(self.b) else (self.a, -1.0)
        vx0, vy0, w0 = self._momentum
        g = _get_gravity(space_handle(self.space))
        cb = body_handle(body)
        m, i = _get_mass(cb), _get_moment(cb)
        v = _get_velocity(cb)
        jx = m * (v.x - vx0 - g.x * dt)
        jy = m * (v.y - vy0 - g.y * dt)
        jw = i * (_get_angular_velocity(cb) - w0) if math.isfinite(i) else 0.0
        return sign * jx, sign * jy, sign * jw

    def step_time(self) -> float:
        """The (sub)step that produced the constraints' current impulses."""
        h = _get_step(space_handle(self.space))
        return float(h) if h > 0 else 1.0 / 60.0

    def impulse_force(self, constraint: pymunk.Constraint | None) -> float:
        """Force or torque magnitude a constraint applied in the last (sub)step."""
        if constraint is None or not in_space(self.space, constraint):
            return 0.0  # switched off, or out of the space with a disabled body
        return float(_get_impulse(constraint_handle(constraint))) / self.step_time()

    def write_reaction(
        self,
        component: Any,
        dt: float,
        force: float,
        torque: float,
        direction: Vec2 | None = None,
    ) -> None:
        """Store reaction magnitudes and write the vector / signed torque.

        ``direction``: the unit line of action when the geometry fixes it (its sign
        is then taken from the balance); otherwise the balance gives the direction.
        """
        self._force, self._torque = force, torque
        bx, by, bw = self.balance(dt)
        if direction is not None:
            ux, uy = direction
            s = -1.0 if bx * ux + by * uy < 0 else 1.0
            fx, fy = s * force * ux, s * force * uy
        else:
            n = math.hypot(bx, by)
            fx, fy = (force * bx / n, force * by / n) if n > 1e-12 else (0.0, 0.0)
        raw_set(component, "reaction_force", (fx, fy))
        raw_set(component, "reaction_torque", math.copysign(torque, bw) if bw else torque)

    def exceeds_break_limits(self, component: Any) -> bool:
        bf, bt = component.break_force, component.break_torque
        return (bf is not None and self._force > bf) or (bt is not None and self._torque > bt)

    def read_back(self, component: Any, dt: float) -> None:
        if not self.active or self.suspended is not None:
            raw_set(component, "reaction_force", (0.0, 0.0))
            raw_set(component, "reaction_torque", 0.0)
            self._force = self._torque = 0.0
            return
        self.project()
        self.read_live(component, dt)

    def project(self) -> bool | None:
        """Position pass after the step (none by default).

        A joint that knows Box2D's criterion returns whether it was within the
        slops (b2_linearSlop, b2_angularSlop); None means "no opinion" (see
        ``JointBridge.position_iterations`` and :mod:`kge.physics.joints.settle`).
        """
        return None

    def jolt(self, error: float, limit: float) -> None:
        """Note the error a position pass found; far beyond ``limit`` it marks a jolt."""
        if error > JOLT * limit:
            self.jolted = True

    def forget_impulses(self) -> list[pymunk.Constraint]:
        """This joint's pymunk constraints that must start the next step from zero
        impulse (:class:`Drain`); a carrier's own solver keeps its state."""
        self.jolted = False
        return [c for c in self.constraints if c is not self._carrier]

    def read_live(self, component: Any, dt: float) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def apply(self, component: Any) -> None:
        self.component = component
        self._epoch = None  # constraints may have been switched: check again
        # a world anchor assigned after the build is resolved against the poses now
        if getattr(component, "anchor", None) is not None:
            self.local_anchors(component)
        if getattr(component, "anchor_a", None) is not None or getattr(
            component, "anchor_b", None
        ) is not None:
            self.split_anchors(component)
        if self.active:
            self.collide = bool(component.collide_connected)
            for c in self.parts:
                if c not in self.own_collide:
                    c.collide_bodies = self.collide
            self.configure(component)
            self.wake()

    def wake(self) -> None:
        """Wake the bodies after a change, as Box2D's joint setters do (a new motor
        speed or mouse target must move a body that fell asleep)."""
        for body in (self.a, self.b):
            if is_dynamic(body) and body.space is self.space and body.is_sleeping:
                body.activate()

    def configure(self, component: Any) -> None:  # pragma: no cover - abstract
        raise NotImplementedError
