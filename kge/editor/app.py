"""The editor window: a kge App whose scene stack holds the edited scene and the editor's UI.

The stack, bottom first:

* the **edited scene** (``EditScene``): the scene file loaded into a world that never
  steps; its lowest entity is the editor's camera, so the viewport pans and zooms
  without touching the scene's own camera. Grid lines, the selection box and handles
  are editor-only entities there (never saved, not in the hierarchy);
* the **editor UI** (``EditorUI``, an overlay): toolbar, hierarchy (a ``TreeView``
  whose row drops reparent), inspector (a ``ScrollView`` of rows: ``SpinBox`` numbers,
  ``ColorPicker`` colours, toggles, dropdowns, text fields), status line and dialogs,
  built from kge.ui widgets; its :class:`EditorInput` system turns clicks, drags, wheel
  and keys into :class:`~kge.editor.model.EditorModel` edits (a drag of a spin box or a
  colour picker is one undo step).

Play pushes the scene as the file would load (``PlayScene``, from the model's text)
with a small bar over it (``PlayBar``); stop pops both, and the edited scene below was
never touched. Everything runs headless with simulated input in tests.
"""

from __future__ import annotations

import functools
import itertools
import math
import os
from pathlib import Path
from typing import Any

from kge.app import App
from kge.components import drawables as draw
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.transform import Transform
from kge.components.ui import (
    Button,
    ColorPicker,
    Dropdown,
    Label,
    Panel,
    ScrollView,
    SpinBox,
    Style,
    TextInput,
    Toggle,
    TreeItem,
    TreeView,
    UINode,
)
from kge.editor.fields import FieldKind, asset_files, kind_of, parse, show
from kge.editor.model import EditorModel, EditorOnly
from kge.editor.starters import starter
from kge.host import CloseRequested
from kge.input import Input, KeyEvent
from kge.keys import Key, Mod, Mouse
from kge.scene import Scene
from kge.scenefile import SceneFileError, default_registry, load_scene_text
from kge.scenefile.registry import COMPONENT
from kge.schedule import Stage, System, SystemSet
from kge.ui import ButtonClicked, Dropped, ItemActivated, TextSubmitted, TreeDrop, ValueChanged
from kge.ui.interact import UIState
from kge.world import World

TOOLS = ("select", "move", "rotate", "scale", "shape", "anchor", "paint", "prefab")
LEFT_W, RIGHT_W, TOP_H, BOTTOM_H = 250.0, 330.0, 40.0, 26.0
EDITOR_TITLE = "kge edit"


def _compact() -> Style:
    """The toolbar's and the hierarchy's buttons: small text, so every label fits."""
    return Style(font_size=12.0, padding=5.0)


#: above this many colliders the physics overlay starts off (the Physics button shows it)
OVERLAY_LIMIT = 1000


class EditScene(Scene):
    """The scene being edited (a world that is drawn but never stepped)."""

    name = "edit"

    def __init__(self, path: str | os.PathLike[str] | None) -> None:
        self.path = path
        self.model: EditorModel | None = None

    def setup(self, world: World, **kwargs: Any) -> None:
        self.model = EditorModel(world, self.path)
        world.insert_resource(self.model)
        if world.try_resource(DebugDraw) is None:  # the physics overlay (unless the scene has one)
            # drawn in Python per collider each frame: off by default on very large scenes
            many = len(world.query(Collider)) > OVERLAY_LIMIT
            world.insert_resource(DebugDraw(enabled=not many, joints=True, contacts=False,
                                            contact_normals=False))
            self.model.own_resources.add(DebugDraw)


class PlayScene(Scene):
    """The edited scene as the game would load it (from the model's current text)."""

    name = "play"

    def __init__(self, text: str, path: Path) -> None:
        self.text = text
        self.path = path

    def setup(self, world: World, **kwargs: Any) -> None:
        load_scene_text(world, self.text, self.path)


class PlayBar(Scene):
    """Pause, step and stop over the running scene."""

    name = "play bar"

    def __init__(self, editor: Editor) -> None:
        self.editor = editor

    def setup(self, world: World, **kwargs: Any) -> None:
        bar = world.spawn(UINode(anchor="top", offset=(0.0, -6.0), width=330.0, height=34.0,
                                 layout="row", padding=3.0, spacing=4.0, align="stretch"),
                          Panel(color=(20, 24, 30, 230)))
        for text in ("Pause", "Step", "Stop"):
            world.spawn(UINode(parent=bar, width=70.0), Button(text))
        world.spawn(UINode(parent=bar, width=100.0), Label("playing", size=13.0))
        world.add_system(PlayBarInput(self.editor))


class PlayBarInput(System):
    stage = Stage.UPDATE
    in_set = SystemSet.FIRST

    def __init__(self, editor: Editor) -> None:
        self.editor = editor

    def process(self, dt: float) -> None:
        for ev in self.world.events(ButtonClicked):
            {"Pause": self.editor.pause, "Step": self.editor.step_once,
             "Stop": self.editor.stop}.get(ev.text, lambda: None)()
        if self.world.events(CloseRequested):  # the window's close button while playing
            self.editor.stop()
            self.editor.quit()
            return
        inp = self.world.resource(Input)
        if inp.pressed(Key.ESCAPE):
            self.editor.stop()


