"""Mapping with a single movable vertex marker: Dudek et al.'s algorithm [24, 26] and its directional
variant [27] (thesis §2.3.1, L139–L152, Figure 2.2; L177; L2036).

The robot carries one vertex marker that it may drop and pick up again
(L139: "The robot can pick up the marker if it is located at the current
vertex and it can put down the marker it holds at the current vertex").  It
keeps the known map S and U, the unexplored edges at known vertices, exactly
as Algorithm 3.1 does (§3.1.3; here ``S.unexplored``).  One step (L148)
removes an unexplored edge e = (v_k, v_u) from U, walks S to v_k, follows e
and answers "have I been here before?":

1. **place validation** (L148) — drop the marker at v_u, come back to v_k
   over e, and visit the known vertices that could be v_u, looking for the
   marker.  Not found: v_u is new (non-loop augmentation, Figure 2.2(a, b)):
   fetch the marker from v_u, which joins S with e as its exit 0.
2. **back-link validation** (L150), marker found at v_k': "the robot drops
   the marker at v_k and goes back to v_k' along the shortest known path in
   S.  At v_k', the robot traverses each of the (unexplored) incident edges
   at v_k', looking for the marker."  The one that leads to the marker is e'
   (Figure 2.2(c, d)); the robot, now at v_k, picks the marker up.
   **Directional variant** (L177, L2036): the marker is dropped at v_u
   pointing at the entry edge e, so where it is found its direction names
   e' at once — no back-link search.

The thesis leaves open, and this module decides (each tested on the
smallest world that shows it in ``tests/test_movable_marker.py``):

* **how the robot returns after a drop** — back over e to v_k (it cannot walk
  S from an unknown place).  L162 describes Dudek et al.'s class of
  strategies as "Depth-One search strategies which always drop a marker at
  the unknown end of an edge and comes back".
* **which known vertices are visited** — L148 says "visiting known vertices
  in S"; only those that can be v_u are visited: the same degree as v_u
  (L146: "two vertices appear identical to the robot if they have the same
  degree"), at least one unexplored edge (v_u is reached by the unexplored
  e, so e' is unexplored at v_u), neither v_k nor a neighbour of v_k in S
  (no self-loops, no multi-edges: L374; L139 "Redundant or
  self-referential edges are prohibited").  They are visited in the
  preorder of a breadth-first tree of S rooted at v_k (children by exit
  index), each reached by a shortest path in S; every vertex the robot
  passes is looked at, so one passed on the way is not visited again.
  With no such vertex, v_u is new and nothing is dropped.
* **when the marker is picked up** — at the end of every step, before the
  next edge is chosen: at v_u (non-loop: the robot walks back to v_k and
  over e once more), at v_k' (directional loop, or undirected when v_k' has
  a single unexplored edge: that edge is e', L150's search has one
  candidate and needs no move), or at v_k (undirected back-link search).
  So between steps the marker is held and the world carries none: S never
  shows a mark, and I-1/I-2 and the final extended isomorphism (markers
  included) are checked between steps exactly as for Algorithm 3.1.
* **the order of the back-link search** — v_k''s unexplored exits in index
  order; each failed one is traversed back (two moves), the last one
  needs no test (when the others failed it is e', and crossing it reaches
  v_k, where the marker must be picked up anyway).

Cost accounting (the robot's purposes, :data:`~topomark.reference.explorers.robot.PURPOSES`):

==============  =================================================================
``travel``      walking S to v_k (as Algorithm 3.1's line 6)
``new``         following e to v_u
``retrace``     back over e to v_k after the drop
``validation``  place validation: walking S looking for the marker
``other``       marker logistics: back to v_u to fetch it (non-loop); carrying it
                to v_k and back to v_k' for the back-link search
``probe``       back-link validation: out and back over v_k''s unexplored edges
==============  =================================================================

References
----------
Thesis §2.3.1 (L139–L152, Figure 2.2; L162; L177) and §6.3 (L2036, the
carried l = ε thread is this directional variant); Dudek et al. [24, 26, 27].

Examples
--------
>>> MovableMarkerExplorer.name, DirectionalMovableMarkerExplorer.name
('dudek', 'dudek-directional')
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from topomark.spec.errors import CheckFailure, Violation
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature

from topomark.reference.explorers.policies import Policies, in_preorder, nearest, open_ends_beyond
from topomark.reference.explorers.robot import Robot

__all__ = ["MarkerIteration", "MovableMarkerExplorer", "DirectionalMovableMarkerExplorer"]

V0 = 0
PICK_UP = MarkerOp("vertex", pick_up=True)


@dataclass
class MarkerIteration:
    """One step: the edge e explored, what was sensed at v_u, and how the marker resolved it."""

    number: int
    edge: MapDart
    signature: Signature | None = None
    kind: str = ""  # "loop" or "non-loop"
    joined: tuple[MapDart, MapDart] | None = None
    candidates: list[int] = field(default_factory=list)  # known vertices that could be v_u, in visiting order
    found: int | None = None  # the known vertex v_k' where the marker was found (loop)
    probes: int = 0  # v_k''s unexplored edges traversed in the back-link search
    hypotheses: list = field(default_factory=list)  # the contract's field: this algorithm makes none

    def to_json(self) -> dict:
        return {"iteration": self.number, "edge": list(self.edge), "signature": str(self.signature),
                "augmentation": self.kind, "joined": [list(d) for d in self.joined] if self.joined else None,
                "candidates": self.candidates, "found": self.found, "probes": self.probes}


class MovableMarkerExplorer:
    """Dudek et al.'s single undirected movable marker algorithm [26] (§2.3.1, L148–L150)."""

    name = "dudek"
    directional = False

    def __init__(self, robot: Robot, policies: Policies | None = None,
                 observer: Callable[["MovableMarkerExplorer", MarkerIteration], None] | None = None,
                 options: dict | None = None):
        self.robot = robot
        self.policies = policies or Policies()
        self.observer = observer
        self.options = options or {}
        self.S = PartialMap()
        self.position: MapDart = (V0, 0)  # believed (map vertex, entry index)
        self.iterations: list[MarkerIteration] = []

    # -- the explorer contract ---------------------------------------------------
    def start(self) -> None:
        """S = {v0}, U = its exits numbered from the exit the robot faces; the robot at v0, entered by exit 0."""
        v0 = self.S.add_vertex(self.robot.sense().degree)
        self.S.unexplored = [(v0, i) for i in range(self.S.degree(v0))]
        self.position = (v0, 0)

    def done(self) -> bool:
        """U is empty (§3.1.3: termination)."""
        return not self.S.unexplored

    def models(self) -> list[tuple[PartialMap, MapDart]]:
        return [(self.S, self.position)]

    def step(self) -> MarkerIteration:
        """One step of L148: take e from U, follow it, resolve v_u with the marker, augment S."""
        edge, parent = self.policies.next_edge(self.S, self.position[0])
        it = MarkerIteration(len(self.iterations) + 1, edge)
        vk, i = it.edge
        self.walk(self.path(parent, vk), "travel")
        it.signature = sig = self.robot.move((i - self.position[1]) % self.S.degree(vk), "new")
        it.candidates = self.candidates(vk, sig.degree)
        if not it.candidates:  # no known vertex can be v_u: it is new, nothing to drop
            self.non_loop_augment(it, sig)
        else:
            self.robot.operate(MarkerOp("vertex", direction=0 if self.directional else None))
            self.robot.move(0, "retrace")  # "comes back" (L162) over e
            self.position = (vk, i)
            found = self.search(it.candidates)
            if found is None:  # Figure 2.2(a, b): fetch the marker from v_u, which is new
                self.walk_to(vk, "other")
                self.robot.move((i - self.position[1]) % self.S.degree(vk), "other")
                self.robot.operate(PICK_UP)
                self.non_loop_augment(it, sig)
            else:  # Figure 2.2(c, d)
                it.found = found[0]
                self.loop_augment(it, (found[0], self.back_link(it, found[1])))
        self.iterations.append(it)
        if self.observer is not None:
            self.observer(self, it)
        return it

    # -- place validation (L148) -------------------------------------------------------
    def candidates(self, vk: int, degree: int) -> list[int]:
        """The known vertices that could be v_u, in the preorder of a breadth-first tree of S rooted at v_k."""
        S = self.S
        return in_preorder(S, vk, {v for v in open_ends_beyond(S, vk) if S.degree(v) == degree})

    def search(self, candidates: list[int]) -> tuple[int, Signature] | None:
        """Visit the candidates until the marker is seen; where (the robot stands there) and what it sensed."""
        looked: set[int] = set()
        for target in candidates:
            if target in looked:
                continue
            found = self.walk_to(target, "validation", looked)
            if found is not None:
                return found
        return None

    # -- back-link validation (L150) ----------------------------------------------------
    def back_link(self, it: MarkerIteration, sig: Signature) -> int:
        """The exit e' of v_k' (where the robot stands, the marker found) that e leads to; the marker picked up.

        L150: drop the marker at v_k, go back to v_k' along the shortest known
        path, traverse v_k''s unexplored edges looking for it.  A single
        unexplored edge at v_k' is e' with no move.
        """
        x = self.position[0]
        vk, i = it.edge
        open_exits = [j for j, t in enumerate(self.S.links(x)) if t is None]
        self.robot.operate(PICK_UP)
        if len(open_exits) == 1:
            return open_exits[0]
        self.walk_to(vk, "other")
        self.robot.operate(MarkerOp("vertex"))
        self.walk_to(x, "other")
        for k, j in enumerate(open_exits):
            it.probes += 1
            got = self.robot.move((j - self.position[1]) % self.S.degree(x), "probe")
            if got.vertex_count:  # the marker: this edge leads to v_k, entered by e
                self.position = (vk, i)
                self.robot.operate(PICK_UP)
                return j
            if k == len(open_exits) - 1:
                break
            self.robot.move(0, "probe")
            self.position = (x, j)
        raise CheckFailure(Violation("Dudek back-link", f"iteration {it.number}", f"the marker at v_k = {vk} "
                                     f"beyond one of {open_exits} at v_k' = {x}", "not found",
                                     "the explorer's own map is inconsistent"))

    # -- walking S -------------------------------------------------------------------
    @staticmethod
    def path(parent: dict[int, MapDart], target: int) -> list[MapDart]:
        """The darts (vertex, exit) from the BFS root to ``target``, in walking order."""
        path = []
        while target in parent:
            path.append(parent[target])
            target = parent[target][0]
        return path[::-1]

    def walk_to(self, target: int, purpose: str, looked: set[int] | None = None) -> tuple[int, Signature] | None:
        """Walk a shortest path of S to ``target``; with ``looked``, stop where the marker is seen."""
        return self.walk(self.path(nearest(self.S, self.position[0], (target,))[1], target), purpose, looked)

    def walk(self, path: list[MapDart], purpose: str, looked: set[int] | None = None) -> tuple[int, Signature] | None:
        """Follow ``path`` (darts of S from the believed position); each vertex entered goes into ``looked``,
        and if ``looked`` is given the walk stops at the first one showing the marker: (it, its signature)."""
        v, entry = self.position
        for u, exit_ in path:
            sig = self.robot.move((exit_ - entry) % self.S.degree(u), purpose)
            v, entry = self.S.arc((u, exit_))
            self.position = (v, entry)
            if looked is not None:
                if sig.vertex_count:
                    return v, sig
                looked.add(v)
        return None

    # -- augmentation (§3.1.3) ---------------------------------------------------------
    def loop_augment(self, it: MarkerIteration, far: MapDart) -> None:
        """Add e/e' = (v_k, v_k'); remove e' from U."""
        if far not in self.S.unexplored:
            raise CheckFailure(Violation("Dudek loop", f"iteration {it.number}", f"e' = {far} in U", "not in U",
                                         "the explorer's own map is inconsistent"))
        self.S.unexplored.remove(far)
        self.S.add_edge(it.edge, far)
        it.kind, it.joined = "loop", (it.edge, far)

    def non_loop_augment(self, it: MarkerIteration, sig: Signature) -> None:
        """Add v_u and e (its exit 0; the robot stands at v_u, entered by e); its other exits join U."""
        u = self.S.add_vertex(sig.degree)
        self.S.add_edge(it.edge, (u, 0))
        self.S.unexplored.extend((u, j) for j in range(1, sig.degree))
        it.kind, it.joined = "non-loop", (it.edge, (u, 0))
        self.position = (u, 0)


class DirectionalMovableMarkerExplorer(MovableMarkerExplorer):
    """The directional variant [27] (§2.3.1, L177; L2036): the marker, dropped at v_u pointing at e, names e'
    where it is found, so back-link validation needs no motion."""

    name = "dudek-directional"
    directional = True

    def back_link(self, it: MarkerIteration, sig: Signature) -> int:
        """e' is the exit the marker points at (L177: "identifying the one that is pointed to by the marker");
        the marker is picked up where it lies, v_k'."""
        x, entry = self.position
        self.robot.operate(PICK_UP)
        return (entry + sig.vertex_direction) % self.S.degree(x)
