"""The census's compiled engine: the map's records from the compiled kernel (thesis §3.2, §3.3, §3.7).

``topomark census --engine {reference,compiled,auto}`` chooses how a map task
computes its records: ``reference`` with
:func:`topomark.proofs.census_map.world_records` (Python; the definition),
``compiled`` with :func:`topomark.proofs.census_kernel.world_codes` (numba),
``auto`` (the default) the compiled engine wherever it applies.  Both write
the same records — same language digests, members and iso keys — so the
shards of either are the other's (``tests/test_census_kernel.py`` compares
them on every world of n ≤ 6, D ≤ 4 and whole sharded censuses).  The
kernel covers the marker classes with vertex markers only
(:data:`~topomark.proofs.census_kernel.CLASS_CODES`); ``auto`` runs the
others, and every class when numba is not installed, on the reference engine
(the latter with a one-line notice); ``compiled`` refuses them (exit 2).

The kernel hashes as the reference does (the least anchored code's BLAKE2b
head and every start's digest as
:func:`~topomark.proofs.census_language.start_digests` does, the iso key as
``census_map._iso_key`` does; :mod:`topomark.proofs.blake2b_compiled`); this
module turns its digests into records.  :func:`arrays_records` takes a world
as arrays, so an enumerator that yields arrays plugs in without building a
:class:`~topomark.spec.world.World`; :func:`batch_records`, which the census
map runs, takes the enumeration's batches (:mod:`topomark.proofs.world_batches`)
as they come, one compiled call per batch.

Examples
--------
>>> resolve_engine("reference", "directional-vertex")
'reference'
>>> resolve_engine("auto", "directional-edge")  # edge markers: the reference engine
'reference'
"""

from __future__ import annotations

from typing import Any, Callable, Iterable

import numpy as np

from topomark.proofs import census_kernel as _kernel
from topomark.proofs import census_moore as _moore
from topomark.proofs.census_shards import RECORD
from topomark.proofs.world_batches import WorldBatch, graph_batches
from topomark.spec.errors import InvalidInput

__all__ = ["ENGINES", "available", "resolve_engine", "arrays_records", "batch_records", "rotation_records",
           "warm_up"]

ENGINES = ("reference", "compiled", "auto")



def available() -> bool:
    """Whether numba compiles the kernel here."""
    return _moore.COMPILED


def resolve_engine(engine: str, class_name: str, note: Callable[[str], None] | None = None) -> str:
    """``"reference"`` or ``"compiled"``: the engine ``engine`` runs ``class_name``'s census on.

    An unknown engine, or ``compiled`` where it cannot run, is :class:`InvalidInput`; ``auto`` without numba
    says so once through ``note``.
    """
    if engine not in ENGINES:
        raise InvalidInput(f"unknown census engine {engine!r}; known: {', '.join(ENGINES)}")
    if engine == "reference":
        return engine
    if class_name not in _kernel.CLASS_CODES:
        if engine == "compiled":
            raise InvalidInput(f"the compiled census engine covers the vertex-marker classes "
                               f"({', '.join(_kernel.CLASS_CODES)}), not {class_name!r}; use --engine reference")
        return "reference"
    if not available():
        if engine == "compiled":
            raise InvalidInput("the compiled census engine needs numba, which is not installed; "
                               "use --engine reference (same results, slower)")
        if note is not None:
            note("census: numba is not installed; running the reference engine (same results, slower)")
        return "reference"
    return "compiled"