class Editor:
    """The editor's state outside the model: tool, widgets, dialogs, play mode."""

    def __init__(self, app: App, edit_world: World, model: EditorModel) -> None:
        self.app = app
        self.edit_world = edit_world
        self.model = model
        self.ui: World | None = None
        self.tool = "select"
        self.playing = False
        self.prefab: str | None = None
        self.message = ""
        self.widgets: dict[int, tuple[int, type, str, FieldKind]] = {}
        self.labels: dict[int, tuple[int, type, str, FieldKind]] = {}
        self.buttons: dict[int, str] = {}
        self.rows: list[int] = []
        self.dialog: list[int] = []
        self.dialog_kind = ""
        self.search = ""
        self.shown_selection: tuple[int, ...] | None = None
        self.inspector_dirty = True
        self.markers: list[int] = []
        self.grid_lines: list[int] = []
        self.drag: dict[str, Any] | None = None
        self.after_dialog: Any = None
        # UI entities, set when the editor's UI scene is built
        self.search_box = 0
        self.tree = 0
        self.inspector = 0
        self.status = 0
        self.remove_buttons: dict[int, tuple[int, type]] = {}
        self.name_box: int | None = None
        self.add_button: int | None = None
        self.add_choice: int | None = None
        self.prefab_choice: int | None = None
        self.inspector_rows: list[int] = []
        self.last_mouse: tuple[float, float] = (0.0, 0.0)
        self.tree_parents: set[int] = set()  #: hierarchy rows with children, last refresh
        self.tree_shown: Any = None  #: (searching, (entity, depth, name) rows) last shown
        #: a spin box or colour picker being dragged: (widget, field value before the drag)
        self.live: tuple[int, Any] | None = None
        self.grid_key: Any = None
        model.listeners.append(self._changed)

    def run_edit(self, fn: Any) -> None:
        """Run an edit; a refused one is shown in the status line, not raised."""
        try:
            fn()
        except (SceneFileError, ValueError, TypeError, KeyError) as exc:
            self.say(str(exc))
        self.inspector_dirty = True

    # -- model notifications -------------------------------------------------------------------
    def _changed(self, what: str) -> None:
        self.inspector_dirty = True

    # -- geometry -----------------------------------------------------------------------------
    def viewport(self) -> tuple[float, float, float, float]:
        w, h = self.app.size
        return (LEFT_W, BOTTOM_H, w - RIGHT_W, h - TOP_H)

    def in_viewport(self, p: tuple[float, float]) -> bool:
        x0, y0, x1, y1 = self.viewport()
        return x0 <= p[0] < x1 and y0 <= p[1] < y1

    def to_world(self, p: tuple[float, float]) -> tuple[float, float]:
        return self.model.camera.screen_to_world(p, self.app.size)

    def to_screen(self, p: tuple[float, float]) -> tuple[float, float]:
        return self.model.camera.world_to_screen(p, self.app.size)

    def frame(self, entities: list[int] | None = None) -> None:
        """Centre the viewport on ``entities`` (default: everything)."""
        pts = [self.model.world_pose(e)[:2] for e in (entities or self.model.entities())
               if self.model.world.has(e, Transform)]
        if not pts:
            return
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        cam = self.model.camera
        x0, y0, x1, y1 = self.viewport()
        span = max(max(xs) - min(xs) + 4.0, (max(ys) - min(ys) + 4.0) * (x1 - x0) / (y1 - y0))
        cam.zoom = (x1 - x0) / (span * cam.pixels_per_meter)
        offset = ((x0 + x1) / 2 - self.app.size[0] / 2) / (cam.pixels_per_meter * cam.zoom)
        cam.center = ((max(xs) + min(xs)) / 2 - offset, (max(ys) + min(ys)) / 2)

    # -- commands (toolbar, keys)  -------------------------------------------------------------
    def run(self, name: str) -> None:
        try:
            self._run(name)
        except (SceneFileError, ValueError, TypeError, KeyError) as exc:
            self.say(f"{name}: {exc}")

    def _run(self, name: str) -> None:
        m = self.model
        if name in TOOLS:
            self.tool = name
            self.say(f"tool: {name}")
        elif name == "undo":
            m.undo()
        elif name == "redo":
            m.redo()
        elif name == "save":
            if m.path is None:
                self.ask_path("Save as")
            else:
                self.say(f"saved {m.save().name}")
        elif name == "save as":
            self.ask_path("Save as")
        elif name == "delete":
            m.delete()
        elif name == "duplicate":
            m.duplicate()
        elif name == "new":
            m.create(Transform(*m.snapped(self.model.camera.center)), name="Entity")
        elif name == "play":
            self.play()
        elif name == "grid":
            m.snap = not m.snap
            self.say(f"snapping {'on' if m.snap else 'off'} ({m.grid} m)")
        elif name == "frame":
            self.frame(m.selection or None)
        elif name == "physics":
            dd = self.edit_world.try_resource(DebugDraw)
            if dd is not None:
                dd.enabled = not dd.enabled
                self.say(f"physics overlay {'on' if dd.enabled else 'off'}")
        elif name == "quit":
            self.quit()
        self.inspector_dirty = True

    def say(self, message: str) -> None:
        self.message = message

    # -- play mode ---------------------------------------------------------------------------
    def play(self) -> None:
        if self.playing:
            return
        path = self.model.path or Path.cwd() / "untitled.scene.toml"
        self.app.push_scene(PlayScene(self.model.text(), path))
        self.app.push_scene(PlayBar(self), overlay=True, run_below=True)
        self.playing = True
        self.app.paused = False
        self.say("playing (Esc stops)")

    def pause(self) -> None:
        self.app.paused = not self.app.paused

    def step_once(self) -> None:
        self.app.paused = True
        self.app.single_step()

    def stop(self) -> None:
        if not self.playing:
            return
        self.app.paused = False
        self.app.pop_scene()
        self.app.pop_scene()
        self.playing = False
        self.say("stopped: the edited scene is as you left it")

    # -- dialogs -------------------------------------------------------------------------------
    def ask_path(self, title: str) -> None:
        default = str(self.model.path or Path.cwd() / "untitled.scene.toml")
        self.open_dialog("save as", title, ["Save", "Cancel"], text=default)

    def quit(self) -> None:
        if self.model.dirty:
            self.open_dialog("unsaved", "Unsaved changes: save them?",
                             ["Save", "Discard", "Cancel"])
            self.after_dialog = self.app.quit
        else:
            self.app.quit()

    def open_dialog(self, kind: str, title: str, buttons: list[str], text: str | None = None
                    ) -> None:
        ui = self.ui
        if ui is None:
            return
        self.close_dialog()
        self.dialog_kind = kind
        box = ui.spawn(UINode(anchor="center", width=440.0, layout="column", padding=14.0,
                              spacing=8.0, align="stretch", order=100), Panel())
        self.dialog.append(box)
        self.dialog.append(ui.spawn(UINode(parent=box), Label(title, size=16.0)))
        if text is not None:
            self.dialog.append(ui.spawn(UINode(parent=box, height=28.0),
                                        TextInput(text, max_length=1024)))
        row = ui.spawn(UINode(parent=box, height=32.0, layout="row", spacing=8.0,
                              align="stretch"))
        self.dialog.append(row)
        for b in buttons:
            e = ui.spawn(UINode(parent=row, width=100.0), Button(b))
            self.dialog.append(e)

    def close_dialog(self) -> None:
        if self.ui is not None:
            for e in self.dialog:
                if self.ui.exists(e):
                    self.ui.despawn(e)
        self.dialog = []
        self.dialog_kind = ""

    def dialog_button(self, text: str) -> None:
        kind, ui = self.dialog_kind, self.ui
        typed = ""
        if ui is not None:
            for e in self.dialog:
                t = ui.try_get(e, TextInput) if ui.exists(e) else None
                if t is not None:
                    typed = t.text
        self.close_dialog()
        after, self.after_dialog = self.after_dialog, None
        if text == "Cancel":
            return
        if kind == "save as" and text == "Save":
            try:
                path = self.model.save(Path(typed).expanduser())
            except (SceneFileError, OSError) as exc:
                self.say(f"save failed: {exc}")
                return
            self.say(f"saved {path}")
        elif kind == "unsaved":
            if text == "Save":
                if self.model.path is None:
                    self.ask_path("Save as")
                    self.after_dialog = after
                    return
                self.model.save()
            if after is not None:
                after()


