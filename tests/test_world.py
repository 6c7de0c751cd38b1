"""Tests of topomark.spec.world: validation (§3.1.1) and the rotation-system accessors."""

from __future__ import annotations

import networkx as nx
import pytest
from hypothesis import given, settings

from topomark.reference.worlds import generators as g
from topomark.reference.worlds.strategies import worlds
from topomark.spec.errors import InvalidInput, InvalidWorld
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.world import Start, World

FAST = settings(max_examples=60, deadline=None)

TRIANGLE = {"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}
PATH = {"a": ["b"], "b": ["a", "c"], "c": ["b"]}  # a - b - c


# -- validation ----------------------------------------------------------------
INVALID = [
    # (id, rotation, markers, start, words every message must contain)
    ("empty", {}, (), None, ["no vertices"]),
    ("self-loop", {"a": ["a", "b"], "b": ["a"]}, (), None, ["self-loop", "'a'"]),
    ("multi-edge", {"a": ["b", "b"], "b": ["a"]}, (), None, ["multi-edge", "'a'", "'b'", "2 times"]),
    ("asymmetric", {"a": ["b", "c"], "b": ["a", "c"], "c": ["a"]}, (), None,
     ["asymmetric", "'b' lists 'c'", "'c' does not list 'b'"]),
    ("disconnected", {"a": ["b"], "b": ["a"], "c": ["d"], "d": ["c"]}, (), None,
     ["disconnected", "'c'", "'a'"]),
    ("degree 0", {"a": ["b"], "b": ["a"], "c": []}, (), None, ["'c'", "degree 0"]),
    ("single vertex", {"a": []}, (), None, ["'a'", "degree 0"]),
    ("unknown neighbour", {"a": ["b", "z"], "b": ["a"]}, (), None, ["'a'", "'z'", "not a vertex"]),
    ("non-string neighbour", {"a": ["b", 7], "b": ["a"]}, (), None, ["'a'", "7", "not a string"]),
    ("non-string vertex", {1: ["b"], "b": [1]}, (), None, ["1", "not a string"]),
    ("marker at non-vertex", PATH, [VertexMarker("z")], None, ["vertex marker", "'z'", "not a vertex"]),
    ("edge marker on non-edge", PATH, [EdgeMarker(("a", "c"))], None, ["('a', 'c')", "not an edge"]),
    ("edge marker on non-vertex", PATH, [EdgeMarker(("a", "z"))], None, ["('a', 'z')", "not an edge"]),
    ("edge marker with 3 ends", PATH, [EdgeMarker(("a", "b", "c"))], None, ["two end vertices"]),
    ("points_to not a neighbour", PATH, [VertexMarker("a", points_to="c")], None,
     ["'a'", "'c'", "not a neighbour of 'a'"]),
    ("points_to non-vertex", PATH, [VertexMarker("b", points_to="q")], None, ["'b'", "'q'", "not a neighbour"]),
    ("edge head not an end", PATH, [EdgeMarker(("a", "b"), head="c")], None,
     ["('a', 'b')", "head 'c'", "not an end"]),
    ("duplicate vertex marker", PATH, [VertexMarker("b"), VertexMarker("b", points_to="a")], None,
     ["two marker entries", "'b'"]),
    ("duplicate edge marker", PATH, [EdgeMarker(("a", "b")), EdgeMarker(("b", "a"), head="a")], None,
     ["two marker entries", "edge", "'a'", "'b'"]),
    ("count 0", PATH, [VertexMarker("a", count=0)], None, ["count", "0"]),
    ("count bool", PATH, [EdgeMarker(("a", "b"), count=True)], None, ["count", "True"]),
    ("count float", PATH, [VertexMarker("a", count=1.0)], None, ["count", "1.0"]),
    ("start at non-vertex", PATH, (), Start("z", "a"), ["start vertex", "'z'", "not a vertex"]),
    ("facing not a neighbour", PATH, (), Start("a", "c"), ["'c'", "not a neighbour of 'a'"]),
    ("facing itself", PATH, (), Start("b", "b"), ["'b'", "not a neighbour of 'b'"]),
]


@pytest.mark.parametrize("rotation, markers, start, words", [c[1:] for c in INVALID], ids=[c[0] for c in INVALID])
def test_invalid_world_names_the_problem(rotation, markers, start, words):
    with pytest.raises(InvalidWorld) as info:
        World(rotation, markers, start)
    message = str(info.value)
    for word in words:
        assert word in message, (word, message)
    assert "\n" not in message
    assert isinstance(info.value, InvalidInput) and isinstance(info.value, ValueError)


def test_valid_worlds_with_every_kind_of_marker_are_accepted():
    w = World(TRIANGLE, [VertexMarker("a", 2, "c"), EdgeMarker(("b", "c"), 3, "c"), EdgeMarker(("a", "b"))],
              Start("b", "a"))
    assert w.vertex_mark("a").count == 2 and w.vertex_mark("a").head == 1
    assert w.vertex_mark("b") is None
    # the directional edge marker on b-c: H at c (its head), T at b
    assert [(d.exit, d.count, d.end) for d in w.dart_marks("c")] == [(1, 3, "H")]
    assert [(d.exit, d.count, d.end) for d in w.dart_marks("b")] == [(0, 3, "T"), (1, 1, None)]
    assert [(d.exit, d.count, d.end) for d in w.dart_marks("a")] == [(0, 1, None)]


# -- accessors -----------------------------------------------------------------
@FAST
@given(worlds(max_vertices=9, markers="any", with_start=True))
def test_target_is_an_involution_without_fixed_points(w):
    darts = list(w.darts())
    assert len(darts) == sum(len(ns) for ns in w.rotation.values()) == 2 * w.m
    assert len(set(darts)) == len(darts)
    for v, i in darts:
        t = w.target((v, i))
        assert w.arc((v, i)) == t
        assert t[0] == w.neighbour(v, i) == w.rotation[v][i]
        assert t[0] != v
        assert w.rotation[t[0]][t[1]] == v  # arrives by the exit that leads back
        assert w.target(t) == (v, i)


@FAST
@given(worlds(max_vertices=9))
def test_index_and_neighbour_are_inverse(w):
    for v in w.vertices:
        assert w.degree(v) == len(w.rotation[v])
        for i in range(w.degree(v)):
            assert w.index(v, w.neighbour(v, i)) == i
        for u in w.rotation[v]:
            assert w.neighbour(v, w.index(v, u)) == u


@FAST
@given(worlds(max_vertices=9))
def test_n_m_and_edges_listed_once(w):
    assert w.n == len(w.rotation) == len(w.vertices)
    edges = list(w.edges())
    assert len(edges) == w.m
    as_sets = {frozenset(e) for e in edges}
    assert len(as_sets) == len(edges)  # each edge once
    assert as_sets == {frozenset((v, u)) for v, ns in w.rotation.items() for u in ns}
    order = list(w.vertices)
    assert all(order.index(u) < order.index(v) for u, v in edges)


def _faces_by_hand(w: World) -> int:
    """Face tracing written independently: the face permutation is dart -> (w, j+1) for (w, j) = reverse."""
    succ = {}
    for v, ns in w.rotation.items():
        for i, u in enumerate(ns):
            j = list(w.rotation[u]).index(v)
            succ[(v, i)] = (u, (j + 1) % len(w.rotation[u]))
    seen, count = set(), 0
    for d in succ:
        if d not in seen:
            count += 1
            while d not in seen:
                seen.add(d)
                d = succ[d]
    return count


@FAST
@given(worlds(max_vertices=9))
def test_faces_and_euler_formula(w):
    f = w.faces()
    assert f == _faces_by_hand(w)
    assert 1 <= f <= 2 * w.m
    assert (2 - w.n + w.m - f) % 2 == 0
    assert w.genus() * 2 == 2 - w.n + w.m - f
    assert w.genus() >= 0


def test_genus_of_known_embeddings():
    lat = g.lattice(3, 4)
    assert (lat.n, lat.m, lat.faces(), lat.genus()) == (12, 17, 7, 0)
    k4 = g.planar(nx.complete_graph(4))
    assert (k4.n, k4.m, k4.faces(), k4.genus()) == (4, 6, 4, 0)
    # K4 drawn on a circle has crossing diagonals: a torus embedding
    assert g.complete(4).genus() == 1
    a, b = g.wheel_pair()
    assert (a.faces(), a.genus()) == (5, 0)
    assert (b.faces(), b.genus()) == (3, 1)
    assert g.cycle(6).faces() == 2 and g.cycle(6).genus() == 0
    assert g.chain(4).faces() == 1 and g.chain(4).genus() == 0


def test_hand_computed_triangle():
    w = World(TRIANGLE)
    assert (w.n, w.m) == (3, 3)
    assert w.target(("a", 0)) == ("b", 1)
    assert w.target(("a", 1)) == ("c", 0)
    assert w.target(("b", 0)) == ("c", 1)
    assert w.faces() == 2 and w.genus() == 0
    assert list(w.edges()) == [("a", "b"), ("a", "c"), ("b", "c")]


def test_start_state():
    assert World(TRIANGLE).start_state() == ("a", 0)
    assert World({"x": ["y"], "y": ["x", "z"], "z": ["y"]}).start_state() == ("x", 0)
    assert World(TRIANGLE, start=Start("b", "a")).start_state() == ("b", 1)
    assert World(TRIANGLE, start=Start("c", "a")).start_state() == ("c", 0)
    a, b = g.wheel_pair()
    assert a.start_state() == b.start_state() == ("0", 0)


@FAST
@given(worlds(max_vertices=8, with_start=True))
def test_start_state_faces_the_start_neighbour(w):
    v, e = w.start_state()
    assert v == w.start.at
    assert w.neighbour(v, e) == w.start.facing


def test_equality_and_hash_ignore_vertex_order():
    w1 = World({"a": ["b"], "b": ["a"]}, [VertexMarker("a")])
    w2 = World({"b": ["a"], "a": ["b"]}, [VertexMarker("a")])
    assert w1 == w2
    assert hash(w1) == hash(w2)
    assert len({w1, w2}) == 1
    assert w1 != World({"a": ["b"], "b": ["a"]}, [VertexMarker("b")])
    assert w1 != World({"a": ["b"], "b": ["a"]}, [VertexMarker("a")], Start("a", "b"))


def test_with_markers_and_with_start_revalidate():
    w = World(PATH)
    assert w.with_markers([VertexMarker("b", points_to="c")]).vertex_mark("b").head == 1
    assert w.with_start(Start("c", "b")).start_state() == ("c", 0)
    with pytest.raises(InvalidWorld, match="'z'"):
        w.with_markers([VertexMarker("z")])
    with pytest.raises(InvalidWorld, match="not a neighbour of 'a'"):
        w.with_start(Start("a", "c"))
