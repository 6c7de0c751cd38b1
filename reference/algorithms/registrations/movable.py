"""Registrations of the single movable marker algorithms of §2.3.1: Dudek et al. [24, 26] and the directional
variant [27] (explorers in :mod:`topomark.reference.explorers.movable_marker`).

Each carries one vertex marker that may be picked up (``Kit(vertex=1, movable=True)``, directional for the
variant), so the marker bound is 1 on every world.  Each is registered twice: topomark's explorer (``dudek``,
``dudek-directional``), which searches only the known vertices that can be v_u, and §2.3.1's description as
written (``dudek-listing``, ``dudek-directional-listing``), which visits every known vertex of S, drops the
marker at every v_u and, undirected, makes the back-link search at every loop step (the explorer module
says what the text leaves open and how it is decided).  Replay's re-run accepts a trace of either under
either name and says which it followed; each has its own conformance suite.

The thesis states the cost bound O(mn) (§2.3.1: "the main cost ... is $O(mn) \\leq O(n^3)$"; for the
directional variant "still $O(mn)$ but the constant is expected to be reduced") with no constant.
:func:`dudek_listing_bound` and :func:`directional_listing_bound` are **topomark's bounds for the
description as written** (``docs/bounds.md``), derived per step with n_s known vertices (distances in S
are at most n_s − 1; a vertex of a simple graph has at most n − 1 exits):

* walk S to v_k by a shortest path ≤ n_s − 1, follow e 1, come back over e 1 (every step of the
  description drops the marker at v_u; topomark's explorer skips all three where no known vertex can be
  v_u, and costs ≤ n_s then);
* place validation: the vertices searched (all of S, or topomark's candidates: a subsequence) in the
  preorder of a breadth-first tree rooted at v_k, each by a shortest path of S (never longer than the tree
  path), so the walk from v_k through them *and back to v_k* is at most the tree's Euler tour, 2(n_s − 1);
* non-loop step (n − 1 of them, the k-th with n_s = k): that walk, back to v_k, and over e once more to
  fetch the marker: ≤ (n_s − 1) + 2 + 2(n_s − 1) + 1 = 3n_s, in all ≤ 3(1 + … + (n − 1)) = 3n(n − 1)/2;
* loop step (m − n + 1 of them, n_s ≤ n): the search stops at v_k' = v_u, at distance d ≥ 2 from v_k (no
  self-loop, no multi-edge), and the rest of the closed walk would lead back to v_k: the search is
  ≤ 2(n − 1) − d.  Directional: nothing more, ≤ (n − 1) + 2 + 2(n − 1) − 2 = 3n − 3.  Undirected: the
  back-link search carries the marker to v_k and comes back, 2d, and tries at most n − 2 unexplored exits
  of v_k' (at least one of its exits is explored), out and back, the one that finds the marker only out:
  ≤ 2n − 5; with d ≤ n − 1, in all ≤ (n − 1) + 2 + 2(n − 1) + (n − 1) + 2n − 5 = 6n − 7.

Every bound above holds whatever edge the policy takes next and whatever order the back-link search tries
the exits in, and for every search that is a closed walk of a spanning tree of S; it holds topomark's
explorers too (their searches are subsequences of the same walk, and they only leave moves out).  So the
improved entries are held to the same bounds, which are bounds of the description (``bound_source``
``listing``: a cost above them fails a conformance client).  On every embedded world of up to five
vertices and degree four, from every start and under every edge policy, each listing entry stays within
its bound and reaches it (on trees), and topomark's explorer never costs more than the listing
(``tests/test_listing_dudek.py``).

:func:`directional_bound` is the bound of the carried l = ε thread (``thread-carried``, §6.3.1), which is
the directional explorer with a thread for a marker.

Examples
--------
>>> dudek_listing_bound(2, 1), directional_listing_bound(2, 1)  # one edge: drop, come back, fetch the marker
(3, 3)
>>> dudek_listing_bound(3, 3), directional_listing_bound(3, 3)  # the triangle: two non-loop steps and a loop
(20, 15)
"""

from __future__ import annotations

from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import STEPWISE_MAP_CHECKS, AlgorithmSpec
from topomark.reference.explorers.movable_marker import (DirectionalMovableMarkerExplorer,
                                                          ListingDirectionalMovableMarkerExplorer,
                                                          ListingMovableMarkerExplorer, MovableMarkerExplorer)

__all__ = ["SPECS", "directional_bound", "dudek_listing_bound", "directional_listing_bound"]


def directional_bound(n: int, m: int) -> int:
    """Topomark's bound for the carried l = ε thread (§6.3.1; ``thread-carried``): 3(n − 1)² + (m − n + 1)(3n − 1)."""
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
_BOUND = "O(mn) (§2.3.1); bound_fn: topomark's, for §2.3.1's description as written"
_WHOSE = "topomark's worst case of §2.3.1's description as written (docs/bounds.md), behind O(mn) (§2.3.1)"
SEARCH = ("§2.3.1 gives no listing (Dudek et al.'s is in [24, 26]) and says the robot searches \"visiting known "
          "vertices in S\": this explorer visits only those that can be v_u (its degree, an unexplored edge, neither "
          "v_k nor a neighbour of v_k) and looks at every vertex it passes on the way")
"""What topomark's movable-marker search changes relative to the thesis's description (``changes``)."""
_NO_DROP = f"{SEARCH}; it drops nothing where no known vertex can be v_u"
_UNDIRECTED = (f"{_NO_DROP}, and where v_k' has a single unexplored exit that exit is e', with no back-link "
               "search")


def _spec(name: str, thesis: str, directional: bool, explorer: type, changes: str | None) -> AlgorithmSpec:
    """One entry: topomark's explorer (``changes``, naming its listing entry) or the description as written."""
    bound_fn, formula = ((directional_listing_bound, "3n(n − 1)/2 + (m − n + 1)(3n − 3)") if directional else
                         (dudek_listing_bound, "3n(n − 1)/2 + (m − n + 1)(6n − 7)"))
    return AlgorithmSpec(name=name, thesis=thesis, kit=Kit(vertex=1, directional=directional, movable=True),
                         bound=_BOUND, markers="1", deterministic=True, options=_OPTIONS, checks=STEPWISE_MAP_CHECKS,
                         bound_fn=bound_fn, bound_source="listing", bound_formula=f"{formula}, {_WHOSE}",
                         explorer=explorer, uses_lighthouse=False, marker_bound_fn=lambda n, m: 1, family="robot",
                         ways=("correct", "marker-moved"), changes=changes,
                         listing_entry=None if changes is None else f"{name}-listing")


_DUDEK = "§2.3.1, Dudek et al. [24, 26]"
_DIRECTIONAL = f"{_DUDEK}; directional variant [27]"
SPECS = (
    _spec("dudek", _DUDEK, False, MovableMarkerExplorer, _UNDIRECTED),
    _spec("dudek-listing", f"{_DUDEK}, as written", False, ListingMovableMarkerExplorer, None),
    _spec("dudek-directional", _DIRECTIONAL, True, DirectionalMovableMarkerExplorer, _NO_DROP),
    _spec("dudek-directional-listing", f"{_DIRECTIONAL} (§6.3.1), as written", True,
          ListingDirectionalMovableMarkerExplorer, None),
)
