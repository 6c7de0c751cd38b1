"""The world families that make Algorithm 3.1 expensive (§3.5.2, §7.2): their sizes, degrees and starts, and the
strip's exact cost formula checked against runs."""

from __future__ import annotations

import pytest

from conftest import needs_engine

from topomark.spec.errors import InvalidInput
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate
from topomark.reference.worstcase.family_costs import STRIP_FROM, strip_cost

CASES = [  # generator, parameters, n, m
    ("strip", {"n": 5}, 5, 7), ("strip", {"n": 13}, 13, 23), ("strip", {"n": 40}, 40, 77),
    ("strip", {"n": 8, "cap": 1}, 8, 16), ("strip", {"n": 30, "cap": 1}, 30, 60),
    ("circulant", {"n": 11, "k": 2}, 11, 22), ("circulant", {"n": 30, "k": 7}, 30, 60),
    ("k5e-chain", {"gadgets": 1}, 5, 9), ("k5e-chain", {"gadgets": 6}, 30, 59),
    ("cylinder", {"rings": 2, "size": 3}, 6, 9), ("cylinder", {"rings": 7, "size": 4}, 28, 52),
]


@pytest.mark.parametrize("name,params,n,m", CASES)
def test_sizes_degrees_and_start(name, params, n, m):
    w = generate(name, **params)
    assert (w.n, w.m) == (n, m)
    degrees = [w.degree(v) for v in w.vertices]
    assert max(degrees) <= 4 and min(degrees) >= 2
    assert w.start_state()[0] == "0"  # the start, and so the marker, at an end (place 0)
    for v in w.vertices:  # a rotation system: each neighbour once, every edge seen from both ends
        assert len(set(w.rotation[v])) == len(w.rotation[v]) and v not in w.rotation[v]
        assert all(v in w.rotation[u] for u in w.rotation[v])


def test_the_strip_is_the_square_of_a_path_and_the_robot_walks_it_end_to_end():
    w = generate("strip", n=12)
    import networkx as nx
    square = nx.power(nx.path_graph(12), 2)
    graph = nx.Graph((u, x) for u in w.vertices for x in w.rotation[u])
    assert nx.is_isomorphic(graph, square)
    o = explore(w, "basic", record=False)
    first = [it.kind for it in o.explorer.iterations[:11]]
    assert first == ["non-loop"] * 11  # S is the path 0, 1, ..., 11 before any loop is closed


def test_the_capped_strip_is_4_regular_and_costs_more_than_the_strip():
    w = generate("strip", n=20, cap=1)
    assert {w.degree(v) for v in w.vertices} == {4}
    capped, plain = (explore(generate("strip", n=20, cap=c), "basic", record=False) for c in (1, 0))
    assert capped.verified and capped.cost > plain.cost


def test_circulant_and_the_other_families_refuse_impossible_parameters():
    for name, params in [("strip", {"n": 9, "cap": 1}), ("strip", {"n": 6, "cap": 1}), ("strip", {"n": 10, "cap": 2}),
                         ("circulant", {"n": 10, "k": 5}), ("circulant", {"n": 10, "k": 1}), ("strip", {"n": 4}),
                         ("k5e-chain", {"gadgets": 0}), ("cylinder", {"rings": 1, "size": 4})]:
        with pytest.raises(InvalidInput):
            generate(name, **params)


@pytest.mark.parametrize("n", [STRIP_FROM + 2, STRIP_FROM + 7])
def test_strip_cost_formula_matches_a_checked_run(n):
    o = explore(generate("strip", n=n), "basic", record=False)
    assert o.verified and o.cost == strip_cost(n)


def test_strip_cost_formula_refuses_sizes_it_was_not_measured_for():
    with pytest.raises(InvalidInput):
        strip_cost(STRIP_FROM - 1)


def _engine_cost(world):
    from topomark.proofs.world_arrays import to_arrays
    from topomark.reference.engine.runs import run_starts
    at, entry = world.start_state()
    run = run_starts(to_arrays(world), [(world.vertices.index(at), entry)], ("nearest", "fifo", "shortest"))[0]
    assert run.claimed == "correct"
    return run.cost


def _needs_engine():
    needs_engine("run every size")


def test_strip_cost_formula_holds_at_every_size_it_was_measured_for():
    _needs_engine()
    assert [n for n in range(STRIP_FROM, 61) if _engine_cost(generate("strip", n=n)) != strip_cost(n)] == []


@pytest.mark.slow
def test_strip_cost_formula_holds_past_its_measured_sizes_up_to_200():
    _needs_engine()
    assert [n for n in range(61, 201) if _engine_cost(generate("strip", n=n)) != strip_cost(n)] == []
