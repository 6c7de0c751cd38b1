"""Tests of the loop invariants I-1 and I-2 (thesis §3.4) on hand-built partial maps.

The world: a square a-b-c-d with a pendant e at a, and a directional marker at a
pointing at b (the directional lighthouse of §3.3)::

    e - a - b        a: (b, d, e)   b: (a, c)   c: (b, d)   d: (c, a)   e: (a)
        |   |
        d - c

The map labels v0's exits starting elsewhere (map exit i of v0 is world exit
(i + 2) mod 3 of a), as an explorer is free to do, so the correspondence has
non-zero offsets.
"""

from __future__ import annotations

import pytest

from topomark.spec.errors import Violation
from topomark.spec.invariants import (
    IncrementalInvariants, check_I1, check_I2, check_invariants, correspondence, explored_world_darts,
    lighthouse_anchor,
)
from topomark.spec.mapstate import PartialMap
from topomark.spec.marker import VertexMarker
from topomark.spec.world import World

WORLD = World({"a": ["b", "d", "e"], "b": ["a", "c"], "c": ["b", "d"], "d": ["c", "a"], "e": ["a"]},
              [VertexMarker("a", points_to="b")])


def start_map() -> PartialMap:
    """S = {v0}: v0 = a, degree 3, the marker head sensed at map exit 1; U = all of v0's exits."""
    S = PartialMap()
    v0 = S.add_vertex(3)
    S.mark_vertex(v0, head=1)
    S.unexplored = [(0, 0), (0, 1), (0, 2)]
    return S


def three_edges() -> PartialMap:
    """After exploring a-b (map exit 1 of v0), a-d (exit 2) and b-c: v1 = b, v2 = d, v3 = c.

    Map darts and world darts:  (0,0)=a->e  (0,1)=a->b  (0,2)=a->d
    v1 = b entered by map exit 1 (world exit 0):  (1,1)=b->a  (1,0)=b->c
    v2 = d entered by map exit 0 (world exit 1):  (2,0)=d->a  (2,1)=d->c
    v3 = c entered by map exit 0 (world exit 0):  (3,0)=c->b  (3,1)=c->d
    """
    S = start_map()
    v1 = S.add_vertex(2)
    S.add_edge((0, 1), (v1, 1))
    v2 = S.add_vertex(2)
    S.add_edge((0, 2), (v2, 0))
    v3 = S.add_vertex(2)
    S.add_edge((v1, 0), (v3, 0))
    S.unexplored = [(0, 0), (2, 1), (3, 1)]
    return S


def anchor(S):
    a = lighthouse_anchor(S, WORLD)
    assert a is not None
    return a


def assert_violation(v, check, where=None, expected=None, found=None):
    assert isinstance(v, Violation), v
    assert v.check == check
    if where is not None:
        assert where in v.where, (where, v.where)
    if expected is not None:
        assert expected in v.expected, (expected, v.expected)
    if found is not None:
        assert found in v.found, (found, v.found)
    assert str(v).startswith(f"{check} violated at {v.where}: expected {v.expected}, found {v.found}")
    assert v.to_json()["check"] == check and v.to_json()["where"] == v.where


# -- correct maps pass ------------------------------------------------------------
def test_lighthouse_anchor_maps_head_to_head():
    assert lighthouse_anchor(start_map(), WORLD) == ((0, 1), ("a", 0))
    assert lighthouse_anchor(start_map(), WORLD.with_markers([VertexMarker("a")])) is None
    unmarked = PartialMap()
    unmarked.add_vertex(3)
    assert lighthouse_anchor(unmarked, WORLD) is None


@pytest.mark.parametrize("build", [start_map, three_edges])
def test_correct_partial_maps_pass(build):
    S = build()
    assert check_invariants(S, WORLD, anchor(S)) is None
    phi = correspondence(S, WORLD, anchor(S))
    assert phi.isomorphic
    assert check_I1(S, WORLD, anchor(S)) is None
    assert check_I2(S, WORLD, phi.witness) is None


def test_correspondence_of_the_three_edge_map():
    S = three_edges()
    phi = correspondence(S, WORLD, anchor(S)).witness
    assert phi.vertex_map == {0: "a", 1: "b", 2: "d", 3: "c"}
    assert phi.offsets == {0: 2, 1: 1, 2: 1, 3: 0}
    assert explored_world_darts(S, phi) == {("a", 0), ("b", 0), ("a", 1), ("d", 1), ("b", 1), ("c", 0)}
    # U's images are exactly the unexplored world darts leaving G_s
    assert {phi.image(S, d) for d in S.unexplored} == {("a", 2), ("d", 0), ("c", 1)}


