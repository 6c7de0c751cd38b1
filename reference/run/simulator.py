"""The simulator: the world, the ground truth and the cost (thesis §3.1.1–3.1.2).

It holds the world and where the robot really is, executes motions, counts
every edge traversal (the thesis's cost metric), enforces the marker class
(what the robot carries and may drop, and its thread, §6.3), and records the
true state after every motion so the checker can compare the explorer's
beliefs with the truth.
Explorers only ever receive :meth:`Simulator.robot`.

Cost and marker accounting — one rule for every algorithm (§3.1.2; §6.2):

* **The cost is every edge traversal**, whatever it was for: "the number of
  edge traversals by the robot" (§3.1.2).  Marker and thread operations cost
  nothing and are counted apart (:attr:`Simulator.operations`).
* **The robot drops and picks up only where it stands**: a vertex marker at
  its vertex, an edge marker on an edge at its vertex, which it senses from
  either end (§6.1).  :meth:`Simulator.operate` acts on the true state, so no
  explorer can drop anywhere else.
* **A drop trip** is a walk made only to carry markers to where they are
  dropped, and back: the moves tagged ``drop``.  They are part of the cost and
  are also counted on their own (:attr:`Simulator.drop_trips`), so a report
  can show the cost with and without them.  Each algorithm walks as its thesis
  text describes: Case 3b "goes back to (non-loop) edge e, dropping a unique
  number of markers on e" and extension-2 "goes back on e, drops i
  markers on e and back" (Algorithm 6.6 line 10): two per marked edge;
  the movable marker "drops the marker at v_k and goes back to v_k'" (§2.3.1);
  the three-undirected-vertex lighthouse walks to the neighbour it marks and
  back (Figure 3.21(b)).  Every other drop is made where the robot
  already is — in transit on e (§6.2.1 Case 1a; Algorithm 6.1 line 10, Algorithm 6.3
  lines 6 and 17; extension-1), or at v_u on v_u or on e (Algorithm 6.1 line 7;
  Algorithm 6.2 line 12, §6.2.2; Algorithms 6.4–6.5) — and makes
  no drop trip.
* **Decision (what the §6.2 findings compare).**  Case 3b's and extension-2's
  trips are not forced by their markers: at v_u the robot stands at an end of
  e and could drop on e there, as Algorithm 6.1 line 7 does in the
  same place.  The thesis's O(m) argument counts no motion for marking
  ("Physical motion for both place and back-link validations is avoided",
  §6.2.1 Case 3b) and its finding that Case 3b costs "very close to the optimal cost
  m" (§6.2.1) holds only without them.  So the findings that compare these
  costs with m or with each other compare the cost without drop trips, and
  show the full cost beside it.
"""

from __future__ import annotations

import json
from collections import Counter, deque

from topomark.spec.errors import CheckFailure, InvalidInput, OutOfMarkers, Violation
from topomark.spec.kit import Kit, MarkerOp, ThreadOp
from topomark.spec.markerlayer import MarkerLayer, apply_op
from topomark.spec.robot import State, step
from topomark.spec.signature import Signature
from topomark.spec.world import World

from topomark.reference.explorers.robot import PURPOSES, Robot

__all__ = ["Simulator", "EVENTS_KEPT"]

EVENTS_KEPT = 1000
"""How many of the latest marker and thread operations :attr:`Simulator.events` keeps."""


