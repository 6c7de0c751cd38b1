"""The O(mn) footprint searches improved with directional markers: *edgeINFO* (thesis §6.2.2,
Figure 6.14): Case 1b with m + 1 directional V-E-markers (``case-1b-edgeinfo``) and Case 2 (Algorithm 6.1)
with m + n directional E-markers (``case-2-edgeinfo``): "The other $O(mn)$ algorithms can be improved in a
similar manner" (§6.2.2) — also Case 1a with m directional E-markers (``case-1a-edgeinfo``, Figure 6.17's
"directional marker version of the m E-marker algorithm", §6.2.2) and the two closest-first extensions of
Case 4 (``case-4-edgeinfo``, ``case-4-mn-edgeinfo``; §6.2.2 names them among the algorithms that "can be
improved with directional markers so cost is reduced, although the cost bound remains unchanged").

The loop, the drops' places, the search and the m extension are Case 1b's
(:class:`~topomark.reference.explorers.edge_footprints.VertexEdgeFootprints`),
Case 2's (``DoubleMarkedEdges``, Algorithm 6.1), Case 1a's
(``EdgeFootprints``) or Case 4's
(:mod:`~topomark.reference.explorers.closest_first`, Algorithm 6.3); only the
markers' directions and the candidate filter differ: each explorer here is its
original holding :data:`EDGE_INFO` (an :class:`EdgeInfo`) as its
``marking`` in place of the undirected one
(:class:`~topomark.reference.explorers.edge_footprints.Marking`).
"Assume that when the robot drops a V-marker at a vertex, it drops the marker
in such a way that the marker head points toward one of the exits (edges), and
that when it drops an E-marker on an edge, it drops the marker in such a way
that the marker head points toward one of the end vertices" (§6.2.2).  On a
marked v_u the robot reads edgeINFO, the presence/absence (and, "enriched",
the head/tail) of E-markers on the edges of v_u "enumerated starting from the
edge pointed to by the directional V-marker" (§6.2.2), and a known vertex is
"potentially confusing" — a candidate to visit — "only if ... 1) the 1st edge
on the *right* of the edge pointed by the V-marker, which corresponds to the
entry edge, must be an unexplored edge, 2) it has [the same] edgeINFO" (§6.2.2).

Decisions, with the thesis references (each shown in ``tests/test_markers_622.py``):

* **Which exit a V-marker points at** (§6.2.2 leaves it open):
  the edge the robot entered by when it dropped it (``direction=0``), at v0
  the exit it faces (the map's exit 0).  A robot entering that vertex later
  by exit j senses ``V-((head − j) mod deg)``.
* **Which end an E-marker's head points at** (§6.2.2 leaves it open): v_u,
  the vertex the robot stands at when it drops the loop marker (``"H"``);
  so the loop edge e = e' reads ``E-p-H`` at v_k' and ``E-p-T`` at v_k.
  The thesis's example reads "incoming (P_H)" (§6.2.2); with this convention
  every loop edge is incoming at the vertex found by the search.  Its
  (P_T, A, P_H, A) from ``[4,V-1,E-1-H,E-3-T]`` (Figure 6.14's caption, §6.2.2)
  is inconsistent with "incoming (P_H)"; here edgeINFO is read from
  the signature as :func:`~topomark.spec.signature.signature_at` defines
  it, so the question does not arise.
* **The candidate test, made exact** (generalising §6.2.2's two conditions):
  a directional V-marker fixes an absolute frame at every vertex, so
  conditions 1) and 2), and the enriched edgeINFO, say together that a
  known vertex w can be v_u only through a dart (w, j) with j unexplored in
  S and ``signature_at(S, w, j)`` equal to what the robot sensed at v_u on
  arrival (before it drops the marker on e, so e's own new marker is not in
  the comparison, as in every footprint search, Algorithm 6.3 line 7).  S
  shows every marker in the world at that moment (all were dropped by the
  robot and recorded), and unexplored edges carry none, so the true v_k'
  always passes: the filter never excludes it.  For a marked vertex the
  V-marker allows at most one such j.  On top of Case 1b's filter (degree,
  c, an unexplored edge, not v_k or its neighbours) this one only removes
  candidates.  :func:`matching_darts` needs no V-marker (it compares
  whole signatures from every unexplored entry), so it serves an E-only
  algorithm as well.
* **Case 2: anchored at the entry** (§6.2.2 "in a similar manner"; §6.2.2
  enumerates edgeINFO "starting from the edge pointed to by the directional
  V-marker", and Case 2 drops no V-marker: the thesis does not say where its
  enumeration starts): a candidate dart (w, j) passes iff j is unexplored and
  S's marks at w read from entry j are the marks sensed at v_u relative to
  its entry — :func:`matching_darts` tries every unexplored entry of w, so the
  comparison does not depend on where an enumeration starts.  Every E-marker's head is at v_u
  (the two on a non-loop e point at the new vertex, the loop one at v_k').
  Observation: the marked edges' *positions* relative to the entry are
  sensed even with undirected markers; the heads and (Case 1b) the V-marker's
  fixing of j are what the directional markers add.  Case 1a's one marker
  on a non-loop e is dropped the same way (head at v_u): one rule,
  :meth:`EdgeInfo.drop_on_entry`, for every E-marker on a non-loop e.
* **Case 4 (closest-first): the filter applies as it is** (§6.2.2 lists "the
  extension algorithm of the E-marker algorithm which requires a maximum of
  m − ⌊n/2⌋ markers" and "the extension algorithm of
  it which requires a maximum of m markers" among those improved; §6.2.2 "in
  a similar manner").  Its search is the footprint search (Algorithm 6.3
  lines 14–24; ``ClosestFirst`` inherits ``search`` and ``candidates``); what
  it changes — the edge chosen closest-first (rule 1, §6.2.1 Case 4) and a non-loop
  edge left blank when v_k has a marked edge (rule 3, §6.2.1 Case 4) — does not touch
  the filter's premise: the robot drops every marker and S records it, a
  blank edge carries none in the world nor in S, an unexplored edge none, so
  S's marks at the true v_k' read from e' are what was sensed at v_u.  Rule 3
  reads "v_k has a marked edge" from S, whatever the heads.  After a search
  the robot stands at the same v_k' as the undirected version, so the
  closest-first choice, and the edge order, are the same
  (``tests/test_markers_622.py``).  Anchored at the entry, as Case 2.
* **A unique candidate is still visited** (§6.2.2: "is not potentially
  confusing and thus does not need to be visited" excludes only the
  vertices that fail; the potentially confusing ones are searched as in
  Case 1b, §6.2.1 Case 1a): the search validates the back-link by the footprint
  itself — the marker on e seen where S shows none — and never trusts a
  match alone.  The cost gained is the candidates not walked to.
* **Cost**: fewer candidates, visited in Case 1b's order, so in practice a
  shorter search; not a theorem — the search stops where v_k' is first
  *passed*, and a skipped candidate's path could have passed it earlier.
  The bound stays Case 1b's O(mn) (§6.2.2: "the cost bound remains
  unchanged"), the markers its m + 1 (n V + m − n + 1 E, all directional);
  Case 2's likewise (m + n − 1 used), Case 1a's (m) and Case
  4's (the corrected m − ⌊(n−1)/2⌋ and m + [n even], §6.2.1 Case 4): the
  drops are the original's, only their heads are added.

Examples
--------
>>> from topomark.spec.mapstate import PartialMap
>>> M = PartialMap(); M.add_vertex(3)
0
>>> M.unexplored.extend([(0, 1), (0, 2)]); M.mark_vertex(0, 1, 0)  # V-marker at v0 pointing at exit 0
>>> matching_darts(M, 0, Signature(3, 1, 2))  # entered by exit 1, the head is 2 exits clockwise
[1]
>>> matching_darts(M, 0, Signature(3, 1, 0))  # that would be entry 0, which S knows
[]
>>> [c.name for c in (EdgeFootprintsEdgeInfo, ClosestFirstEdgeInfo, ClosestFirstDoubleEdgeInfo)]
['case-1a-edgeinfo', 'case-4-edgeinfo', 'case-4-mn-edgeinfo']
"""

