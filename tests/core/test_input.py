"""Input edges over frames, hooks, and key constants without a window."""

from kge import App, Behaviour, Input, Key, Mouse, Script, World


def test_pressed_and_released_last_exactly_one_frame() -> None:
    seen: list[tuple[bool, bool, bool]] = []

    class Probe(Script):
        def on_update(self, dt: float) -> None:
            inp = self.world.resource(Input)
            seen.append((inp.pressed(Key.SPACE), inp.held(Key.SPACE), inp.released(Key.SPACE)))

    def scene(world: World) -> None:
        world.spawn(Behaviour(Probe()))

    app = App(scene, headless=True)
    app.input.press(Key.SPACE)
    app.step()
    app.step()
    app.input.release(Key.SPACE)
    app.step()
    app.step()
    assert seen == [
        (True, True, False),
        (False, True, False),
        (False, False, True),
        (False, False, False),
    ]


def test_key_and_mouse_hooks_receive_events() -> None:
    log: list[object] = []

    class Probe(Script):
        def on_key_down(self, key: int) -> None:
            log.append(("down", key))

        def on_key_up(self, key: int) -> None:
            log.append(("up", key))

        def on_mouse_down(self, event) -> None:
            log.append(("mouse", event.button, event.screen))

    def scene(world: World) -> None:
        world.spawn(Behaviour(Probe()))

    app = App(scene, headless=True)
    app.input.press(Key.W)
    app.input.press(Key.W)  # auto-repeat while held is not a second press
    app.input.click(Mouse.LEFT, at=(10, 20))
    app.step()
    app.input.release(Key.W)
    app.step()
    assert log == [("down", Key.W), ("mouse", Mouse.LEFT, (10.0, 20.0)), ("up", Key.W)]


def test_axis_and_mouse_state() -> None:
    inp = Input()
    inp.press(Key.UP)
    assert inp.axis((Key.S, Key.DOWN), (Key.W, Key.UP)) == 1.0
    inp.press(Key.S)
    assert inp.axis((Key.S, Key.DOWN), (Key.W, Key.UP)) == 0.0
    inp.mouse_down(Mouse.RIGHT, at=(5, 6))
    assert inp.mouse_held(Mouse.RIGHT) and inp.mouse_pressed(Mouse.RIGHT)
    inp.end_frame()
    assert inp.mouse_held(Mouse.RIGHT) and not inp.mouse_pressed(Mouse.RIGHT)
    inp.scroll_by(0, 2)
    assert inp.scroll == (0, 2)


def test_key_codes_match_pyglet() -> None:
    # Values are pyglet's, so window events need no translation. Checked in a
    # subprocess-free way: pyglet.window.key is importable headless under EGL.
    from pyglet.window import key as pkey

    assert (Key.A, Key.SPACE, Key.LEFT, Key.ESCAPE, Key.F11) == (
        pkey.A, pkey.SPACE, pkey.LEFT, pkey.ESCAPE, pkey.F11,
    )
