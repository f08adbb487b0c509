"""``kge.box2d``: pybox2d 2.3's Python API on kge's physics.

Programs written for pybox2d (``import Box2D``) run on kge: ``b2World``,
bodies, fixtures, shapes, all joints, contacts and listeners, queries and the
math types keep pybox2d's names and behaviour, while the simulation is a kge
World stepped by kge's physics system (pymunk with Box2D's rules). It needs no
SWIG and no C++ compiler.

``install()`` makes ``import Box2D`` (and ``Box2D.b2``) resolve to this package,
so unmodified programs, Gymnasium's Box2D environments among them, use it::

    import kge.box2d
    kge.box2d.install()
    import gymnasium as gym
    env = gym.make("LunarLander-v3")

or run a script with ``python -m kge.box2d script.py``, and pybox2d's testbed
examples (or tests of your own for its framework) with
``python -m kge.box2d.testbed NAME`` (:mod:`kge.box2d.testbed`).

Its floor is just under the testbed, gym, testing and scaffold floor: it may
import anything below (app, systems, physics...), and only the testbed's pybox2d
samples import it.
"""

from __future__ import annotations

import sys
from types import ModuleType

from kge.box2d.api import *  # noqa: F403
from kge.box2d.api import __version__

_NAMES = ("Box2D", "Box2D.Box2D", "Box2D.b2")
#: what ``import Box2D`` gave before :func:`install` (the real pybox2d, when imported)
_replaced: dict[str, ModuleType] = {}


def install() -> None:
    """Make ``import Box2D`` and ``Box2D.b2`` resolve to ``kge.box2d`` in this interpreter.

    A real pybox2d imported before is set aside, and :func:`uninstall` puts it back.
    """
    from kge.box2d import b2 as short

    me = sys.modules[__name__]
    for name in _NAMES:
        old = sys.modules.get(name)
        if isinstance(old, ModuleType) and not old.__name__.startswith("kge.box2d"):
            _replaced[name] = old
    sys.modules["Box2D"] = me
    sys.modules["Box2D.Box2D"] = me
    sys.modules["Box2D.b2"] = short


def uninstall() -> None:
    """Undo :func:`install` (modules imported since keep what they imported): ``Box2D``
    is again what it was before (the real pybox2d if it was imported, else nothing)."""
    for name in _NAMES:
        mod = sys.modules.get(name)
        if isinstance(mod, ModuleType) and mod.__name__.startswith("kge.box2d"):
            del sys.modules[name]
            if name in _replaced:
                sys.modules[name] = _replaced.pop(name)
