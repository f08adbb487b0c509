"""``App``: the scene stack, the schedule and the clock.

One frame, in the order of DESIGN.md:

1. **input**: window events (or test calls such as ``app.input.press``) are in
   the :class:`~kge.input.Input` resource; ``on_key_*`` / ``on_mouse_*`` hooks run.
2. **fixed loop**: the accumulator decides how many fixed steps run; each one
   shows the input edges since the previous step to fixed-step code and runs
   the FIXED stage (behaviours ``on_fixed_update`` -> physics -> contact
   events), flushing queued changes after every system.
3. **update**: UPDATE then LATE stages with the scaled frame time.
4. **render** (when a window or ``app.render()`` asks): poses are blended by
   ``alpha`` = leftover accumulator / fixed_dt.

Inside each stage the systems run in the order of :mod:`kge.schedule` (named
sets, ``before`` / ``after``; ``kge schedule`` prints it); events follow
:mod:`kge.events` (readable for one step or one frame, never consumed).

Scene changes requested during a frame (``replace_scene`` from a script, say)
take effect when the frame ends, never half-way through a step. Changes requested
while another one is being made (from ``on_exit``, ``on_destroy`` or a setup) queue
behind it and apply in order, each to the stack as the ones before it left it. A
scene whose setup raises leaves the stack as it was (its error propagates, and the
changes queued behind it are dropped), and the App never loses its last scene:
``pop_scene`` refuses to (use ``replace_scene``, or ``quit``).

Headless use, as in tests::

    app = App(my_scene, headless=True)
    app.step(60)          # 60 fixed steps, each followed by an update pass
    app.world.query(...)  # the current scene's world
"""

from __future__ import annotations

import functools
import os
import sys
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from kge.actions import Bindings, InputMap
from kge.components.camera import Camera, active_camera, camera_at
from kge.components.resolution import canvas_size
from kge.cursor import Cursor
from kge.errors import ComponentTypeError, SceneStackError, ValidationError, WorldLockedError
from kge.host import CloseRequested, Frontend, Host
from kge.input import Input
from kge.platform import has_display
from kge.plugin import Plugin, PluginError, PluginLike, resolve
from kge.plugins import default_plugins
from kge.scene import Scene, SceneLike, Time, as_scene, check_setup_args
from kge.schedule import Stage, System
from kge.timestep import FixedTimestep
from kge.transitions import ActiveTransition, Transition
from kge.validate import boolean, integer, non_negative
from kge.world import World

if TYPE_CHECKING:
    from kge.snapshot import Restorable

SystemFactory = Callable[[], System]
#: what App, push_scene and replace_scene take: a scene, or a scene file's path
SceneSource = SceneLike | str | os.PathLike[str]

#: ``App()`` with no scene (push one later); distinct from ``App(None)``, which is refused
NO_SCENE: Any = type("NoScene", (), {"__repr__": lambda self: "NO_SCENE"})()


