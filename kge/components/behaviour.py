"""``Behaviour``: attach a script object to an entity.

Scripts are plain objects (usually subclasses of :class:`Script`) with any of the
hooks below; kge calls the ones that exist. Each hook's parameters are checked
when the Behaviour is created, so a typo such as ``def on_update(self)`` fails
at once with a message naming the hook, not silently or mid-game.

=====================  ================  =======================================
hook                   arguments         when
=====================  ================  =======================================
on_start               ()                once, before the entity's first update
on_fixed_update        (dt)              every fixed step, before physics
on_update              (dt)              every frame
on_late_update         (dt)              every frame, after all on_update
on_destroy             ()                the entity is despawned / scene closes
on_contact_begin/end   (event)           a collider of this entity touches
on_sensor_begin/end    (event)           a sensor overlap starts/ends
on_hit                 (event)           an impact above the hit threshold
on_key_down/up         (key)             a key code from :mod:`kge.keys`
on_mouse_down/up/move  (event)           a :class:`kge.input.MouseEvent`
on_mouse_scroll        (event)
on_animation_event     (event)           a named frame of a clip was entered
on_animation_end       (event)           a once/hold clip finished
on_tween_end           (event)           a tween started on this entity ended
on_timeline_end        (event)           a timeline (TimelinePlayer) reached its end
on_text                (text)            characters typed (after the keyboard layout)
on_gamepad_down/up     (event)           a :class:`kge.input.GamepadEvent`
on_click               (event)           a UI button of this entity was clicked
on_value_changed       (event)           a UI toggle/slider/dropdown/list/text changed
on_text_submitted      (event)           Enter in a UI text field of this entity
=====================  ================  =======================================

>>> class Spin(Script):
...     def on_update(self, dt):
...         self.get(Transform).angle += dt
>>> b = Behaviour(Spin())
>>> class Broken(Script):
...     def on_update(self):
...         pass
>>> Behaviour(Broken())
Traceback (most recent call last):
...
kge.errors.HookSignatureError: Broken.on_update(self) takes 0 arguments; kge calls on_update(dt)
"""

from __future__ import annotations

import difflib
import inspect
from collections.abc import Callable, Generator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeVar

from kge.components.transform import Transform
from kge.coroutines import Coroutine
from kge.errors import ComponentTypeError, HookSignatureError
from kge.host import Host

if TYPE_CHECKING:
    from kge.world import World

T = TypeVar("T")

#: hook name -> (number of arguments after self, how kge calls it)
HOOKS: dict[str, tuple[int, str]] = {
    "on_start": (0, "on_start()"),
    "on_fixed_update": (1, "on_fixed_update(dt)"),
    "on_update": (1, "on_update(dt)"),
    "on_late_update": (1, "on_late_update(dt)"),
    "on_destroy": (0, "on_destroy()"),
    "on_contact_begin": (1, "on_contact_begin(event)"),
    "on_contact_end": (1, "on_contact_end(event)"),
    "on_sensor_begin": (1, "on_sensor_begin(event)"),
    "on_sensor_end": (1, "on_sensor_end(event)"),
    "on_hit": (1, "on_hit(event)"),
    "on_key_down": (1, "on_key_down(key)"),
    "on_key_up": (1, "on_key_up(key)"),
    "on_mouse_down": (1, "on_mouse_down(event)"),
    "on_mouse_up": (1, "on_mouse_up(event)"),
    "on_mouse_move": (1, "on_mouse_move(event)"),
    "on_mouse_scroll": (1, "on_mouse_scroll(event)"),
    "on_animation_event": (1, "on_animation_event(event)"),
    "on_animation_end": (1, "on_animation_end(event)"),
    "on_tween_end": (1, "on_tween_end(event)"),
    "on_timeline_end": (1, "on_timeline_end(event)"),
    "on_text": (1, "on_text(text)"),
    "on_gamepad_down": (1, "on_gamepad_down(event)"),
    "on_gamepad_up": (1, "on_gamepad_up(event)"),
    "on_click": (1, "on_click(event)"),
    "on_value_changed": (1, "on_value_changed(event)"),
    "on_text_submitted": (1, "on_text_submitted(event)"),
    "on_item_activated": (1, "on_item_activated(event)"),
    "on_item_toggled": (1, "on_item_toggled(event)"),
    "on_dialog_closed": (1, "on_dialog_closed(event)"),
    "on_drag_started": (1, "on_drag_started(event)"),
    "on_drop": (1, "on_drop(event)"),
    "on_drag_cancelled": (1, "on_drag_cancelled(event)"),
}

_hook_cache: dict[type, tuple[str, ...]] = {}


def _accepts(fn: Callable[..., Any], n: int) -> bool:
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):  # builtins without a signature: trust them
        return True
    try:
        sig.bind(*([None] * n))
    except TypeError:
        return False
    return True


