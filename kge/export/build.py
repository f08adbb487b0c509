"""Plan and run a PyInstaller build of a kge game project (see :mod:`kge.export`)."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from kge.errors import KgeError

#: libraries whose modules pyglet and pymunk import by name at run time (platform
#: backends, codecs): PyInstaller cannot see those imports
COLLECTED = ("pyglet", "pymunk", "esper")

#: kge's packages a game never runs (tools, RL, the pybox2d API): left out, with the
#: heavy libraries only they use
KGE_TOOLS = ("kge.testbed", "kge.testing", "kge.scaffold", "kge.gym", "kge.box2d",
             "kge.export", "kge.__main__")
EXCLUDED = ("torch", "ray", "gymnasium", "Box2D", "pygame", "matplotlib", "pytest",
            "hypothesis", "mypy", "PyInstaller", "IPython", "tkinter", "scipy", "pandas")

PYINSTALLER_HINT = "pip install 'pyinstaller>=6.10,<7'"


class ExportError(KgeError, RuntimeError):
    """A project that cannot be exported, or a build that failed (naming which)."""


@dataclass(slots=True)
class ExportPlan:
    """What a build will hold: the game's name and package, and where it goes."""

    project: Path
    name: str
    package: str
    out: Path
    onefile: bool = False
    data: list[tuple[Path, str]] = field(default_factory=list)

    @property
    def executable(self) -> Path:
        """The program the build makes (inside its folder, unless ``onefile``)."""
        exe = self.name + (".exe" if sys.platform == "win32" else "")
        return self.out / exe if self.onefile else self.out / self.name / exe


def plan(project: str | os.PathLike[str] = ".", out: str | os.PathLike[str] | None = None,
         *, onefile: bool = False, name: str | None = None) -> ExportPlan:
    """Read ``project`` and say what :func:`export` would build, without building."""
    root = Path(project).resolve()
    pyproject = root / "pyproject.toml"
    if not pyproject.is_file():
        raise ExportError(f"{root}: no pyproject.toml here (kge export takes a game project "
                          "folder, such as one `kge new NAME` made)")
    try:
        meta = tomllib.loads(pyproject.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as err:
        raise ExportError(f"{pyproject}: cannot read it ({err})") from None
    declared = meta.get("project", {}).get("name")
    game = name or (declared if isinstance(declared, str) and declared else root.name)
    if not game.replace("-", "").replace("_", "").isalnum():
        raise ExportError(f"{pyproject}: {game!r} cannot name a program (letters, digits, - and _)")
    package = _game_package(root, pyproject)
    target = Path(out).resolve() if out is not None else root / "dist"
    data = [(f, f.parent.relative_to(root).as_posix()) for f in _package_data(root / package)]
    return ExportPlan(root, game, package, target, onefile, data)


def _game_package(root: Path, pyproject: Path) -> str:
    """The project's one package with a ``__main__.py`` (what ``python -m`` starts)."""
    found = sorted(p.parent.name for p in root.glob("*/__main__.py")
                   if (p.parent / "__init__.py").is_file())
    if len(found) == 1:
        return found[0]
    if not found:
        raise ExportError(f"{root}: no package with a __main__.py (the game starts as "
                          "`python -m PACKAGE`; kge new makes PACKAGE/__main__.py)")
    raise ExportError(f"{root}: several packages have a __main__.py ({', '.join(found)}): "
                      "keep one, the game's")


def _package_data(folder: Path) -> list[Path]:
    """Every file of the package that is not Python source or a cache."""
    skip_dirs = {"__pycache__", ".pytest_cache", ".mypy_cache"}
    out = []
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or skip_dirs.intersection(path.relative_to(folder).parts):
            continue
        if path.suffix not in (".py", ".pyc", ".pyo"):
            out.append(path)
    return out


def pyinstaller_args(p: ExportPlan, work: Path) -> list[str]:
    """The PyInstaller command line of a plan (its entry script is written into ``work``)."""
    entry = work / f"{p.name}_entry.py"
    entry.write_text(
        "# written by kge export: start the game as `python -m` would\n"
        "import runpy\n"
        f"runpy.run_module({p.package!r}, run_name='__main__', alter_sys=True)\n",
        encoding="utf-8",
    )
    args = [
        str(entry), "--name", p.name, "--noconfirm", "--clean", "--log-level", "WARN",
        "--distpath", str(p.out), "--workpath", str(work / "build"),
        "--specpath", str(work), "--paths", str(p.project),
        # where kge itself lives: an editable install is found by an import hook that
        # PyInstaller's analysis does not run
        "--paths", str(Path(__file__).resolve().parents[2]),
        "--onefile" if p.onefile else "--onedir",
        "--hidden-import", p.package, "--collect-submodules", p.package,
    ]
    for lib in COLLECTED:
        args += ["--collect-submodules", lib]
    for module in kge_modules():  # kge imports its subsystems lazily, by name
        args += ["--hidden-import", module]
    for module in (*EXCLUDED, *KGE_TOOLS):
        args += ["--exclude-module", module]
    sep = os.pathsep
    for src, dest in p.data:
        args += ["--add-data", f"{src}{sep}{dest}"]
    return args


def kge_modules() -> list[str]:
    """Every module of kge a game may import (the tools of :data:`KGE_TOOLS` left out)."""
    import pkgutil

    import kge

    names = ["kge"]
    for info in pkgutil.walk_packages(kge.__path__, "kge."):
        if not info.name.startswith(KGE_TOOLS):
            names.append(info.name)
    return names


def export(project: str | os.PathLike[str] = ".", out: str | os.PathLike[str] | None = None,
           *, onefile: bool = False, name: str | None = None, quiet: bool = False) -> Path:
    """Build the game in ``project``; return the path of its executable.

    Raises :class:`ExportError` when the project cannot be read, PyInstaller is not
    installed (the message says how to install it) or the build fails (with
    PyInstaller's own last lines).
    """
    p = plan(project, out, onefile=onefile, name=name)
    if importlib.util.find_spec("PyInstaller") is None:
        raise ExportError(f"kge export builds with PyInstaller, which is not installed: "
                          f"{PYINSTALLER_HINT}")
    work = p.project / "build" / "kge-export"
    work.mkdir(parents=True, exist_ok=True)
    cmd = [sys.executable, "-m", "PyInstaller", *pyinstaller_args(p, work)]
    run = subprocess.run(cmd, cwd=p.project, capture_output=True, text=True)
    if run.returncode != 0:
        tail = "\n".join((run.stderr or run.stdout).strip().splitlines()[-15:])
        raise ExportError(f"{p.project}: PyInstaller failed (exit {run.returncode}):\n{tail}")
    if not quiet and run.stderr.strip():
        print(run.stderr.strip(), file=sys.stderr)
    if not p.executable.is_file():
        raise ExportError(f"{p.project}: PyInstaller finished but {p.executable} is missing")
    return p.executable
