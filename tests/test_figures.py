"""Tests of topomark.proofs.figures: the thesis's regression pairs reproduce their captions."""

from __future__ import annotations

import pytest

from topomark.proofs.bisim import bisimulation, check_relation, distinguishing_sequence, is_counterexample
from topomark.proofs.figures import (FIGURES, PRISM_MOTIONS, PRISM_PLANAR, PRISM_TWISTED, figure_3_3,
                                     figure_3_3_cycles, figure_3_4, figure_3_6, figure_3_21a, figure_3_21b,
                                     figure_6_1a, figure_6_1b, search_pairs)
from topomark.reference.worlds.generators import wheel_pair
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.robot import perceive, run
from topomark.spec.world import World

A4 = ["[3,A,A]"] * 4


def perceptions(world, motions):
    return [str(s) for s in perceive(world, world.start_state(), motions)]


def assert_counterexample(a, b):
    assert distinguishing_sequence(a, b) is None
    assert check_relation(a, b, bisimulation(a, b)) is None
    assert not find_isomorphism(a, b, markers=True).isomorphic
    assert is_counterexample(a, b)


def test_figure_3_3_cycles():
    cycles = figure_3_3_cycles()
    assert [w.n for w in cycles] == [3, 4, 5]
    assert figure_3_3() == cycles[:2]
    for i in range(3):
        for j in range(i + 1, 3):
            assert_counterexample(cycles[i], cycles[j])
    for w in cycles:
        assert perceptions(w, (1, 0, 1, 1, 0, 1)) == ["[2,A,A]"] * 6


@pytest.mark.parametrize("x", [0, 1, 2, 3])
def test_figure_3_4_caption(x):
    a, b = figure_3_4()
    expected = A4 + ["[4,V,A]"]
    assert perceptions(a, (x, 1, 2, 2, 1)) == expected == perceptions(b, (x, 1, 2, 2, 1))


def test_figure_3_4_pair():
    a, b = figure_3_4()
    assert (a.n, a.m, a.genus(), b.genus()) == (5, 8, 0, 1)
    assert_counterexample(a, b)
    assert (a, b) == wheel_pair()


def test_figure_3_6_caption():
    a, b = figure_3_6()
    motions = (0, 1, 2, 2, 1)
    # start faces the marker head
    assert a.start_state()[1] == a.vertex_mark(a.start.at).head
    ends = {perceptions(a, motions)[-1], perceptions(b, motions)[-1]}
    assert perceptions(a, motions)[:-1] == A4 == perceptions(b, motions)[:-1]
    assert ends == {"[4,V-1,A]", "[4,V-3,A]"}
    assert distinguishing_sequence(a, b) is not None and not is_counterexample(a, b)


def test_figure_3_21a_caption_and_pair():
    a, b = figure_3_21a()
    assert perceptions(a, PRISM_MOTIONS) == A4 + ["[3,V,A]"] == perceptions(b, PRISM_MOTIONS)
    assert_counterexample(a, b)
    # the thesis's [3,V-1,A]: the marked neighbour is exit 1 after the last motion, in both worlds
    for w in (a, b):
        v, entry = run(w, w.start_state(), PRISM_MOTIONS)[-1]
        marked = [k for k in range(w.degree(v)) if w.vertex_mark(w.neighbour(v, (entry + k) % w.degree(v)))]
        assert marked == [1]


def test_figure_3_21b_is_distinguishable():
    a, b = figure_3_21b()
    ends = {perceptions(a, PRISM_MOTIONS)[-1], perceptions(b, PRISM_MOTIONS)[-1]}
    assert ends == {"[3,V,A]", "[3,V2,A]"}
    assert not is_counterexample(a, b) and distinguishing_sequence(a, b) is not None


def test_figure_6_1a_caption_and_pair():
    a, b = figure_6_1a()
    assert perceptions(a, PRISM_MOTIONS) == A4 + ["[3,A,E-1]"] == perceptions(b, PRISM_MOTIONS)
    for w in (a, b):  # the robot starts at v0 facing the marked edge ("entered via the marked edge")
        assert w.start_state() == ("v0", w.index("v0", "v1"))
        assert w.dart_marks("v0")[0].exit == w.start_state()[1]
    assert_counterexample(a, b)


def test_figure_6_1b_caption():
    a, b = figure_6_1b()
    assert perceptions(a, PRISM_MOTIONS) == A4 + ["[3,A,E-1-H]"]
    assert perceptions(b, PRISM_MOTIONS) == A4 + ["[3,A,E-1-T]"]
    assert distinguishing_sequence(a, b) is not None and not is_counterexample(a, b)


def test_prisms_are_the_same_graph_with_different_embeddings():
    a, b = World(PRISM_PLANAR), World(PRISM_TWISTED)
    assert (a.genus(), b.genus()) == (0, 1)
    assert {frozenset(e) for e in a.edges()} == {frozenset(e) for e in b.edges()}
    assert not find_isomorphism(a, b, markers=False).isomorphic


@pytest.mark.parametrize("class_name,last,pair", [
    ("undirected-edge", "[3,A,E-1]", figure_6_1a),
    ("two-undirected-vertex", "[3,V,A]", figure_3_21a),
])
def test_reconstruction_is_unique_among_small_worlds(class_name, last, pair):
    found = list(search_pairs(class_name, 6, 3, PRISM_MOTIONS, A4 + [last], facing_marked=True))
    assert len(found) == 1
    a, b = pair()
    fa, fb = found[0]
    assert {find_isomorphism(fa, a).isomorphic, find_isomorphism(fa, b).isomorphic} == {True, False}
    assert {find_isomorphism(fb, a).isomorphic, find_isomorphism(fb, b).isomorphic} == {True, False}


def test_every_figure_is_registered():
    assert set(FIGURES) == {"3.3", "3.4", "3.6", "3.21a", "3.21b", "6.1a", "6.1b"}
    for make in FIGURES.values():
        a, b = make()
        assert a.start is not None and b.start is not None
