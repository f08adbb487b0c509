"""PONG: KGE 1.0's example game, rebuilt from kge components.

Rules (as in KGE): the left paddle is yours, the right one is an AI that tracks
the ball's height exactly unless the ball is near the top or bottom edge. The
ball starts after one second at (10, -4) m/s, bounces with restitution 1 and no
friction, and each velocity component is capped at 20 m/s. A ball in the left
goal scores for the AI, in the right goal for you; a new ball then serves after
a second. kge adds a menu, a winner at 5 points and a restart, and fixes KGE's
bugs: the music never stacks on a restart, both W/S and the arrows work (and Z
for AZERTY players), and assets load wherever the game is started from.

Controls: W / Z / Up and S / Down move (or a gamepad's d-pad / left stick); R
restarts; P, Esc or Start pauses (a see-through menu: resume, settings, main menu).
The title menu and the settings (volumes, key rebinding) are kge UI, shared with the
shooter in ``game_menus.py``.

Run: ``python examples/pong.py`` (a window; headless machines get a short
self-played match and a summary).
"""

from __future__ import annotations

import math
import random

import game_menus as ui  # imports kge_required first
import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

import kge
from kge import (
    App,
    Assets,
    Audio,
    Behaviour,
    BodyType,
    Box,
    Circle,
    Collider,
    Key,
    Name,
    RigidBody,
    Script,
    Sprite,
    Text,
    Transform,
    Tween,
    Tweens,
    TweenSequence,
    Wait,
    World,
)

ASSETS = Assets(anchor=__file__)  # examples/ and examples/assets/, whatever the working dir

SIZE = (1000, 700)  # 64 px/m: the view spans x in [-7.81, 7.81], y in [-5.47, 5.47]
PADDLE_HALF = (24 / 64 / 2, 115 / 64 / 2)  # KGE's 24 x 115 px collider
PADDLE_SPEED = 7.0
PLAYER_LIMIT = 4.46875  # KGE's B_UP for the player
AI_LIMIT = 4.21875  # and for the AI
AI_STOP = AI_LIMIT - 0.5  # KGE's AI stops tracking a ball beyond +-3.72 m
BALL_RADIUS = 1 / 6
MAX_BALL_SPEED = 20.0
SERVE_DELAY = 1.0
WINNING_SCORE = 5
#: a ball meeting a paddle's very edge leaves with vy = 0.75 of its speed (the centre: 0)
MAX_ENGLISH = 0.75
#: the actions a player can rebind in the settings, with their default bindings
ACTIONS: ui.Bindings = {
    "up": ("key:W", "key:Z", "key:UP", "pad:dpup"),
    "down": ("key:S", "key:DOWN", "pad:dpdown"),
}


class Score(Script):
    """Holds one side's points and shows them in its Text and its corner of the HUD."""

    def __init__(self, side: str, hud: int | None = None) -> None:
        self.side = side
        self.points = 0
        self.hud = hud

    def add(self) -> None:
        self.points += 1
        self.get(Text).text = str(self.points)
        self.world.resource(Tweens).start(self.entity, SCORE_POP)  # the number pops
        if self.hud is not None:  # the HUD corner shows it, and pops the same way
            self.world.get(self.hud, kge.Label).text = f"{self.side}  {self.points}"
            self.world.resource(Tweens).start(self.hud, HUD_POP)


#: a point scored: the score grows quickly, then bounces back to its size
SCORE_POP = TweenSequence(Tween(Text, "size", 24.0, 0.12, ease="quad_out", start=15.0),
                     Tween(Text, "size", 15.0, 0.35, ease="bounce_out"), name="score-pop")
HUD_POP = TweenSequence(Tween(kge.Label, "size", 30.0, 0.12, ease="quad_out", start=22.0),
                   Tween(kge.Label, "size", 22.0, 0.35, ease="bounce_out"), name="hud-pop")


class PlayerPaddle(Script):
    """Moves with the keys at 7 m/s, clamped to the court (a kinematic body)."""

    def on_fixed_update(self, dt: float) -> None:
        actions = self.world.resource(kge.InputMap)  # keys, d-pad (rebindable) and stick
        direction = float(actions.held("up")) - float(actions.held("down"))
        direction = min(max(direction + actions.axis("paddle_stick"), -1.0), 1.0)
        if self.world.has_resource(MatchOver):
            direction = 0.0
        move(self, direction * PADDLE_SPEED, PLAYER_LIMIT, dt)


