"""Mapping with a single movable vertex marker: Dudek et al.'s algorithm [24, 26] and its directional
variant [27] (thesis §2.3.1, Figure 2.2; §6.3.1).

The robot carries one vertex marker that it may drop and pick up again
(§2.3.1: "The robot can pick up the marker if it is located at the current
vertex and it can put down the marker it holds at the current vertex").  It
keeps the known map S and U, the unexplored edges at known vertices, exactly
as Algorithm 3.1 does (§3.1.3; here ``S.unexplored``).  One step (§2.3.1)
removes an unexplored edge e = (v_k, v_u) from U, walks S to v_k, follows e
and answers "have I been here before?":

1. **place validation** (§2.3.1) — drop the marker at v_u, come back to v_k
   over e, and visit the known vertices that could be v_u, looking for the
   marker.  Not found: v_u is new (non-loop augmentation, Figure 2.2(a, b)):
   fetch the marker from v_u, which joins S with e as its exit 0.
2. **back-link validation** (§2.3.1), marker found at v_k': "the robot drops
   the marker at v_k and goes back to v_k' along the shortest known path in
   S.  At v_k', the robot traverses each of the (unexplored) incident edges
   at v_k', looking for the marker."  The one that leads to the marker is e'
   (Figure 2.2(c, d)); the robot, now at v_k, picks the marker up.
   **Directional variant** (§2.3.1, §6.3.1): the marker is dropped at v_u
   pointing at the entry edge e, so where it is found its direction names
   e' at once — no back-link search.

§2.3.1 gives no listing, but its description is precise enough to follow
as written — drop at v_u, come back, visit the known vertices of S, search
v_k''s unexplored edges — once the choices below are made; so each marker
has two explorers: topomark's (which leaves out moves that cannot change
the answer) and the description as written (the ``-listing`` classes).

The thesis leaves open, and this module decides (each tested on the
smallest world that shows it in ``tests/test_movable_marker.py`` and, for
the description as written, ``tests/test_listing_dudek.py``):

* **how the robot returns after a drop** — back over e to v_k (it cannot walk
  S from an unknown place).  §2.3.1 describes Dudek et al.'s class of
  strategies as "Depth-One search strategies which always drop a marker at
  the unknown end of an edge and comes back".
* **which known vertices are visited** — §2.3.1 says "visiting known vertices
  in S".  Topomark's explorers (``dudek``, ``dudek-directional``) visit only
  those that can be v_u: the same degree as v_u (§2.3.1: "two vertices
  appear identical to the robot if they have the same degree"), at least one
  unexplored edge (v_u is reached by the unexplored e, so e' is unexplored at
  v_u), neither v_k nor a neighbour of v_k in S (no self-loops, no
  multi-edges: §3.1.1, §2.3.1 "Redundant or self-referential edges are
  prohibited"); with no such vertex, v_u is new and nothing is dropped.  The
  description as written (``dudek-listing``, ``dudek-directional-listing``)
  drops the marker at every v_u and visits every known vertex but v_k.
  Either way they are visited in the preorder of a breadth-first tree of S
  rooted at v_k (children by exit index), each reached by a shortest path in
  S: the thesis fixes no order, and this one makes the search one closed walk
  of at most 2(n_s − 1) traversals over n_s known vertices (the tree's Euler
  tour), which is what the O(mn) of §2.3.1 needs ("the robot may have to
  visit each vertex in S in order to validate an edge", §6.3.1), and makes
  the candidates' walk a shortcut of the listing's.  Every vertex the robot
  enters is looked at (the marker is part of what it senses there, §2.3.1:
  "whether the marker is present at the current vertex"), so one passed on
  the way is not visited again, and the search stops where the marker is
  first seen.
* **when the marker is picked up** — at the end of every step, before the
  next edge is chosen: at v_u (non-loop: the robot walks back to v_k and
  over e once more), at v_k' (directional loop, or, in topomark's undirected
  explorer, when v_k' has a single unexplored edge: that edge is e', the
  search has one candidate and needs no move), or at v_k (undirected
  back-link search, which the description as written makes at every loop
  step: "the robot drops the marker at v_k and goes back to v_k'", with no
  exception for a single unexplored edge).
  So between steps the marker is held and the world carries none: S never
  shows a mark, and I-1/I-2 and the final extended isomorphism (markers
  included) are checked between steps exactly as for Algorithm 3.1.
* **the order of the back-link search** — v_k''s unexplored exits in index
  order; each failed one is traversed back (two moves), the last one
  needs no test (when the others failed it is e', and crossing it reaches
  v_k, where the marker must be picked up anyway).  The thesis names no order
  ("traverses each of the (unexplored) incident edges"); the bound of
  ``docs/bounds.md`` holds for every order.  The robot walks to v_k by a
  shortest path of S too (§2.3.1 names the shortest path only for the way
  back to v_k').

Cost accounting (the robot's purposes, :data:`~topomark.reference.explorers.robot.PURPOSES`):

==============  =================================================================
``travel``      walking S to v_k (as Algorithm 3.1's line 6)
``new``         following e to v_u
``retrace``     back over e to v_k after the drop
``validation``  place validation: walking S looking for the marker
``other``       marker logistics: back to v_u to fetch it (non-loop)
``drop``        a drop trip: carrying it to v_k and back to v_k' for the back-link
                search (§2.3.1; :mod:`topomark.reference.run.simulator`)
``probe``       back-link validation: out and back over v_k''s unexplored edges
==============  =================================================================

References
----------
Thesis §2.3.1 (Figure 2.2) and §6.3.1 (the
carried l = ε thread is this directional variant); Dudek et al. [24, 26, 27].

Examples
--------
>>> MovableMarkerExplorer.name, DirectionalMovableMarkerExplorer.name
('dudek', 'dudek-directional')
>>> ListingMovableMarkerExplorer.name, ListingDirectionalMovableMarkerExplorer.name
('dudek-listing', 'dudek-directional-listing')
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, cast

from topomark.spec.errors import ExplorerFault
from topomark.spec.kit import MarkerOp
from topomark.spec.signature import Signature

from topomark.reference.explorers.policies import Policies, bfs_preorder
from topomark.reference.explorers.robot import Robot
from topomark.reference.explorers.walker import MapWalker, StepRecord, places_like

__all__ = ["MarkerIteration", "MovableMarkerExplorer", "DirectionalMovableMarkerExplorer", "ListingMovableMarkerExplorer",
           "ListingDirectionalMovableMarkerExplorer"]

PICK_UP = MarkerOp("vertex", pick_up=True)


@dataclass
class MarkerIteration(StepRecord):
    """One step: the edge e explored, what was sensed at v_u, and how the marker resolved it (no hypotheses)."""

    candidates: list[int] = field(default_factory=list)  # the known vertices the search visits, in order
    found: int | None = None  # the known vertex v_k' where the marker was found (loop)
    probes: int = 0  # v_k''s unexplored edges traversed in the back-link search

    def to_json(self) -> dict:
        return {"iteration": self.number, "edge": list(self.edge), "signature": str(self.signature),
                "augmentation": self.kind, "joined": self.joined_json(),
                "candidates": self.candidates, "found": self.found, "probes": self.probes}


class MovableMarkerExplorer(MapWalker):
    """Dudek et al.'s single undirected movable marker algorithm [26] (§2.3.1); the start, the
    termination, the walks of S and the augmentations are the :class:`~.walker.MapWalker`'s."""

    name = "dudek"
    loop_check = "Dudek loop"
    loop_proof = "Dudek's back-link validation, whose marker always leads back (§2.3.1)"
    directional = False
    literal = False  # the listing as written (:class:`ListingMovableMarkerExplorer`)

    def __init__(self, robot: Robot, policies: Policies | None = None,
                 observer: Callable[["MovableMarkerExplorer", MarkerIteration], None] | None = None,
                 options: dict | None = None):
        super().__init__(robot, policies, observer)
        self.options = options or {}

    # -- the explorer contract: step (start, done, models: the walker's) ----------------
    def step(self) -> MarkerIteration:
        """One step of §2.3.1: take e from U, follow it, resolve v_u with the marker, augment S."""
        edge, parent = self.policies.next_edge(self.S, self.position[0])
        it = MarkerIteration(len(self.iterations) + 1, edge)
        vk, i = it.edge
        self.travel_to(vk, parent)
        it.signature = sig = self.take_exit(i, "new")
        it.candidates = self.places(vk, sig.degree)
        if not it.candidates and not self.literal:  # no known vertex can be v_u: it is new, nothing to drop
            self.non_loop_augment(it, sig)
        else:
            self.robot.operate(MarkerOp("vertex", direction=0 if self.directional else None))
            self.robot.move(0, "retrace")  # "comes back" (§2.3.1) over e
            self.position = (vk, i)
            found = self.search(it.candidates)
            if found is None:  # Figure 2.2(a, b): fetch the marker from v_u, which is new
                self.walk_to(vk, "other")
                self.take_exit(i, "other")
                self.robot.operate(PICK_UP)
                self.non_loop_augment(it, sig)
            else:  # Figure 2.2(c, d)
                it.found = found[0]
                self.loop_augment(it, (found[0], self.back_link(it, found[1])))
        return self.record(it)

    # -- place validation (§2.3.1) -------------------------------------------------------
    def places(self, vk: int, degree: int) -> list[int]:
        """The known vertices the search visits: those that could be v_u (:func:`~.walker.places_like`)."""
        return places_like(self.S, vk, degree)

    def search(self, candidates: list[int]) -> tuple[int, Signature] | None:
        """Visit the candidates (:func:`~.walker.places_like`) until the marker is seen; where (the robot
        stands there) and what it sensed.  Every vertex the robot enters is looked at, so a candidate passed on
        the way is not visited again."""
        looked: set[int] = set()

        def marker_seen(v: int, entry: int, sig: Signature) -> bool:
            if sig.vertex_count:
                return True
            looked.add(v)
            return False

        for target in candidates:
            if target in looked:
                continue
            found = self.walk_to(target, "validation", marker_seen)
            if found is not None:
                return found[0], found[2]
        return None

    # -- back-link validation (§2.3.1) ----------------------------------------------------
    def back_link(self, it: MarkerIteration, sig: Signature) -> int:
        """The exit e' of v_k' (where the robot stands, the marker found) that e leads to; the marker picked up.

        §2.3.1: drop the marker at v_k, go back to v_k' along the shortest known
        path, traverse v_k''s unexplored edges looking for it.  In topomark's
        explorer a single unexplored edge at v_k' is e' with no move.
        """
        x = self.position[0]
        vk, i = it.edge
        open_exits = self.open_exits(x)
        self.robot.operate(PICK_UP)
        if len(open_exits) == 1 and not self.literal:  # e' with no search (the listing searches anyway)
            return open_exits[0]
        self.walk_to(vk, "drop")  # a drop trip: to v_k to drop the marker, and back to v_k'
        self.robot.operate(MarkerOp("vertex"))
        self.walk_to(x, "drop")
        for k, j in enumerate(open_exits):
            it.probes += 1
            got = self.take_exit(j, "probe")
            if got.vertex_count:  # the marker: this edge leads to v_k, entered by e
                self.position = (vk, i)
                self.robot.operate(PICK_UP)
                return j
            if k == len(open_exits) - 1:
                break
            self.robot.move(0, "probe")
            self.position = (x, j)
        # "One of the (unexplored) edges e' will take the robot back to v_k , which the robot will immediately
        # recognize due to the presence of the marker" (§2.3.1): not finding it is a bug, not an outcome.
        raise ExplorerFault(f"Dudek back-link: the marker at v_k = {vk} is beyond none of {open_exits} at "
                            f"v_k' = {x} (iteration {it.number}), which §2.3.1 rules out: a bug in the "
                            "explorer")


