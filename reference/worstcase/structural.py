"""Structural moves of the worst-case search: splice paths, re-embed around the marker, restart from a family
(thesis §3.5.2, §7.2).

§7.2 asks which worlds make Algorithm 3.1 reach its O(m²n) bound (§3.5.2).
What makes a world expensive is its structure — long paths of places that look
alike, the start at an end of them, many exits left open while the robot is
far from its marker (``topomark explore --breakdown`` shows it) — and a move
that redraws one rotation or adds one random edge rarely finds it.  These moves
change structure and keep every degree, so a search started in a good family
stays among the worlds of maximum degree D:

* ``switch`` — two edges a–b and c–d (four distinct places, a–c and b–d not
  edges) become a–c and b–d, each new edge taking the old one's place in its
  two rotations: two paths through the world are cut and spliced crosswise.
  Refused (another draw) when the world falls apart.
* ``transpose`` — two neighbours of one place trade places in its rotation:
  the smallest re-embedding, one face split and one joined.
* ``marker`` — the rotation of the start (where the marker is dropped, §3.3)
  or of one of its neighbours redrawn: a re-embedding around the marker,
  where every validation walk ends.

:func:`family_world` names the worlds a search may restart from
(:data:`RESTART_FAMILIES`): the families of
:mod:`~topomark.reference.worlds.expensive`,
:mod:`~topomark.reference.worlds.rewired`,
:mod:`~topomark.reference.worlds.split_strip` and
:mod:`~topomark.reference.worlds.pendant` at exactly n places, with their
generator text, so the search's first generation is that world and its
neighbours instead of random worlds; :func:`restart_world` also takes any one
world ``topomark explore`` accepts (a kept worst world ``worst-case:case=NAME``
or a world file), so a search can go on from where an earlier one stopped.

>>> import random
>>> w = family_world("strip", 12)[0]
>>> moved = structural_move(w, "switch", 4, random.Random(0))  # None when the draw cannot switch (seed 1)
>>> sorted(moved.degree(v) for v in moved.vertices) == sorted(w.degree(v) for v in w.vertices)
True
>>> family_world("strip", 12)[1], family_world("circulant", 12)[1]
('strip:n=12,cap=1', 'circulant:n=12,k=2')
"""

from __future__ import annotations

import random

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World

from topomark.reference.worlds.generators import generate
from topomark.reference.worlds.rewired import REWIRED_FROM
from topomark.reference.worlds.split_strip import SPLIT_FROM
from topomark.reference.worlds.pendant import PENDANT_FROM

__all__ = ["STRUCTURAL_MOVES", "RESTART_FAMILIES", "structural_move", "family_world", "family_text", "restart_world"]

STRUCTURAL_MOVES = ("switch", "transpose", "marker")
RESTART_FAMILIES = ("strip", "circulant", "k5e-chain", "rewired-strip", "split-strip", "pendant-strip")


def _rotation(world: World) -> dict[str, list[str]]:
    return {v: list(ns) for v, ns in world.rotation.items()}


def _switch(world: World, rng: random.Random) -> World | None:
    rot = _rotation(world)
    edges = [(u, v) for u in rot for v in rot[u] if u < v]
    if len(edges) < 2:
        return None
    (a, b), (c, d) = rng.sample(edges, 2)
    if rng.random() < 0.5:
        c, d = d, c
    if len({a, b, c, d}) < 4 or c in rot[a] or d in rot[b]:
        return None
    rot[a][rot[a].index(b)], rot[c][rot[c].index(d)] = c, a
    rot[b][rot[b].index(a)], rot[d][rot[d].index(c)] = d, b
    if not nx.is_connected(nx.Graph([(u, v) for u in rot for v in rot[u]])):
        return None
    assert sorted(map(len, rot.values())) == sorted(map(len, world.rotation.values())), "a switch keeps every degree"
    return _keep_start(world, rot)


