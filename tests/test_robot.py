"""Tests of topomark.spec.robot: motions and perception sequences (§3.1.1; Figures 3.4 and 3.6)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.reference.worlds import generators as g
from topomark.reference.worlds.strategies import worlds
from topomark.spec.errors import InvalidInput
from topomark.spec.marker import VertexMarker
from topomark.spec.robot import exit_of, perceive, run, sense, step
from topomark.spec.signature import signature_at
from topomark.spec.world import Start, World

FAST = settings(max_examples=60, deadline=None)


@st.composite
def world_and_state(draw, **kw):
    w = draw(worlds(**kw))
    v = draw(st.sampled_from(w.vertices))
    return w, (v, draw(st.integers(0, w.degree(v) - 1)))


@FAST
@given(world_and_state(max_vertices=8))
def test_motion_leaves_by_entry_plus_l(ws):
    w, (v, entry) = ws
    d = w.degree(v)
    for l in range(d):
        x = (entry + l) % d
        assert exit_of(w, (v, entry), l) == x
        u, j = step(w, (v, entry), l)
        assert u == w.rotation[v][x]                # the far end of exit x
        assert w.rotation[u][j] == v                # entered by the exit that leads back
        # l = 0 goes back the way it came: to v, entering by exit x again
        assert step(w, (u, j), 0) == (v, x)


@FAST
@given(world_and_state(max_vertices=8), st.lists(st.integers(0, 50), max_size=8))
def test_run_and_perceive(ws, raw):
    w, state = ws
    motions, states, s = [], [], state
    for r in raw:  # make each motion valid where it is taken
        l = r % w.degree(s[0])
        motions.append(l)
        s = step(w, s, l)
        states.append(s)
    assert run(w, state, motions) == states
    p = perceive(w, state, motions)
    assert len(p) == len(motions)   # the start vertex's signature is not part of P
    assert p == [sense(w, t) for t in states] == [signature_at(w, t[0], t[1]) for t in states]


def test_back_and_forth_on_a_path():
    w = World({"a": ["b"], "b": ["a", "c"], "c": ["b"]})
    assert step(w, ("a", 0), 0) == ("b", 0)
    assert step(w, ("b", 0), 1) == ("c", 0)
    assert step(w, ("b", 0), 0) == ("a", 0)
    assert run(w, ("a", 0), [0, 1, 0, 1]) == [("b", 0), ("c", 0), ("b", 1), ("a", 0)]


def test_perceive_excludes_the_start_signature():
    w = World({"a": ["b"], "b": ["a", "c"], "c": ["b"]}, [VertexMarker("a")])
    start = ("a", 0)
    assert str(sense(w, start)) == "[1,V,A]"
    assert perceive(w, start, []) == []
    assert [str(s) for s in perceive(w, start, [0])] == ["[2,A,A]"]
    assert [str(s) for s in perceive(w, start, [0, 0])] == ["[2,A,A]", "[1,V,A]"]


@pytest.mark.parametrize("motion", [2, 3, -1, 1.0, "1", None])
def test_invalid_motion_is_invalid_input(motion):
    w = World({"a": ["b", "c"], "b": ["a", "c"], "c": ["a", "b"]})
    with pytest.raises(InvalidInput) as info:
        step(w, ("a", 0), motion)
    assert "'a'" in str(info.value) and "degree 2" in str(info.value)
    with pytest.raises(InvalidInput):
        perceive(w, ("a", 0), [1, motion])


# -- Figure 3.4 / 3.6 -----------------------------------------------------------
@pytest.mark.parametrize("x", range(4))
def test_figure_3_4_wheels_perceive_alike(x):
    a, b = g.wheel_pair()
    expected = ["[3,A,A]"] * 4 + ["[4,V,A]"]
    for w in (a, b):
        assert [str(s) for s in perceive(w, w.start_state(), [x, 1, 2, 2, 1])] == expected
        # any facing at v0 gives the same sequence (both wheels are symmetric under rotating the corners)
        for corner in "1234":
            s = w.with_start(Start("0", corner)).start_state()
            assert [str(t) for t in perceive(w, s, [x, 1, 2, 2, 1])] == expected


def test_figure_3_4_wheels_differ_as_embeddings():
    a, b = g.wheel_pair()
    assert a.rotation["0"] == b.rotation["0"]
    assert all(a.rotation[c] != b.rotation[c] for c in "1234")
    assert (a.genus(), b.genus()) == (0, 1)


def test_figure_3_6_directional_marker_tells_them_apart():
    a, b = g.wheel_pair_directional()
    pa = [str(s) for s in perceive(a, a.start_state(), [0, 1, 2, 2, 1])]
    pb = [str(s) for s in perceive(b, b.start_state(), [0, 1, 2, 2, 1])]
    assert pa == ["[3,A,A]"] * 4 + ["[4,V-3,A]"]
    assert pb == ["[3,A,A]"] * 4 + ["[4,V-1,A]"]
    # §3.3 text: M = (0, 1, 1)
    assert [str(s) for s in perceive(a, a.start_state(), [0, 1, 1])] == ["[3,A,A]", "[3,A,A]", "[4,V-1,A]"]
    assert [str(s) for s in perceive(b, b.start_state(), [0, 1, 1])] == ["[3,A,A]", "[3,A,A]", "[4,V-3,A]"]


@pytest.mark.parametrize("head", "1234")
def test_figure_3_6_reading_does_not_depend_on_the_head_corner(head):
    a, b = g.wheel_pair_directional()
    readings = []
    for w in (a, b):
        w2 = w.with_markers([VertexMarker("0", points_to=head)], Start("0", head))
        readings.append(str(perceive(w2, w2.start_state(), [0, 1, 2, 2, 1])[-1]))
    assert readings == ["[4,V-3,A]", "[4,V-1,A]"]
