"""The rewired strip (§3.5.2, §7.2): its structure at every size, that at n = 100 it differs from the closed strip
only where the search rewired it, and that it costs ``basic`` more than the closed strip (a checked run, and the
compiled engine cross-checked against it)."""

from __future__ import annotations

import networkx as nx
import pytest

from conftest import needs_engine

from topomark.spec.errors import InvalidInput
from topomark.reference.run.explore import explore
from topomark.reference.worlds import rewired
from topomark.reference.worlds.generators import generate
from topomark.reference.worlds.worst_cases import worst_case_world


def _graph(world):
    return nx.Graph((u, x) for u in world.vertices for x in world.rotation[u])


def _edges(world):
    return {frozenset((u, x)) for u in world.vertices for x in world.rotation[u]}


def _check_structure(w, n):
    assert (w.n, w.m) == (n, 2 * n)
    assert {w.degree(v) for v in w.vertices} == {4}
    for v in w.vertices:  # a rotation system: each neighbour once, every edge seen from both ends
        assert len(set(w.rotation[v])) == 4 and v not in w.rotation[v]
        assert all(v in w.rotation[u] for u in w.rotation[v])
    assert nx.is_connected(_graph(w))
    assert (w.start.at, w.start.facing) == ("0", "1")


@pytest.mark.parametrize("n", [rewired.REWIRED_FROM, 60, 100, 102, 200])
def test_4_regular_connected_and_started_at_place_0(n):
    _check_structure(generate("rewired-strip", n=n), n)


def test_the_structure_check_catches_a_world_not_4_regular():
    """The seeded fault of the check above: the open strip (degrees 2 to 4, m = 2n − 3) must fail it."""
    with pytest.raises(AssertionError):
        _check_structure(generate("strip", n=60), 60)


def test_at_n_100_only_the_rewired_places_differ_from_the_closed_strip():
    w, closed = generate("rewired-strip", n=100), generate("strip", n=100, cap=1)
    differ = {int(v) for v in w.vertices if w.rotation[v] != closed.rotation[v]}
    assert differ == set(rewired.REWIRING)
    assert len(_edges(w) ^ _edges(closed)) == 30  # fifteen edges moved
    searched = worst_case_world("basic-n100-d4-search")  # the world the rewiring was read from
    assert _edges(w) == _edges(searched)


def test_a_place_moved_with_the_wrong_anchor_breaks_the_world(monkeypatch):
    """The seeded fault: the places round the fold must keep their distance from the middle, not their number."""
    monkeypatch.setattr(rewired, "_moved", lambda x, n: x if x < 75 else x + n - rewired.FOUND_AT)
    assert generate("rewired-strip", n=100).m == 200  # at the size it was found nothing moves
    with pytest.raises(InvalidInput):
        rewired.rewired_strip(200)


def test_refuses_odd_and_small_sizes():
    for n in (rewired.REWIRED_FROM - 2, 101):
        with pytest.raises(InvalidInput):
            generate("rewired-strip", n=n)


def test_costs_basic_more_than_the_closed_strip_engine_and_reference_agree():
    from topomark.proofs.world_arrays import to_arrays
    from topomark.reference.engine import available
    from topomark.reference.engine.runs import run_starts
    w, closed = generate("rewired-strip", n=60), generate("strip", n=60, cap=1)
    checked = explore(w, "basic", record=False)
    assert checked.verified and checked.cost == 199110
    assert checked.cost > explore(closed, "basic", record=False).cost == 179739
    if available():
        at, entry = w.start_state()
        run = run_starts(to_arrays(w), [(w.vertices.index(at), entry)], ("nearest", "fifo", "shortest"))[0]
        assert (run.claimed, run.cost) == ("correct", checked.cost)


DOCUMENTED = {46: 79635, 100: 996034, 150: 3368015, 200: 7899490}  # docs/worst-case/families.md


def test_the_documented_costs_and_that_they_beat_the_strip():
    from fractions import Fraction
    from topomark.proofs.world_arrays import to_arrays
    from topomark.reference.algorithms.bounds import upper_bound
    from topomark.reference.engine.runs import run_starts
    from topomark.reference.worstcase.family_costs import strip_cost
    needs_engine("run n = 200 quickly")
    for n, documented in DOCUMENTED.items():
        w = generate("rewired-strip", n=n)
        at, entry = w.start_state()
        run = run_starts(to_arrays(w), [(w.vertices.index(at), entry)], ("nearest", "fifo", "shortest"))[0]
        assert (run.claimed, run.cost) == ("correct", documented), n
        assert Fraction(run.cost, upper_bound(n, 2 * n)) > Fraction(strip_cost(n), upper_bound(n, 2 * n - 3)), n
    closed = generate("strip", n=100, cap=1)  # the seeded fault: without the rewiring the comparison fails
    at, entry = closed.start_state()
    run = run_starts(to_arrays(closed), [(closed.vertices.index(at), entry)], ("nearest", "fifo", "shortest"))[0]
    assert not Fraction(run.cost, upper_bound(100, 200)) > Fraction(strip_cost(100), upper_bound(100, 197))
