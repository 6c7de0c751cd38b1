"""The explorer protocol ``topomark/protocol@1`` and ``@2``: JSON Lines between a world and an explorer.

The thesis separates the robot from the world it explores (§3.1.1): the
robot only issues motions and marker operations and receives signatures.
This module turns that interface into a wire protocol (documented in
``spec/protocol.md``) so that topomark can play a world to another program
(``run-external``, :mod:`topomark.reference.oracle.run_external`) or drive another
program's world with the reference explorer (``drive``,
:mod:`topomark.reference.oracle.drive`).

Contents:

* :func:`encode` / :func:`decode` — one message per line, validated against
  its definition in ``spec/protocol.schema.json`` (:data:`SCHEMA`, JSON Schema
  draft 2020-12; :data:`MESSAGES` maps each version's message types to their
  definitions); the version a receiver speaks travels in its ``expect``
  (:class:`Expect`);
* :func:`shape_error` — the first way a message breaks its schema, in one
  sentence naming the field and what was expected (``decode`` raises it as
  ``garbage``).  The payloads a message carries for judgement — a snapshot's
  ``S`` and ``U``, a map's ``world`` (:data:`PAYLOADS`) — are only checked
  for their JSON type when the line is read: the world side checks the rest
  of a snapshot's shape when it judges the snapshot (``FAIL [snapshot]``, the
  snapshot named by its number), and a map is judged as a world file
  (``FAIL [map-invalid]``).  Rules that need the world — an exit below the
  degree, what the kit allows — are the world side's, not the schema's;
* :func:`clip` — what a verdict may quote of the other side's input (a
  bounded piece, never a whole line);
* :func:`snapshot_to_map` / :func:`map_to_snapshot` — (S, U) of §3.1.3 on
  the wire (:mod:`topomark.reference.oracle.snapshot_wire`).
"""

from __future__ import annotations

import json
from functools import lru_cache
from importlib import resources
from typing import TYPE_CHECKING, Any, Sequence

from topomark.spec.errors import InvalidInput, TopomarkFault, clip
from topomark.spec.jsontext import parse_json
from topomark.spec.worldfile import schema as world_schema

__all__ = ["PROTOCOL", "PROTOCOL2", "VERSIONS", "SCHEMA", "MESSAGES", "PAYLOADS", "Expect", "ProtocolError", "encode",
           "decode", "shape_error", "MAX_LINE", "MAX_MESSAGE"]

PROTOCOL = "topomark/protocol@1"
PROTOCOL2 = "topomark/protocol@2"
VERSIONS = {PROTOCOL: 1, PROTOCOL2: 2}  # the name in ``hello`` -> the version number
MAX_LINE = 4_000_000  # bytes; a longer line is garbage
MAX_MESSAGE = 2000  # characters of a verdict message; what the other side sent is quoted clipped

SCHEMA: dict[str, Any] = json.loads(resources.files("topomark.spec").joinpath("protocol.schema.json").read_text(encoding="utf-8"))
"""``spec/protocol.schema.json``: one JSON Schema definition per message, the only statement of their shapes."""

if TYPE_CHECKING:
    from jsonschema import ValidationError
_DEFS: dict[str, dict[str, Any]] = SCHEMA["$defs"]
# version -> message type -> the name of its definition, read from $defs/message@N's if/then dispatch
MESSAGES: dict[int, dict[str, str]] = {
    number: {case["if"]["properties"]["type"]["const"]: case["then"]["$ref"].rsplit("/", 1)[1]
             for case in _DEFS[f"message@{number}"]["allOf"]} for number in VERSIONS.values()}
# the payloads judged with their message, not when the line is read: a snapshot's S and U (FAIL [snapshot]),
# a map's world (FAIL [map-invalid])
PAYLOADS = {"snapshot": ("S", "U"), "map": ("world",)}
_RANK = {"required": 1, "additionalProperties": 2}  # a wrong value is named before a missing or an unknown field


@lru_cache(maxsize=None)
def _schema_tools() -> tuple[Any, Any]:
    """The validator class and the schema registry, imported when first needed: without the jsonschema package
    (a dependency of topomark) a command that reads no message still runs, and one that does is topomark's fault."""
    try:
        from jsonschema import Draft202012Validator, validators
        from referencing import Registry, Resource
    except ImportError as exc:
        raise TopomarkFault(f"reading protocol messages needs the jsonschema package, a dependency of topomark; "
                            f"reinstall topomark ({exc})") from None
    # JSON Schema counts 1.0 as an integer; the protocol does not (a motion, exit or count is written as one)
    checker = Draft202012Validator.TYPE_CHECKER.redefine(
        "integer", lambda _, x: isinstance(x, int) and not isinstance(x, bool))
    registry = Registry().with_resources([(d["$id"], Resource.from_contents(d)) for d in (SCHEMA, world_schema())])
    return validators.extend(Draft202012Validator, type_checker=checker), registry


