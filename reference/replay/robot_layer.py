"""Replaying a trace's robot layer: every move and marker operation re-executed on the world (``spec/trace.md``).

What the robot did is the same record for every algorithm: ``move`` records
(a motion, the perception sensed after it) and, in ``topomark/trace@2``,
``op`` records (a marker operation, the signature sensed after it), in the
order the robot did them.  :class:`RobotLayer` re-executes them with a
:class:`~topomark.reference.run.simulator.Simulator` carrying the header's kit,
from the world's start, and raises :class:`~topomark.reference.replay.divergence.
Diverged` at the first claim the world contradicts:

* a move's ``step`` is the number of traversals so far, plus one; its motion
  an exit of the vertex the robot is at; its ``perception`` what the robot
  senses after it (:mod:`topomark.spec.robot`);
* an op's ``step`` is the number of traversals before it; the simulator
  carries it out as the kit and the world allow (a refusal — a marker the kit
  does not hold, an exit that does not exist, nothing to pick up — is a
  divergence, not bad input: the trace claims the robot did it); its
  ``signature`` is what the robot senses just after;
* a thread op (§6.3: ``tie``, ``untie``, ``leave``, ``take``, ``knot``) is
  carried out like a marker op; a ``rewind`` op is not an operation of its
  own but the record that the move just replayed rewound the thread (a move
  back along the last laid edge, holding the free end): replay checks that
  it did, and that every move that rewound is followed by one;
* the ``end``'s ``cost`` is the number of traversals replayed.
"""

from __future__ import annotations

import json
from typing import Any

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.kit import THREAD_OPS, Kit, MarkerOp, ThreadOp
from topomark.spec.world import World

from topomark.reference.replay.divergence import diverge
from topomark.reference.run.explore import prepare_world
from topomark.reference.explorers.lighthouses import Lighthouse
from topomark.reference.run.simulator import Simulator

__all__ = ["RobotLayer", "marker_op"]


def marker_op(rec: dict[str, Any]) -> MarkerOp | ThreadOp:
    """The :class:`MarkerOp` or :class:`ThreadOp` an ``op`` record states."""
    if rec["op"] in THREAD_OPS:
        return ThreadOp(rec["op"], rec.get("direction"), rec["count"])
    return MarkerOp(rec["kind"], rec.get("exit"), rec.get("direction"), rec["count"], rec["op"] == "pick_up")


def _op_text(rec: dict[str, Any]) -> str:
    return json.dumps(marker_op(rec).to_json(), sort_keys=True)


class RobotLayer:
    """The world, the robot in it and the traversals replayed so far."""

    def __init__(self, world: World, lighthouse: Lighthouse | None, kit: Kit):
        if lighthouse is not None:
            bare, state = prepare_world(world, lighthouse)
        elif world.markers:
            raise InvalidInput("the world file carries markers, but the trace names no lighthouse that drops them: "
                               "give the world without markers")
        else:
            bare, state = world, world.start_state()
        self.start = state
        self.rewinds: list[int] = []  # the steps whose moves rewound the thread, not yet claimed by a rewind op
        self.sim = Simulator(bare, state, kit, op_listener=self._rewound)
        self.robot = self.sim.robot()
        self.steps = 0
        self.ops = 0

    def step(self, rec: dict[str, Any]) -> str:
        """Count a move; its ``step`` must be the count.  Returns the move's name (``step k``)."""
        self._unclaimed(f"step {self.steps + 1}")
        self.steps += 1
        where = f"step {self.steps}"
        if rec["step"] != self.steps:
            diverge(where, f"step number {self.steps}", str(rec["step"]), "steps must run 1, 2, 3, ...")
        return where

    def move(self, rec: dict[str, Any], where: str) -> str:
        """Execute the move's motion; its perception must be the world's.  Returns the perception."""
        v, _ = self.sim.state
        degree = self.sim.world.degree(v)
        if not 0 <= rec["motion"] < degree:
            diverge(where, f"a motion 0..{degree - 1} (the robot is at a vertex of degree {degree})",
                    f"motion {rec['motion']}")
        try:
            got = str(self.robot.move(rec["motion"], "other"))
        except CheckFailure as exc:  # the kit refuses the move (a thread laid past its length)
            diverge(where, "a move the kit allows", f"motion {rec['motion']}", exc.violation.detail, check="marker kit")
        if rec["perception"] != got:
            diverge(where, f"perception {got} (motion {rec['motion']} on the world)", f"perception {rec['perception']}")
        return got

    def op(self, rec: dict[str, Any]) -> str:
        """Carry out the op as the kit and the world allow; its step and signature must be the world's.
        Returns the signature sensed after it."""
        self.ops += 1
        where = f"op {self.ops} (after step {self.steps})"
        if rec["step"] != self.steps:
            diverge(where, f"step {self.steps} (the traversals before the op)", str(rec["step"]))
        if rec["op"] == "rewind":
            if self.rewinds != [self.steps]:
                diverge(where, "a rewind op only just after a move that rewound the thread", "a rewind op",
                        "the move before it did not pick the thread up", check="marker kit")
            self.rewinds.clear()
            return self._sensed(rec, where)
        self._unclaimed(where)
        try:
            self.sim.operate(marker_op(rec))
        except CheckFailure as exc:
            diverge(where, "an operation the kit and the world allow", _op_text(rec), exc.violation.detail,
                    check="marker kit")
        return self._sensed(rec, where)

    def _sensed(self, rec: dict[str, Any], where: str) -> str:
        got = str(self.robot.sense())
        if rec["signature"] != got:
            diverge(where, f"signature {got} (sensed after the op)", rec["signature"])
        return got

    def _rewound(self, event: dict[str, Any]) -> None:
        if event["op"] == "rewind":
            self.rewinds.append(event["step"])

    def _unclaimed(self, where: str) -> None:
        """A move that rewound the thread must be recorded as one: the next record is its rewind op."""
        if self.rewinds:
            diverge(where, f"a rewind op after step {self.rewinds[0]} (its move rewound the thread)", "none",
                    check="marker kit")

    def end(self, rec: dict[str, Any]) -> None:
        self._unclaimed("end")
        if rec["cost"] != self.steps:
            diverge("end", f"cost {self.steps} (the traversals replayed)", f"cost {rec['cost']}")
