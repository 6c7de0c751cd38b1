"""The proved lower bound on ``circulant:n=N,k=2``: each lemma's premise and conclusion checked on checked runs,
the bound against the runs at every n to 200, its closed form against the sum, and the bound without the
distance limit shown false (the limit is needed)."""

import networkx as nx
import pytest

from first_walk import new_edge_ends

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.run.explore import explore
from topomark.reference.worlds.expensive import circulant
from topomark.reference.worstcase.lower_bound import (circulant_bound, circulant_bound_formula, circulant_distances,
                                                      first_walk_bound)
from topomark.reference.worstcase.search import unchecked_run

CHECKED = range(5, 31)


def _world_distances(n):
    """D_k measured in the world: the distance of place n − 1 − k from 0, k = 1 … n − 2."""
    world = circulant(n, 2)
    graph = nx.Graph((v, w) for v in world.vertices for w in world.rotation[v])
    dist = nx.single_source_shortest_path_length(graph, "0")
    return [dist[str(n - 1 - k)] for k in range(1, n - 1)]


@pytest.mark.parametrize("n", range(5, 61))
def test_the_distances_of_the_proof_are_the_worlds(n):
    assert circulant_distances(n) == _world_distances(n)


def test_the_closed_form_is_the_sum_at_every_n_to_2000():
    assert all(circulant_bound(n) == circulant_bound_formula(n) for n in range(5, 2001))


@pytest.mark.parametrize("n", CHECKED)
def test_lemma_b_the_first_walk_discovers_n_minus_1_down_to_1_in_non_loop_iterations(n):
    """The checked run's first n − 1 iterations are non-loop, iteration k (from 0) tests 2(k − 1) hypotheses,
    and its new edge (replayed on the world by the spec's motion rule) reaches place n − 1 − k."""
    world = circulant(n, 2)
    out = explore(world, "basic")
    assert out.claimed == "correct" and out.violation is None
    rows = out.breakdown.rows()[1:n]
    assert [row[1] for row in rows] == ["non-loop"] * (n - 1)
    assert [row[2] for row in rows] == [max(0, 2 * (k - 1)) for k in range(n - 1)]
    assert new_edge_ends(world, out.trace)[:n - 1] == [str(n - 1 - k) for k in range(n - 1)]


@pytest.mark.parametrize("n", CHECKED)
def test_lemma_a_each_first_walk_iteration_costs_at_least_its_term(n):
    """Iteration k of the first walk (1 ≤ k ≤ n − 2) costs at least 1 + 4·Σ_{j<k} min(j, D_k) in the checked
    run's own breakdown."""
    out = explore(circulant(n, 2), "basic")
    rows = out.breakdown.rows()
    for k, d in enumerate(circulant_distances(n), start=1):
        assert sum(rows[k + 1][3:]) >= first_walk_bound([d] * k) - first_walk_bound([d] * (k - 1)), (n, k)
    assert out.cost >= circulant_bound(n)


@pytest.mark.parametrize("n", range(5, 201))
def test_every_run_to_n_200_costs_at_least_the_bound(n):
    claimed, cost, _ = unchecked_run(circulant(n, 2), algorithm_spec("basic"), True)
    assert claimed == "correct" and cost >= circulant_bound(n)


def test_without_the_distance_limit_the_bound_would_be_false():
    """Every hypothesis walked to the end of its path (min(j, D_k) replaced by j) would cost more than the first
    walk does at n = 5: some walks stop at v0 first, which is why Lemma A takes the world distance."""
    n = 5
    rows = explore(circulant(n, 2), "basic", record=False).breakdown.rows()
    walk = sum(sum(row[3:]) for row in rows[2:n])  # iterations k = 1 … n − 2
    assert first_walk_bound([n] * (n - 2)) > walk >= circulant_bound(n)


def test_the_bound_grows_as_five_twenty_fourths_of_n_cubed():
    assert abs(circulant_bound_formula(10_000) / 10_000**3 - 5 / 24) < 1e-3


@pytest.mark.parametrize("algorithm", ["enh1", "enh2", "enh3"])
@pytest.mark.parametrize("n", [12, 30])
def test_the_first_walk_costs_the_enhancements_at_most_4k_minus_3_an_iteration(algorithm, n):
    """Along the first walk every hypothesis's motions after the first are the same turn, so Enhancement-1's
    overlap (§4.1) walks them once: iteration k costs at most 4k − 3, where basic's costs up to 2k² − 2k + 1."""
    rows = explore(circulant(n, 2), algorithm).breakdown.rows()
    walk = rows[2:n]  # iterations k = 1 … n − 2
    assert [row[1] for row in walk] == ["non-loop"] * (n - 2)
    assert all(sum(row[3:]) <= 4 * k - 3 for k, row in enumerate(walk, start=1))
    basic = explore(circulant(n, 2), "basic", record=False).breakdown.rows()[2:n]
    assert any(sum(row[3:]) > 4 * k - 3 for k, row in enumerate(basic, start=1))
