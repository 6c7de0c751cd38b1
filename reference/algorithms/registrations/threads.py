"""Registrations of the thread algorithms of §6.3 (Table 6.3; explorers in
:mod:`topomark.reference.explorers.threads_carried`, :mod:`~topomark.reference.explorers.threads_explore` and
:mod:`~topomark.reference.explorers.threads_knots`).

The fixed l = ε thread (Table 6.3's first row, O(m²n)) is Algorithm 3.1 with the ``thread`` lighthouse
(``topomark explore W --lighthouse thread``), registered with the lighthouses.  Here:

===================== ============ ================ ==================================================
name                  thread       Table 6.3        cost bound (bound_fn: ours, exact for our explorer)
===================== ============ ================ ==================================================
thread-carried        ε (0)        ε, retied, O(mn) :func:`directional_bound` (it is that explorer)
thread-circumference  n (or L)     c(G), O(mn)      :func:`circumference_bound`
thread-circumference- n (or L)     c(G), O(mn)      :func:`circumference_bound` (Algorithm 6.7 as listed)
listing
thread-knots          m + 1        l ≫ m, O(m)      :func:`knots_bound` = 4m − 2n + 2
thread-explore        L (default 2) l < c(G), O(mn) :func:`explore_bound`
thread-explore-       L (default 2) l < c(G), O(mn) :func:`explore_bound` (Algorithm 6.8 as listed)
listing
thread-fallback       L (default 2) l < c(G), O(m²n) :func:`fallback_bound`
thread-fallback-      L (default 2) l < c(G), O(m²n) :func:`fallback_bound` (phase I: Algorithm 6.7 as listed)
listing
===================== ============ ================ ==================================================

Decisions:

* **Two entries for Algorithm 6.7.**  ``thread-circumference`` is topomark's variant: where its record of
  the thread leaves one vertex and exit v_u can be, it skips the search back along the thread (lines 11–12;
  :mod:`~topomark.reference.explorers.threads_explore`).  ``thread-circumference-listing`` is the listing as
  written: it searches at every loop step.  Both are registered (not a policy of one entry) so that each has
  its own conformance suite whose reference costs are that explorer's, and so a trace names which one it
  follows; replay's re-run accepts a trace of either under either name and says which it followed.  Both
  are held to :func:`circumference_bound`, topomark's bound **for the listing as written** (derived in
  ``docs/bounds.md`` and checked against the listing on every small world of a family,
  ``tests/test_listing_reference.py``); the variant never costs more than the listing on the same world
  (it leaves out searches only), so the same bound holds it.
* **Two entries for Algorithm 6.8, and for the fallback**, the same way: ``thread-explore`` skips line 7's search
  where one vertex fits and leaves v_k's neighbours out of line 11's (a simple world has no second edge
  between two places, §3.1.1); ``thread-explore-listing`` searches as listed.  ``thread-fallback``'s phase I is
  ``thread-circumference``'s steps, ``thread-fallback-listing``'s the listing's.  Each pair is held to one bound
  of the listing (:func:`explore_bound`, :func:`fallback_bound`; ``docs/bounds.md``, checked against the literal
  entry and the variant on every small world of a family, ``tests/test_listing_threads.py``).
* **No literal entry for §6.3.1's carried thread or §6.3.2's knots.**  The thesis lists neither.  For the
  carried l = ε thread it says "we can run the single movable marker algorithm described in [26] but with
  reduced validation efforts ... The robot then searches S looking for the thread" (§6.3.1): which vertices
  are searched, in what order and how the robot comes back are [26]'s, not this thesis's.  For the knots it
  says "the robot may still need to conduct back-link validation ... the robot can just traverse any one of
  thread marked edges to the other end vertex" (§6.3.2): when the validation is needed ("may") and which
  edge is left open.  A literal entry would be an invented one; so both entries' bounds are topomark's for
  its own explorer (``bound_source`` ``variant``): a program costing more passes with a *difference*.
* **l = c(G).**  A kit is computed from n, m and the options only (``AlgorithmSpec.kit_fn``): the
  simulator cannot give the kit c(G) itself, and the robot may not know the world.  And c(G) is not
  enough (§6.3.2 asks for a thread that reaches any vertex without forming a cycle, then calls it c(G), the
  longest simple cycle, footnote 18, §6.3.2; decided by search, ``reference/bench/measure/thread_length.py``):
  Algorithm 6.7's thread is a simple path from v0 plus one loop edge, which a world with a path from v0
  longer than its longest cycle exceeds — the smallest is the triangle with a pendant start (c(G) = 3, 4 edges laid;
  ``tests/test_thread_algorithms.py``).  So ``thread-circumference`` is given **n** edges — at least
  c(G) and at least the n − 1 edges of a longest simple path plus the loop edge, so it never runs out
  — unless ``--thread-length L`` is given, and then it is given L and stops with the failed outcome
  "out of thread" if L is reached.
* **l ≫ m** is m + 1 (the most the knot explorer ever lays; the simulator refuses more).
* **Algorithm 6.9 (explore-merge) is left out.**  It "merges the two partial maps S_1 and S_2 using the
  merging algorithm described in [59, 61]" (§6.3.3), which this thesis does not give (and its
  bibliography is not in the text cited here): how a vertex of S_i is disambiguated against S_B ("using
  some marking aid ... the thread could be used as a movable (directional) marker", §6.3.3), what it
  costs and when the merged map is complete are all in [59, 61].  A merge of our own would be a new
  algorithm, not the thesis's; Algorithm 6.8 (``thread-explore``) covers the same thread class.
* The robot is never told n or m (§6.2.1); only ``thread-explore`` (and ``thread-circumference``
  when given ``--thread-length``) knows its thread's length, as §6.3.3 assumes.

Bounds (topomark's: the thesis gives O(·) only, Table 6.3), derived in the explorer modules; whose each is
and what it bounds is its entry's ``bound_source``:

* The phase-I/phase-II fallback (§6.3.3, :mod:`~topomark.reference.explorers.threads_fallback`): its
  phase I is a prefix of Algorithm 6.7's steps (below), the free end left costs no move, and each phase-II step
  is one pass of Algorithm 3.1's loop body with S at least as large and U no larger than the pass that (3.1)
  or (3.2) counts for it (§3.5.2): Algorithm 6.7's bound plus (3.1)+(3.2).

* Algorithm 6.7 as listed (a bound of the listing, ``docs/bounds.md``): n − 1 tree edges laid and rewound once
  each; a loop step lays e, goes back over e, walks the thread back (≤ n − 1) and rewinds e: ≤ n + 2
  (topomark's variant rewinds e at once where it needs no search: 2).
* Algorithm 6.8 as listed (a bound of the listing, ``docs/bounds.md``): a loop step found on the thread
  costs ≤ n + 2 (as Algorithm 6.7's); a step searching off the thread goes back over e, through the
  candidates in a depth-first order of a breadth-first tree of S and back (≤ 2(n − 1)), and over e again:
  ≤ 2n + 1 for a loop edge, ≤ 2n + 2 for a tree edge with its rewind; each of ≤ n − 1 reties walks
  ≤ n − 1: m(2n + 1) + n(n − 1).

Examples
--------
>>> circumference_bound(3, 3), knots_bound(3, 3), explore_bound(3, 3), fallback_bound(3, 3)
(9, 8, 27, 31)
"""

