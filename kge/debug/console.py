"""The in-game console: a registry of named commands, run from a line of text.

The console runs only what was registered: a command is a Python function the
game (or kge) added by name; its arguments are parsed from the line by the
function's annotations (``int``, ``float``, ``bool``, ``str``, an ``Enum`` by
member name, ``tuple[float, ...]`` as ``1,2``). Nothing typed is ever evaluated
as Python unless the game opts in with ``Console(python=True)`` (a development
build), which adds a ``py`` command.

::

    console = app.console                      # or world.resource(kge.Console)

    @console.command(help="spawn a crate at x, y")
    def crate(world: World, x: float = 0.0, y: float = 5.0) -> str:
        e = world.spawn(Transform(x, y), RigidBody(), Collider(Box(0.5, 0.5)))
        return f"crate {e}"

    console.run("crate 2 8")                   # -> ConsoleResult(ok=True, output=[...])

A first parameter annotated ``World`` (or named ``world``) receives the world
the console runs in. Values to tweak are *variables*: ``console.variable("gravity",
settings, "gravity")`` exposes one attribute to ``set gravity 0,-5`` and ``get
gravity``; ``set 12.Transform.x 3`` writes any component field of entity 12
through the live inspector's parsing and the component's validation.

Built-in commands: ``help [command]``, ``commands``, ``vars``, ``get``, ``set``,
``entities [search]``, ``inspect <entity>``, ``despawn <entity>``, ``pause``,
``resume``, ``step [n]``, ``time_scale [x]``, ``timings [on|off|reset]``,
``gizmos [on|off]``, ``schedule``, ``clear``, ``echo``. A command that raises is
reported in the log (``error: ...``); the game keeps running.

In a window the backquote key (`````) opens the console over the game; while it is
open it takes the keyboard (the game sees no keys), Enter runs the line, Up/Down
walk the history and Tab completes command and variable names.
"""

from __future__ import annotations

import inspect
import shlex
import typing
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from kge.debug.parsing import ConsoleError, parse_value
from kge.errors import KgeError, ValidationError

#: the log keeps this many lines
LOG_LINES = 400
#: the history keeps this many lines
HISTORY = 100


@dataclass(slots=True, frozen=True)
class ConsoleResult:
    """What one line did: ``ok``, and the lines it printed."""

    ok: bool
    output: list[str]

    @property
    def text(self) -> str:
        return "\n".join(self.output)


@dataclass(slots=True)
class _Param:
    name: str
    kind: Any
    default: Any
    variadic: bool = False


@dataclass(slots=True)
class Command:
    """One registered command."""

    name: str
    fn: Callable[..., Any]
    help: str
    params: list[_Param] = field(default_factory=list)
    wants_world: bool = False

    @property
    def usage(self) -> str:
        parts = [self.name]
        for p in self.params:
            kind = getattr(p.kind, "__name__", str(p.kind))
            if p.variadic:
                parts.append(f"[{p.name}: {kind}...]")
            elif p.default is inspect.Parameter.empty:
                parts.append(f"<{p.name}: {kind}>")
            else:
                parts.append(f"[{p.name}={p.default!r}]")
        return " ".join(parts)


@dataclass(slots=True)
class Variable:
    """An attribute exposed to ``get`` / ``set``: ``getattr(target, attr)``."""

    name: str
    target: Any
    attr: str
    help: str = ""


def _signature(fn: Callable[..., Any], name: str) -> tuple[list[_Param], bool]:
    from kge.world import World

    try:
        sig = inspect.signature(fn)
        hints = typing.get_type_hints(fn)
    except (TypeError, ValueError, NameError) as exc:
        raise ValidationError(
            f"Console.command {name!r}: cannot read its parameters ({exc})"
        ) from None
    params = list(sig.parameters.values())
    wants_world = bool(params) and (
        hints.get(params[0].name) is World or params[0].name == "world"
    )
    if wants_world:
        params = params[1:]
    out = []
    for p in params:
        if p.kind in (p.KEYWORD_ONLY, p.VAR_KEYWORD):
            if p.kind is p.KEYWORD_ONLY and p.default is p.empty:
                raise ValidationError(
                    f"Console.command {name!r}: keyword-only parameter {p.name!r} needs a default"
                )
            continue
        kind = hints.get(p.name, p.empty)
        out.append(_Param(p.name, kind, p.default, p.kind is p.VAR_POSITIONAL))
    return out, wants_world


