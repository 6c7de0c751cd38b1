"""Case 4: the closest-first extensions of the two O(mn) E-marker algorithms — Algorithm 6.3 (Case 1a's m
markers cut to m − ⌊(n−1)/2⌋) and the extension of Case 2 (m + n cut to about m) (thesis §6.2.1,
Case 4, Algorithm 6.3, Figure 6.9).

The rules (Case 4), over the footprints search of
:mod:`.edge_footprints`:

1. "chooses edge e = (v_k, v_u) where v_k is the closest known place to the
   current place of robot" — the ``nearest`` choice (ties by U's order),
   whatever edge policy is given: the pattern is part of the algorithm;
2. a loop edge is always marked (one marker, as in Cases 1a and 2);
3. a non-loop edge is marked "*only* if v_k has no marked edge yet" (one
   marker in Algorithm 6.3, two in the extension of Case 2, §6.2.1 Case 4).

So every visited vertex has a marked edge before the robot can enter it
again: a new vertex reached over a blank edge is where the robot stands, and
rule 1 makes its next edge the first one explored, marked by rule 2 or 3
(§6.2.1 Case 4).  The search is Case 1a's (Algorithm 6.3 lines 14–24) or Case
2's (c_1 and c_2).

Correspondence with Algorithm 6.3: line 3 → rule 1 (``edge_policy``); lines 5–6 and 16–17 →
:meth:`ClosestFirst.non_loop_markers` and the loop marker (dropped from v_u, the same edge marked either way);
lines 7–13 → the footprint loop's new-place branch; lines 14–24 → its search, which changes the listing's
moves as every footprint search does (:mod:`.edge_footprints`; ``changes`` in the registrations).

Decision: **m − ⌊(n−1)/2⌋, not m − ⌊n/2⌋** (§6.2.1 Case 4).  The thesis counts
"the m − (n − 1) loop edges" and "Maximumly, half (⌈(n−1)/2⌉) of the
non-loop edges", which is m − (n − 1) + ⌈(n−1)/2⌉ = m − ⌊(n−1)/2⌋; the
same paragraph then says "Totally m − ⌊n/2⌋ markers are sufficient", one too few
for even n.  The half is right: a non-loop edge is marked only when both its
ends are still unmarked (v_k by rule 3, v_u new), and marks both, so the
marked non-loop edges share no end: at most ⌊n/2⌋ = ⌈(n−1)/2⌉ of them.  It
is reached: on the 4-cycle from v0 the robot marks (v0, v1), leaves
(v1, v2) blank, marks (v2, v3) and the loop edge (v3, v0) — 3 markers,
where m − ⌊n/2⌋ = 2 (and on the single edge, n = 2: 1 marker, not 0).  So
``case-4`` is given, and checked against, m − ⌊(n−1)/2⌋; ``--markers 2`` on
the 4-cycle runs out (``tests/test_markers_621.py``).  Likewise the
extension of Case 2 needs m − (n − 1) + 2⌈(n−1)/2⌉, which is m for odd n
but m + 1 for even n (§6.2.1 Case 4 says "m markers are sufficient"; the 4-cycle
needs 5 = m + 1).

Examples
--------
>>> ClosestFirst.name, ClosestFirstDouble.name
('case-4', 'case-4-mn')
"""

from __future__ import annotations


from topomark.reference.explorers.policies import Policies
from topomark.reference.explorers.edge_footprints import DoubleMarkedEdges, EdgeFootprints

__all__ = ["ClosestFirst", "ClosestFirstDouble", "NEAREST", "ListingClosestFirst", "ListingClosestFirstDouble"]

NEAREST = Policies(edge="nearest")
"""Rule (1), §6.2.1 Case 4: the edge whose known end is closest to the robot (ties by U's order)."""


class ClosestFirst(EdgeFootprints):
    """Algorithm 6.3: Case 1a's E-markers, a non-loop edge marked only from an unmarked v_k (§6.2.1 Case 4)."""

    name = "case-4"

    edge_policy = NEAREST  # rule (1): closest first, whatever edge policy was given

    def non_loop_markers(self, vk: int) -> int:
        """Rule (3), Algorithm 6.3 lines 5–6: one marker on e if v_k has no marked edge, else none."""
        return 0 if self.M.dart_marks(vk) else 1


class ListingClosestFirst(ClosestFirst):
    """Algorithm 6.3 as listed (``case-4-listing``): its search as lines 18–24 list it."""

    name, literal = "case-4-listing", True


class ClosestFirstDouble(DoubleMarkedEdges):
    """The extension of Case 2 (§6.2.1 Case 4): two markers on a non-loop edge only from an unmarked v_k."""

    name = "case-4-mn"

    edge_policy = NEAREST  # rule (1): closest first, whatever edge policy was given

    def non_loop_markers(self, vk: int) -> int:
        """Two markers on e if v_k has no marked edge, else none (§6.2.1 Case 4)."""
        return 0 if self.M.dart_marks(vk) else 2


class ListingClosestFirstDouble(ClosestFirstDouble):
    """The closest-first extension of Case 2 with the search as listed (``case-4-mn-listing``)."""

    name, literal = "case-4-mn-listing", True
