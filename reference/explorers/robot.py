"""The robot interface: all an explorer may know of the world (thesis §3.1.1).

An explorer moves by a relative exit index and receives the signature of the
vertex reached; it may sense the signature where it stands and operate the
markers its marker class allows.  It never sees the world, its vertex names,
or where it really is.  :class:`Robot` is the only object an explorer is given;
explorer modules import nothing from :mod:`topomark.reference.run.simulator` or
:mod:`topomark.spec.world` (``tests/test_wall.py`` enforces this).

``purpose`` tags each motion for the cost accounting of §3.1.2 (``travel`` to
v_k, the ``new`` edge, hypothesis ``validation``, ``retrace``, a ``drop`` trip);
the simulator counts every traversal whatever the tag says (the accounting
rule: :mod:`topomark.reference.run.simulator`).

Threads (§6.3): :meth:`Robot.operate` also takes a
:class:`~topomark.spec.kit.ThreadOp` (tie, untie, leave, take, knot);
holding the free end of a tied thread, every :meth:`Robot.move` lays it;
:meth:`Robot.rewind` moves back along the last laid edge, picking it up
(a traversal like any move).
"""

from __future__ import annotations

from typing import Callable

from topomark.spec.errors import TopomarkFault
from topomark.spec.kit import MarkerOp, ThreadOp
from topomark.spec.signature import Signature

__all__ = ["Robot", "PURPOSES"]

PURPOSES = ("travel", "new", "validation", "retrace", "expansion", "other", "establish", "probe", "drop")
"""``establish``: moves that set up a lighthouse (§5.1/§6.1's random walk to its place);
``probe``: out-and-back traversals that sense neighbours (§5.1's D, recognising a lighthouse whose back-link needs them);
``drop``: a *drop trip*, traversals made only to carry markers to where they are dropped and back (the simulator's
drop-trip sub-count, :attr:`~topomark.reference.run.simulator.Simulator.drop_trips`)."""


class Robot:
    """A narrow handle on a simulator: motions, perceptions and marker operations only."""

    __slots__ = ("_move", "_sense", "_operate", "_rewind")

    def __init__(self, move: Callable[[int, str], Signature], sense: Callable[[], Signature],
                 operate: Callable[[MarkerOp | ThreadOp], None],
                 rewind: Callable[[str], Signature] | None = None):
        self._move, self._sense, self._operate, self._rewind = move, sense, operate, rewind

    def move(self, motion: int, purpose: str = "other") -> Signature:
        """Leave through exit ``motion`` counted clockwise from the entry edge; return the signature reached."""
        return self._move(motion, purpose)

    def sense(self) -> Signature:
        """The signature of the current vertex relative to the current entry edge."""
        return self._sense()

    def operate(self, op: MarkerOp | ThreadOp) -> None:
        """Drop or pick up markers here (:class:`~topomark.spec.kit.MarkerOp`), or operate the thread
        (:class:`~topomark.spec.kit.ThreadOp`), as the kit allows."""
        self._operate(op)

    def rewind(self, purpose: str = "retrace") -> Signature:
        """Move back along the thread's last laid edge, picking it up; return the signature reached."""
        if self._rewind is None:
            raise TopomarkFault("this robot (a link without a thread) cannot rewind a thread")
        return self._rewind(purpose)

    def drop_marker(self, direction: int | None = None) -> None:
        """Drop a vertex marker here; directional markers point at relative exit ``direction``."""
        self._operate(MarkerOp("vertex", direction=direction))