def _transpose(world: World, rot: dict[str, list[str]], v: str, rng: random.Random) -> World | None:
    if len(rot[v]) < 3:
        return None  # two neighbours or fewer have one cyclic order
    i, j = rng.sample(range(len(rot[v])), 2)
    rot[v][i], rot[v][j] = rot[v][j], rot[v][i]
    return _keep_start(world, rot)


def _keep_start(world: World, rot: dict[str, list[str]]) -> World:
    """The world of ``rot`` from ``world``'s start; a start facing an edge that is gone faces its first exit."""
    start = world.start or Start(world.vertices[0], world.rotation[world.vertices[0]][0])
    if start.facing not in rot[start.at]:
        start = Start(start.at, rot[start.at][0])
    return World(rot, (), start)


def structural_move(world: World, kind: str, max_degree: int, rng: random.Random) -> World | None:
    """``world`` changed by one move of ``kind`` (:data:`STRUCTURAL_MOVES`), or None when the draw finds nothing
    to do (the caller draws again).  No move changes a degree, so the world stays within ``max_degree``."""
    if kind == "switch":
        return _switch(world, rng)
    rot = _rotation(world)
    if kind == "transpose":
        return _transpose(world, rot, rng.choice(list(world.vertices)), rng)
    if kind == "marker":
        at = world.start.at if world.start is not None else world.vertices[0]
        return _transpose(world, rot, rng.choice([at, *world.rotation[at]]), rng)
    raise InvalidInput(f"unknown structural move {kind!r} (choose from {', '.join(STRUCTURAL_MOVES)})")


def family_text(family: str, n: int) -> str:
    """The generator text of ``family`` at exactly ``n`` places (bad input if the family has no such size)."""
    if family == "strip":
        return f"strip:n={n},cap={1 if n % 2 == 0 and n >= 8 else 0}"
    if family == "circulant":
        return f"circulant:n={n},k=2"
    if family == "k5e-chain":
        if n % 5:
            raise InvalidInput(f"--restart-family k5e-chain has 5 places per gadget: n must be a multiple of 5, "
                               f"not {n}")
        return f"k5e-chain:gadgets={n // 5}"
    if family == "rewired-strip":
        if n % 2 or n < REWIRED_FROM:
            raise InvalidInput(f"--restart-family rewired-strip needs an even n >= {REWIRED_FROM}, not {n}")
        return f"rewired-strip:n={n}"
    if family == "split-strip":
        if n % 2 or n < SPLIT_FROM:
            raise InvalidInput(f"--restart-family split-strip needs an even n >= {SPLIT_FROM}, not {n}")
        return f"split-strip:n={n}"
    if family == "pendant-strip":
        if n < PENDANT_FROM:
            raise InvalidInput(f"--restart-family pendant-strip needs n >= {PENDANT_FROM}, not {n}")
        return f"pendant-strip:n={n}"
    raise InvalidInput(f"unknown restart family {family!r} (choose from {', '.join(RESTART_FAMILIES)})")


def family_world(family: str, n: int) -> tuple[World, str]:
    """The world of ``family`` at ``n`` places with its start, and its generator text."""
    text = family_text(family, n)
    name, _, params = text.partition(":")
    world = generate(name, **dict(p.split("=") for p in params.split(",")))
    assert world.n == n, f"{text} has {world.n} places, not {n}"
    return world, text


def restart_world(restart: str, n: int) -> World:
    """The world a search restarts from at ``n`` places: the world of the family ``restart``
    (:data:`RESTART_FAMILIES`) at that size, or else the one world ``restart`` names (a generator text or a world
    file, as ``topomark explore`` takes it), which must have exactly ``n`` places; without a start it starts at
    its first place facing that place's first exit."""
    if restart in RESTART_FAMILIES:
        return family_world(restart, n)[0]
    from topomark.reference.worlds.argument import resolve_world
    world = resolve_world(restart)
    if world.n != n:
        raise InvalidInput(f"the restart world {restart} has {world.n} places, not {n}: search it at "
                           f"--vertices {world.n}")
    return world if world.start is not None else _keep_start(world, _rotation(world))
