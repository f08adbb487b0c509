"""Pong played headless with scripted input."""

import pong  # examples/pong.py

from kge import App, Audio, Key, Text, Transform
from kge.testbed.samples.build import named


def score(app: App, who: str) -> str:
    return app.world.get(named(app.world, f"score-{who}")[0], Text).text


def start(seed: int = 1) -> App:
    app = App(pong.menu, headless=True, size=pong.SIZE)
    app.input.press(Key.SPACE)
    app.step()
    app.input.release(Key.SPACE)
    app.step()
    assert named(app.world, "ball"), "Space on the menu starts a match"
    return app


def test_idle_player_concedes_points_to_the_ai_and_the_hud_shows_them() -> None:
    app = start()
    app.step(60 * 15)
    assert int(score(app, "ai")) >= 1, "the AI should have scored against an idle player"
    assert score(app, "player") == "0"
    app.close()


def test_ball_keeps_its_speed_and_stays_in_the_court() -> None:
    app = start()
    app.step(90)
    ball = named(app.world, "ball")[0]
    rb = app.world.get(ball, pong.RigidBody)
    speed = (rb.velocity[0] ** 2 + rb.velocity[1] ** 2) ** 0.5
    assert abs(speed - (10**2 + 4**2) ** 0.5) < 0.2  # restitution 1, no friction
    for _ in range(200):
        app.step()
        for e in named(app.world, "ball"):
            assert abs(app.world.get(e, Transform).y) < 5.5


def test_player_paddle_moves_with_w_and_arrows_and_stays_in_bounds() -> None:
    app = start()
    paddle = named(app.world, "paddle-left")[0]
    app.input.press(Key.W)
    app.step(30)
    y = app.world.get(paddle, Transform).y
    assert abs(y - 3.5) < 0.15  # 7 m/s for 0.5 s
    app.step(60)
    assert abs(app.world.get(paddle, Transform).y - pong.PLAYER_LIMIT) < 1e-6
    app.input.release(Key.W)
    app.input.press(Key.DOWN)
    app.step(30)
    assert app.world.get(paddle, Transform).y < y


def test_restart_resets_the_score_and_music_never_stacks() -> None:
    app = start()
    app.step(60 * 15)
    assert score(app, "ai") != "0"
    app.input.press(Key.R)
    app.step()
    app.input.release(Key.R)
    app.input.press(Key.R)
    app.step()
    assert score(app, "ai") == "0" and score(app, "player") == "0"
    audio = app.world.resource(Audio)
    assert audio.music is not None and audio.music.playing
    app.close()


def serve_at(app: App, y: float) -> tuple[int, int]:
    """Put the ball on a course to meet the player's paddle ``y`` metres off its centre."""
    ball = named(app.world, "ball")[0]
    paddle = named(app.world, "paddle-left")[0]
    t = app.world.get(ball, Transform)
    t.x, t.y = -5.0, app.world.get(paddle, Transform).y + y
    app.world.get(ball, pong.RigidBody).velocity = (-10.0, 0.0)
    return ball, paddle


def test_where_the_ball_meets_the_paddle_aims_it() -> None:
    angles = {}
    for offset in (0.0, 0.6, -0.6):
        app = start()
        ball, _ = serve_at(app, offset)
        for _ in range(60):
            app.step()
            vx, vy = app.world.get(ball, pong.RigidBody).velocity
            if vx > 0:
                break
        assert vx > 0, "the ball came back off the paddle"
        assert abs((vx**2 + vy**2) ** 0.5 - 10.0) < 0.1  # same speed, new angle
        angles[offset] = vy
        app.close()
    assert abs(angles[0.0]) < 0.5
    assert angles[0.6] > 3.0 and angles[-0.6] < -3.0  # the top edge sends it up, and so on


def test_esc_on_the_menu_quits() -> None:
    app = App(pong.menu, headless=True, size=pong.SIZE)
    app.input.press(Key.ESCAPE)
    app.run(frames=100)  # headless: stops at quit
    assert app.frame_count == 1 and not app.running


def test_paddles_stop_when_the_match_is_over() -> None:
    app = start()
    pong.game_over(app.world, "You win!")
    paddle = named(app.world, "paddle-left")[0]
    y = app.world.get(paddle, Transform).y
    app.input.press(Key.W)
    app.step(30)
    assert app.world.get(paddle, Transform).y == y
    ai = named(app.world, "paddle-right")[0]
    y_ai = app.world.get(ai, Transform).y
    app.step(30)
    assert app.world.get(ai, Transform).y == y_ai