from __future__ import annotations

from typing import cast

from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.closest_first import ClosestFirst, ClosestFirstDouble
from topomark.reference.explorers.edge_footprints import (DoubleMarkedEdges, EdgeFootprints, FootprintSearch, Marking,
                                                          VertexEdgeFootprints)
from topomark.reference.explorers.marker_walk import MarkerStep

__all__ = ["matching_darts", "EdgeInfo", "EDGE_INFO", "EdgeInfoFootprints", "DoubleMarkedEdgeInfo",
           "EdgeFootprintsEdgeInfo", "ClosestFirstEdgeInfo", "ClosestFirstDoubleEdgeInfo",
           "ListingEdgeInfoFootprints", "ListingDoubleMarkedEdgeInfo", "ListingEdgeFootprintsEdgeInfo",
           "ListingClosestFirstEdgeInfo", "ListingClosestFirstDoubleEdgeInfo"]


def matching_darts(M: PartialMap, w: int, sensed: Signature, exits: list[int] | None = None) -> list[int]:
    """The unexplored exits j of map vertex ``w`` (``exits`` if the caller has them) by which a robot would sense
    ``sensed`` at ``w`` (S's marks)."""
    if exits is None:
        exits = [j for _, j in M.unexplored.at([w])]
    if sensed.degree != M.degree(w):
        return []
    could = _entries_reading_first(M, w, sensed)
    return [j for j in exits if (could is None or j in could) and signature_at(M, w, j) == sensed]


