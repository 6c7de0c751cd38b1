"""Port world files: JSON, format ``topomark/port-world@1`` (schema in ``port_world.schema.json``).

The port-labelled model's own file format (:mod:`.port_world`)::

    {"format": "topomark/port-world@1", "doors": 2, "alphabet": 2,
     "colours": [0, 1], "start": 0,
     "passages": [[[0, 0], [1, 0]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]],
     "names": ["hall", "attic"], "problem": "probatio"}

``colours[r]`` is room ``r``'s colour, in ``0 .. alphabet-1``; ``doors`` is the number of doors of every room
(``0 .. doors-1``, absolute numbers); each passage ``[[r, d], [r2, d2]]`` joins door ``d`` of room ``r`` to door
``d2`` of room ``r2`` (``[[r, d], [r, d]]`` is a door joined to itself), and every door-end is in exactly one
passage; ``start`` is the room the robot starts in.  ``names`` (optional) names the rooms, one distinct string
each (a world converted from a thesis world keeps its vertex names there); ``problem`` (optional) is the contest
problem a map was imported for.  :func:`dumps_port_world` writes the passages in the order
:meth:`~.port_world.PortWorld.passages` gives (each from its smaller door-end), one passage a line.

Loading is strict: malformed JSON, duplicate keys, an unknown key (named, never its value), a wrong format
version, a value of the wrong type, and every condition of :class:`~.port_world.PortWorld` give one
:class:`~topomark.spec.errors.InvalidWorld` naming what is wrong: a door-end out of range, used twice or in no
passage, a colour outside the alphabet, a start out of range, a room the start cannot reach.  The limits of
:mod:`topomark.spec.jsontext` apply (nesting, integer digits, regular files only), and a file larger than
:data:`MAX_PORT_WORLD_BYTES` is refused.

Examples
--------
>>> text = dumps_port_world(PortWorld((0, 1), (((1, 0), (0, 1)), ((0, 0), (1, 1))), 0, doors=2, alphabet=2))
>>> print(text, end="")
{"format": "topomark/port-world@1", "doors": 2, "alphabet": 2, "colours": [0, 1], "start": 0,
 "passages": [
  [[0, 0], [1, 0]],
  [[0, 1], [0, 1]],
  [[1, 1], [1, 1]]]}
>>> loads_port_world(text).target(0, 0)
1
>>> loads_port_world(text.replace("[[1, 1], [1, 1]]", "[[1, 1], [0, 1]]"))
Traceback (most recent call last):
...
topomark.spec.errors.InvalidWorld: <string>: door-end (0, 1) is used twice (passage 2 and an earlier one)
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, cast

from topomark.spec.errors import InvalidInput, InvalidWorld, clip, require_input
from topomark.spec.jsontext import no_duplicate_keys, parse_json, read_text_file
from topomark.spec.port_world import MAX_DOORS, MAX_ROOMS, DoorEnd, PortWorld, from_joins

__all__ = ["FORMAT", "MAX_PORT_WORLD_BYTES", "PortDocument", "schema", "port_world_from_json", "port_world_to_json",
           "loads_port_document", "loads_port_world", "dumps_port_world", "load_port_world", "save_port_world"]

FORMAT = "topomark/port-world@1"

MAX_PORT_WORLD_BYTES = 64 << 20
"""The largest port world file read: 64 MiB (a world of :data:`~.port_world.MAX_ROOMS` rooms of 6 doors takes
about 10 MB as :func:`dumps_port_world` writes it)."""

_KEYS = ("format", "doors", "alphabet", "colours", "start", "passages", "names", "problem")
_REQUIRED = ("format", "doors", "alphabet", "colours", "start", "passages")


@dataclass(frozen=True)
class PortDocument:
    """What a port world file holds: the world, its room names (``None``: none given) and its problem name."""

    world: PortWorld
    names: tuple[str, ...] | None = None
    problem: str | None = None


def schema() -> dict[str, Any]:
    """The published JSON Schema of the port world format."""
    text = resources.files(__package__).joinpath("port_world.schema.json").read_text(encoding="utf-8")
    return cast(dict[str, Any], json.loads(text))


def _int(x: Any, what: str, low: int, high: int) -> int:
    require_input(isinstance(x, int) and not isinstance(x, bool), f"{what} must be an integer", InvalidWorld)
    require_input(low <= x <= high, f"{what} must be in {low}..{high:,}, not {x:,}", InvalidWorld)
    return int(x)


def _end(x: Any, what: str) -> DoorEnd:
    require_input(isinstance(x, list) and len(x) == 2, f"{what} must be a door-end [room, door]", InvalidWorld)
    for k, v in enumerate(x):
        require_input(isinstance(v, int) and not isinstance(v, bool), f"{what}[{k}] must be an integer", InvalidWorld)
    return int(x[0]), int(x[1])


def _names(x: Any, rooms: int) -> tuple[str, ...]:
    require_input(isinstance(x, list) and len(x) == rooms, f"names must be a list of {rooms} room names, one a room",
                  InvalidWorld)
    seen: dict[str, int] = {}
    for k, name in enumerate(x):
        require_input(isinstance(name, str) and 0 < len(name) <= 200, f"names[{k}] must be a string of 1 to 200 "
                      "characters", InvalidWorld)
        require_input(name not in seen, f"names[{k}] repeats the name of room {seen.get(name)}: "
                      + clip(name, 40, quote=True), InvalidWorld)
        seen[name] = k
    return tuple(x)


def port_world_from_json(obj: Any) -> PortDocument:
    """The document of a parsed port world file, checking every condition (see the module's docstring)."""
    require_input(isinstance(obj, dict), "a port world file must hold a JSON object", InvalidWorld)
    fmt = obj.get("format")
    require_input(fmt == FORMAT, f"unknown format {clip(str(fmt), 40, quote=True)} (this is {FORMAT})"
                  if "format" in obj else f"missing key 'format' (expected {FORMAT!r})", InvalidWorld)
    for key in obj:
        require_input(key in _KEYS, f"unknown key {clip(str(key), 40, quote=True)} (a port world has the keys "
                      f"{', '.join(_KEYS)})", InvalidWorld)
    for key in _REQUIRED:
        require_input(key in obj, f"missing key {key!r}", InvalidWorld)
    doors = _int(obj["doors"], "doors", 1, MAX_DOORS)
    alphabet = _int(obj["alphabet"], "alphabet", 1, 1 << 31)
    colours = obj["colours"]
    require_input(isinstance(colours, list) and 1 <= len(colours) <= MAX_ROOMS,
                  f"colours must be a list of 1 to {MAX_ROOMS:,} colours, one a room", InvalidWorld)
    for k, c in enumerate(colours):
        require_input(isinstance(c, int) and not isinstance(c, bool), f"colours[{k}] must be an integer", InvalidWorld)
    start = obj["start"]
    require_input(isinstance(start, int) and not isinstance(start, bool), "start must be an integer", InvalidWorld)
    passages = obj["passages"]
    require_input(isinstance(passages, list) and len(passages) <= doors * len(colours),
                  f"passages must be a list of at most {doors * len(colours):,} passages (doors × rooms)", InvalidWorld)
    pairs = []
    for k, p in enumerate(passages):
        require_input(isinstance(p, list) and len(p) == 2, f"passages[{k}] must be a pair of door-ends",
                      InvalidWorld)
        pairs.append((_end(p[0], f"passages[{k}][0]"), _end(p[1], f"passages[{k}][1]")))
    names = _names(obj["names"], len(colours)) if "names" in obj else None
    problem = obj.get("problem")
    require_input(problem is None and "problem" not in obj or isinstance(problem, str) and 0 < len(problem) <= 64
                  and problem.isprintable(), "problem must be a printable string of 1 to 64 characters", InvalidWorld)
    world = from_joins(colours, pairs, start, doors=doors, alphabet=alphabet)
    return PortDocument(world, names, problem)


def port_world_to_json(world: PortWorld, names: tuple[str, ...] | list[str] | None = None,
                       problem: str | None = None) -> dict[str, Any]:
    """The JSON object of ``world`` (with its room names and problem name when given)."""
    out: dict[str, Any] = {"format": FORMAT, "doors": world.doors, "alphabet": world.alphabet,
                           "colours": list(world.colours), "start": world.start,
                           "passages": [[list(a), list(b)] for a, b in world.passages()]}
    if names is not None:
        out["names"] = list(_names(list(names), world.rooms))
    if problem is not None:
        out["problem"] = problem
    return out


def dumps_port_world(world: PortWorld, names: tuple[str, ...] | list[str] | None = None,
                     problem: str | None = None) -> str:
    """The file text of ``world``: one line of header, then one passage a line (diffs stay readable)."""
    obj = port_world_to_json(world, names, problem)
    passages = obj.pop("passages")
    head = json.dumps(obj, ensure_ascii=False)[:-1]
    lines = ",\n".join("  " + json.dumps(p) for p in passages)
    return f"{head},\n \"passages\": [\n{lines}]}}\n" if passages else f"{head}, \"passages\": []}}\n"


def loads_port_document(text: str, source: str = "<string>") -> PortDocument:
    """Parse a port world file's text; errors are prefixed with ``source``."""
    obj = parse_json(text, source, InvalidWorld, object_pairs_hook=no_duplicate_keys)
    try:
        return port_world_from_json(obj)
    except InvalidInput as exc:
        raise InvalidWorld(f"{source}: {exc}") from None


def loads_port_world(text: str, source: str = "<string>") -> PortWorld:
    """The port world of a port world file's text (names and problem dropped)."""
    return loads_port_document(text, source).world


def load_port_world(path: str | Path) -> PortDocument:
    """Read a port world file; a missing, special (FIFO, device, directory), oversized or non-UTF-8 file is an
    :class:`InvalidWorld` too."""
    return loads_port_document(read_text_file(path, InvalidWorld, MAX_PORT_WORLD_BYTES), str(path))


def save_port_world(world: PortWorld, path: str | Path, *, names: tuple[str, ...] | list[str] | None = None,
                    problem: str | None = None, force: bool = False) -> None:
    """Write ``world`` to ``path``; an existing file is refused (:class:`InvalidInput`) unless ``force``."""
    p = Path(path)
    require_input(force or not p.is_file(), f"path={str(path)!r}: the file exists; give force=True to overwrite it")
    p.write_text(dumps_port_world(world, names, problem), encoding="utf-8")
