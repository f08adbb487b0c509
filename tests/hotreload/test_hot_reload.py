"""Hot reload while a game runs, driven headless: write a file, wait for the watcher's own
event (never a sleep), step, and see the change; broken files keep the old state."""

from __future__ import annotations

import importlib
import shutil
import sys
import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from PIL import Image

from kge import App, Behaviour, Collider, Sprite, Transform, World
from kge.assets.store import Assets, default_assets, set_default_assets
from kge.hotreload import HotReload, HotReloadPlugin
from kge.scenefile import SceneState, instantiate
from kge.sound import tone

PREFABS = Path(__file__).resolve().parents[2] / "kge" / "testbed" / "prefabs"


@pytest.fixture
def game(tmp_path: Path) -> Iterator[Path]:
    before = default_assets()
    set_default_assets(Assets(tmp_path, anchor=tmp_path))
    try:
        yield tmp_path
    finally:
        set_default_assets(before)


def reloading(scene: object, **kw: object) -> tuple[App, HotReload]:
    app = App(scene, headless=True, plugins=None, **kw)  # type: ignore[arg-type]
    app.add_plugins(HotReloadPlugin())
    app.step()  # the first frame starts watching the world's files
    reloader = app.world.resource(HotReload)
    assert reloader.watcher.wait_ready()
    return app, reloader


def change(reloader: HotReload, app: App, path: Path, text: str | bytes) -> None:
    """Write ``path`` and run one frame once the watcher has reported it."""
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text)
    assert reloader.watcher.wait_for(path), "the watcher never reported the change"
    app.step()


SCENE = 'format = 1\n[[entity]]\nid = "box"\n[entity.Transform]\nx = {x}\n'


def test_a_scene_file_reloads_and_a_broken_one_keeps_the_running_world(game: Path) -> None:
    path = game / "one.scene.toml"
    path.write_text(SCENE.format(x=1.0))
    app, reloader = reloading(str(path))
    try:
        change(reloader, app, path, SCENE.format(x=2.0))
        world = app.world
        assert world.get(world.entities()[0], Transform).x == 2.0
        assert "reloaded scene (one.scene.toml)" in reloader.log
        change(reloader, app, path, SCENE.format(x="nan"))
        assert app.world is world  # the running world stays
        assert world.get(world.entities()[0], Transform).x == 2.0
        (message,) = reloader.errors.values()
        assert f"{path}:5: entity 'box', Transform.x: nan is not a finite number" in message
        change(reloader, app, path, SCENE.format(x=3.0))  # fixed: the message goes
        assert not reloader.errors and app.world.get(app.world.entities()[0], Transform).x == 3.0
    finally:
        app.close()


def test_a_changed_prefab_reaches_live_instances_and_keeps_their_motion(game: Path) -> None:
    for name in ("car", "wheel"):
        shutil.copy(PREFABS / f"{name}.prefab.toml", game / f"{name}.prefab.toml")

    def garage(world: World) -> None:
        import kge

        world.spawn(Transform(), Collider(kge.Box(50.0, 0.5)))
        instantiate(world, game / "car.prefab.toml", at=(0.0, 2.0), key="a")
        instantiate(world, game / "car.prefab.toml", at=(8.0, 2.0), key="b",
                    overrides={"front/tyre": {"Collider": {"friction": 0.2}}})

    app, reloader = reloading(garage)
    try:
        app.step(30)
        inst = app.world.resource(SceneState).instances
        chassis = app.world.get(inst["a"].members["chassis"], Transform)
        x_before = chassis.x
        wheel = game / "wheel.prefab.toml"
        change(reloader, app, wheel, wheel.read_text().replace("friction = 0.9", "friction = 0.5"))
        w = app.world
        assert w.get(inst["a"].members["front/tyre"], Collider).friction == 0.5
        assert w.get(inst["a"].members["rear/tyre"], Collider).friction == 0.5
        assert w.get(inst["b"].members["rear/tyre"], Collider).friction == 0.5
        assert w.get(inst["b"].members["front/tyre"], Collider).friction == 0.2  # overridden
        assert w.get(inst["a"].members["chassis"], Transform) is chassis  # same entities...
        assert abs(chassis.x - x_before) < 0.5  # ...carrying on from where they were
        change(reloader, app, wheel, wheel.read_text().replace("friction = 0.5", "friction = -3"))
        assert w.get(inst["a"].members["front/tyre"], Collider).friction == 0.5
        assert any("friction" in m for m in reloader.errors.values())
    finally:
        app.close()


