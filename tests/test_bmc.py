"""Breadth-first distinguishing sequences agree with Z3 bounded model checking (issue 4)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.proofs import figures
from topomark.proofs.bisim import distinguishing_sequence
from topomark.proofs.bmc import shortest_by_bmc
from topomark.reference.worlds.strategies import worlds
from topomark.spec.robot import perceive


def _product_size(a, b) -> int:
    return sum(a.degree(v) for v in a.vertices) * sum(b.degree(v) for v in b.vertices)


def _agree(a, b):
    bfs = distinguishing_sequence(a, b)
    if bfs is not None and not bfs.motions:
        return  # the start signatures differ: nothing for a motion sequence to show
    bound = len(bfs.motions) if bfs is not None else min(_product_size(a, b), 7)
    bmc = shortest_by_bmc(a, b, bound)
    if bfs is None:
        assert bmc is None
    else:
        assert bmc is not None and len(bmc) == len(bfs.motions)
        pa, pb = perceive(a, a.start_state(), bmc), perceive(b, b.start_state(), bmc)
        assert pa[:-1] == pb[:-1] and pa[-1] != pb[-1]


@pytest.mark.slow
@pytest.mark.parametrize("pair", ["figure_3_3", "figure_3_4", "figure_3_6", "figure_3_21a", "figure_6_1a",
                                  "figure_6_1b"])
def test_thesis_pairs(pair):
    a, b = getattr(figures, pair)()
    _agree(a, b)


@settings(max_examples=40, deadline=None)
@given(worlds(max_vertices=5, max_degree=3, markers="directional-vertex", with_start=True),
       worlds(max_vertices=5, max_degree=3, markers="directional-vertex", with_start=True))
def test_random_pairs(a, b):
    _agree(a, b)


@settings(max_examples=20, deadline=None)
@given(worlds(max_vertices=4, max_degree=3, with_start=True), st.integers(0, 3))
def test_unmarked_pairs_with_a_short_bound(a, k):
    """Without markers many pairs are indistinguishable for long; BMC must then find nothing short either."""
    bfs = distinguishing_sequence(a, a)
    assert bfs is None and shortest_by_bmc(a, a, k) is None
