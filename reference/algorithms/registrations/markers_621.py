"""§6.2.1's undirected algorithms that use about m markers and search S for footprints: Case 1a, Case 1b,
Case 2 (Algorithm 6.1) and the two closest-first extensions of Case 4 (Algorithm 6.3 and the extension of
Case 2) (thesis §6.2.1 Cases 1, 1a, 1b, 2 and 4, Algorithm 6.1; Table 6.1).  Explorers:
:mod:`topomark.reference.explorers.edge_footprints` and :mod:`topomark.reference.explorers.closest_first`.

Each is a kit algorithm: by default the robot carries exactly the markers its
case is assured — computed here from n and m, the robot never learns them —
and ``--markers K`` gives K instead (running out is the ``failed`` outcome).
The marker bound checked after every step (``marker-budget``) is the stated
one, as a formula:

============  ======================================  =================  ==========================
algorithm     Table 6.1 / title                       kit (default)      marker bound checked
============  ======================================  =================  ==========================
case-1a       m E-markers (Case 1a)                   m                  m
case-1b       m + 1, extendable to m (Case 1b)        m + 1 V-or-E pool  m + 1
case-2        m + n (title), text m + n − 1 (Case 2)  m + n              m + n − 1
case-4        m − ⌊n/2⌋ (Case 4)                      m − ⌊(n−1)/2⌋      m − ⌊(n−1)/2⌋
case-4-mn     m (Case 4)                              m + [n even]       m + [n even]
============  ======================================  =================  ==========================

The Case 4 counts are corrected (the decision and its proof are in
:mod:`~topomark.reference.explorers.closest_first`).  Case 1b's markers are
one homogeneous pool, each dropped "either on the vertex or on the edge"
as the robot needs (§6.2.1 Case 1b, footnote 16), so its kit is exactly that: a pool
of m + 1 vertex-or-edge markers (``Kit(either=m + 1)``, drawn as
:meth:`~topomark.spec.kit.Kit.draw` says), and ``--markers K`` a pool of K.
The robot is "assured that it has at least m markers" in the extension
(§6.2.1 Case 1b): with ``--markers m`` the last iteration's drop is refused and that
iteration's edge(s) in U are processed with no further motion
(:mod:`~topomark.reference.explorers.edge_footprints`); with fewer the run
ends ``failed`` (out of markers before the last iteration).

The thesis states O(mn) for all five (§6.2.1 Cases 1a, 1b, 2 and 4) with no
constant.  :func:`footprints_bound` is **ours**, the exact worst case of
these explorers: a non-loop step walks S (≤ n − 2, S has ≤ n − 1 vertices)
and follows e (1); a loop step walks S (≤ n − 1), follows e and comes back
(2), and searches the candidates in the preorder of a breadth-first tree of
S rooted at v_k, each by a shortest path, at most the tree's Euler tour
2(n − 1): (n − 1)² + (m − n + 1)(3n − 1) in all.

Examples
--------
>>> [s.name for s in SPECS][::2]
['case-1a', 'case-1b', 'case-2', 'case-4', 'case-4-mn']
>>> [s.name for s in SPECS][1::2]  # the search as listed
['case-1a-listing', 'case-1b-listing', 'case-2-listing', 'case-4-listing', 'case-4-mn-listing']
>>> [s.kit_for(4, 4, {"markers": None}).describe() for s in SPECS[::2]]  # the 4-cycle
['4 undirected edge markers', '5 undirected vertex-or-edge markers', '8 undirected edge markers', \
'3 undirected edge markers', '5 undirected edge markers']
>>> footprints_bound(3, 3)  # the triangle: two non-loop steps, one loop step
12
"""

from __future__ import annotations

from dataclasses import replace

from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import MARKER_MAP_CHECKS, AlgorithmSpec, Parameter
from topomark.reference.explorers.closest_first import (ClosestFirst, ClosestFirstDouble, ListingClosestFirst,
                                                        ListingClosestFirstDouble)