def test_an_image_reloads_into_the_sprites_that_use_it(game: Path) -> None:
    image = game / "ship.png"
    Image.new("RGBA", (8, 8), (255, 0, 0, 255)).save(image)

    def scene(world: World) -> None:
        world.spawn(Transform(), Sprite("ship.png", size=(4.0, 4.0)))

    app, reloader = reloading(scene, size=(64, 64))
    try:
        app.screenshot(game / "before.png")
        assert Image.open(game / "before.png").convert("RGB").getpixel((32, 32)) == (255, 0, 0)
        Image.new("RGBA", (8, 8), (0, 0, 255, 255)).save(game / "next.png")
        change(reloader, app, image, (game / "next.png").read_bytes())
        app.screenshot(game / "after.png")
        assert Image.open(game / "after.png").convert("RGB").getpixel((32, 32)) == (0, 0, 255)
        assert any(m.startswith("reloaded image ship.png: 1") for m in reloader.log)
    finally:
        app.close()


def test_a_sound_reloads(game: Path) -> None:
    sound = game / "hit.wav"
    sound.write_bytes(tone(440, 0.05, rate=8000).to_wav())
    app, reloader = reloading(lambda w: None)
    try:
        store = default_assets()
        store.sound("hit.wav")
        assert store.is_cached("hit.wav")
        change(reloader, app, sound, tone(880, 0.05, rate=8000).to_wav())
        assert not store.is_cached("hit.wav") and "reloaded sound hit.wav" in reloader.log
    finally:
        app.close()


def test_a_tiled_map_reloads_with_its_scene(game: Path) -> None:
    from kge import load_map
    from kge.testbed.samples.tilemaps import write_levels

    first, second = write_levels(game)

    def level(world: World) -> None:
        load_map(world, first, unknown="ignore")

    app, reloader = reloading(level)
    try:
        world = app.world
        count = len(world.entities())
        change(reloader, app, first, second.read_text())  # level 2's layout in level 1's file
        assert app.world is not world and len(app.world.entities()) != count
        assert any(m.startswith("reloaded scene") for m in reloader.log)
    finally:
        app.close()


MODULE = '''
from kge import Script, Transform


class Mover(Script):
    def __init__(self):
        self.steps = 0

    def on_fixed_update(self, dt):
        self.steps += 1
        self.transform.x += {speed}
'''


@pytest.fixture
def game_module(game: Path) -> Iterator[Path]:
    path = game / "moving_parts.py"
    path.write_text(textwrap.dedent(MODULE.format(speed=1.0)))
    sys.path.insert(0, str(game))
    try:
        yield path
    finally:
        sys.path.remove(str(game))
        sys.modules.pop("moving_parts", None)


def test_a_script_reloads_keeping_its_state_and_survives_broken_edits(game_module: Path) -> None:
    mod = importlib.import_module("moving_parts")

    def scene(world: World) -> None:
        world.spawn(Transform(), Behaviour(mod.Mover()))

    app, reloader = reloading(scene)
    try:
        app.step(3)
        world = app.world
        beh = world.get(1, Behaviour)
        t = world.get(1, Transform)
        assert (beh.script.steps, t.x) == (4, 4.0)
        change(reloader, app, game_module, MODULE.format(speed=10.0))
        assert type(beh.script) is sys.modules["moving_parts"].Mover  # the new class...
        assert beh.script.steps == 5  # ...with the entity's state kept
        assert t.x == 5.0  # (that frame's fixed step ran before the reload)
        app.step()
        assert t.x == 15.0
        # a syntax error: reported with its line, the game keeps the running code
        change(reloader, app, game_module, MODULE.format(speed="10.0 +"))
        (message,) = reloader.errors.values()
        assert "moving_parts.py:11: SyntaxError" in message
        x = t.x
        app.step()
        assert t.x == x + 10.0
        # a runtime error in the new code: caught once, reported, the old code runs on
        change(reloader, app, game_module, MODULE.format(speed="undefined_name"))
        assert not reloader.errors  # it imports fine...
        x = t.x
        app.step()  # ...and fails in on_fixed_update: caught, reported, reverted
        (message,) = reloader.errors.values()
        assert "moving_parts.py:11: NameError" in message and "running the previous" in message
        assert t.x == x
        app.step()
        assert t.x == x + 10.0 and app.world is world
    finally:
        app.close()