from __future__ import annotations

from typing import Any

from topomark.spec.kit import MAX_THREAD
from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import STEPWISE_MAP_CHECKS, AlgorithmSpec, Parameter
from topomark.reference.explorers.threads_carried import CarriedThreadExplorer
from topomark.reference.explorers.threads_explore import (CircumferenceThreadExplorer, ListingExploreExplorer,
                                                          ListingThreadExplorer, ThreadExplorer)
from topomark.reference.explorers.threads_fallback import FallbackThreadExplorer, ListingFallbackThreadExplorer
from topomark.reference.explorers.threads_knots import KnotThreadExplorer
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.algorithms.registrations.movable import directional_bound

__all__ = ["SPECS", "circumference_bound", "knots_bound", "explore_bound", "fallback_bound", "directional_bound"]




def circumference_bound(n: int, m: int) -> int:
    """Topomark's bound for Algorithm 6.7 as listed (``docs/bounds.md``): 2(n − 1) + (m − n + 1)(n + 2)."""
    return 2 * (n - 1) + (m - n + 1) * (n + 2)


def knots_bound(n: int, m: int) -> int:
    """Our exact worst case for the knot thread: 2m + 2(m − n + 1) = 4m − 2n + 2."""
    return 4 * m - 2 * n + 2


def explore_bound(n: int, m: int) -> int:
    """Topomark's bound for Algorithm 6.8 as listed (``docs/bounds.md``): m(2n + 1) + n(n − 1)."""
    return m * (2 * n + 1) + n * (n - 1)


