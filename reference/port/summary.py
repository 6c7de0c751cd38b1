"""What a port world is made of: rooms, passages by kind, colours (the port-labelled model, ``topomark port show``).

A passage is one of three kinds: a door joined to itself (the robot stays in its room and comes back through the
same door), two doors of one room joined together, or a passage between two rooms.  A passage is *parallel* when
another passage joins the same two rooms (the same room, for a passage between two doors of one room).

>>> from topomark.spec.port_world import from_joins
>>> w = from_joins([0, 1, 1], [((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (0, 2)), ((1, 2), (2, 0)),
...                            ((2, 1), (2, 2))], 0, doors=3, alphabet=2)
>>> s = summarise(w)
>>> s["passages"], s["self_joined_doors"], s["same_room_passages"], s["parallel_passages"], s["colour_counts"]
(5, 1, 1, 2, [1, 2])
"""

from __future__ import annotations

from collections import Counter
from typing import Any

from topomark.spec.port_world import PortWorld

__all__ = ["summarise"]


def summarise(world: PortWorld) -> dict[str, Any]:
    """The counts ``topomark port show`` prints (see the module's docstring)."""
    passages = list(world.passages())
    self_joined = sum(1 for a, b in passages if a == b)
    same_room = sum(1 for a, b in passages if a != b and a[0] == b[0])
    pairs = Counter((a[0], b[0]) for a, b in passages if a != b)
    parallel = sum(k for k in pairs.values() if k > 1)
    counts = [0] * world.alphabet
    for c in world.colours:
        counts[c] += 1
    return {"rooms": world.rooms, "doors": world.doors, "alphabet": world.alphabet, "start": world.start,
            "passages": len(passages), "self_joined_doors": self_joined, "same_room_passages": same_room,
            "parallel_passages": parallel, "colour_counts": counts}
