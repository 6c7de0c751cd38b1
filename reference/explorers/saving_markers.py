"""Saving E-markers in the O(m) algorithm with directional markers: extension-1 and extension-2 (Algorithm 6.6)
(thesis §6.2.2, Figures 6.15, 6.16; Table 6.2).

With directional E-markers "one (directed) marked edge is sufficient to
identify a vertex as well as its edges" (§6.2.2): a unique count names the
edge, its head or tail names which end the robot stands at, its relative exit
names the entry edge.  So Case 3b's marks are needed only where a place would
otherwise have none.  Both extensions explore closest-first (the ``nearest``
edge policy: the robot always takes an unexplored edge of the closest known
vertex, its own first) and mark an edge e = (v_k, v_u) only if v_k has no
marked edge yet:

* **extension-1** (:class:`MarkFirstEdges`, §6.2.2): marks e whether it is a loop
  or a non-loop edge, so the decision is known at v_k and the markers are
  dropped in transit (before following e): no extra traversal.  At most
  Σ_{k=1}^{⌈m/2⌉} k markers (§6.2.2, stated without a derivation; ours: every
  marked edge but v0's first has a v_k discovered over a blank edge, distinct
  for each, so at most (m+1)/2 edges are marked — the ceiling holds);
* **extension-2** (:class:`SavingEdgeCounts`, Algorithm 6.6): marks non-loop edges
  only (line 9–11: "the robot goes back on e, drops i markers on e and back", two
  traversals: a drop trip, purpose ``drop``, :mod:`topomark.reference.run.simulator`); after a loop edge from an unmarked v_k, the
  robot "comes back to v_k" (line 19–20, purpose ``travel``) — decision: only if
  v_k still has unexplored edges (§6.2.2: "unless v_k has no unexplored edges
  now").  At most Σ_{k=1}^{⌈(n−1)/2⌉} k markers (§6.2.2; Table 6.2's floors
  are the misprint: a chain of 4 places marks 2 edges, ⌊3/2⌋ = 1).

Decisions, with the thesis references:

* **The marker's head points at v_u** (§6.2.2 and Algorithm 6.6,
  leave it unspecified): the robot drops at v_k on e with its tail at v_k
  (``E-p-T`` there, ``E-p-H`` at v_u), so a sensed ``H`` means "I stand at the end discovered over this edge".
* Algorithm 6.6 line 5 senses at v_k before line 6 moves there: S already shows
  v_k's marks, so the robot reads them from S.
* A loop edge's identification must be unique; if the marks ever fit more than
  one unexplored edge of the map, or none, the run stops with
  :class:`~topomark.spec.errors.AlgorithmFailed` (never silently).

Correspondence with Algorithm 6.6 (``extension-2``): line 4 → the ``nearest`` edge policy (closest first);
line 5 → :meth:`SavingEdgeCounts.marked` (read from S); lines 6–7 → the walker's loop; lines 8–13 → the first
branch of :meth:`SavingEdgeCounts.arrive` (lines 9–11, the drop trip, → ``drop_on``); lines 14–18 →
:meth:`SavingEdgeCounts.identify` and the loop augmentation; lines 19–20 → the come-back, taken only while v_k
has an unexplored edge, as §6.2.2's text says — a change to the listing's moves (``changes`` in its
registration); :class:`ListingSavingEdgeCounts` (``extension-2-listing``) takes lines 19–20 as listed.  ``extension-1`` has no listing; it follows §6.2.2's text (markers on e in transit from an
unmarked v_k, :meth:`MarkFirstEdges.depart`, loop edge or not).

Examples
--------
>>> ceil_half(5), ceil_half(6)
(3, 3)
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.closest_first import NEAREST
from topomark.reference.explorers.marker_walk import MarkerStep, MarkerWalk

__all__ = ["SavingEdgeCounts", "ListingSavingEdgeCounts", "MarkFirstEdges", "ceil_half"]


def ceil_half(k: int) -> int:
    """⌈k/2⌉ for k ≥ 0."""
    return (k + 1) // 2


class SavingEdgeCounts(MarkerWalk):
    """Extension-2, Algorithm 6.6: Σ_{k=1}^{⌈(n−1)/2⌉} k directional E-markers, O(m)."""

    name = "extension-2"
    edge_policy = NEAREST  # rule (1) of §6.2.2: closest first, whatever edge policy was given
    come_back = True  # rule (3), lines 19-20; False is the naive extension that fails (§6.2.2, Figure 6.15(b)-(c))
    literal = False  # True: lines 19-20 as listed, back to an unmarked v_k after every loop edge

    def __init__(self, robot, policies=None, observer=None, options=None):
        super().__init__(robot, policies, observer, options)
        self.next_count = 1  # i (line 2)
        self.ends: dict[int, tuple[MapDart, MapDart]] = {}  # count -> (tail dart at v_k, head dart at v_u)

    def marked(self, v: int) -> bool:
        """Whether map vertex ``v`` has a marked edge (what the robot senses there, read from S)."""
        return bool(self.M.dart_marks(v))

    def drop_on(self, it: MarkerStep, exit_: int) -> int:
        """Drop the next count on the edge at map exit ``exit_`` of where the robot stands, tail here."""
        v, entry = self.position
        count = self.next_count
        self.drop(MarkerOp("edge", exit=(exit_ - entry) % self.M.degree(v), count=count, direction="T"), it)
        self.next_count += 1
        return count

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        vk = it.edge[0]
        if not sig.edges:  # line 8: v_u has no marked edge: a new place
            u = self.non_loop(it, sig)
            if not self.marked(vk):  # lines 9-11: back on e, drop i markers on e, and back
                self.leave((u, 0), "drop")
                count = self.drop_on(it, it.edge[1])
                self.leave(it.edge, "drop")
                self.record_marks()
                self.ends[count] = (it.edge, (u, 0))
            return
        self.loop(it, self.identify(it, sig, sig.edges))  # lines 15-18
        if self.come_back and not self.marked(vk) and (self.literal or any(x is None for x in self.M.links(vk))):
            self.leave(self.position, "travel")  # lines 19-20 (ours: only while v_k has an unexplored edge)

    def identify(self, it: MarkerStep, sig: Signature, items) -> MapDart:
        """Lines 15–16: the unexplored dart e' = (v_k', j) that the marked edges ``items`` sensed at v_u name."""
        matches = set()
        for p, count, end in items:
            ends = self.ends.get(count)
            if ends is None or end not in ("H", "T"):
                raise AlgorithmFailed(f"iteration {it.number}: the marks {sig} at v_u name no edge of the map")
            x, t = ends[1] if end == "H" else ends[0]
            j = (t - p) % self.M.degree(x)
            if self.M.degree(x) == sig.degree and self.M.arc((x, j)) is None \
                    and signature_at(self.M, x, j).edges == tuple(sorted(items)):
                matches.add((x, j))
        if len(matches) != 1:
            raise AlgorithmFailed(f"iteration {it.number}: the marked edges at v_u, {sig}, fit {len(matches)} "
                                  f"unexplored edges of the map {sorted(matches)}, not one")
        return matches.pop()


class ListingSavingEdgeCounts(SavingEdgeCounts):
    """Algorithm 6.6 as listed (``extension-2-listing``): lines 19–20 bring the robot back to an unmarked v_k
    after every loop edge, whether or not v_k has an unexplored edge left."""

    name = "extension-2-listing"
    literal = True


class MarkFirstEdges(SavingEdgeCounts):
    """Extension-1: also mark a loop edge whose v_k has no marked edge, in transit; Σ_{k=1}^{⌈m/2⌉} k (§6.2.2)."""

    name = "extension-1"
    pending: int | None = None  # the count dropped on e in transit this iteration

    def depart(self, it: MarkerStep) -> None:
        """At v_k with no marked edge: drop the next count on e before following it (in transit)."""
        self.pending = None
        if not self.marked(it.edge[0]):
            self.pending = self.drop_on(it, it.edge[1])

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        others = tuple(e for e in sig.edges if self.pending is None or e[0] != 0)  # e's own mark excluded
        if not others:
            u = self.non_loop(it, sig)
            if self.pending is not None:
                self.ends[self.pending] = (it.edge, (u, 0))
            return
        far = self.identify(it, sig, others)
        self.loop(it, far)
        self.record_marks()  # e's mark, seen from v_k'
        if self.pending is not None:
            self.ends[self.pending] = (it.edge, far)