class Simulator:
    """Plays ``world`` to a robot starting in ``state`` and carrying ``kit``.

    ``kit`` is a :class:`~topomark.spec.kit.Kit` (or its protocol form, e.g.
    ``{"directional-vertex": 1}``).  Markers live in a
    :class:`~topomark.spec.markerlayer.MarkerLayer` over the world's rotation;
    :attr:`world` is the world as it is now, markers dropped so far included.
    ``listener`` (optional) is called with ``(motion, purpose, signature,
    true_state)`` after every traversal.  Edge traversals are the cost
    (§3.1.2); marker operations are counted apart in :attr:`operations` and
    logged, with the step they followed and the signature sensed just after,
    in :attr:`events` — the last :data:`EVENTS_KEPT` only, so a robot that
    drops and picks up a marker forever without moving holds constant memory
    (the counts in :attr:`operations` are exact; a caller that must stop such a
    robot caps them, as ``run-external``'s ``--max-operations`` does);
    ``op_listener`` (optional) is called with each such
    event as it happens, so moves and marker operations reach a trace in the
    order the robot did them (``spec/trace.md``, trace@2's robot layer).
    :attr:`held` is what the robot still carries: each kind's own markers and
    the kit's vertex-or-edge pool (``"either"``, §6.2.1 Case 1b); a drop draws
    on its kind's own first, then on the pool (:meth:`Kit.draw`), and running
    out of both is :class:`~topomark.spec.errors.OutOfMarkers`.

    Threads (§6.3, :mod:`topomark.spec.thread`): a :class:`ThreadOp` is gated
    by the kit's thread like a marker operation; holding the free end of a
    tied thread, every move lays it or — back along the last laid edge —
    rewinds it; a move that would lay more than the kit's length is refused
    before the robot moves.  A rewinding move is a traversal (cost, §3.1.2)
    and is also logged as a ``rewind`` operation, just after the move.
    """

    def __init__(self, world: World, state: State, kit: Kit | dict | None = None, listener=None, op_listener=None):
        self.layer = MarkerLayer(world)
        self.state = state
        self.kit = kit if isinstance(kit, Kit) else Kit.from_json(kit or {})
        self.held = Counter({"vertex": self.kit.vertex, "edge": self.kit.edge, "either": self.kit.either})
        self.cost = 0
        self.by_purpose: Counter[str] = Counter()
        self.operations: Counter[str] = Counter()
        self.events: deque[dict] = deque(maxlen=EVENTS_KEPT)
        self.listener = listener
        self.op_listener = op_listener

    @property
    def drop_trips(self) -> int:
        """The traversals made only to carry markers to where they are dropped, and back (part of :attr:`cost`)."""
        return self.by_purpose["drop"]

    @property
    def world(self) -> World:
        """The world with every marker now lying in it."""
        return self.layer.world()

    # -- the explorer's side -------------------------------------------------
    def robot(self) -> Robot:
        return Robot(self._move, self._sense, self.operate, self._rewind)

    def _move(self, motion: int, purpose: str) -> Signature:
        if purpose not in PURPOSES:
            raise CheckFailure(Violation("robot interface", "move", f"a purpose in {PURPOSES}", repr(purpose)))
        try:
            before = self.state
            self.state = step(self.layer, before, motion)
        except InvalidInput as exc:
            raise CheckFailure(Violation("robot interface", f"step {self.cost + 1}", "an existing exit",
                                         str(exc), "the explorer asked for an exit that does not exist")) from None
        rewound = False
        if self.layer.thread.tied is not None:
            try:
                rewound = self.layer.pull(before, motion, self.kit.thread or 0)
            except InvalidInput as exc:
                self.state = before
                raise CheckFailure(Violation("marker kit", f"step {self.cost + 1} at vertex {before[0]!r}",
                                             "a move the thread allows", f"motion {motion}", str(exc))) from None
        self.cost += 1
        self.by_purpose[purpose] += 1
        sig = self.layer.sensed(self.state)
        if self.listener is not None:
            self.listener(motion, purpose, sig, self.state)
        if rewound:
            self._log(ThreadOp("rewind"))
        return sig

    def _rewind(self, purpose: str) -> Signature:
        """Move back along the last laid edge, picking the thread up (a traversal, §3.1.2)."""
        try:
            motion = self.layer.thread.rewind_exit(self.base_world, self.state)
        except InvalidInput as exc:
            raise CheckFailure(Violation("marker kit", f"step {self.cost} at vertex {self.state[0]!r}",
                                         "an operation the kit allows", '{"op": "rewind"}', str(exc))) from None
        return self._move(motion, purpose)

    @property
    def base_world(self) -> World:
        """The world's rotation (markers as the run began)."""
        return self.layer.base

    def _log(self, op: MarkerOp | ThreadOp) -> None:
        self.operations[op.op if isinstance(op, ThreadOp) else "pick_up" if op.pick_up else "drop"] += 1
        event = {"step": self.cost, **op.to_json(), "signature": str(self.layer.sensed(self.state))}
        self.events.append(event)
        if self.op_listener is not None:
            self.op_listener(event)

    def _sense(self) -> Signature:
        return self.layer.sensed(self.state)

    def operate(self, op: MarkerOp | ThreadOp) -> None:
        """Carry out a marker or thread operation, gated by the kit; a refused one is the explorer's fault."""
        where = f"step {self.cost} at vertex {self.state[0]!r}"
        directional = op.direction is not None
        if isinstance(op, ThreadOp):
            reason = self.kit.thread_refusal()
        elif not op.pick_up:
            reason = self.kit.refusal(op.kind, directional, op.count, self.kit.count(op.kind) - self.held[op.kind],
                                      self.kit.either - self.held["either"])
        elif not self.kit.movable:
            reason = f"the kit ({self.kit.describe()}) holds immovable markers: none may be picked up"
        else:
            reason = None
        if reason is None:
            try:
                apply_op(self.layer, self.state, op)
            except InvalidInput as exc:
                reason = str(exc)
        if reason is not None:
            out = not isinstance(op, ThreadOp) and not op.pick_up and self.kit.count(op.kind) + self.kit.either \
                and self.held[op.kind] + self.held["either"] < op.count \
                and directional == self.kit.directional  # running out is a named outcome, not a crash
            raise (OutOfMarkers if out else CheckFailure)(Violation(
                "marker kit", where, "an operation the kit allows", json.dumps(op.to_json()), reason))
        if isinstance(op, ThreadOp):
            return self._log(op)
        if op.pick_up:  # never from a pool: a kit with one is never movable (spec/kit.py)
            self.held[op.kind] += op.count
        else:  # the kind's own markers first, then the pool (Kit.draw)
            own, pooled = self.kit.draw(op.kind, op.count, self.kit.count(op.kind) - self.held[op.kind])
            self.held[op.kind] -= own
            self.held["either"] -= pooled
        self._log(op)
