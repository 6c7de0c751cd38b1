"""Tests of the port-labelled model's spec core: PortWorld, from_joins, from_thesis_world, the contest's map format
and the plan semantics (spec/port_world.py, spec/port_icfpc.py, spec/port_plan.py)."""

from __future__ import annotations

import copy

import pytest
from hypothesis import given, settings, strategies as st

from topomark.reference.port.generate import random_port_world
from topomark.reference.worlds.argument import resolve_world
from topomark.spec.errors import InvalidWorld
from topomark.spec.port_icfpc import map_from_json, map_to_json, submission_from_json, submission_to_json
from topomark.spec.port_plan import (InvalidPlan, check_length, explore_cost, parse_plan, plan_text, run_plan)
from topomark.spec.port_world import PortWorld, from_joins, from_thesis_world

worlds = st.builds(random_port_world, st.integers(0, 2**32), st.integers(1, 8))

# Two rooms, two doors: door 0 joins the rooms, door 1 of each room is joined to itself.
PASSAGES = [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))]


def small(colours=(0, 1), passages=PASSAGES, start=0, alphabet=2) -> PortWorld:
    return from_joins(list(colours), passages, start, doors=2, alphabet=alphabet)


# -- validity: every condition has a fault that only it catches ----------------------------------------------

def test_a_valid_world_with_every_kind_of_passage():
    w = from_joins([0, 1], [((0, 0), (0, 0)), ((0, 1), (0, 2)), ((0, 3), (1, 0)), ((0, 4), (1, 1)),
                            ((0, 5), (1, 2)), ((1, 3), (1, 4)), ((1, 5), (1, 5))], 0)
    assert w.target(0, 0) == 0 and w.target(0, 1) == 0 and w.joins[0][1] == (0, 2)
    assert [w.target(0, d) for d in (3, 4, 5)] == [1, 1, 1]


@pytest.mark.parametrize("change, words", [
    (dict(passages=PASSAGES + [((1, 1), (0, 1))]), "(1, 1) is used twice"),
    (dict(passages=PASSAGES[:2]), "door-end (1, 1) is in no passage"),
    (dict(passages=[((0, 0), (1, 2)), ((0, 1), (0, 1)), ((1, 1), (1, 1))]), "(1, 2), which is not a door-end"),
    (dict(passages=[((0, 0), (2, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))]), "(2, 0), which is not a door-end"),
    (dict(colours=(0, 2)), "room 1's colour 2 is outside the alphabet 0..1"),
    (dict(colours=(0, -1)), "room 1's colour -1 is outside"),
    (dict(start=2), "the start room 2 is not a room"),
    (dict(start=-1), "the start room -1 is not a room"),
    (dict(passages=[((0, 0), (0, 0)), ((0, 1), (0, 1)), ((1, 0), (1, 1))]), "room 1 cannot be reached"),
    (dict(colours=()), "1 to 100,000 rooms"),
])
def test_from_joins_names_each_fault(change, words):
    with pytest.raises(InvalidWorld, match=None) as e:
        small(**change)
    assert words in str(e.value)


@pytest.mark.parametrize("joins, words", [
    ((((1, 0), (0, 1)), ((0, 0), (0, 1))), "(1, 1) is joined to (0, 1), but (0, 1) is joined to (0, 1)"),
    ((((1, 0), (0, 1)), ((0, 0),)), "room 1 has 1 doors, not 2"),
    ((((1, 0), (0, 1)),), "2 rooms have colours but 1 have doors"),
    ((((1, 1), (0, 1)), ((0, 0),)), "room 1 has 1 doors, not 2"),  # a later room's missing door, looked up early
    ((((1, 0), (0, 5)), ((0, 0), (1, 1))), "(0, 5), which is not a door-end"),
])
def test_port_world_names_each_fault_of_its_joins(joins, words):
    with pytest.raises(InvalidWorld) as e:
        PortWorld((0, 1), joins, 0, doors=2, alphabet=2)
    assert words in str(e.value)


def test_port_world_refuses_bad_door_and_alphabet_counts():
    with pytest.raises(InvalidWorld, match="1 to 64 doors"):
        PortWorld((0,), ((),), 0, doors=0)
    with pytest.raises(InvalidWorld, match="at least one colour"):
        PortWorld((0,), (((0, 0),),), 0, doors=1, alphabet=0)


