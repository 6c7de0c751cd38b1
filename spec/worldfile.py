"""World and map files: JSON, format ``topomark/world@1`` (schema in ``world.schema.json``).

::

    {"format": "topomark/world@1",
     "rotation": {"c": ["a", "b", "d", "e"], "a": ["c", "b", "e"], ...},
     "markers": [{"kind": "vertex", "at": "c", "points_to": "a"}],
     "start": {"at": "c", "facing": "a"}}

``rotation`` maps each vertex name to its neighbours in clockwise order.
Markers are ``{"kind": "vertex", "at": V, "count": K, "points_to": W}``
(``count`` defaults to 1; ``points_to`` only for a directional marker) and
``{"kind": "edge", "between": [U, V], "count": K, "head": V}`` (``head`` only
for a directional edge marker).  ``start`` is optional.  A map written by an
explorer uses the same format, so any two files can be compared.

``thread`` (optional, §6.3; a file without it is exactly as before) is a
thread laid in the world, :class:`~topomark.spec.thread.Thread`:
``{"walk": [V, ...], "points_to": W, "end": "left", "knots": [[i, K], ...]}``
— tied at ``walk[0]``, laid along the walk's edges in order, ``points_to``
the neighbour of ``walk[0]`` it is laid out toward (optional: the direction
of an l = ε thread, whose walk is its one vertex), ``end`` ``"left"`` (its
free end lies at ``walk[-1]``, the default) or ``"held"`` (a robot holds it
there), ``knots`` ``K`` knots at walk position ``i`` (optional).  A world
with one is a :class:`~topomark.spec.thread.ThreadedWorld`.

Loading is strict: malformed JSON, duplicate keys, unknown keys, a wrong
format version and every graph condition of §3.1.1 give one
:class:`~topomark.spec.errors.InvalidWorld` naming what is wrong.  So do
hostile inputs, refused before they cost anything (:mod:`topomark.spec.jsontext`):
nesting deeper than 64 levels, integers of more than 18 digits, ``NaN``, a
FIFO, device or directory instead of a regular file, a file larger than
:data:`MAX_WORLD_BYTES`, non-UTF-8 text, and a rotation with more vertices or
edges than :data:`~topomark.spec.world.MAX_VERTICES` /
:data:`~topomark.spec.world.MAX_EDGES` (counted before the world is built).

Examples
--------
>>> w = loads_world('{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": ["a"]}}')
>>> loads_world(dumps_world(w)) == w
True
>>> t = loads_world('{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": ["a"]}, '
...                 '"thread": {"walk": ["a"], "points_to": "b"}}')
>>> t.thread_mark("a"), loads_world(dumps_world(t)) == t
(ThreadMark(tied=True, head=0, edges=(), end=True, knots=0), True)
>>> loads_world('{"format": "topomark/world@2", "rotation": {}}')
Traceback (most recent call last):
...
topomark.spec.errors.InvalidWorld: <string>: unknown format 'topomark/world@2' (this is topomark/world@1)
"""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path
from typing import Any, cast

from topomark.spec.errors import InvalidWorld
from topomark.spec.jsontext import no_duplicate_keys, parse_json, read_text_file
from topomark.spec.errors import InvalidInput, clip
from topomark.spec.marker import EdgeMarker, Marker, VertexMarker
from topomark.spec.thread import Thread, ThreadedWorld
from topomark.spec.world import Start, World, check_size

__all__ = ["FORMAT", "MAX_WORLD_BYTES", "schema", "world_from_json", "world_to_json", "marker_to_json",
           "loads_world", "dumps_world", "load_world", "save_world"]

FORMAT = "topomark/world@1"

MAX_WORLD_BYTES = 256 << 20
"""The largest world file :func:`load_world` reads: 256 MiB.

A world at the size limits (:data:`~topomark.spec.world.MAX_VERTICES`
vertices, :data:`~topomark.spec.world.MAX_EDGES` edges) takes about 20-30 MB
as written by :func:`dumps_world`, so this leaves room for long vertex names;
parsing 256 MiB of JSON into Python objects needs a few GB, while the general
1 GiB file limit of :mod:`~topomark.spec.jsontext` would need far more."""