class EditorUI(Scene):
    """The editor's panels, drawn over the edited scene."""

    name = "editor"

    def __init__(self, editor: Editor) -> None:
        self.editor = editor

    def setup(self, world: World, **kwargs: Any) -> None:
        ed = self.editor
        ed.ui = world
        top = world.spawn(UINode(anchor="top_left", width="100%", height=TOP_H, layout="row",
                                 padding=4.0, spacing=3.0, align="stretch"),
                          Panel(color=(24, 27, 34, 245), radius=0.0))
        for name in (*TOOLS, "undo", "redo", "save", "save as", "play", "grid", "physics",
                     "frame"):
            e = world.spawn(UINode(parent=top), Button(name.capitalize()), _compact())
            ed.buttons[e] = name
        # the side panels fill the height between the toolbar and the status line
        frame = world.spawn(UINode(anchor="top_left", width="100%", height="100%",
                                   layout="column", align="stretch"))
        world.spawn(UINode(parent=frame, height=TOP_H))
        middle = world.spawn(UINode(parent=frame, grow=1.0, shrink=1.0, layout="row",
                                    align="stretch"))  # a long inspector scrolls
        world.spawn(UINode(parent=frame, height=BOTTOM_H))
        left = world.spawn(UINode(parent=middle, width=LEFT_W, layout="column", padding=6.0,
                                  spacing=4.0, align="stretch"),
                           Panel(color=(28, 31, 40, 240), radius=0.0))
        world.spawn(UINode(parent=left), Label("Hierarchy", size=14.0, align="left"))
        ed.search_box = world.spawn(UINode(parent=left, height=26.0),
                                    TextInput("", placeholder="search"))
        actions = world.spawn(UINode(parent=left, height=28.0, layout="row", spacing=3.0,
                                     align="stretch"))
        for name in ("new", "duplicate", "delete"):
            e = world.spawn(UINode(parent=actions, grow=1.0), Button(name.capitalize()),
                            _compact())
            ed.buttons[e] = name
        ed.tree = world.spawn(UINode(parent=left, grow=1.0), TreeView(draggable=True))
        world.spawn(UINode(parent=middle, grow=1.0))  # the viewport shows through
        right = world.spawn(UINode(parent=middle, width=RIGHT_W, layout="column", padding=6.0,
                                   spacing=3.0, align="stretch"),
                            Panel(color=(28, 31, 40, 240), radius=0.0))
        world.spawn(UINode(parent=right), Label("Inspector", size=14.0, align="left"))
        ed.inspector = world.spawn(UINode(parent=right, grow=1.0, layout="column", spacing=3.0,
                                          align="stretch"), ScrollView())
        world.spawn(UINode(anchor="bottom_left", width="100%", height=BOTTOM_H),
                    Panel(color=(18, 20, 26, 250), radius=0.0))
        ed.status = world.spawn(UINode(anchor="bottom_left", offset=(8.0, 4.0)),
                                Label("", size=12.0, align="left"))
        world.add_system(EditorInput(ed))


