"""A world as flat integer arrays, for compiled kernels (thesis §3.1.1).

A compiled kernel (the engine's runs, the census's per-world kernel) cannot
hold a :class:`~topomark.spec.world.World`; it takes the same rotation system
as three arrays in *compressed sparse row* form, vertex ``k`` being the
world's ``k``-th vertex (``world.vertices[k]``):

* ``offsets`` (n + 1 entries): the darts of vertex ``k`` are ``offsets[k]``
  to ``offsets[k + 1] - 1``, so ``deg(k) = offsets[k + 1] - offsets[k]``;
* ``nbr`` (2m entries): ``nbr[offsets[k] + i]`` is the vertex reached through
  exit ``i`` of ``k`` — position ``i`` of ``k``'s clockwise neighbour list,
  as in the world (§3.1.1, Figure 3.1);
* ``back`` (2m entries): ``back[offsets[k] + i]`` is the exit of that
  neighbour leading back to ``k``, i.e. the entry index of a robot that
  arrives through ``(k, i)`` (the world has no multi-edges, so it is unique).

The arrays say nothing the world does not; :func:`from_arrays` rebuilds the
world (vertex ``k`` named ``v{k}``, the census's names) and the round trip is
tested.  Markers and the start are not part of the arrays: a kernel takes
them as further arguments.

Examples
--------
>>> from topomark.spec.world import World
>>> a = to_arrays(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}))
>>> a.offsets.tolist(), a.nbr.tolist(), a.back.tolist()
([0, 2, 4, 6], [1, 2, 2, 0, 0, 1], [1, 0, 1, 0, 1, 0])
>>> from_arrays(a.offsets, a.nbr).rotation
{'v0': ('v1', 'v2'), 'v1': ('v2', 'v0'), 'v2': ('v0', 'v1')}
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from topomark.spec.world import World

__all__ = ["WorldArrays", "to_arrays", "from_arrays", "back_links"]


@dataclass(frozen=True)
class WorldArrays:
    """The rotation system as ``offsets``, ``nbr`` and ``back`` (int32), with the world's vertex names."""

    offsets: np.ndarray
    nbr: np.ndarray
    back: np.ndarray
    names: tuple[str, ...]

    @property
    def n(self) -> int:
        return len(self.names)

    @property
    def m(self) -> int:
        return len(self.nbr) // 2


def back_links(offsets: np.ndarray, nbr: np.ndarray) -> np.ndarray:
    """``back`` for ``offsets`` and ``nbr``: for every dart (k, i), the exit of its target leading back to k."""
    back = np.empty(len(nbr), dtype=np.int32)
    for k in range(len(offsets) - 1):
        for d in range(offsets[k], offsets[k + 1]):
            w = nbr[d]
            row = nbr[offsets[w]:offsets[w + 1]]
            hits = np.flatnonzero(row == k)
            assert len(hits) == 1, f"vertex {w} must list {k} exactly once (§3.1.1: no multi-edges)"
            back[d] = hits[0]
    return back


def to_arrays(world: World) -> WorldArrays:
    """The world's rotation system as arrays, vertex ``k`` being ``world.vertices[k]``."""
    names = tuple(world.vertices)
    number = {v: k for k, v in enumerate(names)}
    offsets = np.zeros(len(names) + 1, dtype=np.int32)
    offsets[1:] = np.cumsum([world.degree(v) for v in names])
    nbr = np.fromiter((number[w] for v in names for w in world.rotation[v]), dtype=np.int32, count=int(offsets[-1]))
    back = np.fromiter((world.index(w, v) for v in names for w in world.rotation[v]), dtype=np.int32,
                       count=int(offsets[-1]))
    return WorldArrays(offsets, nbr, back, names)


def from_arrays(offsets: np.ndarray, nbr: np.ndarray) -> World:
    """The world of ``offsets`` and ``nbr``, vertex ``k`` named ``v{k}`` (checked as every world is)."""
    n = len(offsets) - 1
    return World({f"v{k}": [f"v{int(w)}" for w in nbr[offsets[k]:offsets[k + 1]]] for k in range(n)})
