"""The adversarial worst-case search (§7.2): its moves keep worlds valid, it is reproducible, what it
reports is what a run of the world it reports costs, and its bad inputs are refused by name."""

from __future__ import annotations

import math
import random

import networkx as nx
import pytest

from topomark.reference.run.explore import explore
from topomark.reference.worlds.deterministic import lattice_graph
from topomark.reference.worstcase.fit import fit_exponents
from topomark.reference.worstcase.moves import (
    MOVES, LatticeHoles, graph_of, move_lattice, move_world, random_lattice, random_world)
from topomark.reference.worstcase.search import adversarial_search, random_baseline
from topomark.spec.errors import InvalidInput
from topomark.spec.world import World


def _assert_valid(w: World, n: int, max_degree: int) -> None:
    assert sorted(w.vertices, key=int) == [str(v) for v in range(n)]
    assert all(1 <= w.degree(v) <= max_degree for v in w.vertices)
    assert nx.is_connected(graph_of(w))
    assert w.start is not None and w.start.facing in w.rotation[w.start.at]


def _cyclic(ns: tuple[str, ...]) -> tuple[str, ...]:
    k = ns.index(min(ns))
    return ns[k:] + ns[:k]


@pytest.mark.parametrize("max_degree", [2, 3, 5])
def test_random_worlds_are_connected_with_degrees_at_most_d(max_degree):
    rng = random.Random(7)
    for _ in range(100):
        _assert_valid(random_world(8, max_degree, rng), 8, max_degree)


@pytest.mark.slow
@pytest.mark.parametrize("kind", MOVES)
def test_every_move_keeps_the_world_valid_and_does_what_it_says(kind):
    rng = random.Random(11)
    w = random_world(8, 3, rng)
    for _ in range(300):
        before, edges = w, set(map(frozenset, w.edges()))
        w = move_world(w, 3, rng, kinds=(kind,))
        _assert_valid(w, 8, 3)
        after = set(map(frozenset, w.edges()))
        changed = [v for v in w.vertices if _cyclic(w.rotation[v]) != _cyclic(before.rotation[v])]
        if kind == "rotation" and any(before.degree(v) >= 3 for v in before.vertices):
            assert after == edges and len(changed) == 1
        elif kind == "add-edge" and after != edges:
            assert edges < after and len(after - edges) == 1
        elif kind == "remove-edge" and after != edges:
            assert after < edges and len(edges - after) == 1
        elif kind == "start":
            assert w.rotation == before.rotation


def test_mixed_moves_reach_every_kind_and_stay_valid():
    rng = random.Random(3)
    w = random_world(8, 3, rng)
    ms = set()
    for _ in range(500):
        w = move_world(w, 3, rng)
        _assert_valid(w, 8, 3)
        ms.add(w.m)
    assert len(ms) >= 3  # edges came and went


def test_lattice_moves_keep_a_connected_lattice_minus_its_holes():
    rng = random.Random(5)
    cand = random_lattice(5, 6, rng)
    full, _ = lattice_graph(5, 6)
    toggled = set()
    for _ in range(300):
        before = cand.holes
        cand = move_lattice(cand, rng)
        assert len(cand.holes ^ before) <= 1
        toggled |= cand.holes ^ before
        w = cand.world
        cells = {f"{r},{c}" for r, c in full.nodes if (r, c) not in cand.holes}
        assert set(w.vertices) == cells and set(cand.hole_names()).isdisjoint(cells)
        want = {frozenset((f"{a[0]},{a[1]}", f"{b[0]},{b[1]}")) for a, b in full.edges
                if a not in cand.holes and b not in cand.holes}
        assert set(map(frozenset, w.edges())) == want
        assert w.start.facing in w.rotation[w.start.at]
    assert len(toggled) > 5


def test_the_same_seed_gives_the_same_best_world_and_cost():
    def run(seed):
        return adversarial_search("basic", n=8, max_degree=3, evaluations=40, seed=seed).to_json()
    first = run(4)
    assert run(4) == first
    assert first["best"]["world"]["format"] == "topomark/world@1"


def test_the_search_leaves_the_global_random_state_alone():
    state = random.getstate()
    adversarial_search("basic", n=6, max_degree=3, evaluations=10, seed=1, baseline=False)
    assert random.getstate() == state


@pytest.mark.parametrize("algorithm,objective", [("basic", "cost"), ("enh3", "cost-per-m"), ("case-1a", "ratio"),
                                                 ("case-3a", "cost")])
def test_the_best_found_is_what_its_world_costs_and_never_below_the_first(algorithm, objective):
    seen = []
    r = adversarial_search(algorithm, n=8, max_degree=3, objective=objective, evaluations=19, seed=2,
                           progress=lambda k, s: seen.append((k, s)))
    assert r.evaluations == 19 and r.failures == 0 and r.random.failures == 0
    scores = [s for _, s in r.history]
    assert [k for k, _ in r.history] == list(range(1, 20)) and seen == r.history
    assert scores == sorted(scores) and r.best.score == scores[-1] >= scores[0]
    out = explore(r.best.world, algorithm, check=False, record=False)
    assert out.cost == r.best.cost
    j = r.to_json()["best"]
    _assert_valid(r.best.world, 8, 3)
    assert j["cost_per_m"] == round(out.cost / r.best.world.m, 3)
    assert j["diameter"] == nx.diameter(graph_of(r.best.world))
    if objective == "ratio":
        assert math.isclose(r.best.score, j["ratio_to_bound"], abs_tol=1e-6)


