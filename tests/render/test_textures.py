"""Texture options per image: filtering, mipmaps, repeat and mirror, nine-patch, regions,
and animation atlases that grow for large sprite sheets."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import Animator, Clip, Transform
from kge.components.camera import Camera
from kge.components.sprite import Sprite, TextureFilter, TextureWrap
from kge.errors import ValidationError
from kge.render.images import ImageRegion, PixelImage, checker, from_array

from .conftest import SIZE, bbox, mask, pixels

BLACK_WHITE = PixelImage(2, 1, bytes([0, 0, 0, 255, 255, 255, 255, 255]))


def _row(make_app, sprite: Sprite, ppm: float = 20.0) -> np.ndarray:
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=ppm))
        world.spawn(Transform(), sprite)

    return pixels(make_app(scene, background=(255, 0, 0)))[SIZE[1] // 2, :, :3].astype(int)


def test_nearest_keeps_pixel_edges_linear_blends_them(make_app):
    nearest = _row(make_app, Sprite(BLACK_WHITE, size=(4.0, 1.0)))
    linear = _row(make_app, Sprite(BLACK_WHITE, size=(4.0, 1.0), filter=TextureFilter.LINEAR))
    inside = slice(SIZE[0] // 2 - 38, SIZE[0] // 2 + 38)
    assert set(np.unique(nearest[inside, 1])) == {0, 255}
    mids = ((linear[inside, 1] > 10) & (linear[inside, 1] < 245)).sum()
    assert mids > 30  # a gradient across the middle of the sprite


def test_mipmaps_average_a_pattern_drawn_much_smaller_than_its_pixels(make_app):
    fine = checker(64, 64, 1, (0, 0, 0), (255, 255, 255))

    def spread(**options: Any) -> float:
        def scene(world):
            world.insert_resource(Camera(pixels_per_meter=20))
            world.spawn(Transform(), Sprite(fine, size=(0.5, 0.5), **options))

        px = pixels(make_app(scene, background=(255, 0, 0)))
        cy, cx = SIZE[1] // 2, SIZE[0] // 2
        return float(px[cy - 3 : cy + 3, cx - 3 : cx + 3, 1].std())

    assert spread(filter=TextureFilter.LINEAR, mipmaps=True) < 12  # an even grey
    assert spread() > 60  # nearest picks black or white texels: noise


def test_repeat_tiles_one_image_over_the_sprite(make_app):
    row = _row(make_app, Sprite(BLACK_WHITE, size=(8.0, 1.0), wrap=TextureWrap.REPEAT, tile=(1.0, 1.0)))
    inside = row[SIZE[0] // 2 - 80 : SIZE[0] // 2 + 80, 1]
    rises = np.count_nonzero(np.diff((inside > 128).astype(int)) == 1)
    assert rises == 8  # eight copies, one rising edge each
    mirrored = _row(make_app, Sprite(BLACK_WHITE, size=(8.0, 1.0), wrap=TextureWrap.MIRROR, tile=(1.0, 1.0)))
    inside = mirrored[SIZE[0] // 2 - 80 : SIZE[0] // 2 + 80, 1]
    assert np.count_nonzero(np.diff((inside > 128).astype(int)) == 1) == 4  # pairs meet


def test_scrolling_a_repeated_sprite_shifts_the_pattern(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), Sprite(BLACK_WHITE, size=(8.0, 1.0), wrap=TextureWrap.REPEAT,
                                        tile=(1.0, 1.0)))  # fmt: skip

    app = make_app(scene, background=(255, 0, 0))
    before = pixels(app)[SIZE[1] // 2, :, 1].astype(int)
    app.world.get(1, Sprite).scroll = (0.5, 0.0)
    after = pixels(app)[SIZE[1] // 2, :, 1].astype(int)
    mid = slice(SIZE[0] // 2 - 60, SIZE[0] // 2 + 60)
    assert np.array_equal(np.roll(before, -10)[mid], after[mid])  # half a 20-pixel tile


def test_nine_patch_borders_keep_their_pixels_while_the_middle_stretches(make_app):
    arr = np.zeros((12, 12, 4), np.uint8)
    arr[...] = (255, 255, 0, 255)
    arr[4:8, 4:8] = (0, 0, 255, 255)
    panel = from_array(arr)

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), Sprite(panel, size=(6.0, 2.0), nine_patch=(4, 4, 4, 4)))

    px = pixels(make_app(scene))
    yellow, blue = mask(px, (255, 255, 0), 5), mask(px, (0, 0, 255), 5)
    x0, x1, y0, y1 = bbox(yellow | blue)
    assert (x1 - x0 + 1, y1 - y0 + 1) == (120, 40)
    bx0, bx1, by0, by1 = bbox(blue)
    # a border of 4 image pixels is 4 / 20 m, so 4 screen pixels, on every side
    assert (bx0 - x0, x1 - bx1, by0 - y0, y1 - by1) == (4, 4, 4, 4)


def test_a_nine_patch_wider_border_than_its_image_is_refused(make_app):
    def scene(world):
        world.spawn(Transform(), Sprite(checker(8, 8, 2, (0, 0, 0), (9, 9, 9)), size=(2.0, 1.0),
                                        nine_patch=(5, 0, 5, 0)))  # fmt: skip

    app = make_app(scene)
    with pytest.raises(ValidationError, match="nine_patch"):
        pixels(app)
    with pytest.raises(ValidationError, match="nine_patch"):
        Sprite("x.png", nine_patch=(1, 1, 1, 1), wrap=TextureWrap.REPEAT)


def test_image_regions_are_images(make_app):
    arr = np.zeros((4, 8, 3), np.uint8)
    arr[:, 4:] = (0, 255, 0)  # right half green
    sheet = from_array(arr)
    row = _row(make_app, Sprite(ImageRegion(sheet, (4, 0, 4, 4)), size=(2.0, 2.0)))
    inside = row[SIZE[0] // 2 - 15 : SIZE[0] // 2 + 15]
    assert np.all(inside == (0, 255, 0))
    with pytest.raises(ValidationError, match="ImageRegion"):
        ImageRegion(sheet, (0, 0, -1, 4))


@pytest.mark.slow
def test_a_4096_by_3584_sprite_sheet_animates(make_app):
    """56 frames of 512 x 512 do not fit the first 2048 x 2048 atlas page: pages grow."""
    cols, rows = 8, 7
    sheet = np.zeros((rows * 512, cols * 512, 4), np.uint8)
    for i in range(cols * rows):
        r, c = divmod(i, cols)
        sheet[r * 512 : (r + 1) * 512, c * 512 : (c + 1) * 512] = (4 * i, 255 - 4 * i, 7, 255)
    image = from_array(sheet)
    clip = Clip.grid(image, (cols, rows), duration=1 / 60)

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), Sprite(image, size=(2.0, 2.0)), Animator({"all": clip}))

    app = make_app(scene)
    seen = []
    for _ in range(cols * rows):
        app.step(1)
        seen.append(tuple(pixels(app)[SIZE[1] // 2, SIZE[0] // 2, :3]))
    expected = {(4 * i, 255 - 4 * i, 7) for i in range(cols * rows)}
    assert set(seen) == expected  # every frame shown, from whichever page holds it
