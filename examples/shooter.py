"""Defend the centre: KGE 1.0's "space_invaders" example, rebuilt from kge components.

Rules (as in KGE): your ship sits at the centre and turns to face the mouse;
holding the left button fires up to 10 shots a second, each flying at 3 m/s.
Every second an enemy appears on the edge of an 18 m square and homes in on
the ship; every 2 s the enemies get 0.25 m/s faster (the first ones move at
1.75). A shot that touches an enemy destroys both and scores a point; an enemy
that touches the ship ends the game. Shots leaving the 22 m frame vanish.
kge fixes KGE's bugs: the music never stacks on restarts, a missing file
cannot abort the scene half-built, and the ship art points where it shoots.

Controls: mouse to aim, hold the left button to fire (or a gamepad: right stick aims,
A or the right shoulder fires); Space starts, R restarts; P, Esc or Start pauses (a
see-through menu: resume, settings with volumes and rebinding, main menu). The menus
are kge UI, shared with Pong in ``game_menus.py``.

Run: ``python examples/shooter.py`` (a window; headless machines get a short
self-played demo and a summary).
"""

from __future__ import annotations

import math
import random

import game_menus as ui  # imports kge_required first
import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

import kge
from kge import (
    Animator,
    App,
    Assets,
    Audio,
    Behaviour,
    Blend,
    Chain,
    Circle,
    Clip,
    Collider,
    Input,
    Key,
    Loop,
    Mouse,
    Name,
    Polygon,
    RigidBody,
    Script,
    Sprite,
    Text,
    Transform,
    World,
    draw,
)
from kge.physics.events import SensorBegin
from kge.systems.animation import shake

ASSETS = Assets(anchor=__file__)

SIZE = (1000, 700)
SHIP_RADIUS = 1 / 3  # KGE: scale 1/1.5, circle radius = scale / 2
SHOT_RADIUS = 1 / 16
SHOT_SPEED = 3.0
FIRE_RATE = 10.0  # shots per second
ENEMY_SCALE = 1 / 1.5
WAVE_PERIOD = 2.0
SPAWN_PERIOD = 1.0
SPAWN_DISTANCE = 9.0
FIRST_SPEED = 1.5  # +0.25 at once, so the first enemies move at 1.75 m/s
FRAME_HALF = 11.0
BLUE = (0, 0, 125, 255)
#: the actions a player can rebind in the settings, with their default bindings
ACTIONS: ui.Bindings = {"fire": ("mouse:LEFT", "pad:a", "pad:rightshoulder")}


class ShipTag:
    """Marks the ship entity (enemies home in on it)."""


class Ship(Script):
    """Faces the mouse (angle measured from the origin) and fires while the button is held."""

    def __init__(self) -> None:
        self.cooldown = 0.0
        self.score = 0

    def on_update(self, dt: float) -> None:
        actions = self.world.resource(kge.InputMap)
        mx, my = actions.vector("aim")  # a gamepad's right stick, when pushed
        if not (mx or my):
            mx, my = self.world.resource(Input).mouse_world
        t = self.transform
        if mx or my:
            t.angle = math.atan2(my, mx) - math.pi / 2  # the ship's nose is its local +y
        self.cooldown -= dt
        if actions.held("fire") and self.cooldown <= 0.0:
            self.cooldown = 1.0 / FIRE_RATE
            self.fire(t.angle)

    def fire(self, angle: float) -> int:
        nx, ny = -math.sin(angle), math.cos(angle)
        t = self.transform
        shot = self.world.spawn(
            Transform(t.x + 0.5 * nx, t.y + 0.5 * ny, angle),  # the bolt points where it flies
            RigidBody(gravity_scale=0.0, velocity=(SHOT_SPEED * nx, SHOT_SPEED * ny), bullet=True),
            Collider(Circle(SHOT_RADIUS), sensor=True),
            Sprite("laser.png", size=(SHOT_RADIUS * 2, SHOT_RADIUS * 6), layer=2),
            Name("shot"),
        )
        self.world.resource(Audio).play("laser.wav", volume=0.15)
        return shot


