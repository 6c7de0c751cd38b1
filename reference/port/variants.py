"""Changed copies of a port world, as the judge's suite uses them: rooms renumbered, a room's doors renumbered,
two passages' ends exchanged (the port-labelled model, :mod:`topomark.spec.port_world`).

Renumbering rooms never changes what a plan records (:func:`relabelled` gives an equivalent map); renumbering one
room's doors, or exchanging the ends of two passages, may or may not, and the judge says which.

>>> from topomark.spec.port_world import from_joins
>>> w = from_joins([0, 1], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=2)
>>> relabelled(w, [1, 0]).colours, relabelled(w, [1, 0]).start
((1, 0), 1)
>>> door_permuted(w, 0, [1, 0]).joins[0]
((0, 0), (1, 0))
"""

from __future__ import annotations

from typing import Sequence

from topomark.spec.errors import require_input
from topomark.spec.port_world import DoorEnd, PortWorld, from_joins

__all__ = ["relabelled", "door_permuted", "passage_swapped", "world_passages"]


def world_passages(w: PortWorld) -> list[tuple[DoorEnd, DoorEnd]]:
    """The passages of ``w`` as a list (:meth:`PortWorld.passages` order)."""
    return list(w.passages())


def relabelled(w: PortWorld, perm: Sequence[int]) -> PortWorld:
    """``w`` with room ``r`` renumbered ``perm[r]``."""
    colours = [0] * w.rooms
    for r, c in enumerate(w.colours):
        colours[perm[r]] = c
    passages = [((perm[a[0]], a[1]), (perm[b[0]], b[1])) for a, b in w.passages()]
    return from_joins(colours, passages, perm[w.start], doors=w.doors, alphabet=w.alphabet)


def door_permuted(w: PortWorld, room: int, perm: Sequence[int]) -> PortWorld:
    """``w`` with door ``d`` of ``room`` renumbered ``perm[d]`` (the passages stay; only their door numbers at
    ``room`` change)."""
    def moved(end: DoorEnd) -> DoorEnd:
        return (room, perm[end[1]]) if end[0] == room else end

    passages = [(moved(a), moved(b)) for a, b in w.passages()]
    return from_joins(w.colours, passages, w.start, doors=w.doors, alphabet=w.alphabet)


def passage_swapped(w: PortWorld, first: DoorEnd, second: DoorEnd) -> PortWorld:
    """``w`` with the passages ``first–f1`` and ``second–f2`` rejoined as ``first–f2`` and ``second–f1`` (four
    distinct door-ends: neither passage joins a door-end to itself, and they are not one passage);
    :class:`~topomark.spec.errors.InvalidWorld` when a room becomes unreachable."""
    f1, f2 = w.joins[first[0]][first[1]], w.joins[second[0]][second[1]]
    require_input(len({first, second, f1, f2}) == 4, f"door-ends {first} and {second}: a passage swap needs two "
                  "passages with four distinct door-ends")
    passages = [p for p in w.passages() if first not in p and second not in p]
    passages += [(first, f2), (second, f1)]
    return from_joins(w.colours, passages, w.start, doors=w.doors, alphabet=w.alphabet)
