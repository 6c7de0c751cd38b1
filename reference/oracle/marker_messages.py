"""Marker operations on the wire (``topomark/protocol@2``, thesis §3.1.1, §6.1–6.2, §2.3.1).

A ``drop`` or ``pick_up`` message names its operation with the fields of
:meth:`topomark.spec.kit.MarkerOp.to_json` (minus ``op``, which the message
type says): ``kind`` (``"vertex"`` or ``"edge"``), ``exit`` (edge markers: the
marked exit relative to the entry edge), ``direction`` (drops only: a vertex
marker's relative exit, an edge marker's ``"H"``/``"T"``, or null for an
undirected marker) and ``count`` (default 1).

:func:`op_from_message` turns a message into a :class:`MarkerOp` at a vertex
of a given degree, or raises :class:`~topomark.reference.oracle.protocol.ProtocolError`
of kind ``garbage`` for a malformed field; whether the kit and the markers
lying there allow the operation is the simulator's judgement, not this
module's.  :func:`op_to_message` is the inverse (what ``drive`` sends).

A ``thread`` message (§6.3) names a :class:`~topomark.spec.kit.ThreadOp`:
``op`` one of ``tie``, ``untie``, ``leave``, ``take``, ``knot``, ``rewind``;
``direction`` (``tie`` only: the relative exit the thread is laid out
toward, or null) and ``count`` (``knot`` only: how many knots, default 1).
The world answers each with a ``signature``; ``rewind`` moves the robot back
along the last laid edge (a traversal, counted against the limit), its
``signature`` is the vertex reached.

:func:`refusal` words an operation the world refused for the verdict
(``FAIL [marker]``): what the program asked, when, and why — a pick-up
where fewer markers lie than it asks for says so, in the signature the
robot sensed there.
"""

from __future__ import annotations

import json
from typing import Any, TypeGuard

from topomark.spec.errors import clip
from topomark.spec.kit import MAX_COUNT, MAX_THREAD, THREAD_OPS, Kit, MarkerOp, ThreadOp
from topomark.spec.signature import Signature

from topomark.reference.oracle.protocol import ProtocolError

__all__ = ["MAX_COUNT", "MAX_THREAD", "op_from_message", "op_to_message", "refusal"]



def _int(x: Any) -> TypeGuard[int]:
    return isinstance(x, int) and not isinstance(x, bool)


def _bad(msg: dict, what: str) -> ProtocolError:
    return ProtocolError("garbage", f"{msg['type']}: {what}")


def _shown(value: Any) -> str:
    return clip(json.dumps(value), 60)


def op_from_message(msg: dict[str, Any], degree: int) -> MarkerOp | ThreadOp:
    """The operation a decoded ``@2`` ``drop``/``pick_up``/``thread`` states, at a vertex of ``degree``."""
    if msg["type"] == "thread":
        return _thread_op(msg, degree)
    kind, exit_, count = msg["kind"], msg.get("exit"), msg.get("count", 1)
    direction = msg.get("direction")
    if kind not in ("vertex", "edge"):
        raise _bad(msg, f"kind must be \"vertex\" or \"edge\", got {_shown(kind)}")
    if not (_int(count) and 1 <= count <= MAX_COUNT):
        raise _bad(msg, f"count must be an integer 1..{MAX_COUNT}, got {_shown(count)}")
    if kind == "vertex":
        if exit_ is not None:
            raise _bad(msg, f"a vertex marker takes no exit (got exit {_shown(exit_)})")
        if direction is not None and not (_int(direction) and 0 <= direction < degree):
            raise _bad(msg, f"a vertex marker's direction is an exit 0..{degree - 1} here or null, "
                            f"got {_shown(direction)}")
    else:
        if not (_int(exit_) and 0 <= exit_ < degree):
            raise _bad(msg, f"an edge marker needs an exit 0..{degree - 1} here, got {_shown(exit_)}")
        if direction not in (None, "H", "T"):
            raise _bad(msg, f"an edge marker's direction is \"H\", \"T\" or null, got {_shown(direction)}")
    return MarkerOp(kind, exit=exit_, direction=direction, count=count, pick_up=msg["type"] == "pick_up")


def _thread_op(msg: dict[str, Any], degree: int) -> ThreadOp:
    op, direction, count = msg["op"], msg.get("direction"), msg.get("count", 1)
    if op not in THREAD_OPS:
        raise _bad(msg, f"op must be one of {', '.join(THREAD_OPS)}, got {_shown(op)}")
    if direction is not None and not (op == "tie" and _int(direction) and 0 <= direction < degree):
        raise _bad(msg, f"a direction is an exit 0..{degree - 1} here, on a tie only, got {_shown(direction)}")
    if not (_int(count) and 1 <= count <= MAX_COUNT) or (count != 1 and op != "knot"):
        raise _bad(msg, f"count must be an integer 1..{MAX_COUNT}, and 1 but for a knot, got {_shown(count)}")
    return ThreadOp(op, direction, count)


def op_to_message(op: MarkerOp | ThreadOp) -> dict[str, Any]:
    """The ``@2`` message for ``op``: ``MarkerOp.to_json`` with ``type`` in place of ``op``; a thread op is
    ``{"type": "thread", "op": ..., "direction": ..., "count": ...}``."""
    if isinstance(op, ThreadOp):
        fields = op.to_json()
        del fields["kind"]
        return {"type": "thread", **fields}
    fields = op.to_json()
    return {"type": fields.pop("op"), **fields}


def refusal(asked: dict[str, Any], traversals: int, reason: str, op: MarkerOp | ThreadOp | None = None,
            sensed: Signature | None = None, kit: Kit | None = None) -> str:
    """Why the world refused the message ``asked`` (sent after ``traversals`` traversals), in words.

    ``reason`` is the simulator's; a pick-up ``op`` of a movable ``kit`` where fewer markers lie than it
    asks for is worded from ``sensed`` (the signature there, before the pick-up) instead.

    >>> words = refusal({"type": "pick_up", "kind": "vertex"}, 3, "(the simulator's reason)",
    ...                 MarkerOp("vertex", pick_up=True), Signature(2), Kit(vertex=1, movable=True))
    >>> words.split(" refused: ")
    ['pick_up {"kind": "vertex"} after 3 traversals', 'there is no vertex marker here to pick up (the robot senses [2,A,A])']
    """
    if isinstance(op, MarkerOp) and op.pick_up and sensed is not None and kit is not None and kit.movable:
        vertex = op.kind == "vertex"
        there = sensed.vertex_count if vertex else sum(c for x, c, _ in sensed.edges if x == op.exit)
        place = "here" if vertex else f"on the edge at exit {op.exit}"
        if there == 0:
            reason = f"there is no {op.kind} marker {place} to pick up (the robot senses {sensed})"
        elif there < op.count:
            reason = (f"only {there} {op.kind} marker{'s' if there != 1 else ''} lie {place}, not the {op.count} "
                      f"to pick up (the robot senses {sensed})")
    fields = {k: v for k, v in asked.items() if k != "type"}
    return f"{asked['type']} {_shown(fields)} after {traversals} traversals refused: {reason}"
