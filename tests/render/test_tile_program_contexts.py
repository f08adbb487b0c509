"""The tile program is one per GL context (kge.render.program_life): a uniform another
window set last never leaves this window drawing with its own old value."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from kge import App, World


def test_a_layer_shift_set_in_one_window_reaches_the_other(tmp_path: Path) -> None:
    """Two windows draw maps with a parallax layer; window A's next shift equals the one
    window B set last. Through one program shared by both, A drew with its own old shift
    (llvmpipe did not re-upload a uniform set to the value it already held)."""
    import numpy as np

    from kge.components.camera import Camera
    from kge.render.setup import frame_pixels
    from kge.testbed import png
    from kge.tilemap import load_map
    from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map

    png.write(tmp_path / "t.png", np.full((16, 16, 4), (40, 200, 60, 255), np.uint8))
    grid = np.zeros((8, 10), np.int64)
    grid[2, 2] = 1  # x 2..3, y 5..6 m
    write_map(tmp_path / "m.tmx", 16, 16,
              [TilesetSpec("t", "t.png", 16, 16, columns=1, count=1, image_size=(16, 16))],
              [TileLayerSpec("Far", grid, parallax=(0.5, 0.5))])  # fmt: skip

    def scene(center: tuple[float, float]) -> Callable[[World], None]:
        def setup(world: World) -> None:
            world.insert_resource(Camera(center=center, pixels_per_meter=20))
            load_map(world, tmp_path / "m.tmx")

        return setup

    a = App(scene((5.0, 4.0)), headless=True, size=(206, 166), background=(0, 0, 0))
    b = App(scene((7.0, 4.0)), headless=True, size=(186, 146), background=(0, 0, 0))
    try:
        a.render()  # shift ((5 - 0) * 0.5, (4 - 8) * 0.5) = (2.5, -2)
        b.render()  # shift (3.5, -2)
        a.world.resource(Camera).center = (7.0, 4.0)
        a.render()  # shift (3.5, -2) too: the tile at x 5.5..6.5, y 3..4
        px = frame_pixels(a)
        # centre (7, 4) at pixel (103, 83): x 6 m -> 83, y 3.5 m -> 73
        assert tuple(int(v) for v in px[73, 83, :3]) == (40, 200, 60)
        assert tuple(int(v) for v in px[73, 63, :3]) == (0, 0, 0)  # where the old shift put it
    finally:
        a.close()
        b.close()
