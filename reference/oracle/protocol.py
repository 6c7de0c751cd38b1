"""The explorer protocol ``topomark/protocol@1`` and ``@2``: JSON Lines between a world and an explorer.

The thesis separates the robot from the world it explores (§3.1.1): the
robot only issues motions and marker operations and receives signatures.
This module turns that interface into a wire protocol (documented in
``spec/protocol.md``) so that topomark can play a world to another program
(``run-external``, :mod:`topomark.reference.oracle.run_external`) or drive another
program's world with the reference explorer (``drive``,
:mod:`topomark.reference.oracle.drive`).

Contents:

* :func:`encode` / :func:`decode` — one message per line, validated field by
  field against :data:`MESSAGES` (``@1``) or :data:`MESSAGES2` (``@2``: the
  kit in ``hello``, ``drop`` and ``pick_up`` of vertex and edge markers); the
  version a receiver speaks travels in its ``expect`` (:class:`Expect`);
* :func:`clip` — what a verdict may quote of the other side's input (a
  bounded piece, never a whole line);
* :func:`snapshot_to_map` / :func:`map_to_snapshot` — (S, U) of §3.1.3 on
  the wire (:mod:`topomark.reference.oracle.snapshot_wire`).
"""

from __future__ import annotations

import json
from typing import Any, Sequence

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.jsontext import parse_json

__all__ = ["PROTOCOL", "PROTOCOL2", "VERSIONS", "MESSAGES", "MESSAGES2", "Expect", "ProtocolError", "encode",
           "decode", "MAX_LINE", "MAX_MESSAGE"]

PROTOCOL = "topomark/protocol@1"
PROTOCOL2 = "topomark/protocol@2"
VERSIONS = {PROTOCOL: 1, PROTOCOL2: 2}  # the name in ``hello`` -> the version number
MAX_LINE = 4_000_000  # bytes; a longer line is garbage
MAX_MESSAGE = 2000  # characters of a verdict message; what the other side sent is quoted clipped

_INT, _STR, _OBJ, _LIST = "integer", "string", "object", "list"
_OPT_INT = "integer or null"
_DIRECTION = "integer, string or null"  # a vertex marker's exit or an edge marker's end ("H"/"T")

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

# @2: the kit in hello (spec/kit.py ``Kit.to_json``); marker operations as ``MarkerOp.to_json`` names them.
MESSAGES2: dict[str, dict[str, str]] = {
    **MESSAGES,
    "hello": {"protocol": _STR, "role": _STR, "kit": _OBJ, "signature": _STR},
    "drop": {"kind": _STR},
    "pick_up": {"kind": _STR},
    "thread": {"op": _STR},  # §6.3: reference/oracle/marker_messages.py
}
_OPTIONAL2: dict[str, dict[str, str]] = {
    **_OPTIONAL,
    "drop": {"exit": _OPT_INT, "direction": _DIRECTION, "count": _INT},
    "pick_up": {"exit": _OPT_INT, "count": _INT},
    "thread": {"direction": _OPT_INT, "count": _INT},
}
_SCHEMAS = {1: (MESSAGES, _OPTIONAL), 2: (MESSAGES2, _OPTIONAL2)}


class Expect(tuple):
    """The message types a receiver accepts here, and the protocol version it speaks.

    ``Peer.receive(Expect(("move", "drop"), 2))`` validates against ``@2``; a
    plain tuple means ``@1``.  ``version=None`` accepts a ``hello`` of any
    version this module speaks, validated against the version it names.
    """

    version: int | None

    def __new__(cls, types: Sequence[str], version: int | None = 1) -> "Expect":
        self = super().__new__(cls, types)
        self.version = version
        return self


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
    if kind == _DIRECTION:
        return value is None or isinstance(value, str) or _is_kind(value, _INT)
    return isinstance(value, {_STR: str, _OBJ: dict, _LIST: list}[kind])


def decode(line: str, expect: Sequence[str] | None = None) -> dict[str, Any]:
    """Parse and validate one line; raises :class:`ProtocolError` (kind ``garbage``) on anything wrong.

    The version validated against is ``expect.version`` if ``expect`` is an
    :class:`Expect`, else ``@1``.
    """
    text = line.strip()
    try:
        msg = parse_json(text, "the line")  # bounded depth and integers: nothing can blow up later
    except InvalidInput as exc:
        raise ProtocolError("garbage", f"not a JSON object: {clip(text)!r} ({clip(str(exc), 200)})") from None
    if not isinstance(msg, dict) or not isinstance(msg.get("type"), str):
        raise ProtocolError("garbage", f"not a message (a JSON object with a string \"type\"): {clip(text)!r}")
    kind = msg["type"]
    version = _version(msg, getattr(expect, "version", 1))
    required, optional = _SCHEMAS[version]
    if kind not in required:
        raise ProtocolError("garbage", f"unknown message type {clip(kind)!r} in {_NAMES[version]} "
                                       f"(known: {', '.join(required)})")
    if expect is not None and kind not in expect:
        raise ProtocolError("protocol", f"unexpected message {kind!r} here (expected {' or '.join(expect)})")
    fields = {**required[kind], **optional.get(kind, {})}
    for name, want in fields.items():
        if name in msg and not _is_kind(msg[name], want):
            raise ProtocolError("garbage", f"{kind}.{name} must be {want}, got {clip(json.dumps(msg[name]))}")
    missing = [f for f in required[kind] if f not in msg]
    unknown = sorted(set(msg) - set(fields) - {"type"})
    if missing or unknown:
        what = f"missing field {missing[0]!r}" if missing else f"unknown field {clip(unknown[0])!r}"
        raise ProtocolError("garbage", f"{kind} message: {what}")
    return msg


_NAMES = {number: name for name, number in VERSIONS.items()}


def _version(msg: dict[str, Any], version: int | None) -> int:
    """The version to validate ``msg`` against: ``version``, or for None the one a ``hello`` names."""
    if version is not None:
        return version
    if msg["type"] != "hello":
        return 1
    named = msg.get("protocol")
    if named not in VERSIONS:
        shown = clip(named) if isinstance(named, str) else clip(json.dumps(named))
        raise ProtocolError("protocol", f"hello speaking {shown!r}; this topomark speaks "
                                        f"{' and '.join(VERSIONS)}")
    return VERSIONS[named]
