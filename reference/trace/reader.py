"""Reading a trace file (``topomark/trace@1`` or ``@2``): the record schema and a streaming, bounded parser.

:func:`load_trace` reads a trace line by line (a trace can be far larger than
memory allows to hold twice) and yields one checked record per line;
:func:`parse_trace` does the same for a string.  Everything here is
*well-formedness*, and any defect is one :class:`~topomark.spec.errors.
InvalidInput` (exit 2) naming the file and line (``spec/trace.md``):

* the file: a regular file (a FIFO, ``/dev/zero`` or a directory is refused
  before it is read, :func:`topomark.spec.jsontext.open_regular_file`), UTF-8,
  every line at most :data:`MAX_LINE_BYTES`, no empty line, at most
  :data:`MAX_TRACE_RECORDS` lines (records given as objects too);
* each line: JSON within :func:`topomark.spec.jsontext.parse_json`'s limits
  (nesting, integer size, no NaN), an object with an ``event`` the header's
  format and family allow and exactly the fields :data:`EVENTS` (trace@1) or
  :data:`EVENTS_2` (trace@2) list, of the listed kinds; every signature in
  thesis notation; nested objects (hypotheses, the ``enhancement`` counters,
  the ``end`` violation) with exactly their own fields; vocabularies
  (``purpose`` from :data:`topomark.reference.explorers.robot.PURPOSES`, the hypothesis
  ``outcome`` and ``rejected_by``, the ``augmentation``, an ``op``'s ``op``
  and ``kind``) closed; an ``op`` shaped as a
  :class:`~topomark.spec.kit.MarkerOp` (an edge marker's ``exit`` and ``"H"``/
  ``"T"`` direction, a vertex marker's integer direction and no exit);
* the header: first line, judged by :func:`topomark.reference.trace.header.
  check_header` (format, family, algorithm, policies, lighthouse, kit);
* the ``end``: exactly one, on the last line; ``verified: true`` with a
  violation is a contradiction.

Whether the records are *true* is :mod:`topomark.reference.replay.replay`'s business.
"""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterable, Iterator

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.jsontext import open_regular_file, parse_json
from topomark.spec.kit import THREAD_OPS
from topomark.spec.signature import Signature

from topomark.reference.trace.records import TRACE_FORMAT_2
from topomark.reference.explorers.robot import PURPOSES
from topomark.reference.trace.header import check_header, header_policies

__all__ = ["EVENTS", "EVENTS_2", "HYPOTHESIS", "ENHANCEMENT", "VIOLATION", "OUTCOMES", "REJECTED_BY", "MAX_LINE_BYTES",
           "MAX_TRACE_RECORDS",
           "load_trace", "parse_trace", "header_policies", "signature"]

MAX_LINE_BYTES = 64 << 20
"""A longer line is refused (64 MiB: the largest record, an iteration of a 10,000-vertex world, is far smaller)."""

MAX_TRACE_RECORDS = 100_000_000
"""A trace of more records is refused when its record past this is reached, from a file (``topomark replay``) or
from an iterable of records (:func:`topomark.replay`: an endless generator ends there).  A hundred million
records is about ten times the longest run a topomark benchmark records, and several hours of replay."""

OUTCOMES = ("case 1", "case 2", "case 3", "untested")
REJECTED_BY = ("motion", "overlap", "map")
AUGMENTATIONS = ("loop", "non-loop")
STOPPED = ("failed", "limit")
"""trace@2's ``end.outcome``: the run stopped before it had a map (spec.errors.OUTCOMES), ``end.reason`` says why."""

_I, _N, _S, _B, _O, _L, _D = "integer", "natural", "string", "boolean", "object", "list", "dart"
_SIG, _SIGS, _INTS, _DARTS, _JOIN = "signature", "signatures", "integers", "darts", "join"
_OBJ_OR_NULL, _S_OR_NULL, _POS, _DIR = "object or null", "string or null", "positive integer", "direction"
OPS = ("drop", "pick_up", *THREAD_OPS)
KINDS = ("vertex", "edge", "thread")

