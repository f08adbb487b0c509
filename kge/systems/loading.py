"""A loading screen: preload a list of assets a few per frame, show the progress, move on.

::

    app.replace_scene(LoadingScreen(["ship.png", "music.ogg"], then=Level2,
                                    transition=Fade(0.4)))

The screen is an ordinary scene with a UI panel (title, :class:`~kge.components.ui.
ProgressBar`, percent label). Its system loads through :meth:`kge.assets.Assets.preload`
for ``budget`` seconds per frame (or ``items_per_frame`` assets, deterministic in
tests), and when the list is done emits :class:`~kge.assets.preload.AssetsLoaded` into
its world and replaces itself with ``then`` (through the transition, if one is given).
With ``background=True`` worker threads decode the files (Pillow, soundfile, file reads)
while the screen keeps drawing, and each frame only finishes the decoded ones
(:class:`~kge.assets.preload.BackgroundPreload`). Assets that failed to load raise
one :class:`~kge.assets.errors.AssetError` naming them all, at the frame that finished.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from typing import Any

from kge.assets.preload import Preload
from kge.assets.store import Assets, assets_for
from kge.components.ui import Label, Panel, ProgressBar, UINode
from kge.host import Host
from kge.scene import Scene, SceneLike
from kge.schedule import Stage, System
from kge.transitions import Transition
from kge.validate import boolean
from kge.world import World


class LoadingScreen(Scene):
    """Preloads ``assets`` and then replaces itself with ``then`` (see the module docstring)."""

    def __init__(
        self,
        assets: Iterable[str | os.PathLike[str]],
        then: SceneLike,
        *,
        transition: Transition | None = None,
        store: Assets | None = None,
        budget: float = 1.0 / 120.0,
        items_per_frame: int | None = None,
        title: str = "Loading",
        background: bool = False,
        **then_kwargs: Any,
    ) -> None:
        self.names = list(assets)
        self.then = then
        self.transition = transition
        self.store = store
        self.budget = float(budget)
        self.items_per_frame = items_per_frame
        self.title = title
        self.background = boolean(background, "LoadingScreen", "background")
        self.then_kwargs = then_kwargs
        self.preload: Preload | None = None
        self.name = "loading"

    def setup(self, world: World, *args: Any, **kwargs: Any) -> None:
        store = self.store or assets_for(world)
        self.preload = store.preload(self.names, background=self.background)
        panel = world.spawn(
            UINode(width="40%", layout="column", padding=16, spacing=10, align="stretch"), Panel()
        )
        world.spawn(UINode(parent=panel), Label(self.title, size=22))
        bar = world.spawn(UINode(parent=panel, height=16), ProgressBar(0.0))
        text = world.spawn(UINode(parent=panel), Label("0 %"))
        world.add_system(_Loader(self, bar, text))


class _Loader(System):
    stage = Stage.UPDATE

    def __init__(self, screen: LoadingScreen, bar: int, text: int) -> None:
        self.screen, self.bar, self.text = screen, bar, text
        self.finished = False

    def process(self, dt: float) -> None:
        screen, job = self.screen, self.screen.preload
        if job is None or self.finished:
            return
        # a count of items per frame replaces the time budget (deterministic, as documented)
        budget = math.inf if screen.items_per_frame is not None else screen.budget
        job.step(budget, screen.items_per_frame)
        self.world.get(self.bar, ProgressBar).value = job.progress
        self.world.get(self.text, Label).text = f"{job.loaded} / {job.queued}"
        if not job.done:
            return
        self.finished = True
        self.world.emit(job.event())
        job.finish()  # raises if any asset failed
        host = self.world.try_resource(Host)
        if host is not None:
            host.replace_scene(screen.then, transition=screen.transition, **screen.then_kwargs)
