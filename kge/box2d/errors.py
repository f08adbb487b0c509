"""The exceptions kge.box2d raises: kge's errors that are also what pybox2d raises.

pybox2d reports a failed Box2D assertion (a polygon without area, a joint on
one body, a change to a locked world) as ``AssertionError``, and a missing or
malformed argument (no shape, no bodies, a vertex that is not a pair) as
``ValueError``. Programs catch those (pybox2d's own testbed does), so each
error here is both: a kge error (``except KgeError`` keeps working) and the
built-in type pybox2d raises at the same call.

>>> issubclass(b2AssertException, AssertionError), issubclass(b2AssertException, ValueError)
(True, True)
"""

from __future__ import annotations

from kge.errors import ComponentTypeError, ValidationError, WorldLockedError


class b2AssertException(ValidationError, AssertionError):
    """A Box2D assertion failed (pybox2d raises ``AssertionError``): the value is refused."""


class LockedError(WorldLockedError, AssertionError):
    """The world is locked (inside ``Step`` or a callback): Box2D's ``IsLocked()`` assertion."""


class MissingError(ComponentTypeError, ValueError):
    """A required argument is missing or not of its kind (pybox2d raises ``ValueError``)."""


class KeywordError(ComponentTypeError, AttributeError):
    """A definition was given a keyword it does not have (pybox2d raises ``AttributeError``)."""
