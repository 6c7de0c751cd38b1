"""The orbit-least rotation systems of one graph, compiled where numba is installed (thesis §3.1.1, §3.1.3).

A world up to extended isomorphism is a connected graph G with one rotation
system per orbit of Aut(G) (:mod:`topomark.proofs.enumerate`); the
representative of an orbit is its least system in *product order*, the order
of the systems' *ranks* (mixed-radix numbers whose digit ``d_v`` is the index
of vertex v's cyclic order among its ``(deg v - 1)!``, vertex 0 most
significant).  A system is the least of its orbit iff no automorphism σ maps
it to a smaller one, which is decided from the system alone by comparing the
image's digits with its own, vertex by vertex, stopping at the first
difference; the automorphisms whose image is equal are its stabiliser.

:func:`scan` is that decision over the ranks ``rank, rank + step, …`` below
``stop``, written once as plain Python over flat integer sequences:

* ``radices[v]`` — vertex v's number of cyclic orders;
* ``source[a·n + u]`` — ``σ_a⁻¹(u)`` for the graph's automorphisms ``σ_a``
  (the identity among them);
* ``base[u]`` — where vertex u's choices start in a row of ``table``
  (``base[u] = radices[0] + … + radices[u-1]``, a row being ``W`` long);
* ``table[a·W + base[u] + d]`` — the index, among u's cyclic orders, of
  ``σ_a`` applied to cyclic order ``d`` of ``σ_a⁻¹(u)``.

:func:`kernel` gives it compiled by numba (``njit``, cached on disk) when
numba imports, and otherwise the same function uncompiled, which is then fed
Python lists (fast to index) instead of arrays: one source, so the two give
the same output (tests/test_orbit_kernel.py runs both on the same graphs).
:func:`representatives` drives it in chunks and returns numpy arrays.

Examples
--------
The triangle: one cyclic order per vertex, six automorphisms, one world (rank 0) fixed by all six:

>>> import numpy as np
>>> t = (np.array([1, 1, 1]), np.array([0, 1, 2, 1, 0, 2, 2, 1, 0, 0, 2, 1, 1, 2, 0, 2, 0, 1]), np.array([0, 1, 2]),
...      np.zeros(18, dtype=np.int64))
>>> [a.tolist() for a in next(representatives(*t, start=0, step=1, stop=1))]
[[0], [0, 6], [0, 1, 2, 3, 4, 5]]
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Callable, Iterator

import numpy as np

__all__ = ["scan", "kernel", "compiled", "representatives", "CHUNK"]

CHUNK = 1 << 15
"""Ranks decided per call into the kernel: bounds the output buffers (about 1 MB)."""


def scan(radices: Any, source: Any, base: Any, table: Any, rank: int, step: int, stop: int, digits: Any,
         ranks: Any, counts: Any, stab: Any) -> tuple[int, int, int]:
    """Decide ranks ``rank, rank + step, …`` (below ``stop``) until an output buffer is full.

    Writes each orbit-least rank to ``ranks[k]``, its stabiliser's size to
    ``counts[k]`` and the stabiliser (automorphism indices, ascending) to
    ``stab``; returns ``(next rank to decide, representatives written,
    stabiliser entries written)``.  ``digits`` is scratch of length n.
    """
    n = len(radices)
    autos = len(source) // n
    width = len(table) // autos
    k = 0
    s = 0
    while rank < stop and k < len(ranks) and s + autos <= len(stab):
        r = rank
        for v in range(n - 1, -1, -1):
            digits[v] = r % radices[v]
            r //= radices[v]
        least = True
        first = s
        for a in range(autos):
            verdict = 0
            for u in range(n):
                image = table[a * width + base[u] + digits[source[a * n + u]]]
                if image != digits[u]:
                    verdict = -1 if image < digits[u] else 1
                    break
            if verdict < 0:
                least = False
                break
            if verdict == 0:
                stab[s] = a
                s += 1
        if least:
            ranks[k] = rank
            counts[k] = s - first
            k += 1
        else:
            s = first
        rank += step
    return rank, k, s


@lru_cache(maxsize=None)
def compiled() -> Callable[..., tuple[int, int, int]] | None:
    """:func:`scan` compiled by numba, or None when numba is not installed."""
    try:
        import numba
    except ImportError:
        return None
    try:  # compiled once per machine, kept beside the module or in the user's cache directory
        jitted: Callable[..., tuple[int, int, int]] = numba.njit(cache=True, nogil=True)(scan)
    except RuntimeError:  # no writable place for numba's cache: compile in every process instead
        jitted = numba.njit(nogil=True)(scan)
    return jitted


def kernel() -> tuple[Callable[..., tuple[int, int, int]], bool]:
    """The kernel to run and whether it is compiled (else it takes Python lists)."""
    fast = compiled()
    return (scan, False) if fast is None else (fast, True)


def representatives(radices: np.ndarray, source: np.ndarray, base: np.ndarray, table: np.ndarray, start: int,
                    step: int, stop: int, chunk: int = CHUNK,
                    use: tuple[Callable[..., tuple[int, int, int]], bool] | None = None
                    ) -> Iterator[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Chunks ``(ranks, stabiliser offsets, stabiliser indices)`` of the orbit-least ranks among
    ``start, start + step, …`` below ``stop``, ascending; ``use`` picks a kernel (default :func:`kernel`)."""
    run, is_compiled = kernel() if use is None else use
    autos = len(source) // len(radices)
    args = [a.astype(np.int64) for a in (radices, source, base, table)]
    if not is_compiled:
        args = [a.tolist() for a in args]
    rank = start
    while rank < stop:
        buffers: list[Any] = [np.empty(chunk, np.int64), np.empty(chunk, np.int64), np.empty(2 * chunk + autos, np.int64)]
        scratch: Any = np.empty(len(radices), np.int64)
        if not is_compiled:
            buffers, scratch = [b.tolist() for b in buffers], scratch.tolist()
        rank, k, s = run(*args, rank, step, stop, scratch, *buffers)
        ranks, counts, stab = (np.asarray(b, dtype=np.int64) for b in buffers)
        offsets = np.zeros(k + 1, np.int64)
        np.cumsum(counts[:k], out=offsets[1:])
        yield ranks[:k], offsets, stab[:s]
