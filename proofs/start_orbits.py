"""Starts up to symmetry: one start dart per orbit of a world's automorphisms (thesis §3.1.1, §3.1.3).

A *start* is a dart: the robot at v facing its exit i (§3.1.1).  Two starts
that an automorphism of the world maps onto each other give the same run up
to renaming (an automorphism of an embedded world preserves the rotation, so
every perception along the run is the same), so a search over every start
runs only the least dart of each orbit.  The automorphisms are the census's
(:func:`topomark.proofs.census_map.unit_worlds`), as vertex-number maps of
worlds whose vertices are named ``v0, v1, …``.

Examples
--------
>>> from topomark.proofs.census_map import world_at
>>> world = world_at(3, 2, 0, 0)  # the path v1 - v0 - v2, whose automorphisms swap v1 and v2
>>> start_darts(world, ({0: 0, 1: 1, 2: 2}, {0: 0, 1: 2, 2: 1}))
[('v0', 0), ('v1', 0)]
"""

from __future__ import annotations

from topomark.spec.world import World

__all__ = ["dart_image", "start_darts"]


def dart_image(world: World, sigma: dict[int, int], v: str, i: int) -> tuple[int, int]:
    """The dart (v, i) moved by the automorphism ``sigma`` (vertex numbers of ``v0, v1, …``)."""
    w = world.neighbour(v, i)
    sv, sw = f"v{sigma[int(v[1:])]}", f"v{sigma[int(w[1:])]}"
    return int(sv[1:]), world.index(sv, sw)


def start_darts(world: World, autos: tuple[dict[int, int], ...]) -> list[tuple[str, int]]:
    """The least dart of each orbit of the world's automorphisms ``autos`` (identity included) on its darts."""
    out = []
    for v in world.vertices:
        for i in range(world.degree(v)):
            here = (int(v[1:]), i)
            if all(dart_image(world, sigma, v, i) >= here for sigma in autos):
                out.append((v, i))
    return out
