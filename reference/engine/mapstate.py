"""The compiled explorer's map S and its list U, as arrays (thesis §3.1.3, §3.3).

The engine's counterpart of :class:`~topomark.spec.mapstate.PartialMap` and
:class:`~topomark.spec.unexplored.Unexplored`, holding exactly what the
explorer knows: a map is a tuple ``(degree, link_v, link_e, u_v, u_e, meta, marks)``:

* ``degree[v]`` for the ``meta[NS]`` map vertices ``0 .. NS-1`` (v0 is 0);
* ``link_v[v * D + i]``, ``link_e[v * D + i]``: the reverse dart exit ``i`` of
  ``v`` is joined to, or -1 while unexplored (``D = meta[DCAP]``);
* ``u_v[k]``, ``u_e[k]`` for ``k < meta[ULEN]``: U in its order — line 3's
  exits of v0, line 28's appended at its end, entries removed where they are
  (line 5's choice, line 25's e') so the rest keep their order, as
  :class:`~topomark.spec.unexplored.Unexplored` does;
* ``meta``: the sizes, the believed pose (``PV``, ``PE``: map vertex and
  entry exit) and ``HEAD``, v0's ``marks`` (the lighthouse's, §3.3);
* ``marks[v]``: the code (:mod:`.signature`) of the marks the robot sensed at
  ``v`` when it joined S, counted from map exit 0 — v0's lighthouse (§3.3),
  and the far end of a marked edge (§6.1); 0 for a place without marks.

The capacities (vertices, degree, U) are buffer sizes the caller chooses; a
map that would outgrow them stops the run with :data:`LIMIT`.  The searches
over S (:func:`bfs`, :func:`dfs_toward`) scan exits in index order, as
:func:`~topomark.reference.explorers.policies.bfs` and ``_dfs`` do, so they
build the same trees.

Examples
--------
>>> S = new_map(4, 3, 8)
>>> start_map(S, 2, encode(1, 0, 0)), int(S[5][ULEN]), S[3][:2].tolist(), known_signature(S, 0, 1) == (2, encode(1, 1, 0))
(0, 2, [0, 0], True)
>>> u_pop(S, 1); add_vertex(S, 0, 1, 3), int(S[5][ULEN]), u_index(S, 1, 2)
(1, 3, 2)
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.signature import encode, rotate

__all__ = ["new_map", "start_map", "add_vertex", "mark_as_sensed", "join", "u_pop", "u_index", "neighbours", "known_signature", "signature_in",
           "bfs", "dfs_toward", "NS", "ULEN", "PV", "PE", "DCAP", "HEAD", "VCAP", "LIMIT"]

NS, ULEN, PV, PE, DCAP, HEAD, VCAP = range(7)
LIMIT = 4
"""The outcome code of a map that outgrew its buffers (:mod:`.algorithm31`'s codes)."""


@kernel
def new_map(vcap: int, dcap: int, ucap: int) -> tuple:
    """An empty map with room for ``vcap`` vertices of degree ≤ ``dcap`` and ``ucap`` entries of U."""
    meta = np.zeros(8, dtype=np.int64)
    meta[DCAP], meta[VCAP] = dcap, vcap
    return (np.zeros(vcap, dtype=np.int64), np.full(vcap * dcap, -1, dtype=np.int64),
            np.full(vcap * dcap, -1, dtype=np.int64), np.zeros(ucap, dtype=np.int64),
            np.zeros(ucap, dtype=np.int64), meta, np.zeros(vcap, dtype=np.int64))


@kernel
def start_map(S: tuple, degree: int, code: int) -> int:
    """S = {v0} of ``degree`` with the marks sensed there from exit 0 (``code``, the lighthouse's); U = its exits;
    believed pose (v0, 0) (lines 1–3).  Returns 0, or :data:`LIMIT`."""
    deg, lv, le, uv, ue, meta, marks = S
    if degree > meta[DCAP] or degree > uv.shape[0] or meta[VCAP] < 1:
        return LIMIT
    lv[:] = -1
    le[:] = -1
    meta[NS], meta[ULEN], meta[PV], meta[PE], meta[HEAD] = 1, degree, 0, 0, code
    marks[:] = 0
    deg[0], marks[0] = degree, code
    for i in range(degree):
        uv[i], ue[i] = 0, i
    return 0


@step
def join(S: tuple, a: int, i: int, b: int, j: int) -> None:
    """Join dart (a, i) and dart (b, j) (loop augmentation's e/e', or a new vertex's exit 0)."""
    dcap, lv, le = S[5][DCAP], S[1], S[2]
    lv[a * dcap + i], le[a * dcap + i] = b, j
    lv[b * dcap + j], le[b * dcap + j] = a, i


@kernel
def add_vertex(S: tuple, a: int, i: int, degree: int) -> int:
    """Non-loop augmentation (lines 27–28): a new vertex of ``degree`` joined to (a, i) by its exit 0, its other
    exits appended to U clockwise; returns it, or -1 when the buffers are full."""
    deg, uv, ue, meta = S[0], S[3], S[4], S[5]
    u, n = meta[NS], meta[ULEN]
    if u >= meta[VCAP] or degree > meta[DCAP] or n + degree - 1 > uv.shape[0]:
        return -1
    meta[NS] = u + 1
    deg[u] = degree
    join(S, a, i, u, 0)
    for k in range(1, degree):
        uv[n], ue[n] = u, k
        n += 1
    meta[ULEN] = n
    return u


@step
def mark_as_sensed(S: tuple, v: int, code: int) -> None:
    """Record at map vertex ``v`` the marks sensed there entered by its exit 0 (a new vertex's, lines 27–28)."""
    S[6][v] = code


@step
def u_pop(S: tuple, k: int) -> None:
    """Remove entry ``k`` of U, the others keeping their order."""
    uv, ue, meta = S[3], S[4], S[5]
    n = meta[ULEN]
    for t in range(k, n - 1):
        uv[t], ue[t] = uv[t + 1], ue[t + 1]
    meta[ULEN] = n - 1


@step
def u_index(S: tuple, v: int, i: int) -> int:
    """The index of dart (v, i) in U, or -1."""
    uv, ue = S[3], S[4]
    for k in range(S[5][ULEN]):
        if uv[k] == v and ue[k] == i:
            return k
    return -1


@step
def neighbours(S: tuple, v: int, w: int) -> bool:
    """Whether map vertices ``v`` and ``w`` are joined by an explored edge."""
    dcap = S[5][DCAP]
    for i in range(S[0][v]):
        if S[1][v * dcap + i] == w:
            return True
    return False


@step
def known_signature(S: tuple, v: int, entry: int) -> tuple:
    """What S says the robot senses at ``v`` entered by ``entry``: (degree, the code of the marks recorded there,
    counted from ``entry``)."""
    return signature_in(S[0], S[6], v, entry)


@step
def signature_in(degrees: np.ndarray, marks: np.ndarray, v: int, entry: int) -> tuple:
    """:func:`known_signature` from S's degrees and marks, for a loop that binds them once."""
    return degrees[v], rotate(marks[v], degrees[v], entry)


@kernel
def bfs(S: tuple, root: int, dist: np.ndarray, toward: np.ndarray, parent_v: np.ndarray, parent_e: np.ndarray,
        queue: np.ndarray) -> None:
    """Breadth-first over S's explored edges from ``root``, exits in index order: each reached vertex's distance
    (-1: not reached), the exit leading one step back toward ``root`` and the parent dart it was reached by."""
    deg, lv, le, meta = S[0], S[1], S[2], S[5]
    ns, dcap = meta[NS], meta[DCAP]
    dist[:ns] = -1
    dist[root], queue[0] = 0, root
    head, tail = 0, 1
    while head < tail and tail < ns:
        v = queue[head]
        head += 1
        for i in range(deg[v]):
            w = lv[v * dcap + i]
            if w >= 0 and dist[w] < 0:
                dist[w], toward[w] = dist[v] + 1, le[v * dcap + i]
                parent_v[w], parent_e[w] = v, i
                queue[tail] = w
                tail += 1


@kernel
def dfs_toward(S: tuple, root: int, toward: np.ndarray, seen: np.ndarray, stack_v: np.ndarray,
               stack_i: np.ndarray) -> None:
    """The depth-first tree of S from ``root`` (the path policy ``dfs``): for each vertex the exit leading one
    step back toward ``root``, by the same stack walk as the reference's."""
    deg, lv, le, meta = S[0], S[1], S[2], S[5]
    dcap = meta[DCAP]
    seen[:meta[NS]] = 0
    seen[root] = 1
    stack_v[0], stack_i[0] = root, 0
    top = 1
    while top > 0:
        top -= 1
        v, i = stack_v[top], stack_i[top]
        if i >= deg[v]:
            continue
        stack_i[top] = i + 1
        top += 1
        w = lv[v * dcap + i]
        if w >= 0 and seen[w] == 0:
            seen[w], toward[w] = 1, le[v * dcap + i]
            stack_v[top], stack_i[top] = w, 0
            top += 1
