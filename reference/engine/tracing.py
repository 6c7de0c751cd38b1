"""Rejecting hypotheses without motion: stage 1 and tracing on S and T (thesis §4.1–4.3, Algorithms 4.1–4.3).

After each mismatch of a validation walk, the engine's Enhancement 1–3 kernels
(:mod:`.enhanced`) reject the remaining hypotheses the execution trie already
contradicts: stage 1 compares the executed paths overlapping a hypothesis's M
with its P^E (Algorithm 4.1 lines 16–20); tracing maps every executed path
onto S from the hypothesis's dart, the hypothesized edge included, and
compares each place it maps onto (Algorithm 4.2 lines 16–20), continuing into
the records of T beyond unexplored darts (Algorithm 4.3 lines 16–24).

Rejection is incremental, as the reference's is.  Within an iteration S, T
and the trie's old nodes do not change, so a hypothesis that agreed with the
trie at the last check can only be contradicted by a node added since; one
attempt adds its new nodes as one chain ending where the robot stopped
(:func:`to_check`).  So a check follows the path from v_u to that node and
compares only the new nodes on it: stage 1 through the hypothesis trie
(:func:`~.hypothesis_trie.overlapping`), tracing from the depth where this
path and the last one part, each hypothesis's state there kept from the last
check (the *trace cache*: the dart of S reached at each depth, kept while no
record of T is reached).  When the nodes to check are not one path (the first
check of an iteration, after T's records and the expansion were grafted),
every node is compared.  A hypothesis found contradicted is ``MARKED`` in the
hypothesis trie; :mod:`.enhanced` then takes the marked ones out of H.

Every array is bound once per check, not once per hypothesis: numba counts a
reference each time an array is taken out of a tuple, and at n = 200 those
counts, not the comparisons, were most of a run.

The validation buffers ``X`` are a tuple of arrays: M, P^E (degree, code),
each hypothesis's offset into them and its arrival entry at v0, the remaining
hypotheses, the trace (dart, entry, records) per trie node, the robot's path,
the record pool, the nodes to check, and the trace cache (dart and entry per
hypothesis and depth, the depth kept to, the path it followed).
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.algorithm31 import H_E, H_V
from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.hypothesis_trie import MARKED, REMAINING, STATE
from topomark.reference.engine.mapstate import DCAP, signature_in
from topomark.reference.engine.records import R_AT, R_CODE, R_DEGREE, R_FIRST, R_MOTION, R_NEXT, child_in
from topomark.reference.engine.trie import CODE, COUNT, DEGREE, DEPTH, FULL, META, MOTION, PARENT, find_child

__all__ = ["STAGE1", "STAGE2", "TRACE_S", "TRACE_T", "new_buffers", "to_check", "shared_depth", "stage_one",
           "trace", "MOT", "EDEG", "ECODE", "H_OFF", "H_ARR", "REM", "HERE", "NODES", "PREV"]

STAGE1, STAGE2, TRACE_S, TRACE_T = 1, 2, 4, 8
"""Overlap stages 1 and 2 (Enhancement-1), tracing on S (Enhancement-2) and on into T (Enhancement-3)."""
MOT, EDEG, ECODE, H_OFF, H_ARR, REM, SX, SE, HERE, RL, POOL_REC, POOL_NEXT, NODES, CSX, CSE, CVALID, PREV = range(17)


@kernel
def new_buffers(room: int, vcap: int, ucap: int) -> tuple:
    """``X`` with room for ``room`` motions and trie nodes, paths of ``vcap + 1`` and ``ucap`` hypotheses."""
    depths = ucap * (vcap + 2)
    return (np.zeros(room, dtype=np.int64), np.zeros(room, dtype=np.int64), np.zeros(room, dtype=np.int64),
            np.zeros(ucap + 1, dtype=np.int64), np.zeros(ucap, dtype=np.int64), np.zeros(ucap, dtype=np.int64),
            np.zeros(room, dtype=np.int64), np.zeros(room, dtype=np.int64), np.zeros(vcap + 2, dtype=np.int64),
            np.zeros(room, dtype=np.int64), np.zeros(4 * room, dtype=np.int64), np.zeros(4 * room, dtype=np.int64),
            np.zeros(room, dtype=np.int64), np.zeros(depths, dtype=np.int64), np.zeros(depths, dtype=np.int64),
            np.zeros(ucap, dtype=np.int64), np.zeros(vcap + 3, dtype=np.int64))


@kernel
def to_check(T: tuple, X: tuple, first: int) -> tuple:
    """The trie's nodes to compare, in the order added, into ``X[NODES]``, their number and whether they are the
    path from v_u to the last node: so when every node added since the last check (``first`` = the number of
    nodes then) lies on that path; otherwise every node but v_u."""
    n, nodes, parent = T[META][COUNT], X[NODES], T[PARENT]
    depth, x, on = T[DEPTH][n - 1], n - 1, 0
    for s in range(depth - 1, -1, -1):
        nodes[s] = x
        on += x >= first
        x = parent[x]
    if first > 1 and on == n - first:
        return depth, True
    for node in range(1, n):
        nodes[node - 1] = node
    return n - 1, False


@kernel
def shared_depth(X: tuple, count: int) -> int:
    """How deep the path ``X[NODES][:count]`` and the last one traced (``X[PREV]``) coincide."""
    prev, nodes, q = X[PREV], X[NODES], 0
    while q < count and q < prev[0] and prev[q + 1] == nodes[q]:
        q += 1
    return q


@kernel
def stage_one(T: tuple, X: tuple, Q: tuple, remaining: int, first: int) -> None:
    """Stage 1 one hypothesis at a time (for a check of every node): each remaining hypothesis whose M, walked
    down the trie, reaches a node from ``first`` on that sensed other than its P^E is ``MARKED``."""
    rem, off, mot, edeg, ecode, state = X[REM], X[H_OFF], X[MOT], X[EDEG], X[ECODE], Q[STATE]
    tdeg, tcode = T[DEGREE], T[CODE]
    for r in range(remaining):
        k = rem[r]
        node = 0
        for s in range(off[k], off[k + 1]):
            node = find_child(T, node, mot[s])
            if node < 0:
                break
            if node >= first and (tdeg[node] != edeg[s] or tcode[node] != ecode[s]):
                state[k] = MARKED
                break


@step
def _across(x: int, t: int, hv: int, he: int, vk: int, i: int, y: int, y_entry: int) -> tuple:
    """Where exit ``t`` of ``x``, unexplored in S, leads under h': the hypothesized edge joins (hv, he) and (vk, i)
    (e''/e, Algorithm 4.2); elsewhere (``y``, ``y_entry``)."""
    if x == hv and t == he:
        return vk, i
    if x == vk and t == i:
        return hv, he
    return y, y_entry


@step
def _resume(k: int, hv: int, he: int, base: int, shared: int, nodes: np.ndarray, sx: np.ndarray, se: np.ndarray,
            rl: np.ndarray, csx: np.ndarray, cse: np.ndarray, cvalid: np.ndarray) -> int:
    """Where hypothesis ``k``'s trace along a path starts: the depth this path shares with the last one traced, as
    far as ``k``'s kept states reach, its state there put on the node of that depth; -1 when that state is past an
    unexplored dart with no record (nothing further can disagree)."""
    q0 = min(shared, cvalid[k])
    cvalid[k] = q0
    if q0 == 0:
        csx[base], cse[base] = hv, he
        return 0
    node = nodes[q0 - 1]
    sx[node], se[node], rl[node] = csx[base + q0], cse[base + q0], -1
    return q0 if sx[node] >= 0 else -1


@kernel
def trace(S: tuple, T: tuple, X: tuple, R: tuple, Q: tuple, W: tuple, remaining: int, techniques: int, vk: int,
          i: int, count: int, first: int, path: bool, shared: int) -> None:
    """Tracing (Algorithm 4.2 lines 16–20; with ``TRACE_T``, 4.3 lines 16–24) of each unmarked remaining h': the
    nodes ``X[NODES][:count]`` in the order added, each parent's state carried by the node's motion (the map dart
    reached, -1 past an unexplored dart, and the records of T reached); h' is ``MARKED`` at the first node from
    ``first`` on that reads otherwise.  Along a ``path`` a trace starts from its state kept at ``shared``."""
    dcap, sx, se, rl, pool, nxt = S[5][DCAP], X[SX], X[SE], X[RL], X[POOL_REC], X[POOL_NEXT]
    nodes, parent, motion, tdeg, tcode = X[NODES], T[PARENT], T[MOTION], T[DEGREE], T[CODE]
    sdeg, slink, sentry, smarks, rat, rdeg, rcode = S[0], S[1], S[2], S[6], R[R_AT], R[R_DEGREE], R[R_CODE]
    rfirst, rmotion, rnext = R[R_FIRST], R[R_MOTION], R[R_NEXT]
    csx, cse, cvalid, rem, state, hvs, hes = X[CSX], X[CSE], X[CVALID], X[REM], Q[STATE], W[H_V], W[H_E]
    stride, records = X[HERE].shape[0], techniques & TRACE_T != 0
    for r in range(remaining):
        k = rem[r]
        if state[k] != REMAINING:
            continue
        hv, he = hvs[k], hes[k]
        sx[0], se[0], rl[0] = hv, he, -1
        used, q0, keep, base = 0, 0, path and count < stride, k * stride
        if keep:  # start from the state kept at the depth this path shares with the last
            q0 = _resume(k, hv, he, base, shared, nodes, sx, se, rl, csx, cse, cvalid)
            if q0 < 0:
                continue
        for q in range(q0, count):
            node = nodes[q]
            p, m, sx[node], rl[node] = parent[node], motion[node], -1, -1
            if sx[p] >= 0:
                x = sx[p]
                t = (se[p] + m) % sdeg[x]
                y, y_entry = slink[x * dcap + t], sentry[x * dcap + t]
                if y < 0:
                    if records and rat[x * dcap + t] >= 0 and used < pool.shape[0]:
                        pool[used], nxt[used], rl[node] = rat[x * dcap + t], -1, used
                        used += 1
                    y, y_entry = _across(x, t, hv, he, vk, i, y, y_entry)
                if y >= 0:
                    if node >= first and signature_in(sdeg, smarks, y, y_entry) != (tdeg[node], tcode[node]):
                        state[k] = MARKED
                        break
                    sx[node], se[node] = y, y_entry
            if records:  # the records of T reached: the parent's records' children, and any entered here
                rec = rl[p]
                while rec >= 0:
                    c = child_in(rfirst, rmotion, rnext, pool[rec], m)
                    if c >= 0 and used < pool.shape[0]:
                        pool[used], nxt[used], rl[node] = c, rl[node], used
                        used += 1
                    rec = nxt[rec]
                rec = rl[node] if used < pool.shape[0] else -1
                while rec >= 0 and node >= first and rdeg[pool[rec]] == tdeg[node] and rcode[pool[rec]] == tcode[node]:
                    rec = nxt[rec]
                if used >= pool.shape[0] or (rec >= 0 and node >= first):
                    T[META][FULL] |= used >= pool.shape[0]
                    state[k] = MARKED if used < pool.shape[0] else state[k]
                    break
            keep = keep and rl[node] < 0
            if keep:  # the state at depth q + 1, while no record is reached; a trace with neither ends here
                csx[base + q + 1], cse[base + q + 1], cvalid[k] = sx[node], se[node], q + 1
                if sx[node] < 0:
                    break
