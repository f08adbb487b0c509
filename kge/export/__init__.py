"""``kge export``: a standalone build of a game, for the machine it runs on.

The build is made by PyInstaller (the ``export`` extra): one folder holding the game,
its assets, the Python runtime and every library it uses, started by one executable;
``onefile=True`` packs all of it into a single executable instead. The machine that
runs the result needs no Python, only what any desktop has (its OpenGL and audio
drivers, which pyglet loads at run time).

PyInstaller was chosen over Nuitka (which compiles to C: it needs a C compiler and
takes minutes per build) and Briefcase (which makes platform installers and app-store
packages around a separate runtime): it builds from the installed packages with no
compiler, in about a minute, for Linux, Windows and macOS alike, and it is the
packager most pyglet and pygame games ship with.

A project is a folder whose ``pyproject.toml`` names the game (``kge new`` makes one):
its package is the folder with ``__main__.py``, started as ``python -m PACKAGE``
would start it. Every file of the package that is not Python (images, sounds, maps,
scene files) travels with it, at the same place relative to its modules, so the
asset store finds them exactly as it does from source.
"""

from kge.export.build import ExportError, ExportPlan, export, plan

__all__ = ["ExportError", "ExportPlan", "export", "plan"]