def schema() -> dict[str, Any]:
    """The published JSON Schema of the world format."""
    return cast(dict[str, Any], json.loads(resources.files(__package__).joinpath("world.schema.json").read_text(encoding="utf-8")))


def _expect(cond: bool, message: str) -> None:
    if not cond:
        raise InvalidWorld(message)


def _keys(obj: dict[str, Any], allowed: set[str], required: set[str], what: str) -> None:
    unknown = sorted(set(obj) - allowed)
    _expect(not unknown, f"{what}: unknown key {unknown[0]!r}" if unknown else "")
    missing = sorted(required - set(obj))
    _expect(not missing, f"{what}: missing key {missing[0]!r}" if missing else "")


def _show(x: Any, limit: int = 60) -> str:
    """``x`` as JSON for a message, cut to ``limit`` characters (a hostile value can be megabytes long)."""
    return clip(json.dumps(x), limit, note="")


def _string(x: Any, what: str) -> str:
    _expect(isinstance(x, str), f"{what} must be a string, got {_show(x)}")
    return cast(str, x)  # _expect raised otherwise


def _marker(obj: Any, k: int) -> Marker:
    what = f"markers[{k}]"
    _expect(isinstance(obj, dict), f"{what} must be an object")
    kind = obj.get("kind")
    count = obj.get("count", 1)
    _expect(isinstance(count, int) and not isinstance(count, bool) and count >= 1,
            f"{what}: count must be a positive integer, got {_show(count)}")
    if kind == "vertex":
        _keys(obj, {"kind", "at", "count", "points_to"}, {"kind", "at"}, what)
        points = _string(obj["points_to"], f"{what}.points_to") if "points_to" in obj else None
        return VertexMarker(_string(obj["at"], f"{what}.at"), count, points)
    if kind == "edge":
        _keys(obj, {"kind", "between", "count", "head"}, {"kind", "between"}, what)
        between = obj["between"]
        _expect(isinstance(between, list) and len(between) == 2,
                f"{what}.between must be a list of two vertex names")
        head = _string(obj["head"], f"{what}.head") if "head" in obj else None
        return EdgeMarker((_string(between[0], f"{what}.between[0]"), _string(between[1], f"{what}.between[1]")),
                          count, head)
    raise InvalidWorld(f"{what}: kind must be \"vertex\" or \"edge\", got {_show(kind)}")


