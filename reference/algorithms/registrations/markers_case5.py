"""§6.2.1 Case 5 — k > 3 undirected markers, their number not known relative to the world: Version-1
(Algorithm 6.4) and Version-2 (Algorithm 6.5) — and Case 0, the plausible strategy shown to fail (thesis
Figure 6.3; §6.2.1 Case 5, Algorithms 6.4 and 6.5; Table 6.1 row "unknown k > 3").  Explorers:
:mod:`topomark.reference.explorers.case5_v1`, :mod:`~topomark.reference.explorers.case5_v2`,
:mod:`~topomark.reference.explorers.case5_phase2` (phase II, shared) and
:mod:`~topomark.reference.explorers.case0_every_vertex`.

==========  ==========================================  ==========================  =====================
algorithm   kit (``--markers K``; default)               marker bound checked        cost (thesis)
==========  ==========================================  ==========================  =====================
case-5-v1   K undirected V-markers; Σ_{k=1}^{n} k        Σ_{k=1}^{n} k               O(m²n); O(m·d_max)
                                                                                     with every place marked
case-5-v2   one pool of K undirected markers; m + 4      m + 4                       O(m²n); O(mn) with
                                                                                     every place and loop
                                                                                     edge marked
case-0      n undirected V-markers                       n                           none: it fails (§6.2.1 Case 0)
case-5-     K undirected E-markers; Σ_{k=1}^{n−1} k      Σ_{k=1}^{n−1} k             O(m²n); O(m) with
edge                                                                                 every tree edge marked
case-5-     K directional V-markers; Σ_{k=1}^{n} k       Σ_{k=1}^{n} k               O(m²n) (Table 6.2,
direc-                                                                               directional column)
tional
==========  ==========================================  ==========================  =====================

``case-5-edge`` is the E-marker version §6.2.1 Case 5 says "can be developed" (Case 3b's
unique edge counts, then hypotheses to the nearest marked edge:
:mod:`~topomark.reference.explorers.case5_edge`); its default kit is Case 3b's
Σ_{k=1}^{n−1} k, enough to mark every edge of the exploration tree.
``case-5-directional`` is Table 6.2's "unknown k > 3" row with directional
markers: Version-1 whose markers point at the entry edge
(:mod:`~topomark.reference.explorers.case5_directional`); default Σ_{k=1}^{n} k.

Defaults (the thesis gives none: in Case 5 the robot is *not* assured a count):
K is what lets phase I run to the end — Σ_{k=1}^{n} k for Version-1
("sufficient markers to mark each visited vertex", §6.2.1 Case 5) and m + 4 for
Version-2 (2 at v0, 2 on one of its edges, 1 at each other place, 1 on each
loop edge but the double-marked one: "sufficient markers to mark each vertex and
loop edge", §6.2.1 Case 5).  ``--markers`` is at least 4 ("k > 3", §6.2.1 Case 5; Version-2's
line 1 drops four).  Version-2's K is one pool for vertices and edges (the
thesis's markers are homogeneous, §6.2): the kit given to the simulator is a
pool of exactly K vertex-or-edge markers, so a drop beyond K is refused by the
simulator (``OutOfMarkers``), not only avoided by the robot's own count (the
robot knows how many it carries, only not how that compares with the world,
§6.2.1 Case 5; tested with an explorer that overdraws by one).

Case 0 is registered as *not deterministic* in the thesis's sense of the word
(an algorithm that always maps the world, §5.2.2): "this approach does not work
in general" (§6.2.1 Case 0).  It runs until it enters a marked place that more than one
unexplored edge fits, and there it stops with the ``failed`` outcome ("k edges
fit; the robot cannot determine which, §6.2.1 Case 0"; K4 is the smallest world that
shows it).  The certified pairs of worlds in ``tests/vectors/case0/`` (K4 with
two embeddings; K4 against a 5-place world, found by search over every embedded
world of ≤ 5 places and degree ≤ 4 from every start) show that no pick could be
right: the robot senses exactly the same on both up to that place, yet the
worlds are not isomorphic (``tests/test_markers_case5.py`` certifies them).

Examples
--------
>>> [s.name for s in SPECS]  # doctest: +NORMALIZE_WHITESPACE
['case-5-v1', 'case-5-v1-listing', 'case-5-v2', 'case-5-v2-listing', 'case-0', 'case-5-edge', 'case-5-directional',
 'case-5-directional-listing']
>>> SPECS[5].kit_for(4, 5, {"markers": 5}).describe(), SPECS[6].kit_for(4, 5, {"markers": None}).describe()
('5 undirected edge markers', '10 directional vertex markers')
>>> SPECS[0].kit_for(4, 5, {"markers": None}).describe()
'10 undirected vertex markers'
>>> SPECS[2].kit_for(4, 5, {"markers": None}).describe()
'5 undirected vertex markers, 4 undirected edge markers'
>>> SPECS[2].kit_for(4, 5, {"markers": 6}).describe()
'6 undirected vertex-or-edge markers'
"""

