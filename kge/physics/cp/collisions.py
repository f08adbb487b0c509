"""Chipmunk's wildcard ``begin`` and ``separate`` callbacks, called without pymunk's wrapper.

pymunk runs a collision callback through its own trampoline, which looks its
handler object up and builds a :class:`pymunk.Arbiter` for every call. kge's
wildcard handler runs once per new and per ended contact of the whole scene, so
:func:`route_contacts` points Chipmunk's handler at two cffi callbacks of this
module that hand the raw ``cpArbiter *`` to kge's functions: the arbiter is read
with the C functions of :data:`kge.physics.cp.lib`.

The two callbacks are made once and live as long as the process: Chipmunk may
call a space's ``separate`` while pymunk frees the space (its shapes are removed
first), when the space's route is gone; a call for a space without a route does
nothing. An exception raised by kge's function is kept in the route's
:class:`~kge.physics.callback_errors.CallbackErrors` (cffi cannot let it cross C).
A bound method is held weakly (its object, which holds the space, must not be kept
alive by this module: the route goes when the space goes); a plain function strongly.

>>> import pymunk
>>> space = pymunk.Space()
>>> seen = []
>>> route_contacts(space, lambda arb: seen.append("begin"), lambda arb: seen.append("end"),
...                None)
>>> body = pymunk.Body(1.0, 1.0)
>>> space.add(body, pymunk.Circle(body, 1.0), pymunk.Circle(space.static_body, 1.0))
>>> space.step(0.01)
>>> space.remove(*body.shapes)
>>> seen
['begin', 'end']
"""

from __future__ import annotations

import inspect
import weakref
from collections.abc import Callable
from typing import Any

import pymunk

from kge.physics.callback_errors import CallbackErrors
from kge.physics.cp.capi import ffi

#: kge's function for one arbiter (a ``cpArbiter *``)
ArbiterFn = Callable[[Any], None]

#: ``cpSpace *`` -> (begin, separate, where their exceptions go); the functions are
#: behind references (call one to get the function, or None once its object is gone)
_routes: dict[Any, tuple[Callable[[], ArbiterFn | None], Callable[[], ArbiterFn | None],
                         CallbackErrors]] = {}


def _noop(arb: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
    """pymunk's side of the handler (its functions are replaced by the callbacks below)."""


def _begin(arb: Any, space: Any, data: Any) -> None:
    route = _routes.get(space)
    if route is not None and (fn := route[0]()) is not None:
        try:
            fn(arb)
        except Exception as exc:
            route[2].keep(exc)


def _separate(arb: Any, space: Any, data: Any) -> None:
    route = _routes.get(space)
    if route is not None and (fn := route[1]()) is not None:
        try:
            fn(arb)
        except Exception as exc:
            route[2].keep(exc)


def _held(fn: ArbiterFn) -> Callable[[], ArbiterFn | None]:
    if inspect.ismethod(fn):
        return weakref.WeakMethod(fn)
    return lambda: fn


_SIGNATURE = "void(*)(struct cpArbiter *, struct cpSpace *, void *)"
_BEGIN = ffi.callback(_SIGNATURE, _begin)
_SEPARATE = ffi.callback(_SIGNATURE, _separate)


def route_contacts(
    space: pymunk.Space, begin: ArbiterFn, separate: ArbiterFn, errors: CallbackErrors | None
) -> None:
    """Call ``begin(arb)`` / ``separate(arb)`` with the ``cpArbiter *`` of every new and
    ended contact of ``space`` (its wildcard handler; a later call replaces them).

    Exceptions they raise go to ``errors`` (a fresh keeper when None).
    """
    space.on_collision(None, None, begin=_noop, separate=_noop)
    handler = space._handlers[(None, None)]._handler
    handler.beginFunc = _BEGIN
    handler.separateFunc = _SEPARATE
    key = space._space
    if key not in _routes:
        weakref.finalize(space, _routes.pop, key, None)
    _routes[key] = (
        _held(begin), _held(separate), errors if errors is not None else CallbackErrors()
    )
