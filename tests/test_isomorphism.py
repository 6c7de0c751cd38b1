"""Tests of extended isomorphism (§3.1.3): the anchored search, the networkx dart-graph search, and witnesses.

Every witness is checked here by a loop over all darts written from the definition,
independently of ``verify_witness`` (which must agree).
"""

from __future__ import annotations

import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.reference.worlds import generators as g
from topomark.reference.worlds.strategies import relabelled, rotated, worlds
from topomark.spec.dartgraph import find_isomorphism_nx
from topomark.spec.errors import Violation
from topomark.spec.isomorphism import Witness, anchored, find_isomorphism, verify_witness
from topomark.spec.mapstate import PartialMap
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.world import World

MARKER_KINDS = [None, "directional-vertex", "any"]


# -- the definition, written out -----------------------------------------------
def witness_ok(a: World, b: World, wit: Witness, markers: bool = True) -> bool:
    """f is a bijection; every dart (v, i) -> (w, j) of a maps to (f v, i + r_v) -> (f w, j + r_w) in b;
    markers (read from ``world.markers``, not from the marks tables) go to markers."""
    f, r = wit.vertex_map, wit.offsets
    if set(f) != set(a.rotation) or set(f.values()) != set(b.rotation) or len(set(f.values())) != len(f):
        return False
    if set(r) != set(a.rotation):
        return False
    for v, ns in a.rotation.items():
        d = len(ns)
        if len(b.rotation[f[v]]) != d:
            return False
        for i, w in enumerate(ns):
            j = a.rotation[w].index(v)
            bi = (i + r[v]) % d
            bw = b.rotation[f[v]][bi]
            if bw != f[w]:
                return False
            if b.rotation[bw].index(f[v]) != (j + r[w]) % len(a.rotation[w]):
                return False
    if markers:
        image = set()
        for m in a.markers:
            if isinstance(m, VertexMarker):
                image.add(("v", f[m.at], m.count, None if m.points_to is None else f[m.points_to]))
            else:
                image.add(("e", frozenset(f[x] for x in m.between), m.count, None if m.head is None else f[m.head]))
        target = set()
        for m in b.markers:
            if isinstance(m, VertexMarker):
                target.add(("v", m.at, m.count, m.points_to))
            else:
                target.add(("e", frozenset(m.between), m.count, m.head))
        if image != target:
            return False
    return True


def both(a, b, markers=True):
    """Run both implementations; they must agree, and every witness must satisfy the definition."""
    r1 = find_isomorphism(a, b, markers=markers)
    r2 = find_isomorphism_nx(a, b, markers=markers)
    assert r1.isomorphic == r2.isomorphic == bool(r1) == bool(r2)
    for r in (r1, r2):
        if r.isomorphic:
            assert r.witness is not None and r.mismatch is None
            assert witness_ok(a, b, r.witness, markers)
            assert verify_witness(a, b, r.witness, markers=markers) is None
        else:
            assert r.witness is None
            assert isinstance(r.mismatch, Violation)
            assert r.mismatch.where and r.mismatch.expected and r.mismatch.found
    return r1.isomorphic


def mirror(w: World) -> World:
    return World({v: tuple(reversed(ns)) for v, ns in w.rotation.items()}, w.markers, w.start)


def transpose(w: World, v: str, i: int, k: int) -> World:
    """Swap exits i and k of v (a near miss: may or may not stay isomorphic)."""
    ns = list(w.rotation[v])
    ns[i], ns[k] = ns[k], ns[i]
    rot = dict(w.rotation)
    rot[v] = tuple(ns)
    return World(rot, w.markers, w.start)


# -- agreement --------------------------------------------------------------------
@pytest.mark.parametrize("kind", MARKER_KINDS)
@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_implementations_agree_on_random_pairs(kind, data):
    a = data.draw(worlds(max_vertices=4, markers=kind), label="a")
    b = data.draw(worlds(min_vertices=a.n, max_vertices=a.n, markers=kind), label="b")
    both(a, b)
    both(a, b, markers=False)


