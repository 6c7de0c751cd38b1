"""§6.2's algorithms that give places a unique count of markers: Case 3a (Algorithm 6.2), Case 3b, Σ k
directional vertex markers, and Case 3b's extension-1 and extension-2 (Algorithm 6.6) with directional
E-markers (thesis §6.2.1 Cases 3a and 3b, Algorithm 6.2, §6.2.2; Tables 6.1, 6.2).

Each is a kit algorithm: by default the robot carries exactly the markers its
case is assured — Σ_{k=1}^{n−1} k = n(n−1)/2 for Cases 3a/3b and the directional
vertex markers, Σ_{k=1}^{⌈m/2⌉} k for extension-1, Σ_{k=1}^{⌈(n−1)/2⌉} k for
extension-2 — computed here from the world (the robot never learns n or m);
``--markers K`` gives K instead.  The marker bound checked after every step is
the thesis's: the same formulas, except Σ_{k=1}^{n} k for the vertex
algorithms, which mark every vertex when the kit allows (§6.2.1 Case 3b; the decision is
in :mod:`topomark.reference.explorers.counted_markers`).  No exact cost formula
is stated (only O(m), O(m·d_max)), so none is checked per run: each bound is
asymptotic, measured by the bench (``table-6.1``, ``table-6.2``).

Two savings the thesis shows fail are registered with the status
"implemented, expected to fail" (:mod:`topomark.reference.explorers.failing_savings`):
``case-3b-saving`` (Case 3b marking a non-loop edge only from an unmarked v_k,
§6.2.1 Case 4, Figure 6.10) and ``extension-naive`` (extension-2 without coming back to
v_k, §6.2.2, Figure 6.15(b)–(c)).  Each gets the kit of the algorithm it saves
on, and that algorithm's marker bound; the thesis states no cost bound for
either.

``case-dv-sum`` is registered O(m) (Table 6.2) with its default kit
Σ_{k=1}^{n−1} k, which leaves the last new place blank, with no direction.
Its explorer takes the blank's unexplored edges first, from the blank, so no
edge is entered at the blank and no back-link is probed (the decision and its
lines, §6.2.1 Case 3a, §6.2.2, are in :mod:`~topomark.reference.explorers.counted_markers`):
on ``wheel-hub-last``, where the blank is the hub of degree d_max, the cost is
3m/2 − 2, within O(m) (``tests/test_markers_62.py``).

Two entries follow their listing where topomark's explorer changes it (``changes``, ``listing_entry``;
``docs/bounds.md``): ``case-dv-sum-listing`` takes Algorithm 6.2's line 6 by the edge policy alone, so the blank's
loop edges are probed as lines 19–35 list (O(m·d_max) on a wheel whose hub is found last, not Table 6.2's O(m));
``extension-2-listing`` comes back to an unmarked v_k after every loop edge (Algorithm 6.6 lines 19–20).  Neither
has an exact bound (the thesis's are O(·) only): each is measured by the bench like its variant, and replay's
re-run accepts a trace of either explorer of a pair under either name and says which it followed.

Examples
--------
>>> [s.name for s in SPECS]  # doctest: +NORMALIZE_WHITESPACE
['case-3a', 'case-3b', 'case-3b-saving', 'case-dv-sum', 'case-dv-sum-listing', 'extension-1', 'extension-2',
 'extension-2-listing', 'extension-naive']
>>> SPECS[1].kit_for(5, 7, {"markers": None}).describe()
'10 undirected edge markers'
>>> SPECS[3].kit_for(5, 7, {"markers": 3}).describe()
'3 directional vertex markers'
"""

from __future__ import annotations

from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import MARKER_MAP_CHECKS, AlgorithmSpec, Parameter
from topomark.reference.explorers.counted_markers import (DirectionalVertexCounts, EdgeCounts,
                                                          ListingDirectionalVertexCounts, VertexCounts, sum_to)
from topomark.reference.explorers.failing_savings import NaiveExtension, UndirectedSaving
from topomark.reference.explorers.saving_markers import (ListingSavingEdgeCounts, MarkFirstEdges, SavingEdgeCounts,
                                                         ceil_half)

__all__ = ["SPECS"]

MARKERS = Parameter("markers", "how many markers the robot carries (default: what its case is assured, "
                               "from n and m)", None, minimum=1)


