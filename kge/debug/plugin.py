"""``DebugPlugin``: gizmos, the console, the live inspector and per-system timings.

=====================  ======================  ==========================================
system                 stage, set              does
=====================  ======================  ==========================================
``GizmoFrameStart``    INPUT, FIRST            last frame's gizmos go
``DebugInput``         INPUT, DEBUG            the console's keys (backquote), F3 the
                                               inspector, F4 per-system timings
``GizmoStepStart``     FIXED, FIRST            last step's gizmos go
``GizmoUpdateStart``   UPDATE, FIRST           fixed-step gizmos end; a world below an
                                               overlay (no INPUT stage) starts its frame
=====================  ======================  ==========================================

The console is App-wide (one history and log across scene changes); gizmos and
the inspector belong to each world. Drawing is two after-passes: ``gizmos`` (on top
of the world, under the UI) and ``debug_overlay`` (the console and inspector panels,
over everything); both import pyglet only when a frame is drawn.
"""

from __future__ import annotations

from typing import Any

from kge.components.debug import DebugDraw
from kge.debug.commands import inspector_of
from kge.debug.console import Console
from kge.debug.gizmos import Gizmos
from kge.debug.inspector import Inspector, label
from kge.host import Host
from kge.input import Input, KeyEvent
from kge.keys import Key, Mouse
from kge.physics.settings import PhysicsSettings
from kge.plugin import Plugin
from kge.render.passes import Frame, passes_for
from kge.scene import Time
from kge.schedule import Stage, System, SystemSet
from kge.systems.animation import AnimationFrameStart, ShakeRestore
from kge.systems.render import DebugKeys, RenderStepClock
from kge.world import World

#: the attribute of the App (Host) that holds its console: an attribute, not a table
#: keyed by the App, so an App that is dropped is collected with its console
_CONSOLE_ATTR = "_kge_console"

#: keys the open console handles itself (everything else it swallows)
_EDIT_KEYS = (Key.ENTER, Key.NUM_ENTER, Key.BACKSPACE, Key.TAB, Key.UP, Key.DOWN, Key.ESCAPE)


def console_for(world: World) -> Console:
    """The console of ``world``'s App (shared by its scenes), or the world's own."""
    found = world.try_resource(Console)
    if found is not None:
        return found
    host = world.try_resource(Host)
    console = getattr(host, _CONSOLE_ATTR, None) if host is not None else None
    if console is None:
        console = Console()
        if host is not None:
            setattr(host, _CONSOLE_ATTR, console)
            console.variable("time_scale", host, "time_scale", help="game time per real second")
            console.variable("paused", host, "paused", help="the game is paused")
        console.variable("gravity", PhysicsSettings, "gravity", help="m/s^2, this scene's")
    return world.insert_resource(console)


def gizmos_of(world: World) -> Gizmos:
    """The world's :class:`Gizmos`, created on first use."""
    found = world.try_resource(Gizmos)
    if found is None:
        found = world.insert_resource(Gizmos())
    return found


def _frame_key(world: World) -> Any:
    host = world.try_resource(Host)
    return getattr(host, "frame_count", None)


def _now(world: World) -> float:
    t = world.try_resource(Time)
    return float(t.elapsed) if t is not None else 0.0


class GizmoFrameStart(System):
    """Starts the frame's gizmos (INPUT, first)."""

    stage = Stage.INPUT
    in_set = SystemSet.FIRST
    after = (AnimationFrameStart,)

    def process(self, dt: float) -> None:
        start_frame(self.world)


def start_frame(world: World) -> None:
    """Clear last frame's gizmos once per App frame (whichever stage gets here first)."""
    g = gizmos_of(world)
    key = _frame_key(world)
    if key is None or key != getattr(g, "_frame_key", object()):
        g.begin_frame(_now(world))
        g._frame_key = key  # type: ignore[attr-defined]


class GizmoStepStart(System):
    """Drops the previous fixed step's gizmos (FIXED, first)."""

    stage = Stage.FIXED
    in_set = SystemSet.FIRST
    after = (RenderStepClock,)

    def process(self, dt: float) -> None:
        gizmos_of(self.world).begin_step()


class GizmoUpdateStart(System):
    """Fixed-step gizmos end; a world that ran no INPUT stage starts its frame here."""

    stage = Stage.UPDATE
    in_set = SystemSet.FIRST
    after = (ShakeRestore,)

    def process(self, dt: float) -> None:
        g = gizmos_of(self.world)
        g.end_step()
        start_frame(self.world)
        g.expire(_now(self.world))  # game time moved on in this frame's fixed steps
        if self.world.try_resource(Host) is None:  # a bare world: every UPDATE is a frame
            g.begin_frame(_now(self.world))


