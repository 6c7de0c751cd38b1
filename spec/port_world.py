"""The port world: rooms with numbered doors, a colour per room, a start (the port-labelled model).

This model stands beside the thesis's (which it leaves untouched).  It is Table 2.3's *labelled graph* model as
the ICFP Programming Contest 2025 ("Ædificium") posed it: the robot moves by **absolute** door numbers (the same
door of a room has the same number however the robot came in), senses the room's colour, and can rewrite that colour
with charcoal for the rest of one plan (:mod:`.port_plan`).  A thesis world converts to a port world with port ``i``
= exit ``i`` (:func:`from_thesis_world`).

A port world has ``rooms`` rooms, each with the same number ``doors`` of doors ``0 .. doors-1``.  A *door-end* is a
pair ``(room, door)``.  Every door-end is joined to exactly one door-end: ``joins[r][d]`` is the door-end that
``(r, d)`` is joined to, and joining is symmetric (``joins`` is an involution on door-ends).  A door joined to itself,
two doors of one room joined together, and several passages between one pair of rooms are all allowed (the contest's
maps have all three).  Each room has a colour from the alphabet ``0 .. colours-1``; ``start`` is the room the robot
starts in.

Decisions (the thesis is silent on this model; the contest's task statement gives the rest):

* **Every room is reachable from the start.**  A room no door leads to could never be seen by any plan, so two maps
  that differ only there could not be told apart while their room counts agree; the loader refuses such a world,
  naming the room.
* **A uniform door count.**  The contest's rooms all have six doors; a thesis world's vertices have different
  degrees, so :func:`from_thesis_world` uses the largest degree and joins each missing door to itself (a door that
  leads back into its own room), and by default colours each room with its degree, so a port robot senses what the
  thesis's robot senses there (§3.1.1: the degree of the place).

Examples
--------
>>> w = PortWorld(colours=(0, 1), joins=(((1, 0), (0, 1)), ((0, 0), (1, 1))), start=0, doors=2, alphabet=2)
>>> w.rooms, w.target(0, 0), w.target(0, 1)
(2, 1, 0)
>>> w.passage((0, 0))
((0, 0), (1, 0))
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Iterator, Mapping, Sequence

from topomark.spec.errors import InvalidWorld, require_input

__all__ = ["PortWorld", "DoorEnd", "CONTEST_DOORS", "CONTEST_ALPHABET", "MAX_ROOMS", "MAX_DOORS", "from_thesis_world",
           "from_joins"]

DoorEnd = tuple[int, int]
"""``(room, door)``: one end of a passage."""

CONTEST_DOORS = 6
"""Doors per room in the contest's problems."""

CONTEST_ALPHABET = 4
"""Room labels in the contest are 2 bits: colours ``0 .. 3``."""

MAX_ROOMS = 100_000
"""The most rooms a port world may have (the contest's largest problem has 90; a limit keeps a file from asking
for unbounded memory before anything is checked)."""

MAX_DOORS = 64
"""The most doors a room may have (a plan names a door by one character in the contest's syntax, so 10 is its own
limit; 64 leaves room for converted thesis worlds of moderate degree)."""


@dataclass(frozen=True)
class PortWorld:
    """A port world (see the module's docstring).  Construction checks every condition and raises
    :class:`~topomark.spec.errors.InvalidWorld` naming the first offending room or door-end."""

    colours: tuple[int, ...]
    joins: tuple[tuple[DoorEnd, ...], ...]
    start: int
    doors: int = CONTEST_DOORS
    alphabet: int = CONTEST_ALPHABET

    def __post_init__(self) -> None:
        n = len(self.colours)
        require_input(1 <= n <= MAX_ROOMS, f"a port world has 1 to {MAX_ROOMS:,} rooms, not {n:,}", InvalidWorld)
        require_input(1 <= self.doors <= MAX_DOORS, f"a room has 1 to {MAX_DOORS} doors, not {self.doors}",
                      InvalidWorld)
        require_input(self.alphabet >= 1, f"the alphabet has at least one colour, not {self.alphabet}", InvalidWorld)
        require_input(len(self.joins) == n, f"{n} rooms have colours but {len(self.joins)} have doors", InvalidWorld)
        require_input(0 <= self.start < n, f"the start room {self.start} is not a room (rooms 0..{n - 1})",
                      InvalidWorld)
        for room, colour in enumerate(self.colours):
            require_input(0 <= colour < self.alphabet,
                          f"room {room}'s colour {colour} is outside the alphabet 0..{self.alphabet - 1}", InvalidWorld)
        for room, ends in enumerate(self.joins):  # every room's doors first: a join's other end is looked up below
            require_input(len(ends) == self.doors, f"room {room} has {len(ends)} doors, not {self.doors}", InvalidWorld)
        for room, ends in enumerate(self.joins):
            for door, (r, d) in enumerate(ends):
                require_input(0 <= r < n and 0 <= d < self.doors,
                              f"door-end ({room}, {door}) is joined to ({r}, {d}), which is not a door-end",
                              InvalidWorld)
                back = self.joins[r][d]
                require_input(back == (room, door),
                              f"door-end ({room}, {door}) is joined to ({r}, {d}), but ({r}, {d}) is joined to "
                              f"{back}: each door-end is joined to exactly one door-end", InvalidWorld)
        unreached = sorted(set(range(n)) - self.reachable())
        require_input(not unreached, f"room {unreached[0] if unreached else 0} cannot be reached from the start room "
                      f"{self.start} ({len(unreached)} such rooms)", InvalidWorld)

    @property
    def rooms(self) -> int:
        """The number of rooms."""
        return len(self.colours)

    def target(self, room: int, door: int) -> int:
        """The room that door ``door`` of ``room`` leads to."""
        return self.joins[room][door][0]

    def passage(self, end: DoorEnd) -> tuple[DoorEnd, DoorEnd]:
        """The passage through door-end ``end``, as its two door-ends in sorted order."""
        other = self.joins[end[0]][end[1]]
        return (min(end, other), max(end, other))

    def passages(self) -> Iterator[tuple[DoorEnd, DoorEnd]]:
        """Every passage once, as :meth:`passage` gives it, in order of its smaller door-end."""
        for room in range(self.rooms):
            for door in range(self.doors):
                a, b = self.passage((room, door))
                if a == (room, door):
                    yield a, b

    def reachable(self) -> set[int]:
        """The rooms some walk from the start reaches."""
        seen, queue = {self.start}, deque([self.start])
        while queue:
            room = queue.popleft()
            for r, _ in self.joins[room]:
                if r not in seen:
                    seen.add(r)
                    queue.append(r)
        return seen


