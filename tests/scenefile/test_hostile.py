"""Malformed and hostile files: a clear error naming the place, nothing run, nothing loaded.

Each case is a scene file (sometimes with a prefab or two beside it). Loading it
into a world that already holds entities must raise ``SceneFileError`` with the
expected words, leave that world exactly as it was (entities, components,
resources, the id counter), import no module and call no code the file names.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from kge import App, Box, Collider, PhysicsSettings, RigidBody, Transform, World
from kge.scenefile import LIMITS, SceneFileError, SceneState, load_game, load_scene

HEAD = "format = 1\n"
BOX = '[[entity]]\nid = "box"\n[entity.Transform]\ny = 2.0\n[entity.RigidBody]\n'
PREFAB = 'format = 1\nkind = "prefab"\n'


@dataclass
class Case:
    name: str
    text: str | bytes
    match: str
    files: dict[str, str] = field(default_factory=dict)
    line: int | None = None


def ent(body: str, key: str = "e") -> str:
    return f'[[entity]]\nid = "{key}"\n{body}\n'


CASES = [
    Case("not TOML", "[[entity\n", "not valid TOML", line=1),
    Case("not UTF-8", b"format = 1\nname = \"\xff\xfe\"\n", "not UTF-8"),
    Case("no format line", ent("[entity.Transform]"), "starts with format = 1"),
    Case("format from the future", "format = 99\n", "newer kge"),
    Case("format as a string", 'format = "1"\n', "starts with format"),
    Case("unknown kind", HEAD + 'kind = "level"\n', "kind must be one of"),
    Case("unknown top-level key", HEAD + 'exec = "rm -rf /"\n', "unknown top-level key 'exec'"),
    Case("entity is not an array of tables", HEAD + "entity = 3\n", "array of tables"),
    Case("an entity that is not a table", HEAD + "entity = [1, 2]\n", "an entity must be a table"),
    Case("misspelt component", HEAD + ent("[entity.Colider]\nshape = { type = \"Box\", "
         "half_width = 1.0, half_height = 1.0 }"), "unknown component 'Colider' \\(did you mean "
         "Collider\\?\\)", line=4),
    Case("a component naming a Python callable", HEAD + ent('[entity."os.system"]\ncommand = '
         '"touch /tmp/pwned"'), "unknown component 'os.system'"),
    Case("a module path as a component", HEAD + ent('[entity."antigravity.Fly"]'),
         "unknown component"),
    Case("a value naming a Python callable", HEAD + ent('[entity.Transform]\n[entity.Collider]\n'
         'shape = { type = "builtins.eval", source = "1+1" }'), "unknown value type "
         "'builtins.eval'", line=6),
    Case("a script naming a Python callable", HEAD + ent('[entity.Behaviour]\nscript = '
         '"subprocess.Popen"'), "unknown script 'subprocess.Popen'"),
    Case("a script named by a dotted path", HEAD + ent('[entity.Behaviour]\nscript = '
         '"kge.components.behaviour.Script"'), "unknown script"),
    Case("a resource used as a component", HEAD + ent("[entity.PhysicsSettings]"),
         "PhysicsSettings is a resource, not a component"),
    Case("unknown resource", HEAD + "[resources.Transform]\n", "unknown resource 'Transform'"),
    Case("string where a number goes", HEAD + ent('[entity.Transform]\nx = "far"'),
         "Transform.x", line=5),
    Case("bool where a number goes", HEAD + ent('[entity.Transform]\n[entity.Collider]\nshape = '
         '{ type = "Circle", radius = 1.0 }\ndensity = true'), "Collider.density"),
    Case("number where a bool goes", HEAD + ent("[entity.RigidBody]\nbullet = 1"),
         "RigidBody.bullet"),
    Case("misspelt field", HEAD + ent('[entity.Collider]\nshape = { type = "Circle", radius = 1.0 }'
         "\ndensty = 2.0"), "no field 'densty' \\(did you mean 'density'\\?\\)", line=6),
    Case("missing required field", HEAD + ent("[entity.Collider]\ndensity = 2.0"),
         "Collider.shape: is required"),
    Case("missing field of a value", HEAD + ent('[entity.Collider]\nshape = { type = "Box", '
         "half_width = 1.0 }"), "half_height"),
    Case("NaN", HEAD + ent("[entity.Transform]\nx = nan"), "not a finite number", line=5),
    Case("infinity", HEAD + ent("[entity.Transform]\ny = -inf"), "not a finite number"),
    Case("a huge coordinate", HEAD + ent("[entity.Transform]\nx = 1e300"), "Transform.x"),
    Case("an integer beyond 64 bits", HEAD + ent('[entity.Sprite]\nimage = "a.png"\nlayer = '
         "99999999999999999999"), "beyond 64 bits"),
    Case("an integer of 5,000 digits", HEAD + ent("[entity.Transform]\nx = " + "9" * 5000),
         "not valid TOML"),
    Case("arrays nested 100,000 deep", HEAD + "x = " + "[" * 100_000 + "]" * 100_000 + "\n",
         "nested deeper|not valid TOML"),
    Case("arrays nested 40 deep in a field", HEAD + ent('[entity.Collider]\nshape = { type = '
         '"Circle", radius = 1.0 }\nuser_data = ' + "[" * 40 + "]" * 40), "nested deeper"),
    Case("a date", HEAD + ent("[entity.Transform]\nx = 1979-05-27"), "dates"),
    Case("dangling entity reference", HEAD + BOX + ent('[entity.Transform]\n[entity.Collider]\n'
         'shape = { type = "Circle", radius = 0.5 }\nbody = "nobody"'), "names entity 'nobody'"),
    Case("entity reference of the wrong type", HEAD + BOX + ent('[entity.Transform]\n'
         '[entity.Collider]\nshape = { type = "Circle", radius = 0.5 }\nbody = 1'),
         "an entity reference is the other entity's id"),
    Case("reference to an entity without a body", HEAD + ent("[entity.Transform]", "plain") +
         ent('[entity.Transform]\n[entity.Collider]\nshape = { type = "Circle", radius = 0.5 }\n'
             'body = "plain"'), "entity \\d+ \\('plain'\\) has no RigidBody"),
    Case("joint of a body to itself", HEAD + BOX + ent('[entity.RevoluteJoint]\nbody_a = "box"\n'
         'body_b = "box"'), "RevoluteJoint"),
    Case("two joints on one entity", HEAD + BOX + ent('[entity.RevoluteJoint]\nbody_b = "box"\n'
         '[entity.WeldJoint]\nbody_b = "box"'), "both joints"),
    Case("a UI node that is its own parent", HEAD + ent('[entity.UINode]\nparent = "e"'),
         "own parent"),
    Case("duplicate ids", HEAD + ent("[entity.Transform]", "a") + ent("[entity.Transform]", "a"),
         "two entities have the id 'a'"),
    Case("id with a slash", HEAD + ent("[entity.Transform]", "a/b"), "an entity id"),
    Case("id that is not a string", HEAD + "[[entity]]\nid = 7\n", "an entity id"),
    Case("absolute asset path", HEAD + ent('[entity.Sprite]\nimage = "/etc/hostname"'),
         "is absolute"),
    Case("asset path climbing out", HEAD + ent('[entity.Sprite]\nimage = '
         '"../../../../../../etc/passwd"'), "leads outside the folders this game allows"),
    Case("asset path with a drive letter", HEAD + ent('[entity.Sprite]\nimage = "C:/boot.ini"'),
         "is absolute"),
    Case("asset path with a NUL byte", HEAD + ent('[entity.Sprite]\nimage = "a.png\\u0000.txt"'),
         "NUL"),
    Case("asset path with backslashes", HEAD + ent('[entity.Sprite]\nimage = "..\\\\..\\\\x.png"'),
         "use '/'"),
    Case("missing asset", HEAD + ent('[entity.Sprite]\nimage = "nope.png"'), "not found"),
    Case("asset path that is a number", HEAD + ent("[entity.Sprite]\nimage = 3"),
         "must be a string"),
    Case("a sound from /dev", HEAD + ent('[entity.AudioSource]\nsound = "/dev/zero"'),
         "is absolute"),
    Case("prefab that includes itself", HEAD + ent("", "i").replace("\n\n", '\nprefab = '
         '"loop.prefab.toml"\n'), "prefab cycle",
         files={"loop.prefab.toml": PREFAB + '[[entity]]\nid = "me"\nprefab = "loop.prefab.toml"\n'}),
    Case("prefabs in a two-file cycle", HEAD + '[[entity]]\nid = "i"\nprefab = "a.prefab.toml"\n',
         "prefab cycle: level.scene.toml -> a.prefab.toml -> b.prefab.toml -> a.prefab.toml",
         files={"a.prefab.toml": PREFAB + '[[entity]]\nid = "x"\nprefab = "b.prefab.toml"\n',
                "b.prefab.toml": PREFAB + '[[entity]]\nid = "y"\nprefab = "a.prefab.toml"\n'}),
    Case("absolute prefab path", HEAD + '[[entity]]\nid = "i"\nprefab = "/etc/passwd"\n',
         "is absolute"),
    Case("prefab path climbing out", HEAD + '[[entity]]\nid = "i"\nprefab = '
         '"../../../../../../etc/passwd"\n', "leads outside"),
    Case("missing prefab", HEAD + '[[entity]]\nid = "i"\nprefab = "gone.prefab.toml"\n',
         "not found"),
    Case("a scene used as a prefab", HEAD + '[[entity]]\nid = "i"\nprefab = "s.scene.toml"\n',
         "is a scene file, not a prefab", files={"s.scene.toml": HEAD}),
    Case("overrides on a plain entity", HEAD + ent("[entity.overrides.x.Transform]\nx = 1.0"),
         "only prefab instances"),
    Case("an instance with components of its own", HEAD + '[[entity]]\nid = "i"\nprefab = '
         '"p.prefab.toml"\n[entity.Transform]\n', "holds no components of its own",
         files={"p.prefab.toml": PREFAB + ent("[entity.Transform]", "a")}),
    Case("override of an unknown member", HEAD + '[[entity]]\nid = "i"\nprefab = "p.prefab.toml"'
         "\n[entity.overrides.ghost.Transform]\nx = 1.0\n", "no member",
         files={"p.prefab.toml": PREFAB + ent("[entity.Transform]", "a")}),
    Case("override with a bad value", HEAD + '[[entity]]\nid = "i"\nprefab = "p.prefab.toml"'
         "\n[entity.overrides.a.Transform]\nx = \"left\"\n", "Transform.x",
         files={"p.prefab.toml": PREFAB + ent("[entity.Transform]", "a")}),
    Case("a bad field inside a prefab", HEAD + '[[entity]]\nid = "i"\nprefab = "p.prefab.toml"\n',
         "p.prefab.toml:6: entity 'i/a', Transform.x: must be a number", files={"p.prefab.toml": PREFAB +
                                                              ent("[entity.Transform]\nx = true",
                                                                  "a")}),
    Case("at without a prefab", HEAD + ent("at = [1.0, 2.0]"), "at places a prefab instance"),
    Case("at of the wrong shape", HEAD + '[[entity]]\nid = "i"\nprefab = "p.prefab.toml"\n'
         'at = ["x"]\n', "at must be", files={"p.prefab.toml": PREFAB + ent("", "a")}),
    Case("unknown enum name", HEAD + ent('[entity.RigidBody]\ntype = "FLOATY"'),
         "'FLOATY' is not a BodyType"),
    Case("clockwise polygon", HEAD + ent('[entity.Collider]\nshape = { type = "Polygon", '
         "vertices = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0]] }"), "counter-clockwise"),
    Case("negative radius", HEAD + ent('[entity.Collider]\nshape = { type = "Circle", radius = '
         "-1.0 }"), "radius"),
    Case("filter bits past 32", HEAD + ent('[entity.Collider]\nshape = { type = "Circle", '
         'radius = 1.0 }\nfilter = { type = "Filter", category_bits = 1099511627776 }'),
         "category_bits"),
    Case("a chain of one point", HEAD + ent('[entity.Collider]\nshape = { type = "Chain", '
         "vertices = [[0.0, 0.0]] }"), "at least 2"),
    Case("a private script attribute", HEAD + ent('[entity.Behaviour]\nscript = "Quiet"\n'
         '_secret = 1'), "not a script attribute"),
    Case("a dunder script attribute", HEAD + ent('[entity.Behaviour]\nscript = "Quiet"\n'
         '__class__ = "os"'), "not a script attribute"),
    Case("started in a scene", HEAD + ent('[entity.Behaviour]\nscript = "Quiet"\nstarted = true'),
         "save files only"),
    Case("read-back state in a scene", HEAD + BOX + ent('[entity.RevoluteJoint]\nbody_b = "box"\n'
         "angle = 1.0"), "state kge writes while the game runs"),
    Case("a save loaded as a scene", HEAD + 'kind = "save"\nnext_id = 1\n', "use kge.load_game"),
    Case("tilemap outside the game", HEAD + '[[tilemap]]\nsource = "../../../../etc/passwd"\n',
         "leads outside"),
    Case("unknown tilemap option", HEAD + '[[tilemap]]\nsource = "m.tmx"\nspawn = "os.system"\n',
         "unknown tilemap option 'spawn'"),
    Case("a sprite frame without a grid", HEAD + ent('[entity.Sprite]\nimage = "a.png"\n'
         "region = 3"), "grid"),
    Case("component that is not a table", HEAD + "[[entity]]\nid = \"e\"\nTransform = 3\n",
         "must be a table of fields"),
]


@dataclass(slots=True)
class Quiet:
    pass


def _register_quiet() -> None:
    from kge import Script
    from kge.scenefile import default_registry

    class QuietScript(Script):
        pass

    QuietScript.__qualname__ = QuietScript.__name__ = "QuietScript"
    default_registry().register_script(QuietScript, name="Quiet")


_register_quiet()


def state(world: World) -> tuple[object, ...]:
    comps = {e: sorted(repr(c) for c in world.components(e)) for e in world.entities()}
    res = world.try_resource(SceneState)
    return (comps, repr(world.resource(PhysicsSettings)),
            None if res is None else (dict(res.keys), list(res.instances)))


def test_at_least_forty_hostile_files() -> None:
    assert len(CASES) >= 60
    assert len({c.name for c in CASES}) == len(CASES)


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_a_hostile_file_is_refused_and_changes_nothing(tmp_path: Path, case: Case) -> None:
    from PIL import Image

    Image.new("RGBA", (4, 4)).save(tmp_path / "a.png")
    for name, text in case.files.items():
        (tmp_path / name).write_text(text)
    path = tmp_path / "level.scene.toml"
    if isinstance(case.text, bytes):
        path.write_bytes(case.text)
    else:
        path.write_text(case.text)
    app = App(lambda w: (w.spawn(Transform(1.0), RigidBody(), Collider(Box(0.5, 0.5))),
                         w.spawn(Transform(3.0))), headless=True)
    app.step(3)
    world = app.world
    before = state(world)
    modules = set(sys.modules)
    with pytest.raises(SceneFileError, match=case.match) as info:
        load_scene(world, path)
    err = info.value
    assert err.path is not None and err.path.name.endswith(".toml")
    if case.line is not None:
        assert err.line == case.line, str(err)
    assert state(world) == before, case.name
    assert world.spawn() == 3  # the id counter did not move either
    new = {m for m in set(sys.modules) - modules if not m.startswith(("kge", "PIL", "pytiled"))}
    assert not new, f"loading imported {sorted(new)}"
    app.step(2)


def test_errors_name_file_line_entity_component_and_field(tmp_path: Path) -> None:
    path = tmp_path / "one.scene.toml"
    path.write_text(HEAD + '[[entity]]\nid = "crate"\nname = "Crate"\n[entity.Transform]\n'
                    '[entity.Collider]\nshape = { type = "Circle", radius = 1.0 }\n'
                    "density = -1.0\n")
    with pytest.raises(SceneFileError) as info:
        load_scene(World(), path)
    err = info.value
    assert (err.line, err.entity, err.component, err.field) == (8, "crate", "Collider", "density")
    assert str(err) == f"{path}:8: entity 'crate' ('Crate'), Collider.density: must be >= 0, got -1.0"


def test_limits_are_checked_before_building(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "many.scene.toml"
    path.write_text(HEAD + "".join(ent("[entity.Transform]", f"e{i}") for i in range(20)))
    monkeypatch.setattr(LIMITS, "max_entities", 10)
    with pytest.raises(SceneFileError, match="20 entities"):
        load_scene(World(), path)
    monkeypatch.setattr(LIMITS, "max_entities", 1_000_000)
    monkeypatch.setattr(LIMITS, "max_bytes", 100)
    with pytest.raises(SceneFileError, match="larger than 100"):
        load_scene(World(), path)
    monkeypatch.setattr(LIMITS, "max_bytes", 64 * 2**20)
    monkeypatch.setattr(LIMITS, "max_string", 5)
    path.write_text(HEAD + ent('name = "a long name"'))
    with pytest.raises(SceneFileError, match="a string of 11 characters"):
        load_scene(World(), path)


def test_a_hostile_save_is_refused_too(tmp_path: Path) -> None:
    path = tmp_path / "save.toml"
    path.write_text(HEAD + 'kind = "save"\nnext_id = 3\n[[entity]]\nid = 1\n'
                    '[entity.Behaviour]\nscript = "os.system"\n')
    save = load_game(path)
    app = App(lambda w: w.spawn(Transform(2.0)), headless=True)
    world = app.world
    with pytest.raises(SceneFileError, match="unknown script 'os.system'"):
        app.restore(save)
    assert app.world is world and world.get(1, Transform).x == 2.0
