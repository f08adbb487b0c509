"""GL shader programs across kge's windows: kept alive, and not shared where it bites.

kge's windows share one GL object space (headless Apps reuse pooled windows), and
Mesa's llvmpipe 22.x (the driver of headless and CI machines) mishandles programs
used by more than one context in two ways, both seen in the test suite:

* **Deleted programs.** pyglet caches the programs it makes for shapes, sprites and
  text per context, weakly: a program goes (``glDeleteProgram``) as soon as the
  last drawable holding it does, often with the App that held it and while another
  window's context is current. Mesa then frees the first context's compiled copies
  at that context's next flush by binding *no* shader behind its own state cache;
  the next draw there with the program it used last runs without a vertex shader
  and the process dies (SIGSEGV in ``glDrawElements``). :func:`pin_programs` makes
  each context's cache strong, so a program lives as long as its context.
* **Uniforms.** A uniform set in context B, then set to the same value in context
  A, is not re-uploaded for A, which draws with the value it had before. Programs
  whose uniforms change per draw (kge's tile program) are made once per context
  (:func:`per_context`), so no other context ever changes them.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any

_per_context: weakref.WeakKeyDictionary[Any, dict[str, Any]] = weakref.WeakKeyDictionary()


def pin_programs(context: Any) -> None:
    """Make ``context``'s program cache strong (its programs live as long as it does)."""
    cache = getattr(context, "_cached_programs", None)
    if isinstance(cache, weakref.WeakValueDictionary):
        context._cached_programs = dict(cache)


def per_context(name: str, make: Callable[[], Any]) -> Any:
    """The program ``name`` of the current GL context, made by ``make()`` on first use."""
    import pyglet

    ctx = pyglet.gl.current_context
    programs = _per_context.get(ctx)
    if programs is None:
        programs = _per_context[ctx] = {}
    prog = programs.get(name)
    if prog is None:
        prog = programs[name] = make()
    return prog