@lru_cache(maxsize=None)
def _validator(name: str, envelope: bool) -> Any:
    """The validator of ``$defs/name``; ``envelope`` leaves the payloads (:data:`PAYLOADS`) to their judge."""
    definition = _DEFS[name]
    skipped = PAYLOADS.get(definition["properties"]["type"]["const"], ()) if envelope else ()
    if skipped:
        props = {k: ({"type": v["type"]} if k in skipped else v) for k, v in definition["properties"].items()}
        definition = {**definition, "properties": props}
    validator, registry = _schema_tools()
    return validator({**definition, "$defs": _DEFS}, registry=registry)


def shape_error(msg: dict[str, Any], version: int, envelope: bool = False) -> str | None:
    """The first way ``msg`` (a message of a type ``version`` knows) breaks its schema, in words, or None.

    >>> shape_error({"type": "move", "motion": "1"}, 1)
    'move.motion must be integer, got "1"'
    >>> shape_error({"type": "snapshot", "S": {"exits": [[None]], "marks": [{"vertex": 0, "head": "x"}]},
    ...              "U": [[0, 0]]}, 1)
    'snapshot.S.marks[0].head must be integer or null, got "x"'
    """
    kind = msg["type"]
    errors = list(_validator(MESSAGES[version][kind], envelope).iter_errors(msg))
    if not errors:
        return None
    _, error = min(enumerate(errors), key=lambda ke: (_RANK.get(ke[1].validator, 0), len(ke[1].absolute_path), ke[0]))
    return _words(error, kind)


def _words(error: "ValidationError", kind: str) -> str:
    """One precise sentence for a schema error: the field by its path, and what was expected."""
    where = kind + "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in error.absolute_path)
    got = clip(json.dumps(error.instance), 60)
    rule = error.validator
    want: Any = error.validator_value
    instance: Any = error.instance  # the JSON value and schema the rule failed on
    schema: Any = error.schema
    if rule == "required":
        missing = next(name for name in want if name not in instance)
        return f"{where if error.absolute_path else kind + ' message'}: missing field {missing!r}"
    if rule == "additionalProperties":
        known = set(schema.get("properties", {}))
        unknown = sorted(set(instance) - known)[0]
        return f"{where if error.absolute_path else kind + ' message'}: unknown field {clip(unknown)!r}"
    if rule == "type":
        names = [want] if isinstance(want, str) else list(want)
        return f"{where} must be {_either(names)}, got {got}"
    if rule in ("enum", "const"):
        values = want if rule == "enum" else [want]
        shown = [v if isinstance(v, str) and v.isidentifier() else json.dumps(v) for v in values]
        return f"{where} must be {'one of ' if len(shown) > 1 else ''}{', '.join(shown)}, got {got}"
    if rule in ("minimum", "maximum", "exclusiveMinimum"):
        low, high = schema.get("minimum"), schema.get("maximum")
        span = f"{low}..{high}" if low is not None and high is not None else (
            f"at least {low}" if low is not None else f"above {schema.get('exclusiveMinimum', high)}"
            if high is None else f"at most {high}")
        return f"{where} must be {'an integer ' if high is not None and low is not None else ''}{span}, got {got}"
    if rule in ("minItems", "maxItems"):
        low, high = schema.get("minItems", 0), schema.get("maxItems")
        size = f"{low} item(s)" if low == high else f"at least {low} item(s)" if high is None else f"{low}..{high} items"
        return f"{where} must have {size}, got {got}"
    return f"{where}: {clip(error.message, 200)}"


def _either(names: list[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]


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
    known = MESSAGES[version]
    if kind not in known:
        raise ProtocolError("garbage", f"unknown message type {clip(kind)!r} in {_NAMES[version]} "
                                       f"(known: {', '.join(known)})")
    if expect is not None and kind not in expect:
        raise ProtocolError("protocol", f"unexpected message {kind!r} here (expected {' or '.join(expect)})")
    wrong = shape_error(msg, version, envelope=True)
    if wrong is not None:
        raise ProtocolError("garbage", wrong)
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