class App(Host):
    """Runs scenes. ``App(scene, headless=True)`` needs no window.

    ``plugins`` chooses the subsystems every scene world gets (default:
    :func:`kge.default_plugins`, everything); ``App(scene, plugins=[PhysicsPlugin()])``
    is a physics-only App that never imports rendering or audio. ``bindings`` declares
    the game's input actions (:meth:`kge.InputMap.declare`: a dict, a JSON file or a
    function), ready before the first scene is set up.
    """

    def __init__(
        self,
        scene: SceneSource = NO_SCENE,
        *,
        headless: bool | None = None,
        size: tuple[int, int] = (960, 540),
        title: str = "kge",
        fixed_dt: float = 1.0 / 60.0,
        max_steps_per_frame: int = 5,
        max_frame_dt: float = 0.25,
        time_scale: float = 1.0,
        background: tuple[int, int, int] = (24, 26, 33),
        plugins: Iterable[PluginLike] | None = None,
        bindings: Bindings | None = None,
        **scene_kwargs: Any,
    ) -> None:
        self.headless = (not has_display()) if headless is None else bool(headless)
        #: why a window cannot open, told once by run() (None: a window can, or headless=True)
        self.no_window_reason: str | None = (
            "no display (DISPLAY and WAYLAND_DISPLAY are unset, or PYGLET_HEADLESS is set)"
            if headless is None and self.headless
            else None
        )
        self.size = (int(size[0]), int(size[1]))
        self.title = title
        self.background = background
        self.timestep = FixedTimestep(
            fixed_dt=fixed_dt,
            max_steps_per_frame=max_steps_per_frame,
            max_frame_dt=max_frame_dt,
            time_scale=time_scale,
        )
        self.input = Input()
        self.input.screen_to_world = self.screen_to_world
        self.actions = InputMap(self.input)  #: named actions, shared by every scene
        if bindings is not None:  # the game's controls, before any scene is set up
            self.actions.declare(bindings)
        self.frontend: Frontend | None = None
        self.extra_systems: list[SystemFactory] = []
        self._stack: list[tuple[Scene, World]] = []
        #: worlds pushed as overlays: True if the scene below keeps running
        self._overlays: dict[World, bool] = {}
        #: the keyword arguments each world's setup ran with (reload_scene runs it again)
        self._setup_kwargs: dict[World, dict[str, Any]] = {}
        self.transition: ActiveTransition | None = None
        self._swap: Callable[[], None] | None = None
        self._plugins: list[Plugin] = []
        #: scene changes waiting for the frame (or the change being made) to end, with
        #: how many scenes each adds to the stack
        self._scene_ops: list[tuple[int, Callable[[], None]]] = []
        self._applying = False
        self._closing = False
        #: while a replace is being made: how many scenes at the bottom of the stack stay
        #: (the ones above close); its new scene is counted apart, on the stack during its
        #: setup and off it while the old ones close
        self._keep: int | None = None
        self._swap_grows = 0  #: how the pending transition's change grows the stack
        self._autoloads: dict[type, Any] = {}  #: resources every scene world shares
        self._in_frame = False
        self._ending_frame = False  #: the scene changes asked for during a frame are running
        self._running = False
        #: how the mouse pointer looks over the window (hide, lock, an image)
        self.cursor = Cursor()
        #: the window's close button quits at once (False: it sends CloseRequested)
        self.quit_on_close = True
        self.frame_count = 0
        self.add_plugins(*(default_plugins() if plugins is None else plugins))
        if scene is not NO_SCENE:  # App(None) is refused: usually App(level(world)) by mistake
            self.push_scene(scene, **scene_kwargs)

    # -- clock controls -------------------------------------------------------------
    @property
    def fixed_dt(self) -> float:
        return self.timestep.fixed_dt

    @property
    def time_scale(self) -> float:
        return self.timestep.time_scale

    @time_scale.setter
    def time_scale(self, value: float) -> None:
        self.timestep.time_scale = non_negative(value, "App", "time_scale")

    @property
    def paused(self) -> bool:
        return self.timestep.paused

    @paused.setter
    def paused(self, value: bool) -> None:
        self.timestep.paused = boolean(value, "App", "paused")

    def single_step(self) -> None:
        """While paused: run exactly one fixed step on the next frame."""
        self.timestep.single_step()

    @property
    def alpha(self) -> float:
        return self.timestep.alpha

    def screen_to_world(self, point: tuple[float, float]) -> tuple[float, float]:
        """Screen pixels (origin bottom-left; design pixels with a ``Resolution``) to world
        metres, through the camera whose viewport is under the point.

        Live: it always uses the current scene's cameras and the current window size,
        so mouse positions are right after a scene change or a resize, headless too.
        """
        canvas = self._canvas()
        cam = camera_at(self.world, point, canvas) if self._stack else None
        return (cam or _default_camera()).screen_to_world(point, canvas)

    def world_to_screen(self, point: tuple[float, float]) -> tuple[float, float]:
        """World metres to screen pixels through the active camera (the inverse)."""
        return self._camera().world_to_screen(point, self._canvas())

    def _canvas(self) -> tuple[int, int]:
        return canvas_size(self.world if self._stack else None, self.size)

    def _camera(self) -> Camera:
        """The active camera of the current scene, or a default one (shared, never written)."""
        cam = active_camera(self.world) if self._stack else None
        return cam if cam is not None else _default_camera()

    # -- scenes -----------------------------------------------------------------------
    @property
    def world(self) -> World:
        """The World of the scene on top of the stack."""
        if not self._stack:
            raise RuntimeError("the App has no scene: pass one to App(...) or push_scene()")
        return self._stack[-1][1]

    @property
    def scene(self) -> Scene:
        if not self._stack:
            raise RuntimeError("the App has no scene")
        return self._stack[-1][0]

    @property
    def scenes(self) -> list[Scene]:
        """The scenes of the stack, bottom first."""
        return [s for s, _ in self._stack]

    @property
    def worlds(self) -> list[World]:
        """The worlds of the stack's scenes, bottom first (``worlds[-1]`` is ``world``)."""
        return [w for _, w in self._stack]

    def push_scene(
        self,
        scene: SceneSource,
        *,
        overlay: bool = False,
        run_below: bool = False,
        transition: Transition | None = None,
        **kwargs: Any,
    ) -> None:
        """Put ``scene`` on top (the one below pauses); kwargs go to its setup.

        ``overlay=True`` draws it over the scene below (a see-through pause menu);
        the scene below stays frozen, or keeps running (without input) when
        ``run_below=True``. Popping returns to it with its state intact.
        ``transition`` plays over the push as it does for :meth:`replace_scene`
        (the scene is pushed when the transition is due: a menu that fades in).
        """
        target = _as_scene(scene)
        check_setup_args(target, kwargs)
        overlay = boolean(overlay, "push_scene", "overlay")
        run_below = boolean(run_below, "push_scene", "run_below")
        if run_below and not overlay:
            raise ValidationError("push_scene(run_below=True) needs overlay=True")
        _check_transition(transition, "push_scene")
        keeps_running = run_below if overlay else None
        push = lambda: self._push(target, kwargs, overlay=keeps_running)  # noqa: E731
        if transition is None:
            self._schedule(+1, push)
        else:
            self._schedule(+1, self._transition_to(push, transition, +1))

    def pop_scene(self, *, transition: Transition | None = None) -> None:
        """Close the top scene and resume the one below (behind ``transition`` if given).

        Refused with :class:`~kge.errors.SceneStackError` when it would pop the App's
        last scene (counting the changes already queued): change scene with
        :meth:`replace_scene`, or stop with :meth:`quit`.
        """
        if self._depth_when_queued() <= 1:
            raise SceneStackError(
                "pop_scene() would leave the App with no scene: use replace_scene() to "
                "change scene, or app.quit() to stop"
            )
        _check_transition(transition, "pop_scene")
        if transition is None:
            self._schedule(-1, self._pop)
        else:
            self._schedule(-1, self._transition_to(self._pop, transition, -1))

    def _transition_to(self, change: Callable[[], None], transition: Transition, grows: int
                       ) -> Callable[[], None]:
        """An op that starts ``transition``, which makes ``change`` (a push or a pop:
        the stack ``grows`` by one or shrinks) when it is due."""

        def begin() -> None:
            self._swap = change
            self._swap_grows = grows  # a pop is counted by _depth_when_queued until made
            # the newest one wins; asked for during a frame, its time starts with the next
            self.transition = ActiveTransition(transition, fresh=self._ending_frame)

        return begin

    def replace_scene(
        self, scene: SceneSource, *, transition: Transition | None = None, **kwargs: Any
    ) -> None:
        """Close the top scene and start ``scene`` (with kwargs) in its place.

        The new scene is set up first and the old one exits once it is ready, so a
        setup that raises leaves the old scene running. ``transition``
        (:mod:`kge.transitions`: ``Fade(0.4)``, ``Crossfade``, ``Slide``, ``Wipe``)
        plays over the change and the scene changes when it is due: the scene on top
        when it starts (after the changes asked for before it) leaves then, with any
        scene pushed over it meanwhile (a pause menu opened during the fade).
        """
        target = _as_scene(scene)
        check_setup_args(target, kwargs)
        _check_transition(transition, "replace_scene")
        grows = 0 if self._depth_when_queued() else 1
        if transition is None:
            self._schedule(grows, lambda: self._replace(target, kwargs, None))
            return

        def begin() -> None:  # in order with the changes queued before it
            leaving = self._stack[-1][1] if self._stack else None
            self._swap = lambda: self._replace(target, kwargs, leaving)
            self._swap_grows = 0
            # the newest one wins; asked for during a frame, its time starts with the next
            self.transition = ActiveTransition(transition, fresh=self._ending_frame)

        self._schedule(0, begin)

    def _depth_when_queued(self) -> int:
        """How many scenes the stack will hold once the queued changes are made."""
        queued = sum(grows for grows, _ in self._scene_ops)
        # a pending pop counts now; a pending push only once made (nothing pops it before)
        pending = min(self._swap_grows, 0) if self._swap is not None else 0
        # a replace being made (its setup or the old scenes' on_exit asking): the scenes
        # that stay and its new scene, whatever the stack holds at this moment
        depth = len(self._stack) if self._keep is None else self._keep + 1
        return depth + queued + pending

    def _advance_transition(self, real_dt: float) -> None:
        """Play the running transition: change the scene when due, end it when done."""
        active = self.transition
        if active is None:
            return
        if active.fresh:  # begun as the frame that asked for it ended
            active.fresh = False
            return
        active.advance(real_dt)
        swap = self._swap
        if active.swap_due and swap is not None:
            if active.transition.needs_picture and active.picture is None:
                active.picture = self._capture()  # the old scene as it looks now
            active.swapped = True
            self._swap, grows, self._swap_grows = None, self._swap_grows, 0
            self._schedule(grows, swap)
        if active.done:
            self.transition = None

    def _capture(self) -> Any:
        """A picture of what the window shows now (None before anything was drawn)."""
        capture = getattr(self.frontend, "capture", None)
        return capture(self) if capture is not None else None

    def visible_worlds(self) -> list[World]:
        """The worlds drawn this frame, bottom first: the top one and the scenes below
        each overlay."""
        shown = []
        for _, world in reversed(self._stack):
            shown.append(world)
            if world not in self._overlays:
                break
        return shown[::-1]

    def _running_worlds(self) -> list[World]:
        """The top world, then the ones below overlays pushed with ``run_below=True``."""
        worlds = [self.world]
        for _, world in reversed(self._stack[:-1]):
            above = worlds[-1]
            if not self._overlays.get(above, False):
                break
            worlds.append(world)
        return worlds

    def _schedule(self, grows: int, op: Callable[[], None]) -> None:
        """Queue a scene change; make it now unless a frame or another change runs."""
        if self._closing:
            return
        self._scene_ops.append((grows, op))
        if not self._in_frame:
            self._run_scene_ops()

    def _push(
        self,
        scene: Scene,
        kwargs: dict[str, Any],
        overlay: bool | None = None,
    ) -> None:
        below = self._stack[-1] if self._stack else None
        if below is not None:
            below[0].on_pause(below[1])
        try:
            self._start(scene, kwargs, overlay)
        except BaseException:
            if below is not None:
                below[0].on_resume(below[1])
            raise

    def _replace(self, scene: Scene, kwargs: dict[str, Any], leaving: World | None) -> None:
        """Start ``scene``, then close ``leaving`` and every scene above it (the top
        scene when ``leaving`` is None; nothing when it has already left)."""
        worlds = [w for _, w in self._stack]
        if leaving is None:
            first = len(worlds) - 1 if worlds else 0
        else:
            first = worlds.index(leaving) if leaving in worlds else len(worlds)
        self._keep = first  # for the changes its setup and the on_exits ask for
        try:
            self._start(scene, kwargs, None)
            new = self._stack.pop()
            try:
                while len(self._stack) > first:
                    self._close_top()
            finally:
                self._stack.append(new)
        finally:
            self._keep = None

    def _start(self, scene: Scene, kwargs: dict[str, Any], overlay: bool | None) -> None:
        """Make a world for ``scene`` on top and set it up; on any error, take it off
        again (closing it) and leave the stack as it was."""
        world = self._make_world(scene)
        self._stack.append((scene, world))
        self._setup_kwargs[world] = kwargs
        if overlay is not None:
            self._overlays[world] = overlay
        self.input.reset()
        self.actions.clock.reset()
        try:
            scene.setup(world, **kwargs)
            world.flush()
        except BaseException:
            self._stack.pop()
            self._overlays.pop(world, None)
            self._setup_kwargs.pop(world, None)
            world.close()
            raise

    def reload_scene(self) -> None:
        """Build the top scene again from its setup, and swap it in only if that succeeds.

        Hot reload calls this when a scene file or map changes. On any error the new
        world is closed, the error is raised, and the running world carries on as it was.
        """
        if not self._stack:
            raise RuntimeError("App.reload_scene() needs a running scene")
        scene, old = self._stack[-1]
        kwargs = self._setup_kwargs.get(old, {})
        world = self._make_world(scene)
        try:
            scene.setup(world, **kwargs)
            world.flush()
        except BaseException:
            world.close()
            raise

        def op() -> None:
            if not self._stack or self._stack[-1][1] is not old:
                world.close()  # the scene changed meanwhile: the rebuilt world is stale
                return
            self._stack.pop()
            overlay = self._overlays.pop(old, None)
            self._setup_kwargs.pop(old, None)
            scene.on_exit(old)
            old.close()
            self._stack.append((scene, world))
            self._setup_kwargs[world] = kwargs
            if overlay is not None:
                self._overlays[world] = overlay

        self._schedule(0, op)

    def _close_top(self) -> None:
        scene, world = self._stack.pop()
        self._overlays.pop(world, None)
        self._setup_kwargs.pop(world, None)
        scene.on_exit(world)
        world.close()

    def _pop(self) -> None:
        if len(self._stack) <= 1:
            raise SceneStackError("pop_scene() would leave the App with no scene")
        self._close_top()
        self.input.reset()
        self.actions.clock.reset()
        scene, world = self._stack[-1]
        scene.on_resume(world)

    # -- autoloads ------------------------------------------------------------------------
    def autoload(self, resource: Any, *, as_type: type | None = None) -> Any:
        """Share ``resource`` with every scene, now and later: the same object is the
        resource of each scene world, so what it holds (a score, settings, a save slot,
        an inventory) survives scene changes (Godot's autoloads). One of a type
        replaces the last. Returns ``resource``.
        """
        key = as_type or type(resource)
        if isinstance(resource, type):
            raise ComponentTypeError(
                f"App.autoload: expected an instance, got the class {resource.__name__} "
                f"(write app.autoload({resource.__name__}(...)))"
            )
        if issubclass(key, _APP_OWNED) or isinstance(resource, (World, *_APP_OWNED)):
            raise ValidationError(
                f"App.autoload: {key.__name__} is the App's own; every scene has it already"
            )
        for world in self.worlds:  # checked (as_type) before anything is stored
            world.insert_resource(resource, as_type=as_type)
        self._autoloads[key] = resource
        return resource

    @property
    def autoloads(self) -> dict[type, Any]:
        """The shared resources, by type (a copy)."""
        return dict(self._autoloads)

    def _make_world(self, scene: Scene) -> World:
        world = World(name=scene.name or type(scene).__name__)
        for key, resource in self._autoloads.items():  # before plugins and setup see it
            world.insert_resource(resource, as_type=key)
        world.insert_resource(self.input)
        world.insert_resource(self.actions)
        world.insert_resource(Time(self.fixed_dt))
        world.insert_resource(self)
        world.insert_resource(self, as_type=Host)
        world.add_plugins(*self._plugins)
        for factory in self.extra_systems:
            world.add_system(factory())
        return world

    def restore(self, data: bytes | Restorable) -> None:
        """Replace the current scene's world with one restored from ``world.snapshot()``
        (in memory) or from a save file read by ``kge.load_game(path)``.

        The scene object stays; its ``setup`` is not run again. Systems are rebuilt,
        and the physics system recreates every body from the restored components.
        The data is validated in full first (as ``spawn`` validates): on any error a
        ``SnapshotError`` is raised here and the running scene is left as it was.
        What the scene registered in code carries over (see :mod:`kge.scene_carry`).
        """
        from kge.scene_carry import carry_over
        from kge.snapshot import restore_into

        if not self._stack:
            raise RuntimeError("App.restore() needs a running scene")
        world = self._make_world(self._stack[-1][0])
        try:
            if isinstance(data, bytes | bytearray):
                restore_into(world, data)
            else:
                data.restore_into(world)
        except BaseException:
            world.close()
            raise

        def op() -> None:
            scene, old = self._stack.pop()
            carry_over(old, world)
            for key, resource in self._autoloads.items():  # shared, never restored
                world.insert_resource(resource, as_type=key)
            old.close()
            self._stack.append((scene, world))

        self._schedule(0, op)

    # -- plugins ----------------------------------------------------------------------------
    def add_plugins(self, *plugins: PluginLike) -> None:
        """Add plugins to the App: built into every current and future scene world.

        A plugin already present, or one whose requirement is missing, raises
        :class:`~kge.plugin.PluginError` naming both, and nothing is built.
        """
        for plugin in resolve(self._plugins, plugins, "this App"):
            plugin.build_app(self)
            self._plugins.append(plugin)
            for _, world in self._stack:
                world.add_plugins(plugin)

    @property
    def plugins(self) -> tuple[Plugin, ...]:
        """The App's plugins, in build order."""
        return tuple(self._plugins)

    def add_system_to_all(self, factory: SystemFactory) -> None:
        """Add a system to every current and future scene world (render, audio...)."""
        self.extra_systems.append(factory)
        for _, world in self._stack:
            world.add_system(factory())

    # -- running ------------------------------------------------------------------------
    def step(self, n: int = 1) -> None:
        """Advance ``n`` fixed steps, each followed by an update pass with dt = fixed_dt.

        This ignores the accumulator and the pause flag: it is the test driver.
        """
        self._not_reentrant("step")
        count = integer(n, "App.step", "n")
        if count < 0:
            raise ValidationError(f"App.step.n must be >= 0, got {count}")
        for _ in range(count):
            self._frame(steps=1, game_dt=self.fixed_dt, real_dt=self.fixed_dt)
            self._advance_transition(self.fixed_dt)

    def advance(self, frame_dt: float) -> int:
        """Run one frame of ``frame_dt`` real seconds through the accumulator.

        Returns the number of fixed steps that ran. A window calls this every tick.
        """
        self._not_reentrant("advance")
        steps = self.timestep.advance(frame_dt)
        game_dt = self.timestep.frame_time(frame_dt)
        if self.paused and steps:
            game_dt = self.fixed_dt * steps  # a single step also advances update time
        real_dt = min(max(frame_dt, 0.0), self.timestep.max_frame_dt)
        self._frame(steps, game_dt, real_dt)
        self._advance_transition(real_dt)
        return steps

    def _not_reentrant(self, op: str) -> None:
        """Refuse a frame inside a frame (a hook or physics callback calling app.step()):
        the inner frame would clear and deliver the outer step's events mid-delivery."""
        if self._in_frame:
            raise WorldLockedError(
                f"App.{op}() inside a running frame (a system, behaviour or physics "
                "callback): schedule the work for the next frame instead"
            )

    def _frame(self, steps: int, game_dt: float, real_dt: float) -> None:
        if not self._stack:
            raise RuntimeError("the App has no scene to run")
        self._in_frame = True
        try:
            self.input.refresh_world_position()
            self.input.touch.advance(real_dt)  # taps are timed in real time too
            self.actions.update(real_dt)  # holds, taps, buffers, combos: real time
            top, *below = self._running_worlds()
            self._run_world(top, steps, game_dt, with_input=True)
            for world in below:
                with self.input.muted():  # scenes below an overlay get no input
                    self._run_world(world, steps, game_dt, with_input=False)
        finally:
            self._in_frame = False
            self.input.end_frame()
            self.frame_count += 1
        self._ending_frame = True
        try:
            self._run_scene_ops()
        finally:
            self._ending_frame = False

    def _run_world(self, world: World, steps: int, game_dt: float, with_input: bool) -> None:
        """One frame of ``world``: its stages in order (kge/schedule.py's FRAME)."""
        time = world.resource(Time)
        inp, schedule, log = self.input, world.schedule, world.eventlog
        log.begin_frame()
        if with_input:  # action events and hooks, input hooks and the UI
            self.actions.clock.deliver(world.emit)
            inp.touch.deliver(world.emit)  # TouchPoint and the gesture events (kge.touch)
            schedule.run(Stage.INPUT, game_dt)
        for _ in range(steps):
            if self._scene_ops:
                break  # the scene is changing: do not step a world about to close
            log.begin_step()
            inp.begin_step()  # fixed-step code sees each input edge once
            schedule.run(Stage.FIXED, self.fixed_dt)
            inp.end_step()
            time.step += 1
            time.fixed_elapsed += self.fixed_dt
        time.dt = game_dt
        time.elapsed += game_dt
        time.frame += 1
        time.alpha = self.timestep.alpha
        schedule.run(Stage.UPDATE, game_dt)
        schedule.run(Stage.LATE, game_dt)
        log.end_frame()
        schedule.end_frame()

    def _run_scene_ops(self) -> None:
        """Make the queued scene changes in order; one asked for while another is being
        made (from on_exit, on_destroy, a setup) waits for it. If a change raises, the
        error propagates and the changes behind it are dropped with it."""
        if self._applying:
            return
        self._applying = True
        try:
            while self._scene_ops:
                _, op = self._scene_ops.pop(0)
                op()
        except BaseException:
            self._scene_ops.clear()
            raise
        finally:
            self._applying = False

    def _frontend(self, what: str) -> Frontend:
        if self.frontend is None:
            names = ", ".join(p.name for p in self._plugins) or "none"
            raise PluginError(
                f"App.{what} needs the RenderPlugin, and this App's plugins are: {names} "
                "(add kge.RenderPlugin() to plugins=, or leave plugins= out for all of them)"
            )
        return self.frontend

    def render(self) -> None:
        """Draw one frame of the current scene (offscreen when headless)."""
        self._frontend("render()").render(self)

    def screenshot(self, path: str | os.PathLike[str]) -> None:
        """Render the current frame and save it as a PNG."""
        self._frontend("screenshot()").screenshot(self, os.fspath(path))

    def quit(self) -> None:
        """Stop :meth:`run` after the current frame."""
        self._running = False

    def request_close(self) -> None:
        """The window's close button: quit, or, with ``quit_on_close = False``, emit
        :class:`~kge.host.CloseRequested` into the top scene's world and keep running
        (an editor asks about unsaved changes first). Headless tests call it too."""
        if self.quit_on_close or not self._stack:
            self.quit()
        else:
            self.world.emit(CloseRequested())

    @property
    def running(self) -> bool:
        """True while :meth:`run` loops (a window, or headless), until ``quit``."""
        return self._running

    def run(self, frames: int | None = None, screenshot: str | None = None) -> None:
        """Open a window and run until it closes (headless: until ``quit`` or ``frames``).

        ``screenshot`` saves the last frame as a PNG (smoke tests, docs).
        """
        if not self.headless and self.frontend is not None:
            if self.frontend.run_window(self, frames, screenshot):
                return
            self.headless = True
            self.no_window_reason = "pyglet's window module cannot be imported here"
        if self.no_window_reason and frames is None:
            print(
                f"kge: {self.no_window_reason}: App.run() runs headless until app.quit(); "
                "set DISPLAY for a window, or pass frames=N",
                file=sys.stderr,
            )
        self._running = True
        count = 0
        while self._running and self._stack and (frames is None or count < frames):
            self.advance(self.fixed_dt)
            count += 1
        self._running = False
        if screenshot:
            self.screenshot(screenshot)

    def close(self) -> None:
        """Close every scene (despawning all entities), then let each plugin clean up
        (the audio plugin stops the App's music). Scene changes asked for while the
        App closes (from on_exit or on_destroy) are dropped."""
        self._closing = True
        self._scene_ops.clear()
        self._swap = None
        self.transition = None
        while self._stack:
            self._close_top()
        for plugin in reversed(self._plugins):
            plugin.cleanup(self)


