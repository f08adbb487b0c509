"""pyglet's player worker can remove a player twice (a check-then-act race); the mixer's
pump drops exactly that KeyError and dispatches the rest of the queue."""

from __future__ import annotations

import pytest

from kge.audio.mixer import pump_posted_events


class Loop:
    """A posted-event queue whose first event hits the worker's double removal."""

    def __init__(self, worker_file: str) -> None:
        self.events = ["eos-of-a-player-the-worker-already-dropped", "next"]
        self.seen: list[str] = []
        code = compile("def remove(player):\n    raise KeyError(player)\n", worker_file, "exec")
        namespace: dict[str, object] = {}
        exec(code, namespace)
        self.remove = namespace["remove"]

    def dispatch_posted_events(self) -> None:
        while self.events:
            event = self.events.pop(0)
            self.seen.append(event)
            if event.startswith("eos"):
                self.remove(event)  # type: ignore[operator]


def test_the_double_removal_is_dropped_and_the_queue_drains() -> None:
    loop = Loop("/x/pyglet/media/player_worker_thread.py")
    pump_posted_events(loop)
    assert loop.seen == ["eos-of-a-player-the-worker-already-dropped", "next"]


def test_other_key_errors_are_raised() -> None:
    loop = Loop("/x/my_game/sounds.py")
    with pytest.raises(KeyError):
        pump_posted_events(loop)
