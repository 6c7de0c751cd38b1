"""Two ways of saving markers that the thesis shows fail: the undirected saving of Case 3b (§6.2.1 Case 4,
Figure 6.10) and the naive directional extension of Case 3b (§6.2.2, Figure 6.15(b)–(c)).

Both take Algorithm 6.3's idea (§6.2.1 Case 4) — explore closest-first and mark a
non-loop edge e = (v_k, v_u) "only if v_k has no marked edge yet" — into an
algorithm whose places are named by a unique count of E-markers, and both mark
no loop edge.  They are registered so that the checker judges them like any
algorithm, with the status "implemented, expected to fail":

* **Undirected saving** (:class:`UndirectedSaving`, ``case-3b-saving``): Case
  3b (:class:`~.counted_markers.EdgeCounts`) with rule (3) of Algorithm 6.3.  The
  thesis: "these marked edges may not always identify a visited vertex and its
  incident edges.  That is, the situation shown in Figure 6.8(c) ... which is
  impossible in the original algorithm, can now happen" (§6.2.1 Case 4): two
  neighbours whose only marked edge is the one joining them show the same
  signature (``[3,A,E1-1]``, Figure 6.10(b)).  Decision: the explorer
  identifies a marked v_u as Case 3b does; when the marks fit more than one
  unexplored edge of the map it stops with the ``failed`` outcome (the robot
  cannot tell v_k' from its neighbour, and picking one would be a guess it knows
  to be one — as for Case 0).  A place left without a marked edge (a loop
  edge explored from an unmarked v_k, §6.2.2's flaw, which this variant shares)
  is taken for a new one when entered again: the checker finds the wrong map.
* **Naive extension** (:class:`NaiveExtension`, ``extension-naive``): extension-2
  (Algorithm 6.6) without rule (3), lines 19–20: after a loop edge from an
  unmarked v_k the robot goes on closest-first from v_k', "leaving v_k unmarked"
  (§6.2.2, Figure 6.15(c)); a later entry into v_k senses no marked edge and
  takes it for a new place: ``wrong-map``.

Neither has a listing of its own; each follows the text quoted above, on its base's steps (Case 3b's, and
Algorithm 6.6's without lines 19–20), and makes no choice that changes the moves.

The figures' drawings are not in the text; the worlds that show each failure
are rebuilt from the captions in :mod:`topomark.reference.worlds.figures`.

Examples
--------
>>> UndirectedSaving.name, NaiveExtension.name, NaiveExtension.come_back
('case-3b-saving', 'extension-naive', False)
"""

from __future__ import annotations

from topomark.spec.signature import Signature

from topomark.reference.explorers.closest_first import NEAREST
from topomark.reference.explorers.counted_markers import EdgeCounts
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.saving_markers import SavingEdgeCounts

__all__ = ["UndirectedSaving", "NaiveExtension"]


class UndirectedSaving(EdgeCounts):
    """Case 3b's unique counts of undirected E-markers, a non-loop edge marked only from an unmarked v_k,
    closest-first (§6.2.1 Case 4, Figure 6.10): expected to fail."""

    name = "case-3b-saving"
    edge_policy = NEAREST  # Algorithm 6.3's rule (1), §6.2.1 Case 4: the idea being tried needs it

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if sig.edges:  # marked: a known place, named (if it can be) by its marks, as in Case 3b
            self.loop(it, self.identify(it, sig))
            return
        unmarked_vk = not self.M.dart_marks(it.edge[0])
        u = self.non_loop(it, sig)
        if unmarked_vk:  # Algorithm 6.3 rule (3), §6.2.1 Case 4, with Case 3b's unique count (§6.2.1 Case 4)
            self.mark_tree_edge(it, u)


class NaiveExtension(SavingEdgeCounts):
    """Extension-2 (Algorithm 6.6) without lines 19–20: no coming back to an unmarked v_k after a loop edge
    (§6.2.2, Figure 6.15(b)–(c)): expected to fail."""

    name = "extension-naive"
    come_back = False