class AIPaddle(Script):
    """KGE's AI: match the ball's height within one step, except near the edges."""

    def on_fixed_update(self, dt: float) -> None:
        balls = self.world.query(Ball.Tag, Transform)
        ball_y = balls[0][1][1].y if balls else None
        if ball_y is None or abs(ball_y) >= AI_STOP or self.world.has_resource(MatchOver):
            move(self, 0.0, AI_LIMIT, dt)
        else:
            move(self, (ball_y - self.transform.y) / dt, AI_LIMIT, dt)


def move(script: Script, speed: float, limit: float, dt: float) -> None:
    """Drive a kinematic paddle at ``speed`` (m/s) without leaving [-limit, limit]."""
    y = script.transform.y
    target = min(max(y + speed * dt, -limit), limit)
    script.get(RigidBody).velocity = (0.0, (target - y) / dt)


class Ball(Script):
    """Waits, serves, keeps its speed under the cap and sounds its bounces."""

    class Tag:
        """Marks the ball entity (the AI and the goals look for it)."""

    def __init__(self, velocity: tuple[float, float]) -> None:
        self.serve = velocity

    def on_start(self) -> None:
        self.start_coroutine(self.serve_after_delay())

    def serve_after_delay(self):  # type: ignore[no-untyped-def]
        yield Wait(SERVE_DELAY)
        self.get(RigidBody).velocity = self.serve

    def on_fixed_update(self, dt: float) -> None:
        rb = self.get(RigidBody)
        vx, vy = rb.velocity
        cx = min(max(vx, -MAX_BALL_SPEED), MAX_BALL_SPEED)
        cy = min(max(vy, -MAX_BALL_SPEED), MAX_BALL_SPEED)
        if (cx, cy) != (vx, vy):
            rb.velocity = (cx, cy)

    def on_contact_begin(self, event) -> None:  # type: ignore[no-untyped-def]
        other = event.collider_b if event.collider_a == self.entity else event.collider_a
        name = self.world.try_get(other, Name)
        paddle = name is not None and name.value.startswith("paddle")
        if paddle:
            self.english(other)
        sound = "paddle_hit.wav" if paddle else "wall_hit.wav"
        self.world.resource(Audio).play(sound, volume=0.5)

    def english(self, paddle: int) -> None:
        """Aim: where the ball meets the paddle sets its angle (the edges send it steep),
        at the same speed, always away from that paddle."""
        rb = self.get(RigidBody)
        speed = math.hypot(*rb.velocity)
        p = self.world.get(paddle, Transform)
        offset = max(-1.0, min(1.0, (self.transform.y - p.y) / PADDLE_HALF[1]))
        vy = offset * MAX_ENGLISH * speed
        vx = math.copysign(math.sqrt(max(speed * speed - vy * vy, 0.0)), -p.x)
        rb.velocity = (vx, vy)


def spawn_ball(world: World, velocity: tuple[float, float]) -> int:
    return world.spawn(
        Transform(0.0, 0.0),
        RigidBody(gravity_scale=0.0, fixed_rotation=True, bullet=True),
        Collider(Circle(BALL_RADIUS, center=(-0.03, 0.0)), friction=0.0, restitution=1.0),
        Sprite("ball.png", size=(2 * BALL_RADIUS + 0.06, 2 * BALL_RADIUS + 0.06), layer=1),
        Ball.Tag(),
        Behaviour(Ball(velocity)),
        Name("ball"),
    )


class Goal(Script):
    """A sensor behind a paddle: a ball entering it scores for ``scorer``."""

    def __init__(self, scorer: int, serve_direction: float, rng: random.Random) -> None:
        self.scorer = scorer
        self.direction = serve_direction
        self.rng = rng

    def on_sensor_begin(self, event) -> None:  # type: ignore[no-untyped-def]
        ball = event.body_b
        if ball is None or not self.world.has(ball, Ball.Tag) or not self.world.exists(ball):
            return
        self.world.despawn(ball)
        score = self.world.get(self.scorer, Behaviour).script
        score.add()
        self.world.resource(Audio).play("score.wav", volume=0.6)
        if score.points >= WINNING_SCORE:
            game_over(self.world, f"{score.side} wins!")
            return
        vy = float(self.rng.randint(-5, 5)) or self.rng.choice((-5.0, 5.0))
        spawn_ball(self.world, (10.0 * self.direction, vy))


class MatchOver:
    """A resource: the match is decided; the paddles stop until R or Esc."""


def game_over(world: World, message: str) -> None:
    world.insert_resource(MatchOver())
    for text, y, size in ((message, 0.5, 36), ("R: play again    Esc: menu", -0.5, 16)):
        label = Text(text, size=size, bold=True, layer=10)
        world.spawn(Transform(0.0, y), label, Name("game-over"))