@pytest.mark.parametrize("kind", MARKER_KINDS)
@settings(max_examples=50, deadline=None)
@given(data=st.data())
def test_implementations_agree_on_near_misses(kind, data):
    a = data.draw(worlds(max_vertices=7, markers=kind), label="a")
    big = [v for v in a.vertices if a.degree(v) >= 2]
    if not big:  # a single edge: no transposition exists; compare with a relabelled copy instead
        assert both(a, relabelled(a, {"0": "1", "1": "0"}))
        return
    v = data.draw(st.sampled_from(big), label="v")
    i, k = data.draw(st.lists(st.integers(0, a.degree(v) - 1), min_size=2, max_size=2, unique=True), label="ik")
    b = transpose(a, v, i, k)
    verdict = both(a, b)
    if a.degree(v) == 2:  # swapping the two exits of a degree-2 vertex is a rotation
        assert verdict
    # hide the change behind a random relabelling and renumbering: same verdict
    rng = random.Random(data.draw(st.integers(0, 2**32), label="seed"))
    assert both(a, rotated(relabelled(b, rng), rng)) == verdict


@pytest.mark.parametrize("kind", MARKER_KINDS)
@settings(max_examples=50, deadline=None)
@given(data=st.data())
def test_relabelled_and_rotated_copies_are_isomorphic(kind, data):
    a = data.draw(worlds(max_vertices=9, markers=kind), label="a")
    rng = random.Random(data.draw(st.integers(0, 2**32), label="seed"))
    assert both(a, relabelled(a, rng))
    assert both(a, rotated(a, rng))
    c = rotated(relabelled(a, rng), rng)
    assert both(a, c)
    assert both(c, a)
    # renaming to quite different names
    assert both(a, relabelled(a, {v: f"x{v}y" for v in a.vertices}))


@pytest.mark.parametrize("kind", MARKER_KINDS)
@settings(max_examples=40, deadline=None)
@given(data=st.data())
def test_mirror_images_agree(kind, data):
    a = data.draw(worlds(max_vertices=8, markers=kind), label="a")
    verdict = both(a, mirror(a))
    if all(a.degree(v) <= 2 for v in a.vertices):  # reversing 1 or 2 exits is a rotation
        assert verdict


@settings(max_examples=40, deadline=None)
@given(worlds(min_vertices=3, max_vertices=7), st.data())
def test_witness_checks_agree_on_corrupted_witnesses(a, data):
    rng = random.Random(data.draw(st.integers(0, 2**32)))
    b = rotated(relabelled(a, rng), rng)
    res = find_isomorphism(a, b)
    assert res.isomorphic
    f, r = dict(res.witness.vertex_map), dict(res.witness.offsets)
    # shifting one offset at a vertex of degree >= 2 breaks the witness (its neighbours are distinct)
    v = data.draw(st.sampled_from([x for x in a.vertices if a.degree(x) >= 2]))
    bad_r = dict(r)
    bad_r[v] = (r[v] + data.draw(st.integers(1, a.degree(v) - 1))) % a.degree(v)
    bad = Witness(f, bad_r)
    assert not witness_ok(a, b, bad)
    assert verify_witness(a, b, bad) is not None
    # swapping two images: whatever the verdict, the two checks agree
    x, y = data.draw(st.lists(st.sampled_from(list(a.vertices)), min_size=2, max_size=2, unique=True))
    f2 = dict(f)
    f2[x], f2[y] = f[y], f[x]
    swapped = Witness(f2, r)
    assert witness_ok(a, b, swapped) == (verify_witness(a, b, swapped) is None)
    # not a bijection
    f3 = dict(f)
    f3[x] = f[y]
    assert not witness_ok(a, b, Witness(f3, r))
    assert verify_witness(a, b, Witness(f3, r)) is not None


# -- concrete cases -----------------------------------------------------------------
# a "spider": hub h with legs of lengths 1, 2, 3 -- its three branches are distinguishable
SPIDER = {"h": ["p1", "q1", "r1"], "p1": ["h"], "q1": ["h", "q2"], "q2": ["q1"],
          "r1": ["h", "r2"], "r2": ["r1", "r3"], "r3": ["r2"]}


