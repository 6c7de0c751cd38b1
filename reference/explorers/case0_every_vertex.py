"""§6.2.1 Case 0: n undirected markers, one dropped at every vertex as it is discovered — the thesis's
"plausible strategy", shown to fail (§6.2.1 Case 0, Figure 6.3).

"A vertex that contains a marker must be a known (visited) vertex in S, whereas
a vertex where no marker is sensed must be a new vertex.  When entering a
marked vertex, however, the robot may not be able to determine its place and
back-link" (§6.2.1 Case 0).  The explorer does exactly what the strategy allows and
nothing more:

* an unmarked v_u is new: non-loop augmentation, one marker dropped there;
* a marked v_u is known, and every unexplored dart (v_k', i') whose known end
  shows v_u's signature (marked, same degree; v_k' neither v_k nor a neighbour
  of it: no self-loops, no multi-edges) fits it.  The true e' is always one of
  them (e is new, so e' is unexplored, at a known place that shows what v_u
  shows), so exactly one fit is e' and the explorer joins e/e'.

Decision: when k > 1 darts fit, the explorer stops with the ``failed`` outcome
(:class:`~topomark.spec.errors.AlgorithmFailed`, reason "k edges fit; the robot
cannot determine which, §6.2.1 Case 0"), exit 1.  The thesis says so in as many words:
"the robot cannot determine if it is visiting v_k' or v_k''.  Thus this approach
does not work in general" (§6.2.1 Case 0) — it does not let the robot pick one.  Taking
the first would be a guess the robot knows to be one, and on some worlds the
checker would refute the map it claims.  No fitting dart is ``failed`` too (it
cannot happen in a simple world, as said above).

There is no listing: the explorer follows the text (§6.2.1 Case 0) and validates nothing with motion.  Leaving
out the darts at v_k and its neighbours (never e', §3.1.1) decides only where the run can go on without a guess:
a reading that kept them would stop, failed, at the first marked place they make ambiguous.

``tests/test_markers_case5.py`` shows why no choice can be right: the pairs of
worlds under ``tests/vectors/case0/`` (found by search over small worlds) give
the robot the same perceptions up to the first marked place, where several
edges fit, yet are not isomorphic; the explorer stops there on both.

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
    """Case 0: one undirected V-marker at every vertex discovered; a marked place that several edges fit stops
    the run (§6.2.1 Case 0)."""

    name = "case-0"
    undecided = None
    """The iteration that stopped the run, its ``candidates`` the darts that fit (None while it runs)."""

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
        if len(fits) > 1:
            self.undecided = it
            raise AlgorithmFailed(f"iteration {it.number}: v_u shows {sig}; {len(fits)} edges fit; the robot "
                                  "cannot determine which, §6.2.1 Case 0")
        self.loop(it, fits[0])
