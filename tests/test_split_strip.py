"""The split strip (§6.2.1, §7.2): what it is, that the footprint searches of Cases 1a and 4 cost exactly
:func:`~topomark.reference.worstcase.family_costs.split_strip_cost` on it, and that their cost / bound rises
with n towards 5/16 — their O(mn) bound tight up to that constant."""

from __future__ import annotations

from fractions import Fraction

import pytest

from topomark.spec.errors import InvalidInput
from topomark.reference.algorithms.registrations.markers_621 import footprints_bound
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate
from topomark.reference.worlds.split_strip import SPLIT_FROM, split_place
from topomark.reference.worstcase.family_costs import SPLIT_STRIP_FROM, split_strip_cost

ALGORITHMS = ("case-1a", "case-4")


def _edges(world):
    return {frozenset(edge) for edge in world.edges()}


@pytest.mark.parametrize("n", [SPLIT_FROM, 50, 100])
def test_it_is_the_closed_strip_less_three_edges_with_one_place_turned(n):
    w, closed = generate("split-strip", n=n), generate("strip", n=n, cap=1)
    half, k = n // 2, split_place(n)
    gone = {frozenset(map(str, e)) for e in ((0, half - 1), (k, k + 1), (k, n - 1 - k))}
    assert _edges(closed) - _edges(w) == gone and _edges(w) <= _edges(closed)
    assert (w.n, w.m, w.start_state()) == (n, 2 * n - 3, ("0", 0))
    assert w.rotation[str(n - 1)] == tuple(map(str, (half, half - 1, n - 2, 0)))
    turned = [v for v in w.vertices if v not in {str(n - 1)} and
              [x for x in closed.rotation[v] if frozenset((v, x)) not in gone] != list(w.rotation[v])]
    assert turned == []  # every other place keeps the closed strip's clockwise order


def test_it_refuses_odd_and_small_sizes():
    for n in (SPLIT_FROM - 2, 51):
        with pytest.raises(InvalidInput):
            generate("split-strip", n=n)
    with pytest.raises(InvalidInput):
        split_strip_cost(SPLIT_STRIP_FROM - 2)
    with pytest.raises(InvalidInput):
        split_strip_cost(51)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_the_cost_formula_matches_a_checked_run(algorithm):
    o = explore(generate("split-strip", n=42), algorithm, record=False)
    assert o.verified and o.cost == split_strip_cost(42) == 1883  # (5·42² − 31·42 + 14) / 4


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_the_cost_formula_holds_at_every_size_to_100_and_cost_over_bound_rises(algorithm):
    ratios = []
    for n in range(SPLIT_STRIP_FROM, 101, 2):
        o = explore(generate("split-strip", n=n), algorithm, check=False, record=False)
        assert (o.claimed, o.cost) == ("correct", split_strip_cost(n)), n
        assert o.upper_bound == footprints_bound(n, 2 * n - 3) == 4 * n * n - 9 * n + 3
        ratios.append(Fraction(o.cost, o.upper_bound))
    assert all(a < b for a, b in zip(ratios, ratios[1:])) and ratios[-1] < Fraction(5, 16)


def test_it_costs_cases_1a_and_4_more_than_the_closed_strip_from_the_least_size():
    for n in (SPLIT_STRIP_FROM, 50, 100):
        for algorithm in ALGORITHMS:
            closed = explore(generate("strip", n=n, cap=1), algorithm, check=False, record=False)
            split = explore(generate("split-strip", n=n), algorithm, check=False, record=False)
            assert Fraction(split.cost, split.upper_bound) > Fraction(closed.cost, closed.upper_bound), (n, algorithm)


@pytest.mark.slow
def test_the_cost_formula_holds_past_100_up_to_300():
    """The reference at both ends; the compiled engine, which agrees with it run for run, at every even n between
    (the reference where the engine is not installed)."""
    from topomark.reference.algorithms.registry import algorithm_spec
    from topomark.reference.engine import available
    from topomark.reference.worstcase.search import unchecked_run
    for n in range(102, 301, 2):
        _, cost, _ = unchecked_run(generate("split-strip", n=n), algorithm_spec("case-4"),
                                   available() and n not in (102, 300))
        assert cost == split_strip_cost(n), n
