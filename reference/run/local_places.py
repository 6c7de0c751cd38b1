"""The truth about a marker-less lighthouse (thesis §5.2.1): is the place it chose unique?

A §5.2.1 lighthouse (:mod:`~topomark.reference.explorers.local_lighthouses`)
is recognised by its local signature only, so the map it gives is
guaranteed right exactly when that signature picks out one place and one
entry of it in the world — then the virtual lighthouse is a directional
lighthouse and Algorithm 3.1's correctness (§3.4) applies.  The thesis says
neither scheme can guarantee it: "This approach cannot guarantee the
uniqueness of the place information as well as the back-link information"
(scheme A, §5.2.1); "can guarantee the explicitness of back-link information
… but cannot guarantee the uniqueness of the lighthouse itself" (scheme B,
§5.2.1).

This module sees the world; explorers never import it (tests/test_wall.py).
Tests and benchmarks use :func:`unique_place` to tell a run whose
precondition held (it must be ``correct``) from one where it did not (any of
``correct``, ``wrong-map``, ``failed``: §5.2.1).

* ``local-pair``: v0 (degree a) entered from its exit 0, whose far end has
  degree b.  The precondition: v0 is the only vertex of degree a with a
  neighbour of degree b, and it has exactly one (so the first one clockwise
  is the same from every entry).
* ``local-degree-list``: D, the views at distance ``neighbourhood`` of v0's
  neighbours by exit (as the robot probes them).  The precondition: no other
  vertex shows a rotation of D (D itself is aperiodic by construction).

Examples
--------
>>> from topomark.reference.worlds.generators import wheel_a
>>> w = wheel_a()
>>> corner = w.rotation["0"][0]
>>> neighbour_views(w, corner, w.index(corner, "0"), 1)
(4, 3, 3)
>>> unique_place(w, "local-degree-list", (corner, w.index(corner, "0")))  # four corners show (4, 3, 3)
False
"""

from __future__ import annotations

from typing import Any

from topomark.spec.world import World

__all__ = ["view", "neighbour_views", "unique_place"]


def view(world: World, v: str, entry: int, depth: int) -> Any:
    """What a robot entering ``v`` by ``entry`` learns by probing to ``depth`` (as ``probing.view_here``)."""
    d = world.degree(v)
    if depth == 0:
        return d
    return d, tuple(view(world, *world.target((v, (entry + r) % d)), depth - 1) for r in range(1, d))


def neighbour_views(world: World, v: str, entry: int, depth: int) -> tuple[Any, ...]:
    """D at ``v`` from ``entry``: each neighbour's view to ``depth`` − 1, by exit counted from ``entry``."""
    d = world.degree(v)
    return tuple(view(world, *world.target((v, (entry + r) % d)), depth - 1) for r in range(d))


def unique_place(world, lighthouse: str, state: tuple, neighbourhood: int = 1) -> bool:
    """Whether the lighthouse ``lighthouse`` established at world ``state`` (v0, the entry that is its exit 0)
    is told apart, place and back-link, by its local signature — the precondition of a correct map."""
    v0, entry = state
    if lighthouse == "local-pair":
        a, b = world.degree(v0), world.degree(world.neighbour(v0, entry))
        holders = [v for v in world.vertices if world.degree(v) == a
                   and any(world.degree(u) == b for u in world.rotation[v])]
        return holders == [v0] and sum(world.degree(u) == b for u in world.rotation[v0]) == 1
    if lighthouse == "local-degree-list":
        D = neighbour_views(world, v0, entry, neighbourhood)
        return not any(neighbour_views(world, v, j, neighbourhood) == D for v in world.vertices if v != v0
                       for j in range(world.degree(v)) if world.degree(v) == len(D))
    raise ValueError(f"{lighthouse!r} is not a §5.2.1 lighthouse")