class DirectionalMovableMarkerExplorer(MovableMarkerExplorer):
    """The directional variant [27] (§2.3.1, §6.3.1): the marker, dropped at v_u pointing at e, names e'
    where it is found, so back-link validation needs no motion."""

    name = "dudek-directional"
    directional = True

    def back_link(self, it: MarkerIteration, sig: Signature) -> int:
        """e' is the exit the marker points at (§2.3.1: "identifying the one that is pointed to by the marker");
        the marker is picked up where it lies, v_k'."""
        x, entry = self.position
        self.robot.operate(PICK_UP)
        return (entry + cast(int, sig.vertex_direction)) % self.S.degree(x)  # the directional marker's reading


def _visit_all_of_s(self: MovableMarkerExplorer, vk: int, degree: int) -> list[int]:
    """§2.3.1's search as written, "visiting known vertices in S": every known vertex but v_k (where the robot
    stands, having seen no marker there), in the preorder of a breadth-first tree of S rooted at v_k."""
    return bfs_preorder(self.S, vk)[1:]


class ListingMovableMarkerExplorer(MovableMarkerExplorer):
    """§2.3.1's description as written (``dudek-listing``): the marker dropped at every v_u, every known vertex
    of S visited, and the back-link search made at every loop step (module docstring: the listing)."""

    name = "dudek-listing"
    literal = True
    places = _visit_all_of_s


class ListingDirectionalMovableMarkerExplorer(DirectionalMovableMarkerExplorer):
    """The directional variant as written (``dudek-directional-listing``; §2.3.1, §6.3.1): the marker dropped
    at every v_u pointing at e, every known vertex of S visited; e' is where the marker points."""

    name = "dudek-directional-listing"
    literal = True
    places = _visit_all_of_s