class DebugInput(System):
    """The console's keyboard, F3 (inspector) and F4 (system timings), before the game."""

    stage = Stage.INPUT
    in_set = SystemSet.DEBUG
    before = (DebugKeys,)

    def process(self, dt: float) -> None:
        world = self.world
        inp = world.try_resource(Input)
        if inp is None:
            return
        console = console_for(world)
        console.world = world
        overlay = overlay_of(world)
        if console.enabled and inp.pressed(console.toggle_key):
            console.open = not console.open
            inp.consume_keys(console.toggle_key)
            inp.consume_text()
            if not console.open:
                inp.reset()  # what was typed stays out of the game
                return
        if console.open:
            self._type(inp, console)
            return
        if inp.pressed(Key.F3):
            overlay.inspector = not overlay.inspector
            inp.consume_keys(Key.F3)
        if inp.pressed(Key.F4):
            self._toggle_timings(world)
            inp.consume_keys(Key.F4)
        if overlay.inspector:
            self._inspect(inp, world)

    def _type(self, inp: Input, console: Console) -> None:
        """Edit the console line from this frame's text and keys, then hide all input."""
        for ev in list(inp.events):
            if not isinstance(ev, KeyEvent) or not ev.down:
                continue
            if ev.key in (Key.ENTER, Key.NUM_ENTER):
                console.submit()
            elif ev.key == Key.BACKSPACE:
                console.line = console.line[:-1]
            elif ev.key == Key.TAB:
                console.tab()
            elif ev.key == Key.UP:
                console.recall(-1)
            elif ev.key == Key.DOWN:
                console.recall(+1)
            elif ev.key == Key.ESCAPE:
                console.open = False
        typed = "".join(ch for ch in inp.text if ch.isprintable() and ch != "`")
        console.line += typed
        inp.capture()  # the game sees no keyboard or mouse while the console is open

    def _toggle_timings(self, world: World) -> None:
        settings = world.try_resource(DebugDraw)
        if settings is None:
            settings = world.insert_resource(DebugDraw(enabled=False))
        settings.stats = settings.timings = not settings.timings
        if settings.timings:
            world.schedule.enable_timings()
        else:
            world.schedule.disable_timings()

    def _inspect(self, inp: Input, world: World) -> None:
        ins = inspector_of(world)
        if inp.pressed(Key.PAGEDOWN):
            ins.step(+1)
        if inp.pressed(Key.PAGEUP):
            ins.step(-1)
        if inp.mouse_pressed(Mouse.LEFT):
            ins.pick(inp.mouse_world)
        if ins.selected is not None and not world.exists(ins.selected):
            ins.selected = None
        if ins.selected is not None:
            from kge.components.transform import Transform

            t = world.try_get(ins.selected, Transform)
            if t is not None:
                gizmos_of(world).cross((t.x, t.y), 0.6, (255, 220, 60))


class DebugOverlay:
    """What the debug overlay shows (a resource): the inspector panel on or off."""

    def __init__(self) -> None:
        self.inspector = False


def overlay_of(world: World) -> DebugOverlay:
    found = world.try_resource(DebugOverlay)
    if found is None:
        found = world.insert_resource(DebugOverlay())
    return found


def inspector_lines(world: World, ins: Inspector, limit: int = 14) -> list[str]:
    """The inspector panel's text: a window of the entity list, then the fields."""
    ents = ins.entities()
    lines = [f"INSPECTOR  {len(ents)} entities   click: pick   PgUp/PgDn: step   "
             "console: set <id>.<Component>.<field> <value>"]  # fmt: skip
    ids = [e for e, _ in ents]
    at = ids.index(ins.selected) if ins.selected in ids else 0
    lo = max(0, min(at - limit // 2, len(ents) - limit))
    for e, text in ents[lo : lo + limit]:
        lines.append(f"{'>' if e == ins.selected else ' '} {e:>5}  {text}")
    if ins.selected is not None and world.exists(ins.selected):
        lines.append("")
        lines.append(f"entity {ins.selected}: {label(world, ins.selected)}")
        last = None
        for r in ins.rows():
            if r.component != last:
                lines.append(f"[{r.component}]")
                last = r.component
            lines.append(f"  {r.field} = {r.text}")
    return lines


class _Drawer:
    """The two after-passes (GL loaded only when a frame is drawn)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.gizmos: Any = None
        self.console: Any = None
        self.inspector: Any = None

    def _window(self) -> Any:
        from kge.render.setup import renderer_for

        host = self.world.try_resource(Host)
        renderer = renderer_for(host) if host is not None else None
        return None if renderer is None else renderer.window

    def draw_gizmos(self, frame: Frame) -> None:
        g = self.world.try_resource(Gizmos)
        window = self._window()
        if g is None or window is None or not len(g):
            return
        if self.gizmos is None:
            from kge.render.gizmos import GizmoDrawer

            self.gizmos = GizmoDrawer()
        segs, cols = g.segments()
        self.gizmos.draw(window, frame.world_matrix, segs, cols, g.texts(), frame.world_to_screen)

    def draw_overlay(self, frame: Frame) -> None:
        console = self.world.try_resource(Console)
        overlay = self.world.try_resource(DebugOverlay)
        w, h = frame.viewport
        if overlay is not None and overlay.inspector:
            if self.inspector is None:
                from kge.render.gizmos import TextPanel

                self.inspector = TextPanel(9.0)
            lines = inspector_lines(self.world, inspector_of(self.world))
            self.inspector.draw(lines, w * 0.62, 0.0, w * 0.38, h, tail=False)
        if console is not None and console.open:
            if self.console is None:
                from kge.render.gizmos import TextPanel

                self.console = TextPanel(10.0)
            lines = [*console.log, f"> {console.line}_"]
            self.console.draw(lines, 0.0, h * 0.55, w, h * 0.45)


class DebugPlugin(Plugin):
    """Gizmos, the console, the live inspector, per-system timings (module docstring)."""

    def build(self, world: World) -> None:
        gizmos_of(world)
        console_for(world).world = world
        overlay_of(world)
        for system in (GizmoFrameStart(), DebugInput(), GizmoStepStart(), GizmoUpdateStart()):
            world.add_system(system)
        drawer = _Drawer(world)
        passes = passes_for(world)
        passes.add(drawer.draw_gizmos, phase="after", name="gizmos", before=["ui"])
        passes.add(drawer.draw_overlay, phase="after", name="debug_overlay",
                   after=["ui", "hot_reload", "gizmos"])  # fmt: skip