def fallback_bound(n: int, m: int) -> int:
    """Our bound for the phase-I/phase-II fallback: Algorithm 6.7's plus Algorithm 3.1's (3.1)+(3.2)."""
    return circumference_bound(n, m) + upper_bound(n, m)


LENGTH = Parameter("thread-length", f"the thread's length L in edges (an integer 1..{MAX_THREAD:,}, the cap of "
                   "a marker count); the robot knows it", default="n", minimum=1, maximum=MAX_THREAD)
"""``thread-circumference``'s option: not given ("n"), the kit holds n edges and the robot is not told."""


def _circumference_kit(n: int, m: int, opts: dict) -> Kit:
    length = opts.get("thread-length", "n")
    return Kit(thread=n if length in ("n", None) else length)


_LAID = ("correct", "thread-laid", "thread-rewound")
"""How a run of Algorithm 6.7 goes (§6.3.2): the thread laid and rewound, and — a thread shorter than the world
needs — out of thread."""
_ROBOT: dict[str, Any] = dict(deterministic=True, checks=STEPWISE_MAP_CHECKS, uses_lighthouse=False,
                              marker_bound_fn=lambda n, m: 0, family="robot")
"""What every thread algorithm shares: one edge joins S per step, and no marker is ever dropped (a thread is
no marker, so the marker bound is 0)."""
_O_MN = "O(mn) (Table 6.3); bound_fn: topomark's"
_SKIPS = ("where the robot's record of the thread leaves one vertex and exit v_u can be, it skips the search back "
          "along the thread (Algorithm 6.7 lines 11–12) and rewinds e at once: the same map, fewer traversals")
_OURS = "ours: our explorer's exact worst case behind O(mn) (Table 6.3)"
_CARRIED = ("§6.3.1 gives no listing: it says to \"run the single movable marker algorithm described in [26] but "
            "with reduced validation efforts\" and that \"the robot then searches S looking for the thread\"; this "
            "explorer is dudek-directional's (§2.3.1), which visits only the vertices that can be v_u (its degree, "
            "an unexplored edge, neither v_k nor a neighbour of v_k) and looks at every vertex it passes on the way")
_EXPLORE_SKIPS = ("where the robot's record of the thread leaves one vertex and exit v_u can be, it skips the search "
                  "back along the thread (Algorithm 6.8 line 7) and rewinds e at once; line 11's search leaves out "
                  "v_k's neighbours, which a simple world rules out (§3.1.1): the same map, fewer traversals")