def _check_spelling(cls: type) -> None:
    """Refuse a method one typo away from a hook (``on_udpate``): kge would never call it."""
    for name in dir(cls):
        if not name.startswith("on_") or name in HOOKS:
            continue
        close = difflib.get_close_matches(name, HOOKS, n=1, cutoff=0.85)
        if close:
            raise HookSignatureError(
                f"{cls.__name__}.{name} is not a kge hook and would never be called; "
                f"did you mean {close[0]}? (kge calls {HOOKS[close[0]][1]})"
            )


def script_hooks(script: object) -> tuple[str, ...]:
    """The hook names ``script`` defines, after checking their signatures and spelling.

    Looked up per instance: a hook assigned on one instance (``s.on_update = fn``)
    belongs to that instance only. The per-class cache is used for instances
    without such assignments, and filled only from them.
    """
    cls = type(script)
    own: dict[str, Any] = getattr(script, "__dict__", None) or {}
    per_instance = any(name in own for name in HOOKS)
    cached = None if per_instance else _hook_cache.get(cls)
    if cached is not None:
        return cached
    _check_spelling(cls)
    found = []
    for name, (nargs, call) in HOOKS.items():
        fn = getattr(script, name, None)
        if fn is None:
            continue
        if not callable(fn):
            raise HookSignatureError(f"{cls.__name__}.{name} is not callable; kge calls {call}")
        if not _accepts(fn, nargs):
            try:
                params = str(inspect.signature(getattr(cls, name)))
            except (TypeError, ValueError, AttributeError):
                params = "(...)"
            raise HookSignatureError(
                f"{cls.__name__}.{name}{params} takes {_count(fn)} arguments; kge calls {call}"
            )
        found.append(name)
    result = tuple(found)
    if not per_instance:
        _hook_cache[cls] = result
    return result


def _count(fn: Callable[..., Any]) -> int:
    try:
        return len(inspect.signature(fn).parameters)
    except (TypeError, ValueError):  # pragma: no cover
        return -1


class Script:
    """Convenience base for behaviour scripts: entity, world and coroutine helpers.

    ``self.entity`` and ``self.world`` are set when the Behaviour is attached.
    """

    entity: int = 0
    world: World

    def get(self, component_type: type[T]) -> T:
        """This entity's component of ``component_type``."""
        return self.world.get(self.entity, component_type)

    @property
    def transform(self) -> Transform:
        return self.world.get(self.entity, Transform)

    @property
    def app(self) -> Host:
        """The App running this script's scene: ``self.app.replace_scene(Level2,
        transition=Fade(0.4))``, ``push_scene``, ``pop_scene``, ``quit()``, ``size``,
        ``input``. Scene changes asked for here happen when the frame ends."""
        world = getattr(self, "world", None)
        host = world.try_resource(Host) if world is not None else None
        if host is None:
            raise LookupError(
                f"{type(self).__name__}.app: this script is not run by an App (not attached "
                "yet, or in a bare World)"
            )
        return host

    def start_coroutine(self, gen: Generator[Any, None, Any]) -> Coroutine:
        """Run generator ``gen`` as a coroutine of this entity (see :mod:`kge.coroutines`)."""
        co = Coroutine(self.entity, gen)
        pending: list[Coroutine] = self.__dict__.setdefault("_kge_coroutines", [])
        pending.append(co)
        runner = self.__dict__.get("_kge_runner")
        if runner is not None:
            runner.adopt(self)
        return co

    def despawn(self) -> None:
        """Despawn this script's entity (at the next flush)."""
        self.world.despawn(self.entity)

    def __getstate__(self) -> dict[str, Any]:
        """Snapshots keep the script's own data, not its world or its running coroutines."""
        state = dict(self.__dict__)
        for key in ("world", "_kge_runner", "_kge_coroutines"):
            state.pop(key, None)
        return state


@dataclass(slots=True)
class Behaviour:
    """Attach ``script`` (an object with hooks, usually a :class:`Script`) to an entity."""

    script: Any
    hooks: tuple[str, ...] = field(init=False, repr=False, compare=False, default=())
    started: bool = field(init=False, repr=False, compare=False, default=False)

    def __setattr__(self, name: str, value: Any) -> None:
        if name == "script":
            try:
                object.__getattribute__(self, "hooks")
            except AttributeError:  # inside __init__: the first assignment
                pass
            else:
                raise ComponentTypeError(
                    "Behaviour.script cannot be replaced (the runner keeps calling the "
                    "script it was given); add a new Behaviour(script) to the entity instead"
                )
        object.__setattr__(self, name, value)

    def __post_init__(self) -> None:
        if self.script is None or isinstance(self.script, type):
            what = "None" if self.script is None else f"the class {self.script.__name__}"
            raise ComponentTypeError(f"Behaviour.script must be a script instance, got {what}")
        self.hooks = script_hooks(self.script)
        if not self.hooks and not isinstance(self.script, Script):
            script = self.script
            raise ComponentTypeError(
                f"Behaviour.script must define a hook ({', '.join(list(HOOKS)[:3])}, ...) or "
                f"be a kge.Script, got {type(script).__name__} {script!r}"
            )
