"""The thesis's listings that cannot be implemented from the thesis: Algorithm 3.2 (§3.6.2) and Algorithm 6.9
(§6.3.3) — listed by ``topomark algorithms`` with the reason, refused by ``topomark explore``.

Every other listing of the thesis (Algorithms 3.1, 4.1–4.5, 5.1, 6.1–6.8) is a
registered algorithm; the failing ideas the thesis describes without a listing
(Case 0; the undirected saving of Case 3b, §6.2.1 Case 4; the naive directional
extension, §6.2.2) are registered too, with the status "implemented, expected
to fail".

Examples
--------
>>> [entry.name for entry in LISTED]
['path-execution', 'explore-merge']
"""

from __future__ import annotations

from topomark.reference.algorithms.algorithm_spec import Listed

__all__ = ["LISTED"]

LISTED = (
    Listed(
        name="path-execution", thesis="§3.6.2, Algorithm 3.2",
        reason="it drives the physical robot of §3.6 through hallways and junctions from panoramic camera "
               "pictures (Algorithm 3.2: 'take a panoramic picture', line 3; §3.6.2: the sensing and motion 'to navigate a "
               "hallway-like environment'); a world here is a rotation system with no pictures, and the robot interface's move by relative exit is "
               "what the listing provides to Algorithm 3.1 (run it with --algorithm basic)"),
    Listed(
        name="explore-merge", thesis="§6.3.3, Algorithm 6.9 (Algorithm 6.8; l < c(G), explore-merge)",
        reason="its merging phase (lines 8 and 13, 'merge S_i into S_B') is 'the merging algorithm described in "
               "[59, 61]' (§6.3.3), cited, not given: the thesis says only that one map's vertices and edges are "
               "disambiguated against the other's 'using some marking aid', that 'the thread could be used as a "
               "movable (directional) marker (See [59, 61] for details)' (§6.3.3) and that some are told apart "
               "'without traversals (see [59])' (§6.3.3); [59] merges the maps of two robots, each with an "
               "undirected movable marker (§2.3.1).  How one robot with a thread disambiguates two maps, at what "
               "cost (the O(mn) of §6.3.3), is not in the thesis; the explore-explore approach, Algorithm 6.8, "
               "is --algorithm thread-explore"),
)
