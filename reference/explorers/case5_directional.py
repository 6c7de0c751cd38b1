"""§6.2.2 Table 6.2's row "unknown k > 3" with *directional* markers: Case 5 Version-1 (Algorithm 6.4) whose
V-markers point at the entry edge, so every marked place is a directional lighthouse (thesis Table 6.2;
Version-1, §6.2.1 Case 5, listing Algorithm 6.4; directional counts, §6.2.2).

Table 6.2 gives the row an O(m²n) bound in its directional column and no
algorithm of its own.  This is the one we give it: Version-1, with the
markers of the Σ k directional V-marker algorithm (§6.2.2: "the robot
drops the markers in such a way that the entry edge is indicated ... each
visited vertex is a directional lighthouse").

* **Phase I**: the i-th place discovered gets i markers pointing at its entry
  edge (v0's at the exit it faces).  A marked v_u is known by its count and its
  entry edge by where the markers point: loop augmentation at once, no probing
  (§6.2.2), where Version-1 probes its other edges (Algorithm 6.4 line 8).
* **Phase II** (the first refused drop, as in Version-1): an unmarked v_u is
  tested against every unexplored dart at an unmarked known end of its degree
  (Algorithm 6.4 lines 17–18), each hypothesis driving the robot along a
  shortest path of S from v_k' to the nearest marked place v_l.  Decision
  (§6.2.1 Case 5 ask for v_l *then a marked neighbour v_n* to fix the entry at an
  undirected v_l): with directional markers the path ends at v_l, since the
  direction of its markers, sensed relative to the entry, already gives the
  entry edge — the expected perception P^E at v_l holds its count and
  direction, so a full match fixes the embedded path (§6.2.1 Case 5).  A marked v_u in
  phase II is, as in phase I, known at once.

Cost O(m²n) with few markers (Table 6.2); with Σ_{k=1}^{n} k markers (every
place marked) it is the Σ k directional V-marker algorithm's O(m)-like
exploration without the blank place (tested: no hypothesis).

Examples
--------
>>> DirectionalCountsThenLighthouse.name, DirectionalCountsThenLighthouse.directional
('case-5-directional', True)
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature

from topomark.reference.explorers.case5_v1 import VertexCountsThenLighthouse
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.policies import nearest
from topomark.reference.explorers.walker import tree_path

__all__ = ["DirectionalCountsThenLighthouse", "ListingDirectionalCountsThenLighthouse"]


class DirectionalCountsThenLighthouse(VertexCountsThenLighthouse):
    """Version-1 with directional V-markers: each marked place names itself and its entry edge (module docstring)."""

    name = "case-5-directional"
    directional = True

    def join_marked(self, it: MarkerStep, place: int, sig: Signature) -> None:
        """A directional lighthouse gives place and back-link at once: the head points at exit 0 (§6.2.2)."""
        if sig.vertex_direction is None:
            super().join_marked(it, place, sig)
        else:
            self.loop(it, (place, (0 - sig.vertex_direction) % sig.degree))

    def lighthouse_path(self, v: int) -> list[MapDart]:
        """A shortest path of S from v_k' = ``v`` to the nearest marked v_l (its direction gives the entry)."""
        light, parent = nearest(self.M, v, self.count_of)
        if light is None:
            raise AlgorithmFailed(f"no marked place is connected to map vertex {v}")
        return tree_path(parent, v, light)


class ListingDirectionalCountsThenLighthouse(DirectionalCountsThenLighthouse):
    """Version-1 with directional V-markers and Algorithm 6.4's counter as listed (``case-5-directional-listing``):
    v0 and the first new place both show one marker, so a run fails where that count must name v_u."""

    name = "case-5-directional-listing"
    literal = True