class EditorInput(System):
    """Turns the frame's UI events, mouse and keys into edits; refreshes the panels."""

    stage = Stage.UPDATE
    in_set = SystemSet.FIRST

    def __init__(self, editor: Editor) -> None:
        self.ed = editor

    def process(self, dt: float) -> None:
        ed = self.ed
        if ed.playing:
            return
        if self.world.events(CloseRequested):  # the window's close button: as Quit does
            ed.run("quit")
        self.ui_events()
        self.keys()
        self.viewport()
        self.refresh()

    # -- UI events -----------------------------------------------------------------------------
    def ui_events(self) -> None:
        ed, world = self.ed, self.world
        for ev in world.events(ButtonClicked, TextSubmitted, ValueChanged, Dropped,
                               ItemActivated):  # in order
            if isinstance(ev, ButtonClicked):
                if ev.entity in ed.dialog:
                    ed.dialog_button(ev.text)
                elif ev.entity in ed.buttons:
                    ed.run(ed.buttons[ev.entity])
                elif ev.entity in ed.remove_buttons:
                    ent, ctype = ed.remove_buttons[ev.entity]
                    ed.run_edit(lambda e=ent, c=ctype: ed.model.remove_component(e, c))
                elif ev.entity == ed.add_button:
                    self.add_component()
            elif isinstance(ev, TextSubmitted):
                if ev.entity in ed.widgets:
                    self.field_edit(ev.entity, ev.text)
                elif ev.entity == ed.name_box and ed.model.selection:
                    ed.run_edit(functools.partial(ed.model.rename, ed.model.selection[0],
                                                  ev.text))
                elif ev.entity in ed.dialog:
                    ed.dialog_button("Save")
            elif isinstance(ev, ValueChanged):
                if ev.entity == ed.tree:
                    self.tree_pick(ev.value)
                elif ev.entity in ed.widgets:
                    w = ed.widgets[ev.entity]
                    if w[3].widget == "toggle":
                        self.field_edit(ev.entity, "true" if ev.value else "false")
                    elif w[3].widget == "choice":
                        self.field_edit(ev.entity, w[3].choices[int(ev.value)])
                    elif w[3].widget in ("number", "angle", "colour", "vector"):
                        self.live_edit(ev.entity, ev.value)
            elif isinstance(ev, Dropped):
                if ev.target == ed.tree and isinstance(ev.payload, TreeDrop):
                    self.tree_drop(ev.payload)
            elif isinstance(ev, ItemActivated) and ev.entity == ed.tree:
                ed.frame([ev.item])
        if ed.live is not None and not world.resource(Input).mouse_held(Mouse.LEFT):
            self.commit_live()
        search = world.try_get(ed.search_box, TextInput)
        if search is not None and search.text != ed.search:
            ed.search = search.text
            ed.inspector_dirty = True

    def tree_pick(self, entity: int | None) -> None:
        ed = self.ed
        if entity is None or entity not in ed.rows:
            return
        inp = self.world.resource(Input)
        ed.model.select(entity, add=bool(inp.modifiers & Mod.SHIFT))

    def tree_drop(self, drop: TreeDrop) -> None:
        """A hierarchy row dropped inside another row reparents it there; before or after
        a row, beside it (its parent); below the last row, to no parent."""
        ed = self.ed
        target = drop.target
        if target is not None and drop.where != "inside":
            target = ed.model.parent(int(target))
        item = int(drop.item)
        ed.run_edit(lambda: ed.model.reparent(item, None if target is None else int(target)))

    def live_edit(self, widget: int, value: Any) -> None:
        """A spin box's or colour picker's new value, applied at once; the undo step is
        made when the mouse lets go (:meth:`commit_live`), one for the whole drag."""
        ed = self.ed
        entity, ctype, name, kind = ed.widgets[widget]
        comp: Any = ed.model.world.get(entity, ctype)
        current = getattr(comp, name)
        if kind.widget == "colour":
            text = ", ".join(str(int(v)) for v in tuple(value)[: len(current)])
        elif kind.widget == "vector":  # this widget's component of the vector
            parts = [float(value) if i == kind.index else v for i, v in enumerate(current)]
            text = ", ".join(repr(float(v)) for v in parts)
        else:
            text = repr(float(value))
        info = default_registry().info(ctype)
        if info is None:
            return
        folder = ed.model.path.parent if ed.model.path else Path.cwd()
        if ed.live is not None and ed.live[0] != widget:
            self.commit_live()
        before = current if ed.live is None else ed.live[1]
        try:
            setattr(comp, name, parse(kind, text, info, name, current, folder, ed.model.entity))
        except (SceneFileError, ValueError, TypeError) as exc:
            ed.say(str(exc))
            return
        ed.live = (widget, before)

    def commit_live(self) -> None:
        ed = self.ed
        assert ed.live is not None
        (widget, before), ed.live = ed.live, None
        entity, ctype, name, _ = ed.widgets[widget]
        if not ed.model.world.exists(entity) or not ed.model.world.has(entity, ctype):
            return
        now = getattr(ed.model.world.get(entity, ctype), name)
        ed.run_edit(lambda: ed.model.set_fields(entity, ctype, {name: now},
                                                f"{ctype.__name__}.{name}", before={name: before}))

    def field_edit(self, widget: int, text: str) -> None:
        ed = self.ed
        entity, ctype, name, kind = ed.widgets[widget]
        info = default_registry().info(ctype)
        if info is None:
            return
        folder = ed.model.path.parent if ed.model.path else Path.cwd()
        comp: Any = ed.model.world.get(entity, ctype)

        def edit() -> None:
            value = parse(kind, text, info, name, getattr(comp, name), folder, ed.model.entity)
            ed.model.set_field(entity, ctype, name, value)

        ed.run_edit(edit)

    def add_component(self) -> None:
        ed = self.ed
        dd = self.world.try_get(ed.add_choice, Dropdown) if ed.add_choice else None
        if dd is None or not ed.model.selection or dd.value is None:
            return
        info = default_registry().get(dd.value or "")
        if info is None:
            return
        entity = ed.model.selection[0]
        folder = ed.model.path.parent if ed.model.path else None
        ed.run_edit(lambda: ed.model.add_component(
            entity, starter(info.cls, entity, [str(folder / a) for a in asset_files(folder)]
                            if folder else [])))

    # -- keys  ---------------------------------------------------------------------------------
    def keys(self) -> None:
        """Shortcuts, read from this frame's key events (a whole ctrl+s can arrive inside
        one frame, the Ctrl key already up when the editor looks)."""
        ed = self.ed
        inp = self.world.resource(Input)
        state = self.world.resource(UIState)
        typing = state.focused is not None and self.world.exists(state.focused) and \
            self.world.has(state.focused, TextInput)
        for ev in list(inp.events):
            if not isinstance(ev, KeyEvent) or not ev.down:
                continue
            ctrl, shift = bool(ev.modifiers & Mod.CTRL), bool(ev.modifiers & Mod.SHIFT)
            name = None
            if ctrl:
                name = {Key.Z: "redo" if shift else "undo", Key.Y: "redo", Key.S: "save",
                        Key.D: "duplicate", Key.Q: "quit"}.get(ev.key)
            elif ev.key == Key.DELETE and not typing:
                name = "delete"
            elif ev.key == Key.F5:
                name = "play"
            if name is not None:
                ed.run(name)

    # -- the viewport  -------------------------------------------------------------------------
    def viewport(self) -> None:
        ed, m = self.ed, self.ed.model
        inp = self.world.resource(Input)
        mouse = inp.mouse_screen
        cam = m.camera
        if ed.dialog:
            return
        if inp.scroll != (0.0, 0.0) and ed.in_viewport(mouse):
            before = ed.to_world(mouse)
            cam.zoom = cam.zoom * (1.15 ** inp.scroll[1])
            after = ed.to_world(mouse)
            cam.center = (cam.center[0] + before[0] - after[0],
                          cam.center[1] + before[1] - after[1])
        pan = inp.mouse_held(Mouse.MIDDLE) or inp.mouse_held(Mouse.RIGHT)
        last = ed.last_mouse
        if pan and ed.in_viewport(mouse):
            k = 1.0 / (cam.pixels_per_meter * cam.zoom)
            cam.center = (cam.center[0] - (mouse[0] - last[0]) * k,
                          cam.center[1] - (mouse[1] - last[1]) * k)
        ed.last_mouse = mouse
        if inp.mouse_pressed(Mouse.LEFT) and ed.in_viewport(mouse):
            self.press(ed.to_world(mouse), inp)
        elif ed.drag is not None and inp.mouse_held(Mouse.LEFT):
            self.dragging(ed.to_world(mouse))
        elif ed.drag is not None:
            self.release(ed.to_world(mouse))

    def press(self, p: tuple[float, float], inp: Input) -> None:
        ed, m = self.ed, self.ed.model
        tool = ed.tool
        add = bool(inp.modifiers & Mod.SHIFT)
        if tool == "prefab":
            if ed.prefab:
                ed.run_edit(lambda: m.place_prefab(ed.prefab or "", p))
            else:
                ed.say("choose a prefab file in the inspector first")
            return
        if tool == "shape" and m.selection:
            e = m.selection[0]
            for i, h in enumerate(m.shape_handles(e)):
                if math.dist(h, p) < 0.3 / max(m.camera.zoom, 0.1):
                    ed.drag = {"kind": "shape", "entity": e, "index": i}
                    return
        if tool == "anchor" and m.selection:
            e = m.selection[0]
            a = m.joint_anchor(e)
            if a is not None and math.dist(a, p) < 0.4 / max(m.camera.zoom, 0.1):
                ed.drag = {"kind": "anchor", "entity": e}
                return
        if tool == "paint" and m.selection:
            ed.drag = {"kind": "paint", "brush": m.selection[0], "cells": [p]}
            return
        hit = m.pick(p)
        if hit is None or tool == "select" or hit not in m.selection:
            m.select(hit, add=add)
        if not m.selection or tool == "select":
            return
        e = m.selection[0]
        t = m.world.try_get(e, Transform)
        if t is None:
            return
        if tool == "move":
            ed.drag = {"kind": "move", "from": p, "start": {
                x: (m.world.get(x, Transform).x, m.world.get(x, Transform).y)
                for x in m.selection if m.world.has(x, Transform)}}
        elif tool == "rotate":
            ed.drag = {"kind": "rotate", "entity": e, "angle": t.angle,
                       "from": math.atan2(p[1] - t.y, p[0] - t.x)}
        elif tool == "scale":
            ed.drag = {"kind": "scale", "entity": e, "from": p,
                       "r0": max(math.dist(p, (t.x, t.y)), 1e-3)}

    def dragging(self, p: tuple[float, float]) -> None:
        ed, m = self.ed, self.ed.model
        d = ed.drag
        assert d is not None
        if d["kind"] == "move":
            m.move(list(d["start"]), (p[0] - d["from"][0], p[1] - d["from"][1]), live=True,
                   start=d["start"])
        elif d["kind"] == "rotate":
            t = m.world.get(d["entity"], Transform)
            t.angle = d["angle"] + math.atan2(p[1] - t.y, p[0] - t.x) - d["from"]
        elif d["kind"] == "paint":
            d["cells"].append(p)

    def release(self, p: tuple[float, float]) -> None:
        ed, m = self.ed, self.ed.model
        d, ed.drag = ed.drag, None
        assert d is not None
        kind = d["kind"]
        if kind == "move":
            ed.run_edit(lambda: m.move(list(d["start"]), (p[0] - d["from"][0],
                                                          p[1] - d["from"][1]), start=d["start"]))
        elif kind == "rotate":
            t = m.world.get(d["entity"], Transform)
            angle = d["angle"] + math.atan2(p[1] - t.y, p[0] - t.x) - d["from"]
            ed.run_edit(lambda: m.rotate(d["entity"], angle, before=d["angle"]))
        elif kind == "scale":
            t = m.world.get(d["entity"], Transform)
            factor = max(math.dist(p, (t.x, t.y)), 1e-3) / d["r0"]
            ed.run_edit(lambda: m.scale(d["entity"], factor))
        elif kind == "shape":
            ed.run_edit(lambda: m.drag_shape_handle(d["entity"], d["index"], p))
        elif kind == "anchor":
            ed.run_edit(lambda: m.drag_joint_anchor(d["entity"], p))
        elif kind == "paint":
            cells = _cells_along(d["cells"] + [p], m.grid or 0.5)
            ed.run_edit(lambda: m.paint(d["brush"], cells))

    # -- panels  -------------------------------------------------------------------------------
    def refresh(self) -> None:
        ed = self.ed
        m = ed.model
        world = self.world
        rows = m.hierarchy(ed.search)
        ed.rows = [e for e, _ in rows]
        tree = world.get(ed.tree, TreeView)
        shown = (bool(ed.search), [(e, d, m.name(e)) for e, d in rows])
        if shown != ed.tree_shown:  # TreeItems are built only when a row changed
            ed.tree_shown = shown
            items = _tree_items(shown[1], flat=shown[0])
            parents = {int(it.parent) for it in items if it.parent is not None}
            # rows that gained children open; what the user folded stays folded
            ids = set(ed.rows)
            tree.items = items
            tree.expanded = (set(tree.expanded) & ids) | (parents - ed.tree_parents)
            ed.tree_parents = parents
        sel = m.selection[0] if m.selection and m.selection[0] in ed.rows else None
        if tree.selected != sel:
            tree.selected = sel
        name = m.path.name if m.path else "untitled"
        status = f"{name}{' *' if m.dirty else ''}   tool: {ed.tool}   {ed.message}"
        reloader = _reloader(world)
        if reloader is not None and reloader.errors:
            status += "   " + " | ".join(reloader.errors.values())
        label = world.get(ed.status, Label)
        if label.text != status:
            label.text = status
        if ed.inspector_dirty or tuple(m.selection) != ed.shown_selection:
            ed.inspector_dirty = False
            ed.shown_selection = tuple(m.selection)
            build_inspector(ed, world)
        update_markers(ed)