from topomark.reference.explorers.edge_footprints import (DoubleMarkedEdges, EdgeFootprints, ListingDoubleMarkedEdges,
                                                          ListingEdgeFootprints, ListingVertexEdgeFootprints,
                                                          VertexEdgeFootprints)

__all__ = ["SPECS", "SEARCH_CHANGES", "with_listing", "footprints_bound", "case_4_markers", "case_4_mn_markers", "MARKER_OPTIONS", "kit_size", "case_1b_kit",
           "footprint_spec"]

MARKERS = Parameter("markers", "how many markers the robot carries (default: what its case is assured, "
                               "from n and m)", None, minimum=1)


def footprints_bound(n: int, m: int) -> int:
    """Our exact worst-case cost of these explorers (module docstring): (n − 1)² + (m − n + 1)(3n − 1)."""
    return (n - 1) ** 2 + (m - n + 1) * (3 * n - 1)


def case_4_markers(n: int, m: int) -> int:
    """Algorithm 6.3's count, corrected: (m − n + 1) loop edges + ⌈(n−1)/2⌉ non-loop edges = m − ⌊(n−1)/2⌋."""
    return m - (n - 1) // 2


def case_4_mn_markers(n: int, m: int) -> int:
    """The extension of Case 2, corrected: (m − n + 1) + 2⌈(n−1)/2⌉ = m, or m + 1 for even n."""
    return m - n + 1 + 2 * (n // 2)


def kit_size(options: dict, assured: int) -> int:
    """The kit's size: ``--markers`` if given, else what the case is assured."""
    given = options.get("markers")
    return assured if given is None else given


def case_1b_kit(n: int, m: int, options: dict) -> Kit:
    """Case 1b's m + 1 homogeneous V-E-markers as one pool, each dropped at a vertex or on an edge (§6.2.1 Case 1b,
    footnote 16); ``--markers K``: a pool of K (§6.2.1 Case 1b: m suffices)."""
    return Kit(either=kit_size(options, m + 1))


_BOUND = "O(mn) ({}); bound_fn: ours, exact for our explorer"
MARKER_OPTIONS = ("markers",)
SEARCH_CHANGES = ("the listing's search (Algorithm 6.1 lines 11–19, Algorithm 6.3 lines 18–24; the text of Cases 1a "
                  "and 1b) visits every vertex of S with an unexplored edge, v_u's degree and its marks, and checks "
                  "each where it goes: this explorer leaves out the known neighbours of v_k (no multi-edges, §3.1.1) "
                  "and checks every vertex it passes, so one passed is not visited again and the search stops "
                  "wherever v_k' is seen")
"""What every footprint search of §6.2.1 (and §6.2.2's edgeINFO variants) changes relative to its listing: the
search of :class:`~topomark.reference.explorers.edge_footprints.FootprintSearch` (``tests/test_listing_audit.py``
shows each half on the smallest world the enumeration finds)."""


def footprint_spec(name, thesis, markers, explorer, kit_fn, marker_bound_fn, cites, options=MARKER_OPTIONS + ("policy edge",),
          kind=Kit(edge=1), changes=SEARCH_CHANGES):
    """The registration template of a §6.2.1 footprint search: a kit algorithm (``explorer`` built as
    ``explorer(robot, policies, observer, options)``) taking ``--markers``, deterministic, held to
    :data:`~topomark.reference.algorithms.algorithm_spec.MARKER_MAP_CHECKS` and to the exact bound
    :func:`footprints_bound`; ``kit_fn(n, m, options)`` gives the kit, ``marker_bound_fn(n, m)`` the stated marker
    bound (``markers`` in words, ``cites`` its thesis line).  ``kind``: the kind of marker the kit holds (the
    registry's ``kit``; the counts come from ``kit_fn``).  ``changes``: what the search changes relative to the
    listing (default :data:`SEARCH_CHANGES`)."""
    return AlgorithmSpec(name=name, thesis=thesis, kit=kind, bound=_BOUND.format(cites), markers=markers,
                         deterministic=True, options=options, checks=MARKER_MAP_CHECKS, bound_fn=footprints_bound,
                         explorer=explorer, uses_lighthouse=False, parameters=(MARKERS,), kit_fn=kit_fn,
                         marker_bound_fn=marker_bound_fn, family="robot", ways=("correct", "failed-out-of-markers"),
                         changes=changes,
                         bound_formula=f"(n − 1)² + (m − n + 1)(3n − 1), ours: the exact worst case of the footprint "
                                       f"search behind O(mn) ({cites})")


def with_listing(spec: AlgorithmSpec, literal: type,
                 what: str = "the search as listed (Algorithm 6.1 lines 11–19, Algorithm 6.3 lines 18–24)"
                 ) -> tuple[AlgorithmSpec, AlgorithmSpec]:
    """A footprint entry that changes its listing's search (:data:`SEARCH_CHANGES`) and, beside it, the entry
    ``NAME-listing`` whose explorer ``literal`` searches as listed (``literal = True``): the same kit, markers and
    bound formula, which is topomark's bound for the search as listed (``docs/bounds.md``; checked against the
    literal entries on every small world, ``tests/test_listing_cases.py``).  ``what``: how the thesis
    entry names the listing followed."""
    name = f"{spec.name}-listing"
    assert spec.changes is not None and getattr(literal, "literal", False) and getattr(literal, "name", "") == name
    assert spec.bound is not None and spec.bound_formula is not None  # every footprint entry has both
    listed = replace(spec, name=name, thesis=f"{spec.thesis}, {what}", explorer=literal,
                     bound=spec.bound.split("; bound_fn")[0] + "; bound_fn: topomark's, for the search as listed",
                     changes=None, listing_entry=None, bound_source="listing",
                     bound_formula=f"(n − 1)² + (m − n + 1)(3n − 1), topomark's bound for {what} (docs/bounds.md), "
                                   f"behind O(mn) ({spec.bound_formula.rsplit('(', 1)[-1]}")
    return replace(spec, listing_entry=name), listed


SPECS = (
    *with_listing(footprint_spec("case-1a", "§6.2.1 Case 1a, m E-markers (Figure 6.4; footprints [18])",
          "m undirected E-markers", EdgeFootprints, lambda n, m, o: Kit(edge=kit_size(o, m)), lambda n, m: m,
          "§6.2.1 Case 1a"), ListingEdgeFootprints),
    *with_listing(footprint_spec("case-1b", "§6.2.1 Case 1b, m + 1 V-E-markers, extendable to m (Figure 6.5)",
          "m + 1 undirected V-E-markers, one pool (m with the extension, §6.2.1 Case 1b)", VertexEdgeFootprints, case_1b_kit,
          lambda n, m: m + 1, "§6.2.1 Case 1b", kind=Kit(either=1)), ListingVertexEdgeFootprints),
    *with_listing(footprint_spec("case-2", "§6.2.1 Case 2, Algorithm 6.1, m + n E-markers",
          "m + n undirected E-markers (m + n − 1 used, §6.2.1 Case 2)", DoubleMarkedEdges,
          lambda n, m, o: Kit(edge=kit_size(o, m + n)), lambda n, m: m + n - 1, "§6.2.1 Case 2"),
          ListingDoubleMarkedEdges),
    *with_listing(footprint_spec("case-4", "§6.2.1 Case 4, Algorithm 6.3, closest-first (Figure 6.9)",
          "m − ⌊(n−1)/2⌋ undirected E-markers (stated m − ⌊n/2⌋, §6.2.1 Case 4: one short for even n)", ClosestFirst,
          lambda n, m, o: Kit(edge=kit_size(o, case_4_markers(n, m))), case_4_markers, "§6.2.1 Case 4", MARKER_OPTIONS),
          ListingClosestFirst),
    *with_listing(footprint_spec("case-4-mn", "§6.2.1 Case 4, the closest-first extension of Case 2",
          "m + [n even] undirected E-markers (stated m, §6.2.1 Case 4: one short for even n)", ClosestFirstDouble,
          lambda n, m, o: Kit(edge=kit_size(o, case_4_mn_markers(n, m))), case_4_mn_markers, "§6.2.1 Case 4", MARKER_OPTIONS),
          ListingClosestFirstDouble),
)