Schema = tuple[dict[str, Any], dict[str, Any]]  # (required fields, optional fields): name -> kind or vocabulary
EVENTS: dict[str, Schema] = {
    "header": ({"format": _S, "algorithm": _S, "policies": _O, "n": _I, "m": _I}, {}),
    "drop": ({"direction": _I, "signature": _SIG}, {}),
    "move": ({"step": _I, "motion": _I, "perception": _SIG, "purpose": PURPOSES}, {}),
    "iteration": ({"iteration": _I, "edge": _D, "signature": _SIG, "hypotheses": _L, "augmentation": AUGMENTATIONS,
                   "joined": _JOIN, "by_marker": _B}, {"unexplored": _DARTS, "enhancement": _O}),
    "end": ({"cost": _I, "verified": _B, "violation": _OBJ_OR_NULL}, {}),
}
EVENTS_2: dict[str, Schema] = {
    "header": ({"format": _S, "family": _S, "algorithm": _S, "policies": _O, "lighthouse": _S_OR_NULL, "kit": _O,
                "n": _I, "m": _I}, {"options": _O}),
    "op": ({"step": _N, "op": OPS, "kind": KINDS, "count": _POS, "signature": _SIG}, {"exit": _N, "direction": _DIR}),
    **{k: v for k, v in EVENTS.items() if k not in ("header", "drop", "end")},
    "end": ({"cost": _I, "verified": _B, "violation": _OBJ_OR_NULL}, {"outcome": STOPPED, "reason": _S}),
}
HYPOTHESIS: Schema = ({"dart": _D, "motions": _INTS, "expected": _SIGS, "outcome": OUTCOMES, "perceived": _SIGS},
                      {"rejected_by": REJECTED_BY})
ENHANCEMENT: Schema = ({"pruned": _N, "without_motion": _N, "expansion": _N, "known": _N}, {})
VIOLATION: Schema = ({"check": _S, "where": _S, "expected": _S, "found": _S, "detail": _S}, {})

_SHAPES = {_D: "[vertex, exit]", _DARTS: "a list of [vertex, exit]", _JOIN: "[[vertex, exit], [vertex, exit]]",
           _INTS: "a list of integers", _SIGS: "a list of signatures", _N: "an integer >= 0",
           _POS: "an integer >= 1", _DIR: "an integer >= 0, \"H\" or \"T\""}


def _show(value: Any) -> str:
    return clip(json.dumps(value), 80, note="")


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_dart(value: Any) -> bool:
    return isinstance(value, list) and len(value) == 2 and all(_is_int(x) for x in value)


_KINDS = {
    _I: _is_int, _N: lambda v: _is_int(v) and v >= 0, _D: _is_dart, _S: lambda v: isinstance(v, str),
    _SIG: lambda v: isinstance(v, str), _B: lambda v: isinstance(v, bool), _O: lambda v: isinstance(v, dict),
    _L: lambda v: isinstance(v, list), _OBJ_OR_NULL: lambda v: v is None or isinstance(v, dict),
    _S_OR_NULL: lambda v: v is None or isinstance(v, str), _POS: lambda v: _is_int(v) and v >= 1,
    _DIR: lambda v: (_is_int(v) and v >= 0) or v in ("H", "T"),
    _INTS: lambda v: isinstance(v, list) and all(_is_int(x) for x in v),
    _SIGS: lambda v: isinstance(v, list) and all(isinstance(x, str) for x in v),
    _DARTS: lambda v: isinstance(v, list) and all(_is_dart(x) for x in v),
    _JOIN: lambda v: isinstance(v, list) and len(v) == 2 and all(_is_dart(x) for x in v),
}


_parse_signature = lru_cache(maxsize=4096)(Signature.parse)  # a trace repeats few signatures very often


def signature(text: str, where: str) -> Signature:
    """``text`` read as a signature in thesis notation, or :class:`InvalidInput` naming ``where``."""
    try:
        return _parse_signature(text)
    except (InvalidInput, ValueError) as exc:  # ValueError: digits int() cannot read (e.g. superscripts)
        raise InvalidInput(f"{where}: {exc}") from None


