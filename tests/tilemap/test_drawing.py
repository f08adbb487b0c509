"""Tile layers drawn headless (EGL): pixels where the tiles are, flips, opacity, culling."""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import App
from kge.components.camera import Camera
from kge.tilemap import load_map
from kge.tilemap.model import TILED_FLIP_H, TILED_FLIP_V
from kge.tilemap.writer import TileLayerSpec

from .maps import ANIM_A, COLORS, DECOR, GROUND, MARK, ONE_WAY, write_level

SIZE = (200, 160)
PPM = 20  # window pixels per metre; a tile is 1 m


def render(apps: list[App], setup: Any) -> tuple[App, np.ndarray]:
    from kge.render.setup import frame_pixels

    app = App(setup, headless=True, size=SIZE, background=(0, 0, 0))
    apps.append(app)
    app.render()
    return app, frame_pixels(app)


class Near(tuple):
    """A colour that equals any colour within 10 per channel (PNG decoding rounds)."""

    def __eq__(self, other: object) -> bool:
        return isinstance(other, tuple) and all(
            abs(int(a) - int(b)) <= 10 for a, b in zip(self, other, strict=True)
        )

    def __hash__(self) -> int:
        return hash(tuple(self))


def at(px: np.ndarray, x: float, y: float) -> Near:
    """The pixel at world point (x, y) with the camera centred on (5, 4)."""
    sx = int(SIZE[0] / 2 + (x - 5.0) * PPM)
    sy = int(SIZE[1] / 2 + (y - 4.0) * PPM)
    return Near(int(v) for v in px[sy, sx, :3])


def test_tiles_are_drawn_at_their_cells(tmp_path: Path, apps: list[App]) -> None:
    g = np.zeros((8, 10), np.int64)
    g[7, :] = GROUND  # bottom row: y in [0, 1)
    g[2, 3] = ONE_WAY  # row 2 from the top: y in [5, 6), x in [3, 4)
    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    _, px = render(apps, setup)
    assert at(px, 0.5, 0.5) == COLORS[0] and at(px, 9.5, 0.5) == COLORS[0]
    assert at(px, 3.5, 5.5) == COLORS[1]
    assert at(px, 2.5, 5.5) == (0, 0, 0) and at(px, 4.5, 5.5) == (0, 0, 0)
    assert at(px, 0.5, 1.5) == (0, 0, 0)
    # the cell's edges land on the expected pixels (one tile = PPM pixels)
    sy = int(SIZE[1] / 2 + (5.5 - 4.0) * PPM)
    xs = np.nonzero(np.abs(px[sy, :, 1].astype(int) - COLORS[1][1]) <= 10)[0]
    assert (xs.min(), xs.max() + 1) == (int(SIZE[0] / 2 - 2 * PPM), int(SIZE[0] / 2 - 1 * PPM))


def test_flips_and_layer_opacity(tmp_path: Path, apps: list[App]) -> None:
    g = np.zeros((8, 10), np.int64)
    g[2, 2] = MARK  # black quarter at the image's top-left
    g[2, 4] = MARK | TILED_FLIP_H  # ... top-right
    g[2, 6] = MARK | TILED_FLIP_V  # ... bottom-left
    faded = np.zeros((8, 10), np.int64)
    faded[5, 5] = GROUND
    path = write_level(tmp_path, g, extra_layers=[TileLayerSpec("Faded", faded, opacity=0.5)])

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    _, px = render(apps, setup)
    black, white = (0, 0, 0), COLORS[7]
    # tile at column 2, row 2: x in [2, 3), y in [5, 6); top-left quarter is near (2.25, 5.75)
    assert at(px, 2.25, 5.75) == black and at(px, 2.75, 5.75) == white
    assert at(px, 4.75, 5.75) == black and at(px, 4.25, 5.75) == white
    assert at(px, 6.25, 5.25) == black and at(px, 6.25, 5.75) == white
    assert at(px, 5.5, 2.5) == tuple(c // 2 for c in COLORS[0])  # half opacity over black


def test_animated_tiles_follow_game_time(tmp_path: Path, apps: list[App]) -> None:
    g = np.zeros((8, 10), np.int64)
    g[2, 5] = ANIM_A  # frames: tile 4 for 0.1 s, tile 5 for 0.1 s

    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    from kge.render.setup import frame_pixels

    app, px = render(apps, setup)
    assert at(px, 5.5, 5.5) == COLORS[4]
    app.step(9)  # 0.15 s of game time
    app.render()
    assert at(frame_pixels(app), 5.5, 5.5) == COLORS[5]


def test_only_visible_chunks_are_in_the_batch(tmp_path: Path, apps: list[App]) -> None:
    g = np.full((200, 300), GROUND, np.int64)
    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(150.0, 100.0), pixels_per_meter=PPM))
        load_map(world, path)

    app, _ = render(apps, setup)
    from kge.render.passes import RenderPasses

    (draw,) = [
        p
        for p in app.world.resource(RenderPasses).before()
        if getattr(p, "__name__", "") == "draw_maps"
    ]
    renderer = draw.state["renderer"]  # type: ignore[attr-defined]
    # a 10 x 8 m view touches at most 2 x 2 chunks of 32 tiles (70 chunks in the map)
    assert 1 <= renderer.chunk_count <= 4
    app.world.resource(Camera).center = (20.0, 180.0)
    app.render()
    assert 1 <= renderer.chunk_count <= 4


