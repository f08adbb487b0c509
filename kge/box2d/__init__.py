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


def real_pybox2d() -> dict[str, ModuleType]:
    """The real pybox2d's ``Box2D`` modules when it is imported (in ``sys.modules``, or set
    aside by :func:`install`), else ``{}``."""
    top = sys.modules.get("Box2D")
    if isinstance(top, ModuleType) and not top.__name__.startswith("kge.box2d"):
        return {k: m for k, m in sys.modules.items()
                if (k == "Box2D" or k.startswith("Box2D.")) and not k.startswith("Box2D.examples")}
    return dict(_replaced) if "Box2D" in _replaced else {}


def keep_real_pybox2d(modules: dict[str, ModuleType]) -> None:
    """Leave the real pybox2d's ``modules`` where a later ``import Box2D`` finds them: in
    ``sys.modules`` when nothing is there, else set aside for :func:`uninstall`. pybox2d
    cannot be imported twice in a process (its SWIG types keep the first import's
    classes: a body of one copy refuses the other's ``b2FixtureDef``)."""
    if "Box2D" not in sys.modules:
        sys.modules.update(modules)
    else:
        for name in _NAMES:
            if name in modules:
                _replaced.setdefault(name, modules[name])


def uninstall() -> None:
    """Undo :func:`install` (modules imported since keep what they imported): ``Box2D``
    is again what it was before (the real pybox2d if it was imported, else nothing)."""
    for name in _NAMES:
        mod = sys.modules.get(name)
        if isinstance(mod, ModuleType) and mod.__name__.startswith("kge.box2d"):
            del sys.modules[name]
            if name in _replaced:
                sys.modules[name] = _replaced.pop(name)