def test_loop_closure_and_completion_pass():
    S = three_edges()
    S.add_edge((2, 1), (3, 1))        # the loop edge d-c
    S.unexplored = [(0, 0)]
    assert check_invariants(S, WORLD, anchor(S)) is None
    v4 = S.add_vertex(1)              # e, the last vertex
    S.add_edge((0, 0), (v4, 0))
    S.unexplored = []
    assert check_invariants(S, WORLD, anchor(S)) is None
    assert S.complete()


# -- I-2 ---------------------------------------------------------------------------
def test_missing_U_entry_names_the_world_dart():
    S = three_edges()
    S.unexplored.remove((2, 1))       # d -> c, world dart (d, 0)
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-2", where="world dart ('d', 0)", expected="an entry in U", found="none")
    assert "'d'-'c'" in v.expected


def test_missing_U_entry_at_v0():
    S = start_map()
    S.unexplored = [(0, 0), (0, 2)]   # map exit 1 = world exit 0 of a forgotten
    assert_violation(check_invariants(S, WORLD, anchor(S)), "I-2", where="world dart ('a', 0)", found="none")


def test_duplicate_U_entry():
    S = three_edges()
    S.unexplored.append((3, 1))
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-2", where="U entry (3, 1)", expected="listed once", found="listed 2 times")


def test_explored_dart_left_in_U():
    S = three_edges()
    S.unexplored.append((1, 0))       # b -> c was explored
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-2", where="U entry (1, 0)", expected="an unexplored edge", found="already explored")
    assert "('b', 1)" in v.found and v.detail == "an explored edge was left in U"


def test_U_entry_that_is_not_a_dart():
    S = three_edges()
    S.unexplored.append((0, 7))
    assert_violation(check_invariants(S, WORLD, anchor(S)), "I-2", where="U entry (0, 7)", found="no such")
    S = three_edges()
    S.unexplored.append((9, 0))
    assert_violation(check_invariants(S, WORLD, anchor(S)), "I-2", where="U entry (9, 0)")


# The incremental checker (run after every iteration) must report each U fault exactly as the full one does,
# including a duplicate that hides a missing entry (same length as the right U).
U_FAULTS = {
    "missing": lambda U: U.remove((2, 1)),
    "duplicate": lambda U: U.append((3, 1)),
    "explored": lambda U: U.append((1, 0)),
    "bad exit": lambda U: U.append((0, 7)),
    "bad vertex": lambda U: U.append((9, 0)),
    "duplicate for missing": lambda U: U.__setitem__(U.index((2, 1)), (3, 1)),
    "not a dart": lambda U: U.append([0, 0]),
    "added past U's record": lambda U: list.append(U, (3, 1)),  # U's length then disagrees with its record
    "removed past U's record": lambda U: list.remove(U, (2, 1)),
}


@pytest.mark.parametrize("fault", sorted(U_FAULTS))
def test_incremental_I2_agrees_with_the_full_check(fault):
    S = three_edges()
    quick = IncrementalInvariants(S, WORLD, anchor(S))
    assert quick.update() is None
    U_FAULTS[fault](S.unexplored)
    full = check_invariants(S, WORLD, anchor(S))
    assert isinstance(full, Violation) and full.check == "I-2"
    assert quick.update() == full
    S.unexplored = three_edges().unexplored  # a new U is counted whole
    assert quick.update() is None and check_invariants(S, WORLD, anchor(S)) is None
    U_FAULTS[fault](S.unexplored)
    assert quick.update() == full
    S.unexplored[:] = three_edges().unexplored
    assert quick.update() is None and check_invariants(S, WORLD, anchor(S)) is None


def test_incremental_I2_sees_a_new_vertex_s_exits_left_out_of_U():
    """S gains b (map exit 1 of v0) but U is not given b's other exit: I-2 fails, the incremental check reports
    it as the full one does (the open darts a new vertex brings are counted, not only U's changes)."""
    S = start_map()
    quick = IncrementalInvariants(S, WORLD, anchor(S))
    assert quick.update() is None
    v1 = S.add_vertex(2)
    S.add_edge((0, 1), (v1, 1))
    S.unexplored.remove((0, 1))
    full = check_invariants(S, WORLD, anchor(S))
    assert_violation(full, "I-2", found="none")
    assert quick.update() == full
    S.unexplored.append((v1, 0))
    assert quick.update() is None and check_invariants(S, WORLD, anchor(S)) is None