def _tree_items(rows: list[tuple[int, int, str]], flat: bool) -> list[TreeItem]:
    """The hierarchy's rows as tree items: each row's parent is the row above it one level
    up (so a parent cycle in the scene never reaches the tree); a search shows a flat
    list of the matches."""
    items: list[TreeItem] = []
    above: list[int] = []  # the open rows, one per depth
    for e, depth, name in rows:
        del above[depth:]
        parent = above[-1] if above and not flat else None
        items.append(TreeItem(e, name, parent))
        above.append(e)
    return items


def _reloader(world: World) -> Any:
    from kge.hotreload import HotReload

    return world.try_resource(HotReload)


def _cells_along(points: list[tuple[float, float]], step: float) -> list[tuple[float, float]]:
    out = []
    for a, b in itertools.pairwise(points):
        n = max(1, int(math.dist(a, b) / (step / 2)))
        out += [(a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n) for i in range(n + 1)]
    return out or points




def build_inspector(ed: Editor, ui: World) -> None:
    """The inspector's rows for the first selected entity (rebuilt when it changes)."""
    m = ed.model
    for e in ed.inspector_rows:
        if ui.exists(e):
            ui.despawn(e)
    ui.flush()
    rows: list[int] = []
    ed.widgets, ed.labels, ed.remove_buttons = {}, {}, {}
    ed.name_box, ed.add_button, ed.add_choice = None, None, None

    def row(*widgets: tuple[Any, float], height: float = 24.0) -> int:
        r = ui.spawn(UINode(parent=ed.inspector, height=height, layout="row", spacing=4.0,
                            align="stretch"))
        rows.append(r)
        for comp, width in widgets:  # fixed sizes: "auto" would measure every option
            rows.append(ui.spawn(UINode(parent=r, width=width), comp))
        return r

    if not m.selection or not m.world.exists(m.selection[0]):
        rows.append(ui.spawn(UINode(parent=ed.inspector), Label(
            "nothing selected", size=12.0, align="left")))
        prefabs = [p.relative_to(m.path.parent).as_posix() for p in
                   sorted(m.path.parent.rglob("*.prefab.toml"))] if m.path else []
        if prefabs:
            rows.append(ui.spawn(UINode(parent=ed.inspector), Label("Prefab tool places:",
                                                                    size=12.0, align="left")))
            dd = Dropdown(prefabs, selected=0)
            ed.prefab_choice = ui.spawn(UINode(parent=ed.inspector, height=24.0), dd)
            rows.append(ed.prefab_choice)
            ed.prefab = str(m.path.parent / prefabs[0]) if m.path else None
        ed.inspector_rows = rows
        return
    entity = m.selection[0]
    keys = [m.key(e) for e in m.entities()]
    folder = m.path.parent if m.path else None
    assets = asset_files(folder)
    extra = f" (+{len(m.selection) - 1} more)" if len(m.selection) > 1 else ""
    rows.append(ui.spawn(UINode(parent=ed.inspector), Label(
        f"{m.key(entity)}{extra}", size=12.0, align="left")))
    r = row((Label("name", size=12.0, align="left"), 90.0),
            (TextInput(m.name(entity), max_length=200), 210.0))
    ed.name_box = rows[-1]
    del r
    for comp in m.world.components(entity):
        info = default_registry().info(type(comp))
        if info is None or info.name == "Name":
            continue
        row((Label(info.name, size=13.0, align="left"), 250.0), (Button("x"), 40.0))
        ed.remove_buttons[rows[-1]] = (entity, type(comp))
        for f in info.fields:
            if not f.init:
                continue
            value = getattr(comp, f.name)
            kind = kind_of(info, f.name, value, keys, assets)
            unit = " (deg)" if kind.widget == "angle" else ""
            text = show(kind, value, folder or Path.cwd(), m.key)
            widget: Any
            height = 24.0
            if kind.widget == "vector":  # x and y side by side
                label = (Label(f.name, size=12.0, align="left"), 130.0)
                row(label, *((_number_box(v, whole=isinstance(v, int)), 83.0) for v in value))
                for i, w in enumerate(rows[-2:]):
                    ed.widgets[w] = (entity, type(comp), f.name, FieldKind("vector", index=i))
                ed.labels[rows[-3]] = (entity, type(comp), f.name, kind)
                continue
            if kind.widget == "toggle":
                widget = Toggle(bool(value))
            elif kind.widget == "number":
                widget = _number_box(value, whole=isinstance(value, int))
            elif kind.widget == "angle":
                widget = SpinBox(math.degrees(value), step=0.0, drag_speed=0.5)
            elif kind.widget == "colour":
                widget = ColorPicker(tuple(value) + (255,) * (4 - len(value)),
                                     alpha=len(value) == 4)
                height = 90.0
            elif kind.widget == "choice":
                opts = list(kind.choices)
                if text not in opts:
                    opts.append(text)
                widget = Dropdown(opts, selected=opts.index(text))
                kind = FieldKind("choice", tuple(opts))
            else:
                widget = TextInput(text, max_length=4000)
            row((Label(f.name + unit, size=12.0, align="left"), 130.0), (widget, 170.0),
                height=height)
            ed.widgets[rows[-1]] = (entity, type(comp), f.name, kind)
            ed.labels[rows[-2]] = (entity, type(comp), f.name, kind)
    names = [n for n in default_registry().names(COMPONENT)
             if n != "Name" and default_registry().get(n) is not None]
    row((Dropdown(names, selected=0), 200.0), (Button("Add"), 90.0))
    ed.add_choice, ed.add_button = rows[-2], rows[-1]  # [.., the row, the list, the button]
    ed.inspector_rows = rows


