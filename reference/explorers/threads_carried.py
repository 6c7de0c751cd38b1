"""Mapping by carrying an l = ε thread: the thread as a directional movable marker (thesis §6.3.1).

"The thread now can be used as a movable directional marker ... we can run
the single movable marker algorithm described in [26] but with reduced
validation efforts.  At each new place v_u via e, the robot ties the thread
at v_u and lays it out toward the entry edge.  The robot then searches S
looking for the thread.  If the thread is not found, then v_u has not been
visited before.  If the thread is found tied at some vertex v_k' in S then
both the place and back-link can be determined immediately due to the
'directional' thread in the vertex" (§6.3.1).  That is, word for word, the
directional variant of Dudek et al.'s algorithm (§2.3.1), which
:class:`~topomark.reference.explorers.movable_marker.DirectionalMovableMarkerExplorer`
already is.  So this module runs that explorer unchanged over
:class:`ThreadAsMarker`, a view of the robot in which the ε thread *is* the
directional movable vertex marker — the thesis's own argument (§6.3.1: "can be
considered as a generalization of a directional marker", §6.3.1), made
executable:

* dropping the marker pointing at relative exit ``p`` is tying the thread
  here laid out toward ``p`` (``tie`` with direction ``p``) and leaving its
  free end here (``leave``: an l = ε thread cannot be laid along an edge, so
  the robot lets go of it before it moves on, §6.3.1);
* picking the marker up is untying the thread (``untie``; nothing is laid);
* a vertex where the thread is tied toward relative exit ``p`` (``T-p`` in
  :mod:`topomark.spec.signature`) is sensed as ``V-p``; anything else as
  unmarked (the free end ``F`` lying with the tie adds nothing).

Every decision of the movable marker explorer carries over (how the robot
returns after a tie: back over e, §2.3.1; which known vertices are searched;
the thread is untied at the end of every step, so between steps the world
carries no thread and S shows none): see its module docstring.  Cost O(mn)
(§6.3.1: "the robot may have to visit each vertex in S in order to validate
an edge"); the registry states our exact bound, the directional variant's.

Examples
--------
>>> CarriedThreadExplorer.name
'thread-carried'
"""

from __future__ import annotations

from typing import cast

from topomark.spec.errors import TopomarkFault
from topomark.spec.kit import MarkerOp, ThreadOp
from topomark.spec.signature import Signature

from topomark.reference.explorers.movable_marker import DirectionalMovableMarkerExplorer

__all__ = ["ThreadAsMarker", "CarriedThreadExplorer"]


class ThreadAsMarker:
    """The robot with its l = ε thread seen as one directional movable vertex marker (§6.3.1)."""

    __slots__ = ("_robot",)

    def __init__(self, robot) -> None:
        self._robot = robot

    @staticmethod
    def as_marker(sig: Signature) -> Signature:
        """``T-p`` (tied here toward relative exit p) reads as ``V-p``; no tie reads as unmarked."""
        t = sig.thread
        if t is None or not t.tied:
            return Signature(sig.degree)
        return Signature(sig.degree, 1, t.head)

    def move(self, motion: int, purpose: str = "other") -> Signature:
        return self.as_marker(self._robot.move(motion, purpose))

    def sense(self) -> Signature:
        return self.as_marker(self._robot.sense())

    def operate(self, op: MarkerOp) -> None:
        """A vertex marker drop is tie + leave; a pick-up is untie (the thread never lies along an edge)."""
        if op.kind != "vertex" or op.count != 1:
            raise TopomarkFault(f"the ε thread stands for one vertex marker, not {op}")
        if op.pick_up:
            self._robot.operate(ThreadOp("untie"))
        else:
            self._robot.operate(ThreadOp("tie", direction=cast("int | None", op.direction)))  # a vertex marker
            self._robot.operate(ThreadOp("leave"))


class CarriedThreadExplorer(DirectionalMovableMarkerExplorer):
    """§6.3.1's carried l = ε thread: the directional movable marker algorithm over
    :class:`ThreadAsMarker`."""

    name = "thread-carried"

    def __init__(self, robot, policies=None, observer=None, options=None):
        super().__init__(ThreadAsMarker(robot), policies, observer, options)
