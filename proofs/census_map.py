"""The census's map: languages of every placement on a slice of the worlds (thesis §3.2, §3.3, §3.7, §6.1).

A *unit* is ``(n, gi, c, C)``: the rotation systems of graph ``gi`` of
:func:`topomark.proofs.enumerate.connected_graphs` (n, D) whose *rank* — index
in the product order of :func:`topomark.proofs.enumerate.rotation_systems` —
is ``c`` modulo ``C``, of which the unit keeps the orbit representatives (the
least system of each Aut-orbit, decided from the system alone, so a graph
with many rotation systems splits into independent units).  A world is named
by ``(n, gi, rank)``; at fixed n that order is the enumeration's order.
:func:`plan` groups units into map tasks of about ``task_worlds`` worlds,
estimated as ``∏ (deg v - 1)! / |Aut|`` per graph (exact when the
automorphism group acts freely; only used for balancing and the progress bar).

:func:`run_map` computes, for every world of a task, every placement's
language digest (the kernel of :mod:`topomark.proofs.census`), combines the
records per digest (:func:`topomark.proofs.census_shards.combine`), and
writes one file per shard, then the task's ``done`` file.

The iso key of a placement (equal iff the marked worlds are extended-
isomorphic, markers preserved) is computed from the world's automorphisms,
not from :func:`topomark.proofs.enumerate.canonical_form` as the in-memory
census does: two placements on different worlds of the enumeration are never
isomorphic (the worlds are pairwise non-isomorphic), and two on the same
world ``W`` are iff an automorphism of ``W`` maps one layout onto the other
(an isomorphism of marked worlds on W is an automorphism of W preserving the
markers; §3.1.3, mirror images excluded).  The automorphisms of W are the
graph automorphisms fixing its rotation system.  ``tests/test_census_shards.py``
compares the two censuses, so the two iso keys are checked against each other.

Examples
--------
>>> units = [u for t in plan(4, 3, 2, task_worlds=5) for u, _ in t]
>>> sorted(units)[:3]
[(2, 0, 0, 1), (3, 0, 0, 1), (3, 1, 0, 1)]
>>> [rank for rank, _, _ in unit_worlds((4, 5, 0, 1), 3)]  # K4: 16 rotation systems, 3 worlds
[0, 1, 5]
"""

from __future__ import annotations

import hashlib
import math
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterator

import networkx as nx
import numpy as np

from topomark.proofs.census import machine, marker_key, marker_layouts, minimise
from topomark.proofs.census_compiled import batch_records
from topomark.proofs.census_language import start_digests
from topomark.proofs.census_integrity import code_version
from topomark.proofs.census_shards import (combine, digest, done_path, map_path, records, seal, shard_of, write_atomic,
                                           write_json)
from topomark.proofs.enumerate import world_of_rotation
from topomark.proofs.world_batches import WorldBatch, graph_batches
from topomark.proofs.world_batches import automorphisms_of as _autos
from topomark.proofs.world_batches import graph_data as _graph_data
from topomark.proofs.world_batches import graphs_of as _graphs
from topomark.spec.world import DartMark, World

__all__ = ["Unit", "plan", "estimate", "rotation_count", "map_task", "run_map", "unit_arrays", "unit_worlds",
           "unit_rotations", "automorphism_images", "world_at", "world_records", "marked"]

Unit = tuple[int, int, int, int]  # (n, graph index, c, C): the ranks c, c + C, c + 2C, ...


