"""Z3 and the exhaustive census agree on existence at every size both cover (issue 4).

The census enumerates every embedded world up to N vertices and maximum degree D
with every placement of a class's markers and every start, and groups them by
the robot's minimised language; Z3 searches the same space symbolically.  For
each marker class and bound both cover here, a counterexample exists by one
method iff it exists by the other, and the smallest pairs have the same larger
world size.
"""

from __future__ import annotations

import pytest

from topomark.proofs.bisim import is_counterexample
from topomark.proofs.census import census
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.proofs.z3search import search

BOUNDS = [(3, 2), (4, 3), (4, 4), (5, 3)]


@pytest.mark.slow
@pytest.mark.parametrize("name", list(MARKER_CLASSES))
@pytest.mark.parametrize("n, d", BOUNDS)
def test_z3_and_census_agree(name, n, d):
    by_census = census(name, n, d).smallest_counterexample
    by_z3 = search(name, n, d)
    assert by_z3.outcome in ("found", "none")
    assert (by_census is not None) == (by_z3.outcome == "found"), (name, n, d)
    if by_census is not None:
        assert is_counterexample(*by_census) and is_counterexample(*by_z3.worlds)
        assert max(w.n for w in by_census) == max(w.n for w in by_z3.worlds)


@pytest.mark.slow
def test_they_agree_where_two_undirected_markers_first_fail():
    """Two undirected vertex markers: no counterexample below 5 vertices; one at 5 with degree 4."""
    assert census("two-undirected-vertex", 4, 4).smallest_counterexample is None
    assert search("two-undirected-vertex", 4, 4).outcome == "none"
    found = census("two-undirected-vertex", 5, 4).smallest_counterexample
    z3 = search("two-undirected-vertex", 5, 4, min_vertices=5)
    assert found is not None and z3.outcome == "found"
    assert {w.n for w in found} == {w.n for w in z3.worlds} == {5}
