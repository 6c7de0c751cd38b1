"""Every embedded world as batches of flat arrays, without a World object per world (thesis §3.1.1, §3.1.3).

The same worlds, in the same order, as
:func:`topomark.proofs.enumerate.embedded_worlds` — per graph of
:func:`topomark.proofs.enumerate.connected_graphs`, the least rotation system
of each Aut-orbit, in product order — decided by the kernel of
:mod:`topomark.proofs.orbit_kernel` and delivered as a :class:`WorldBatch`:
the worlds of one graph as rows of the arrays of
:mod:`topomark.proofs.world_arrays` (``offsets`` shared, ``nbr`` and
``back`` one row per world), with each world's rank, its digits (vertex v's
cyclic order is choice ``digits[v]`` of :func:`graph_data`'s ``choices[v]``)
and its stabiliser (the automorphisms fixing it, as indices into
:func:`graph_data`'s ``actions``, the identity being 0).

:func:`graph_data` is the per-graph table both this module and
:mod:`topomark.proofs.census_map` read: the cyclic orders of each vertex in
the order of :func:`topomark.proofs.enumerate.rotation_systems`, and each
automorphism's action on them.

Examples
--------
>>> sum(len(b) for b in embedded_batches(6, 4))   # Burnside: 1 + 2 + 9 + 275 + 7229
7516
>>> b = next(graph_batches(4, 3, 5))               # K4: 16 rotation systems, 3 worlds
>>> b.ranks.tolist(), b.nbr[1].tolist()
([0, 1, 5], [1, 2, 3, 0, 2, 3, 0, 1, 3, 0, 2, 1])
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import lru_cache
from typing import Iterator

import networkx as nx
import numpy as np

from topomark.proofs.enumerate import check_bounds, connected_graphs, graph_automorphisms
from topomark.proofs.orbit_kernel import representatives
from topomark.proofs.world_arrays import WorldArrays

__all__ = ["WorldBatch", "graphs_of", "automorphisms_of", "graph_data", "graph_batches", "embedded_batches"]


@lru_cache(maxsize=None)
def graphs_of(n: int, max_degree: int) -> tuple[nx.Graph, ...]:
    """:func:`topomark.proofs.enumerate.connected_graphs`, kept: a graph's index names it in witnesses."""
    return tuple(connected_graphs(n, max_degree))


@lru_cache(maxsize=64)
def automorphisms_of(n: int, max_degree: int, gi: int) -> tuple[dict[int, int], ...]:
    return tuple(graph_automorphisms(graphs_of(n, max_degree)[gi]))


@lru_cache(maxsize=64)
def graph_data(n: int, max_degree: int, gi: int) -> tuple[list[list[tuple[int, ...]]], list[int], list[tuple]]:
    """Per vertex its cyclic orders (the factors of ``enumerate.rotation_systems``, in its order), their
    numbers, and every automorphism sigma of graph ``gi`` (the identity first) with its action on choices:
    ``rows[u] = (w, table)`` where ``w = sigma⁻¹(u)`` and ``table[d]`` is the index, among u's choices,
    of the image of w's choice ``d`` (written from its least neighbour, as ``enumerate._normal`` does)."""
    g = graphs_of(n, max_degree)[gi]
    choices = []
    for v in range(n):
        first, *rest = sorted(g[v])
        choices.append([(first, *perm) for perm in itertools.permutations(rest)])
    index = [{c: d for d, c in enumerate(cs)} for cs in choices]
    actions = []
    for sigma in sorted(automorphisms_of(n, max_degree, gi), key=lambda s: any(k != v for k, v in s.items())):
        inverse = {v: k for k, v in sigma.items()}
        rows = []
        for u in range(n):
            w = inverse[u]
            table = []
            for c in choices[w]:
                image = [sigma[x] for x in c]
                k = image.index(min(image))
                table.append(index[u][tuple(image[k:] + image[:k])])
            rows.append((w, table))
        actions.append((sigma, rows))
    return choices, [len(c) for c in choices], actions