def arrays_records(class_name: str, world_id: tuple[int, int, int], offsets: np.ndarray, nbr: np.ndarray,
                   back: np.ndarray, autos: np.ndarray, max_degree: int) -> tuple[np.ndarray, int]:
    """``census_map.world_records`` on a world given as arrays (vertex k named ``v{k}``) with its automorphisms
    as rows of vertex images (the identity first): its records (:data:`~topomark.proofs.census_shards.RECORD`,
    in the reference's order) and its placements."""
    digests, placements = _digests(class_name, world_id, offsets, nbr, back, autos, max_degree)
    return _records([(digests, len(offsets) - 1, len(nbr) // 2, world_id[1], world_id[2])]), placements


def _digests(class_name: str, world_id: tuple[int, int, int], offsets: np.ndarray, nbr: np.ndarray,
             back: np.ndarray, autos: np.ndarray, max_degree: int) -> tuple[np.ndarray, int]:
    texts, rank = _moore.signature_table(max_degree)
    digests, placements = _kernel.world_digests(offsets, nbr, back, _kernel.CLASS_CODES[class_name], autos,
                                                max_degree, texts, rank, np.array(world_id, np.int64))
    return digests, int(placements)


def _records(parts: list[tuple[np.ndarray, int, int, int, int]]) -> np.ndarray:
    """One record array of ``(digests (R, 5), n, m, gi, ri)`` per world: (d0, d1, k, i0, i1) and the world."""
    if not parts:
        return np.zeros(0, RECORD)
    counts = [len(p[0]) for p in parts]
    n, m, gi, ri = (np.repeat([p[j] for p in parts], counts) for j in range(1, 5))
    return _fill(np.concatenate([p[0] for p in parts]), n, m, gi, ri)


def _fill(digests: np.ndarray, n: Any, m: Any, gi: Any, ri: Any) -> np.ndarray:
    """Records of kernel rows ``digests`` ((R, 5): d0, d1, k, i0, i1) on worlds ``(n, m, gi, ri)`` (each one
    value, or one per row)."""
    out = np.zeros(len(digests), RECORD)
    for j, name in enumerate(("d0", "d1", "k", "i0", "i1")):
        out[name] = digests[:, j]
    out["n"], out["m"], out["gi"], out["ri"] = n, m, gi, ri
    out["mask"] = np.uint32(1) << out["n"].astype(np.uint32)
    return out


def batch_records(class_name: str, max_degree: int, batches: Iterable[WorldBatch], images: np.ndarray
                  ) -> tuple[np.ndarray, int, int]:
    """:func:`arrays_records` for every world of ``batches`` (one graph's, ``census_map.unit_arrays``), read
    from the batch arrays as they are; ``images[a]`` is automorphism ``a`` of the graph as vertex images (the
    stabiliser's indices point into it, the identity first).  Returns ``(records, worlds, placements)``."""
    texts, rank = _moore.signature_table(max_degree)
    code = _kernel.CLASS_CODES[class_name]
    out = []
    worlds = placements = 0
    for b in batches:
        digests, counts, placed = _kernel.batch_digests(b.offsets, b.nbr, b.back, code, images, b.stab_offsets,
                                                        b.stab, max_degree, texts, rank, b.n, b.gi, b.ranks)
        out.append(_fill(digests, b.n, b.nbr.shape[1] // 2, b.gi, np.repeat(b.ranks, counts)))
        worlds += len(b)
        placements += int(placed)
    return (np.concatenate(out) if out else np.zeros(0, RECORD)), worlds, placements


def rotation_records(class_name: str, n: int, gi: int, max_degree: int,
                     worlds: Iterable[tuple[int, tuple[tuple[int, ...], ...], tuple[dict[int, int], ...]]]
                     ) -> tuple[np.ndarray, int, int]:
    """:func:`arrays_records` for ``(rank, rotation system, automorphisms)`` of graph ``gi``
    (``census_map.unit_rotations``); returns ``(records, worlds, placements)``."""
    parts = []
    placements = 0
    offsets = np.zeros(n + 1, np.int32)
    for rank, rot, autos in worlds:
        offsets[1:] = np.cumsum([len(ns) for ns in rot])
        nbr = np.fromiter((w for ns in rot for w in ns), np.int32, int(offsets[-1]))
        sigma = np.array([[s[k] for k in range(n)] for s in autos], np.int32)
        digests, count = _digests(class_name, (n, gi, rank), offsets, nbr, _moore.back_of(offsets, nbr), sigma,
                                  max_degree)
        parts.append((digests, n, len(nbr) // 2, gi, rank))
        placements += count
    return _records(parts), len(parts), placements


def warm_up() -> None:
    """Compile the kernel (or load it from numba's cache) by running it on the one-edge world."""
    rotation_records("directional-vertex", 2, 0, 1, [(0, ((1,), (0,)), ({0: 0, 1: 1},))])
    batch_records("directional-vertex", 1, graph_batches(2, 1, 0), np.arange(2, dtype=np.int32).reshape(1, 2))
