"""Exploring a labelled graph depth first: every place carries a distinct label, O(m) (thesis §2.3.1;
Table 2.3's labelled-graph row, Table 2.2).

"By marking each visited vertex and edge uniquely, at a new vertex the robot can
determine 'have I been here' and 'by which exit did I arrive' without any
further validation.  Without the need for both validations, the mapping problem
can be solved using search algorithms such as Depth-first search (DFS) …, which
have O(m) cost" (§2.3.1).  The robot labels every place as it discovers it and
explores depth first:

* **The label.**  Map vertex v (numbered in order of discovery, v0 = 0) gets
  label v + 1, simulated by v + 1 homogeneous markers ("by using i identical
  markers in place of a distinct marker with label i", §2.3.1), all
  *directional*, pointing along v's exit 0 (the edge it was first entered by;
  v0's, the exit the robot faced at the start).
* **At v_u.**  No marker: a new place — non-loop augmentation, then its label.
  A label L: the place is map vertex L − 1, and the markers' direction, sensed
  relative to the entry, is where its exit 0 lies, so the robot entered by map
  exit −direction (mod its degree): e' at once, no motion, no search.
* **Depth first.**  The next edge is the newest one of U (the ``lifo`` choice),
  reached by a shortest path of S.

Decisions, with the thesis references (each shown in ``tests/test_baselines.py``):

* **Vertex labels with a direction, not m + n labels.**  Table 2.3 counts m + n
  distinct markers, "one on each visited vertex and edge" (§2.3.1, Table 2.2).  A label
  that points along an edge tells the robot its entry exit as well as its place
  — all an edge label adds (§2.3.1: "by which exit did I arrive") — so the edges
  need no marker; the directional vertex markers are the thesis's own (§3.1.1,
  §6.2.2).  The kit is 1 + 2 + … + n = n(n + 1)/2 directional vertex markers,
  exactly what every run drops.  (The thesis counts C(n, 2) homogeneous markers
  for n labels, §2.3.1, labels 0 … n − 1; here no label is 0, since an unmarked
  place is a new one.)  The thesis's own algorithm with Σ k directional
  V-markers (``case-dv-sum``, §6.2.2) leaves v0 unmarked and chooses the
  closest edge first; this baseline is the classic DFS.
* **The exact bound is 2m (ours).**  With every place labelled the robot's
  steps are those of a depth-first search: every edge of the DFS tree is
  walked down once and back up at most once, and every other edge joins an
  ancestor (an undirected DFS has no cross edges), walked once and back once
  (the way back is the shortest path the next step takes, at most one more
  move than the tree path): at most 2(n − 1) + 2(m − n + 1) = 2m traversals.

§2.3.1 gives no listing: the explorer follows its text (no validation, depth-first search).  The labels'
form is the choice above; it changes no move, since an edge label would tell the robot nothing the
direction of a vertex label does not.

Examples
--------
>>> LabelledGraphDFS.name
'labelled-dfs'
>>> entry_exit(Signature(4, vertex_count=3, vertex_direction=1))  # exit 0 lies 1 clockwise of the entry
(2, 3)
"""

from __future__ import annotations

from typing import cast

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.kit import MarkerOp
from topomark.spec.signature import Signature

from topomark.reference.explorers.marker_walk import MarkerStep, MarkerWalk
from topomark.reference.explorers.policies import Policies

__all__ = ["LabelledGraphDFS", "entry_exit"]

DEPTH_FIRST = Policies(edge="lifo")
"""The newest edge of U first: depth-first search (§2.3.1)."""


def entry_exit(sig: Signature) -> tuple[int, int]:
    """(map vertex, map exit entered by) that a labelled place's signature ``sig`` names: label L is map vertex
    L − 1; its markers point along its exit 0, ``vertex_direction`` exits clockwise of the entry."""
    return sig.vertex_count - 1, (-cast(int, sig.vertex_direction)) % sig.degree  # labels are directional


class LabelledGraphDFS(MarkerWalk):
    """Depth-first search of a graph whose places the robot labels distinctly (module docstring; §2.3.1)."""

    name = "labelled-dfs"

    @property
    def edge_policy(self) -> Policies:
        """Depth first, whatever policy is given (the 2m bound is DFS's)."""
        return DEPTH_FIRST

    def begin(self) -> None:
        """v0's label, 1, pointing along the exit the robot faces (v0's exit 0)."""
        self.label(0, None)

    def label(self, v: int, it: MarkerStep | None) -> None:
        """Drop map vertex ``v``'s label (v + 1 markers) where the robot stands, pointing along v's exit 0."""
        _, entry = self.position
        self.drop(MarkerOp("vertex", count=v + 1, direction=-entry % self.M.degree(v)), it)

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if sig.vertex_count == 0:
            self.label(self.non_loop(it, sig), it)
            return
        x, entry = entry_exit(sig)
        if not 0 <= x < self.M.n or self.M.degree(x) != sig.degree:
            raise AlgorithmFailed(f"iteration {it.number}: label {sig.vertex_count} names no known place of "
                                  f"degree {sig.degree}")
        self.loop(it, (x, entry))