def test_tint_offset_parallax_and_image_layers(tmp_path: Path, apps: list[App]) -> None:
    from kge.testbed import png
    from kge.tilemap.writer import ImageLayerSpec

    g = np.zeros((8, 10), np.int64)
    tinted = np.zeros((8, 10), np.int64)
    tinted[2, 2] = MARK  # white tile (its black quarter aside) tinted red: x [2, 3), y [5, 6)
    moved = np.zeros((8, 10), np.int64)
    moved[5, 2] = GROUND  # drawn 16 px (1 m) right and 16 px (1 m) down: x [3, 4), y [1, 2)
    fixed = np.zeros((8, 10), np.int64)
    # parallax 0: drawn moved by the camera's offset from the parallax origin (the map's
    # top-left, (0, 8)): with the camera at (5, 4) this tile at (2.5, 6.5) shows at (7.5, 2.5)
    fixed[1, 2] = ONE_WAY
    png.write(tmp_path / "sun.png", np.full((16, 32, 4), (20, 60, 250, 255), np.uint8))
    path = write_level(
        tmp_path,
        g,
        extra_layers=[
            ImageLayerSpec("Sun", "sun.png", offset=(128, 0)),  # x [8, 10), y [7, 8)
            TileLayerSpec("Tinted", tinted, tint="#ff0000"),
            TileLayerSpec("Moved", moved, offset=(16, 16)),
            TileLayerSpec("Fixed", fixed, parallax=(0.0, 0.0)),
        ],
    )

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    app, px = render(apps, setup)
    assert at(px, 2.75, 5.75) == (250, 0, 0)
    assert at(px, 3.5, 1.5) == COLORS[0] and at(px, 2.5, 2.5) == (0, 0, 0)
    assert at(px, 9.5, 7.5) == (20, 60, 250) and at(px, 7.5, 7.5) == (0, 0, 0)
    assert at(px, 7.5, 2.5) == COLORS[1]
    from kge.render.setup import frame_pixels

    # the camera moves 2 m right: the map moves 2 m left on screen, the parallax-0 layer does not
    app.world.resource(Camera).center = (7.0, 4.0)
    app.render()
    px = frame_pixels(app)
    assert at(px, 7.5, 2.5) == COLORS[1]  # same screen spot as before (at() assumes centre 5, 4)
    assert at(px, 1.5, 1.5) == COLORS[0]  # the offset tile, 2 m to the left on screen


def test_no_seams_or_bleeding_between_tiles_at_any_camera(tmp_path: Path, apps: list[App]) -> None:
    """A block of one tile shows only that tile's colour inside: no gap to the
    background, no pixel of the sheet's neighbouring tiles, wherever the camera sits
    (between pixels, zoomed out below one pixel per texel, zoomed in)."""
    from kge.render.setup import frame_pixels

    g = np.zeros((8, 10), np.int64)
    g[1:7, 1:9] = DECOR  # grey; its neighbours in the sheet are cyan, white, green, yellow
    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    app, _ = render(apps, setup)
    cam = app.world.resource(Camera)
    rng = np.random.default_rng(1)
    # seeded cameras, with three that bled a column of the next tile before the fix
    cameras = [((5.6536507, 4.7710405), 27.433149), ((4.8936259, 3.7437091), 20.651738),
               ((5.4347435, 3.5526260), 7.962957)]  # fmt: skip
    cameras += [((float(rng.uniform(4, 6)), float(rng.uniform(3, 5))), float(rng.uniform(3, 40)))
                for _ in range(40)]  # fmt: skip
    bad = []
    for center, ppm in cameras:
        cam.center, cam.pixels_per_meter = center, ppm
        app.render()
        px = frame_pixels(app)
        # the block covers x in [1, 9), y in [1, 7); look two pixels inside its edges
        x0 = int(np.ceil(SIZE[0] / 2 + (1.0 - center[0]) * ppm)) + 2
        x1 = int(np.floor(SIZE[0] / 2 + (9.0 - center[0]) * ppm)) - 2
        y0 = int(np.ceil(SIZE[1] / 2 + (1.0 - center[1]) * ppm)) + 2
        y1 = int(np.floor(SIZE[1] / 2 + (7.0 - center[1]) * ppm)) - 2
        inside = px[max(y0, 0) : min(y1, SIZE[1]), max(x0, 0) : min(x1, SIZE[0]), :3].astype(int)
        assert inside.size > 0
        off = np.abs(inside - np.array(COLORS[6])).max(axis=-1) > 10
        if off.any():
            bad.append((center, ppm, int(off.sum()), tuple(inside[off][0])))
    assert not bad, f"pixels off the tile's colour (camera, ppm, count, first): {bad}"