def _check_object(obj: Any, schema: Schema, label: str, what: str, where: str, skip: str = "") -> None:
    """``obj`` has exactly the schema's fields (``skip`` aside), each of its kind or in its vocabulary."""
    if not isinstance(obj, dict):
        raise InvalidInput(f"{where}: {label} must be an object, got {_show(obj)}")
    required, optional = schema
    for key in sorted(set(obj) - {skip}):
        kind = required.get(key) or optional.get(key)
        if kind is None:
            raise InvalidInput(f"{where}: unknown field {key!r} in {what}")
        value = obj[key]
        if isinstance(kind, tuple):
            if not isinstance(value, str) or value not in kind:
                raise InvalidInput(f"{where}: {label}.{key} must be one of {', '.join(map(json.dumps, kind))}, "
                                   f"got {_show(value)}")
        elif not _KINDS[kind](value):
            raise InvalidInput(f"{where}: {label}.{key} must be {_SHAPES.get(kind, kind)}, got {_show(value)}")
        elif kind == _SIG:
            signature(value, f"{where}: {label}.{key}")
        elif kind == _SIGS:
            for k, text in enumerate(value):
                signature(text, f"{where}: {label}.{key}[{k}]")
    missing = [k for k in required if k not in obj]
    if missing:
        raise InvalidInput(f"{where}: {what} without field {missing[0]!r}")


def _check_record(rec: Any, where: str, table: dict[str, Schema], allowed: tuple[str, ...]) -> tuple[dict, tuple]:
    """The record checked against ``table``'s schemas and the ``allowed`` events; returns it with the events
    allowed from now on (a header narrows them to its format's and family's)."""
    if not isinstance(rec, dict) or rec.get("event") not in allowed:
        found = rec.get("event") if isinstance(rec, dict) else type(rec).__name__
        raise InvalidInput(f"{where}: expected a trace event ({', '.join(allowed)}), found {_show(found)}")
    event = rec["event"]
    _check_object(rec, table[event], event, f"a {event} event", where, skip="event")
    if event == "header":
        allowed = ("header", *check_header(rec, where), "end")
    elif event == "op":
        _check_op(rec, where)
    elif event == "iteration":
        for k, h in enumerate(rec["hypotheses"]):
            _check_object(h, HYPOTHESIS, f"iteration.hypotheses[{k}]", f"iteration.hypotheses[{k}]", where)
        if "enhancement" in rec:
            _check_object(rec["enhancement"], ENHANCEMENT, "iteration.enhancement", "iteration.enhancement", where)
    elif event == "end" and ("outcome" in rec) != ("reason" in rec) or "outcome" in rec and (
            rec["verified"] or rec["violation"] is not None):
        raise InvalidInput(f"{where}: end.outcome and end.reason come together (the run stopped, and why), on an end "
                           f"neither verified nor a violation")
    elif event == "end" and rec["violation"] is not None:
        _check_object(rec["violation"], VIOLATION, "end.violation", "end.violation", where)
        if rec["verified"]:
            raise InvalidInput(f"{where}: end says verified: true and names a violation (a contradiction)")
    return rec, allowed


def _check_op(rec: dict[str, Any], where: str) -> None:
    """An op is a :class:`~topomark.spec.kit.MarkerOp` as written: its fields fit its kind and operation."""
    kind, direction = rec["kind"], rec.get("direction")
    if (kind == "thread") != (rec["op"] in THREAD_OPS):
        raise InvalidInput(f"{where}: op.kind: a thread op ({', '.join(THREAD_OPS)}) has kind \"thread\" and no "
                           f"other op does, got op {rec['op']!r} with kind {kind!r}")
    if kind == "thread" and ("exit" in rec or (direction is not None and (rec["op"] != "tie"
                                                                          or isinstance(direction, str)))):
        raise InvalidInput(f"{where}: a thread op takes no exit, and a direction (a relative exit) only on a tie")
    if kind == "thread" and rec["op"] != "knot" and rec["count"] != 1:
        raise InvalidInput(f"{where}: op.count: only a knot takes a count other than 1")
    if kind == "vertex" and "exit" in rec:
        raise InvalidInput(f"{where}: op.exit: a vertex marker takes no exit")
    if kind == "edge" and "exit" not in rec:
        raise InvalidInput(f"{where}: an edge marker op without field 'exit'")
    if rec["op"] == "pick_up" and direction is not None:
        raise InvalidInput(f"{where}: op.direction: a pick_up takes no direction")
    if direction is not None and isinstance(direction, str) != (kind == "edge"):
        want = '"H" or "T"' if kind == "edge" else "a relative exit (an integer >= 0)"
        raise InvalidInput(f"{where}: op.direction: a {kind} marker's direction is {want}, got {_show(direction)}")


