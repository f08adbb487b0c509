"""Lantern Woods, kge's showcase game: a fox with a lantern lights the shrine at the end of
a night forest.

What it shows, all from files made by code (``tools/make_assets.py``):

* a Tiled level (``assets/lantern_woods.tmx``: ground, one-way planks, decor, objects)
  with three parallax image layers (sky, hills, far trees) behind it;
* an animated character (a fox sheet cut by tags: idle, run, jump, fall), a
  ``CharacterBody`` that collides and slides, with coyote time, a jump buffer, a
  variable jump height and hard landings;
* night lighting: the fox's lantern casts collider shadows, firefly jars glow;
  fireflies, landing dust and jar sparkles are particles;
* UI menus (title over the living level, pause, settings with rebinding), fade
  transitions, a HUD, music and sounds, keyboard and gamepad (stick, d-pad, A).

Keys: left/right (A/D) run, space/up/W jump (hold for higher), P/Escape pause.
Run: ``python examples/lantern.py`` (a window); headless it plays itself for a
minute and prints what it did; ``--gif FILE`` records the README's animation.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import game_menus as ui
import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

import kge
from kge import (
    Animator,
    App,
    Assets,
    Audio,
    Behaviour,
    Blend,
    Box,
    Camera,
    CharacterBody,
    Clip,
    Collider,
    EmitBox,
    InputMap,
    Key,
    Light,
    Lighting,
    MapObject,
    ParticleBurst,
    ParticleEmitter,
    Physics,
    Script,
    SensorBegin,
    Spawn,
    Spawners,
    Sprite,
    Transform,
    UINode,
    World,
)

ASSETS = Path(__file__).resolve().parent / "assets"
LEVEL = ASSETS / "lantern_woods.tmx"
STORE = Assets(anchor=__file__)  #: this file's folder and its assets/: found from anywhere
SIZE = (960, 540)
SKY = (14, 18, 44)  #: the sky image's top colour: the clear colour behind it
PPM = 48.0  #: a 16 px tile drawn 48 px wide: chunky pixel art
UNLIT = 100  #: Lighting.unlit_layer: glowing things draw above the night

RUN_SPEED, ACCEL = 7.0, 60.0  #: m/s, m/s² on the ground (a third of it in the air)
JUMP_SPEED, CUT = 11.5, 0.45  #: take-off speed; releasing early keeps this share of it
COYOTE, BUFFER = 0.1, 0.12  #: seconds a jump is still allowed / remembered
HALF = (0.38, 0.42)  #: the fox's collider half-extents, metres
FOX_TAGS = {"idle": (0, 1), "run": (2, 7), "jump": (8, 8), "fall": (9, 9)}
ACTIONS: ui.Bindings = {
    "jump": ("key:SPACE", "key:UP", "key:W", "pad:a"),
}


@dataclass(slots=True)
class Progress:
    """A resource: jars carried, jars in the level, seconds played, falls, shrine lit."""

    jars: int = 0
    total: int = 0
    time: float = 0.0
    falls: int = 0
    lit: bool = False
    checkpoint: tuple[float, float] = (3.5, 5.0)


# -- the fox -----------------------------------------------------------------------------
class Fox(Script):
    """Runs and jumps through its CharacterBody (which brings coyote time, the jump buffer,
    the variable height and hard landings), animates, lands in dust."""

    def on_fixed_update(self, dt: float) -> None:
        actions = self.world.resource(InputMap)
        body = self.get(CharacterBody)
        vx, vy = body.velocity
        target = RUN_SPEED * actions.axis("run")
        accel = ACCEL if body.on_floor else ACCEL / 3
        vx += max(-accel * dt, min(accel * dt, target - vx))
        body.velocity = (vx, vy)
        body.jump = actions.held("jump")
        if body.jumped:
            self.world.resource(Audio).play("lantern_jump.wav", volume=0.4)
        if body.hard_landing:
            t = self.transform
            self.world.emit(ParticleBurst(self.entity, 14, position=(t.x, t.y - HALF[1])))
            self.world.resource(Audio).play("lantern_land.wav", volume=0.5)
        self.animate(vx, vy, body.on_floor)
        if self.transform.y < -3.0:
            self.fell()

    def animate(self, vx: float, vy: float, grounded: bool) -> None:
        anim, sprite = self.get(Animator), self.get(Sprite)
        if abs(vx) > 0.3:
            sprite.flip_x = vx < 0
        if not grounded:
            anim.play("jump" if vy > 0 else "fall", restart=False)
        else:
            anim.play("run" if abs(vx) > 0.5 else "idle", restart=False)
            anim.speed = max(0.6, abs(vx) / RUN_SPEED * 1.4) if abs(vx) > 0.5 else 1.0

    def fell(self) -> None:
        progress = self.world.resource(Progress)
        progress.falls += 1
        t = self.transform
        t.x, t.y = progress.checkpoint
        self.get(CharacterBody).velocity = (0.0, 0.0)


def solid(world: World, skip: int | None = None) -> Any:
    """A query filter: colliders that are not sensors (jars and the shrine are), and not
    ``skip`` (the fox's own)."""

    def keep(entity: int) -> bool:
        c = world.try_get(entity, Collider)
        return entity != skip and c is not None and not c.sensor

    return keep


def fox(spawn: Spawn) -> list[Any]:
    clips = Clip.tags("lantern_fox.png", (10, 1), FOX_TAGS, fps=12)
    return [
        CharacterBody(Box(*HALF), jump_speed=JUMP_SPEED, jump_cut=CUT, coyote_time=COYOTE,
                      jump_buffer=BUFFER, hard_landing_speed=7.0),
        Sprite("lantern_fox.png", size=(1.5, 1.5), anchor=(0.5, 0.78), layer=5),
        Animator(clips, current="idle"),
        Light(radius=8.0, color=(255, 200, 130), intensity=1.6, falloff=1.0, shadows=True,
              offset=(0.5, 0.3)),
        ParticleEmitter(rate=0.0, lifetime=(0.3, 0.6), speed=(0.5, 1.6), direction=math.pi / 2,
                        spread=2.4, acceleration=(0.0, -3.0), size=(0.12, 0.02),
                        color=((190, 170, 140), (120, 100, 80)), opacity=(220, 0), layer=6,
                        seed=3),
        Behaviour(Fox()),
    ]


# -- jars and the shrine -------------------------------------------------------------------
def jar(spawn: Spawn) -> list[Any]:
    return [
        Sprite("lantern_jar.png", size=(1.0, 1.0), layer=UNLIT + 1),
        Light(radius=2.6, color=(255, 220, 120), intensity=0.9),
        ParticleEmitter(rate=0.0, lifetime=(0.4, 0.9), speed=(1.0, 3.0), spread=math.tau,
                        size=(0.14, 0.0), color=((255, 250, 200), (255, 200, 80)),
                        opacity=(255, 0), blend=Blend.ADDITIVE, layer=UNLIT + 2, seed=8),
    ]


def shrine(spawn: Spawn) -> list[Any]:
    return [
        Sprite("lantern_shrine.png", size=(2.0, 3.0), layer=4),
        Light(radius=14.0, color=(255, 210, 140), intensity=1.6, offset=(0.0, 0.6),
              enabled=False),
    ]


SPAWNERS = Spawners({"PlayerStart": fox, "Jar": jar, "Shrine": shrine})


class Referee(Script):
    """The fox takes jars (sensor events; each jar is a checkpoint) and lights the shrine
    by passing it, on the ground or above it, with at least one jar."""

    def __init__(self, fox: int, shrine: int, menus: bool = True) -> None:
        self.fox, self.shrine, self.menus = fox, shrine, menus

    def on_fixed_update(self, dt: float) -> None:
        world = self.world
        progress = world.resource(Progress)
        if progress.lit:
            return
        progress.time += dt
        for ev in world.events(SensorBegin):
            for a, b in ((ev.collider_a, ev.collider_b), (ev.collider_b, ev.collider_a)):
                obj = world.try_get(b, MapObject) if world.exists(b) else None
                if a == self.fox and obj is not None and obj.cls == "Jar":
                    self.take(b, progress)
        reached = world.get(self.fox, Transform).x >= world.get(self.shrine, Transform).x - 1.0
        if reached and progress.jars > 0:
            self.light(self.shrine, progress)
        _hud(world)

    def take(self, jar_entity: int, progress: Progress) -> None:
        world = self.world
        t = world.get(jar_entity, Transform)
        progress.jars += 1
        progress.checkpoint = (t.x, t.y + 0.5)
        world.emit(ParticleBurst(jar_entity, 24))
        for kind in (Sprite, Collider, Light):  # the jar goes; its sparkles play out
            world.remove(jar_entity, kind)
        world.resource(Audio).play("lantern_jar.wav", volume=0.5)

    def light(self, shrine_entity: int, progress: Progress) -> None:
        progress.lit = True
        self.world.get(shrine_entity, Light).enabled = True
        self.world.resource(Audio).play("lantern_lit.wav", volume=0.6)
        if self.menus:
            self.world.resource(App).push_scene(won, overlay=True)


def _hud(world: World) -> None:
    progress = world.resource(Progress)
    hud = world.resource(Hud)
    world.get(hud.jars, kge.Label).text = f"jars {progress.jars} / {progress.total}"
    world.get(hud.time, kge.Label).text = f"{progress.time:5.1f} s"


@dataclass(slots=True)
class Hud:
    jars: int
    time: int


# -- scenes -------------------------------------------------------------------------------
def woods(world: World, follow: bool = True) -> int:
    """The level with its lights and fireflies; returns the fox."""
    world.insert_resource(STORE)
    bind_controls(world.resource(InputMap))
    world.insert_resource(Lighting(ambient=(46, 50, 92), unlit_layer=UNLIT))
    m = kge.load_map(world, LEVEL, spawners=SPAWNERS)
    fox_entity = next(e for e in m.objects if world.get(e, MapObject).cls == "PlayerStart")
    world.insert_resource(Camera(pixels_per_meter=PPM, follow=fox_entity if follow else None,
                                 bounds=m.bounds, smoothing=0.12, dead_zone=(1.5, 2.0),
                                 look_ahead=0.6, center=(10.0, 8.0)))
    x0, _, x1, _ = m.bounds
    world.spawn(Transform((x0 + x1) / 2, 7.0), ParticleEmitter(
        rate=30.0, shape=EmitBox(x1 - x0, 6.0), spread=math.tau, speed=(0.1, 0.4),
        lifetime=(3.0, 6.0), size=0.16, color=((220, 255, 140), (140, 230, 90)),
        opacity=(0, 255, 0), blend=Blend.ADDITIVE, layer=UNLIT + 3, prewarm=5.0,
        max_particles=800, seed=6,
    ))
    return fox_entity


def level(world: World, menus: bool = True) -> None:
    """The game: the woods, the referee, the HUD, music, and P / Escape / Start to pause
    (``menus=False``: no pause menu nor won screen, as the testbed runs it)."""
    fox_entity = woods(world)
    total = sum(1 for _, (m,) in world.query(MapObject) if m.cls == "Jar")
    world.insert_resource(Progress(total=total))
    world.insert_resource(Hud(ui.hud_label(world, "top_left", ""),
                              ui.hud_label(world, "top_right", "")))
    shrine_entity = next(e for e, (m,) in world.query(MapObject) if m.cls == "Shrine")
    world.spawn(Behaviour(Referee(fox_entity, shrine_entity, menus)))
    if menus:
        world.spawn(Behaviour(ui.PauseKey(title, ("jump",))))
    world.resource(Audio).play_music("lantern_music.wav", volume=0.45)
    _hud(world)


class Drift(Script):
    """The title's camera: a slow flight over the woods and back."""

    def __init__(self) -> None:
        self.t = 0.0

    def on_update(self, dt: float) -> None:
        self.t += dt
        self.world.resource(Camera).center = (40.0 - 30.0 * math.cos(self.t * 0.06), 9.0)


def title(world: World) -> None:
    """The title menu over the living woods: Play fades into the level."""
    woods(world, follow=False)
    world.spawn(Behaviour(Drift()))
    world.resource(Audio).play_music("lantern_music.wav", volume=0.45)
    ui.title_menu(world, "Lantern Woods",
                  "arrows / A-D run, space jumps, P pauses; a gamepad works too",
                  level, rebindable=("jump",))


def won(world: World) -> None:
    """An overlay when the shrine is lit: the run's numbers, then again or the menu."""
    below = world.resource(App).worlds[-2]
    progress = below.resource(Progress)
    ui._dim(world, 90)
    col = ui._column(world, "The woods are lit", width=380)
    world.spawn(UINode(parent=col), kge.Label(
        f"{progress.jars} of {progress.total} jars in {progress.time:.1f} s", size=18))
    again = ui._button(world, col, "Play again")
    ui._button(world, col, "Main menu")
    ui.focus(world, again)
    world.spawn(Behaviour(ui._Buttons({
        "Play again": lambda app: _leave(app, level),
        "Main menu": lambda app: _leave(app, title),
    })))


def _leave(app: App, scene: Any) -> None:
    """Close the won overlay, then fade the woods into ``scene``."""
    app.pop_scene()
    app.replace_scene(scene, transition=ui.FADE)


def bind_controls(actions: InputMap) -> None:
    """The run axis (keys, d-pad, left stick) and the actions of the game and its menus."""
    actions.bind_axis("run", negative=("key:LEFT", "key:A", "pad:dpleft"),
                      positive=("key:RIGHT", "key:D", "pad:dpright"), stick="pad:leftx",
                      dead_zone=0.25)
    ui.bind_defaults(actions, ACTIONS)


def make_app(start: Any = title, **kwargs: Any) -> App:
    return App(start, title="Lantern Woods (kge)", size=SIZE, background=SKY, **kwargs)


# -- the self-playing run ------------------------------------------------------------------
def autopilot(app: App) -> None:
    """One step of scripted input: run right; jump over pits, at walls and under jars."""
    world = app.world
    if not world.has_resource(Progress):
        return
    fox_entity = next((e for e, (b,) in world.query(Behaviour) if isinstance(b.script, Fox)),
                      None)
    if fox_entity is None:
        return
    t = world.get(fox_entity, Transform)
    physics, keep = world.resource(Physics), solid(world, skip=fox_entity)
    feet = t.y - HALF[1]
    pit = physics.raycast((t.x + 1.2, feet + 0.2), (t.x + 1.2, -2.0), filter=keep) is None
    wall = physics.raycast((t.x, feet + 0.2), (t.x + 1.4, feet + 0.2), filter=keep) is not None
    jar_above = any(
        0.3 < jt.x - t.x < 2.0 and 0.8 < jt.y - t.y < 6.0
        for _, (jt, m, _s) in world.query(Transform, MapObject, Sprite) if m.cls == "Jar"
    )
    want = pit or wall or jar_above
    body = world.get(fox_entity, CharacterBody)
    held = app.input.held(Key.SPACE)
    if want and not held:
        app.input.press(Key.SPACE)
    elif held and body.velocity[1] < 2.0 and (body.on_floor or not want):
        app.input.release(Key.SPACE)  # past the top of the jump, or landed: press again
    if not app.input.held(Key.RIGHT):
        app.input.press(Key.RIGHT)


def _tap(app: App, key: int, wait: int = 20) -> None:
    app.step(wait)
    app.input.press(key)
    app.step(1)
    app.input.release(key)


@dataclass(slots=True)
class Run:
    """What a self-playing session did: one line per finished run, the last one's state."""

    finished: list[Progress]
    last: Progress | None = None


def play(app: App, seconds: float = 60.0, every: int = 0, frame: Any = None) -> Run:
    """Start from the title, press Play, let the autopilot run the level, and press
    "Play again" at each lit shrine, until ``seconds`` of game time have passed."""
    _tap(app, Key.TAB)  # the menu by keyboard: focus Play, press it
    _tap(app, Key.ENTER)
    run = Run([])
    won_at = None
    for i in range(int(seconds * 60)):
        autopilot(app)
        app.step()
        if every and frame is not None and i % every == 0:
            frame(app)
        below = app.worlds[0]
        progress = below.try_resource(Progress)
        if progress is not None:
            run.last = progress
            if progress.lit and won_at is None:
                won_at, run.finished = i, [*run.finished, progress]
        if won_at is not None and i - won_at == 120:  # two seconds of the lit shrine
            app.input.release(Key.RIGHT)
            app.input.press(Key.ENTER)  # "Play again" has the focus
        elif won_at is not None and i - won_at == 121:
            app.input.release(Key.ENTER)
            won_at = None
    return run


def record_gif(path: Path, seconds: float, size: tuple[int, int] = (480, 270)) -> None:
    """Play headless and write an animated GIF of the run (10 frames a second)."""
    from PIL import Image

    from kge.testbed.showcase import grab

    frames: list[Any] = []

    def keep(app: App) -> None:  # pixel art: nearest scaling, 96 colours, no dithering
        img = Image.fromarray(grab(app)[:, :, :3]).resize(size, Image.Resampling.NEAREST)
        frames.append(img.quantize(96, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE))

    app = make_app(headless=True)
    play(app, seconds, every=6, frame=keep)
    app.close()
    frames[0].save(path, save_all=True, append_images=frames[1:], duration=100, loop=0,
                   optimize=True)
    print(f"{path}: {len(frames)} frames")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description="Lantern Woods, kge's showcase game")
    parser.add_argument("--gif", type=Path, help="record a headless run as an animated GIF")
    parser.add_argument("--seconds", type=float, default=60.0)
    args = parser.parse_args(argv)
    if args.gif:
        record_gif(args.gif, args.seconds)
        return
    app = make_app()
    if not app.headless:
        app.run()
        return
    run = play(app, args.seconds)
    print(f"kge {kge.__version__} Lantern Woods, headless, {args.seconds:g} s of play:")
    for k, p in enumerate(run.finished, 1):
        print(f"  run {k}: shrine lit with {p.jars}/{p.total} jars in {p.time:.1f} s, "
              f"{p.falls} falls")
    app.close()


if __name__ == "__main__":
    main()