class Keys(Script):
    """R restarts the match (a fresh scene); pausing is the "pause" action (ui.PauseKey)."""

    def on_key_down(self, key: int) -> None:
        if key == Key.R:
            self.world.resource(App).replace_scene(pong)


def pong(world: World, seed: int | None = None) -> None:
    """The match scene."""
    world.insert_resource(ASSETS)
    bind_actions(world)
    rng = random.Random(seed)
    world.resource(Audio).play_music("music_loop.wav", volume=0.5)  # keyed: never stacks
    world.spawn(Transform(0.0, 0.0), Sprite("background.png", size=(16.0, 11.0), layer=0,
                                            tint=(60, 60, 60)))
    for side, x, image, script in (("left", -7.0, "pad_left.png", PlayerPaddle()),
                                   ("right", 7.0, "pad_right.png", AIPaddle())):
        world.spawn(
            Transform(x, 0.0),
            RigidBody(type=BodyType.KINEMATIC),
            Collider(Box(*PADDLE_HALF), friction=0.0, restitution=1.0),
            Sprite(image, size=(2 * PADDLE_HALF[0], 2 * PADDLE_HALF[1]), layer=1),
            Behaviour(script),
            Name(f"paddle-{side}"),
        )
    for y in (6.0, -6.0):  # walls: inner faces at y = +-5.5
        world.spawn(Transform(0.0, y), Collider(Box(10.0, 0.5), friction=0.0, restitution=1.0),
                    Name("wall"))
    # the scores show in the HUD's top corners; their Texts keep the numbers (hidden)
    you_hud = ui.hud_label(world, "top_left", "You  0", size=22)
    ai_hud = ui.hud_label(world, "top_right", "The AI  0", size=22)
    you = world.spawn(Transform(-1.0, 5.0), Text("0", visible=False),
                      Behaviour(Score("You", you_hud)), Name("score-player"))
    ai = world.spawn(Transform(1.0, 5.0), Text("0", visible=False),
                     Behaviour(Score("The AI", ai_hud)), Name("score-ai"))
    # A ball in the left goal is a point for the AI; it then serves towards the player.
    world.spawn(Transform(-8.0, 0.0), Collider(Box(0.5, 10.0), sensor=True),
                Behaviour(Goal(ai, -1.0, rng)), Name("goal-left"))
    world.spawn(Transform(8.0, 0.0), Collider(Box(0.5, 10.0), sensor=True),
                Behaviour(Goal(you, 1.0, rng)), Name("goal-right"))
    world.spawn(Behaviour(Keys()))
    world.spawn(Behaviour(ui.PauseKey(menu, tuple(ACTIONS))))
    spawn_ball(world, (10.0, -4.0))


class MenuKeys(Script):
    """Space or Enter plays; Esc quits."""

    def on_key_down(self, key: int) -> None:
        if key in (Key.SPACE, Key.ENTER, Key.RETURN):
            self.world.resource(App).replace_scene(pong)
        elif key == Key.ESCAPE:
            self.world.resource(App).quit()


def bind_actions(world: World) -> None:
    """The game's actions, bound once per App (the settings may rebind them)."""
    actions = world.resource(kge.InputMap)
    ui.bind_defaults(actions, ACTIONS)
    actions.bind_axis("paddle_stick", stick="pad:lefty", dead_zone=0.25)


def menu(world: World) -> None:
    """Title screen: Play (fades in), Settings, Quit; Space starts a match at once."""
    world.insert_resource(ASSETS)
    bind_actions(world)
    world.resource(Audio).play_music("music_loop.wav", volume=0.5)
    ui.title_menu(world, "PONG !", "Space: play at once.  W/S, the arrows or a gamepad move "
                  "your paddle; aim with where the ball meets it. First to 5.  Esc: quit",
                  pong, tuple(ACTIONS))  # fmt: skip
    world.spawn(Behaviour(MenuKeys()))


def main() -> None:
    app = App(menu, title="PONG !", size=SIZE)
    if app.headless:
        app.input.press(Key.SPACE)
        app.step(2)
        app.step(60 * 8)
        scores = {n.value: t.text for _, (n, t) in app.world.query(Name, Text)
                  if n.value.startswith("score")}
        print(f"kge {kge.__version__} pong, 8 s headless with an idle player: {scores}")
        app.screenshot("out/pong.png")
        print("screenshot: out/pong.png")
        app.close()
    else:
        app.run()


if __name__ == "__main__":
    main()