def _sheet(path: Path, colours: list[tuple[int, int, int]]) -> None:
    """A sprite sheet of 8x8 frames in one row, each frame one colour."""
    img = Image.new("RGBA", (8 * len(colours), 8))
    for i, c in enumerate(colours):
        img.paste((*c, 255), (8 * i, 0, 8 * i + 8, 8))
    img.save(path)


def _playing(game: Path, clip: object) -> tuple[App, HotReload, int, Callable[[str], object]]:
    """A 64x64 App running one animated sprite playing ``clip`` (drawn 4 m wide at the
    centre): the app, its reloader, the entity, and ``shown(name)``, the centre pixel
    of a screenshot saved as ``name``."""
    from kge import Animator

    def scene(world: World) -> None:
        world.spawn(Transform(), Sprite("run.png", size=(4.0, 4.0)),
                    Animator({"run": clip}, current="run"))  # type: ignore[dict-item]

    app, reloader = reloading(scene, size=(64, 64))

    def shown(name: str) -> object:
        app.screenshot(game / name)
        return Image.open(game / name).convert("RGB").getpixel((32, 32))

    (hero,) = [e for e, _ in app.world.query(Animator)]
    return app, reloader, hero, shown


def test_an_animated_sprite_sheet_reloads_while_its_clip_plays(game: Path) -> None:
    from kge import Animations, Animator, Clip

    sheet = game / "run.png"
    old = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0)]
    new = [(0, 255, 255), (255, 0, 255), (255, 255, 255), (128, 64, 0)]
    _sheet(sheet, old)

    clip = Clip.grid("run.png", (4, 1), fps=6)  # 10 steps a frame at 60 Hz
    app, reloader, hero, shown = _playing(game, clip)
    try:
        anims = app.world.resource(Animations)
        app.step(14)  # 15 steps: frame 1, 5 steps into it
        assert anims.frame(hero) == 1 and shown("before.png") == old[1]
        _sheet(game / "next.png", new)
        change(reloader, app, sheet, (game / "next.png").read_bytes())  # one more step
        # the clip went on from where it was (frame 1, 6 steps in), drawn from the new sheet
        assert anims.frame(hero) == 1 and shown("after.png") == new[1]
        assert any(m.startswith("reloaded image run.png") for m in reloader.log)
        app.step(4)  # 4 more steps: into frame 2, as if nothing had happened
        assert anims.frame(hero) == 2 and shown("later.png") == new[2]
        assert app.world.get(hero, Animator).current == "run"
    finally:
        app.close()


def test_a_sheet_with_bigger_frames_or_a_broken_one_keeps_the_clip_playing(game: Path) -> None:
    from kge import Animations, Clip

    sheet = game / "run.png"
    _sheet(sheet, [(255, 0, 0), (0, 255, 0)])

    app, reloader, hero, shown = _playing(game, Clip.grid("run.png", (2, 1), fps=6))
    try:
        anims = app.world.resource(Animations)
        app.step(12)
        assert anims.frame(hero) == 1 and shown("a.png") == (0, 255, 0)
        change(reloader, app, sheet, b"not a png")  # a half-written or broken file
        assert any("run.png" in m for m in reloader.errors.values())
        assert anims.frame(hero) == 1 and shown("b.png") == (0, 255, 0)  # the old frames
        big = Image.new("RGBA", (64, 32), (0, 0, 255, 255))  # 32x32 frames now
        big.paste((255, 255, 0, 255), (32, 0, 64, 32))
        big.save(game / "big.png")
        change(reloader, app, sheet, (game / "big.png").read_bytes())
        assert not reloader.errors  # fixed: the message goes
        assert anims.frame(hero) == 1 and shown("c.png") == (255, 255, 0)
        app.step(8)  # 22 steps in: frame 0 again (10 steps a frame)
        assert anims.frame(hero) == 0 and shown("d.png") == (0, 0, 255)
    finally:
        app.close()
