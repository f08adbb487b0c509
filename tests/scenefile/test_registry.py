"""The registry: a game's own types, renames and migrations, name clashes."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest

from kge import World
from kge.scenefile import SceneFileError, TypeRegistry, dumps, load_scene, migration
from kge.scenefile.migrate import _MIGRATIONS


@dataclass(slots=True)
class Fuel:
    litres: float = 10.0


def test_renamed_fields_and_types_still_load_and_save_under_new_names(tmp_path: Path) -> None:
    reg = TypeRegistry()
    reg.register(Fuel, renamed={"gallons": "litres"}, previous_names=("Petrol",))
    path = tmp_path / "old.scene.toml"
    path.write_text('format = 1\n[[entity]]\nid = "tank"\n[entity.Petrol]\ngallons = 3.5\n')
    world = World()
    (e,) = load_scene(world, path, registry=reg)
    assert world.get(e, Fuel).litres == 3.5
    assert "[entity.Fuel]\nlitres = 3.5" in dumps(world, tmp_path, registry=reg)
    path.write_text('format = 1\n[[entity]]\nid = "t"\n[entity.Fuel]\ngallons = 1.0\n'
                    "litres = 2.0\n")
    with pytest.raises(SceneFileError, match="both 'gallons' and its new name 'litres'"):
        load_scene(World(), path, registry=reg)


def test_a_migration_brings_an_old_format_up(tmp_path: Path, monkeypatch: pytest.MonkeyPatch
                                              ) -> None:
    import kge.scenefile.migrate as mig

    monkeypatch.setattr(mig, "FORMAT", 2)
    seen: list[int] = []

    @migration(1)
    def _v1_to_v2(data: dict) -> dict:
        seen.append(data["format"])
        for entity in data.get("entity", []):
            if "pos" in entity:  # format 1 (in this test) kept poses in a `pos` key
                x, y = entity.pop("pos")
                entity["Transform"] = {"x": x, "y": y}
        return data

    try:
        path = tmp_path / "v1.scene.toml"
        path.write_text('format = 1\n[[entity]]\nid = "a"\npos = [1.0, 2.0]\n')
        world = World()
        (e,) = load_scene(world, path)
        from kge import Transform

        assert world.get(e, Transform).position == (1.0, 2.0) and seen == [1]
        path.write_text("format = 0\n")
        with pytest.raises(SceneFileError, match="format 0 is too old"):
            load_scene(World(), path)
    finally:
        del _MIGRATIONS[1]


def test_name_clashes_are_refused() -> None:
    reg = TypeRegistry()
    reg.register(Fuel)

    @dataclass
    class Fuel2:
        x: int = 0

    with pytest.raises(SceneFileError, match="the name 'Fuel' is taken"):
        reg.register(Fuel2, name="Fuel")
    with pytest.raises(SceneFileError, match="needs a dataclass"):
        reg.register(int)
    with pytest.raises(SceneFileError, match="letters, digits"):
        reg.register(Fuel2, name="bad name!")
    with pytest.raises(SceneFileError, match="no field"):
        reg.register(Fuel2, entity_fields=("y",))
