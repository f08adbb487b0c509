"""Exceptions raised inside pymunk's callbacks, kept and raised again after the step.

pymunk calls back into Python from C in the middle of a step: collision
handlers (kge's contact events and hooks), constraints' ``pre_solve`` (the
joints' own solvers), bodies' ``position_func`` (continuous collision) and
post-step callbacks. cffi cannot let an exception cross C, so it prints it
through ``sys.unraisablehook`` and the step carries on as if nothing happened.
A ``WorldLockedError`` from a contact hook or a bug in a joint solver would be
a line on stderr and a silently wrong world.

The contact handlers are wrapped with :meth:`CallbackErrors.guard`; the
joints' substep solvers and continuous collision's sweeps catch and
:meth:`CallbackErrors.keep` themselves (no extra frame on a hot path). The
only callbacks left bare are two whose bodies are a few attribute writes
(the damping ``velocity_func``). The simulation calls
:meth:`CallbackErrors.raise_pending` once the step is over and its state is
consistent, so the first exception reaches the caller of the step; the test
suite turns anything that still reaches ``sys.unraisablehook`` into a failure.

>>> errors = CallbackErrors()
>>> def hook(x: int) -> None:
...     raise ValueError(f"bad {x}")
>>> guarded = errors.guard(hook)
>>> guarded(1); guarded(2)  # both swallowed for now; the first is kept
>>> errors.raise_pending()
Traceback (most recent call last):
ValueError: bad 1
>>> errors.raise_pending()  # cleared once raised
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class CallbackErrors:
    """The first exception raised by a guarded callback since the last raise."""

    __slots__ = ("error",)

    def __init__(self) -> None:
        self.error: BaseException | None = None

    def keep(self, exc: BaseException) -> None:
        """Remember ``exc`` unless an earlier one is waiting (the first is the cause)."""
        if self.error is None:
            self.error = exc

    def guard(self, fn: Callable[..., Any]) -> Callable[..., None]:
        """``fn`` wrapped so that an exception is kept instead of reaching cffi."""

        def call(*args: Any) -> None:
            try:
                fn(*args)
            except Exception as exc:
                self.keep(exc)

        return call

    def raise_pending(self) -> None:
        """Raise the kept exception, if any, and forget it."""
        err, self.error = self.error, None
        if err is not None:
            raise err
