"""§6.2.2's enhancements of the O(mn) footprint searches with *directional* markers: edgeINFO (thesis
§6.2.2, Figure 6.14).  Explorer: :mod:`topomark.reference.explorers.edge_info`.

============================  ==========================================  ===========================  =============
algorithm                     thesis                                      kit (default)                marker bound
============================  ==========================================  ===========================  =============
case-1b-edgeinfo              Case 1b, m + 1 directional V-E (§6.2.2)     m + 1 V-or-E pool, directed  m + 1
case-2-edgeinfo               Case 2, m + n directional E (§6.2.2)        m + n E, directed            m + n − 1
case-1a-edgeinfo              Case 1a, m directional E (§6.2.2)           m E, directed                m
case-4-edgeinfo               Case 4, m − ⌊n/2⌋ directional E (§6.2.2)    m − ⌊(n−1)/2⌋ E, directed    m − ⌊(n−1)/2⌋
case-4-mn-edgeinfo            Case 4-mn, m directional E (§6.2.2)         m + [n even] E, directed     m + [n even]
============================  ==========================================  ===========================  =============

The bound is Case 1b's (:func:`~topomark.reference.algorithms.registrations.markers_621.footprints_bound`,
ours, exact for the explorer): "the cost bound remains unchanged" (§6.2.2), and
the search only walks to fewer candidates.  The kit is Case 1b's pool, all
markers directional; ``--markers K`` gives a pool of K, as for ``case-1b``.  ``case-2-edgeinfo``
is ``case-2`` (kit m + n, m + n − 1 used, §6.2.1 Case 2) with directional E-markers; ``case-1a-edgeinfo``,
``case-4-edgeinfo`` and ``case-4-mn-edgeinfo`` are ``case-1a``, ``case-4`` and ``case-4-mn`` (their kits, their
checked marker bounds — Case 4's corrected, :mod:`~topomark.reference.explorers.closest_first` — and options:
Case 4 chooses closest-first whatever the edge policy) with directional E-markers.  Every E-only variant anchors
edgeINFO at the entry, as ``case-2-edgeinfo`` (:mod:`~topomark.reference.explorers.edge_info`).

Examples
--------
>>> [s.name for s in SPECS][::2]  # each followed by its NAME-listing, the search as listed
['case-1b-edgeinfo', 'case-2-edgeinfo', 'case-1a-edgeinfo', 'case-4-edgeinfo', 'case-4-mn-edgeinfo']
>>> SPECS[6].kit_for(4, 4, {"markers": None}).describe()  # the 4-cycle: m − ⌊(n−1)/2⌋ = 3
'3 directional edge markers'
>>> SPECS[0].kit_for(4, 4, {"markers": None}).describe()  # the 4-cycle
'5 directional vertex-or-edge markers'
>>> SPECS[0].bound_for(3, 3) == footprints_bound(3, 3)
True
"""

from __future__ import annotations

from dataclasses import replace

from topomark.spec.kit import Kit

from topomark.reference.explorers.edge_info import (ClosestFirstDoubleEdgeInfo, ClosestFirstEdgeInfo, DoubleMarkedEdgeInfo,
                                   EdgeFootprintsEdgeInfo, EdgeInfoFootprints, ListingClosestFirstDoubleEdgeInfo,
                                   ListingClosestFirstEdgeInfo, ListingDoubleMarkedEdgeInfo,
                                   ListingEdgeFootprintsEdgeInfo, ListingEdgeInfoFootprints)
from topomark.reference.algorithms.registrations.markers_621 import (MARKER_OPTIONS, case_1b_kit, case_4_markers,
                                                                     case_4_mn_markers, footprint_spec,
                                                                     footprints_bound, kit_size, with_listing)

__all__ = ["SPECS", "edge_only_spec"]


def _directional_1b_kit(n: int, m: int, options: dict) -> Kit:
    """Case 1b's kit (a pool of m + 1, or ``--markers K``), every marker directional (§6.2.2)."""
    return replace(case_1b_kit(n, m, options), directional=True)


def edge_only_spec(name: str, thesis: str, markers: str, explorer, count, bound,
                   options=MARKER_OPTIONS + ("policy edge",)):
    """The registration template of a §6.2.2 E-only variant (:func:`~.markers_621.footprint_spec` with directional
    E-markers): ``count(n, m)`` directional E-markers by default (``--markers K``: K), the marker bound ``bound(n,
    m)`` checked (``marker-budget``); ``markers`` states the count in words, ``explorer`` is built as
    ``explorer(robot, policies, observer, options)``."""
    return footprint_spec(name, thesis, markers, explorer,
                 lambda n, m, o: Kit(edge=kit_size(o, count(n, m)), directional=True), bound, "§6.2.2", options,
                 kind=Kit(edge=1, directional=True))


SPECS = (
    *with_listing(footprint_spec("case-1b-edgeinfo", "§6.2.2 Case 1b with directional V-E-markers, edgeINFO (Figure 6.14)",
          "m + 1 directional V-E-markers, one pool (as case-1b)", EdgeInfoFootprints, _directional_1b_kit,
          lambda n, m: m + 1, "§6.2.2", kind=Kit(either=1, directional=True)), ListingEdgeInfoFootprints),
    *with_listing(edge_only_spec("case-2-edgeinfo", "§6.2.2 Case 2 (Algorithm 6.1) with directional E-markers, edgeINFO anchored at "
               "the entry (§6.2.2)", "m + n directional E-markers (m + n − 1 used, §6.2.1 Case 2)", DoubleMarkedEdgeInfo,
               lambda n, m: m + n, lambda n, m: m + n - 1), ListingDoubleMarkedEdgeInfo),
    *with_listing(edge_only_spec("case-1a-edgeinfo", "§6.2.2 Case 1a with directional E-markers, edgeINFO anchored at the entry "
               "(§6.2.2; Figure 6.17, §6.2.2)", "m directional E-markers (as case-1a)", EdgeFootprintsEdgeInfo,
               lambda n, m: m, lambda n, m: m), ListingEdgeFootprintsEdgeInfo),
    *with_listing(edge_only_spec("case-4-edgeinfo", "§6.2.2 Case 4 (Algorithm 6.3, closest-first) with directional E-markers, "
               "edgeINFO anchored at the entry (§6.2.2)", "m − ⌊(n−1)/2⌋ directional E-markers (as case-4; stated "
               "m − ⌊n/2⌋, §6.2.1 Case 4)", ClosestFirstEdgeInfo, case_4_markers, case_4_markers, MARKER_OPTIONS),
          ListingClosestFirstEdgeInfo),
    *with_listing(edge_only_spec("case-4-mn-edgeinfo", "§6.2.2 Case 4, the closest-first extension of Case 2, with directional "
               "E-markers, edgeINFO anchored at the entry (§6.2.2)", "m + [n even] directional E-markers (as "
               "case-4-mn; stated m, §6.2.1 Case 4)", ClosestFirstDoubleEdgeInfo, case_4_mn_markers, case_4_mn_markers,
               MARKER_OPTIONS), ListingClosestFirstDoubleEdgeInfo),
)
