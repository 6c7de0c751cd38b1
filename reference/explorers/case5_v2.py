"""§6.2.1 Case 5, Version-2 (Algorithm 6.5): k > 3 undirected V-E-markers, their number not known relative to
the world — Case 1b's footprint search with a double-marked lighthouse while markers last (phase I), then
Algorithm 3.1's hypotheses with v0 as the directional lighthouse (phase II) (thesis §6.2.1 Case 5, listing
Algorithm 6.5).

* **Line 1**: two markers at v0 and two on one of its edges, e0 (the exit the
  robot faces).  v0 is the only place with two markers and e0 the only edge with
  two, so entering v0 tells the entry edge by where e0 lies relative to it.
* **Phase I** (lines 5–13, 29–33): as Case 1b
  (:class:`~topomark.reference.explorers.edge_footprints.VertexEdgeFootprints`):
  an unmarked v_u is new and gets one marker; a one-marker v_u is known — one
  marker on e, back to v_k, search S for the place with one more marked edge.
* **Phase II** (lines 14–28, 34–37), once the pool is empty: a one- or
  zero-marker v_u is tested against every unexplored dart whose known end shows
  v_u's signature, each hypothesis driving the robot along a shortest path of S
  to v0 (:mod:`.case5_phase2`); the two markers on e0 sensed at v0 fix the
  entry, so the path is unique.

Decisions, with the thesis references (each tested in ``tests/test_markers_case5.py``):

* **Line 23** (Algorithm 6.5 line 23): "case P and P^E do not match throughout →
  confirm hypothesis" repeats line 21's condition; it must be "match
  throughout" (Algorithm 6.4 line 29, Algorithm 3.1).  We confirm on a full
  match; "exit for loop" is the inner while loop.  The literal line would
  confirm a hypothesis that line 21 has already rejected, and never one that
  matched.  On the smallest world where phase II must close a loop by a
  hypothesis — the paw (a triangle with a pendant edge, 4 places) entered from
  the pendant's free end with K = 4 — the literal reading adds the triangle's
  first place twice (the checker's ``wrong-map``); ours maps it (and every
  world of ≤ 5 places and degree ≤ 4 from every start, K = 4).
* **Line 28** (Algorithm 6.5 line 28): a one-marker v_u is always a phase-I place, so the
  non-loop branch after rejecting every hypothesis cannot be reached in a
  correct run; it is kept as Algorithm 3.1's non-loop augmentation (the checker
  would report the wrong map if it ever were).
* **The entry edge at v0** (§6.2.1 Case 5 "traversing edges in v0 looking for the edge
  with two markers"): under §6.1's sensing the robot senses the markers on
  v0's edges from v0 (``[d,V2,E2-p]``), so it reads the entry at once, no
  traversal.
* **Crossing e0 itself.**  e0 carries two markers and no loop marker is ever
  added to it: following e0 from v0 to a known place, the place is the far end
  of e0 (the only other place showing two markers on an edge), so loop
  augmentation needs no drop and no search; from the far end to v0 line 5
  applies.  (A third marker on e0 would break the search's "one more marked
  edge", §6.2.1 Case 1b.)
* **The pool.**  The thesis's markers are one homogeneous pool (§6.2): with
  ``--markers K`` the simulator's kit is a pool of exactly K vertex-or-edge
  markers and refuses any drop beyond it.  The robot also knows how many it
  carries (``options["markers"]``: only not how that compares with the world,
  §6.2.1 Case 5), so "if the robot has one or more markers" (lines 9, 31) is K minus
  the markers dropped, asked before a drop is tried.  With the default kit
  (``markers`` not given) the kit is exactly the split phase I spends and the
  pool is not counted.
* **Signature, not only the count** (lines 15–16, 35–36 say "contains one
  marker [no marker] and has the same degree"): H holds the darts whose known
  end shows v_u's whole signature, loop-edge markers included — the signature
  of §3.1.1/§6.1 the robot senses; the true e' always shows it.

Examples
--------
>>> VertexEdgeThenLighthouse.name
'case-5-v2'
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature

from topomark.reference.explorers.algorithm31 import Hypothesis
from topomark.reference.explorers.policies import nearest
from topomark.reference.explorers.case5_phase2 import TwoPhases
from topomark.reference.explorers.edge_footprints import FootprintSearch, VertexEdgeFootprints
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.walker import tree_path

__all__ = ["VertexEdgeThenLighthouse", "E0", "ListingVertexEdgeThenLighthouse"]

E0: MapDart = (0, 0)
"""The double-marked edge e0, as v0's map exit: the exit the robot faces at the start."""


