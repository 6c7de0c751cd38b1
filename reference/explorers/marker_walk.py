"""The loop the §6.2 marker algorithms share: take an unexplored edge, walk S to it, follow it, augment S
(thesis §6.2, Algorithms 6.1–6.6 lines "remove an unexplored edge e = (v_k, v_u) from U; the robot traverses S
to v_k and follows e to v_u").

Every algorithm of §6.2 keeps the map S and the unexplored edges U of §3.1.3 and
differs only in what it does on arriving at v_u (which markers it senses and
drops there, and how it tells a known place and its back-link).  A subclass of
:class:`MarkerWalk` writes that as :meth:`MarkerWalk.arrive`; this module walks
S, chooses e (the ``nearest`` edge policy by default: the closest known end,
ties by U's order — the closest-first pattern Algorithms 6.3 and 6.6 require),
augments S and records every marker dropped in S as the robot senses it.

Purposes of the moves (the cost splits as §6.2's measurement asks): ``new`` —
the edge e itself; ``travel`` — walking S to v_k; ``other`` — trips made only to
drop markers (Algorithm 6.6 line 10: "goes back on e, drops i markers on e and
back"); ``validation`` / ``retrace`` — back-link probes and their returns
(Algorithm 6.2 lines 21–35).

Decision (a gap in the kernel's checker): the map the checker reads, ``S``,
shows the markers dropped after start only at termination; the algorithm works
on its own map ``M``, which records every drop as sensed (:meth:`MarkerWalk.finish`
says why and how to switch it off).

Decision (the kernel's robot cannot count what it carries): "if the robot has
enough markers" (Algorithm 6.2 line 10) is the robot trying the drop — the
simulator refuses a drop the kit cannot cover *before* anything changes
(:class:`~topomark.spec.errors.OutOfMarkers`), which :meth:`MarkerWalk.try_drop`
turns into False.  Elsewhere a refused drop ends the run as the ``failed``
outcome.

Examples
--------
>>> MarkerStep(3, (0, 1), kind="loop").to_json()["augmentation"]
'loop'
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from topomark.spec.errors import AlgorithmFailed, OutOfMarkers
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import KeptSignatures, Signature, signature_at

from topomark.reference.explorers.policies import Policies

__all__ = ["MarkerStep", "MarkerWalk"]


@dataclass
class MarkerStep:
    """One iteration: the edge e taken from U, what was sensed at v_u, how S grew, the markers dropped."""

    number: int
    edge: MapDart
    kind: str = ""  # "loop" or "non-loop"
    signature: Signature | None = None
    joined: tuple[MapDart, MapDart] | None = None
    dropped: int = 0  # markers dropped in this iteration
    probes: int = 0  # back-link probes (Algorithm 6.2 lines 21-35)
    hypotheses: list = field(default_factory=list)  # none: §6.2's O(m) algorithms validate without hypotheses

    def to_json(self) -> dict[str, Any]:
        return {"iteration": self.number, "edge": list(self.edge), "signature": str(self.signature),
                "augmentation": self.kind, "joined": [list(d) for d in self.joined] if self.joined else None,
                "dropped": self.dropped, "probes": self.probes, "hypotheses": []}


class MarkerWalk:
    """S, U and the believed pose, with the loop of §6.2; subclasses write :meth:`arrive` (and :meth:`begin`)."""

    name = "marker-walk"
    step_type: type = MarkerStep  # the record of one iteration (a subclass may record more)
    marks_at_end = False  # S shows M's marks only at termination (see finish()); False: S is M

    def __init__(self, robot, policies: Policies | None = None, observer=None, options: dict | None = None):
        self.robot = robot
        self.policies = policies or Policies()
        self.observer = observer
        self.options = dict(options or {})
        self.M = PartialMap()  # the algorithm's map: S with every marker dropped, recorded as sensed
        self.S = PartialMap() if self.marks_at_end else self.M  # what the checker reads (see finish())
        self.S.unexplored = self.M.unexplored  # one U
        self.position: MapDart = (0, 0)  # believed (map vertex, entry exit); exit 0 of v0 is the faced exit
        self.iterations: list[MarkerStep] = []
        self.dropped = 0  # markers dropped so far
        self._finished = False
        self._shown = KeptSignatures()  # map_signature's
        self._shown_upto = 0  # how much of M's journal _shown has taken in

    # -- the explorer contract ---------------------------------------------------
    def start(self) -> None:
        """S ← v0; U ← the edges of v0 (line 1 of every §6.2 listing); then the algorithm's own first drops."""
        degree = self.robot.sense().degree
        self.add_vertex(degree)
        self.M.unexplored.extend((0, i) for i in range(degree))
        self.position = (0, 0)
        self.begin()
        self.finish_start()

    def finish_start(self) -> None:
        """The marks dropped by :meth:`begin` are in the world the checker snapshots after start: S shows them."""
        sig = signature_at(self.M, 0, 0)
        if sig.marked and self.S is not self.M:
            self.S.mark_as_sensed(0, sig, 0)

    def done(self) -> bool:
        """U is empty; then S shows M's marks (see :meth:`finish`)."""
        if self.M.unexplored:
            return False
        self.finish()
        return True

    def finish(self) -> None:
        """Copy M's marks into S once, at termination.

        Decision (a gap in the kernel, reported): the checker compares S's marks,
        step by step, with the world *as it was after start()* (``Checker.world``
        and its incremental I-1 are that snapshot), so a mark dropped later would
        read as a violation of I-1.  S therefore grows with M's vertices, edges and
        U (checked by ``pose``, ``I-1``, ``I-2`` after every step) and receives
        M's marks at termination, where ``isomorphism`` compares them with every
        marker in the world.  The marks dropped at start (before the snapshot) are
        in S from the start.  Once the checker compares with the world as it is
        now (``Checker.sim.world``), ``marks_at_end = False`` makes S the map M
        itself, marks recorded as they are dropped.
        """
        if self._finished or self.S is self.M:
            return
        self._finished = True
        for v in self.M.vertices:
            sig, have = signature_at(self.M, v, 0), signature_at(self.S, v, 0)
            if sig != have:
                self.S.mark_as_sensed(v, Signature(sig.degree, 0 if have.vertex_count else sig.vertex_count,
                                                   None if have.vertex_count else sig.vertex_direction,
                                                   tuple(e for e in sig.edges if e not in have.edges)), 0)

    def step(self) -> MarkerStep:
        """One iteration: remove e = (v_k, v_u) from U, walk S to v_k, follow e, then :meth:`arrive`."""
        edge, parent = self.edge_policy.next_edge(self.M, self.position[0])
        it = self.step_type(len(self.iterations) + 1, edge)
        self.travel_to(it.edge[0], parent)
        self.depart(it)
        it.signature = self.leave(it.edge, "new")
        self.arrive(it, it.signature)
        self.iterations.append(it)
        if self.observer is not None:
            self.observer(self, it)
        return it

    def models(self) -> list[tuple[PartialMap, MapDart]]:
        return [(self.S, self.position)]

    # -- what a subclass writes ----------------------------------------------------
    def begin(self) -> None:
        """After S ← v0 (the robot at v0, entered by exit 0): the algorithm's first drops, if any."""

    def depart(self, it: MarkerStep) -> None:
        """At v_k, about to follow e (a drop "during transit on e", Algorithm 6.3 line 6, is made here)."""

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        """The robot has followed e and senses ``sig`` at v_u: augment S (and drop what the algorithm drops)."""
        raise NotImplementedError

    @property
    def edge_policy(self) -> Policies:
        """Which e leaves U: the edge policy given (``nearest``: the closest known end first)."""
        return self.policies

    # -- motion -----------------------------------------------------------------
    def leave(self, dart: MapDart, purpose: str) -> Signature:
        """Leave the believed position's vertex by map exit ``dart[1]``; the position becomes the far end if S
        knows it (the caller sets it otherwise).  Returns the signature sensed there."""
        v, entry = self.position
        if dart[0] != v:
            raise AlgorithmFailed(f"internal: asked to leave map vertex {dart[0]} while at {v}")
        sig = self.robot.move((dart[1] - entry) % self.M.degree(v), purpose)
        far = self.M.arc(dart)
        self.position = far if far is not None else (-1, -1)
        return sig

    def path_to(self, target: int, parent: dict[int, MapDart]) -> list[MapDart]:
        """The darts of S from the believed position to ``target`` along the BFS tree ``parent`` rooted there."""
        path = []
        x = target
        while x != self.position[0]:
            path.append(parent[x])
            x = parent[x][0]
        return path[::-1]

    def travel_to(self, target: int, parent: dict[int, MapDart]) -> None:
        """Walk S from the believed position to ``target`` along the BFS tree ``parent`` rooted there."""
        for dart in self.path_to(target, parent):
            self.leave(dart, "travel")

    # -- augmentation ---------------------------------------------------------------
    def non_loop(self, it: MarkerStep, sig: Signature) -> int:
        """v_u is new: add it with e as its exit 0, its other exits (clockwise) to U; the robot stands there."""
        u = self.add_vertex(sig.degree)
        self.add_edge(it.edge, (u, 0))
        self.M.unexplored.extend((u, i) for i in range(1, sig.degree))
        it.kind, it.joined = "non-loop", (it.edge, (u, 0))
        self.position = (u, 0)
        self.record_marks()  # a marker dropped on e in transit shows at v_u too
        return u

    def loop(self, it: MarkerStep, far: MapDart) -> None:
        """v_u is the known place of dart ``far`` = e' (entered by it): add e/e' and remove e' from U."""
        try:
            self.M.unexplored.remove(far)
        except ValueError:
            raise AlgorithmFailed(f"internal: e' = {far} identified at iteration {it.number} is not in U") from None
        self.add_edge(it.edge, far)
        it.kind, it.joined = "loop", (it.edge, far)
        self.position = far

    def add_vertex(self, degree: int) -> int:
        if self.S is not self.M:
            self.S.add_vertex(degree)
        return self.M.add_vertex(degree)

    def add_edge(self, a: MapDart, b: MapDart) -> None:
        if self.S is not self.M:
            self.S.add_edge(a, b)
        self.M.add_edge(a, b)

    # -- markers --------------------------------------------------------------------
    def drop(self, op: MarkerOp, it: MarkerStep | None = None) -> None:
        """Drop ``op`` here and record in S what the robot now senses (every dropped marker shown in the map)."""
        self.robot.operate(op)
        self.dropped += op.count
        if it is not None:
            it.dropped += op.count
        self.record_marks()

    def try_drop(self, op: MarkerOp, it: MarkerStep | None = None) -> bool:
        """:meth:`drop` if the robot still has ``op.count`` markers; False (nothing dropped) if it has not."""
        try:
            self.drop(op, it)
        except OutOfMarkers:
            return False
        return True

    def map_signature(self, v: int, entry: int) -> Signature:
        """What M says a robot entering ``v`` by ``entry`` senses (:func:`signature_at` of M), kept until M's
        journal records a mark at ``v`` (M only grows, and a vertex's signature changes only with its marks)."""
        journal = self.M.journal
        self._shown.forget([op[1] for op in journal[self._shown_upto:] if op[0] == "mark"])
        self._shown_upto = len(journal)
        return self._shown.get(self.M, v, entry)

    def record_marks(self) -> None:
        """Record at the believed position the marks the robot senses there that S does not show yet."""
        v, entry = self.position
        sensed, known = self.robot.sense(), self.map_signature(v, entry)
        if sensed == known:
            return
        have = {x for x, _, _ in known.edges}
        edges = tuple(e for e in sensed.edges if e[0] not in have)
        if known.vertex_count and (sensed.vertex_count, sensed.vertex_direction) != \
                (known.vertex_count, known.vertex_direction) or sensed.edges != tuple(sorted(known.edges + edges)):
            raise AlgorithmFailed(f"internal: map vertex {v} shows {known}, the robot senses {sensed}: markers "
                                  "changed where this algorithm drops none")
        vertex = (0, None) if known.vertex_count else (sensed.vertex_count, sensed.vertex_direction)
        self.M.mark_as_sensed(v, Signature(sensed.degree, vertex[0], vertex[1], edges), entry)
