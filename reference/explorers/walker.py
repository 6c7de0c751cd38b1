"""The bookkeeping every explorer family shares: S, U and the believed pose; recording a step; walking S;
loop and non-loop augmentation (thesis §3.1.3, Algorithm 3.1 lines 1–6 and 22–28).

Every family of explorers keeps the map S with its unexplored darts U and the
pose it believes the robot has, takes an edge e = (v_k, v_u) from U, walks S
to v_k, follows e and augments S — loop augmentation joins e to a known dart
e' (and removes e' from U), non-loop augmentation adds v_u with e as its
exit 0 and its other exits, clockwise, to U.  What differs is how each tells
v_u (hypotheses, markers, a thread, models).  This module writes once what
is the same:

* :class:`StepRecord` — what a step that takes e from U records: its
  number, e, the signature sensed at v_u and how S grew (the
  :class:`~.contract.IterationRecord` every family extends);
* :class:`ExplorerState` — the contract's state (:mod:`.contract`): the
  robot, the observer, ``S``, ``position``, ``iterations``, ``models()``, and
  :meth:`ExplorerState.record`, which ends every step (append the record,
  call the observer);
* :class:`MapWalker` — a single map walked by the robot: the start (S ←
  {v0}, U ← its exits numbered from the faced exit), ``done`` (U empty),
  walking S along a breadth-first tree (:func:`tree_path`,
  :meth:`MapWalker.walk`), and the two augmentations;
* :func:`places_like` — the known vertices that could be v_u by degree
  alone (Dudek et al.'s place validation, §2.3.1, and the thread's search of
  §6.3.3 line 11).

Algorithm 5.1's model tree keeps several models and walks a traversal map,
not S: it shares only :class:`ExplorerState`.

Examples
--------
>>> tree_path({1: (0, 2), 2: (1, 0)}, 0, 2)
[(0, 2), (1, 0)]
>>> tree_path({1: (0, 2)}, 0, 0)
[]
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Iterable

from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature

from topomark.reference.explorers.policies import Policies, in_preorder, nearest, open_ends_beyond
from topomark.reference.explorers.inconsistency import inconsistent

__all__ = ["StepRecord", "ExplorerState", "MapWalker", "tree_path", "places_like"]


def tree_path(parent: dict[int, MapDart], root: int, target: int) -> list[MapDart]:
    """The darts (vertex, exit) from ``root`` to ``target`` along the breadth-first tree ``parent`` rooted at
    ``root`` (each reached vertex ↦ the dart it was reached by), in walking order."""
    path = []
    x = target
    while x != root:
        path.append(parent[x])
        x = parent[x][0]
    return path[::-1]


def places_like(S: PartialMap, vk: int, degree: int) -> list[int]:
    """The known vertices that could be v_u, reached from v_k by an unexplored edge: ``degree`` exits, one of
    them unexplored, neither v_k nor a neighbour of v_k (no self-loops, no multi-edges, §3.1.1), in the preorder
    of a breadth-first tree of S rooted at v_k."""
    return in_preorder(S, vk, {v for v in open_ends_beyond(S, vk) if S.degree(v) == degree})


@dataclass
class StepRecord:
    """One step that took e = (v_k, i) from U: its number, e, the signature sensed at v_u, how S grew
    (``kind`` "loop" or "non-loop", ``joined`` the two darts joined) and its hypotheses (none, unless the
    family makes them).  Each family's record adds its own fields and writes its own ``to_json``."""

    number: int
    edge: MapDart
    signature: Signature | None = None
    kind: str = ""  # "loop" or "non-loop"
    joined: tuple[MapDart, MapDart] | None = None
    hypotheses: list = field(default_factory=list)

    def joined_json(self) -> list | None:
        """``joined`` as the trace writes it: two [vertex, exit] pairs, or None."""
        return [list(d) for d in self.joined] if self.joined else None


class ExplorerState:
    """The state the explorer contract exposes, and how a step is recorded: ``observer(explorer, record)``
    runs once after every step, the record appended to ``iterations`` first."""

    def __init__(self, robot, observer: Callable | None = None):
        self.robot = robot
        self.observer = observer
        self.S = PartialMap()
        self.position: MapDart = (0, 0)  # believed (map vertex, entry exit); exit 0 of v0 is the faced exit
        self.iterations: list = []

    def models(self) -> list[tuple[PartialMap, MapDart]]:
        """The (map, believed pose) pairs the explorer holds: one, for an algorithm with a single map."""
        return [(self.S, self.position)]

    def record(self, it):
        """End a step: ``it`` joins ``iterations`` and the observer sees it; returns ``it``."""
        self.iterations.append(it)
        if self.observer is not None:
            self.observer(self, it)
        return it