def _entries_reading_first(M: PartialMap, w: int, sensed: Signature) -> set[int] | None:
    """The entries j of ``w`` from which the first relative direction in ``sensed`` (the V-marker's head, else
    its first E-marker) is read as sensed (§3.1.1: exit x reads (x − j) mod deg); None if it has none.  Only
    these can read all of ``sensed``: a shortcut past most entries, never a test in its own right."""
    d, mark = M.degree(w), M.vertex_mark(w)
    if sensed.vertex_direction is not None:
        return set() if mark is None or mark.head is None else {(mark.head - sensed.vertex_direction) % d}
    if not sensed.edges:
        return None
    p, count, end = sensed.edges[0]
    return {(dm.exit - p) % d for dm in M.dart_marks(w) if dm.count == count and dm.end == end}


class EdgeInfo(Marking):
    """Directional markers read as edgeINFO: a candidate must read, from some unexplored entry, exactly what the
    robot sensed at v_u (§6.2.2, generalised; module docstring)."""

    vertex_head = 0  # each V-marker points at the edge the robot entered by
    loop_head = "H"  # each loop E-marker's head points at v_u, where the robot drops it

    def candidates(self, walker: FootprintSearch, it: MarkerStep, places: list[int]) -> list[int]:
        """The case's own candidates that are potentially confusing by edgeINFO: some unexplored entry reads what
        was sensed at v_u (``it.signature``)."""
        sig = cast(Signature, it.signature)  # sensed at v_u before its candidates are asked
        return [w for w in places if matching_darts(walker.M, w, sig)]

    def drop_on_entry(self, walker: FootprintSearch, it: MarkerStep, count: int) -> None:
        """The marker(s) on a non-loop e, head at v_u (the new vertex, where they are dropped), tail at v_k."""
        walker.drop(MarkerOp("edge", exit=0, count=count, direction="H"), it)
        v, i = it.edge
        walker.M.mark_as_sensed(v, Signature(walker.M.degree(v), edges=((i, count, "T"),)), 0)


EDGE_INFO = EdgeInfo()
"""The marking every explorer of this module holds."""


class EdgeInfoFootprints(VertexEdgeFootprints):
    """Case 1b with directional V-E-markers: candidates must match edgeINFO from the entry (§6.2.2)."""

    name = "case-1b-edgeinfo"
    marking = EDGE_INFO


class DoubleMarkedEdgeInfo(DoubleMarkedEdges):
    """Case 2 (Algorithm 6.1) with directional E-markers, heads at v_u: "The other O(mn) algorithms can be
    improved in a similar manner" (§6.2.2); anchored at the entry (module docstring)."""

    name = "case-2-edgeinfo"
    marking = EDGE_INFO


class EdgeFootprintsEdgeInfo(EdgeFootprints):
    """Case 1a (m E-markers) with directional E-markers, heads at v_u, anchored at the entry: Figure 6.17's
    "directional marker version of the m E-marker algorithm" (§6.2.2)."""

    name = "case-1a-edgeinfo"
    marking = EDGE_INFO


class ClosestFirstEdgeInfo(ClosestFirst):
    """Case 4 (Algorithm 6.3, closest-first, m − ⌊(n−1)/2⌋ markers) with directional E-markers (§6.2.2)."""

    name = "case-4-edgeinfo"
    marking = EDGE_INFO


class ClosestFirstDoubleEdgeInfo(ClosestFirstDouble):
    """The closest-first extension of Case 2 (§6.2.1 Case 4) with directional E-markers (§6.2.2)."""

    name = "case-4-mn-edgeinfo"
    marking = EDGE_INFO


class ListingEdgeInfoFootprints(EdgeInfoFootprints):
    """``case-1b-edgeinfo`` with the search as listed (``case-1b-edgeinfo-listing``; Algorithm 6.1 lines 11–19, 6.3 lines 18–24)."""

    name, literal = "case-1b-edgeinfo-listing", True


class ListingDoubleMarkedEdgeInfo(DoubleMarkedEdgeInfo):
    """``case-2-edgeinfo`` with the search as listed (``case-2-edgeinfo-listing``; Algorithm 6.1 lines 11–19, 6.3 lines 18–24)."""

    name, literal = "case-2-edgeinfo-listing", True


class ListingEdgeFootprintsEdgeInfo(EdgeFootprintsEdgeInfo):
    """``case-1a-edgeinfo`` with the search as listed (``case-1a-edgeinfo-listing``; Algorithm 6.1 lines 11–19, 6.3 lines 18–24)."""

    name, literal = "case-1a-edgeinfo-listing", True


class ListingClosestFirstEdgeInfo(ClosestFirstEdgeInfo):
    """``case-4-edgeinfo`` with the search as listed (``case-4-edgeinfo-listing``; Algorithm 6.1 lines 11–19, 6.3 lines 18–24)."""

    name, literal = "case-4-edgeinfo-listing", True


class ListingClosestFirstDoubleEdgeInfo(ClosestFirstDoubleEdgeInfo):
    """``case-4-mn-edgeinfo`` with the search as listed (``case-4-mn-edgeinfo-listing``; Algorithm 6.1 lines 11–19, 6.3 lines 18–24)."""

    name, literal = "case-4-mn-edgeinfo-listing", True