def _table(rec: Any) -> dict[str, Schema]:
    """The schemas a trace starting with ``rec`` is read by: trace@2's if it is a trace@2 header."""
    is_2 = isinstance(rec, dict) and rec.get("event") == "header" and rec.get("format") == TRACE_FORMAT_2
    return EVENTS_2 if is_2 else EVENTS


def _records(lines: Iterable[tuple[int, str]], source: str) -> Iterator[dict[str, Any]]:
    """Checked records; each is yielded only once the next line is read, so nothing may follow the end."""
    held: dict[str, Any] | None = None
    table, allowed = EVENTS, tuple(EVENTS)
    for k, line in lines:
        where = f"{source} line {k}"
        if k > MAX_TRACE_RECORDS:  # read at each call: a test lowers it
            raise InvalidInput(f"{where}: the trace goes on past {MAX_TRACE_RECORDS:,} records, the most a trace "
                               "may hold; refused")
        if not line.strip():
            raise InvalidInput(f"{where}: empty line (a trace has one JSON object per line)")
        rec = parse_json(line, where)
        if held is None:
            table = _table(rec)
            allowed = tuple(table)
        rec, allowed = _check_record(rec, where, table, allowed)
        if held is None:
            if rec["event"] != "header":
                raise InvalidInput(f"{source}: the first line must be the header event")
        elif held["event"] == "end":
            raise InvalidInput(f"{where}: there must be exactly one end event, on the last line (found one on "
                               f"line {k - 1}, followed by a {rec['event']} event)")
        elif rec["event"] == "header":
            raise InvalidInput(f"{where}: a second header")
        if held is not None:
            yield held
        held = rec
    if held is None:
        raise InvalidInput(f"{source}: an empty trace (the first line must be the header event)")
    if held["event"] != "end":
        raise InvalidInput(f"{source}: there must be exactly one end event, on the last line (found none: "
                           f"truncated trace?)")
    yield held


def parse_trace(text: str, source: str = "<trace>") -> list[dict[str, Any]]:
    """Parse and structurally validate a whole trace held in a string; any defect is one :class:`InvalidInput`."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return list(_records(enumerate(lines, 1), source))


def _file_lines(path: str | Path) -> Iterator[tuple[int, str]]:
    with open_regular_file(path, max_bytes=None) as fh:
        k = 0
        while True:
            try:
                raw = fh.readline(MAX_LINE_BYTES + 1)
            except OSError as exc:
                raise InvalidInput(f"{path}: cannot read the trace ({exc.__class__.__name__})") from None
            if not raw:
                return
            k += 1
            if len(raw) > MAX_LINE_BYTES and not raw.endswith(b"\n"):
                raise InvalidInput(f"{path} line {k}: longer than {MAX_LINE_BYTES:,} bytes")
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError as exc:
                raise InvalidInput(f"{path} line {k}: not UTF-8 text (invalid byte at column {exc.start + 1})") \
                    from None
            yield k, text[:-1] if text.endswith("\n") else text


def load_trace(path: str | Path) -> Iterator[dict[str, Any]]:
    """The checked records of the trace file ``path``, read lazily one line at a time.

    The file is opened (and a FIFO, device or directory refused) at once; each
    further defect is raised when the iteration reaches its line.
    """
    lines = _file_lines(path)
    first = next(lines, None)  # opens the file now: an unreadable path fails here, not mid-replay

    def chained() -> Iterator[tuple[int, str]]:
        if first is not None:
            yield first
            yield from lines

    return _records(chained(), str(path))
