"""The footprints model of Deng and Mirzaian [18] with m + n homogeneous immovable markers: the classic baseline
the thesis reviews (§2.3.1, Figure 2.4; Tables 2.2 and 2.3) and builds its Cases 1 and 2 on (§6.2.1,
Cases 1, 2 and 4).

"The robot drops one marker at each vertex and edge the first time the vertex or
edge is visited, and does not pick it up again" (§2.3.1).  S and U are kept as in
§3.1.3; one step takes e = (v_k, v_u) from U, walks S to v_k and follows e,
leaving a footprint on e:

* **v_u has no footprint** (Figure 2.4(a)): it has not been visited before; a
  footprint is left at v_u and "both e and v_u … are then added into S without
  additional validations" (Figure 2.4(b)).
* **v_u has a footprint** (Figure 2.4(c)): "the newly dropped footprint/marker on
  e is exploited in identifying both v_u and the edge e' leaving v_u which
  correspond to e … Validations are conducted by the robot returning to v_k
  and then visiting each (other) known vertex in S which has the same degree
  as v_u, looking for the (other) vertex that has one additional footprinted
  edge" (§2.3.1); that vertex is v_k' and the edge e' (Figure 2.4(d)).

The search is :class:`~.edge_footprints.FootprintSearch`'s (the thesis's Case 1a
is "the mapping strategy described in the footprints model … implemented by
dropping markers at each newly visited edge only", §6.2.1 Case 1a): the differences are
only the ones the text states.

Decisions, with the thesis references (each shown in ``tests/test_baselines.py``):

* **Homogeneous means one pool.**  "m + n homogeneous immovable (undirected)
  markers, one for each node or edge" (§2.3.1): the kit is one pool of m + n
  undirected vertex-or-edge markers (``Kit(either=m + n)``), and every run
  drops exactly m + n of them — one at every vertex (v0's at the start, as the
  robot first "visits" it there), one on every edge.
* **Which candidates.**  The text names only the degree: "each (other) known
  vertex in S which has the same degree as v_u" (§2.3.1).  The robot visits
  exactly those, other than v_k, in the preorder of a breadth-first tree of S
  rooted at v_k, each by a shortest path of S, sensing every vertex it passes
  (stopping wherever v_k' is seen) — not filtered by the marked edges v_u
  showed, nor by an unexplored edge, as the thesis's own Cases 1a and 2 do
  (Algorithm 6.1 lines 11–12).  Looking at every vertex passed changes the
  text's moves ("visiting each (other) known vertex"), which the registration
  says (``changes``); ``footprints-listing`` (:class:`ListingFootprints`) checks each candidate only where
  it goes, as written.  The walk is still within the tree's Euler tour
  (2(n − 1) moves), so the registered exact bound is the footprint searches'.
* **Back to v_k over e** before the search ("the robot returning to v_k",
  §2.3.1): purpose ``retrace``, as in Cases 1a and 2.
* **Drops cost nothing extra**: the footprints on v_u and on e are left while
  the robot stands at v_u, on its entry edge ("leaving a footprint/marker on
  e" during the traversal, §2.3.1).

Examples
--------
>>> Footprints.name
'footprints'
>>> Footprints.loop_markers
1
"""

from __future__ import annotations

from topomark.spec.kit import MarkerOp
from topomark.spec.signature import Signature

from topomark.reference.explorers.edge_footprints import FootprintSearch
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.policies import in_preorder

__all__ = ["Footprints", "ListingFootprints"]


class Footprints(FootprintSearch):
    """Deng and Mirzaian's footprints [18]: a footprint on every vertex and every edge, m + n (§2.3.1)."""

    name = "footprints"

    def begin(self) -> None:
        """The footprint at v0, where the robot first visits a vertex."""
        self.drop(MarkerOp("vertex"))

    def is_new(self, sig: Signature) -> bool:
        """"If v_u contains no marker then it must not have been visited before" (§2.3.1)."""
        return sig.vertex_count == 0

    def non_loop_markers(self, vk: int) -> int:
        return 1  # the footprint on e

    def on_new(self, it: MarkerStep, u: int, count: int) -> None:
        """"The robot leaves a footprint/marker at v_u" (§2.3.1), and the one on e."""
        self.drop(MarkerOp("vertex"), it)
        super().on_new(it, u, count)

    def candidates(self, vk: int, key: tuple[int, ...], degree: int) -> list[int]:
        """"each (other) known vertex in S which has the same degree as v_u" (§2.3.1), in the preorder of a
        breadth-first tree of S rooted at v_k; the marks v_u showed (``key``) are not used."""
        M = self.M
        return in_preorder(M, vk, {v for v in M.vertices if v != vk and M.degree(v) == degree})


class ListingFootprints(Footprints):
    """§2.3.1's footprints as written (``footprints-listing``): each candidate checked where the robot goes to it
    ("visiting each (other) known vertex in S which has the same degree as v_u"), none on the way."""

    name, literal = "footprints-listing", True
