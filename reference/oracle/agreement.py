"""Agreement: whether two worlds show a program the same observations (§3.1: what the robot senses).

A program's *actions* — motions, marker and thread operations, in order — are replayed on two worlds from their
starts; they *agree* when the robot senses the same signature (:class:`~topomark.spec.signature.Signature`, compared
as sensed) before the first action and after each.  This is the robot's own language, which the oracle's guess check
(:mod:`~topomark.reference.oracle.determination`, :mod:`~topomark.reference.oracle.walk_folding`) decides by.

Examples
--------
>>> from topomark.spec.kit import Kit
>>> from topomark.reference.worlds.deterministic import cycle
>>> kit = Kit(vertex=1, directional=True)
>>> agrees(cycle(6), cycle(6).start_state(), cycle(3), cycle(3).start_state(), kit, [1, 1, 1])
(True, 3)
"""

from __future__ import annotations

from array import array
from typing import Sequence, Union

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.kit import Kit, MarkerOp, ThreadOp
from topomark.spec.signature import Signature
from topomark.spec.world import World

from topomark.reference.run.simulator import Simulator

__all__ = ["Action", "REWIND", "act", "agrees", "matches"]

REWIND = "rewind"  # the @2 thread operation that moves back along the thread
Action = Union[int, MarkerOp, ThreadOp, str]
"""One thing the program did: a motion (int), a marker or thread operation, or :data:`REWIND`."""


def act(sim: Simulator, action: Action) -> Signature:
    """Do ``action`` in ``sim``; the signature sensed after it."""
    robot = sim.robot()
    if isinstance(action, int):
        return robot.move(action, "other")
    if isinstance(action, str):
        assert action == REWIND, f"an action is a motion, an operation or {REWIND!r}"
        return robot.rewind("other")
    robot.operate(action)
    return robot.sense()


def agrees(candidate: World, at: tuple[str, int], truth: World, start: tuple[str, int], kit: Kit,
           actions: Sequence[Action], budget: int | None = None) -> tuple[bool | None, int]:
    """Whether ``actions`` sense the same signatures on ``candidate`` from ``at`` as on ``truth`` from ``start``
    (both without markers), and how many actions were replayed; None when ``budget`` actions were replayed without
    a difference and more remain."""
    real, other = Simulator(truth, start, kit), Simulator(candidate, at, kit)
    if str(real.robot().sense()) != str(other.robot().sense()):
        return False, 0
    for done, action in enumerate(actions):
        if budget is not None and done >= budget:
            return None, done
        seen = act(real, action)
        try:
            if str(act(other, action)) != str(seen):
                return False, done + 1
        except (CheckFailure, InvalidInput):  # the candidate refuses what the world allowed: a difference
            return False, done + 1
    return True, len(actions)


def matches(candidate: World, at: tuple[str, int], kit: Kit, actions: Sequence[Action], seen: array,
            budget: int | None = None) -> tuple[bool | None, int]:
    """:func:`agrees` against ``seen``, the hashes of the signatures a replay on the world sensed (the start's
    first), replaying the candidate only; a full match of hashes is then confirmed by :func:`agrees`."""
    other = Simulator(candidate, at, kit)
    if hash(str(other.robot().sense())) != seen[0]:
        return False, 0
    for done, action in enumerate(actions):
        if budget is not None and done >= budget:
            return None, done
        try:
            if hash(str(act(other, action))) != seen[done + 1]:
                return False, done + 1
        except (CheckFailure, InvalidInput):  # the candidate refuses what the world allowed: a difference
            return False, done + 1
    return True, len(actions)