def test_chiral_world_is_not_isomorphic_to_its_mirror():
    s = World(SPIDER)
    assert not both(s, mirror(s))
    assert both(s, mirror(mirror(s)))
    # ... but as plain graphs they are the same: every vertex keeps its neighbours
    assert all(set(s.rotation[v]) == set(mirror(s).rotation[v]) for v in s.vertices)


def test_wheels():
    a, b = g.wheel_pair()
    assert not both(a, b)                      # Figure 3.4: same graph, different embedding
    assert not both(a, b, markers=False)
    assert both(a, mirror(a))                  # the planar wheel is achiral
    assert both(b, mirror(b))                  # so is the twisted wheel (its mirror is a relabelling)
    da, db = g.wheel_pair_directional()
    assert not both(da, db)
    assert both(da, rotated(relabelled(da, random.Random(5)), random.Random(6)))


def test_markers_must_be_preserved():
    s = World(SPIDER)
    # same graph, marker at a different vertex
    assert not both(s.with_markers([VertexMarker("p1")]), s.with_markers([VertexMarker("r3")]))
    assert both(s.with_markers([VertexMarker("p1")]), s.with_markers([VertexMarker("r3")]), markers=False)
    assert not both(s.with_markers([VertexMarker("h")]), s)
    assert both(s.with_markers([VertexMarker("h")]), s, markers=False)
    assert not both(s.with_markers([VertexMarker("h", count=2)]), s.with_markers([VertexMarker("h")]))
    # directional head different
    assert not both(s.with_markers([VertexMarker("h", points_to="p1")]), s.with_markers([VertexMarker("h", points_to="q1")]))
    assert not both(s.with_markers([VertexMarker("h", points_to="p1")]), s.with_markers([VertexMarker("h")]))
    # edge markers: place, head, count
    e1 = s.with_markers([EdgeMarker(("h", "r1"), head="r1")])
    assert not both(e1, s.with_markers([EdgeMarker(("h", "r1"), head="h")]))
    assert not both(e1, s.with_markers([EdgeMarker(("h", "r1"))]))
    assert not both(e1, s.with_markers([EdgeMarker(("h", "q1"), head="q1")]))
    assert not both(e1, s.with_markers([EdgeMarker(("h", "r1"), count=2, head="r1")]))
    assert both(e1, s.with_markers([EdgeMarker(("r1", "h"), head="r1")]))
    # in a symmetric world a directional marker may point anywhere
    c = g.cycle(5)
    assert both(c.with_markers([VertexMarker("0", points_to="1")]), c.with_markers([VertexMarker("3", points_to="2")]))


def test_different_sizes_are_reported():
    res = find_isomorphism(g.cycle(4), g.cycle(5))
    assert not res.isomorphic
    assert res.mismatch.where == "vertices" and res.mismatch.expected == "4" and res.mismatch.found == "5"
    assert not find_isomorphism_nx(g.cycle(4), g.cycle(5)).isomorphic
    assert not both(g.chain(4), g.lattice(2, 2))


# -- anchored ------------------------------------------------------------------------
def test_anchored_explains_a_degree_mismatch():
    a, b = g.wheel_pair()
    res = anchored(a, b, ("0", 0), ("1", 0))
    assert not res.isomorphic and res.witness is None
    m = res.mismatch
    assert m.check == "extended isomorphism"
    assert "'0'" in m.where
    assert m.expected == "degree 4 at its image '1'" and m.found == "degree 3"
    assert "expected" in str(m) and "found" in str(m)


def test_anchored_explains_a_rotation_mismatch():
    a, b = g.wheel_pair()
    res = anchored(a, b, ("0", 0), ("0", 0))
    assert not res.isomorphic
    m = res.mismatch
    assert m.check == "extended isomorphism"
    assert m.where.startswith("vertex '") and "exit" in m.where
    assert m.expected != m.found
    assert "leads to" in m.found
    assert res.mapped >= 2
    assert str(m).startswith(f"extended isomorphism violated at {m.where}: expected {m.expected}, found {m.found}")


