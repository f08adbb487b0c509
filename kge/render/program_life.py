"""Shader programs live as long as the GL objects they draw with, in every context.

pyglet caches the programs it makes for shapes, sprites and text per GL context,
weakly: a program goes (``glDeleteProgram``) as soon as the last drawable holding it
does. kge's windows share one GL object space (headless Apps reuse pooled windows),
so a program one window has drawn with is easily dropped with the App that held it
while another window's context is current. Mesa (llvmpipe 22.x, the driver of
headless and CI machines) then frees the first context's compiled copies of it at
that context's next flush by binding *no* shader behind its own state cache; the
next draw there with the program it used last runs without a vertex shader and the
process dies with SIGSEGV in ``glDrawElements``.

:func:`pin_programs` gives each object space one strong cache, shared by all its
contexts: a program is compiled once per process (per object space) and never
deleted while a context may still hold compiled copies of it. kge's own programs
(particles, lights) are module-level for the same reason.

Uniforms are another matter: on the same driver a uniform set in context B, then set
to the same value in context A, is not re-uploaded for A, which draws with the value
it had before. Programs whose uniforms change per draw (kge's tile program: a layer's
shift, tint and wrap) are therefore made once per context
(:func:`kge.render.glutil.per_context`), so no other context ever changes them.
"""

from __future__ import annotations

import weakref
from typing import Any

#: object space -> its programs by source (the strong stand-in for pyglet's weak cache)
_caches: weakref.WeakKeyDictionary[Any, dict[str, Any]] = weakref.WeakKeyDictionary()


def pin_programs(context: Any) -> None:
    """Make ``context``'s program cache strong and shared with its object space."""
    if context is None or not hasattr(context, "_cached_programs"):
        return
    cache = _caches.get(context.object_space)
    if cache is None:
        cache = _caches[context.object_space] = {}
    cache.update(context._cached_programs)
    context._cached_programs = cache