from __future__ import annotations

from dataclasses import replace

from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import EXPECTED_TO_FAIL, MARKER_MAP_CHECKS, AlgorithmSpec, Parameter
from topomark.reference.algorithms.registrations.markers_621 import SEARCH_CHANGES
from topomark.reference.explorers.case0_every_vertex import EveryVertexMarked
from topomark.reference.explorers.case5_directional import (DirectionalCountsThenLighthouse,
                                                            ListingDirectionalCountsThenLighthouse)
from topomark.reference.explorers.case5_edge import EdgeCountsThenLighthouse
from topomark.reference.explorers.case5_v1 import ListingVertexCountsThenLighthouse, VertexCountsThenLighthouse
from topomark.reference.explorers.case5_v2 import ListingVertexEdgeThenLighthouse, VertexEdgeThenLighthouse
from topomark.reference.explorers.counted_markers import sum_to

__all__ = ["SPECS", "v2_markers", "failing_listing"]

MARKERS = Parameter("markers", "how many markers the robot carries, K > 3 (default: enough for phase I to the end, "
                               "from n and m)", None, minimum=4)


def v2_markers(n: int, m: int) -> int:
    """Version-2 with every place and loop edge marked: 2 + 2 + (n − 1) + (m − n + 1) at most = m + 4."""
    return m + 4


def _v1_kit(n: int, m: int, options: dict) -> Kit:
    given = options.get("markers")
    return Kit(vertex=sum_to(n) if given is None else given)


def _v2_kit(n: int, m: int, options: dict) -> Kit:
    """Default: the split m + 4 is spent in (n + 1 V, m − n + 3 E); ``--markers K``: one pool of exactly K
    vertex-or-edge markers, which the simulator keeps (module docstring)."""
    given = options.get("markers")
    return Kit(vertex=n + 1, edge=m - n + 3) if given is None else Kit(either=given)


def _edge_kit(n: int, m: int, options: dict) -> Kit:
    given = options.get("markers")
    return Kit(edge=sum_to(n - 1) if given is None else given)


def _directional_kit(n: int, m: int, options: dict) -> Kit:
    given = options.get("markers")
    return Kit(vertex=sum_to(n) if given is None else given, directional=True)


_COUNTER = ("Algorithm 6.4's counter (lines 1, 3, 13, 15) gives the first new place one marker, v0's label: this "
            "explorer counts as Algorithm 6.2 does (v0 1, the j-th new place j + 1), so every count is unique as "
            "§6.2.1 Case 5 requires; the literal counter fails on the triangle")
"""What Version-1 (and its directional form) changes relative to Algorithm 6.4 (``changes``; shown by
``tests/test_listing_audit.py``)."""

_WAYS = ("correct", "phase-i", "phase-ii")
"""How a Case 5 run goes (§6.2.1 Case 5): phase I while the markers last, phase II once they run short, and the
map at the end — with K > 3 markers it never fails for want of them."""

_COUNTER_FAILS = ("Algorithm 6.4's counter as listed (i ← 1 at line 3, dropped at line 13) gives v0 and the first new "
                  "place one marker each, yet line 9 (Algorithm 6.2 line 18) names v_u by its unique count (§6.2.1 "
                  "Case 5): where that count must name v_u the run ends failed (on the triangle, cycle:n=3, for "
                  "one); where it need not, the listing maps the world")
_LINE_23_FAILS = ("Algorithm 6.5 line 23 as printed confirms a hypothesis whose perceptions \"do not match "
                  "throughout\", which line 21 has already rejected: phase II never confirms one and adds a known "
                  "place again where a loop must be closed by a hypothesis (with --markers 4: the paw entered from "
                  "its pendant, or lattice:rows=2,cols=3, end with the wrong map); phase I's search is Case 1b's as "
                  "listed")
"""Why ``case-5-v2-listing`` fails.  Its declared ways leave phase II out: on the suite's worlds every run that
reaches it must close a loop there and ends with a wrong map, which no conformance case can hold (the smallest-kit
case is passed over, :mod:`~topomark.reference.oracle.conformance.coverage`)."""


def failing_listing(spec: AlgorithmSpec, explorer: type, reason: str, way: str,
                    ways: tuple[str, ...] | None = None) -> tuple[AlgorithmSpec, AlgorithmSpec]:
    """``spec`` naming its listing entry, and beside it ``NAME-listing``: the listing followed to the letter by
    ``explorer``, registered "implemented, expected to fail" with ``reason`` (its lines and the world that shows
    it) and the ``way`` its runs fail by: a run of it may end correct, failed or with a wrong map
    (``fails-by-design``), and a conformance case whose reference run fails is passed by giving up or by a
    correct map (``docs/bounds.md``); like every entry expected to fail it states no cost bound (the bench's
    tables measure the entries that map).  ``ways``: the listing's declared ways where they are not ``spec``'s and
    ``way``."""
    name = f"{spec.name}-listing"
    assert spec.changes is not None and getattr(explorer, "literal", False) and getattr(explorer, "name", "") == name
    listed = replace(spec, name=name, thesis=f"{spec.thesis}, as listed: fails", explorer=explorer, changes=None,
                     listing_entry=None, bound=None, bound_bench=None, status=EXPECTED_TO_FAIL, status_reason=reason,
                     ways=(*spec.ways, way) if ways is None else ways)
    return replace(spec, listing_entry=name), listed


