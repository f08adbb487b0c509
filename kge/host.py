"""What the systems of a world may know of the App that runs them.

Systems and plugins sit below :mod:`kge.app` (they must not import it), yet a few of
them need facts only the running App has: the window size for a camera's bounds,
the App's identity for the music mixer all its scenes share, the headless flag.
:class:`Host` names exactly those facts; :class:`~kge.app.App` is a Host and puts
itself in every scene world as the ``Host`` resource::

    host = world.try_resource(Host)       # None in a bare World (unit tests)
    width, height = host.size if host else (960, 540)

A :class:`Frontend` is how the App draws and opens windows without naming the
render package: the render plugin installs one (``host.frontend``), and an App
without it is headless-only and says so when asked to draw.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from collections.abc import Callable

    from kge.input import Input
    from kge.schedule import System
    from kge.transitions import ActiveTransition
    from kge.world import World


@dataclass(slots=True, frozen=True)
class CloseRequested:
    """The window's close button (or :meth:`App.request_close`) asked the App to end
    while ``app.quit_on_close`` is False: the top scene decides (ask to save, then
    ``app.quit()``), and the window stays open until it does."""


class Frontend(Protocol):
    """Drawing and windows for one App (installed by the render plugin)."""

    def render(self, host: Host) -> None:
        """Draw the current frame (offscreen when headless)."""

    def screenshot(self, host: Host, path: str) -> None:
        """Render the current frame and save it as a PNG at ``path``."""

    def run_window(self, host: Host, frames: int | None, screenshot: str | None) -> bool:
        """Run the App in a real window until it closes; False when no window can open."""

    def capture(self, host: Host) -> Any:
        """Draw the current frame and return it as a texture (None if nothing was drawn
        yet): the picture of the old scene a transition fades, slides or wipes away."""


class Host:
    """The App as its systems see it (see the module docstring)."""

    size: tuple[int, int]
    title: str
    headless: bool
    background: tuple[int, int, int]
    input: Input
    frontend: Frontend | None
    #: the scene transition playing now (drawn over the frame), or None
    transition: ActiveTransition | None

    @property
    def fixed_dt(self) -> float:  # pragma: no cover - App overrides
        raise NotImplementedError

    @property
    def alpha(self) -> float:  # pragma: no cover - App overrides
        """How far between the last two fixed steps the frame being drawn is (0..1)."""
        raise NotImplementedError

    @property
    def world(self) -> World:  # pragma: no cover - App overrides
        raise NotImplementedError

    def visible_worlds(self) -> list[World]:  # pragma: no cover - App overrides
        """The worlds drawn this frame, bottom first (scenes below overlays, then the top)."""
        raise NotImplementedError

    def replace_scene(self, scene: Any, *, transition: Any = None, **kwargs: Any) -> None:
        """Close the top scene and start ``scene`` (App overrides)."""  # pragma: no cover
        raise NotImplementedError

    def push_scene(
        self, scene: Any, *, overlay: bool = False, run_below: bool = False, **kwargs: Any
    ) -> None:  # pragma: no cover - App overrides
        """Put ``scene`` on top (``overlay=True``: drawn over the one below)."""
        raise NotImplementedError

    def pop_scene(self) -> None:  # pragma: no cover - App overrides
        """Close the top scene and resume the one below."""
        raise NotImplementedError

    def quit(self) -> None:  # pragma: no cover - App overrides
        """Stop the App's loop after the current frame (the window closes)."""
        raise NotImplementedError

    def world_to_screen(self, point: tuple[float, float]) -> tuple[float, float]:
        """World metres to window pixels through the active camera (App overrides)."""
        raise NotImplementedError  # pragma: no cover

    def add_system_to_all(self, factory: Callable[[], System]) -> None:  # pragma: no cover
        """Add a system to every current and future scene world (App overrides)."""
        raise NotImplementedError
