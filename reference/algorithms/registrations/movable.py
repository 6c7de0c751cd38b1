"""Registrations of the single movable marker algorithms of §2.3.1: Dudek et al. [24, 26] and the directional
variant [27] (explorers in :mod:`topomark.reference.explorers.movable_marker`).

Both carry one vertex marker that may be picked up (``Kit(vertex=1, movable=True)``, directional for the
variant), so the marker bound is 1 on every world.  The thesis states the cost bound O(mn) (§2.3.1: "the main
cost ... is $O(mn) \\leq O(n^3)$"; §2.3.1 for the directional variant: "still $O(mn)$ but the constant is
expected to be reduced") with no constant; :func:`dudek_bound` and :func:`directional_bound` are **ours**:
exact worst-case bounds of our explorers, derived per step with n_s ≤ n known vertices (distances in S are
at most n_s − 1; a vertex of a simple graph has at most n − 1 exits, one of them explored once it is a
candidate):

* walk S to v_k ≤ n − 1, follow e 1, come back over e 1;
* place validation: the candidates in the preorder of a breadth-first tree rooted at v_k, each by a shortest
  path of S (never longer than the tree path), so the walk from v_k through them *and back to v_k* is at
  most the tree's Euler tour, 2(n_s − 1);
* non-loop (n − 1 steps, n_s ≤ n − 1): that walk back to v_k and over e once more to fetch the marker —
  in all ≤ (n_s − 1) + 2 + 2(n_s − 1) + 1 = 3n_s ≤ 3n − 3 (a step with no candidate costs ≤ n_s);
* loop (m − n + 1 steps, n_s ≤ n): the search stops at v_k', ≤ 2(n − 1); directional ≤ 3n − 1 (nothing
  more); undirected adds the back-link search, to v_k and back ≤ 2(n − 1), and at most n − 2 unexplored
  exits at v_k' tried (out and back, the last only out) ≤ 2n − 5 — in all ≤ 7n − 8.

Examples
--------
>>> dudek_bound(2, 1), directional_bound(2, 1)  # one edge: no loop step; the single non-loop step costs 1
(3, 3)
>>> dudek_bound(16, 24) <= 8 * 16 * 24 and directional_bound(16, 24) <= 4 * 16 * 24
True
"""

from __future__ import annotations

from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import STEPWISE_MAP_CHECKS, AlgorithmSpec
from topomark.reference.explorers.movable_marker import (DirectionalMovableMarkerExplorer,
                                                          ListingDirectionalMovableMarkerExplorer,
                                                          ListingMovableMarkerExplorer, MovableMarkerExplorer)

__all__ = ["SPECS", "dudek_bound", "directional_bound", "dudek_listing_bound", "directional_listing_bound"]


def dudek_bound(n: int, m: int) -> int:
    """Our exact worst-case cost of ``dudek`` (module docstring): 3(n − 1)² + (m − n + 1)(7n − 8)."""
    return 3 * (n - 1) ** 2 + (m - n + 1) * (7 * n - 8)


def directional_bound(n: int, m: int) -> int:
    """Our exact worst-case cost of ``dudek-directional``: 3(n − 1)² + (m − n + 1)(3n − 1)."""
    return 3 * (n - 1) ** 2 + (m - n + 1) * (3 * n - 1)


def dudek_listing_bound(n: int, m: int) -> int:
    """Topomark's bound for §2.3.1's description as written (``dudek-listing``; ``docs/bounds.md``):
    3n(n − 1)/2 + (m − n + 1)(6n − 7)."""
    return 3 * n * (n - 1) // 2 + (m - n + 1) * (6 * n - 7)


def directional_listing_bound(n: int, m: int) -> int:
    """Topomark's bound for the directional variant as written (``dudek-directional-listing``;
    ``docs/bounds.md``): 3n(n − 1)/2 + (m − n + 1)(3n − 3)."""
    return 3 * n * (n - 1) // 2 + (m - n + 1) * (3 * n - 3)


