"""World: spawning, deferred despawn, isolation, locking, resources and events."""

from dataclasses import dataclass

import pytest

from kge import (
    ComponentTypeError,
    EntityNotFoundError,
    MissingComponentError,
    MissingResourceError,
    Transform,
    World,
    WorldLockedError,
)


@dataclass(slots=True)
class Health:
    hp: int = 3


@dataclass(slots=True)
class Tag:
    name: str = ""


@pytest.fixture
def world():
    w = World()
    yield w
    w.close()


def snapshot(w: World) -> dict[int, tuple]:
    return {e: w.components(e) for e in w.entities()}


def test_spawn_returns_id_and_components_are_readable(world: World) -> None:
    e = world.spawn(Transform(1.0, 2.0), Health(5))
    assert world.exists(e)
    assert world.get(e, Health).hp == 5
    assert world.get(e, Transform).position == (1.0, 2.0)
    assert [ent for ent, _ in world.query(Transform, Health)] == [e]


def test_add_remove_and_missing_component(world: World) -> None:
    e = world.spawn(Transform())
    world.add(e, Health(1))
    assert world.has(e, Health)
    removed = world.remove(e, Health)
    assert removed.hp == 1 and not world.has(e, Health)
    with pytest.raises(MissingComponentError, match=f"entity {e} has no Health"):
        world.get(e, Health)


def test_despawn_is_deferred_to_the_flush(world: World) -> None:
    e = world.spawn(Health())
    world.despawn(e)
    assert not world.exists(e)
    assert world.query(Health) == []  # hidden from queries at once
    world.flush()
    assert world.entities() == []


def test_despawn_during_iteration_never_invalidates_the_loop(world: World) -> None:
    ids = [world.spawn(Health(i)) for i in range(10)]
    seen = []
    for e, (h,) in world.query(Health):
        seen.append(h.hp)  # components of already-despawned entities stay readable in the loop
        if world.exists(e):
            world.despawn(e)
        if e + 1 in ids and world.exists(e + 1):
            world.despawn(e + 1)  # despawning an entity later in the same list
    assert sorted(seen) == list(range(10))
    world.flush()
    assert world.entities() == []


def test_despawning_twice_and_using_a_despawned_entity_are_clear_errors(world: World) -> None:
    e = world.spawn(Health())
    world.despawn(e)
    with pytest.raises(EntityNotFoundError, match=f"entity {e} was despawned"):
        world.despawn(e)
    with pytest.raises(EntityNotFoundError, match="despawned"):
        world.add(e, Tag())
    with pytest.raises(EntityNotFoundError, match="does not exist"):
        world.get(12345, Health)


def test_wrong_component_values_are_refused_without_changing_the_world(world: World) -> None:
    e = world.spawn(Health())
    before = snapshot(world)
    with pytest.raises(ComponentTypeError, match="class Tag"):
        world.spawn(Transform(), Tag)
    with pytest.raises(ComponentTypeError, match="two Health"):
        world.spawn(Health(), Health())
    with pytest.raises(ComponentTypeError):
        world.add(e, 42)
    assert snapshot(world) == before


def test_two_worlds_are_isolated() -> None:
    a, b = World(), World()
    try:
        ea = a.spawn(Tag("a"))
        b.spawn(Tag("b"))
        b.spawn(Tag("b2"))
        assert [t.name for _, (t,) in a.query(Tag)] == ["a"]
        assert sorted(t.name for _, (t,) in b.query(Tag)) == ["b", "b2"]
        assert a.get(ea, Tag).name == "a"  # switching back and forth keeps data apart
        a.insert_resource(Health(9))
        assert not b.has_resource(Health)
    finally:
        a.close()
        b.close()


def test_a_new_world_never_sees_an_unclosed_one_of_the_same_name() -> None:
    """Worlds named alike (every App of a function scene is "function") never share data.

    The esper tables were named after ``id(world)``, which CPython hands out again
    once a world is collected: a new world then found the entities of an unclosed
    one that had the same name (a flaky render test showed it). The tables of an
    unclosed world now go with it, and names are never reused.
    """
    import gc

    import esper

    before = set(esper.list_worlds())
    for k in range(50):
        w = World(name="scene")
        assert w.query(Tag) == []
        w.spawn(Tag(f"world {k}"))
        del w
        gc.collect()
    assert set(esper.list_worlds()) - before <= {esper.current_world}