class Spawner(Script):
    """Sends an enemy every second from the edge of an 18 m square; faster every wave."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.speed = FIRST_SPEED
        self.wave_clock = WAVE_PERIOD  # the first update starts a wave at once, as in KGE
        self.spawn_clock = 0.0
        self.stopped = False

    def on_update(self, dt: float) -> None:
        if self.stopped:
            return
        self.wave_clock += dt
        if self.wave_clock >= WAVE_PERIOD:
            self.wave_clock -= WAVE_PERIOD
            self.speed += 0.25
        self.spawn_clock += dt
        if self.spawn_clock >= SPAWN_PERIOD:
            self.spawn_clock -= SPAWN_PERIOD
            r = float(self.rng.randint(-9, 9))
            d = SPAWN_DISTANCE
            x, y = self.rng.choice(((d, r), (-d, r), (r, d), (r, -d)))
            spawn_enemy(self.world, x, y, self.speed)


class Enemy(Script):
    """Homes in on the ship at a constant speed, nose towards the centre."""

    def __init__(self, speed: float) -> None:
        self.speed = speed
        self.target = (0.0, 0.0)

    def on_fixed_update(self, dt: float) -> None:
        ships = self.world.query(ShipTag, Transform)
        if ships:
            t = ships[0][1][1]
            self.target = (t.x, t.y)
        me = self.transform
        dx, dy = self.target[0] - me.x, self.target[1] - me.y
        dist = math.hypot(dx, dy)
        step = min(self.speed, dist / dt) if dist > 0 else 0.0
        rb = self.get(RigidBody)
        rb.velocity = (step * dx / dist, step * dy / dist) if dist > 0 else (0.0, 0.0)
        me.angle = math.atan2(-me.y, -me.x) - math.pi / 2  # nose (local +y) at the origin


def spawn_enemy(world: World, x: float, y: float, speed: float) -> int:
    s = ENEMY_SCALE / 2
    triangle = ((0.0, s), (-s, -s), (s, -s))  # nose up, like the sprite
    return world.spawn(
        Transform(x, y),
        RigidBody(gravity_scale=0.0),
        Collider(Polygon(triangle), sensor=True),
        Sprite("enemy.png", size=(ENEMY_SCALE, ENEMY_SCALE), layer=1),
        Behaviour(Enemy(speed)),
        Name("enemy"),
        engine_trail(),
    )


def engine_trail() -> kge.ParticleEmitter:
    """Hot exhaust behind an enemy (local -y): 25 puffs per metre flown, fading red."""
    return kge.ParticleEmitter(
        rate_per_meter=25.0, offset=(0.0, -ENEMY_SCALE / 2), direction=-math.pi / 2, spread=0.6,
        speed=(0.2, 0.6), lifetime=(0.25, 0.5), size=(0.14, 0.02), opacity=(230, 0),
        color=((255, 220, 120), (255, 90, 20), (90, 20, 10)), blend=Blend.ADDITIVE,
        max_particles=64,
    )  # fmt: skip


def explosion(world: World, at: tuple[float, float]) -> int:
    """A one-shot burst of sparks where an enemy died; the entity despawns itself when done."""
    return world.spawn(Transform(*at), Name("sparks"), kge.ParticleEmitter(
        burst=60, one_shot=True, spread=2 * math.pi, speed=(1.0, 4.0), drag=3.0,
        lifetime=(0.3, 0.7), size=(0.18, 0.03), opacity=(255, 0), blend=Blend.ADDITIVE,
        color=((255, 255, 200), (255, 150, 40), (160, 30, 0)),
    ))  # fmt: skip


class Referee(Script):
    """Reads this step's sensor events: shots kill enemies, enemies kill the ship,
    shots leaving the frame vanish. Reading events after the step (not inside a
    physics callback) is what makes despawning here always safe."""

    def on_fixed_update(self, dt: float) -> None:
        world = self.world
        for ev in world.events(SensorBegin):
            a, b = sorted((ev.collider_a, ev.collider_b))
            kinds = {_kind(world, a): a, _kind(world, b): b}
            if "shot" in kinds and "enemy" in kinds:
                self.kill(kinds["enemy"], kinds["shot"])
            elif "enemy" in kinds and "ship" in kinds:
                self.lose(kinds["ship"])
            elif "shot" in kinds and "frame" in kinds:
                _despawn(world, kinds["shot"])

    def kill(self, enemy: int, shot: int) -> None:
        if not (self.world.exists(enemy) and self.world.exists(shot)):
            return
        t = self.world.get(enemy, Transform)
        explode(self.world, t.x, t.y)  # the animated blast
        explosion(self.world, t.position)  # and its particles
        shake(self.world, 0.3)  # the camera shakes on a hit
        _despawn(self.world, enemy)
        _despawn(self.world, shot)
        self.world.resource(Audio).play("explosion.wav", volume=0.2)
        ships = self.world.query(ShipTag, Behaviour)
        if ships:
            ships[0][1][1].script.score += 1

    def lose(self, ship: int) -> None:
        if not self.world.exists(ship):
            return
        t = self.world.get(ship, Transform)
        explode(self.world, t.x, t.y, size=2.0)
        shake(self.world, 0.8)
        _despawn(self.world, ship)
        for _, (beh,) in self.world.query(Behaviour):
            if isinstance(beh.script, Spawner):
                beh.script.stopped = True
        self.world.resource(Audio).play("death.wav", volume=0.8)
        self.world.spawn(Transform(0.0, 0.5), Text("GAME OVER", size=30, bold=True, color=BLUE),
                         Name("game-over"))
        self.world.spawn(Transform(0.0, -0.7), Text("PRESS R TO RESTART", size=20, bold=True,
                                                    color=BLUE), Name("game-over"))


# -- animation: explosions and the thruster, cut from generated sheets ---------------------
EXPLOSION = Clip.grid("explosion_sheet.png", (8, 1), fps=20, loop=Loop.ONCE)
THRUSTER = Clip.grid("thruster.png", (4, 1), duration=[0.06, 0.05, 0.07, 0.05])


class Blast(Script):
    """An explosion that removes itself when its clip ends."""

    def on_animation_end(self, event: object) -> None:
        self.despawn()


def explode(world: World, x: float, y: float, size: float = 1.2) -> int:
    return world.spawn(Transform(x, y), Sprite("explosion_sheet.png", size=(size, size), layer=2),
                       Animator({"boom": EXPLOSION}), Behaviour(Blast()), Name("explosion"))


class Thruster(Script):
    """A flame behind the ship, turning with it (and gone with it)."""

    def on_late_update(self, dt: float) -> None:
        ships = self.world.query(ShipTag, Transform)
        if not ships:
            self.despawn()
            return
        ship = ships[0][1][1]
        back = SHIP_RADIUS * 1.1  # the ship art points along +y of its angle
        self.transform.x = ship.x + math.sin(ship.angle) * back
        self.transform.y = ship.y - math.cos(ship.angle) * back
        self.transform.angle = ship.angle


def _kind(world: World, entity: int) -> str:
    name = world.try_get(entity, Name)
    return name.value if name is not None else ""


def _despawn(world: World, entity: int) -> None:
    if world.exists(entity):
        world.despawn(entity)


class Hud(Script):
    """Keeps the score text current (it stays after the ship dies); R restarts."""

    def __init__(self, label: int | None = None) -> None:
        self.score = 0
        self.label = label  # the HUD corner label that shows it

    def on_update(self, dt: float) -> None:
        ships = self.world.query(ShipTag, Behaviour)
        if ships:
            self.score = ships[0][1][1].script.score
        text = f"Score : {self.score}"
        if self.get(Text).text != text:
            self.get(Text).text = text
            if self.label is not None:
                self.world.get(self.label, kge.Label).text = text

    def on_key_down(self, key: int) -> None:
        if key == Key.R:
            self.world.resource(App).replace_scene(game)


class Aim(Script):
    """A ring that follows the mouse."""

    def on_update(self, dt: float) -> None:
        self.transform.position = self.world.resource(Input).mouse_world


def game(world: World, seed: int | None = None) -> None:
    """The game scene (seed the enemy spawner for repeatable tests)."""
    world.insert_resource(ASSETS)
    bind_actions(world)
    world.resource(Audio).play_music("music_loop.wav", volume=0.5)  # keyed: never stacks
    world.spawn(
        Transform(0.0, 0.0),
        RigidBody(gravity_scale=0.0),
        Collider(Circle(SHIP_RADIUS), sensor=True),
        Sprite("ship.png", size=(2 * SHIP_RADIUS, 2 * SHIP_RADIUS), layer=1),
        ShipTag(),
        Behaviour(Ship()),
        Name("ship"),
    )
    world.spawn(Transform(0.0, -SHIP_RADIUS), Sprite("thruster.png", size=(0.45, 0.45), layer=0),
                Animator({"flame": THRUSTER}), Behaviour(Thruster()), Name("thruster"))
    f = FRAME_HALF
    world.spawn(Transform(), Collider(Chain([(-f, -f), (f, -f), (f, f), (-f, f)], loop=True),
                                      sensor=True), Name("frame"))
    world.spawn(Transform(), draw.Circle(0.125, color=BLUE, filled=False, layer=3),
                Behaviour(Aim()), Name("aim"))
    world.spawn(Behaviour(Spawner(random.Random(seed))), Name("spawner"))
    world.spawn(Behaviour(Referee()))
    label = ui.hud_label(world, "top_left", "Score : 0", size=24, color=BLUE)
    world.spawn(Transform(-4.0, -5.0), Text("Score : 0", visible=False),
                Behaviour(Hud(label)), Name("score"))  # the number; shown by the HUD label
    world.spawn(Behaviour(ui.PauseKey(menu, tuple(ACTIONS))))


class MenuKeys(Script):
    def on_key_up(self, key: int) -> None:
        if key == Key.SPACE:
            self.world.resource(App).replace_scene(game)


def bind_actions(world: World) -> None:
    """The game's actions, bound once per App (the settings may rebind them)."""
    actions = world.resource(kge.InputMap)
    ui.bind_defaults(actions, ACTIONS)
    actions.bind_axis("aim_x", stick="pad:rightx", dead_zone=0.3)
    actions.bind_axis("aim_y", stick="pad:righty", dead_zone=0.3)
    actions.bind_vector("aim", "aim_x", "aim_y")