def _count(n: int, options: dict, assured: int | None = None) -> int:
    """The kit's size: ``--markers`` if given, else the assured Σ_{k=1}^{n−1} k (or ``assured``)."""
    given = options.get("markers")
    return (sum_to(n - 1) if assured is None else assured) if given is None else given


_BLANK_FIRST = ("once the last new place is left blank (Algorithm 6.2 lines 14–16), its unexplored edges are taken "
                "first, whatever the edge policy (line 6 leaves the choice open), so no loop edge enters the blank "
                "and needs its back-link probed (lines 19–35): the edge policy alone would choose otherwise")
"""What ``case-dv-sum`` changes relative to Algorithm 6.2 (``case-dv-sum-listing`` takes line 6 by the policy)."""
_COME_BACK_SOMETIMES = (
    "Algorithm 6.6 lines 19–20 bring the robot back to an unmarked v_k after every loop edge: this explorer comes "
    "back only if v_k still has an unexplored edge, as §6.2.2's text says (\"unless v_k has no unexplored edges "
    "now\"), one traversal fewer otherwise")
"""What ``extension-2`` changes relative to Algorithm 6.6 (``extension-2-listing`` follows lines 19–20)."""

CLOSEST_FIRST = ("markers",)
"""The options of §6.2.2's extensions of Case 3b: ``--markers`` only.  They take no edge policy: rule (1) of
§6.2.2 ("the robot selects the *closest* edge to explore in the next iteration"; Table 6.2's "closest-first") is what
keeps every accessible visited place marked, so the ``nearest`` policy is part of the algorithm (with ``fifo`` the
run reaches a place with no marked edge and I-1 fails on ``lattice:rows=3,cols=3``)."""

