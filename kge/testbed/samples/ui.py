"""UI samples: a widget gallery, layouts that follow the window, a see-through pause
overlay, and scene transitions. The editor widgets, scrolling and lists, dialogs and
drag and drop, and UI in the world are in ``ui_editor``, ``ui_lists``, ``ui_overlays``
and ``ui_world``; ``ui_parts`` holds what they share."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour, Script, Transform
from kge.components.drawables import Rect
from kge.components.ui import (
    Button,
    Dropdown,
    Label,
    Panel,
    ProgressBar,
    RadioGroup,
    RichText,
    ScrollList,
    Slider,
    SpinBox,
    Style,
    Tabs,
    TextInput,
    Toggle,
    UIImage,
    UINode,
)
from kge.host import Host
from kge.keys import Key
from kge.render.images import checker
from kge.testbed.registry import sample
from kge.testbed.samples.build import box, static_box
from kge.testbed.samples.ui_parts import Status, column, root_area, tip
from kge.transition_shaders import Iris, ShaderTransition
from kge.transitions import Crossfade, Fade, Slide, Transition, Wipe
from kge.ui.events import ButtonClicked
from kge.ui.interact import UIState
from kge.world import World


@sample("UI", "Widget Gallery",
        help="Every basic widget: click, drag, type, Tab/arrows/Enter, d-pad; hover for tips.")
def widget_gallery(world: World) -> None:
    root = root_area(world)
    left = column(world, parent=root, anchor="left", offset=(16, 0), width=300)
    world.spawn(UINode(parent=left), Label("Widgets", size=22))
    tip(world, world.spawn(UINode(parent=left, height=38), Button("Button")), "Emits ButtonClicked")
    row = world.spawn(UINode(parent=left, layout="row", spacing=8))
    world.spawn(UINode(parent=row, grow=1, height=38), Button("Disabled", disabled=True))
    world.spawn(UINode(parent=row, grow=1, height=38), Button("Delete"),
                Style(background=(190, 50, 60, 255), radius=19, bold=True))  # a per-widget style
    world.spawn(UINode(parent=left), Toggle(True, "Toggle"))
    world.spawn(UINode(parent=left, height=26), Slider(0, 100, 40, step=5))
    world.spawn(UINode(parent=left, height=14), ProgressBar(0.65))
    world.spawn(UINode(parent=left), TextInput(placeholder="type here", max_length=24))
    world.spawn(UINode(parent=left), Dropdown(["Easy", "Normal", "Hard"], 1))
    spin = world.spawn(UINode(parent=left), SpinBox(12.5, 0, 100, 0.5, suffix=" m"))
    tip(world, spin, "Drag sideways, or click and type")
    world.spawn(UINode(parent=left), RadioGroup(["Low", "Mid", "High"], 1, horizontal=True))
    middle = column(world, parent=root, anchor="center", offset=(20, 40), width=320)
    tabs = world.spawn(UINode(parent=middle, height=190), Tabs(["Audio", "Video", "About"]))
    audio = world.spawn(UINode(parent=tabs, layout="column", padding=10, spacing=8,
                               align="stretch"))  # fmt: skip
    world.spawn(UINode(parent=audio), Label("Music", align="left"))
    world.spawn(UINode(parent=audio, height=24), Slider(0, 1, 0.8))
    world.spawn(UINode(parent=audio), Toggle(False, "Mute"))
    video = world.spawn(UINode(parent=tabs, layout="column", padding=10, spacing=8,
                               align="stretch"))  # fmt: skip
    world.spawn(UINode(parent=video), Toggle(True, "Fullscreen"))
    world.spawn(UINode(parent=video), Dropdown(["1280 x 720", "1920 x 1080"], 0))
    world.spawn(UINode(parent=tabs, padding=10), RichText(
        "[b]kge[/b] UI: widgets are [color=#2ec4b6]entities[/color], themes are "
        "[i]data[/i], and every frame is [size=20]testable[/size] headless."))  # fmt: skip
    right = column(world, parent=root, anchor="right", offset=(-16, 0), width=240)
    world.spawn(UINode(parent=right), Label("Scroll list", size=18))
    rows = [f"Level {i + 1}" for i in range(30)]
    world.spawn(UINode(parent=right, height=180), ScrollList(rows))
    icons = world.spawn(UINode(parent=right, layout="row", spacing=8, justify="center"))
    art = checker(16, 16, 4, (46, 196, 182), (30, 34, 44))
    world.spawn(UINode(parent=icons, width=48, height=48), UIImage(art))
    world.spawn(UINode(parent=icons, width=120, height=48), Button("Icon", image=art))
    status = world.spawn(UINode(parent=root, anchor="bottom", offset=(0, 16)),
                         Label("Click something"))  # fmt: skip
    world.spawn(Behaviour(Status(status)))


@widget_gallery.claim
def _gallery_reports_a_click(app: Any) -> None:
    world = app.world
    button = next(e for e, (b,) in world.query(Button) if b.text == "Button")
    app.input.click(at=world.resource(UIState).layout.boxes[button].center)
    app.step()
    assert any(lbl.text == "ButtonClicked: Button" for _, (lbl,) in world.query(Label))


@sample("UI", "Resizing Layout", help="HUD in the corners, a percent-wide bar, a grid: resize!")
def resizing_layout(world: World) -> None:
    root = root_area(world)
    for name in ("top_left", "top_right", "bottom_left", "bottom_right"):
        x = 12 if "left" in name else -12
        y = -12 if "top" in name else 12
        align = "left" if "left" in name else "right"
        label = Label(name.replace("_", " "), align=align)
        world.spawn(UINode(parent=root, anchor=name, offset=(x, y)), label)
    bar = UINode(parent=root, anchor="bottom", offset=(0, 48), width="60%", height=18)
    world.spawn(bar, ProgressBar(0.4))
    grid_node = UINode(parent=root, width="50%", height="40%", layout="grid", columns=3,
                       padding=10, spacing=8)  # fmt: skip
    grid = world.spawn(grid_node, Panel())
    for i in range(6):
        world.spawn(UINode(parent=grid, height=40), Button(f"Cell {i + 1}"))


@resizing_layout.claim
def _corners_follow_the_window(app: Any) -> None:
    world = app.world
    for size in ((1200, 700), (500, 400)):
        app.size = size
        app.step()
        boxes = world.resource(UIState).layout.boxes
        (corner,) = [
            e for e, (node, _) in world.query(UINode, Label) if node.anchor == "bottom_right"
        ]
        b = boxes[corner]
        assert abs(b.right - (size[0] - 12)) < 1e-6 and abs(b.y - 12) < 1e-6
        (bar,) = [e for e, _ in world.query(ProgressBar)]
        assert abs(boxes[bar].w - 0.6 * 0.85 * size[0]) < 1e-6


class _Pause(Script):
    """P or Escape (or the HUD button) opens the see-through pause overlay."""

    def on_update(self, dt: float) -> None:
        inp = self.world.resource(Host).input
        clicked = any(b.text == "Pause" for ev in self.world.events(ButtonClicked)
                      for b in [self.world.get(ev.entity, Button)])  # fmt: skip
        if inp.pressed(Key.P) or inp.pressed(Key.ESCAPE) or clicked:
            self.world.resource(Host).push_scene(pause_menu, overlay=True)


def pause_menu(world: World) -> None:
    """A see-through overlay: the game below is frozen and stays visible."""
    world.spawn(UINode(width="100%", height="100%"), Panel(color=(0, 0, 0, 110), radius=0))
    menu = column(world, width=240)
    world.spawn(UINode(parent=menu), Label("Paused", size=24))
    resume = world.spawn(UINode(parent=menu, height=40), Button("Resume"))
    world.spawn(Behaviour(_Resume(resume)))
    from kge.systems.ui import focus

    focus(world, resume)


class _Resume(Script):
    def __init__(self, button: int) -> None:
        self.button = button

    def on_update(self, dt: float) -> None:
        inp = self.world.resource(Host).input
        clicked = any(ev.entity == self.button for ev in self.world.events(ButtonClicked))
        if clicked or inp.pressed(Key.ESCAPE):
            self.world.resource(Host).pop_scene()


@sample("UI", "Pause Overlay", help="P, Escape or the button: a see-through pause menu.")
def pause_overlay(world: World) -> None:
    ground = static_box(world, 0.0, -1.0, 30.0, 1.0, name="ground")
    world.add(ground, Rect(60.0, 2.0, color=(90, 96, 110, 255)))
    for i in range(12):
        crate = box(world, -5.5 + i, 2.0 + 1.5 * (i % 4), 0.4, 0.4, density=1.0, name="crate")
        world.add(crate, Rect(0.8, 0.8, color=(230, 160, 60, 255)))
    corner = UINode(parent=root_area(world), anchor="top_right", offset=(-12, -12), width=90,
                    height=34)  # fmt: skip
    world.spawn(corner, Button("Pause"))
    world.spawn(Behaviour(_Pause()))


@pause_overlay.claim
def _overlay_freezes_the_game(app: Any) -> None:
    game = app.world
    app.input.press(Key.P)
    app.step()
    app.input.release(Key.P)
    assert app.world is not game and app.visible_worlds() == [game, app.world]
    poses = [(t.x, t.y) for _, (t,) in game.query(Transform)]
    app.step(30)
    assert [(t.x, t.y) for _, (t,) in game.query(Transform)] == poses
    app.input.press(Key.ESCAPE)
    app.step()
    assert app.world is game


#: a user-shader transition: the old picture breaks up into blocks of ``grain`` pixels
DISSOLVE = """
uniform float grain;
vec4 transition(sampler2D old_scene, vec2 uv, float progress) {
    float n = fract(sin(dot(floor(uv * resolution / grain), vec2(12.9898, 78.233))) * 43758.5);
    return n < progress ? vec4(0.0) : texture(old_scene, uv);
}
"""

_KINDS: dict[str, Transition] = {
    "Fade": Fade(0.5),
    "Crossfade": Crossfade(0.6),
    "Slide": Slide(0.6, direction="left"),
    "Wipe": Wipe(0.6, direction="up"),
    "Iris": Iris(0.8, center=(0.5, 0.5)),
    "Dissolve": ShaderTransition(DISSOLVE, 0.8, uniforms={"grain": 6.0}),
}


class _Switch(Script):
    def __init__(self, target: Any) -> None:
        self.target = target

    def on_update(self, dt: float) -> None:
        for ev in self.world.events(ButtonClicked):
            kind = self.world.get(ev.entity, Button).text
            self.world.resource(Host).replace_scene(self.target, transition=_KINDS[kind])


def _room(world: World, title: str, color: tuple[int, int, int, int], target: Any) -> None:
    root = root_area(world)
    world.spawn(UINode(parent=root, width="100%", height="100%"), Panel(color=color, radius=0))
    col = column(world, parent=root, width=260)
    world.spawn(UINode(parent=col), Label(title, size=26))
    for kind in _KINDS:
        world.spawn(UINode(parent=col, height=36), Button(kind))
    world.spawn(Behaviour(_Switch(target)))


def _blue_room(world: World) -> None:
    _room(world, "Blue room", (30, 60, 140, 255), _red_room)


def _red_room(world: World) -> None:
    _room(world, "Red room", (140, 40, 40, 255), _blue_room)


@sample("UI", "Scene Transitions",
        help="Fade, crossfade, slide, wipe, iris and a dissolve shader between two rooms.")
def scene_transitions(world: World) -> None:
    _blue_room(world)


@scene_transitions.claim
def _a_button_fades_to_the_other_room(app: Any) -> None:
    world = app.world
    fade = next(e for e, (b,) in world.query(Button) if b.text == "Fade")
    app.input.click(at=world.resource(UIState).layout.boxes[fade].center)
    app.step()
    assert app.transition is not None and app.world is world
    app.step(40)
    assert app.transition is None and app.world is not world
    assert any(lbl.text == "Red room" for _, (lbl,) in app.world.query(Label))
    red = app.world
    iris = next(e for e, (b,) in red.query(Button) if b.text == "Iris")
    app.input.click(at=red.resource(UIState).layout.boxes[iris].center)
    app.step(60)
    assert app.transition is None and app.world is not red
