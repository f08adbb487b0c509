"""The console's built-in commands (see :mod:`kge.debug.console` for the list)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.debug.inspector import FieldRow, Inspector, _parse_plain, _plain_kind, public_fields
from kge.debug.parsing import ConsoleError
from kge.errors import KgeError, ValidationError
from kge.world import World

if TYPE_CHECKING:
    from kge.debug.console import Console


def _host(world: Any) -> Any:
    from kge.host import Host

    host = world.try_resource(Host) if world is not None else None
    if host is None:
        raise ConsoleError("this command needs an App (the world runs on its own)")
    return host


def inspector_of(world: World) -> Inspector:
    """The world's live inspector (a resource, created on first use)."""
    found = world.try_resource(Inspector)
    if found is None:
        found = world.insert_resource(Inspector(world))
    return found


def _entity(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise ConsoleError(f"{text!r} is not an entity id") from None


def _split_path(path: str) -> tuple[int, str, str] | None:
    """``12.Transform.x`` -> (12, "Transform", "x"); None for a variable name."""
    parts = path.split(".")
    if len(parts) == 3 and parts[0].lstrip("-").isdigit():
        return int(parts[0]), parts[1], parts[2]
    return None


def _resolve_variable(console: Console, world: Any, name: str) -> tuple[Any, str]:
    var = console.get_variable(name)
    if var is None:
        known = ", ".join(console.variables) or "none"
        raise ConsoleError(
            f"unknown variable {name!r} (variables: {known}; or entity.Component.field)"
        )
    target = var.target
    if isinstance(target, type):  # a resource type: this world's instance
        if world is None:
            raise ConsoleError(f"{name} lives in a world's {target.__name__} resource")
        target = world.resource(target)
    return target, var.attr


def _show(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, tuple) and all(isinstance(v, float) for v in value):
        return ", ".join(f"{v:.6g}" for v in value)
    if hasattr(value, "name") and type(value).__module__ != "builtins" and hasattr(
        type(value), "__members__"
    ):
        return str(value.name)
    return repr(value) if isinstance(value, str) else str(value)


def _parse_like(current: Any, text: str, what: str) -> Any:
    from kge.editor.fields import FieldKind

    widget, choices = _plain_kind(what, current)
    if widget == "angle":
        widget = "number"  # a variable holds what it holds: radians stay radians
    try:
        return _parse_plain(FieldKind(widget, choices), text, current)
    except ValueError as exc:
        raise ConsoleError(f"{what}: {exc}") from None


def _rows_text(rows: list[FieldRow]) -> str:
    lines = []
    last = None
    for r in rows:
        if r.component != last:
            lines.append(f"[{r.component}]")
            last = r.component
        lines.append(f"  {r.field} = {r.text}")
    return "\n".join(lines)


def install_builtins(console: Console) -> None:
    """Add kge's commands to ``console`` (called by its constructor)."""
    add = console.add_command

    def help(name: str = "") -> str:
        """list the commands, or describe one"""
        if name:
            cmd = console.get_command(name)
            return f"{cmd.usage}\n  {cmd.help}".rstrip()
        width = max(len(c) for c in console.commands)
        return "\n".join(
            f"{c.ljust(width)}  {console.get_command(c).help}" for c in console.commands
        )

    def commands() -> str:
        """the command names"""
        return "  ".join(console.commands)

    def echo(*words: str) -> str:
        """print the words"""
        return " ".join(words)

    def clear() -> None:
        """empty the log"""
        console.clear()

    def variables(world: World) -> str:
        """list the variables and their values"""
        if not console.variables:
            return "no variables (console.variable(name, target, attr) adds one)"
        lines = []
        for name in console.variables:
            try:
                target, attr = _resolve_variable(console, world, name)
                lines.append(f"{name} = {_show(getattr(target, attr))}")
            except KgeError as exc:
                lines.append(f"{name}: {exc}")
        return "\n".join(lines)

    def get(world: World, path: str) -> str:
        """a variable's value, or entity.Component.field"""
        split = _split_path(path)
        if split is not None:
            e, comp, fname = split
            return f"{path} = {inspector_of(world).value_text(e, comp, fname)}"
        target, attr = _resolve_variable(console, world, path)
        return f"{path} = {_show(getattr(target, attr))}"

    def set(world: World, path: str, *value: str) -> str:
        """set a variable, or entity.Component.field, from text"""
        text = " ".join(value)
        if not text:
            raise ValidationError(f"set {path}: give a value")
        split = _split_path(path)
        if split is not None:
            e, comp, fname = split
            ins = inspector_of(world)
            ins.set(e, comp, fname, text)
            return f"{path} = {ins.value_text(e, comp, fname)}"
        target, attr = _resolve_variable(console, world, path)
        new = _parse_like(getattr(target, attr), text, path)
        try:
            setattr(target, attr, new)
        except (KgeError, ValueError, TypeError) as exc:
            raise ValidationError(f"set {path}: {exc}") from None
        return f"{path} = {_show(getattr(target, attr))}"

    def entities(world: World, search: str = "") -> str:
        """list entities (id and name), filtered by a word"""
        found = inspector_of(world).entities(search)
        if not found:
            return "no entities" + (f" matching {search!r}" if search else "")
        return "\n".join(f"{e:>6}  {text}" for e, text in found)

    def inspect(world: World, entity: str) -> str:
        """show (and select) an entity's components and fields"""
        e = _entity(entity)
        ins = inspector_of(world)
        ins.select(e)
        return f"entity {e}\n" + _rows_text(ins.rows(e))

    def despawn(world: World, entity: str) -> str:
        """despawn an entity"""
        e = _entity(entity)
        if not world.exists(e):
            raise ValidationError(f"entity {e} does not exist")
        world.despawn(e)
        return f"despawned {e}"

    def pause(world: World) -> str:
        """pause the game"""
        _host(world).paused = True
        return "paused"

    def resume(world: World) -> str:
        """resume the game"""
        _host(world).paused = False
        return "running"

    def step(world: World, n: int = 1) -> str:
        """while paused, run n fixed steps"""
        host = _host(world)
        if n < 1:
            raise ValidationError(f"step: n must be >= 1, got {n}")
        for _ in range(n):
            host.single_step()
        return f"{n} step(s) queued"

    def time_scale(world: World, value: float | None = None) -> str:
        """show or set the game's time scale"""
        host = _host(world)
        if value is not None:
            host.time_scale = value
        return f"time_scale = {host.time_scale:g}"

    def timings(world: World, mode: str = "") -> str:
        """per-system timings: on, off, reset, or show them"""
        sched = world.schedule
        if mode == "on":
            sched.enable_timings()
            return "timings on"
        if mode == "off":
            sched.disable_timings()
            return "timings off"
        if mode == "reset":
            if sched.timings is not None:
                sched.timings.reset()
            return "timings reset"
        if mode:
            raise ValidationError(f"timings: {mode!r} is not on, off or reset")
        if sched.timings is None:
            return "timings are off (timings on)"
        return sched.timings.describe(top=20)

    def gizmos(world: World, on: bool | None = None) -> str:
        """turn immediate-mode debug drawing on or off"""
        from kge.debug.gizmos import Gizmos

        g = world.try_resource(Gizmos)
        if g is None:
            raise ValidationError("this world has no Gizmos (the DebugPlugin adds them)")
        if on is not None:
            g.enabled = on
        return f"gizmos {'on' if g.enabled else 'off'}"

    def schedule(world: World) -> str:
        """the frame order of this world's systems"""
        return str(world.schedule.describe())

    for fn in (help, commands, echo, clear, variables, get, set, entities, inspect, despawn,
               pause, resume, step, time_scale, timings, gizmos, schedule):  # fmt: skip
        add(fn, fn.__name__.rstrip("_"))
    console.add_command(variables, "vars")
    console.remove_command("variables")

    if console.python:

        def py(world: World, *code: str) -> str:
            """evaluate Python (only in a console made with python=True)"""
            namespace: dict[str, Any] = {"world": world, "console": console}
            source = " ".join(code)
            try:
                return repr(eval(compile(source, "<console>", "eval"), namespace))
            except SyntaxError:
                exec(compile(source, "<console>", "exec"), namespace)
                return ""

        add(py, "py")


__all__ = ["inspector_of", "install_builtins", "public_fields"]
