"""Random port worlds and their covers, in the contest's shapes (the port-labelled model, :mod:`topomark.spec.port_world`).

:func:`random_port_world` joins door-ends at random over a random spanning tree (so every room is reachable), with
self-joined doors and parallel passages as likely as chance makes them, as the contest's maps have them.
:func:`cover` makes a ``k``-copy map of a base world, as the contest's later problems were made: every room
``k`` times (the same colour in each copy), each passage of the base joined between copies by a random permutation
(an involution for a door joined to itself), retried until every room is reachable; without charcoal marks no plan
tells the cover from its base, and with them they differ (they have different room counts).

Examples
--------
>>> w = random_port_world(7, rooms=5)
>>> w.rooms, w.doors, len(list(w.passages())) >= 4
(5, 6, True)
>>> c = cover(w, 3, seed=1)
>>> c.rooms, [c.colours[3 * r] for r in range(5)] == list(w.colours)
(15, True)
"""

from __future__ import annotations

import random

from topomark.spec.errors import InvalidInput, require_input
from topomark.spec.port_world import (CONTEST_ALPHABET, CONTEST_DOORS, MAX_ROOMS, DoorEnd, PortWorld,
                                      from_joins)

__all__ = ["random_port_world", "cover", "MAX_COVER_TRIES"]

MAX_COVER_TRIES = 1000
"""How many random layer permutations :func:`cover` tries before it reports that no connected cover was drawn."""


def random_port_world(seed: int, rooms: int, *, doors: int = CONTEST_DOORS, alphabet: int = CONTEST_ALPHABET,
                      self_doors: float | None = None) -> PortWorld:
    """A random port world of ``rooms`` rooms, every room reachable from room 0 (the start).

    Room colours are uniform over the alphabet, except that room 0 has colour 0 (as in every contest map).
    ``self_doors`` is the chance that a door left after the spanning tree is joined to itself (default: what a
    uniform matching of the free door-ends gives, about one door in ``free`` door-ends).
    """
    require_input(1 <= rooms <= MAX_ROOMS, f"rooms: 1 to {MAX_ROOMS:,}, not {rooms:,}")
    require_input(doors >= 2 or rooms == 1, f"a world of {rooms} rooms needs at least 2 doors a room to be connected")
    rng = random.Random(seed)
    free: list[list[int]] = [list(range(doors)) for _ in range(rooms)]
    for doors_left in free:
        rng.shuffle(doors_left)
    passages: list[tuple[DoorEnd, DoorEnd]] = []
    order = list(range(1, rooms))
    rng.shuffle(order)
    placed = [0]
    for room in order:  # a random spanning tree: each room joined to a placed room with a free door
        host = rng.choice([r for r in placed if free[r]])
        passages.append(((host, free[host].pop()), (room, free[room].pop())))
        placed.append(room)
    ends = [(r, d) for r in range(rooms) for d in free[r]]
    rng.shuffle(ends)
    while ends:
        a = ends.pop()
        if not ends or (self_doors is not None and rng.random() < self_doors):
            passages.append((a, a))
            continue
        k = rng.randrange(len(ends) + (1 if self_doors is None else 0))
        passages.append((a, a) if k == len(ends) else (a, ends.pop(k)))
    colours = [0] + [rng.randrange(alphabet) for _ in range(rooms - 1)]
    return from_joins(colours, passages, 0, doors=doors, alphabet=alphabet)


def cover(base: PortWorld, copies: int, seed: int) -> PortWorld:
    """A ``copies``-copy map of ``base`` (see the module's docstring): room ``r`` of copy ``i`` is room
    ``copies * r + i``; the start is copy 0 of the base's start."""
    require_input(1 <= copies and base.rooms * copies <= MAX_ROOMS,
                  f"copies: 1 or more, with at most {MAX_ROOMS:,} rooms in all")
    rng = random.Random(seed)
    for _ in range(MAX_COVER_TRIES):
        passages = []
        for (r, d), (r2, d2) in base.passages():
            layers = list(range(copies))
            if (r, d) == (r2, d2):
                rng.shuffle(layers)  # an involution: pair up layers, some joined to themselves
                perm = list(range(copies))
                while len(layers) >= 2 and rng.random() < 0.7:
                    i, j = layers.pop(), layers.pop()
                    perm[i], perm[j] = j, i
            else:
                perm = layers[:]
                rng.shuffle(perm)
            for i in range(copies):
                if (r, d) != (r2, d2) or perm[i] >= i:
                    passages.append(((copies * r + i, d), (copies * r2 + perm[i], d2)))
        colours = [c for c in base.colours for _ in range(copies)]
        try:
            return from_joins(colours, passages, copies * base.start, doors=base.doors, alphabet=base.alphabet)
        except InvalidInput as e:
            if "cannot be reached" not in str(e):
                raise
    raise InvalidInput(f"no connected {copies}-copy cover of this world in {MAX_COVER_TRIES} random tries")