@pytest.mark.parametrize("ppm", [20.0, 13.7])
def test_a_bounded_follow_camera_never_shows_past_the_map(
    tmp_path: Path, apps: list[App], ppm: float
) -> None:
    """A camera clamped to the map's bounds, following a body from the map's corner
    out: no frame shows a strip of the background at a map edge (neither the first,
    drawn before the camera system ran, nor those whose drawn pose lags the body)."""
    from kge import BodyType, RigidBody, Transform, draw
    from kge.render.setup import frame_pixels

    path = write_level(tmp_path, np.full((12, 40), DECOR, np.int64))

    def setup(world: Any) -> None:
        m = load_map(world, path)
        mover = world.spawn(Transform(3.0, 3.0),
                            RigidBody(type=BodyType.KINEMATIC, velocity=(6.0, 3.0)),
                            draw.Circle(0.3, color=(255, 0, 0)))  # fmt: skip
        world.spawn(Camera(pixels_per_meter=ppm, follow=mover, bounds=m.bounds, smoothing=0.25))

    app, px = render(apps, setup)
    strips = []
    for frame in range(60):
        dark = px[..., :3].astype(int).sum(-1) < 30
        if dark.any():
            strips.append((frame, int(dark.sum())))
        app.advance(1 / 100)  # frames between fixed steps: the drawn pose is blended
        app.render()
        px = frame_pixels(app)
    assert not strips, f"frames with background showing (frame, pixels): {strips}"


TONE = """
uniform vec3 tone;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world) {
    vec4 t = texture(tex, uv);
    return vec4(tone * t.rgb, t.a) * color;
}
"""


def test_a_tile_layer_drawn_with_a_material(tmp_path: Path, apps: list[App]) -> None:
    """A Material on a tile layer: its shader draws every tile of that layer (uniforms
    read each frame, so set() shows at once), other layers stay plain; None undoes it."""
    import warnings

    from kge.components.material import Material, Shader, ShaderWarning
    from kge.tilemap.errors import TilemapError
    from kge.tilemap.runtime import TileMaps

    g = np.zeros((8, 10), np.int64)
    g[7, :] = GROUND  # bottom row, (200, 60, 40)
    other = np.zeros((8, 10), np.int64)
    other[2, 3] = ONE_WAY  # (40, 200, 60), another layer
    path = write_level(tmp_path, g, extra_layers=[TileLayerSpec("Top", other)])
    tone = Material(Shader(TONE, name="tone"), {"tone": (0.5, 1.0, 0.0)})

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path).set_material("Ground", tone)

    app, px = render(apps, setup)
    assert at(px, 4.5, 0.5) == (100, 60, 0)  # red halved, green kept, blue gone
    assert at(px, 3.5, 5.5) == COLORS[1]  # the other layer is drawn plainly
    tone.set("tone", (1.0, 0.0, 1.0))
    app.render()
    from kge.render.setup import frame_pixels

    assert at(frame_pixels(app), 4.5, 0.5) == (200, 0, 40)
    (tmap,) = app.world.resource(TileMaps).maps
    tmap.set_material("Ground", None)
    app.render()
    assert at(frame_pixels(app), 4.5, 0.5) == COLORS[0]
    broken = Material(Shader("vec4 effect(vec4 c, sampler2D t, vec2 uv, vec2 w) { return nope; }",
                             name="broken"))  # fmt: skip
    tmap.set_material("Ground", broken)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        app.render()
    assert any(issubclass(w.category, ShaderWarning) and "broken" in str(w.message)
               for w in caught)  # fmt: skip
    assert at(frame_pixels(app), 4.5, 0.5) == COLORS[0]  # drawn plainly meanwhile
    with pytest.raises(TilemapError, match="no tile layer 'Water'"):
        tmap.set_material("Water", tone)
    with pytest.raises(TilemapError, match="expected a Material"):
        tmap.set_material("Ground", "tone")  # type: ignore[arg-type]