def _number_box(value: float, whole: bool) -> SpinBox:
    """A number field: 0.02 per pixel dragged (0.1 for whole numbers), typed exactly."""
    return SpinBox(float(value), step=0.0, drag_speed=0.1 if whole else 0.02, rounded=whole)


def update_markers(ed: Editor) -> None:
    """Selection boxes, handles and grid lines: editor-only drawables in the edited world."""
    m = ed.model
    w = m.world
    wanted: list[tuple[tuple[float, float], Any]] = []
    for e in m.selection:
        if not w.exists(e) or not w.has(e, Transform):
            continue
        pose = m.world_pose(e)
        wanted.append(((pose[0], pose[1]), draw.Circle(0.12, color=(255, 210, 60, 255),
                                                       filled=False, layer=1000)))
        if ed.tool == "shape":
            for h in m.shape_handles(e):
                wanted.append((h, draw.Circle(0.08, color=(90, 200, 255, 255), layer=1001)))
    if ed.tool == "anchor":
        for e in m.selection:
            a = m.joint_anchor(e) if w.exists(e) else None
            if a is not None:
                wanted.append((a, draw.Circle(0.1, color=(255, 90, 200, 255), layer=1001)))
    while len(ed.markers) < len(wanted):
        ed.markers.append(w.spawn(EditorOnly(), Transform(), draw.Circle(0.1, visible=False)))
    for i, e in enumerate(ed.markers):
        if i < len(wanted):
            (x, y), shape = wanted[i]
            t = w.get(e, Transform)
            if (t.x, t.y) != (x, y):
                t.x, t.y = x, y
            if w.get(e, draw.Circle) != shape:
                w.add(e, shape)
        elif w.get(e, draw.Circle).visible:
            w.get(e, draw.Circle).visible = False
    grid_lines(ed)


