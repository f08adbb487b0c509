"""Sprites land on the right pixels: position, zoom, rotation sense, layers, visibility."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import Transform
from kge.assets import AssetDecodeError
from kge.components.camera import Camera
from kge.components.sprite import Sprite
from kge.errors import ValidationError
from kge.render.images import from_array, solid
from kge.testing import write_png

from .conftest import SIZE, bbox, mask, pixels

RED, GREEN, BLUE = (255, 0, 0), (0, 255, 0), (0, 0, 255)


@pytest.mark.parametrize("zoom", [1.0, 2.0])
def test_red_box_at_known_world_position(make_app, zoom):
    def scene(world):
        world.insert_resource(Camera(center=(0.0, 0.0), pixels_per_meter=20, zoom=zoom))
        world.spawn(Transform(1.0, -0.5), Sprite(solid(4, 4, RED), size=(1.0, 1.0)))

    app = make_app(scene)
    x0, x1, y0, y1 = bbox(mask(pixels(app), RED))
    k = 20 * zoom
    cam = app.world.resource(Camera)
    cx, cy = cam.world_to_screen((1.0, -0.5), SIZE)
    assert (cx, cy) == (SIZE[0] / 2 + 1.0 * k, SIZE[1] / 2 - 0.5 * k)
    # a 1 m box covers k pixels centred on the projected point (+-1 px of rasterisation)
    assert abs(x0 - (cx - k / 2)) <= 1 and abs(x1 + 1 - (cx + k / 2)) <= 1
    assert abs(y0 - (cy - k / 2)) <= 1 and abs(y1 + 1 - (cy + k / 2)) <= 1


def test_default_size_is_image_pixels_over_pixels_per_meter(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=10))
        world.spawn(Transform(), Sprite(solid(30, 10, RED)))

    x0, x1, y0, y1 = bbox(mask(pixels(make_app(scene)), RED))
    assert (x1 - x0 + 1, y1 - y0 + 1) == (30, 10)


def test_rotation_is_counter_clockwise_positive(make_app):
    # a 3 m x 0.4 m bar turned +45 degrees must rise to the right (CCW), not fall
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(0.0, 0.0, math.pi / 4), Sprite(solid(4, 4, RED), size=(3.0, 0.4)))

    m = mask(pixels(make_app(scene)), RED)
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    d = 18  # ~0.9 m along the diagonal
    assert m[cy + d, cx + d] and m[cy - d, cx - d]
    assert not m[cy - d, cx + d] and not m[cy + d, cx - d]


def test_layers_and_order_decide_what_is_on_top(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), Sprite(solid(2, 2, RED), size=(2, 2), layer=2))
        world.spawn(Transform(), Sprite(solid(2, 2, GREEN), size=(2, 2), layer=1))
        world.spawn(Transform(0.0, 2.5), Sprite(solid(2, 2, BLUE), size=(2, 2), order=5))
        world.spawn(Transform(0.0, 2.5), Sprite(solid(2, 2, GREEN), size=(2, 2), order=1))

    app = make_app(scene)
    px = pixels(app)
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    assert mask(px, RED)[cy, cx]  # layer 2 over layer 1, whatever the spawn order
    assert mask(px, BLUE)[cy + 50, cx]  # order 5 over order 1 in the same layer
    # moving the green one up a layer at run time re-sorts it
    for _e, (s,) in app.world.query(Sprite):
        if s.layer == 1:
            s.layer = 3
    assert mask(pixels(app), GREEN)[cy, cx]


def test_hidden_sprite_draws_nothing(make_app):
    def scene(world):
        world.spawn(Transform(), Sprite(solid(4, 4, RED), size=(1, 1), visible=False))

    app = make_app(scene)
    assert not mask(pixels(app), RED).any()
    ((_, (s,)),) = app.world.query(Sprite)
    s.visible = True
    assert mask(pixels(app), RED).any()


def test_despawned_sprite_disappears(make_app):
    def scene(world):
        world.spawn(Transform(), Sprite(solid(4, 4, RED), size=(1, 1)))

    app = make_app(scene)
    assert mask(pixels(app), RED).any()
    ((e, _),) = app.world.query(Sprite)
    app.world.despawn(e)
    app.world.flush()
    assert not mask(pixels(app), RED).any()


def _two_tone():
    arr = np.zeros((2, 4, 3), np.uint8)
    arr[:, :2] = RED
    arr[:, 2:] = BLUE
    return from_array(arr)


def test_flip_x_mirrors_about_the_pivot(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), Sprite(_two_tone(), size=(4, 2)))

    app = make_app(scene)
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    px = pixels(app)
    assert mask(px, RED)[cy, cx - 20] and mask(px, BLUE)[cy, cx + 20]
    ((_, (s,)),) = app.world.query(Sprite)
    s.flip_x = True
    px = pixels(app)
    assert mask(px, BLUE)[cy, cx - 20] and mask(px, RED)[cy, cx + 20]


def test_sprite_sheet_grid_frame_and_rectangle(make_app):
    sheet = np.zeros((2, 2, 3), np.uint8)  # top row: red, green; bottom row: blue, white
    sheet[0, 0], sheet[0, 1], sheet[1, 0], sheet[1, 1] = RED, GREEN, BLUE, (255, 255, 255)
    img = from_array(sheet)

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(-2, 0), Sprite(img, size=(1, 1), region=1, grid=(2, 2)))
        world.spawn(Transform(2, 0), Sprite(img, size=(1, 1), region=(0, 1, 1, 1)))

    px = pixels(make_app(scene))
    cx, cy = SIZE[0] // 2, SIZE[1] // 2
    assert mask(px, GREEN)[cy, cx - 40]  # frame 1 = top row, second column
    assert mask(px, BLUE)[cy, cx + 40]  # pixel rect from the top-left: second row


def test_tint_and_opacity(make_app):
    def scene(world):
        world.spawn(
            Transform(),
            Sprite(solid(4, 4, (255, 255, 255)), size=(1, 1), tint=(255, 0, 0), opacity=128),
        )

    px = pixels(make_app(scene))
    r, g, b = px[SIZE[1] // 2, SIZE[0] // 2, :3]
    assert 110 <= r <= 145 and g < 10 and b < 10  # half red over black


def test_unknown_image_is_refused_at_spawn_not_at_the_first_frame(make_app, tmp_path):
    from kge.assets import AssetNotFoundError

    app = make_app(lambda world: None)
    world = app.world
    with pytest.raises(AssetNotFoundError, match=r"Sprite.image: asset .*missing.png' not found"):
        world.spawn(Transform(), Sprite(str(tmp_path / "missing.png")))
    assert world.entities() == []  # nothing half-spawned
    e = world.spawn(Transform())
    with pytest.raises(AssetNotFoundError, match=f"entity {e}, Sprite.image"):
        world.add(e, Sprite(str(tmp_path / "missing.png")))
    assert not world.has(e, Sprite)


def test_bad_values_are_refused_at_the_write():
    s = Sprite(solid(2, 2, RED))
    with pytest.raises(ValidationError, match="Sprite.size"):
        s.size = (0.0, 1.0)
    with pytest.raises(ValidationError, match="outside the 2x2 grid"):
        Sprite(solid(2, 2), region=4, grid=(2, 2)).frame_rect(2, 2)


def test_screenshot_writes_a_png(make_app, tmp_path):
    def scene(world):
        world.spawn(Transform(), Sprite(solid(4, 4, RED), size=(1, 1)))

    app = make_app(scene)
    out = tmp_path / "shot.png"
    app.screenshot(out)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_mouse_world_position_uses_the_camera(make_app):
    def scene(world):
        world.insert_resource(Camera(center=(3.0, 1.0), pixels_per_meter=20, zoom=2))

    app = make_app(scene)
    app.render()
    app.input.move_mouse(SIZE[0] / 2 + 40, SIZE[1] / 2)
    assert app.input.mouse_world == pytest.approx((4.0, 1.0))


def test_culling_keeps_far_sprites_out_and_brings_them_back(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(100.0, 0.0), Sprite(solid(4, 4, RED), size=(1, 1)))

    app = make_app(scene)
    from kge.systems.render import RenderSystem

    app.render()
    view = app.world.get_system(RenderSystem).view
    assert view.culled == 1
    app.world.resource(Camera).center = (100.0, 0.0)
    assert mask(pixels(app), RED).any() and view.culled == 0


def test_animating_the_region_reuses_the_sprite(make_app):
    sheet = np.zeros((1, 2, 3), np.uint8)
    sheet[0, 0], sheet[0, 1] = RED, GREEN
    img = from_array(sheet)

    def scene(world):
        world.spawn(Transform(), Sprite(img, size=(1, 1), region=0, grid=(2, 1)))

    app = make_app(scene)
    from kge.systems.render import RenderSystem

    assert mask(pixels(app), RED).any()
    view = app.world.get_system(RenderSystem).view
    before = dict(view.sprites.sprites)
    ((_, (s,)),) = app.world.query(Sprite)
    s.region = 1  # next animation frame
    px = pixels(app)
    assert mask(px, GREEN).any() and not mask(px, RED).any()
    assert view.sprites.sprites == before  # same pyglet sprite, new texture coordinates


def test_pixels_per_meter_change_resizes_default_sized_sprites(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=10))
        world.spawn(Transform(), Sprite(solid(20, 10, RED)))

    app = make_app(scene)
    x0, x1, _, _ = bbox(mask(pixels(app), RED))
    assert x1 - x0 + 1 == 20  # 2 m at 10 px/m
    app.world.resource(Camera).pixels_per_meter = 20
    x0, x1, _, _ = bbox(mask(pixels(app), RED))
    assert x1 - x0 + 1 == 20  # still image pixels: 1 m at 20 px/m


def test_a_new_scene_draws_its_own_world(make_app):
    def first(world):
        world.spawn(Transform(), Sprite(solid(4, 4, RED), size=(1, 1)))

    def second(world):
        world.spawn(Transform(), Sprite(solid(4, 4, BLUE), size=(1, 1)))

    app = make_app(first)
    assert mask(pixels(app), RED).any()
    app.replace_scene(second)
    px = pixels(app)
    assert mask(px, BLUE).any() and not mask(px, RED).any()
    app.push_scene(first)
    app.pop_scene()
    assert mask(pixels(app), BLUE).any()


def test_a_bad_image_does_not_lose_other_sprites(make_app, tmp_path):
    state = {}
    png = tmp_path / "nope.png"
    write_png(np.full((2, 2, 4), 255, np.uint8), png)  # a good header at spawn...

    def scene(world):
        state["bad"] = world.spawn(Transform(), Sprite(str(png)))
        world.spawn(Transform(2, 0), Sprite(solid(4, 4, RED), size=(1, 1)))

    app = make_app(scene)
    png.write_bytes(b"not a png")  # ...then the file breaks before the first draw
    with pytest.raises(ValidationError, match=f"entity {state['bad']}, Sprite.image"):
        app.render()
    app.world.get(state["bad"], Sprite).image = solid(2, 2, BLUE)  # fixed: both draw now
    px = pixels(app)
    assert mask(px, RED).any() and mask(px, BLUE).any()


def test_an_undecodable_image_is_refused_at_the_spawn(make_app, tmp_path):
    (tmp_path / "nope.png").write_bytes(b"not a png")
    app = make_app(lambda world: None)
    before = sorted(app.world.entities())
    with pytest.raises(AssetDecodeError, match=r"Sprite\.image: asset .*nope\.png.* not an image"):
        app.world.spawn(Transform(), Sprite(str(tmp_path / "nope.png")))
    assert sorted(app.world.entities()) == before


def test_sprites_keep_moving_after_a_neighbour_is_despawned(make_app):
    # a hole in the vertex domain switches the bulk writer to its indexed path
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        for x in (-3.0, 0.0, 3.0):
            world.spawn(Transform(x, 0.0), Sprite(solid(2, 2, RED), size=(1, 1)))

    app = make_app(scene)
    app.render()
    ents = sorted(e for e, _ in app.world.query(Sprite))
    app.world.despawn(ents[1])
    app.world.flush()
    for e in (ents[0], ents[2]):
        app.world.get(e, Transform).y = 2.0
    from kge.systems.render import RenderSystem

    m = mask(pixels(app), RED)
    domain = next(iter(app.world.get_system(RenderSystem).view.sprites.poser._domains.values()))
    assert not domain.block
    cy = SIZE[1] // 2
    assert m[cy + 40, SIZE[0] // 2 - 60] and m[cy + 40, SIZE[0] // 2 + 60]
    assert not m[cy, SIZE[0] // 2] and not m[cy, SIZE[0] // 2 - 60]


def test_renaming_an_image_to_a_missing_file_is_refused_at_the_write(make_app, tmp_path):
    from kge.assets import AssetNotFoundError

    app = make_app(lambda world: None)
    e = app.world.spawn(Transform(), Sprite(solid(2, 2, RED)))
    sprite = app.world.get(e, Sprite)
    with pytest.raises(AssetNotFoundError, match=f"entity {e}, Sprite.image"):
        sprite.image = str(tmp_path / "missing.png")
    assert sprite.image is not None and not isinstance(sprite.image, str)  # unchanged
