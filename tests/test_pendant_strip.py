"""The pendant strip (§4.1–4.3, §7.2): its structure at every size, the walk the docstring describes on a checked
run, and the documented costs of the Chapter 4 enhancements, whose cost / bound rises with n there (the compiled
engine, cross-checked against the reference at n = 50)."""

from __future__ import annotations

from fractions import Fraction

import networkx as nx
import pytest

from conftest import needs_engine

from topomark.spec.errors import InvalidInput
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.run.explore import explore
from topomark.reference.worlds import pendant
from topomark.reference.worlds.generators import generate
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.worstcase.family_costs import PENDANT_ALGORITHMS as ENHANCEMENTS
from topomark.reference.worstcase.family_costs import PENDANT_COSTS as DOCUMENTED
from topomark.reference.worstcase.family_costs import pendant_ratios
from topomark.reference.worstcase.search import unchecked_run


def _check_structure(w, n):
    j = pendant.stem_length(n)
    assert (w.n, w.m) == (n, j + j // 2 + 2 * (n - 1 - j) + 1) and (n - 1 - j) % 2 == 0
    assert j == 9 * n // 25 + (n - 1 - 9 * n // 25) % 2
    chords = {i for i in range(j + 1) if (j - i) % 2 == 0}  # the places of J's parity: degree 4 but at the ends
    assert {int(v) for v in w.vertices if w.degree(v) == 4} == set(range(j + 1, n)) | chords - {0, 1, j - 1}
    for v in w.vertices:  # a rotation system: each neighbour once, every edge seen from both ends
        assert len(set(w.rotation[v])) == w.degree(v) and v not in w.rotation[v]
        assert all(v in w.rotation[u] for u in w.rotation[v])
    assert nx.is_connected(nx.Graph((u, x) for u in w.vertices for x in w.rotation[u]))
    for i in range(2, j):  # the stem: the first walk's next place follows the one it came from
        assert w.rotation[str(i)][:2] == (str(i - 1), str(i + 1))
    assert w.rotation[str(j)] == tuple(map(str, (j - 1, j - 2, j + 1, n - 1)))  # J: exit 1 closes the first loop
    assert (w.start.at, w.start.facing) == ("0", "1")


@pytest.mark.parametrize("n", [pendant.PENDANT_FROM, 14, 20, 21, 50, 99, 100, 200])
def test_structure_at_each_size(n):
    _check_structure(generate("pendant-strip", n=n), n)


def test_the_structure_check_catches_a_stem_walked_the_other_way():
    """The seeded fault of the check above: a stem whose places list i + 1 before i − 1 fails it."""
    w = generate("pendant-strip", n=30)
    rot = {v: list(ns) for v, ns in w.rotation.items()}
    rot["4"][0], rot["4"][1] = rot["4"][1], rot["4"][0]
    from topomark.spec.world import World
    with pytest.raises(AssertionError):
        _check_structure(World(rot, (), w.start), 30)


def test_refuses_sizes_below_the_smallest_closed_strip():
    with pytest.raises(InvalidInput, match="n must be >= 13, got 12"):
        generate("pendant-strip", n=pendant.PENDANT_FROM - 1)


def test_the_walk_the_docstring_describes_on_a_checked_run():
    """The first walk runs up the stem and closes its first loop at J; the stem's chords come next; the robot
    enters the pendant last, and there each non-loop iteration walks every open exit's path to within one motion
    of its end, each path parting from the others where it turns off the walk."""
    n = 60
    j = pendant.stem_length(n)
    out = explore(generate("pendant-strip", n=n), "enh1", record=True)
    assert out.verified and out.claimed == "correct"
    its = [r for r in out.trace if r["event"] == "iteration"]
    assert [r["augmentation"] for r in its[:j]] == ["non-loop"] * j and its[j]["augmentation"] == "loop"
    into = next(k for k, r in enumerate(its) if k > j and r["augmentation"] == "non-loop")
    assert all(r["augmentation"] == "loop" for r in its[j:into]) and into - j == j // 2  # the first loop, the other chords
    pendant_walk = [r for r in its[into:] if r["augmentation"] == "non-loop"]
    for r in pendant_walk[len(pendant_walk) // 2:]:
        long = [h for h in r["hypotheses"] if len(h["motions"]) > j // 2]
        assert len(long) > n // 4 and all(len(h["perceived"]) >= len(h["motions"]) - 1 for h in long)
        tails = {tuple(h["motions"][1:]) for h in long}  # a place's two open exits differ in their first motion only
        assert len(tails) * 2 >= len(long)


@pytest.mark.parametrize("algorithm", ENHANCEMENTS)
def test_engine_and_reference_agree_at_n_50(algorithm):
    from topomark.reference.engine import available
    w = generate("pendant-strip", n=50)
    checked = explore(w, algorithm, record=False)
    assert checked.verified and checked.cost == DOCUMENTED[50][ENHANCEMENTS.index(algorithm)]
    if available():
        assert unchecked_run(w, algorithm_spec(algorithm), True)[:2] == ("correct", checked.cost)


def _rises(ratios: list[Fraction]) -> bool:
    return all(a < b for a, b in zip(ratios, ratios[1:]))


def test_the_documented_costs_and_that_cost_over_bound_rises_with_n():
    needs_engine("run n = 300 quickly")
    for n, documented in DOCUMENTED.items():
        w = generate("pendant-strip", n=n)
        for algorithm, cost in zip(ENHANCEMENTS, documented):
            assert unchecked_run(w, algorithm_spec(algorithm), True)[:2] == ("correct", cost), (n, algorithm)
    for algorithm in ENHANCEMENTS:
        assert _rises([r for _, r in pendant_ratios(algorithm)]), algorithm
    # the seeded fault: on the rewired strip, the costliest family for them before, enh1's cost / bound falls
    rewired = {}
    for n in (100, 200):
        w = generate("rewired-strip", n=n)
        rewired[n] = Fraction(unchecked_run(w, algorithm_spec("enh1"), True)[1], upper_bound(n, w.m))
    assert not _rises([rewired[100], rewired[200]])


def test_the_report_states_what_the_pendant_strip_shows_and_only_while_it_rises(monkeypatch):
    from topomark.reference.worstcase import family_costs
    from topomark.reference.worstcase.verdicts import pendant_statement, verdicts
    shown, says = pendant_statement("enh2")
    assert "0.0412, 0.0498, 0.0571, 0.0594, 0.0606, 0.0618 at n = 20, 50, 100, 150, 200, 300" in shown
    assert "tight up to a constant factor" in says and pendant_statement("basic") is None
    run = {"algorithm": "enh2", "max_degree": 4, "per_n": []}
    assert "`pendant-strip:n=N`" in verdicts([], [run])[0]
    # the seeded fault: a size where cost / bound falls takes the statement away
    monkeypatch.setattr(family_costs, "PENDANT_COSTS", {**family_costs.PENDANT_COSTS, 300: (1, 1, 1)})
    assert pendant_statement("enh2") is None