def run(
    scene: SceneSource,
    *,
    title: str = "kge",
    size: tuple[int, int] = (960, 540),
    hot_reload: bool | None = None,
    **kwargs: Any,
) -> App:
    """One-line entry point: ``kge.run(my_scene, title="Pong")``.

    Every other keyword goes to :class:`App` (``bindings={"jump": ["key:SPACE",
    "pad:a"]}``, ``fixed_dt=...``) or, when App has no such parameter, to the scene's
    setup. ``hot_reload`` (default: on when a window opens, or when
    ``KGE_HOT_RELOAD=1``) reloads changed scene, prefab, map, image, sound and Python
    files while the game runs (:mod:`kge.hotreload`).
    """
    app = App(scene, title=title, size=size, **kwargs)
    if hot_reload is None:
        env = os.environ.get("KGE_HOT_RELOAD")
        hot_reload = env == "1" if env in ("0", "1") else not app.headless
    reloader = None
    if hot_reload:
        from kge.hotreload import HotReloadPlugin

        reloader = HotReloadPlugin()
        app.add_plugins(reloader)
    try:
        app.run()
    finally:
        if reloader is not None:
            reloader.cleanup(app)  # stop watching; the App stays as run() left it
    return app


#: resources the App puts in every world itself (autoloading one is a mistake)
_APP_OWNED: tuple[type, ...] = (Input, InputMap, Time, Host)


def _check_transition(transition: object, call: str) -> None:
    if transition is not None and not isinstance(transition, Transition):
        raise ComponentTypeError(
            f"{call}: transition must be a Transition (Fade(0.4)...), got {transition!r}"
        )


def _as_scene(scene: SceneSource) -> Scene:
    """A Scene from a Scene, a setup function or a scene file's path (``App("a.scene.toml")``)."""
    if isinstance(scene, str | os.PathLike):
        from kge.scenefile.scene import SceneFile

        return SceneFile(scene)
    return as_scene(scene)


@functools.cache
def _default_camera() -> Camera:
    """The camera used when a scene has none (built once: the mouse is mapped every frame)."""
    return Camera()
