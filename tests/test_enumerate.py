"""Tests of topomark.proofs.enumerate: small worlds up to extended isomorphism (§3.1.1, §3.1.3)."""

from __future__ import annotations

import itertools
import math

import networkx as nx
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.proofs import graphs
from topomark.proofs.enumerate import (MAX_VERTICES, graph_automorphisms, _image, _orbit_representatives, world_of_rotation,
                                       canonical_form, connected_graphs, count_by_size, embedded_worlds,
                                       rotation_systems)
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.reference.worlds.strategies import relabelled, rotated, worlds
from topomark.spec.errors import InvalidInput
from topomark.spec.isomorphism import anchored, find_isomorphism
from topomark.spec.world import World

FAST = settings(max_examples=60, deadline=None)


def brute_force_classes(ws: list[World], markers: bool = False) -> list[World]:
    """One representative per extended-isomorphism class, by pairwise find_isomorphism."""
    reps: list[World] = []
    for w in ws:
        if not any(find_isomorphism(w, r, markers=markers).isomorphic for r in reps):
            reps.append(w)
    return reps


def all_rotation_systems(n: int, max_degree: int) -> list[World]:
    return [world_of_rotation(r) for g in connected_graphs(n, max_degree) for r in rotation_systems(g)]


def mirror(world: World) -> World:
    return World({v: list(reversed(ns)) for v, ns in world.rotation.items()}, world.markers, world.start)


# -- graphs --------------------------------------------------------------------------
def test_connected_graph_counts_match_published_figures():
    # A001349: connected graphs on n nodes; connected graphs with max degree <= 3: Wolfram, NKS (2002),
    # notes to ch. 9 sec. 7 "Trivalent networks" (see topomark.proofs.graphs)
    assert [len(connected_graphs(n, n - 1)) for n in range(2, 8)] == [1, 2, 6, 21, 112, 853]
    assert [len(connected_graphs(n, 3)) for n in range(2, 10)] == [1, 2, 6, 10, 29, 64, 194, 531]


def test_graphs_past_the_atlas_come_from_augmentation():
    ours = connected_graphs(8, 3)
    assert [sorted(g.edges) for g in ours] == [sorted(g.edges) for g in graphs.generate(8, 3)]
    assert all(nx.is_connected(g) and max(d for _, d in g.degree()) <= 3 for g in ours)


def test_orbit_representatives_are_the_least_of_their_orbits():
    """Memory-free choice of representative == the first of every orbit in product order (a seen-set)."""
    for g in connected_graphs(5, 4) + connected_graphs(6, 3):
        autos = graph_automorphisms(g)
        seen, expected = set(), []
        for rot in rotation_systems(g):
            if rot not in seen:
                seen |= {_image(rot, sigma) for sigma in autos}
                expected.append(rot)
        assert list(_orbit_representatives(g)) == expected


def test_rotation_system_count_is_product_of_factorials():
    for g in connected_graphs(5, 4):
        expected = math.prod(math.factorial(g.degree(v) - 1) for v in g)
        assert sum(1 for _ in rotation_systems(g)) == expected


# -- embedded worlds -------------------------------------------------------------------
@pytest.mark.parametrize("n,max_degree", [(2, 1), (3, 2), (4, 3), (4, 2), (5, 3)])
def test_enumeration_matches_brute_force_dedup(n, max_degree):
    everything = all_rotation_systems(n, max_degree)
    reps = brute_force_classes(everything)
    ours = list(embedded_worlds(n, max_degree, min_vertices=n))
    assert len(ours) == len(reps)
    # pairwise non-isomorphic, and every rotation system is isomorphic to one of ours
    assert len({canonical_form(w) for w in ours}) == len(ours)
    assert {canonical_form(w) for w in everything} == {canonical_form(w) for w in ours}


def test_counts_per_size():
    assert count_by_size(6, 3) == {2: 1, 3: 2, 4: 9, 5: 22, 6: 95}
    assert count_by_size(5, 4) == {2: 1, 3: 2, 4: 9, 5: 275}
    assert count_by_size(5, 2) == {2: 1, 3: 2, 4: 2, 5: 2}  # paths and cycles


def test_canonical_form_dedup_of_all_rotation_systems_n6_degree3():
    everything = all_rotation_systems(6, 3)
    assert len({canonical_form(w) for w in everything}) == 95


def test_enumeration_is_deterministic_and_validated():
    a = [w.rotation for w in embedded_worlds(5, 3)]
    b = [w.rotation for w in embedded_worlds(5, 3)]
    assert a == b
    with pytest.raises(InvalidInput):
        list(embedded_worlds(MAX_VERTICES + 1, 3))
    with pytest.raises(InvalidInput):
        list(embedded_worlds(4, 0))


# -- canonical form ----------------------------------------------------------------------
@FAST
@given(worlds(2, 7, max_degree=4, markers="any", with_start=False),
       st.randoms(use_true_random=False))
def test_canonical_form_is_invariant_under_relabelling(world, rng):
    copy = rotated(relabelled(world, rng), rng)
    assert canonical_form(copy) == canonical_form(world)
    assert canonical_form(copy, markers=False) == canonical_form(world, markers=False)


@FAST
@given(worlds(2, 7, max_degree=4, markers="any", with_start=True), st.randoms(use_true_random=False))
def test_canonical_form_with_start_is_invariant_under_relabelling(world, rng):
    assert canonical_form(rotated(relabelled(world, rng), rng)) == canonical_form(world)


def test_canonical_form_agrees_with_find_isomorphism_on_marked_placements():
    for cls in ("undirected-vertex", "directional-vertex", "undirected-edge", "directional-edge",
                "two-undirected-vertex"):
        marked = {}
        for w in embedded_worlds(4, 3, min_vertices=4):
            for p in MARKER_CLASSES[cls].placements(w):
                marked[canonical_form(p.with_start(None))] = p.with_start(None)
        placed = [p.with_start(None) for w in embedded_worlds(4, 3, min_vertices=4)
                  for p in MARKER_CLASSES[cls].placements(w)]
        reps = brute_force_classes(placed, markers=True)
        assert len(reps) == len(marked), cls


def test_canonical_form_with_start_agrees_with_anchored_isomorphism():
    placed = [p for w in embedded_worlds(4, 3, min_vertices=4)
              for p in MARKER_CLASSES["undirected-vertex"].placements(w)]
    for a, b in itertools.combinations(placed[:60], 2):
        same = anchored(a, b, a.start_state(), b.start_state(), markers=True).isomorphic
        assert (canonical_form(a) == canonical_form(b)) == same


def test_mirror_images_differ_unless_isomorphic():
    seen_chiral = 0
    for w in embedded_worlds(5, 3):
        m = mirror(w)
        iso = find_isomorphism(w, m, markers=False).isomorphic
        assert (canonical_form(w) == canonical_form(m)) == iso
        seen_chiral += not iso
    assert seen_chiral > 0


def test_start_is_part_of_the_code():
    w = next(iter(embedded_worlds(2, 1)))
    p = next(MARKER_CLASSES["none"].placements(w))
    assert canonical_form(p) != canonical_form(p.with_start(None))