def test_runs_that_do_not_end_correct_are_counted_and_never_best():
    # a lighthouse needing a start of degree >= 2: on paths and cycles (D = 2) some starts are refused
    r = random_baseline("basic", n=6, max_degree=2, evaluations=40, seed=0, lighthouse="three-undirected-edge")
    assert 0 < r.failures < 40
    assert r.best.world.degree(r.best.world.start.at) >= 2


def test_ratio_is_refused_for_an_algorithm_with_no_exact_bound():
    with pytest.raises(InvalidInput, match="ratio needs an exact cost bound.*enh4"):
        adversarial_search("enh4", n=6, max_degree=3, objective="ratio", evaluations=5)


@pytest.mark.parametrize("kwargs,message", [
    ({"n": 2}, "n must be >= 3"), ({"max_degree": 1}, "max_degree must be >= 2"),
    ({"algorithm": "nope"}, "unknown algorithm 'nope'"), ({"objective": "speed"}, "unknown objective 'speed'"),
    ({"family": "torus"}, "unknown family 'torus'"), ({"evaluations": 0}, "evaluations must be >= 1"),
    ({"algorithm": "case-1a", "lighthouse": "directional-vertex"}, "takes no lighthouse"),
    ({"family": "lattice-hole", "max_degree": 3}, "max_degree must be >= 4"),
])
def test_bad_input_is_refused_by_name(kwargs, message):
    args = {"algorithm": "basic", "n": 6, "max_degree": 4, "evaluations": 3, **kwargs}
    with pytest.raises(InvalidInput, match=message):
        adversarial_search(**args)


def test_the_lattice_hole_family_reports_its_hole_pattern():
    r = adversarial_search("basic", n=25, max_degree=4, evaluations=12, seed=1, family="lattice-hole")
    j = r.to_json()
    assert j["family"] == "lattice-hole" and set(j["best"]["world"]["rotation"]).isdisjoint(j["best"]["holes"])
    assert j["best"]["n"] + len(j["best"]["holes"]) == 25
    assert explore(r.best.world, "basic", check=False, record=False).cost == j["best"]["cost"]


def test_fit_exponents_recovers_known_exponents():
    rows = [{"n": n, "m": m, "diameter": d, "max_degree": k, "cost": 5 * d**3}
            for n, m, d, k in ((10, 12, 2, 3), (20, 30, 3, 3), (40, 70, 5, 4), (80, 90, 9, 4))]
    fit = fit_exponents(rows)
    assert fit["diameter"] == {"exponent": 3.0, "r2": 1.0, "ci95": [3.0, 3.0]}
    assert fit["m"]["r2"] < 1.0 and fit["rows"] == 4
    lo, hi = fit["m"]["ci95"]
    assert lo < fit["m"]["exponent"] < hi
    rows = [{**row, "cost": 0.5 * row["m"] ** 1.5 * row["n"] ** 0.5} for row in rows]
    assert fit_exponents(rows)["m_n"] == {"c": 0.5, "a": 1.5, "b": 0.5, "r2": 1.0}


def test_the_exponents_confidence_interval_is_students_t_on_the_slopes_standard_error():
    """Points (0, 0), (1, 1), (2, 1), (3, 2) in log-log: slope 0.6, residual variance 0.1, Sxx 5, so the
    interval is 0.6 ± t(0.975, 2)·√(0.1/5) = 0.6 ± 4.303·0.141421."""
    import math
    rows = [{"n": 2, "m": math.e ** x, "diameter": 1, "max_degree": 2, "cost": math.e ** y}
            for x, y in ((0, 0), (1, 1), (2, 1), (3, 2))]
    got = fit_exponents(rows)["m"]
    half = 4.303 * math.sqrt(0.1 / 5)
    assert got["exponent"] == pytest.approx(0.6) and got["ci95"] == pytest.approx([0.6 - half, 0.6 + half], abs=1e-6)


def test_fit_exponents_refuses_a_row_without_a_positive_cost():
    with pytest.raises(InvalidInput, match="row 1 needs a positive number 'cost'"):
        fit_exponents([{"n": 3, "m": 3, "diameter": 1, "max_degree": 2, "cost": 4},
                       {"n": 4, "m": 4, "diameter": 2, "max_degree": 2, "cost": 0}])


def test_a_lattice_candidate_is_immutable_and_equal_by_value():
    a = LatticeHoles(3, 3, frozenset({(1, 1)}), ((0, 0), (0, 1)))
    b = LatticeHoles(3, 3, frozenset({(1, 1)}), ((0, 0), (0, 1)))
    assert a == b and a.world == b.world and a.world.n == 8