def test_deferred_changes_apply_at_flush_in_sorted_entity_order(world: World) -> None:
    order: list[tuple[str, int]] = []
    world.on_add(Tag, lambda e, c: order.append(("add", e)))
    world.on_remove(Tag, lambda e, c: order.append(("remove", e)))
    first = world.spawn(Tag())
    second = world.spawn(Tag())
    order.clear()
    with world.deferred():
        third = world.spawn(Tag("new"))
        assert world.get(third, Tag).name == "new"  # queued components are visible to get()
        assert world.query(Tag) and all(e != third for e, _ in world.query(Tag))
        world.despawn(second)
        world.despawn(first)
        assert order == []  # nothing applied yet
    assert order == [("remove", first), ("remove", second), ("add", third)]
    assert world.entities() == [third]


def test_the_same_script_builds_the_same_world() -> None:
    def script(w: World) -> list:
        with w.deferred():
            for i in range(20):
                e = w.spawn(Health(i))
                if i % 3 == 0:
                    w.despawn(e)
        return [(e, w.get(e, Health).hp) for e in w.entities()]

    a, b = World(), World()
    try:
        assert script(a) == script(b)
    finally:
        a.close()
        b.close()


def test_locked_world_refuses_structural_changes_and_changes_nothing(world: World) -> None:
    e = world.spawn(Health())
    before = snapshot(world)
    with world.locked():
        for attempt in (
            lambda: world.spawn(Tag()),
            lambda: world.despawn(e),
            lambda: world.add(e, Tag()),
            lambda: world.remove(e, Health),
        ):
            with pytest.raises(WorldLockedError, match="locked"):
                attempt()
    world.flush()
    assert snapshot(world) == before


def test_resources(world: World) -> None:
    h = world.insert_resource(Health(7))
    assert world.resource(Health) is h
    with pytest.raises(MissingResourceError, match="no Tag resource"):
        world.resource(Tag)
    assert world.try_resource(Tag) is None


def test_per_step_events_and_esper_handlers(world: World) -> None:
    got = []
    world.set_handler("boom", lambda ev: got.append(ev))  # kept alive by the World
    world.emit(Tag("x"))
    world.emit(Tag("y"))
    assert [t.name for t in world.events(Tag)] == ["x", "y"]
    world.dispatch("boom", 5)
    assert got == [5]
    world.clear_events()
    assert world.events(Tag) == []


def test_validators_run_before_any_change(world: World) -> None:
    def no_negative(entity, comp):
        if comp.hp < 0:
            raise ValueError(f"entity {entity}, Health.hp must be >= 0")

    world.validator(Health, no_negative)
    e = world.spawn(Tag())
    before = snapshot(world)
    with pytest.raises(ValueError, match="Health.hp"):
        world.spawn(Tag("other"), Health(-1))
    with pytest.raises(ValueError, match=f"entity {e}, Health.hp"):
        world.add(e, Health(-1))
    assert snapshot(world) == before


def test_close_runs_remove_hooks_for_everything() -> None:
    w = World()
    removed = []
    w.on_remove(Health, lambda e, c: removed.append(e))
    ids = [w.spawn(Health()) for _ in range(3)]
    w.close()
    assert removed == ids
    with pytest.raises(WorldLockedError, match="closed"):
        w.spawn(Health())


def test_first_missing_names_the_first_absent_or_despawned_entity() -> None:
    world = World()
    a, b, c = world.spawn(), world.spawn(), world.spawn()
    assert world.first_missing([a, b, c]) is None
    assert world.first_missing([a, 999, c, 1000]) == 999
    with world.deferred():
        world.despawn(b)  # queued: gone for exists() already
        assert world.first_missing([a, b, c]) == b
    world.despawn(a)
    assert world.first_missing([c, a]) == a
    assert world.first_missing([]) is None