def test_incremental_marks_are_checked_again_after_S_or_the_world_changes():
    """A vertex whose marks passed is not re-checked while S and the world stay as they were; a mark added to
    S, or a marker dropped in the world, there is checked (and here fails)."""
    S = three_edges()
    quick = IncrementalInvariants(S, WORLD, anchor(S))
    assert quick.update() is None and quick.rebase(WORLD) is None
    S.mark_vertex(3)                  # c has no marker
    assert_violation(quick.update(), "I-1", where="map vertex 3", found="1 vertex marker(s)")
    S = three_edges()
    quick = IncrementalInvariants(S, WORLD, anchor(S))
    assert quick.update() is None
    dropped = WORLD.with_markers(WORLD.markers + (VertexMarker("c"),))
    assert_violation(quick.rebase(dropped), "I-1", where="map vertex 3", expected="1 vertex marker(s)")


# -- I-1 ---------------------------------------------------------------------------
def test_wrongly_joined_edge():
    """The edge a-d is joined to b (map vertex 1) instead of a new vertex."""
    S = start_map()
    v1 = S.add_vertex(2)
    S.add_edge((0, 1), (v1, 1))
    S.add_edge((0, 2), (v1, 0))       # world a->d, but the map says it leads to b
    S.unexplored = [(0, 0)]
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-1", where="vertex 0 exit 2", expected="to 'b' through exit 1 of 'a'",
                     found="exit 1 of 'a' leads to 'd'")


def test_loop_edge_taken_for_a_new_vertex():
    """The loop edge d-c is added as a non-loop edge: a second map vertex for the world vertex c."""
    S = three_edges()
    v4 = S.add_vertex(2)
    S.add_edge((2, 1), (v4, 1))
    S.unexplored = [(0, 0), (3, 1), (4, 0)]
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-1", where="vertex 2 exit 1", found="'c', already the image of 3")


def test_map_vertex_with_the_wrong_degree():
    S = start_map()
    v1 = S.add_vertex(3)              # b has degree 2
    S.add_edge((0, 1), (v1, 0))
    S.unexplored = [(0, 0), (0, 2), (1, 1), (1, 2)]
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-1", where="vertex 0 exit 1", expected="degree 3", found="'b' of degree 2")


def test_map_marker_must_match():
    S = three_edges()
    S.mark_vertex(3)                  # an undirected marker on c, which has none
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-1", where="vertex 3", expected="1 vertex marker(s)", found="no markers")


def test_head_sensed_at_the_wrong_exit_breaks_I1():
    S = three_edges()
    S.mark_vertex(0, head=2)          # the anchor now says map exit 2 is world exit 0 (a->b)
    v = check_invariants(S, WORLD, anchor(S))
    assert_violation(v, "I-1")
    assert "exit" in v.where and v.expected != v.found


def test_detached_map_vertex():
    S = three_edges()
    S.add_vertex(1)                   # never joined to anything
    v = check_I1(S, WORLD, anchor(S))
    assert_violation(v, "I-1", where="map vertex 4", expected="connected to v0", found="not connected")


def test_empty_map():
    v = check_I1(PartialMap(), WORLD, ((0, 0), ("a", 0)))
    assert_violation(v, "I-1", where="S", found="an empty map")


def test_changed_places_are_the_places_whose_marks_differ():
    """_changed_places (the checker's rebase after a drop) against a place-by-place comparison, over a run of
    random drops and pick-ups on one layer (each snapshot shares the unchanged places' marks with the last)."""
    import random

    from topomark.reference.worlds.generators import lattice_hole
    from topomark.spec.invariants import _changed_places
    from topomark.spec.markerlayer import MarkerLayer

    base = World(lattice_hole(3, 4, seed=2).rotation)
    layer, rng, changed = MarkerLayer(base), random.Random(3), 0
    before = layer.world()
    for _ in range(200):
        v = rng.choice(base.vertices)
        if rng.random() < 0.3 and layer.vertex_mark(v):
            layer.pick_up_vertex(v, 1)
        elif rng.random() < 0.5:
            layer.drop_vertex(v, 1, None if layer.vertex_mark(v) is None else layer.vertex_mark(v).head)
        elif layer.dart_marks(v) and rng.random() < 0.5:
            layer.pick_up_edge(v, layer.dart_marks(v)[0].exit, 1)
        else:
            exit_ = rng.randrange(base.degree(v))
            same = [dm.end for dm in layer.dart_marks(v) if dm.exit == exit_]
            layer.drop_edge(v, exit_, 1, same[0] if same else rng.choice((None, "H", "T")))
        after = layer.world()
        differ = {x for x in base.vertices if (before.vertex_mark(x), before.dart_marks(x))
                  != (after.vertex_mark(x), after.dart_marks(x))}
        assert _changed_places(before, after) == differ
        changed += len(differ)
        before = after
    assert changed > 200
    rebuilt = World(base.rotation, after.markers)  # equal marks in other objects: not a change
    assert _changed_places(after, rebuilt) == set()
