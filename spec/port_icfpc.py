"""The ICFP Contest 2025's map format, read strictly and written exactly (the port-labelled model, :mod:`.port_world`).

A contest map is a JSON object ``{"rooms": [...], "startingRoom": s, "connections": [...]}``: ``rooms[i]`` is room
``i``'s label (colour), and each connection ``{"from": {"room": r, "door": d}, "to": {"room": r2, "door": d2}}``
joins two door-ends.  A map file as the contest's server accepted it is ``{"problemName": NAME, "map": MAP}``; the
server's ``/guess`` body is ``{"id": ..., "map": MAP}`` (the id is the server's business, :func:`map_from_json`
reads the map).

Reading is strict: any key but those named is refused, naming the key and never echoing its value (a team's ``id``
is a secret); a door-end used twice or in no connection is named; door numbers are kept exactly as given (door ``d``
of room ``r`` is the world's door ``d`` of room ``r``, whatever order the connections come in).  Rooms have
:data:`~.port_world.CONTEST_DOORS` doors and :data:`~.port_world.CONTEST_ALPHABET` colours.

Examples
--------
>>> obj = {"rooms": [0, 1], "startingRoom": 0, "connections": [
...     {"from": {"room": 0, "door": d}, "to": {"room": 1, "door": d}} for d in range(6)]}
>>> w = map_from_json(obj)
>>> w.rooms, w.target(0, 3), w.colours
(2, 1, (0, 1))
>>> map_to_json(w) == obj
True
>>> map_from_json({**obj, "id": "secret"})
Traceback (most recent call last):
...
topomark.spec.errors.InvalidWorld: map: unknown key 'id' (a map has the keys rooms, startingRoom, connections)
"""

from __future__ import annotations

from typing import Any

from topomark.spec.errors import InvalidWorld, clip, require_input
from topomark.spec.port_world import CONTEST_ALPHABET, CONTEST_DOORS, MAX_ROOMS, DoorEnd, PortWorld, from_joins

__all__ = ["map_from_json", "map_to_json", "submission_from_json", "submission_to_json", "MAP_KEYS", "FILE_KEYS"]

MAP_KEYS = ("rooms", "startingRoom", "connections")
FILE_KEYS = ("problemName", "map")


def _keys(obj: Any, allowed: tuple[str, ...], what: str) -> None:
    require_input(isinstance(obj, dict), f"{what}: expected a JSON object, not {type(obj).__name__}", InvalidWorld)
    for key in obj:
        require_input(key in allowed, f"{what}: unknown key {clip(str(key), 40, quote=True)} (a {what} has the "
                      f"keys {', '.join(allowed)})", InvalidWorld)
    for key in allowed:
        require_input(key in obj, f"{what}: the key {key!r} is missing", InvalidWorld)


def _int(x: Any, what: str) -> int:
    require_input(isinstance(x, int) and not isinstance(x, bool), f"{what} is not an integer", InvalidWorld)
    return int(x)


def _end(obj: Any, what: str) -> DoorEnd:
    _keys(obj, ("room", "door"), what)
    return _int(obj["room"], f"{what}.room"), _int(obj["door"], f"{what}.door")


def map_from_json(obj: Any) -> PortWorld:
    """The port world of a contest map object (see the module's docstring)."""
    _keys(obj, MAP_KEYS, "map")
    rooms, connections = obj["rooms"], obj["connections"]
    require_input(isinstance(rooms, list) and 1 <= len(rooms) <= MAX_ROOMS,
                  f"map: rooms is a list of 1 to {MAX_ROOMS:,} labels", InvalidWorld)
    colours = [_int(c, f"map: rooms[{k}]") for k, c in enumerate(rooms)]
    require_input(isinstance(connections, list) and len(connections) <= CONTEST_DOORS * len(rooms),
                  f"map: connections is a list of at most {CONTEST_DOORS * len(rooms):,} connections", InvalidWorld)
    passages = []
    for k, c in enumerate(connections):
        _keys(c, ("from", "to"), f"map: connections[{k}]")
        passages.append((_end(c["from"], f"map: connections[{k}].from"), _end(c["to"], f"map: connections[{k}].to")))
    start = _int(obj["startingRoom"], "map: startingRoom")
    try:
        return from_joins(colours, passages, start, doors=CONTEST_DOORS, alphabet=CONTEST_ALPHABET)
    except InvalidWorld as e:
        raise InvalidWorld(f"map: {e}") from None


def map_to_json(world: PortWorld) -> dict[str, Any]:
    """The contest map object of ``world``: each passage once, from its smaller door-end, in door-end order."""
    require_input(world.doors == CONTEST_DOORS and world.alphabet <= CONTEST_ALPHABET,
                  f"a contest map has {CONTEST_DOORS} doors a room and colours 0..{CONTEST_ALPHABET - 1}; this world "
                  f"has {world.doors} doors and {world.alphabet} colours", InvalidWorld)
    return {"rooms": list(world.colours), "startingRoom": world.start,
            "connections": [{"from": {"room": a[0], "door": a[1]}, "to": {"room": b[0], "door": b[1]}}
                            for a, b in world.passages()]}


def submission_from_json(obj: Any) -> tuple[str, PortWorld]:
    """The problem name and port world of a contest map file ``{"problemName": ..., "map": ...}``."""
    _keys(obj, FILE_KEYS, "map file")
    name = obj["problemName"]
    require_input(isinstance(name, str) and 0 < len(name) <= 64 and name.isprintable(),
                  "map file: problemName is a printable string of 1 to 64 characters", InvalidWorld)
    return name, map_from_json(obj["map"])


def submission_to_json(name: str, world: PortWorld) -> dict[str, Any]:
    """The contest map file of ``world`` for problem ``name``."""
    return {"problemName": name, "map": map_to_json(world)}