SPECS = (
    AlgorithmSpec(name="thread-carried", thesis="§6.3.1, l = ε thread carried and retied",
                  kit=Kit(thread=0), bound=_O_MN, markers="no marker; a thread of length ε", options=("policy edge",),
                  bound_fn=directional_bound, explorer=CarriedThreadExplorer, changes=_CARRIED, bound_source="variant",
                  ways=("correct", "thread-laid", "thread-retied"),
                  bound_formula=f"3(n − 1)² + (m − n + 1)(3n − 1), {_OURS} (§6.3.1)", **_ROBOT),
    *(AlgorithmSpec(name=name, thesis=f"§6.3.2, Algorithm 6.7{what} (l = c(G), given n: see the docstring)",
                    kit=Kit(thread=0), bound=_O_MN, markers="no marker; a thread of n edges (--thread-length: L)",
                    options=("thread-length L (default n; reaching L is the failed outcome 'out of thread')",),
                    bound_fn=circumference_bound, explorer=explorer, bound_source="listing",
                    bound_formula="2(n − 1) + (m − n + 1)(n + 2), topomark's exact worst case of Algorithm 6.7 as "
                                  "listed (§6.3.2; docs/bounds.md), behind O(mn) (Table 6.3)",
                    parameters=(LENGTH,), kit_fn=_circumference_kit, changes=changes,
                    listing_entry=None if changes is None else "thread-circumference-listing",
                    ways=(*_LAID, "failed-out-of-thread"), **_ROBOT)
      for name, what, explorer, changes in (
          ("thread-circumference", "", CircumferenceThreadExplorer, _SKIPS),
          ("thread-circumference-listing", " as listed", ListingThreadExplorer, None))),
    AlgorithmSpec(name="thread-knots", thesis="§6.3.2, l ≫ m thread with knots (Figure 6.20)",
                  kit=Kit(thread=0), bound="O(m) (Table 6.3); bound_fn: ours, exact worst case",
                  markers="no marker; a thread of m + 1 edges", options=(), bound_fn=knots_bound,
                  bound_formula="4m − 2n + 2, ours: the exact worst case behind O(m) (Table 6.3, §6.3.2)",
                  explorer=KnotThreadExplorer, kit_fn=lambda n, m, opts: Kit(thread=m + 1), bound_source="variant",
                  ways=(*_LAID, "thread-knots"),
                  changes="the thesis gives no listing (Figure 6.20, §6.3.2; \"the robot may still need to conduct "
                          "back-link validation\"): at a known v_k' with one unexplored exit that exit is e', with no "
                          "back-link validation", **_ROBOT),
    *(AlgorithmSpec(name=name, thesis=f"§6.3.3, Algorithm 6.8{what} (l < c(G), explore-explore)",
                    kit=Kit(thread=2), bound=_O_MN, markers="no marker; a thread of --thread-length edges",
                    options=("thread-length L (default 2, Figure 6.21)",), bound_fn=explore_bound,
                    bound_source="listing",
                    bound_formula="m(2n + 1) + n(n − 1), topomark's bound for Algorithm 6.8 as listed (§6.3.3; "
                                  "docs/bounds.md), behind O(mn) (Table 6.3)",
                    explorer=explorer, ways=(*_LAID, "thread-retied"), changes=changes,
                    listing_entry=None if changes is None else "thread-explore-listing",
                    parameters=(Parameter("thread-length", LENGTH.help, default=2, minimum=1, maximum=MAX_THREAD),),
                    kit_fn=lambda n, m, opts: Kit(thread=opts["thread-length"]), **_ROBOT)
      for name, what, explorer, changes in (
          ("thread-explore", "", ThreadExplorer, _EXPLORE_SKIPS),
          ("thread-explore-listing", " as listed", ListingExploreExplorer, None))),
    *(AlgorithmSpec(name=name,
                    thesis=f"§6.3.3, phase-I/phase-II fallback (l < c(G), Algorithm 6.7{what} then Algorithm 3.1)",
                    kit=Kit(thread=2), bound="O(m²n) (§6.3.3); bound_fn: topomark's",
                    markers="no marker; a thread of --thread-length edges, left laid once it runs out",
                    options=("thread-length L (default 2, Figure 6.21)", "policy edge=nearest|fifo|lifo (phase II)",
                             "policy hypothesis=fifo|lifo|shortest (phase II)", "policy path=shortest|dfs (phase II)"),
                    bound_fn=fallback_bound, bound_source="listing",
                    bound_formula="2(n − 1) + (m − n + 1)(n + 2) + (3.1) + (3.2), topomark's bound for phase I as "
                                  "Algorithm 6.7 is listed (§6.3.2) plus Algorithm 3.1's (§3.5.2) for phase II "
                                  "(docs/bounds.md), behind O(m²n) (§6.3.3)",
                    explorer=explorer, ways=("correct", "thread-laid", "thread-phase-ii"), changes=changes,
                    listing_entry=None if changes is None else "thread-fallback-listing",
                    parameters=(Parameter("thread-length", LENGTH.help, default=2, minimum=1, maximum=MAX_THREAD),),
                    kit_fn=lambda n, m, opts: Kit(thread=opts["thread-length"]), **_ROBOT)
      for name, what, explorer, changes in (
          ("thread-fallback", "", FallbackThreadExplorer, f"phase I is thread-circumference's steps: {_SKIPS}"),
          ("thread-fallback-listing", " as listed", ListingFallbackThreadExplorer, None))),
)
