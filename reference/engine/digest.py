"""The trace digest: one 64-bit number for the sequence of a run's robot actions (thesis §3.1.1–3.1.2).

A run's *actions* are what the robot is told to do, in order: every motion
(the relative exit ``l`` of §3.1.1, tagged with its purpose for the cost
accounting of §3.1.2) and every marker operation (§3.3: the drop of the
directional marker).  Perceptions are not actions: they follow from the
actions and the world.  Two runs of the same explorer on the same world and
start that do the same actions made the same decisions, so comparing the
action sequences (or their digests) compares the runs step by step.

Each action is an integer *code*:

* a motion ``l`` with purpose ``p`` (the index of ``p`` in
  :data:`~topomark.reference.explorers.robot.PURPOSES`) is ``16 l + p`` (≥ 0);
* a marker operation is ``-1 - packed`` (< 0), ``packed`` holding the
  operation (drop, pick up), the kind (vertex, edge, thread), the count, the
  relative exit of an edge marker and the direction (:func:`op_code`).

The digest of a code sequence is FNV-1a over 64-bit words: start from the FNV
offset basis, and for each code xor in its 64-bit two's complement and multiply
by the FNV prime, modulo 2⁶⁴ (:func:`digest`).  The functions here are plain
integer arithmetic, so the compiled engine compiles these very functions
(:mod:`.robot`): the codes are defined once.

Examples
--------
>>> move_code(2, PURPOSE["travel"]), move_code(0, PURPOSE["retrace"])
(32, 3)
>>> op_code("drop", "vertex", 1, None, 0) < 0
True
>>> digest([]) == FNV_OFFSET, digest([1, 2]) != digest([2, 1])
(True, True)
"""

from __future__ import annotations

from typing import Iterable

from topomark.reference.explorers.robot import PURPOSES

__all__ = ["PURPOSE", "FNV_OFFSET", "FNV_PRIME", "move_code", "pack_op", "op_code", "event_code", "digest",
           "describe"]

PURPOSE = {name: k for k, name in enumerate(PURPOSES)}
"""Each purpose's index in :data:`~topomark.reference.explorers.robot.PURPOSES` (under 16)."""

FNV_OFFSET = 0xCBF29CE484222325
FNV_PRIME = 0x100000001B3
_MASK = (1 << 64) - 1
_OPS = ("drop", "pick_up", "tie", "untie", "leave", "take", "knot", "rewind")  # MarkerOp's, then THREAD_OPS
_KINDS = ("vertex", "edge", "thread")
_ENDS = {"H": 1, "T": 2}


def move_code(motion: int, purpose: int) -> int:
    """The code of motion ``motion`` made for purpose index ``purpose``."""
    return motion * 16 + purpose


def pack_op(op: int, kind: int, count: int, exit_code: int, direction_code: int) -> int:
    """The code of a marker or thread operation from small integers: ``op`` (its index in drop, pick up and
    :data:`~topomark.spec.kit.THREAD_OPS`; < 8), ``kind`` (0 vertex,
    1 edge, 2 thread), ``count`` (< 64), ``exit_code`` (0: none, else the relative exit + 1; < 256) and
    ``direction_code`` (0: undirected, 1/2: an edge marker's head/tail, else a vertex marker's relative
    direction + 3)."""
    return -1 - (op + 8 * (kind + 4 * (count + 64 * (exit_code + 256 * direction_code))))


def op_code(op: str, kind: str, count: int, exit_: int | None, direction: int | str | None) -> int:
    """The code of an operation as :meth:`~topomark.spec.kit.MarkerOp.to_json` (or a thread operation's JSON
    form, kind ``"thread"``) states it."""
    if direction is None:
        d = 0
    elif isinstance(direction, str):
        d = _ENDS[direction]
    else:
        d = direction + 3
    return pack_op(_OPS.index(op), _KINDS.index(kind), count, 0 if exit_ is None else exit_ + 1, d)


def event_code(record: dict) -> int | None:
    """The code of one trace record (``spec/trace.md``): a ``move``, a ``drop`` (trace@1's directional vertex
    marker) or an ``op``; None for any other record (header, iteration, end)."""
    event = record.get("event")
    if event == "move":
        return move_code(record["motion"], PURPOSE[record["purpose"]])
    if event == "drop":
        return op_code("drop", "vertex", 1, None, record.get("direction"))
    if event == "op":
        return op_code(record["op"], record["kind"], record.get("count", 1), record.get("exit"),
                       record.get("direction"))
    return None


def digest(codes: Iterable[int]) -> int:
    """FNV-1a over the codes as 64-bit words: the trace digest of a run."""
    h = FNV_OFFSET
    for code in codes:
        h = ((h ^ (int(code) & _MASK)) * FNV_PRIME) & _MASK
    return h


def describe(code: int) -> str:
    """A code in words, for a report of the first differing action."""
    if code >= 0:
        return f"move {code // 16} ({PURPOSES[code % 16] if code % 16 < len(PURPOSES) else '?'})"
    packed = -1 - code
    op, kind = _OPS[packed % 8], _KINDS[(packed // 8) % 4] if (packed // 8) % 4 < 3 else "?"
    count, exit_code, d = (packed // 32) % 64, (packed // 2048) % 256, packed // 524288
    where = f" on relative exit {exit_code - 1}" if exit_code else ""
    way = "" if d == 0 else f" head {'HT'[d - 1]}" if d < 3 else f" pointing at relative exit {d - 3}"
    return f"{op} {count} {kind} marker(s){where}{way}"
