"""Algorithm 3.1's line 5, "choose an unexplored edge e from U", as named edge choices (thesis §3.3).

The thesis leaves the choice open: any edge of U will do, and the loop conditions and the bound (3.1)+(3.2)
hold whichever is taken (§3.4, §3.5.2).  An **edge choice** is a function ``choose(S, dist) -> k``: given the
map S (U is ``S.unexplored``, in its order) and ``dist``, the distance in S from the robot to every vertex of
S, it returns the index in U of the edge to take.  :data:`EDGE_CHOICES` holds them by name:

* ``nearest`` — the entry of U whose known end is nearest the robot, the first listed among equals;
* ``fifo`` — the oldest entry of U; ``lifo`` — the newest.

:func:`register_edge_choice` adds one under a new name.  A name in :data:`EDGE_CHOICES` is an edge policy
like the built-in ones: ``Policies(edge=NAME)``, ``topomark explore --policy edge=NAME`` for every algorithm
that takes an edge policy, the default of a registration that names it (``AlgorithmSpec(edge_policy=NAME)``,
``docs/adding-an-algorithm.md``), and a trace header's ``policies.edge``.

Examples
--------
>>> from topomark.spec.mapstate import PartialMap
>>> S = PartialMap()
>>> v0 = S.add_vertex(3)
>>> S.unexplored.extend([(v0, 0), (v0, 1), (v0, 2)])
>>> [EDGE_CHOICES[name](S, {v0: 0}) for name in ("nearest", "fifo", "lifo")]
[0, 0, 2]
"""

from __future__ import annotations

from typing import Callable, Mapping

from topomark.spec.mapstate import PartialMap

__all__ = ["EdgeChoice", "EDGE_CHOICES", "BUILT_IN", "register_edge_choice", "unregister_edge_choice"]

EdgeChoice = Callable[[PartialMap, Mapping[int, int]], int]
"""``choose(S, dist) -> k``: the index in ``S.unexplored`` of the edge line 5 takes (module docstring)."""


def nearest(S: PartialMap, dist: Mapping[int, int]) -> int:
    """The entry of U whose known end is nearest the robot in S, the first listed among equals."""
    ds = [dist[v] for v, _ in S.unexplored]
    return ds.index(min(ds))


def fifo(S: PartialMap, dist: Mapping[int, int]) -> int:
    """The oldest entry of U."""
    return 0


def lifo(S: PartialMap, dist: Mapping[int, int]) -> int:
    """The newest entry of U."""
    return len(S.unexplored) - 1


EDGE_CHOICES: dict[str, EdgeChoice] = {"nearest": nearest, "fifo": fifo, "lifo": lifo}
"""Every edge choice by name: the built-in ones and those :func:`register_edge_choice` added."""

BUILT_IN = tuple(EDGE_CHOICES)
"""The names of the built-in edge choices, which cannot be unregistered."""


def register_edge_choice(name: str, choose: EdgeChoice) -> EdgeChoice:
    """Add ``choose`` to :data:`EDGE_CHOICES` as ``name`` (a lower-case word, hyphens allowed) and return it.

    A name taken by another function is refused (``ValueError``); registering the same function under its
    name again is allowed, so that a registration module may be imported twice."""
    if not (name and name.replace("-", "").isalnum() and name.isascii() and name == name.lower()):
        raise ValueError(f"edge choice name {name!r}: lower-case letters, digits and hyphens only")
    if EDGE_CHOICES.get(name, choose) is not choose:
        raise ValueError(f"edge choice {name!r} is registered twice")
    if not callable(choose):
        raise ValueError(f"edge choice {name!r}: {choose!r} is not callable as choose(S, dist)")
    EDGE_CHOICES[name] = choose
    return choose


def unregister_edge_choice(name: str) -> EdgeChoice:
    """Take the edge choice ``name`` out of :data:`EDGE_CHOICES` (what :func:`register_edge_choice` added)."""
    if name in BUILT_IN:
        raise ValueError(f"the built-in edge choice {name!r} cannot be unregistered")
    return EDGE_CHOICES.pop(name)