_OPTIONS = ("policy edge=nearest|fifo|lifo",)
_BOUND = "O(mn) (§2.3.1); bound_fn: ours, exact for our explorer"
_OURS = "ours: our explorer's exact worst case behind O(mn) (§2.3.1)"
_BOUND_LISTING = "O(mn) (§2.3.1); bound_fn: topomark's, for the description as written"
_LISTING = ("topomark's worst case of §2.3.1's description as written (docs/bounds.md), behind O(mn) "
            "(§2.3.1)")
SEARCH = ("§2.3.1 gives no listing (Dudek et al.'s is in [24, 26]) and says the robot searches \"visiting known "
          "vertices in S\": this explorer visits only those that can be v_u (its degree, an unexplored edge, neither "
          "v_k nor a neighbour of v_k) and looks at every vertex it passes on the way")
"""What topomark's movable-marker search changes relative to the thesis's description (``changes``)."""

SPECS = (
    AlgorithmSpec(name="dudek", thesis="§2.3.1, Dudek et al. [24, 26]", kit=Kit(vertex=1, movable=True),
                  bound=_BOUND, markers="1", deterministic=True, options=_OPTIONS, checks=STEPWISE_MAP_CHECKS,
                  bound_fn=dudek_bound, bound_formula=f"3(n − 1)² + (m − n + 1)(7n − 8), {_OURS}",
                  explorer=MovableMarkerExplorer, uses_lighthouse=False,
                  marker_bound_fn=lambda n, m: 1, family="robot", ways=("correct", "marker-moved"),
                  changes=f"{SEARCH}; it drops nothing where no known vertex can be v_u, and where v_k' has a "
                          "single unexplored exit that exit is e', with no back-link search",
                  listing_entry="dudek-listing"),
    AlgorithmSpec(name="dudek-listing", thesis="§2.3.1, Dudek et al. [24, 26], as written",
                  kit=Kit(vertex=1, movable=True), bound=_BOUND_LISTING, markers="1", deterministic=True,
                  options=_OPTIONS, checks=STEPWISE_MAP_CHECKS, bound_fn=dudek_listing_bound,
                  bound_source="listing", bound_formula=f"3n(n − 1)/2 + (m − n + 1)(6n − 7), {_LISTING}",
                  explorer=ListingMovableMarkerExplorer, uses_lighthouse=False, marker_bound_fn=lambda n, m: 1,
                  family="robot", ways=("correct", "marker-moved")),
    AlgorithmSpec(name="dudek-directional", thesis="§2.3.1, Dudek et al. [24, 26]; directional variant [27]",
                  kit=Kit(vertex=1, directional=True, movable=True), bound=_BOUND, markers="1", deterministic=True,
                  options=_OPTIONS, checks=STEPWISE_MAP_CHECKS, bound_fn=directional_bound,
                  bound_formula=f"3(n − 1)² + (m − n + 1)(3n − 1), {_OURS}",
                  explorer=DirectionalMovableMarkerExplorer, uses_lighthouse=False, marker_bound_fn=lambda n, m: 1,
                  family="robot", changes=f"{SEARCH}; it drops nothing where no known vertex can be v_u",
                  listing_entry="dudek-directional-listing", ways=("correct", "marker-moved")),
    AlgorithmSpec(name="dudek-directional-listing",
                  thesis="§2.3.1, Dudek et al. [24, 26]; directional variant [27] (§6.3.1), as written",
                  kit=Kit(vertex=1, directional=True, movable=True), bound=_BOUND_LISTING, markers="1",
                  deterministic=True, options=_OPTIONS, checks=STEPWISE_MAP_CHECKS, bound_fn=directional_listing_bound,
                  bound_source="listing", bound_formula=f"3n(n − 1)/2 + (m − n + 1)(3n − 3), {_LISTING}",
                  explorer=ListingDirectionalMovableMarkerExplorer, uses_lighthouse=False,
                  marker_bound_fn=lambda n, m: 1, family="robot", ways=("correct", "marker-moved")),
)
