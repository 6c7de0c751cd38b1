"""The searches that serve the edge policy and the walks (reference/explorers/policies.py) against a whole breadth-first
search, and edgeINFO's matching entries against their definition, on partial maps part-way explored.

The shortcuts (a search stopped at the nearest end in U, or at the walk's target; entries anchored at the first
relative direction sensed) must choose the same edge, walk the same path and keep the same candidates as the
whole computation: the §6.2 traces depend on it.
"""

import random

import pytest

from topomark.reference.explorers.edge_info import matching_darts
from topomark.reference.explorers.policies import (Policies, bfs, bfs_preorder, in_preorder, open_ends_beyond,
                                         parents_toward)
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature, signature_at
from topomark.spec.world import DartMark

from conftest import make_world

WORLDS = [make_world(text) for text in ("lattice-hole:rows=5,cols=6,seed=2", "complete-hole:n=8,seed=1",
                                         "random:n=12,fraction=0.3,seed=4")]


def partial_map(world, rng: random.Random, fraction: float) -> PartialMap:
    """S part-way explored: the world's vertices (in a breadth-first order from its start), a spanning tree's
    edges and about ``fraction`` of the rest; U the open darts, shuffled."""
    start = world.start_state()[0]
    order, number = [start], {start: 0}
    S = PartialMap()
    S.add_vertex(world.degree(start))
    edges, k = [], 0
    while k < len(order):
        x = order[k]
        for i in range(world.degree(x)):
            y, j = world.target((x, i))
            if y not in number:
                number[y] = len(order)
                order.append(y)
                S.add_vertex(world.degree(y))
                S.add_edge((number[x], i), (number[y], j))
            elif (y, j) > (x, i):
                edges.append(((number[x], i), (number[y], j)))
        k += 1
    for a, b in edges:
        if rng.random() < fraction and S.arc(a) is None and S.arc(b) is None:
            S.add_edge(a, b)
    S.unexplored.extend(S.open_darts())
    rng.shuffle(S.unexplored)
    return S


def maps():
    rng = random.Random(7)
    for world in WORLDS:
        for fraction in (0.0, 0.3, 0.7, 0.95):
            for _ in range(3):
                yield partial_map(world, rng, fraction), rng


@pytest.mark.parametrize("edge", ["nearest", "fifo", "lifo"])
def test_next_edge_chooses_and_walks_as_a_whole_search(edge):
    policy, runs = Policies(edge=edge), 0
    for S, rng in maps():
        if not S.unexplored:
            continue
        root = rng.randrange(S.n)
        dist, _, parent = bfs(S, root)
        whole = list(S.unexplored)
        expected = policy.choose_edge(S, dist)
        S.unexplored[:] = whole
        edge_, some_parent = policy.next_edge(S, root)
        assert edge_ == expected and S.unexplored == [d for d in whole if d != expected]
        x = expected[0]
        while x != root:  # the walk to the chosen end uses bfs's parents all the way
            assert some_parent[x] == parent[x]
            x = parent[x][0]
        runs += 1
    assert runs > 20


def test_next_edge_searches_no_further_than_the_nearest_end():
    S, _ = next(maps())
    root = S.unexplored[0][0]
    first = S.unexplored[0]
    assert Policies().next_edge(S, root) == (first, {})


def test_candidates_in_preorder_are_the_preorder_filtered():
    for S, rng in maps():
        root = rng.randrange(S.n)
        chosen = set(rng.sample(range(S.n), rng.choice((rng.randint(0, min(4, S.n)), rng.randint(0, S.n)))))
        assert in_preorder(S, root, chosen) == [v for v in bfs_preorder(S, root) if v in chosen]
        near = {root} | {t[0] for t in S.links(root) if t is not None}
        assert open_ends_beyond(S, root) == {v for v, _ in S.unexplored} - near


def test_parents_toward_are_the_whole_searchs_parents_on_the_path():
    for S, rng in maps():
        for _ in range(10):
            root, target = rng.randrange(S.n), rng.randrange(S.n)
            S._bfs_memo = None  # the search, not the kept one
            parent, whole = parents_toward(S, root, target), bfs(S, root)[2]
            x = target
            while x != root:
                assert parent[x] == whole[x]
                x = parent[x][0]
            assert parents_toward(S, root, target) is whole  # now kept: the same search is reused


def marked(S: PartialMap, rng: random.Random) -> PartialMap:
    """Random edge marks (counts 1–2, ends H/T/None) and directional or plain vertex marks on S."""
    for v in S.vertices:
        for i in rng.sample(range(S.degree(v)), rng.randint(0, S.degree(v))):
            S.mark_dart(v, DartMark(i, rng.choice((1, 1, 2)), rng.choice((None, "H", "T"))))
        if rng.random() < 0.4:
            S.mark_vertex(v, 1, rng.choice((None, rng.randrange(S.degree(v)))))
    return S


def test_matching_darts_are_the_entries_that_read_what_was_sensed():
    """The anchored shortcut gives exactly [j in exits | signature_at(S, w, j) == sensed]."""
    hits = 0
    for S, rng in maps():
        S = marked(S, rng)
        for _ in range(30):
            w, v = rng.randrange(S.n), rng.randrange(S.n)
            sensed = signature_at(S, v, rng.randrange(S.degree(v)))
            if rng.random() < 0.2:
                sensed = Signature(sensed.degree, sensed.vertex_count, sensed.vertex_direction)
            exits = list(range(S.degree(w)))
            expected = [j for j in exits if signature_at(S, w, j) == sensed]
            assert matching_darts(S, w, sensed, exits) == expected
            hits += bool(expected)
    assert hits > 50


def test_reads_as_is_the_signature_comparison_asked_per_dart():
    """spec.signature.reads_as (the hypotheses' filter) against signature_at compared afresh at every dart."""
    from topomark.spec.signature import reads_as
    hits = 0
    for S, rng in maps():
        S = marked(S, rng)
        v = rng.randrange(S.n)
        sensed = signature_at(S, v, rng.randrange(S.degree(v)))
        reads = reads_as(S, sensed)
        for w in S.vertices:
            for j in range(S.degree(w)):
                expected = S.degree(w) == sensed.degree and signature_at(S, w, j) == sensed
                assert reads(w, j) == expected
                hits += expected
    assert hits > 20


def test_joined_is_links_without_the_open_exits():
    """The searches read S.joined(v); it must be S.links(v)'s explored exits with their neighbours, in exit
    order, however S was built (edges added in any order) and in a copy of S."""
    for S, _ in maps():
        for T in (S, S.copy()):
            for v in T.vertices:
                assert T.joined(v) == [(i, t[0]) for i, t in enumerate(T.links(v)) if t is not None]
