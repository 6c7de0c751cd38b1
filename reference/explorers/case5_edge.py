"""§6.2.1 Case 5 with E-markers: k > 3 undirected E-markers, their number not known relative to the world —
Case 3b's unique counts on non-loop edges while they last (phase I), then Algorithm 3.1's hypotheses with the
nearest marked edge as lighthouse (phase II) (thesis §6.2.1 Case 5: "A similar E-marker algorithm can be developed using
the technique in the Σ_{k=1}^{n−1} k E-marker algorithm (Case 3b) and the single directional E-marker algorithm").

The thesis only names this version; it is built as Version-1 is (Algorithm
6.4), with Case 3b's marks in place of Case 3a's:

* **Phase I** (Case 3b, §6.2.1): an unmarked v_u (no marked edge) is new;
  the robot walks back over e to v_k, drops the next count on e and returns (a
  drop trip, §6.2.1 Case 3b), so the marked edges form a spanning tree of the phase-I
  places and each names its two ends.  A v_u with marked edges is known at once
  by their counts and positions (Case 3b's identification), in either phase.
* **Where phase I ends** (as Version-1's line 12, Algorithm 6.4, reads for us): the
  first drop the simulator refuses.  The robot has walked back to v_k and
  returns to v_u with nothing dropped; v_u joins S unmarked (every known place
  has a marked edge then, so it is new) and phase II begins.  No drop is tried
  again.
* **Phase II** (Algorithm 6.4 lines 16–35, :mod:`.case5_phase2`): an unmarked
  v_u may be new or a phase-II place; each unexplored dart at a known end with
  no marked edge and v_u's degree is a hypothesis h'.  Decision (the thesis
  gives no lighthouse for this version; §6.2.1 Case 5 give Version-1's): M_h'
  walks a shortest path of S from v_k' to the nearest place v_l with a marked
  edge, then crosses v_l's marked edge of least count to its other end v_n.
  The count names the edge, so v_l is one of its two ends; arriving at v_n over
  it with the expected marks at both ends fixes which end and the entry edge at
  v_l, as Version-1's v_l-then-v_n does (§6.2.1 Case 5).

There is no listing for this version ("a similar E-marker algorithm", §6.2.1 Case 5): it follows Case 3b's
text in phase I and Algorithm 6.4 lines 16–35 in phase II (H as line 17–18 with the marks for the signature,
hypotheses in turn as lines 19–30, augmentation as lines 31–35), with the choices above.

Kit: K undirected E-markers (``--markers K``, K > 3, §6.2.1 Case 5); the default is
Case 3b's Σ_{k=1}^{n−1} k, which marks every non-loop edge of the exploration
tree, so phase II never runs and the algorithm is Case 3b (O(m), §6.2.1 Case 4); with
fewer markers the bound is Table 6.1's O(m²n).

Examples
--------
>>> EdgeCountsThenLighthouse.name
'case-5-edge'
"""

from __future__ import annotations

from typing import cast

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature

from topomark.reference.explorers.algorithm31 import Hypothesis
from topomark.reference.explorers.case5_phase2 import TwoPhases
from topomark.reference.explorers.counted_markers import EdgeCounts
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.policies import nearest
from topomark.reference.explorers.walker import tree_path

__all__ = ["EdgeCountsThenLighthouse"]


class EdgeCountsThenLighthouse(TwoPhases, EdgeCounts):
    """Case 3b's unique edge counts (phase I), then hypotheses to the nearest marked edge (phase II)."""

    name = "case-5-edge"

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if sig.edges:  # a phase-I place: its marked edges name it and the entry (Case 3b)
            self.loop(it, self.identify(it, sig))
        elif self.phase == 1:
            u = self.non_loop(it, sig)
            if not self.mark_tree_edge(it, u):
                self.phase, self.phase_two_from = 2, it.number
        else:
            self.phase_two.run(self, it, sig)

    def mark_tree_edge(self, it: MarkerStep, u: int) -> bool:
        """Case 3b's drop trip (back over e to v_k, drop the next count on e, back to v_u); False if the
        simulator refused the drop (nothing dropped: phase I is over)."""
        count = self.next_count
        self.leave((u, 0), "drop")
        dropped = self.try_drop(MarkerOp("edge", exit=0, count=count), it)
        self.leave(it.edge, "drop")
        if dropped:
            self.record_marks()  # v_u now senses the marked e too
            self.tree[count] = cast("tuple[MapDart, MapDart]", it.joined)  # e was joined
            self.next_count += 1
        return dropped

    def lighthouse_path(self, v: int) -> list[MapDart]:
        """A shortest path of S from v_k' = ``v`` to the nearest v_l with a marked edge, then over that edge."""
        exits: dict[int, int] = {}
        for count in sorted(self.tree):  # the least count at each marked place
            for x, t in self.tree[count]:
                exits.setdefault(x, t)
        light, parent = nearest(self.M, v, exits)
        if light is None:
            raise AlgorithmFailed(f"no place with a marked edge is connected to map vertex {v}")
        return tree_path(parent, v, light) + [(light, exits[light])]

    def confirms(self, h: Hypothesis) -> bool:
        """A hypothesis whose perceptions matched P^E throughout is confirmed (Algorithm 6.4 line 29)."""
        return True