def menu(world: World) -> None:
    """Title screen: Play (fades in), Settings, Quit; Space starts at once."""
    world.insert_resource(ASSETS)
    bind_actions(world)
    ui.title_menu(world, "DEFEND THE CENTRE", "Space: play at once.  Aim with the mouse "
                  "(or the right stick), hold the left button (or A) to fire.", game,
                  tuple(ACTIONS), hint_color=BLUE)  # fmt: skip
    world.spawn(Behaviour(MenuKeys()))


def main() -> None:
    app = App(menu, title="Kiss Game Engine", size=SIZE, background=(255, 255, 255))
    if app.headless:
        app.input.press(Key.SPACE)
        app.step()
        app.input.release(Key.SPACE)
        app.step()
        app.input.mouse_down(Mouse.LEFT)
        for _ in range(60 * 10):  # a self-playing demo: aim at the oldest enemy
            enemies = sorted(e for e, (n,) in app.world.query(Name) if n.value == "enemy")
            if enemies:
                t = app.world.get(enemies[0], Transform)
                app.input.move_mouse(*app.world_to_screen((t.x, t.y)))
            app.step()
        hud = next(t for _, (n, t) in app.world.query(Name, Text) if n.value == "score")
        print(f"kge {kge.__version__} shooter, 10 s headless with auto-aim: {hud.text}")
        app.screenshot("out/shooter.png")
        print("screenshot: out/shooter.png")
        app.close()
    else:
        app.run()


if __name__ == "__main__":
    main()
