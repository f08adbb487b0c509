"""``AppHolder``: the App an environment runs its scene in, made by its first ``reset``.

A single env (:class:`~kge.gym.env.KgeEnv`) and the batched landers
(:class:`~kge.gym.lander_vector.LunarLanderVector`) both hold one App that does
not exist until ``reset``; using it before then is Gymnasium's "reset first" error,
named after the env.
"""

from __future__ import annotations

from kge.app import App
from kge.gym.errors import ResetNeededError
from kge.world import World


class AppHolder:
    """``app`` and ``world`` of an env, refused before the first ``reset``."""

    _app: App | None

    @property
    def app(self) -> App:
        """The kge App running the scene (created by the first ``reset``)."""
        if self._app is None:
            # ``env_name`` is a property of the single env and an attribute of the vector
            name = getattr(self, "env_name", type(self).__name__)
            raise ResetNeededError(f"{name}: call reset() before using the App")
        return self._app

    @property
    def world(self) -> World:
        return self.app.world
