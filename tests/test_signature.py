"""Tests of topomark.spec.signature: thesis notation (§3.1.1, Figure 3.2; §6.1) and directional reading."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.reference.worlds.strategies import worlds
from topomark.spec.errors import InvalidInput
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.signature import Signature, depends_on_entry, signature_at
from topomark.spec.world import World

FAST = settings(max_examples=80, deadline=None)


# -- rendering ------------------------------------------------------------------
@pytest.mark.parametrize("sig, text", [
    (Signature(3), "[3,A,A]"),
    (Signature(4, vertex_count=1, vertex_direction=1), "[4,V-1,A]"),
    (Signature(4, vertex_count=1), "[4,V,A]"),
    (Signature(4, vertex_count=1, vertex_direction=0), "[4,V-0,A]"),
    (Signature(3, edges=((1, 1, "H"),)), "[3,A,E-1-H]"),
    (Signature(2, vertex_count=2), "[2,V2,A]"),
    (Signature(5, vertex_count=2, vertex_direction=3), "[5,V2-3,A]"),
    (Signature(4, 1, 1, ((1, 1, "H"), (3, 1, "T"))), "[4,V-1,E-1-H,E-3-T]"),
    (Signature(3, edges=((1, 1, None),)), "[3,A,E-1]"),
    (Signature(3, edges=((0, 2, None), (2, 3, "T"))), "[3,A,E2-0,E3-2-T]"),
])
def test_thesis_notation(sig, text):
    assert str(sig) == text
    assert repr(sig) == text
    assert Signature.parse(text) == sig
    assert sig.marked == (text != f"[{sig.degree},A,A]")


def test_figure_3_2_signatures_sensed_in_a_world():
    # a degree-4 vertex "c" entered via its exit 0 (from "n"), as in Figure 3.2
    rot = {"c": ["n", "e", "s", "w"], "n": ["c"], "e": ["c"], "s": ["c"], "w": ["c"]}
    assert str(signature_at(World(rot), "c", 0)) == "[4,A,A]"
    assert str(signature_at(World(rot, [VertexMarker("c")]), "c", 0)) == "[4,V,A]"
    assert str(signature_at(World(rot, [VertexMarker("c", points_to="s")]), "c", 0)) == "[4,V-2,A]"
    # entered from "e" (exit 1) the same marker is two exits further... and "s" is 1 to the left
    assert str(signature_at(World(rot, [VertexMarker("c", points_to="s")]), "c", 1)) == "[4,V-1,A]"
    assert str(signature_at(World(rot, [VertexMarker("c", points_to="n")]), "c", 1)) == "[4,V-3,A]"
    two = World(rot, [VertexMarker("c", count=2)])
    assert str(signature_at(two, "c", 3)) == "[4,V2,A]"
    # edge markers (§6.1): a directional marker on c-e with head at c, one on c-w with head at w
    edged = World(rot, [VertexMarker("c", points_to="e"), EdgeMarker(("c", "e"), head="c"),
                        EdgeMarker(("w", "c"), head="w")])
    assert str(signature_at(edged, "c", 0)) == "[4,V-1,E-1-H,E-3-T]"
    assert str(signature_at(edged, "e", 0)) == "[1,A,E-0-T]"
    assert str(signature_at(edged, "w", 0)) == "[1,A,E-0-H]"
    assert str(signature_at(World(rot, [EdgeMarker(("c", "s"))]), "c", 1)) == "[4,A,E-1]"


# -- parsing --------------------------------------------------------------------
@st.composite
def signatures(draw):
    d = draw(st.integers(1, 9))
    count = draw(st.integers(0, 3))
    direction = draw(st.none() | st.integers(0, d - 1)) if count else None
    positions = draw(st.lists(st.integers(0, d - 1), unique=True, max_size=d))
    edges = tuple(sorted((p, draw(st.integers(1, 3)), draw(st.sampled_from((None, "H", "T")))) for p in positions))
    return Signature(d, count, direction, edges)


@FAST
@given(signatures())
def test_parse_round_trips(sig):
    text = str(sig)
    assert Signature.parse(text) == sig
    assert str(Signature.parse(text)) == text
    assert Signature.parse(" " + text.replace(",", ", ") + " ") == sig


@pytest.mark.parametrize("text", [
    "", "[]", "3,A,A", "[3,A,A", "3,A,A]", "[3,A]", "[x,A,A]", "[-1,A,A]", "[3,B,A]", "[3,V-,A]", "[3,V-x,A]",
    "[3,A,E]", "[3,A,E-]", "[3,A,E-1-X]", "[3,A,E-1-H-T]", "[3,A,E-1,A]", "[3,A,A,A]", "[3,A,]",
    "[3,V1,A]",        # not canonical: one marker is written V
    "[3,V0,A]",        # zero markers is A
    "[4,A,E-3,E-1]",   # edge items out of order
    "[3,A,E1-1]",      # one edge marker is E, not E1
    "[03,A,A]",
    "[0,A,A]",         # no vertex has degree 0
    "[3,V-3,A]",       # direction must be an exit of the vertex
    "[2,A,E-2]",       # edge marker on a non-existent exit
    "[3,A,E-1,E2-1]",  # two entries for one exit
])
def test_parse_rejects_malformed_text(text):
    with pytest.raises(InvalidInput):
        Signature.parse(text)


# -- directional reading (§3.1.1) ----------------------------------------------
@FAST
@given(worlds(max_vertices=8, markers="directional-vertex"))
def test_directional_vertex_marker_reads_relative_to_entry(w):
    (marker,) = w.markers
    v = marker.at
    d = w.degree(v)
    h = w.rotation[v].index(marker.points_to)
    for j in range(d):
        sig = signature_at(w, v, j)
        assert sig.degree == d and sig.vertex_count == 1
        assert sig.vertex_direction == (h - j) % d
        assert str(sig) == f"[{d},V-{(h - j) % d},A]"
        # counting (h - j) mod d exits clockwise from the entry reaches the head
        assert w.rotation[v][(j + sig.vertex_direction) % d] == marker.points_to
    for u in w.vertices:
        if u != v:
            for j in range(w.degree(u)):
                assert str(signature_at(w, u, j)) == f"[{w.degree(u)},A,A]"


@FAST
@given(worlds(max_vertices=7, markers="any"), st.data())
def test_signature_read_from_the_marker_list(w, data):
    """Every vertex, every entry: the signature equals one computed from ``world.markers`` by hand."""
    for v in w.vertices:
        d = w.degree(v)
        j = data.draw(st.integers(0, d - 1))
        vms = [m for m in w.markers if isinstance(m, VertexMarker) and m.at == v]
        count = sum(m.count for m in vms)
        direction = None
        if vms and vms[0].points_to is not None:
            direction = (w.rotation[v].index(vms[0].points_to) - j) % d
        edges = []
        for m in w.markers:
            if isinstance(m, EdgeMarker) and v in m.between:
                other = m.between[1] if m.between[0] == v else m.between[0]
                x = w.rotation[v].index(other)
                end = None if m.head is None else ("H" if m.head == v else "T")
                edges.append(((x - j) % d, m.count, end))
        expected = Signature(d, count, direction, tuple(sorted(edges)))
        got = signature_at(w, v, j)
        assert got == expected
        assert Signature.parse(str(got)) == got


def test_edge_marker_head_and_tail():
    # square a-b-c-d; a directional edge marker on a-b pointing at b
    rot = {"a": ["b", "d"], "b": ["c", "a"], "c": ["d", "b"], "d": ["a", "c"]}
    w = World(rot, [EdgeMarker(("a", "b"), head="b")])
    assert str(signature_at(w, "b", 0)) == "[2,A,E-1-H]"   # marked exit 1, entered by exit 0
    assert str(signature_at(w, "b", 1)) == "[2,A,E-0-H]"
    assert str(signature_at(w, "a", 0)) == "[2,A,E-0-T]"
    assert str(signature_at(w, "a", 1)) == "[2,A,E-1-T]"
    assert str(signature_at(w, "c", 0)) == "[2,A,A]"
    w2 = World(rot, [EdgeMarker(("b", "a"), count=2)])
    assert str(signature_at(w2, "a", 1)) == "[2,A,E2-1]"
    assert str(signature_at(w2, "b", 1)) == "[2,A,E2-0]"


@FAST
@given(worlds(max_vertices=7, markers="any"))
def test_depends_on_entry_exactly_when_some_entry_reads_differently(w):
    """Explorers may compare a vertex's signature once when it does not depend on the entry."""
    for v in w.vertices:
        readings = {signature_at(w, v, j) for j in range(w.degree(v))}
        mark = w.vertex_mark(v)
        if not depends_on_entry(w, v):
            assert len(readings) == 1
        elif mark is not None and mark.head is not None and not w.dart_marks(v):
            assert len(readings) == w.degree(v)  # V-0 .. V-(d-1), one per entry


def test_back_link_table_states_the_lighthouse_condition():
    """§3.2.2: a directional marker gives one signature per entry; an undirected one gives one for all."""
    from topomark.spec.marker import VertexMarker
    from topomark.spec.signature import back_link_table
    from topomark.spec.world import World
    rot = {"a": ["b", "c", "d"], "b": ["a", "c"], "c": ["a", "b", "d"], "d": ["a", "c"]}
    table, bad = back_link_table(World(rot, [VertexMarker("a", points_to="b")]), "a", "v0")
    assert bad is None and sorted(table.values()) == [0, 1, 2]
    table, bad = back_link_table(World(rot, [VertexMarker("a")]), "a", "v0")
    assert len(table) == 1 and bad.check == "lighthouse" and "back-link" in bad.detail