class MapWalker(ExplorerState):
    """One map S walked by the robot: start, termination, walking S, loop and non-loop augmentation."""

    loop_check = "loop augmentation"  # the check a loop augmentation that finds e' outside U names
    loop_proof = "Lemma 1 (§3.4)"  # what proves e' is in U (:meth:`not_in_u`)

    def __init__(self, robot, policies: Policies | None = None, observer: Callable | None = None):
        super().__init__(robot, observer)
        self.policies = policies or Policies()

    # -- the explorer contract -------------------------------------------------------
    def start(self) -> None:
        """S = {v0}, U = its exits numbered from the exit the robot faces; the robot at v0, entered by exit 0."""
        v0 = self.S.add_vertex(self.robot.sense().degree)
        self.S.unexplored = [(v0, i) for i in range(self.S.degree(v0))]
        self.position = (v0, 0)

    def done(self) -> bool:
        """U is empty (Algorithm 3.1 line 4; §3.1.3: termination)."""
        return not self.S.unexplored

    # -- walking S ---------------------------------------------------------------------
    def open_exits(self, v: int) -> list[int]:
        """The unexplored exits of map vertex ``v``, in index order."""
        return [j for j, t in enumerate(self.S.links(v)) if t is None]

    def take_exit(self, exit_: int, purpose: str) -> Signature:
        """Leave the believed position's vertex by its map exit ``exit_`` (the motion is counted from the entry
        edge, §3.1.1); returns the signature sensed at the far end.  The believed pose is the caller's to set."""
        v, entry = self.position
        return self.robot.move((exit_ - entry) % self.S.degree(v), purpose)

    def path_to(self, target: int, parent: dict[int, MapDart]) -> list[MapDart]:
        """The darts of S from the believed position to ``target`` along the BFS tree ``parent`` rooted there."""
        return tree_path(parent, self.position[0], target)

    def shortest_path_to(self, target: int) -> list[MapDart]:
        """The darts of a shortest path of S from the believed position to ``target`` (bfs's, exits in order)."""
        return self.path_to(target, nearest(self.S, self.position[0], (target,))[1])

    def walk(self, path: Iterable[MapDart], purpose: str,
             stop: Callable[[int, int, Signature], bool] | None = None) -> tuple[int, int, Signature] | None:
        """Follow darts of S from the believed position, which follows the robot; with ``stop``, end at the first
        vertex entered where ``stop(vertex, entry, signature)`` holds: (vertex, entry, signature), else None."""
        for dart in path:
            sig = self.take_exit(dart[1], purpose)
            self.position = self.S.target(dart)
            if stop is not None and stop(self.position[0], self.position[1], sig):
                return self.position[0], self.position[1], sig
        return None

    def walk_to(self, target: int, purpose: str, stop: Callable[[int, int, Signature], bool] | None = None
                ) -> tuple[int, int, Signature] | None:
        """:meth:`walk` along a shortest path of S to ``target``."""
        return self.walk(self.shortest_path_to(target), purpose, stop)

    def travel_to(self, target: int, parent: dict[int, MapDart]) -> None:
        """Walk S from the believed position to ``target`` along the BFS tree ``parent`` rooted there (line 6)."""
        self.walk(self.path_to(target, parent), "travel")

    # -- augmentation (§3.1.3) ---------------------------------------------------------
    def loop_augment(self, it, far: MapDart) -> None:
        """Add e/e' = (v_k, v_k') with the existing indices; remove e' = ``far`` from U (lines 24–25).  The
        believed pose is the caller's to set: where the robot stands depends on how e' was found."""
        if far not in self.S.unexplored:
            raise self.not_in_u(it, far)
        if far[0] == it.edge[0] or far[0] in {u for _, u in self.S.joined(it.edge[0])}:
            raise self.degenerate(it, far)
        self.S.unexplored.remove(far)
        self.S.add_edge(it.edge, far)
        it.kind, it.joined = "loop", (it.edge, far)

    def not_in_u(self, it, far: MapDart) -> Exception:
        """What a loop augmentation raises when e' is not in U: the explorer's own map is inconsistent.

        With a lighthouse of explicit place and back-link an accepted hypothesis is the true place and entry
        (§3.4: Lemma 1), and Dudek's marker always leads back (§2.3.1): a bug.  With a lighthouse
        that is not explicit the thesis predicts it, a wrong loop closing (§5.2.1): the ``failed`` outcome.
        """
        return inconsistent(getattr(self, "lighthouse", None), f"{self.loop_check}: e' = {far} identified at "
                            f"iteration {it.number} is not in U", self.loop_proof)

    def degenerate(self, it, far: MapDart) -> Exception:
        """What a loop augmentation raises when e/e' would be a self-loop or a second edge between two places:
        no world has one (cycles of length ≤ 2 are excluded, §3.1.1), so the explorer's own map is
        inconsistent — a bug under an explicit lighthouse, a wrong loop closing the thesis predicts under one
        that is not (§5.2.1)."""
        kind = "a self-loop" if far[0] == it.edge[0] else "a second edge between two places"
        return inconsistent(getattr(self, "lighthouse", None), f"{self.loop_check}: joining e = {it.edge} to e' = "
                            f"{far} at iteration {it.number} would make {kind}, which no world has (§3.1.1)",
                            self.loop_proof)

    def non_loop_augment(self, it, sig: Signature, heading: int = 0, sensed: bool = False) -> int:
        """Add v_u (``sig``'s degree) and e, e its exit 0, the rest numbered clockwise and added to U (lines
        27–28); the robot stands at v_u, entered ``heading`` exits clockwise from e.  ``sensed``: S records
        the marks ``sig`` shows, read from e.  Returns v_u's map vertex."""
        u = self.S.add_vertex(sig.degree)
        if sensed:
            self.S.mark_as_sensed(u, sig, 0)
        self.S.add_edge(it.edge, (u, 0))
        self.S.unexplored.extend((u, i) for i in range(1, sig.degree))
        it.kind, it.joined = "non-loop", (it.edge, (u, 0))
        self.position = (u, heading)
        return u
