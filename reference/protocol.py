"""The explorer protocol ``topomark/protocol@1``: JSON Lines between a world and an explorer.

The thesis separates the robot from the world it explores (§3.1.1): the
robot only issues motions and marker operations and receives signatures.
This module turns that interface into a wire protocol (documented in
``spec/protocol.md``) so that topomark can play a world to another program
(``run-external``, :mod:`topomark.reference.external`) or drive another
program's world with the reference explorer (``drive``,
:mod:`topomark.reference.drive`).

Contents:

* :func:`encode` / :func:`decode` — one message per line, validated field by
  field against :data:`MESSAGES`;
* :func:`clip` — what a verdict may quote of the other side's input (a
  bounded piece, never a whole line);
* :func:`snapshot_to_map` / :func:`map_to_snapshot` — (S, U) of §3.1.3 on
  the wire.
"""

from __future__ import annotations

import json
from typing import Any, Sequence

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.jsontext import parse_json
from topomark.spec.mapstate import PartialMap

__all__ = ["PROTOCOL", "MESSAGES", "ProtocolError", "encode", "decode", "clip", "snapshot_to_map",
           "map_to_snapshot", "MAX_LINE", "MAX_MESSAGE"]

PROTOCOL = "topomark/protocol@1"
MAX_LINE = 4_000_000  # bytes; a longer line is garbage
MAX_MESSAGE = 2000  # characters of a verdict message; what the other side sent is quoted clipped

_INT, _STR, _OBJ, _LIST = "integer", "string", "object", "list"
_OPT_INT = "integer or null"

# type -> {field: kind}; every listed field is required, no other field is allowed.
MESSAGES: dict[str, dict[str, str]] = {
    "hello": {"protocol": _STR, "role": _STR, "markers": _OBJ, "signature": _STR},
    "move": {"motion": _INT},
    "drop": {"direction": _OPT_INT},
    "signature": {"value": _STR},
    "snapshot": {"S": _OBJ, "U": _LIST},
    "map": {"world": _OBJ},
    "error": {"message": _STR},
    "bye": {},
}
_OPTIONAL: dict[str, dict[str, str]] = {
    "hello": {"limits": _OBJ},
    "snapshot": {"iteration": _INT},
    "signature": {"step": _INT},
    "bye": {"verdict": _STR, "cost": _INT, "message": _STR},
}


class ProtocolError(Exception):
    """The other side broke the protocol: ``kind`` is garbage, timeout, crash, limit or protocol."""

    def __init__(self, kind: str, message: str):
        super().__init__(clip(message, MAX_MESSAGE))
        self.kind = kind


def encode(msg: dict[str, Any]) -> str:
    return json.dumps(msg, sort_keys=True, separators=(",", ":")) + "\n"


def _is_kind(value: Any, kind: str) -> bool:
    if kind == _INT:
        return isinstance(value, int) and not isinstance(value, bool)
    if kind == _OPT_INT:
        return value is None or _is_kind(value, _INT)
    return isinstance(value, {_STR: str, _OBJ: dict, _LIST: list}[kind])


def decode(line: str, expect: Sequence[str] | None = None) -> dict[str, Any]:
    """Parse and validate one line; raises :class:`ProtocolError` (kind ``garbage``) on anything wrong."""
    text = line.strip()
    try:
        msg = parse_json(text, "the line")  # bounded depth and integers: nothing can blow up later
    except InvalidInput as exc:
        raise ProtocolError("garbage", f"not a JSON object: {clip(text)!r} ({clip(str(exc), 200)})") from None
    if not isinstance(msg, dict) or not isinstance(msg.get("type"), str):
        raise ProtocolError("garbage", f"not a message (a JSON object with a string \"type\"): {clip(text)!r}")
    kind = msg["type"]
    if kind not in MESSAGES:
        raise ProtocolError("garbage", f"unknown message type {clip(kind)!r} (known: {', '.join(MESSAGES)})")
    if expect is not None and kind not in expect:
        raise ProtocolError("protocol", f"unexpected message {kind!r} here (expected {' or '.join(expect)})")
    fields = {**MESSAGES[kind], **_OPTIONAL.get(kind, {})}
    for name, want in fields.items():
        if name in msg and not _is_kind(msg[name], want):
            raise ProtocolError("garbage", f"{kind}.{name} must be {want}, got {clip(json.dumps(msg[name]))}")
    missing = [f for f in MESSAGES[kind] if f not in msg]
    unknown = sorted(set(msg) - set(fields) - {"type"})
    if missing or unknown:
        what = f"missing field {missing[0]!r}" if missing else f"unknown field {clip(unknown[0])!r}"
        raise ProtocolError("garbage", f"{kind} message: {what}")
    return msg


