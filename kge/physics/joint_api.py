"""The contract between the physics system and the joint implementations.

The physics system (``kge.systems.physics``) owns the pymunk Space and the map
from body entities to pymunk bodies. Joint modules (``kge.physics.joints``)
turn one joint component into a composition of pymunk constraints and, where
pymunk has no equivalent (pulley, general gear, linear motor), a custom solver
step. They meet here:

* a joint module calls :func:`register` for its component type with a builder;
* the physics system calls the builder once the joint's bodies exist, then every
  step calls :meth:`JointHandle.apply` when the component changed,
  :meth:`JointHandle.before_step` before ``space.step``, and
  :meth:`JointHandle.read_back` after it; it removes the handle (and emits a
  joint-destroyed event) when either body goes away, and a joint-broken event
  when :meth:`JointHandle.exceeds_break_limits` says so.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import Any, Protocol

import pymunk

from kge.physics.callback_errors import CallbackErrors
from kge.physics.cp import constraint_handle, lib, space_handle

Vec2 = tuple[float, float]

_contains = lib.cpSpaceContainsConstraint


def in_space(space: pymunk.Space, constraint: pymunk.Constraint) -> bool:
    """Whether ``constraint`` is in ``space``, in constant time (``c in
    space.constraints`` copies the space's whole constraint list first)."""
    return bool(_contains(space_handle(space), constraint_handle(constraint)))


class JointContext(Protocol):
    """What a builder may ask of the physics system."""

    space: pymunk.Space
    dt: float  # the fixed step (1/60 by default), for impulse -> force conversions
    #: where an exception raised by a joint's own solver (run from pymunk's
    #: ``pre_solve``, inside the step) is kept until the step is over
    errors: CallbackErrors

    @property
    def substep(self) -> float:
        """The length of one pymunk step (``dt / substeps``): springs' stability limit."""
        ...

    @property
    def iterated_hinges(self) -> bool:
        """``PhysicsSettings.iterated_hinges``: motors solved in pymunk's iterations."""
        ...

    @property
    def hinge_limit_push(self) -> float:
        """``PhysicsSettings.hinge_limit_push``: an iterated limit's push-back speed."""
        ...

    def body(self, entity: int) -> pymunk.Body:
        """The pymunk body of a body entity (a static placeholder for static ones)."""
        ...

    def joint(self, entity: int) -> JointHandle | None:
        """The live handle of another joint entity (gear joints couple two joints)."""
        ...


class JointHandle(ABC):
    """One live joint: its pymunk constraints plus any custom solver state."""

    entity: int
    body_a: int
    body_b: int
    constraints: list[pymunk.Constraint]
    #: other joint entities this one depends on (a gear on its two joints): when one
    #: of them is destroyed, this joint is destroyed first.
    depends_on: tuple[int, ...] = ()
    #: ``body_a``, ``body_b`` and ``depends_on`` stay as built. The bridge indexes
    #: joints by them (a despawned body finds its joints without a pass over all);
    #: a handle that changes them later (a gear, which takes its joints' bodies
    #: once they exist) sets this False and is looked at by every such query.
    fixed_ends: bool = True
    #: its last position pass moved its bodies a long way (set by the handle)
    jolted: bool = False

    @abstractmethod
    def apply(self, component: Any) -> None:
        """Push the component's current settings (motor speed, limits, target...)."""

    def before_step(self, dt: float) -> None:  # noqa: B027 - optional hook
        """Run custom solver work before ``space.step`` (pulley, gear, linear motor)."""

    @abstractmethod
    def read_back(self, component: Any, dt: float) -> None:
        """Write live state (angle, speed, translation, reaction_force...) into the component."""

    def exceeds_break_limits(self, component: Any) -> bool:
        """True when the last step's reaction exceeded break_force / break_torque."""
        bf = getattr(component, "break_force", None)
        bt = getattr(component, "break_torque", None)
        if bf is not None:
            fx, fy = getattr(component, "reaction_force", (0.0, 0.0))
            if (fx * fx + fy * fy) ** 0.5 > bf:
                return True
        return bt is not None and abs(getattr(component, "reaction_torque", 0.0)) > bt

    def forget_impulses(self) -> list[pymunk.Constraint]:
        """Start the next step with no warm-start impulse (after a big position jump):
        the pymunk constraints the physics must drain (see ``JointBridge.drain``)."""
        self.jolted = False
        return []

    def remove(self, space: pymunk.Space) -> None:
        """Take every constraint of this joint out of ``space``."""
        for c in self.constraints:
            if in_space(space, c):
                space.remove(c)
        self.constraints = []


Builder = Callable[[JointContext, int, Any], JointHandle]

#: joint component type -> builder
BUILDERS: dict[type, Builder] = {}


def register(component_type: type, builder: Builder) -> None:
    """Declare how to build ``component_type`` joints."""
    BUILDERS[component_type] = builder


def joint_types() -> tuple[type, ...]:
    return tuple(BUILDERS)
