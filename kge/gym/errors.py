"""Errors of the Gymnasium adapter.

Every message names the environment (its registered id, or its class when it was
built by hand) and the offending value, because an RL loop that feeds a bad action
is usually several frames of library code away from the line that made it.
"""

from __future__ import annotations

from kge.errors import KgeError


class EnvError(KgeError):
    """Base of the errors a kge environment raises on purpose."""


class InvalidActionError(EnvError, ValueError):
    """``step`` got an action that is not in the action space (wrong shape, range or dtype)."""


class InvalidSeedError(EnvError, TypeError):
    """``reset`` got a seed that is not a non-negative int (or None)."""


class ResetNeededError(EnvError, RuntimeError):
    """``step`` was called before ``reset``, or after the episode ended, without a reset."""


class ObservationError(EnvError, ValueError):
    """The observation function returned NaN/inf or a value outside the observation space."""
