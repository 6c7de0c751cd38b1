"""The robot's Moore machine on world arrays and its Moore equivalence, compiled (thesis §3.1.1, §3.2).

The machine part of :mod:`topomark.proofs.census_kernel`, on a world given as
arrays (:mod:`topomark.proofs.world_arrays`):

* state ``s = offsets[v] + entry`` is robot state ``(v, entry)``, the order of
  ``World.darts``; motion ``l`` leaves through exit ``(entry + l) mod deg``
  (:func:`topomark.spec.robot.step`): :func:`machine_arrays`;
* a vertex marker's output as a small int, :func:`output_id`, standing for
  the text ``str(Signature(deg, count, direction))`` of
  :mod:`topomark.spec.signature`; :func:`signature_table` builds the texts
  from the spec and their ranks in text order;
* Moore equivalence by partition refinement (:func:`refine`), blocks numbered
  by first occurrence as :func:`topomark.proofs.census.minimise` numbers them.

Without numba (:data:`COMPILED` false) the same functions run as Python.

Examples
--------
>>> import numpy as np
>>> offsets, nbr = np.array([0, 2, 4, 6], np.int32), np.array([1, 2, 2, 0, 0, 1], np.int32)
>>> succ, deg = machine_arrays(offsets, nbr, back_of(offsets, nbr), 2)
>>> succ.tolist()  # the triangle: from (v0, 0) motion 1 reaches (v2, 0), state 4
[[3, 4], [4, 3], [5, 0], [0, 5], [1, 2], [2, 1]]
>>> marks = np.array([[0, 1, -1]], np.int32)  # an undirected marker at v0
>>> block, rep, count = refine(outputs(offsets, marks, 1, 3), succ, deg)
>>> block.tolist(), count
([0, 0, 1, 2, 2, 1], 3)
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Callable

import numpy as np

from topomark.spec.signature import Signature

try:
    from numba import njit
    COMPILED = True
    """Whether numba compiles the kernel here (without it the same functions run as Python, slowly)."""
except ImportError:  # numba is not installed, or not for this platform
    COMPILED = False

    def njit(*args: Any, **kwargs: Any) -> Callable[[Callable[..., Any]], Callable[..., Any]]:  # type: ignore[no-redef]
        return lambda f: f


def output_id(degree: int, count: int, direction: int, max_degree: int) -> int:
    """The small int standing for ``Signature(degree, count, direction or None)`` (direction -1: none)."""
    return (degree * 4 + count) * (max_degree + 1) + direction + 1


@lru_cache(maxsize=16)
def signature_table(max_degree: int) -> tuple[tuple[np.ndarray, np.ndarray], np.ndarray]:
    """``((text bytes, offsets), rank)`` of every output id up to ``max_degree``: the signature's text
    (:class:`~topomark.spec.signature.Signature`, UTF-8) and its rank in text order (ids that stand for no
    signature: empty text, rank -1)."""
    size = output_id(max_degree, 3, max_degree - 1, max_degree) + 1
    texts = [b""] * size
    for d in range(1, max_degree + 1):
        for count in range(3):
            for direction in ([-1] if count == 0 else range(-1, d)):
                sig = Signature(d, count, None if direction < 0 else direction)
                texts[output_id(d, count, direction, max_degree)] = str(sig).encode()
    rank = np.full(size, -1, np.int32)
    real = sorted((t, i) for i, t in enumerate(texts) if t)
    for r, (_, i) in enumerate(real):
        rank[i] = r
    offsets = np.zeros(size + 1, np.int32)
    offsets[1:] = np.cumsum([len(t) for t in texts])
    return (np.frombuffer(b"".join(texts), np.uint8).copy(), offsets), rank

@njit(cache=True)
def machine_arrays(offsets, nbr, back, dmax):  # pragma: no cover - compiled
    """Successor table ``succ[s, l]`` and degree of every state (spec/robot.py ``step``)."""
    n = offsets.size - 1
    size = offsets[n]
    succ = np.zeros((size, dmax), np.int32)
    deg = np.empty(size, np.int32)
    for v in range(n):
        d = offsets[v + 1] - offsets[v]
        for e in range(d):
            s = offsets[v] + e
            deg[s] = d
            for motion in range(d):
                x = offsets[v] + (e + motion) % d
                succ[s, motion] = offsets[nbr[x]] + back[x]
    return succ, deg


@njit(cache=True)
def outputs(offsets, marks, nmarks, width):  # pragma: no cover - compiled
    """The output id of every state of the world carrying ``marks[:nmarks]`` = (vertex, count, head exit)."""
    n = offsets.size - 1
    out = np.empty(offsets[n], np.int32)
    for v in range(n):
        d = offsets[v + 1] - offsets[v]
        count, head = 0, -1
        for r in range(nmarks):
            if marks[r, 0] == v:
                count, head = marks[r, 1], marks[r, 2]
        for e in range(d):
            direction = -1 if head < 0 else (head - e) % d
            out[offsets[v] + e] = (d * 4 + count) * width + direction + 1
    return out


@njit(cache=True)
def _number(keys, width, block, rep, table):  # pragma: no cover - compiled
    """Blocks of equal key rows ``keys[s, :width]``, numbered by first occurrence; returns their count."""
    size = keys.shape[0]
    mask = table.size - 1
    table[:] = -1
    count = 0
    for s in range(size):
        h = 0
        for j in range(width):
            h = h * 1000003 + keys[s, j] + 2  # int64, wrapping: only a slot to start probing from
        slot = (h ^ (h >> 17)) & mask
        while True:
            b = table[slot]
            if b < 0:
                table[slot] = count
                rep[count] = s
                block[s] = count
                count += 1
                break
            r = rep[b]
            same = True
            for j in range(width):
                if keys[r, j] != keys[s, j]:
                    same = False
                    break
            if same:
                block[s] = b
                break
            slot = (slot + 1) & mask
    return count


@njit(cache=True)
def refine(out, succ, deg):  # pragma: no cover - compiled
    """Moore equivalence (``census.minimise``): ``(block, representative of each block, block count)``."""
    size, dmax = succ.shape
    keys = np.full((size, dmax + 1), -1, np.int64)
    keys[:, 0] = out
    block = np.empty(size, np.int32)
    rep = np.empty(size, np.int32)
    tsize = 4
    while tsize < 2 * size:
        tsize *= 2
    table = np.empty(tsize, np.int32)
    count = _number(keys, 1, block, rep, table)
    while True:
        for s in range(size):
            keys[s, 0] = block[s]
            for motion in range(deg[s]):
                keys[s, motion + 1] = block[succ[s, motion]]
        new = _number(keys, dmax + 1, block, rep, table)
        if new == count:
            return block, rep, count
        count = new

@njit(cache=True)
def back_of(offsets, nbr):  # pragma: no cover - compiled
    """``back`` of :mod:`topomark.proofs.world_arrays` (``back_links``), compiled: the entry of every dart."""
    back = np.empty(nbr.size, np.int32)
    for k in range(offsets.size - 1):
        for x in range(offsets[k], offsets[k + 1]):
            w = nbr[x]
            for y in range(offsets[w], offsets[w + 1]):
                if nbr[y] == k:
                    back[x] = y - offsets[w]
    return back