# -- the contest's map format ---------------------------------------------------------------------------------

def contest_map() -> dict:
    return {"rooms": [0, 1], "startingRoom": 0, "connections": [
        {"from": {"room": 0, "door": d}, "to": {"room": 1, "door": 5 - d}} for d in range(6)]}


def test_map_keeps_door_numbers_as_given():
    w = map_from_json(contest_map())
    assert [w.joins[0][d] for d in range(6)] == [(1, 5 - d) for d in range(6)]
    assert map_from_json(map_to_json(w)) == w


def _edit(path_value):
    obj = contest_map()
    path, value = path_value
    target = obj
    for key in path[:-1]:
        target = target[key]
    if value is KeyError:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return obj


@pytest.mark.parametrize("edit, words", [
    ((("id",), "SECRET-TEAM-ID"), "unknown key 'id'"),
    ((("startingRoom",), KeyError), "the key 'startingRoom' is missing"),
    ((("startingRoom",), 2), "the start room 2 is not a room"),
    ((("startingRoom",), True), "startingRoom is not an integer"),
    ((("rooms", 1), 4), "room 1's colour 4 is outside the alphabet 0..3"),
    ((("rooms",), []), "rooms is a list of 1 to"),
    ((("connections", 0, "to", "door"), 4), "door-end (1, 4) is used twice"),
    ((("connections", 0, "to", "door"), 6), "(1, 6), which is not a door-end"),
    ((("connections", 0, "from", "side"), 1), "unknown key 'side'"),
    ((("connections",), [{"from": {"room": 0, "door": 0}, "to": {"room": 1, "door": 5}}]),
     "door-end (0, 1) is in no passage"),
])
def test_map_from_json_names_each_fault(edit, words):
    with pytest.raises(InvalidWorld) as e:
        map_from_json(_edit(edit))
    assert words in str(e.value)
    assert "SECRET" not in str(e.value)


def test_submission_refuses_an_unknown_key_without_echoing_it():
    with pytest.raises(InvalidWorld, match="unknown key 'id'") as e:
        submission_from_json({"problemName": "probatio", "id": "SECRET", "map": contest_map()})
    assert "SECRET" not in str(e.value)
    with pytest.raises(InvalidWorld, match="problemName is a printable string"):
        submission_from_json({"problemName": "", "map": contest_map()})


@settings(max_examples=40, deadline=None)
@given(worlds)
def test_contest_format_round_trips(w):
    assert map_from_json(map_to_json(w)) == w
    assert submission_from_json(submission_to_json("primus", w)) == ("primus", w)


# -- plans and records ----------------------------------------------------------------------------------------

# A corridor of three rooms, colours 0 0 0: door 0 goes right, door 1 goes left, ends join to themselves.
CORRIDOR = from_joins([0, 0, 0], [((0, 0), (1, 1)), ((1, 0), (2, 1)), ((0, 1), (0, 1)), ((2, 0), (2, 0))], 0,
                      doors=2, alphabet=4)


def test_a_mark_is_seen_again_later_in_the_plan():
    assert run_plan(CORRIDOR, parse_plan("0[3]011", doors=2)) == (0, 0, 3, 0, 3, 0)
    assert run_plan(CORRIDOR, parse_plan("[2]0[1]1", doors=2)) == (0, 2, 0, 1, 2)


def test_marks_are_not_carried_to_the_next_plan():
    run_plan(CORRIDOR, parse_plan("0[3]", doors=2))
    assert run_plan(CORRIDOR, parse_plan("01", doors=2)) == (0, 0, 0)


def test_the_echo_option():
    actions = parse_plan("[1]0[2]1", doors=2)
    assert run_plan(CORRIDOR, actions) == (0, 1, 0, 2, 1)
    assert run_plan(CORRIDOR, actions, echo_marks=False) == (0, 0, 1)
    assert len(run_plan(CORRIDOR, actions, echo_marks=False)) == 1 + 2


def test_a_later_mark_overwrites_an_earlier_one():
    assert run_plan(CORRIDOR, parse_plan("[1][2]01", doors=2), echo_marks=False) == (0, 0, 2)