class Console:
    """The command registry, the log and the line being typed (see the module docstring)."""

    def __init__(self, *, python: bool = False) -> None:
        self._commands: dict[str, Command] = {}
        self._vars: dict[str, Variable] = {}
        self.log: deque[str] = deque(maxlen=LOG_LINES)
        self.history: list[str] = []
        self._browse: int | None = None
        #: True while the overlay is shown (it takes the keyboard)
        self.open = False
        #: the line being typed in the overlay
        self.line = ""
        #: False: the toggle key does nothing (a release build)
        self.enabled = True
        #: the key that opens and closes the overlay (kge.Key code)
        from kge.keys import Key

        self.toggle_key: int = Key.GRAVE
        #: the world commands run in (the debug plugin points it at the top scene)
        self.world: Any = None
        self.python = bool(python)
        from kge.debug.commands import install_builtins

        install_builtins(self)

    # -- registering -------------------------------------------------------------------------
    def command(self, name: str | Callable[..., Any] | None = None, *,
                help: str = "") -> Any:
        """Register a function as a command (a decorator; ``name`` defaults to the
        function's). A command of that name is replaced."""
        if callable(name):
            return self.add_command(name)

        def register(fn: Callable[..., Any]) -> Callable[..., Any]:
            self.add_command(fn, name, help=help)
            return fn

        return register

    def add_command(self, fn: Callable[..., Any], name: str | None = None, *,
                    help: str = "") -> Command:
        """Register ``fn`` under ``name``; returns the :class:`Command`."""
        if not callable(fn):
            raise ValidationError(f"Console.add_command needs a function, got {fn!r}")
        cname = name or getattr(fn, "__name__", "")
        if not isinstance(cname, str) or not cname.isidentifier():
            raise ValidationError(
                f"Console.add_command: a command name is one word (letters, digits, _), "
                f"got {cname!r}"
            )
        params, wants_world = _signature(fn, cname)
        doc = help or (inspect.getdoc(fn) or "").split("\n", 1)[0]
        cmd = Command(cname, fn, doc, params, wants_world)
        self._commands[cname] = cmd
        return cmd

    def remove_command(self, name: str) -> None:
        self._commands.pop(name, None)

    def variable(self, name: str, target: Any, attr: str, *, help: str = "") -> None:
        """Expose ``target.attr`` as the variable ``name`` (for ``get`` and ``set``)."""
        if not isinstance(name, str) or not name.isidentifier():
            raise ValidationError(f"Console.variable: a name is one word, got {name!r}")
        if attr.startswith("_") or not hasattr(target, attr):
            raise ValidationError(
                f"Console.variable {name!r}: {target!r} has no attribute {attr!r}"
            )
        self._vars[name] = Variable(name, target, attr, help)

    @property
    def commands(self) -> list[str]:
        return sorted(self._commands)

    @property
    def variables(self) -> list[str]:
        return sorted(self._vars)

    def get_command(self, name: str) -> Command:
        found = self._commands.get(name)
        if found is None:
            import difflib

            near = difflib.get_close_matches(name, list(self._commands), n=1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            raise ConsoleError(f"unknown command {name!r}{hint}; type help for the list")
        return found

    def get_variable(self, name: str) -> Variable | None:
        return self._vars.get(name)

    # -- running ---------------------------------------------------------------------------
    def run(self, line: str, world: Any = None) -> ConsoleResult:
        """Run one line in ``world`` (default: :attr:`world`); the output is logged too.

        Errors never propagate: an unknown command, a bad argument or an exception
        inside the command is reported as ``error: ...`` with ``ok=False``.
        """
        text = str(line).strip()
        self.print(f"> {text}")
        if text and (not self.history or self.history[-1] != text):
            self.history.append(text)
            del self.history[:-HISTORY]
        self._browse = None
        if not text:
            return ConsoleResult(True, [])
        out: list[str] = []
        ok = True
        try:
            result = self._call(text, self.world if world is None else world)
            if result is not None:
                out = str(result).split("\n")
        except KgeError as exc:
            ok, out = False, [f"error: {exc}"]
        except Exception as exc:  # a command's own bug: reported, the game runs on
            ok, out = False, [f"error: {type(exc).__name__}: {exc}"]
        for ln in out:
            self.print(ln)
        return ConsoleResult(ok, out)

    def _call(self, text: str, world: Any) -> Any:
        try:
            words = shlex.split(text)
        except ValueError as exc:
            raise ConsoleError(f"cannot split the line: {exc}") from None
        if not words:
            return None
        cmd = self.get_command(words[0])
        args = self._arguments(cmd, words[1:])
        if cmd.wants_world:
            if world is None:
                raise ConsoleError(f"{cmd.name} needs a running world")
            return cmd.fn(world, *args)
        return cmd.fn(*args)

    def _arguments(self, cmd: Command, words: list[str]) -> list[Any]:
        args: list[Any] = []
        rest = list(words)
        for p in cmd.params:
            if p.variadic:
                args += [parse_value(w, p.kind, f"{cmd.name} {p.name}") for w in rest]
                rest = []
                break
            if rest:
                args.append(parse_value(rest.pop(0), p.kind, f"{cmd.name} {p.name}"))
            elif p.default is inspect.Parameter.empty:
                raise ConsoleError(f"{cmd.name} needs {p.name}; usage: {cmd.usage}")
            else:
                args.append(p.default)
        if rest:
            raise ConsoleError(
                f"{cmd.name} takes {len(cmd.params)} argument(s), got {len(words)}; "
                f"usage: {cmd.usage}"
            )
        return args

    def print(self, text: str) -> None:
        """Add a line to the log (commands may call it; the overlay shows the log)."""
        for ln in str(text).split("\n"):
            self.log.append(ln)

    # -- typing (the overlay) ---------------------------------------------------------------
    def complete(self, prefix: str | None = None) -> list[str]:
        """Command names (first word) or variable names (after get/set) starting with
        ``prefix`` (default: the line being typed)."""
        text = self.line if prefix is None else prefix
        words = text.split(" ")
        if len(words) == 1:
            return [c for c in self.commands if c.startswith(words[0])]
        if words[0] in ("get", "set") and len(words) == 2:
            return [v for v in self.variables if v.startswith(words[1])]
        if words[0] == "help" and len(words) == 2:
            return [c for c in self.commands if c.startswith(words[1])]
        return []

    def tab(self) -> None:
        """Complete the line being typed (to the common prefix of the matches)."""
        matches = self.complete()
        if not matches:
            return
        words = self.line.split(" ")
        common = matches[0]
        for m in matches[1:]:
            while not m.startswith(common):
                common = common[:-1]
        words[-1] = common
        self.line = " ".join(words) + (" " if len(matches) == 1 else "")
        if len(matches) > 1:
            self.print("  ".join(matches))

    def submit(self) -> ConsoleResult:
        """Run the line being typed and clear it."""
        line, self.line = self.line, ""
        return self.run(line)

    def recall(self, delta: int) -> None:
        """Walk the history (-1: older, +1: newer) into the line being typed."""
        if not self.history:
            return
        i = len(self.history) if self._browse is None else self._browse
        i = max(0, min(len(self.history), i + delta))
        self._browse = i
        self.line = self.history[i] if i < len(self.history) else ""

    def clear(self) -> None:
        self.log.clear()