def world_from_json(obj: Any) -> World:
    """Build a :class:`World` from parsed JSON, checking every condition."""
    _expect(isinstance(obj, dict), "a world file must hold a JSON object")
    fmt = obj.get("format")
    _expect(fmt == FORMAT, f"unknown format {fmt!r} (this is {FORMAT})" if "format" in obj
            else f"missing key 'format' (expected {FORMAT!r})")
    _keys(obj, {"format", "rotation", "markers", "start", "thread"}, {"format", "rotation"}, "world")
    rot = obj["rotation"]
    _expect(isinstance(rot, dict), "rotation must be an object mapping each vertex to its clockwise neighbours")
    for v, ns in rot.items():
        _expect(isinstance(ns, list), f"rotation of vertex {v!r} must be a list of vertex names")
    check_size(len(rot), sum(len(ns) for ns in rot.values()) // 2, "the world")
    for v, ns in rot.items():
        for w in ns:
            _string(w, f"neighbour of vertex {v!r}")
    markers = obj.get("markers", [])
    _expect(isinstance(markers, list), "markers must be a list")
    start = obj.get("start")
    if "start" in obj:  # present means an object: null is not "no start" (the schema agrees)
        _expect(isinstance(start, dict), "start must be an object {\"at\": V, \"facing\": W}")
        _keys(start, {"at", "facing"}, {"at", "facing"}, "start")
        start = Start(_string(start["at"], "start.at"), _string(start["facing"], "start.facing"))
    marks = [_marker(m, k) for k, m in enumerate(markers)]
    if "thread" not in obj:
        return World(rot, marks, start)
    thread = _thread(obj["thread"])
    try:
        return ThreadedWorld(rot, marks, start, thread)
    except InvalidInput as exc:
        raise InvalidWorld(f"thread: {exc}") from None


def _thread(obj: Any) -> Thread:
    _expect(isinstance(obj, dict), "thread must be an object {\"walk\": [V, ...], ...}")
    _keys(obj, {"walk", "points_to", "end", "knots"}, {"walk"}, "thread")
    walk = obj["walk"]
    _expect(isinstance(walk, list) and len(walk) >= 1, "thread.walk must be a non-empty list of vertex names")
    walk = tuple(_string(v, f"thread.walk[{k}]") for k, v in enumerate(walk))
    points = _string(obj["points_to"], "thread.points_to") if "points_to" in obj else None
    end = obj.get("end", "left")
    _expect(end in ("left", "held"), f"thread.end must be \"left\" or \"held\", got {_show(end)}")
    knots = obj.get("knots", [])
    _expect(isinstance(knots, list) and all(isinstance(k, list) and len(k) == 2 and all(
        isinstance(x, int) and not isinstance(x, bool) for x in k) for k in knots),
        "thread.knots must be a list of [position, count] pairs of integers")
    return Thread(walk, points, end == "left", tuple(tuple(k) for k in knots))


def world_to_json(world: World) -> dict[str, Any]:
    """The JSON object of a world (markers and start included when present)."""
    out: dict[str, Any] = {"format": FORMAT, "rotation": {v: list(ns) for v, ns in world.rotation.items()}}
    markers = [marker_to_json(m) for m in world.markers]
    if markers:
        out["markers"] = markers
    if world.start is not None:
        out["start"] = {"at": world.start.at, "facing": world.start.facing}
    thread = getattr(world, "thread", None)
    if thread is not None:
        item: dict[str, Any] = {"walk": list(thread.walk)}
        if thread.points_to is not None:
            item["points_to"] = thread.points_to
        item["end"] = "left" if thread.end_left else "held"
        if thread.knots:
            item["knots"] = [list(k) for k in thread.knots]
        out["thread"] = item
    return out


def marker_to_json(m: Marker) -> dict[str, Any]:
    """One marker as its JSON object in the world format."""
    if isinstance(m, VertexMarker):
        item: dict[str, Any] = {"kind": "vertex", "at": m.at, "count": m.count}
        if m.points_to is not None:
            item["points_to"] = m.points_to
        return item
    item = {"kind": "edge", "between": list(m.between), "count": m.count}
    if m.head is not None:
        item["head"] = m.head
    return item


def loads_world(text: str, source: str = "<string>") -> World:
    """Parse a world from JSON text within the limits of :func:`~topomark.spec.jsontext.parse_json`;
    errors are prefixed with ``source``."""
    obj = parse_json(text, source, InvalidWorld, object_pairs_hook=no_duplicate_keys)
    try:
        return world_from_json(obj)
    except InvalidWorld as exc:
        raise InvalidWorld(f"{source}: {exc}") from None


def dumps_world(world: World) -> str:
    return json.dumps(world_to_json(world), indent=1) + "\n"


def load_world(path: str | Path) -> World:
    """Read a world file; a missing, unreadable, special (FIFO, device, directory), oversized
    (> :data:`MAX_WORLD_BYTES`) or non-UTF-8 file is an :class:`InvalidWorld` too."""
    return loads_world(read_text_file(path, InvalidWorld, MAX_WORLD_BYTES), str(path))


def save_world(world: World, path: str | Path) -> None:
    Path(path).write_text(dumps_world(world), encoding="utf-8")