SPECS = (
    AlgorithmSpec(
        name="case-3a", thesis="§6.2.1 Case 3a, Algorithm 6.2 (Figure 6.6)", kit=Kit(vertex=1),
        bound="O(m·d_max)", markers="Σ_{k=1}^{n−1} k undirected V-markers (Σ_{k=1}^{n} k if the kit allows)",
        deterministic=True, options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=VertexCounts,
        uses_lighthouse=False, parameters=(MARKERS,), kit_fn=lambda n, m, o: Kit(vertex=_count(n, o)),
        marker_bound_fn=lambda n, m: sum_to(n), family="robot", bound_bench="table-6.1", ways=("correct", "failed-out-of-markers")),
    AlgorithmSpec(
        name="case-3b", thesis="§6.2.1 Case 3b (Figures 6.7, 6.8)", kit=Kit(edge=1),
        bound="O(m)", markers="Σ_{k=1}^{n−1} k undirected E-markers",
        deterministic=True, options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=EdgeCounts,
        uses_lighthouse=False, parameters=(MARKERS,), kit_fn=lambda n, m, o: Kit(edge=_count(n, o)),
        marker_bound_fn=lambda n, m: sum_to(n - 1), family="robot", bound_bench="table-6.1",
        ways=("correct", "failed-out-of-markers", "drop-trip")),
    AlgorithmSpec(
        name="case-3b-saving", thesis="§6.2.1 Case 3b saving markers like Algorithm 6.3: fails (Case 4, Figure 6.10)",
        kit=Kit(edge=1), bound=None, markers="at most Σ_{k=1}^{n−1} k undirected E-markers (Case 3b's kit)",
        deterministic=True, options=("markers",), checks=MARKER_MAP_CHECKS, explorer=UndirectedSaving,
        uses_lighthouse=False, parameters=(MARKERS,), kit_fn=lambda n, m, o: Kit(edge=_count(n, o)),
        marker_bound_fn=lambda n, m: sum_to(n - 1), family="robot", status="implemented, expected to fail",
        ways=("correct", "failed-out-of-markers", "failed-marks-ambiguous", "drop-trip", "wrong-map"),
        status_reason="the marked edges 'may not always identify a visited vertex and its incident edges' "
                      "(§6.2.1 Case 4): two neighbours whose only marked edge joins them show the same signature "
                      "(Figure 6.10(b)); on figure-6.10 the run ends failed (the marks fit two edges)"),
    *(AlgorithmSpec(
        name=name, thesis=f"§6.2.2 Σ_{{k=1}}^{{n−1}} k directional V-markers (Table 6.2){what}",
        kit=Kit(vertex=1, directional=True), bound=bound,
        markers="Σ_{k=1}^{n−1} k directional V-markers (Σ_{k=1}^{n} k if the kit allows)",
        deterministic=True, options=("markers", "policy edge"), checks=MARKER_MAP_CHECKS, explorer=explorer,
        uses_lighthouse=False, parameters=(MARKERS,),
        kit_fn=lambda n, m, o: Kit(vertex=_count(n, o), directional=True),
        marker_bound_fn=lambda n, m: sum_to(n), family="robot", bound_bench="table-6.2",
        ways=("correct", "failed-out-of-markers"), changes=changes,
        listing_entry=None if changes is None else "case-dv-sum-listing")
      for name, what, explorer, bound, changes in (
          ("case-dv-sum", "", DirectionalVertexCounts, "O(m)", _BLANK_FIRST),
          ("case-dv-sum-listing", ": Algorithm 6.2 as listed", ListingDirectionalVertexCounts,
           "O(m) (Table 6.2); as listed, a blank of degree d_max probed: O(m·d_max) (§6.2.1 Case 3a)", None))),
    AlgorithmSpec(
        name="extension-1", thesis="§6.2.2 extension-1 of Case 3b (Figure 6.15, Table 6.2)",
        kit=Kit(edge=1, directional=True), bound="O(m)", markers="Σ_{k=1}^{⌈m/2⌉} k directional E-markers",
        deterministic=True, options=CLOSEST_FIRST, checks=MARKER_MAP_CHECKS, explorer=MarkFirstEdges,
        uses_lighthouse=False, parameters=(MARKERS,),
        kit_fn=lambda n, m, o: Kit(edge=_count(n, o, sum_to(ceil_half(m))), directional=True),
        marker_bound_fn=lambda n, m: sum_to(ceil_half(m)), family="robot", bound_bench="table-6.2",
        ways=("correct", "failed-out-of-markers")),
    *(AlgorithmSpec(
        name=name, thesis=f"§6.2.2 extension-2 of Case 3b, Algorithm 6.6{what} (Figure 6.16, Table 6.2)",
        kit=Kit(edge=1, directional=True), bound="O(m)", markers="Σ_{k=1}^{⌈(n−1)/2⌉} k directional E-markers",
        deterministic=True, options=CLOSEST_FIRST, checks=MARKER_MAP_CHECKS, explorer=explorer,
        uses_lighthouse=False, parameters=(MARKERS,),
        kit_fn=lambda n, m, o: Kit(edge=_count(n, o, sum_to(ceil_half(n - 1))), directional=True),
        marker_bound_fn=lambda n, m: sum_to(ceil_half(n - 1)), family="robot", bound_bench="table-6.2",
        ways=("correct", "failed-out-of-markers", "drop-trip"), changes=changes,
        listing_entry=None if changes is None else "extension-2-listing")
      for name, what, explorer, changes in (
          ("extension-2", "", SavingEdgeCounts, _COME_BACK_SOMETIMES),
          ("extension-2-listing", " as listed", ListingSavingEdgeCounts, None))),
    AlgorithmSpec(
        name="extension-naive",
        thesis="§6.2.2 the naive extension of Case 3b, extension-2 without coming back: fails (Figure 6.15)",
        kit=Kit(edge=1, directional=True), bound=None,
        markers="at most Σ_{k=1}^{⌈(n−1)/2⌉} k directional E-markers (extension-2's kit)",
        deterministic=True, options=CLOSEST_FIRST, checks=MARKER_MAP_CHECKS, explorer=NaiveExtension,
        uses_lighthouse=False, parameters=(MARKERS,),
        kit_fn=lambda n, m, o: Kit(edge=_count(n, o, sum_to(ceil_half(n - 1))), directional=True),
        marker_bound_fn=lambda n, m: sum_to(ceil_half(n - 1)), family="robot", status="implemented, expected to fail",
        ways=("correct", "failed-out-of-markers", "drop-trip", "wrong-map"),
        status_reason="'this extension idea does not work when a loop edge e is explored ... and v_k has no "
                      "marked edges yet' (§6.2.2, Figure 6.15(b)-(c)): v_k is left unmarked and later taken for a "
                      "new place; on figure-6.15 the checker finds the wrong map"),
)