def grid_lines(ed: Editor) -> None:
    """Lines every grid step over the visible area (at most 60 a side)."""
    m = ed.model
    w = m.world
    cam = m.camera
    sx, sy = ed.app.size
    x0, y0 = ed.to_world((0.0, 0.0))
    x1, y1 = ed.to_world((float(sx), float(sy)))
    step = m.grid if m.grid > 0 else 1.0
    while (x1 - x0) / step > 60:
        step *= 2
    key = (round(x0 / step), round(y0 / step), round(x1 / step), round(y1 / step), step)
    if ed.grid_key == key:
        return
    ed.grid_key = key
    lines: list[tuple[tuple[float, float], tuple[float, float]]] = []
    gx = math.floor(x0 / step) * step
    while gx <= x1:
        lines.append(((gx, y0), (gx, y1)))
        gx += step
    gy = math.floor(y0 / step) * step
    while gy <= y1:
        lines.append(((x0, gy), (x1, gy)))
        gy += step
    while len(ed.grid_lines) < len(lines):
        ed.grid_lines.append(w.spawn(EditorOnly(), Transform(), draw.Line(
            (0.0, 0.0), (1.0, 0.0), color=(255, 255, 255, 28), thickness=0.02, layer=-1000)))
    for i, e in enumerate(ed.grid_lines):
        if i < len(lines):
            a, b = lines[i]
            w.add(e, draw.Line(a, b, color=(255, 255, 255, 28),
                               thickness=1.0 / (cam.pixels_per_meter * cam.zoom), layer=-1000))
        else:
            w.add(e, draw.Line((0.0, 0.0), (1.0, 0.0), visible=False, layer=-1000))


def editor_app(
    path: str | os.PathLike[str] | None = None,
    *,
    headless: bool | None = None,
    size: tuple[int, int] = (1280, 800),
    hot_reload: bool = True,
) -> tuple[App, Editor]:
    """The editor on the scene file ``path`` (a new scene when None or missing)."""
    app = App(headless=headless, size=size, title=EDITOR_TITLE, background=(38, 42, 52))
    app.quit_on_close = False  # closing the window asks about unsaved changes first
    if hot_reload:
        from kge.hotreload import HotReloadPlugin

        app.add_plugins(HotReloadPlugin())
    scene = EditScene(path)
    app.push_scene(scene)
    assert scene.model is not None
    editor = Editor(app, app.world, scene.model)
    app.push_scene(EditorUI(editor), overlay=True)
    editor.frame()
    return app, editor