class VertexEdgeThenLighthouse(TwoPhases, VertexEdgeFootprints):
    """Algorithm 6.5: Case 1b's search with a double-marked v0 and e0 (phase I), then hypotheses to v0 (phase
    II, held: :data:`~.case5_phase2.PHASE_TWO`, which asks :meth:`lighthouse_path` and :meth:`confirms`)."""

    name = "case-5-v2"

    def __init__(self, robot, policies=None, observer=None, options=None):
        super().__init__(robot, policies, observer, options)
        self.pool = self.options.get("markers")  # K, or None: the default kit, enough for phase I

    def left(self) -> int | None:
        """Markers left in the pool (None: not counted, the default kit)."""
        return None if self.pool is None else self.pool - self.dropped

    def has_markers(self, it: MarkerStep) -> bool:
        """Lines 9 and 31: "if the robot has one or more markers"; the first no ends phase I."""
        left = self.left()
        if left is None or left > 0:
            return True
        if self.phase_two_from is None:
            self.phase_two_from = it.number
        return False

    def begin(self) -> None:
        """Line 1: two markers at v0, two on the edge it faces (e0)."""
        self.drop(MarkerOp("vertex", count=2))
        self.drop(MarkerOp("edge", exit=0, count=2))

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        it.candidates, it.found = [], None
        if it.edge == E0:  # e0 from v0: its far end, if known, shows the other end of e0
            far = self.far_end_of_e0()
            if far is not None:
                self.loop(it, far)
                return
        if sig.vertex_count == 2:  # lines 5-7: v0, entered at the exit e0 lies p before
            p = next(p for p, count, _ in sig.edges if count == 2)
            self.loop(it, (0, (0 - p) % sig.degree))
        elif sig.vertex_count == 1:  # lines 8-28
            if self.has_markers(it):
                self.validate(it, sig)  # lines 10-13: the footprint search of Case 1
            else:
                self.phase_two.run(self, it, sig)
        elif self.has_markers(it):  # lines 31-33
            self.non_loop(it, sig)
            self.drop(MarkerOp("vertex"), it)
        else:  # lines 34-37
            self.phase_two.run(self, it, sig)

    def far_end_of_e0(self) -> MapDart | None:
        """The dart of e0 at its far end, if S knows that place (it shows two markers on that exit)."""
        for v in self.M.vertices:
            if v != 0:
                for dm in self.M.dart_marks(v):
                    if dm.count == 2:
                        return (v, dm.exit)
        return None

    def mark_loop_edge(self, it: MarkerStep, sig: Signature) -> bool:
        """Line 11: one marker on e (the pool has one: :meth:`has_markers` said so)."""
        return FootprintSearch.mark_loop_edge(self, it, sig)

    def lighthouse_path(self, v: int) -> list[MapDart]:
        """A shortest path of S from v_k' = ``v`` to v0 (§6.2.1 Case 5: v0 is the directional lighthouse)."""
        reached, parent = nearest(self.M, v, (0,))
        if reached is None:
            raise AlgorithmFailed(f"internal: v0 is not connected to map vertex {v}")
        return tree_path(parent, v, 0)

    def confirms(self, h: Hypothesis) -> bool:
        """A hypothesis whose perceptions matched P^E throughout is confirmed: line 23 read as "match
        throughout" (the decision above; read literally, "do not match throughout", it would never confirm one).
        As listed (``literal``): never — a hypothesis that matched throughout is not confirmed."""
        return not self.literal


class ListingVertexEdgeThenLighthouse(VertexEdgeThenLighthouse):
    """Algorithm 6.5 as listed (``case-5-v2-listing``): phase I's search as Algorithm 6.1 lines 11–19 list it
    (Case 1b's, line 12), and line 23 as printed, so phase II confirms no hypothesis and maps a loop it must close
    by one (the paw with K = 4) wrongly."""

    name = "case-5-v2-listing"
    literal = True