SPECS = (
    *failing_listing(AlgorithmSpec(
        name="case-5-v1", thesis="§6.2.1 Case 5 Version-1, Algorithm 6.4",
        kit=Kit(vertex=1), bound="O(m²n) (§6.2.1 Case 5; O(m·d_max) when every place is marked)",
        markers="K > 3 undirected V-markers, any K (Σ_{k=1}^{n} k mark every place)", deterministic=True,
        options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=VertexCountsThenLighthouse, uses_lighthouse=False,
        parameters=(MARKERS,), kit_fn=_v1_kit, marker_bound_fn=lambda n, m: sum_to(n), family="robot", bound_bench="table-6.1", ways=_WAYS,
        changes=_COUNTER), ListingVertexCountsThenLighthouse, _COUNTER_FAILS, "failed-marks-ambiguous"),
    *failing_listing(AlgorithmSpec(
        name="case-5-v2", thesis="§6.2.1 Case 5 Version-2, Algorithm 6.5",
        kit=Kit(vertex=1, edge=1), bound="O(m²n) (Table 6.1; O(mn) when every place and loop edge is marked, §6.2.1 Case 5)",
        markers="K > 3 undirected V-E-markers, any K, one pool (m + 4 mark every place and loop edge)",
        deterministic=True, options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=VertexEdgeThenLighthouse,
        uses_lighthouse=False, parameters=(MARKERS,), kit_fn=_v2_kit, marker_bound_fn=v2_markers, family="robot", bound_bench="table-6.1", ways=_WAYS,
        changes="phase I's search is Case 1b's (Algorithm 6.5 line 12: \"See algorithms in Case 1\"), with its "
                "change: " + SEARCH_CHANGES + "; and Algorithm 6.5 line 23 (\"do not match throughout\" → confirm) "
                "is read as \"match throughout\" (line 21 repeats it; the literal line maps the paw wrongly)"),
        ListingVertexEdgeThenLighthouse, _LINE_23_FAILS, "wrong-map", ("correct", "phase-i", "wrong-map")),
    AlgorithmSpec(
        name="case-0", thesis="§6.2.1 Case 0, n markers, one per visited vertex: fails (Figure 6.3)",
        kit=Kit(vertex=1), bound=None, markers="n undirected V-markers", deterministic=False, options=("policy edge",),
        checks=MARKER_MAP_CHECKS, explorer=EveryVertexMarked, uses_lighthouse=False,
        kit_fn=lambda n, m, o: Kit(vertex=n), marker_bound_fn=lambda n, m: n, family="robot",
        status="implemented, expected to fail", ways=("correct", "failed-marks-ambiguous"),
        status_reason="'this approach does not work in general' (§6.2.1 Case 0, Figure 6.3): a marked place that several "
                      "edges fit ends the run failed (on complete:n=4, for one)"),
    AlgorithmSpec(
        name="case-5-edge", thesis="§6.2.1 Case 5 with E-markers, \"a similar E-marker algorithm\"",
        kit=Kit(edge=1), bound="O(m²n) (Table 6.1; O(m) when every tree edge is marked, as Case 3b)",
        markers="K > 3 undirected E-markers, any K (Σ_{k=1}^{n−1} k mark every tree edge)", deterministic=True,
        options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=EdgeCountsThenLighthouse,
        uses_lighthouse=False, parameters=(MARKERS,), kit_fn=_edge_kit, marker_bound_fn=lambda n, m: sum_to(n - 1),
        family="robot", bound_bench="table-6.1", ways=(*_WAYS, "drop-trip")),
    *failing_listing(AlgorithmSpec(
        name="case-5-directional", thesis="§6.2.2 Table 6.2 \"unknown k > 3\", directional: Version-1 "
                                         "with directional V-markers (§6.2.1 Case 5, §6.2.2)",
        kit=Kit(vertex=1, directional=True), bound="O(m²n) (Table 6.2, directional column)",
        markers="K > 3 directional V-markers, any K (Σ_{k=1}^{n} k mark every place)", deterministic=True,
        options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=DirectionalCountsThenLighthouse,
        uses_lighthouse=False, parameters=(MARKERS,), kit_fn=_directional_kit, marker_bound_fn=lambda n, m: sum_to(n),
        family="robot", bound_bench="table-6.2", ways=_WAYS,
        changes=f"Version-1's phase I with directional markers, and so its {_COUNTER}"),
        ListingDirectionalCountsThenLighthouse, _COUNTER_FAILS, "failed-marks-ambiguous"),
)