def test_anchored_explains_a_marker_mismatch():
    s = World(SPIDER)
    res = anchored(s.with_markers([VertexMarker("h", points_to="p1")]),
                   s.with_markers([VertexMarker("h", points_to="q1")]), ("h", 0), ("h", 0))
    m = res.mismatch
    assert not res.isomorphic
    assert "'h'" in m.where and m.detail == "markers are not preserved"
    assert "pointing at exit 0" in m.expected and "pointing at exit 1" in m.found


def test_anchored_finds_the_witness_from_the_right_anchor():
    a = g.lattice(2, 3)
    b = rotated(relabelled(a, random.Random(1)), random.Random(2))
    res = find_isomorphism(a, b)
    v = "0,0"
    w, k = res.witness.image(a, (v, 0))
    again = anchored(a, b, (v, 0), (w, k))
    assert again.isomorphic and witness_ok(a, b, again.witness)
    assert again.witness.vertex_map == res.witness.vertex_map
    # the image of (v, 0) determines everything: other anchors at the same vertex fail or differ
    other = anchored(a, b, (v, 0), (w, (k + 1) % b.degree(w)))
    assert not other.isomorphic or other.witness.vertex_map != res.witness.vertex_map


# -- partial mode ------------------------------------------------------------------
def _partial_lattice():
    """The 2x3 lattice with the top row explored: S = 0,0 - 0,1 - 0,2 (map vertices 0, 1, 2)."""
    w = g.lattice(2, 3)
    S = PartialMap()
    for v in ("0,0", "0,1", "0,2"):
        S.add_vertex(w.degree(v))
    # use the world's own exit numbers (offset 0)
    S.add_edge((0, w.index("0,0", "0,1")), (1, w.index("0,1", "0,0")))
    S.add_edge((1, w.index("0,1", "0,2")), (2, w.index("0,2", "0,1")))
    return w, S


def test_partial_mode_embeds_the_explored_part():
    w, S = _partial_lattice()
    res = anchored(S, w, (0, 0), ("0,0", 0), partial=True)
    assert res.isomorphic
    assert res.witness.vertex_map == {0: "0,0", 1: "0,1", 2: "0,2"}
    assert res.witness.offsets == {0: 0, 1: 0, 2: 0}
    # not partial: the unexplored darts are reported
    full = anchored(S, w, (0, 0), ("0,0", 0))
    assert not full.isomorphic
    assert full.mismatch.found == "an unexplored dart" and full.mismatch.expected == "an explored edge"
    # anchored at the mirror corner it does not fit
    assert not anchored(S, w, (0, 0), ("0,2", 0), partial=True).isomorphic


def test_partial_mode_rejects_a_wrong_join():
    w = g.lattice(2, 3)
    S = PartialMap()
    for v in ("0,0", "0,1", "0,2"):
        S.add_vertex(w.degree(v))
    S.add_edge((0, w.index("0,0", "0,1")), (1, w.index("0,1", "0,0")))
    # the edge 0,1 - 0,2 joined at the wrong exit of 0,1 (the south exit instead of the east one)
    S.add_edge((1, w.index("0,1", "1,1")), (2, w.index("0,2", "0,1")))
    res = anchored(S, w, (0, 0), ("0,0", 0), partial=True)
    assert not res.isomorphic
    assert res.mismatch.check == "extended isomorphism" and "exit" in res.mismatch.where


def test_complete_map_is_isomorphic_to_its_world():
    w = g.lattice(2, 2)
    S = PartialMap()
    names = list(w.vertices)
    for v in names:
        S.add_vertex(w.degree(v))
    for u, v in w.edges():
        S.add_edge((names.index(u), w.index(u, v)), (names.index(v), w.index(v, u)))
    assert S.complete()
    assert both(S.to_world(), w)
    res = anchored(S, w, (0, 0), (names[0], 0))
    assert res.isomorphic and res.witness.vertex_map == dict(enumerate(names))