@pytest.mark.parametrize("text, words", [
    ("012", "plan character 3 ('2') is not a door (doors 0..1)"),
    ("0[4]", "plan character 2 starts a mark"),
    ("0[", "plan character 2 starts a mark"),
    ("[]", "plan character 1 starts a mark"),
    ("a", "plan character 1 ('a')"),
    ("٣", "plan character 1"),
    ("0[" + "1" * 5000 + "]", "plan character 2 starts a mark"),  # a colour too long to read as an integer
])
def test_parse_plan_names_the_character(text, words):
    with pytest.raises(InvalidPlan) as e:
        parse_plan(text, doors=2, alphabet=4)
    assert words in str(e.value)


def test_plan_text_inverts_parse_plan():
    for text in ["", "0", "[3]", "01[2]10[0]"]:
        assert plan_text(parse_plan(text, doors=2)) == text


def test_the_length_limits():
    check_length(parse_plan("0" * 18, doors=2), 3)
    with pytest.raises(InvalidPlan, match="19 doors, over the full round's limit of 18"):
        check_length(parse_plan("0" * 19, doors=2), 3)
    check_length(parse_plan("0" * 54, doors=2), 3, "lightning")
    with pytest.raises(InvalidPlan, match="lightning round's limit of 54"):
        check_length(parse_plan("0" * 55, doors=2), 3, "lightning")
    check_length(parse_plan("[1]" * 40 + "0" * 18, doors=2), 3)  # marks do not count
    assert explore_cost(3) == 4


# -- from thesis worlds ----------------------------------------------------------------------------------------

def test_conversion_keeps_what_the_thesis_robot_senses_along_a_walk():
    world = resolve_world("lattice-hole:rows=3,cols=4")
    rotation = {v: list(ns) for v, ns in world.rotation.items()}
    start = next(iter(rotation))
    port, names = from_thesis_world(rotation, start)
    rng = __import__("random").Random(5)
    v, plan = start, []
    degrees = [len(rotation[v])]
    for _ in range(40):
        i = rng.randrange(len(rotation[v]))
        plan.append(str(i))
        v = rotation[v][i]
        degrees.append(len(rotation[v]))
    record = run_plan(port, parse_plan("".join(plan), doors=port.doors, alphabet=port.alphabet))
    assert list(record) == degrees
    assert names[0] == start and port.rooms == len(rotation)


def test_conversion_joins_missing_doors_to_themselves_and_can_drop_colours():
    port, names = from_thesis_world({"a": ["b"], "b": ["a", "c"], "c": ["b"]}, "b", colour_by_degree=False)
    assert names == ["b", "a", "c"] and port.colours == (0, 0, 0) and port.alphabet == 1
    assert port.joins[1][1] == (1, 1) and port.joins[2][1] == (2, 1)


def test_conversion_refuses_an_unknown_start():
    with pytest.raises(InvalidWorld, match="is not a vertex"):
        from_thesis_world({"a": ["b"], "b": ["a"]}, "z")


def test_worlds_are_values():
    w = small()
    assert copy.deepcopy(w) == w and hash(w) == hash(small())


# -- a second reading of the semantics, from the contest's map object alone -----------------------------------

def record_from_map(obj: dict, plan: str, echo: bool) -> list[int]:
    """The record of ``plan`` computed from a contest map object's connections, by string rewriting of the
    plan, without PortWorld or parse_plan."""
    where = {}
    for c in obj["connections"]:
        a, b = (c["from"]["room"], c["from"]["door"]), (c["to"]["room"], c["to"]["door"])
        where[a], where[b] = b[0], a[0]
    labels = list(obj["rooms"])
    room, out, k = obj["startingRoom"], [labels[obj["startingRoom"]]], 0
    while k < len(plan):
        if plan[k] == "[":
            labels[room] = int(plan[k + 1])
            out += [labels[room]] if echo else []
            k += 3
        else:
            room = where[(room, int(plan[k]))]
            out.append(labels[room])
            k += 1
    return out


plans = st.lists(st.one_of(st.sampled_from("012345"), st.sampled_from(["[0]", "[1]", "[2]", "[3]"])),
                 max_size=30).map("".join)


@settings(max_examples=60, deadline=None)
@given(worlds, plans, st.booleans())
def test_run_plan_agrees_with_a_second_reading_from_the_map(w, plan, echo):
    assert list(run_plan(w, parse_plan(plan), echo_marks=echo)) == record_from_map(map_to_json(w), plan, echo)