def clip(text: str, limit: int = 120) -> str:
    """``text`` cut to ``limit`` characters (with "..." and the full length when cut)."""
    return text if len(text) <= limit else f"{text[:limit]}... ({len(text):,} characters)"


# -- (S, U) on the wire -----------------------------------------------------------
def _dart(x: Any, what: str) -> tuple[int, int]:
    if not (isinstance(x, list) and len(x) == 2 and all(_is_kind(k, _INT) for k in x)):
        raise CheckFailure(f"{what} must be a map dart [vertex, exit], got {clip(json.dumps(x))}")
    return (x[0], x[1])


def snapshot_to_map(S_obj: dict[str, Any], U: list[Any]) -> PartialMap:
    """Rebuild S and U from a snapshot; a malformed one raises :class:`CheckFailure` naming the defect.

    ``S`` is ``{"exits": [[dart-or-null, ...] per vertex], "marks": [{"vertex": v, "head": h}]}``.
    """
    exits = S_obj.get("exits")
    marks = S_obj.get("marks", [])
    if set(S_obj) - {"exits", "marks"} or not isinstance(exits, list) or not isinstance(marks, list):
        raise CheckFailure("snapshot S must be {\"exits\": [...], \"marks\": [...]}")
    S = PartialMap()
    for v, row in enumerate(exits):
        if not isinstance(row, list) or not row:
            raise CheckFailure(f"snapshot S.exits[{v}] must be a non-empty list (one entry per exit)")
        S.add_vertex(len(row))
    for v, row in enumerate(exits):
        for i, x in enumerate(row):
            if x is None:
                continue
            w, j = _dart(x, f"S.exits[{v}][{i}]")
            if not (0 <= w < len(exits) and 0 <= j < len(exits[w])) or exits[w][j] != [v, i]:
                raise CheckFailure(f"snapshot S: exit {i} of vertex {v} leads to {[w, j]}, "
                                   f"which does not lead back to {[v, i]}")
            if (v, i) < (w, j):
                S.add_edge((v, i), (w, j))
    for k, mark in enumerate(marks):
        if not (isinstance(mark, dict) and set(mark) == {"vertex", "head"} and _is_kind(mark["vertex"], _INT)
                and _is_kind(mark["head"], _OPT_INT) and 0 <= mark["vertex"] < S.n):
            raise CheckFailure(f"snapshot S.marks[{k}] must be {{\"vertex\": v, \"head\": exit or null}}")
        head = mark["head"]
        if head is not None and not 0 <= head < S.degree(mark["vertex"]):
            raise CheckFailure(f"snapshot S.marks[{k}]: head {head} is not an exit of vertex {mark['vertex']}")
        S.mark_vertex(mark["vertex"], head=head)
    S.unexplored = [_dart(x, f"U[{k}]") for k, x in enumerate(U)]
    return S


def map_to_snapshot(S: PartialMap) -> dict[str, Any]:
    """The ``snapshot`` message for (S, U)."""
    exits = [[None if S.arc((v, i)) is None else list(S.arc((v, i))) for i in range(S.degree(v))]
             for v in S.vertices]
    marks = [{"vertex": v, "head": S.vertex_mark(v).head} for v in S.vertices if S.vertex_mark(v)]
    return {"type": "snapshot", "S": {"exits": exits, "marks": marks}, "U": [list(d) for d in S.unexplored]}
