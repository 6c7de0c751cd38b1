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
the edge e itself; ``travel`` — walking S to v_k; ``drop`` — drop trips, made only to
drop markers (Algorithm 6.6 line 10: "goes back on e, drops i markers on e and
back"; the accounting rule: :mod:`topomark.reference.run.simulator`);
``validation`` / ``retrace`` — back-link probes and their returns
(Algorithm 6.2 lines 21–35).

The map is S (also named ``M`` in these modules: the algorithm's map): every
marker dropped is recorded in it as the robot senses it, so after every step
the checker compares it with the world as it is then, dropped markers
included.

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
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import KeptSignatures, Signature

from topomark.reference.explorers.policies import Policies
from topomark.reference.explorers.walker import MapWalker, StepRecord

__all__ = ["MarkerStep", "MarkerWalk"]


@dataclass
class MarkerStep(StepRecord):
    """One iteration: the edge e taken from U, what was sensed at v_u, how S grew, the markers dropped (no
    hypotheses: §6.2's O(m) algorithms validate without them)."""

    dropped: int = 0  # markers dropped in this iteration
    probes: int = 0  # back-link probes (Algorithm 6.2 lines 21-35)
    candidates: list[int] = field(default_factory=list)  # known vertices that could be v_u (footprint searches)
    found: int | None = None  # the known vertex v_u turned out to be (footprint searches)

    def to_json(self) -> dict[str, Any]:
        return {"iteration": self.number, "edge": list(self.edge), "signature": str(self.signature),
                "augmentation": self.kind, "joined": self.joined_json(),
                "dropped": self.dropped, "probes": self.probes, "hypotheses": []}


class MarkerWalk(MapWalker):
    """S, U and the believed pose, with the loop of §6.2; subclasses write :meth:`arrive` (and :meth:`begin`).
    The start, termination, walks of S and augmentations are the :class:`~.walker.MapWalker`'s."""

    name = "marker-walk"
    step_type: type = MarkerStep  # the record of one iteration (a subclass may record more)

    def __init__(self, robot, policies: Policies | None = None, observer=None, options: dict | None = None):
        super().__init__(robot, policies, observer)
        self.options = dict(options or {})
        self.M = self.S  # the algorithm's map, S: every marker dropped recorded as sensed
        self.dropped = 0  # markers dropped so far
        self._shown = KeptSignatures()  # map_signature's
        self._shown_upto = 0  # how much of M's journal _shown has taken in

    # -- the explorer contract: start, step (done, models: the walker's) -----------------
    def start(self) -> None:
        """S ← v0; U ← the edges of v0 (line 1 of every §6.2 listing); then the algorithm's own first drops."""
        super().start()
        self.begin()

    def step(self) -> MarkerStep:
        """One iteration: remove e = (v_k, v_u) from U, walk S to v_k, follow e, then :meth:`arrive`."""
        edge, parent = self.edge_policy.next_edge(self.M, self.position[0])
        it = self.step_type(len(self.iterations) + 1, edge)
        self.travel_to(it.edge[0], parent)
        self.depart(it)
        it.signature = self.leave(it.edge, "new")
        self.arrive(it, it.signature)
        return self.record(it)

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
        v = self.position[0]
        if dart[0] != v:
            raise AlgorithmFailed(f"internal: asked to leave map vertex {dart[0]} while at {v}")
        sig = self.take_exit(dart[1], purpose)
        far = self.M.arc(dart)
        self.position = far if far is not None else (-1, -1)
        return sig

    # -- augmentation ---------------------------------------------------------------
    def non_loop(self, it: MarkerStep, sig: Signature) -> int:
        """v_u is new: add it with e as its exit 0, its other exits (clockwise) to U; the robot stands there."""
        u = self.non_loop_augment(it, sig)
        self.record_marks()  # a marker dropped on e in transit shows at v_u too
        return u

    def loop(self, it: MarkerStep, far: MapDart) -> None:
        """v_u is the known place of dart ``far`` = e' (entered by it): add e/e' and remove e' from U."""
        self.loop_augment(it, far)
        self.position = far

    def not_in_u(self, it: MarkerStep, far: MapDart) -> Exception:
        """e' not in U: the algorithm identified a place wrongly (the ``failed`` outcome)."""
        return AlgorithmFailed(f"internal: e' = {far} identified at iteration {it.number} is not in U")

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