def from_joins(colours: Sequence[int], passages: Sequence[tuple[DoorEnd, DoorEnd]], start: int, *,
               doors: int = CONTEST_DOORS, alphabet: int = CONTEST_ALPHABET) -> PortWorld:
    """The port world whose passages are ``passages`` (pairs of door-ends), each door-end in exactly one.

    >>> w = from_joins([0, 0], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=1)
    >>> w.joins
    (((1, 0), (0, 1)), ((0, 0), (1, 1)))
    """
    n = len(colours)
    require_input(1 <= n <= MAX_ROOMS, f"a port world has 1 to {MAX_ROOMS:,} rooms, not {n:,}", InvalidWorld)
    require_input(1 <= doors <= MAX_DOORS, f"a room has 1 to {MAX_DOORS} doors, not {doors}", InvalidWorld)
    table: list[list[DoorEnd | None]] = [[None] * doors for _ in range(n)]
    for k, (a, b) in enumerate(passages):
        for end, other in {a: b, b: a}.items():
            room, door = end
            require_input(0 <= room < n and 0 <= door < doors,
                          f"passage {k} names door-end ({room}, {door}), which is not a door-end (rooms 0..{n - 1}, "
                          f"doors 0..{doors - 1})", InvalidWorld)
            require_input(table[room][door] is None,
                          f"door-end ({room}, {door}) is used twice (passage {k} and an earlier one)", InvalidWorld)
            table[room][door] = other
    for room, ends in enumerate(table):
        for door, joined in enumerate(ends):
            require_input(joined is not None, f"door-end ({room}, {door}) is in no passage", InvalidWorld)
    joins = tuple(tuple(e for e in ends if e is not None) for ends in table)  # every door-end is joined (above)
    return PortWorld(colours=tuple(colours), joins=joins, start=start, doors=doors, alphabet=alphabet)


def from_thesis_world(rotation: Mapping[str, Sequence[str]], start: str, *, colour_by_degree: bool = True
                      ) -> tuple[PortWorld, list[str]]:
    """The port world of a thesis world (a rotation system), with port ``i`` = exit ``i`` (§3.1.1), and the names
    of its rooms in room order (room 0 is ``start``).

    Rooms have as many doors as the largest degree; a vertex's missing doors are joined to themselves.  With
    ``colour_by_degree`` (the default) each room's colour is its vertex's degree, so the port robot senses what the
    thesis's robot senses (the alphabet is ``0 .. max degree``); otherwise every room has colour 0.

    >>> w, names = from_thesis_world({"a": ["b"], "b": ["a", "c"], "c": ["b"]}, "a")
    >>> names, w.colours, w.joins[1]
    (['a', 'b', 'c'], (1, 2, 1), ((0, 0), (2, 0)))
    """
    require_input(start in rotation, f"the start {start!r} is not a vertex", InvalidWorld)
    names = [start, *sorted(v for v in rotation if v != start)]
    index = {v: k for k, v in enumerate(names)}
    doors = max(len(ns) for ns in rotation.values())
    passages: list[tuple[DoorEnd, DoorEnd]] = []
    for v in names:
        nbrs = rotation[v]
        for i, u in enumerate(nbrs):
            back = [j for j, x in enumerate(rotation[u]) if x == v]
            require_input(len(back) == 1, f"edge {v}-{u} is not a simple edge of a rotation system", InvalidWorld)
            a, b = (index[v], i), (index[u], back[0])
            if a <= b:
                passages.append((a, b))
        passages.extend(((index[v], i), (index[v], i)) for i in range(len(nbrs), doors))
    colours = [len(rotation[v]) if colour_by_degree else 0 for v in names]
    return from_joins(colours, passages, 0, doors=doors, alphabet=doors + 1 if colour_by_degree else 1), names
