"""§6.2.1 Case 5, Version-1 (Algorithm 6.4): k > 3 undirected V-markers, their number not known relative to the
world — Case 3a's unique counts while they last (phase I), then Algorithm 3.1's hypotheses with the closest
marked place as lighthouse (phase II) (thesis §6.2.1 Case 5, listing Algorithm 6.4).

* **Phase I** (lines 1–15): the i-th place discovered gets i markers, so a
  marked place names itself; a marked v_u is known by its count and its
  back-link is found by probing its other edges until a known neighbour over an
  explored edge is sensed (Algorithm 6.2 lines 19–35, reused from
  :class:`~topomark.reference.explorers.counted_markers.VertexCounts`).
* **Phase II** (lines 16–35): the first unmarked place the robot cannot mark
  ("does not have sufficient markers to uniquely mark the vertex", §6.2.1 Case 5) ends
  phase I.  A marked v_u is still validated by probing (§6.2.1 Case 5 "as in phase-I");
  an unmarked v_u is tested against every unexplored dart at an *unmarked*
  known end of its degree (:mod:`.case5_phase2`), each hypothesis driving the
  robot from v_k' to the marked place v_l closest to v_k' and on to a marked
  neighbour v_n of v_l (lines 21–24).  Reaching v_n by the expected exit of v_l
  fixes the entry edge at v_l (no multi-edges), so the embedded path is unique
  (§6.2.1 Case 5).

Decisions, with the thesis references (each tested in ``tests/test_markers_case5.py``):

* **Algorithm 6.4's counter** (lines 1–15): line 1 drops one marker at v0,
  line 3 sets i ← 1 and line 15 increments only after line 13's drop, so the
  first place discovered would get one marker too — the same label as v0,
  which contradicts "the unique marker count identifies v_u" (§6.2.1 Case 5).  We
  follow Algorithm 6.2 (Case 3a, which Version-1 says it combines, §6.2.1 Case 5): v0
  gets 1 and the j-th new place j + 1 (i ← 2 at line 3).  The literal counter
  cannot map the triangle, the smallest world with a loop edge: the loop edge's
  far end shows one marker, the label of two places (the ``failed`` outcome).
  :class:`ListingVertexCountsThenLighthouse` (``case-5-v1-listing``) counts as listed and fails there.
* **Where phase I ends.**  Line 12 "if the robot has at least i markers" is the
  robot trying the drop (the kernel's robot counts nothing; the simulator
  refuses a drop the kit cannot cover before anything changes,
  :mod:`.marker_walk`).  At that first refusal every known place is marked, so
  line 17's H is empty and v_u joins S unmarked at once (line 35) — no motion.
  Later unmarked places are not offered a drop again (line 12 with the same i
  would refuse again: i only grows on a drop).
* **Probing in phase II** (Algorithm 6.4 lines 8–9, probes "until an explored
  edge has been traversed", silent on unmarked neighbours): a probe that reaches an
  *unmarked* neighbour learns nothing (it may be new or a phase-II place), so
  the robot retraces and tries the next edge; the probe ends at the first
  *marked* neighbour over an explored edge.  One exists: every marked place
  other than v0 has its discoverer (marked) as a neighbour over an explored
  edge, and v0 has the second place (marked whenever K ≥ 3).
* **Lighthouse and neighbour** (lines 21–22): v_l is the marked place nearest
  v_k' in S (ties: the lower map vertex), reached by a shortest path of S (its
  inner places are unmarked, else one of them would be nearer); v_n is v_l's
  marked neighbour by the lowest explored exit — never on that path.
* "K > 3" (§6.2.1 Case 5) is the parameter's minimum; Version-1 itself would run from
  K = 3 (v0 and the second place marked).

Examples
--------
>>> VertexCountsThenLighthouse.name
'case-5-v1'
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature

from topomark.reference.explorers.algorithm31 import Hypothesis
from topomark.reference.explorers.policies import nearest
from topomark.reference.explorers.case5_phase2 import TwoPhases
from topomark.reference.explorers.counted_markers import VertexCounts
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.walker import tree_path

__all__ = ["VertexCountsThenLighthouse", "ListingVertexCountsThenLighthouse"]


class VertexCountsThenLighthouse(TwoPhases, VertexCounts):
    """Algorithm 6.4: unique V-marker counts (phase I), then hypotheses with the nearest marked lighthouse
    (phase II, held: :data:`~.case5_phase2.PHASE_TWO`, which asks :meth:`lighthouse_path` and :meth:`confirms`)."""

    name = "case-5-v1"
    literal = False  # True: Algorithm 6.4's counter as listed, i ← 1 at line 3 (ListingVertexCountsThenLighthouse)

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if sig.vertex_count:  # lines 7-10: the count names v_u; its back-link by probing
            self.one_place(it, sig.vertex_count, self.places_counted(sig.vertex_count))
            place = self.vertex_of.get(sig.vertex_count)
            if place is None or self.M.degree(place) != sig.degree:
                raise AlgorithmFailed(f"iteration {it.number} senses {sig}, which no marked place of the map shows")
            self.join_marked(it, place, sig)
        elif self.phase == 1:  # lines 11-15
            u = self.non_loop(it, sig)
            count = self.next_count()
            if self.try_drop(self.mark_op(count), it):
                self.name_vertex(u, count)
            else:  # line 16 at the first refusal: every known place is marked, H is empty, line 35
                self.phase, self.phase_two_from = 2, it.number
        else:  # lines 16-35
            self.phase_two.run(self, it, sig)

    def join_marked(self, it: MarkerStep, place: int, sig: Signature) -> None:
        """Lines 7-10: v_u is the marked ``place``; its back-link by probing."""
        self.probe(it, place, sig.degree)

    def next_count(self) -> int:
        """i at line 13: v0 has 1, the j-th place discovered gets j + 1 (the counter decision above); as listed
        (``literal``), i starts at 1 (line 3), so the j-th place gets j and the first one v0's count."""
        return len(self.count_of) + (0 if self.literal else 1)

    def places_counted(self, count: int) -> list[int]:
        """The places of the map marked with ``count`` markers (one, but for the listing's counter)."""
        return [v for v, c in self.count_of.items() if c == count]

    def one_place(self, it: MarkerStep | None, count: int, places: list[int]) -> None:
        """Algorithm 6.2 line 18 (which lines 8–9 follow) names v_u by its *unique* count: fail where the
        listing's counter gave ``count`` markers to more than one of ``places``."""
        if len(places) > 1:
            where = f"iteration {it.number}: " if it is not None else ""
            raise AlgorithmFailed(f"{where}{count} marker(s) mark {len(places)} places of the map (Algorithm 6.4's "
                                  "counter, lines 1, 3 and 13, gives v0 and the first new place one each): the "
                                  "count does not name the place")

    def explored_exit(self, x: int, sig: Signature) -> int | None:
        """Line 9 (Algorithm 6.2 lines 19–35): as :meth:`VertexCounts.explored_exit`; with the listing's counter a
        count two places share is read as "c ∈ s", the counts at the far ends of x's explored edges, and fails
        where it fits more than one of them (or, directional, names no one place)."""
        places = self.places_counted(sig.vertex_count) if sig.vertex_count else []
        if len(places) < 2:
            return super().explored_exit(x, sig)
        if self.directional:
            self.one_place(None, sig.vertex_count, places)
        ends = [(t, far[0]) for t, far in enumerate(self.M.links(x)) if far is not None and far[0] in places]
        self.one_place(None, sig.vertex_count, [w for _, w in ends])
        return ends[0][0] if ends else None

    def lighthouse_path(self, v: int) -> list[MapDart]:
        """Lines 21–24: a shortest path of S from v_k' = ``v`` to the nearest marked v_l, then to v_n."""
        light, parent = nearest(self.M, v, self.count_of)  # the least-numbered among the nearest marked
        if light is None:
            raise AlgorithmFailed(f"no marked place is connected to map vertex {v}")
        path = tree_path(parent, v, light)
        for t, far in enumerate(self.M.links(light)):
            if far is not None and far[0] in self.count_of:
                return path + [(light, t)]
        raise AlgorithmFailed(f"the lighthouse {light} has no marked neighbour over an explored edge")

    def confirms(self, h: Hypothesis) -> bool:
        """A hypothesis whose perceptions matched P^E throughout is confirmed (Algorithm 6.4 line 29)."""
        return True


class ListingVertexCountsThenLighthouse(VertexCountsThenLighthouse):
    """Algorithm 6.4 as listed (``case-5-v1-listing``): its counter gives v0 and the first new place one marker
    each, so a run fails where a count two places share must name v_u (the triangle, for one)."""

    name = "case-5-v1-listing"
    literal = True