@dataclass(frozen=True)
class WorldBatch:
    """Worlds on graph ``gi`` of size ``n``: row ``i`` is the world of rank ``ranks[i]``."""

    n: int
    gi: int
    ranks: np.ndarray          # (k,) int64, ascending
    digits: np.ndarray         # (k, n) int64: the choice index at each vertex
    offsets: np.ndarray        # (n + 1,) int32, shared by every row (one graph)
    nbr: np.ndarray            # (k, 2m) int32
    back: np.ndarray           # (k, 2m) int32
    stab_offsets: np.ndarray   # (k + 1,) int64: row i's stabiliser is stab[stab_offsets[i]:stab_offsets[i + 1]]
    stab: np.ndarray           # int64 indices into graph_data(...)[2], identity = 0

    def __len__(self) -> int:
        return len(self.ranks)

    def stabiliser(self, i: int) -> np.ndarray:
        return self.stab[self.stab_offsets[i]:self.stab_offsets[i + 1]]

    def arrays(self, i: int) -> WorldArrays:
        """Row ``i`` as :class:`~topomark.proofs.world_arrays.WorldArrays` (vertex k named ``v{k}``)."""
        return WorldArrays(self.offsets, self.nbr[i], self.back[i], tuple(f"v{k}" for k in range(self.n)))


@dataclass(frozen=True)
class _Tables:
    """graph_data as the kernel's flat arrays, and per vertex its choices and the positions in them."""

    kernel: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]
    offsets: np.ndarray
    place: np.ndarray                  # place[v] = radices[v + 1] · … · radices[n - 1]
    orders: tuple[np.ndarray, ...]     # orders[v][d] = choice d of v (deg v neighbours)
    positions: tuple[np.ndarray, ...]  # positions[v][d, w] = exit of v leading to w under choice d
    total: int


@lru_cache(maxsize=64)
def _tables(n: int, max_degree: int, gi: int) -> _Tables:
    choices, radices, actions = graph_data(n, max_degree, gi)
    base = np.concatenate([[0], np.cumsum(radices)[:-1]]).astype(np.int64)
    source = np.array([w for _, rows in actions for w, _ in rows], dtype=np.int64)
    table = np.array([d for _, rows in actions for _, t in rows for d in t], dtype=np.int64)
    degrees = [len(cs[0]) for cs in choices]
    offsets = np.zeros(n + 1, np.int32)
    offsets[1:] = np.cumsum(degrees)
    place = np.array([int(np.prod(radices[v + 1:], dtype=np.int64)) for v in range(n)], dtype=np.int64)
    orders = tuple(np.array(cs, dtype=np.int32).reshape(len(cs), degrees[v]) for v, cs in enumerate(choices))
    positions = []
    for v, cs in enumerate(choices):
        pos = np.full((len(cs), n), -1, np.int32)
        for d, c in enumerate(cs):
            pos[d, list(c)] = np.arange(len(c))
        positions.append(pos)
    return _Tables((np.array(radices, np.int64), source, base, table), offsets, place, orders, tuple(positions),
                   int(np.prod(radices, dtype=np.int64)))


def _batch(n: int, gi: int, t: _Tables, ranks: np.ndarray, stab_offsets: np.ndarray, stab: np.ndarray) -> WorldBatch:
    radices = t.kernel[0]
    digits = (ranks[:, None] // t.place[None, :]) % radices[None, :]
    k, darts = len(ranks), int(t.offsets[-1])
    nbr = np.empty((k, darts), np.int32)
    back = np.empty((k, darts), np.int32)
    rows = np.arange(k)
    for v in range(n):
        nbr[:, t.offsets[v]:t.offsets[v + 1]] = t.orders[v][digits[:, v]]
        for w in t.orders[v][0]:
            exit_v = t.positions[v][digits[:, v], w]
            back[rows, t.offsets[v] + exit_v] = t.positions[w][digits[:, w], v]
    return WorldBatch(n, gi, ranks, digits, t.offsets, nbr, back, stab_offsets, stab)


def graph_batches(n: int, max_degree: int, gi: int, start: int = 0, step: int = 1) -> Iterator[WorldBatch]:
    """The worlds on graph ``gi`` whose rank is ``start`` modulo ``step`` (ascending), in batches."""
    t = _tables(n, max_degree, gi)
    for ranks, stab_offsets, stab in representatives(*t.kernel, start=start, step=step, stop=t.total):
        if len(ranks):
            yield _batch(n, gi, t, ranks, stab_offsets, stab)


def embedded_batches(max_vertices: int, max_degree: int, min_vertices: int = 2) -> Iterator[WorldBatch]:
    """:func:`topomark.proofs.enumerate.embedded_worlds`'s worlds, in its order, as batches."""
    check_bounds(max_vertices, max_degree)
    for n in range(max(min_vertices, 2), max_vertices + 1):
        for gi in range(len(graphs_of(n, max_degree))):
            yield from graph_batches(n, max_degree, gi)
