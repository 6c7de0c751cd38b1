"""§6.2.1 Case 0: n undirected markers, one dropped at every vertex as it is discovered — the thesis's
"plausible strategy", shown to fail (L1489–L1491, Figure 6.3).

"A vertex that contains a marker must be a known (visited) vertex in S, whereas
a vertex where no marker is sensed must be a new vertex.  When entering a
marked vertex, however, the robot may not be able to determine its place and
back-link" (L1491).  The explorer does exactly what the strategy allows and
nothing more:

* an unmarked v_u is new: non-loop augmentation, one marker dropped there;
* a marked v_u is known, but every unexplored dart (v_k', i') whose known end
  shows v_u's signature (marked, same degree; v_k' neither v_k nor a neighbour
  of it: no self-loops, no multi-edges) fits it.  The strategy offers nothing
  to tell them apart, so the explorer takes the first in U's order (a guess —
  correct whenever only one fits) and joins e/e'.  No fitting dart is the
  ``failed`` outcome.

Since the explorer's every motion is a function of the perceptions so far, two
worlds that give it the same perception sequence get the same map, and if they
are not isomorphic one of the two maps is wrong.  ``tests/test_markers_case5.py``
certifies such a pair (found by search over small worlds, written as test
vectors under ``tests/vectors/case0/``).

Examples
--------
>>> EveryVertexMarked.name
'case-0'
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.kit import MarkerOp
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.policies import open_ends_beyond
from topomark.reference.explorers.marker_walk import MarkerStep, MarkerWalk

__all__ = ["EveryVertexMarked"]


class EveryVertexMarked(MarkerWalk):
    """Case 0: one undirected V-marker at every vertex discovered; a marked place is guessed (L1491)."""

    name = "case-0"

    def begin(self) -> None:
        """The marker at v0."""
        self.drop(MarkerOp("vertex"))

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if not sig.vertex_count:  # "a vertex where no marker is sensed must be a new vertex"
            self.non_loop(it, sig)
            self.drop(MarkerOp("vertex"), it)
            return
        beyond = open_ends_beyond(self.M, it.edge[0])  # U's entries at places other than v_k and its neighbours
        fits = [d for d in self.M.unexplored.at(beyond) if signature_at(self.M, *d) == sig]
        if not fits:
            raise AlgorithmFailed(f"iteration {it.number}: v_u shows {sig}, but no unexplored edge of the map "
                                  "leads from a known place that shows it")
        it.candidates = fits  # what the strategy cannot tell apart (Figure 6.3(b): v_k' or v_k'')
        self.loop(it, fits[0])
