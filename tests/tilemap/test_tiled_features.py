"""Tiled features drawn as Tiled draws them (8-bit headless frames, TMX written as Tiled does):
transparent colours, background colour, repeated image layers, object layer opacity / tint /
visibility / offset, hidden objects, text objects, and tile objects on parallax layers that
move, turn and go away with their entities."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from kge import App, RigidBody, Sprite, Text, Transform
from kge.components.camera import Camera
from kge.components.tilemap import MapObject
from kge.testbed import png
from kge.tilemap import load_map

from .test_drawing import SIZE, Near, at, render

GREEN, WHITE, MAGENTA = (40, 200, 60), (250, 250, 250), (255, 0, 255)


def write(folder: Path, layers: str, map_attrs: str = "", trans: str = "") -> Path:
    """A 10 x 8 map of 16 px tiles: tile 0 green with a magenta top-left quarter, tile 1
    white with a black top-left quarter."""
    sheet = np.zeros((16, 32, 4), np.uint8)
    sheet[..., 3] = 255
    sheet[:, :16, :3] = GREEN
    sheet[:8, :8, :3] = MAGENTA
    sheet[:, 16:, :3] = WHITE
    sheet[:8, 16:24, :3] = 0
    png.write(folder / "t.png", sheet)
    png.write(folder / "sky.png", np.full((16, 32, 4), (20, 60, 250, 255), np.uint8))
    t = f' trans="{trans}"' if trans else ""
    text = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<map version="1.10" tiledversion="1.10.2" orientation="orthogonal" '
        'renderorder="right-down" width="10" height="8" tilewidth="16" tileheight="16" '
        f'infinite="0" nextlayerid="9" nextobjectid="9"{map_attrs}>'
        '<tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="2" columns="2">'
        f'<image source="t.png" width="32" height="16"{t}/></tileset>'
        f"{layers}</map>\n"
    )
    path = folder / "m.tmx"
    path.write_text(text)
    return path


def tile_layer(cells: dict[tuple[int, int], int]) -> str:
    g = np.zeros((8, 10), np.int64)
    for (c, r), gid in cells.items():
        g[r, c] = gid
    csv = ",\n".join(",".join(str(v) for v in row) for row in g)
    return f'<layer id="1" name="Ground" width="10" height="8"><data encoding="csv">{csv}</data></layer>'


def setup_for(path: Path, made: list[Any] | None = None) -> Any:
    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=20))
        m = load_map(world, path)
        if made is not None:
            made.append(m)

    return setup


def test_a_tilesets_transparent_colour_is_keyed_out(tmp_path: Path, apps: list[App]) -> None:
    path = write(tmp_path, tile_layer({(2, 2): 1}), trans="ff00ff")
    _, px = render(apps, setup_for(path))
    # cell (2, 2): x in [2, 3), y in [5, 6); its top-left quarter was magenta
    assert at(px, 2.25, 5.75) == (0, 0, 0)
    assert at(px, 2.75, 5.75) == GREEN and at(px, 2.25, 5.25) == GREEN
    path = write(tmp_path, tile_layer({(2, 2): 1}))  # without trans: magenta stays
    _, px = render(apps, setup_for(path))
    assert at(px, 2.25, 5.75) == MAGENTA


def test_the_maps_background_colour_fills_the_view(tmp_path: Path, apps: list[App]) -> None:
    path = write(tmp_path, tile_layer({(2, 2): 2}), map_attrs=' backgroundcolor="#3050a0"')
    _, px = render(apps, setup_for(path))
    assert at(px, 7.5, 1.5) == (48, 80, 160)  # an empty cell
    assert at(px, 2.75, 5.25) == WHITE  # tiles over it
    assert at(px, 5.0 - SIZE[0] / 40 + 0.05, 4.0) == (48, 80, 160)  # the view's left edge


def test_an_image_layer_repeats_along_x(tmp_path: Path, apps: list[App]) -> None:
    layer = ('<imagelayer id="3" name="Sky" offsetx="8" offsety="16" repeatx="1">'
             '<image source="sky.png" width="32" height="16"/></imagelayer>')  # fmt: skip
    path = write(tmp_path, layer)
    _, px = render(apps, setup_for(path))
    sky = (20, 60, 250)
    # y from 8 - 1 - 1 = 6 to 7 m (16 px down from the top); repeated every 2 m from x = 0.5
    for x in (0.2, 1.5, 3.9, 6.1, 9.8):
        assert at(px, x, 6.5) == sky, x
    assert at(px, 5.0, 5.5) == (0, 0, 0) and at(px, 5.0, 7.5) == (0, 0, 0)  # not along y


def test_object_layer_opacity_tint_visibility_and_offset(tmp_path: Path, apps: list[App]) -> None:
    obj = '<object id="{id}" gid="2" x="{x}" y="48" width="16" height="16"{extra}/>'
    layers = (
        '<objectgroup id="2" name="Styled" opacity="0.5" tintcolor="#ff0000" offsetx="16">'
        + obj.format(id=1, x=16, extra="")
        + obj.format(id=2, x=64, extra=' visible="0"')
        + '</objectgroup><objectgroup id="3" name="Hidden" visible="0">'
        + obj.format(id=3, x=112, extra="")
        + '</objectgroup><objectgroup id="4" name="Words">'
        '<object id="4" name="sign" x="16" y="96" width="64" height="16">'
        '<text pixelsize="12" color="#ffffff" halign="center">Hello</text></object>'
        "</objectgroup>"
    )
    made: list[Any] = []
    app, px = render(apps, setup_for(write(tmp_path, layers), made))
    world = app.world
    by_id = {world.get(e, MapObject).id: e for e in made[0].objects}
    s1 = world.get(by_id[1], Sprite)
    assert (s1.opacity, s1.tint, s1.visible) == (128, (255, 0, 0), True)
    assert (world.get(by_id[1], Transform).x, world.get(by_id[1], Transform).y) == (2.5, 5.5)
    assert world.get(by_id[2], Sprite).visible is False  # the object's own visible="0"
    assert world.get(by_id[3], Sprite).visible is False  # its layer is hidden
    assert world.get(by_id[4], Text).text == "Hello"
    # drawn: white tinted red at half opacity over black, moved 1 m right by the offset
    assert at(px, 2.75, 5.25) == Near((125, 0, 0))
    assert at(px, 1.75, 5.25) == (0, 0, 0)
    assert at(px, 5.5, 5.5) == (0, 0, 0) and at(px, 7.5, 5.5) == (0, 0, 0)


def test_tile_objects_on_a_parallax_layer_follow_their_entities(
    tmp_path: Path, apps: list[App]
) -> None:
    """Parallax 0.5 from the map's top-left (0, 8): with the camera at (5, 4) the layer is
    drawn moved by ((5 - 0) * 0.5, (4 - 8) * 0.5) = (2.5, -2) m. The object (x 2..3,
    y 4..5 m, a kinematic body) is drawn at x 4.5..5.5, y 2..3, then moves and turns."""
    layers = (
        '<objectgroup id="2" name="Far" parallaxx="0.5" parallaxy="0.5">'
        '<object id="1" gid="2" x="32" y="64" width="16" height="16"><properties>'
        '<property name="collider" type="bool" value="true"/>'
        '<property name="body" value="kinematic"/></properties></object></objectgroup>'
    )
    made: list[Any] = []
    app, px = render(apps, setup_for(write(tmp_path, layers), made))
    (e,) = made[0].objects
    assert at(px, 5.25, 2.25) == WHITE and at(px, 4.75, 2.75) == (0, 0, 0)  # black top-left
    assert at(px, 2.5, 4.5) == (0, 0, 0)  # not at its own place
    from kge.render.setup import frame_pixels

    app.world.get(e, RigidBody).velocity = (2.0, 0.0)
    app.step(30)  # 0.5 s at 2 m/s: 1 m right
    assert abs(app.world.get(e, Transform).x - 3.5) < 1e-6
    app.render()
    px = frame_pixels(app)
    assert at(px, 6.25, 2.25) == WHITE and at(px, 5.75, 2.75) == (0, 0, 0)
    assert at(px, 5.25, 2.25) == (0, 0, 0)  # left its old place
    app.world.get(e, RigidBody).velocity = (0.0, 0.0)
    app.world.get(e, Transform).angle = math.pi  # half a turn: the black quarter at the bottom right
    app.render()
    px = frame_pixels(app)
    assert at(px, 6.25, 2.25) == (0, 0, 0) and at(px, 5.75, 2.75) == WHITE
    app.world.despawn(e)
    app.step(1)
    app.render()
    px = frame_pixels(app)
    assert at(px, 6.25, 2.75) == (0, 0, 0) and at(px, 5.75, 2.25) == (0, 0, 0)


def test_an_image_layer_repeats_along_y(tmp_path: Path, apps: list[App]) -> None:
    layer = ('<imagelayer id="3" name="Sky" offsetx="32" repeaty="1">'
             '<image source="sky.png" width="32" height="16"/></imagelayer>')  # fmt: skip
    _, px = render(apps, setup_for(write(tmp_path, layer)))
    sky = (20, 60, 250)
    for y in (0.2, 1.5, 3.9, 6.1, 7.8):  # x from 2 to 4 m, every row of the map
        assert at(px, 3.0, y) == sky, y
    assert at(px, 1.5, 4.0) == (0, 0, 0) and at(px, 4.5, 4.0) == (0, 0, 0)  # not along x


def test_tile_objects_are_drawn_flipped_and_rotated(tmp_path: Path, apps: list[App]) -> None:
    """Tile 2 is white with a black top-left quarter. Tiled places a tile object by its
    bottom-left corner and turns it clockwise about that corner."""
    obj = '<object id="{id}" gid="{gid}" x="{x}" y="48" width="16" height="16"{extra}/>'
    flip_h, flip_v = 0x80000000, 0x40000000
    layers = (
        '<objectgroup id="2" name="Things">'
        + obj.format(id=1, gid=2, x=16, extra="")  # x 1..2, y 5..6 m
        + obj.format(id=2, gid=2 | flip_h, x=48, extra="")  # x 3..4
        + obj.format(id=3, gid=2 | flip_v, x=80, extra="")  # x 5..6
        + obj.format(id=4, gid=2, x=112, extra=' rotation="90"')  # x 7..8, y 4..5 m
        + "</objectgroup>"
    )
    _, px = render(apps, setup_for(write(tmp_path, layers)))
    assert at(px, 1.25, 5.75) == (0, 0, 0) and at(px, 1.75, 5.75) == WHITE  # as drawn
    assert at(px, 3.75, 5.75) == (0, 0, 0) and at(px, 3.25, 5.75) == WHITE  # mirrored
    assert at(px, 5.25, 5.25) == (0, 0, 0) and at(px, 5.25, 5.75) == WHITE  # upside down
    # a quarter turn clockwise: the top-left corner goes to the top right, below y 5
    assert at(px, 7.75, 4.75) == (0, 0, 0) and at(px, 7.25, 4.75) == WHITE
    assert at(px, 7.5, 5.5) == (0, 0, 0) and at(px, 7.25, 4.25) == WHITE


def test_groups_nest_every_layer_kind_and_pass_their_style_down(
    tmp_path: Path, apps: list[App]
) -> None:
    """A group (opacity 0.5, offset 1 m right) holding a tile layer, an object layer with
    a tile object, an image layer and a group (tint red, offset 1 m down) with a tile layer:
    each is drawn with the styles of all its groups combined."""
    cells = tile_layer({(2, 2): 2}).replace('name="Ground"', 'name="Tiles"')
    inner = tile_layer({(6, 2): 2}).replace('id="1" name="Ground"', 'id="7" name="Deep"')
    layers = (
        '<group id="5" name="Outer" opacity="0.5" offsetx="16">'
        + cells
        + '<objectgroup id="2" name="Things">'
        '<object id="1" gid="2" x="64" y="48" width="16" height="16"/></objectgroup>'
        '<imagelayer id="3" name="Sky" offsety="96"><image source="sky.png" width="32" '
        'height="16"/></imagelayer>'
        '<group id="6" name="Inner" tintcolor="#ff0000" offsety="16">' + inner + "</group>"
        "</group>"
    )
    _, px = render(apps, setup_for(write(tmp_path, layers)))
    half_white, half_red = Near((125, 125, 125)), Near((125, 0, 0))
    assert at(px, 3.75, 5.25) == half_white and at(px, 2.75, 5.25) == (0, 0, 0)  # tile, moved
    assert at(px, 5.75, 5.25) == half_white and at(px, 4.75, 5.25) == (0, 0, 0)  # tile object
    assert at(px, 2.0, 1.5) == Near((10, 30, 125))  # image layer: x 1..3, y 1..2 m
    assert at(px, 7.75, 4.25) == half_red and at(px, 7.25, 4.75) == (0, 0, 0)  # nested group
    assert at(px, 7.75, 5.25) == (0, 0, 0)  # not at its own row
