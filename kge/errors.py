"""Every exception kge raises on purpose.

Why a hierarchy: callers catch ``kge.KgeError`` for "kge refused this", and the
subclasses keep the builtin type a Python user would guess (``ValueError`` for bad
values, ``KeyError`` for missing things, ``TypeError`` for wrong types). Messages
always name the entity, component and field when they are known, because the
call that made the mistake may be far from the step that would have exploded.
"""

from __future__ import annotations


class KgeError(Exception):
    """Base of every error kge raises deliberately."""


class ValidationError(KgeError, ValueError):
    """A value is out of its documented range (NaN, negative radius, 17 vertices...)."""


class ComponentTypeError(KgeError, TypeError):
    """Something that is not the expected type was passed (a class instead of an instance...)."""


class EntityNotFoundError(KgeError, KeyError):
    """The entity does not exist (never spawned, or already despawned)."""

    def __str__(self) -> str:  # KeyError quotes its argument; we want a sentence.
        return str(self.args[0]) if self.args else ""


class MissingComponentError(KgeError, KeyError):
    """The entity exists but has no component of the requested type."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


class MissingResourceError(KgeError, KeyError):
    """``world.resource(T)`` was asked for a resource nobody inserted."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


class WorldLockedError(KgeError, RuntimeError):
    """A structural change was attempted inside a physics callback (Box2D's locked world)."""


class HookSignatureError(KgeError, TypeError):
    """A Behaviour script defines a hook whose parameters do not match the contract."""


def where(entity: int | None, component: str, field: str | None = None) -> str:
    """Format the "entity 7, Collider.density" prefix used by every validation message."""
    target = component if field is None else f"{component}.{field}"
    return target if entity is None else f"entity {entity}, {target}"


class DisplayError(KgeError, RuntimeError):
    """A window was asked for and the display cannot give one (a stale ``DISPLAY``...)."""


class SceneStackError(KgeError, RuntimeError):
    """A scene-stack change that cannot be made (popping the App's last scene)."""


class ScheduleError(KgeError, ValueError):
    """A system's place in the frame is impossible: an unknown set, an anchor in another
    stage, or ``before`` / ``after`` constraints that form a cycle."""