def estimate(g: nx.Graph, autos: int) -> int:
    """About how many worlds graph ``g`` carries: rotation systems over automorphisms (at least 1)."""
    rots = math.prod(math.factorial(d - 1) for _, d in g.degree())
    return max(1, -(-rots // autos))


def plan(max_vertices: int, max_degree: int, min_vertices: int = 2,
         task_worlds: int = 2000) -> list[list[tuple[Unit, int]]]:
    """Map tasks: lists of ``(unit, estimated worlds)`` of about ``task_worlds`` worlds each."""
    tasks: list[list[tuple[Unit, int]]] = []
    current: list[tuple[Unit, int]] = []
    size = 0
    for n in range(max(min_vertices, 2), max_vertices + 1):
        for gi, g in enumerate(_graphs(n, max_degree)):
            est = estimate(g, len(_autos(n, max_degree, gi)))
            chunks = -(-est // task_worlds)
            for c in range(chunks):
                share = est // chunks + (c < est % chunks)
                current.append(((n, gi, c, chunks), share))
                size += share
                if size >= task_worlds:
                    tasks.append(current)
                    current, size = [], 0
    if current:
        tasks.append(current)
    return tasks


def rotation_count(n: int, max_degree: int, gi: int) -> int:
    """The number of rotation systems of graph ``gi``: ranks run over ``range(rotation_count(...))``."""
    return math.prod(_graph_data(n, max_degree, gi)[1])


def _digits(rank: int, radices: list[int]) -> list[int]:
    """Mixed-radix digits of ``rank``, vertex 0 most significant (product order)."""
    digits = [0] * len(radices)
    for v in range(len(radices) - 1, -1, -1):
        rank, digits[v] = divmod(rank, radices[v])
    return digits


def unit_arrays(unit: Unit, max_degree: int) -> Iterator[WorldBatch]:
    """The unit's orbit representatives as batches of world arrays (:mod:`topomark.proofs.world_batches`),
    ascending by rank: the worlds :func:`unit_worlds` lists, without a World object per world."""
    n, gi, c, step = unit
    return graph_batches(n, max_degree, gi, c, step)


def unit_worlds(unit: Unit, max_degree: int) -> Iterator[tuple[int, World, tuple[dict[int, int], ...]]]:
    """(rank, world, automorphisms of the world) for the orbit representatives of the unit's ranks.

    A representative is the least rotation system of its Aut-orbit in
    product order, the one :func:`topomark.proofs.enumerate.embedded_worlds`
    lists; deciding it needs only the system itself
    (:mod:`topomark.proofs.orbit_kernel`), so a graph's ranks split into
    units that run anywhere — by residue, not by range, because the
    representatives crowd at small ranks (``tests/test_census_shards.py``
    checks the representatives against ``enumerate._orbit_representatives``).
    The automorphisms of the world (those of the graph fixing its rotation
    system) come in :func:`~topomark.proofs.world_batches.graph_data`'s
    order, the identity first.
    """
    for rank, rot, fixing in unit_rotations(unit, max_degree):
        yield rank, world_of_rotation(rot), fixing


def unit_rotations(unit: Unit, max_degree: int) -> Iterator[tuple[int, tuple[tuple[int, ...], ...],
                                                                  tuple[dict[int, int], ...]]]:
    """:func:`unit_worlds` with each world as its rotation system (vertex v's neighbours in clockwise order)."""
    n, gi = unit[0], unit[1]
    choices, _, actions = _graph_data(n, max_degree, gi)
    for batch in unit_arrays(unit, max_degree):
        for i, digits in enumerate(batch.digits.tolist()):
            yield (int(batch.ranks[i]), tuple(choices[v][d] for v, d in enumerate(digits)),
                   tuple(actions[a][0] for a in batch.stabiliser(i).tolist()))


@lru_cache(maxsize=64)
def automorphism_images(n: int, max_degree: int, gi: int) -> np.ndarray:
    """Graph ``gi``'s automorphisms as rows of vertex images, in :func:`~topomark.proofs.world_batches.graph_data`'s
    order (the identity first): a batch's stabiliser indices select the world's automorphisms from it."""
    images = np.array([[sigma[k] for k in range(n)] for sigma, _ in _graph_data(n, max_degree, gi)[2]], np.int32)
    assert (images[0] == np.arange(n)).all(), "graph_data lists the identity first"
    return images


def world_at(n: int, max_degree: int, gi: int, rank: int) -> World:
    """The world a record names: the rotation system of rank ``rank`` of graph ``gi``."""
    choices, radices, _ = _graph_data(n, max_degree, gi)
    return world_of_rotation(tuple(choices[v][d] for v, d in enumerate(_digits(rank, radices))))


def _layout_code(key: frozenset, sigma: dict[int, int]) -> tuple:
    """A layout (``census.marker_key``) moved by a vertex permutation, as a sorted tuple of ints."""
    def f(name: str | None) -> int:
        return -1 if name is None else sigma[int(name[1:])]

    items: list[tuple[int, ...]] = []
    for item in key:
        if isinstance(item[0], str):
            at, count, points_to = item
            items.append((0, f(at), count, f(points_to)))
        else:
            between, count, head = item
            u, v = sorted(f(x) for x in between)
            items.append((1, u, v, count, f(head)))
    return tuple(sorted(items))


def _iso_key(world_id: tuple[int, int, int], key: frozenset, autos: tuple[dict[int, int], ...]) -> bytes:
    code = min(_layout_code(key, s) for s in autos)
    return hashlib.blake2b(repr((world_id, code)).encode(), digest_size=16).digest()


def marked(world: World, markers: tuple) -> World:
    """``World(world.rotation, markers)`` without re-validating the rotation system of an enumerated world.

    The marks are derived by World's own ``_add_marker`` (the marks at v are
    defined once, in spec); ``tests/test_census_shards.py`` checks every
    signature against the validated construction.
    """
    w = object.__new__(World)
    w.rotation, w.markers, w.start, w._index = world.rotation, tuple(markers), None, world._index
    w._vmarks = {}
    dmarks: dict[str, list[DartMark]] = {}
    for marker in w.markers:
        w._add_marker(marker, dmarks)
    w._dmarks = {v: tuple(sorted(ms, key=lambda d: d.exit)) for v, ms in dmarks.items()}
    return w


def world_records(class_name: str, world_id: tuple[int, int, int], world: World, autos: tuple[dict[int, int], ...],
                  rows: list[tuple[bytes, int, tuple, bytes]]) -> int:
    """Append ``(digest, 1 << n, (n, m, gi, ri, k), iso)`` for every placement on ``world`` to ``rows``
    (equivalent starts of one layout once: same language, larger member); returns the number of placements."""
    n, gi, ri = world_id
    base = machine(world)
    cache: dict[frozenset, tuple] = {}
    placements = 0
    for k, markers, starts in marker_layouts(class_name, world):
        placements += len(starts)
        key = marker_key(markers)
        if key not in cache:
            mach = machine(marked(world, markers), base) if markers else base
            block = minimise(mach)
            cache[key] = (mach, block, _iso_key(world_id, key, autos), set())
        mach, block, iso, seen = cache[key]
        index = [mach.index[s] for s in starts]
        digests = start_digests(mach, block, index)
        for j, s in enumerate(index):
            b = block[s]
            if b not in seen:
                seen.add(b)
                rows.append((digests[b], 1 << n, (n, world.m, gi, ri, k + j), iso))
    return placements


def map_task(task: int, class_name: str, max_degree: int, units: list[Unit], shards: int,
             census: str = "", engine: str = "reference") -> tuple[bytes, dict[str, Any]]:
    """Map task ``task`` of census ``census`` (the manifest's checksum) computed, nothing written: its data
    file's bytes and its sealed ``done`` record (``{"sizes": {n: [worlds, placements]}, "offsets": shard
    boundaries in the data}``, with the data's size and checksum, :mod:`topomark.proofs.census_integrity`).

    ``engine`` is ``"reference"`` (:func:`world_records`) or ``"compiled"``
    (:mod:`topomark.proofs.census_compiled`, as ``resolve_engine`` chose it): the records are the same."""
    rows: list[tuple] = []
    compiled: list[np.ndarray] = []
    sizes: dict[int, list[int]] = {}
    for unit in units:
        n, gi = unit[0], unit[1]
        tally = sizes.setdefault(n, [0, 0])
        if engine == "compiled":
            recs, worlds, placements = batch_records(class_name, max_degree, unit_arrays(unit, max_degree),
                                                     automorphism_images(n, max_degree, gi))
            compiled.append(recs)
            tally[0] += worlds
            tally[1] += placements
            continue
        for ri, world, autos in unit_worlds(unit, max_degree):
            tally[0] += 1
            tally[1] += world_records(class_name, (n, gi, ri), world, autos, rows)
    recs = combine(np.concatenate([records(rows), *compiled]))
    where = shard_of(recs, shards)
    order = np.argsort(where, kind="stable")
    bounds = np.searchsorted(where[order], np.arange(shards + 1))
    data = recs[order].tobytes()
    return data, seal({"sizes": {str(n): v for n, v in sizes.items()}, "offsets": [int(b) for b in bounds],
                       "records": len(recs), "bytes": len(data), "data": digest(data), "census": census,
                       "task": task, "code": code_version()})


def run_map(root: str, task: int, class_name: str, max_degree: int, units: list[Unit],
            shards: int, census: str = "", engine: str = "reference") -> dict[str, Any]:
    """Run map task ``task`` (:func:`map_task`) into directory ``root``: the data file, then the ``done``
    record, which it returns."""
    data, result = map_task(task, class_name, max_degree, units, shards, census, engine)
    path = Path(root)
    write_atomic(map_path(path, task), data)
    write_json(done_path(path, task), result)
    return result
