"""The door to esper's private layer (``kge.esper_door``) agrees with esper's public API."""

from __future__ import annotations

from collections.abc import Iterator

import esper
import pytest

from kge.esper_door import entity_table, next_entity_id, set_next_entity_id


@pytest.fixture
def fresh_world() -> Iterator[None]:
    before = esper.current_world
    esper.switch_world("test-esper-door")
    try:
        yield
    finally:
        esper.switch_world(before)
        esper.delete_world("test-esper-door")


def test_entity_table_is_what_esper_reports(fresh_world: None) -> None:
    a = esper.create_entity(1.5, "x")
    b = esper.create_entity(7)
    table = entity_table()
    assert set(table) == {a, b}
    for e in (a, b):
        assert tuple(table[e].values()) == esper.components_for_entity(e)
    esper.add_component(b, 2.5)
    assert table[b] == {int: 7, float: 2.5}  # live, not a copy


def test_an_entity_written_into_the_table_is_an_esper_entity(fresh_world: None) -> None:
    entity_table()[40] = {}  # how a restore keeps its ids
    assert esper.entity_exists(40)
    esper.add_component(40, 4.0)
    assert esper.get_component(float) == [(40, 4.0)]


def test_next_entity_id_peeks_without_taking(fresh_world: None) -> None:
    first = next_entity_id()
    assert next_entity_id() == first
    assert esper.create_entity() == first
    assert next_entity_id() == first + 1


def test_set_next_entity_id_moves_esper_on(fresh_world: None) -> None:
    set_next_entity_id(100)
    assert next_entity_id() == 100
    assert esper.create_entity() == 100
    assert esper.create_entity() == 101


def test_each_world_has_its_own_table(fresh_world: None) -> None:
    e = esper.create_entity(1.0)
    mine = entity_table()
    esper.switch_world("test-esper-door-other")
    try:
        assert e not in entity_table()
        assert entity_table() is not mine
    finally:
        esper.switch_world("test-esper-door")
        esper.delete_world("test-esper-door-other")
