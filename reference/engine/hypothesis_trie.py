"""The remaining hypotheses' motion sequences as one trie (thesis §4.1, Algorithm 4.1 lines 16–26).

Overlap stages 1 and 2 compare the hypotheses' motion sequences M with the
paths the robot has executed from v_u: stage 1 rejects a hypothesis whose M
overlaps an executed path that sensed other than its P^E (lines 16–20); stage
2 takes next the remaining hypothesis that overlaps the robot's path longest
(lines 23–26).  Compared one hypothesis at a time, each check walks every
hypothesis's common prefix with the path, and the strips of the worst-case
search make those prefixes long (most hypotheses there begin "straight on").

So the engine keeps, for one iteration, the M of every hypothesis of H as a
trie of motions (the *hypothesis trie*, nodes by the order first reached),
each node knowing the hypotheses whose M passes through it and how many of
them remain.  Walking a path of the execution trie down this trie visits only
the hypotheses that overlap it: :func:`overlapping` marks the ones a new node
contradicts (stage 1), :func:`longest_overlap` finds stage 2's choice.  Both
answer exactly as the comparison one hypothesis at a time does;
:mod:`.enhanced` checks them against it on every world the equality command
runs.

A hypothesis trie is a tuple of arrays: per node its ``first`` child, ``next``
sibling and ``motion``, the number of remaining hypotheses through it
(``live``), and the hypotheses through it (``members`` from ``start[node]`` to
``start[node + 1]``); per position of the motion buffer, the node that motion
reaches (``at``); per hypothesis its ``state`` (:data:`REMAINING`,
:data:`GONE`, :data:`MARKED`) and its ``rank`` in the hypothesis policy's
order; ``meta`` holds the node count.

Examples
--------
>>> Q = new_hypothesis_trie(16, 4)
>>> mot, off = np.array([1, 2, 1, 3, 2, 2], dtype=np.int64), np.array([0, 2, 4, 6], dtype=np.int64)
>>> build(Q, mot, off, 3, np.array([2, 0, 1], dtype=np.int64), 3)
>>> int(Q[META][0]), int(Q[LIVE][Q[AT][0]]), int(Q[RANK][0])   # root, (1), (1, 2), (1, 3), (2), (2, 2)
(6, 2, 1)
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.trie import CODE as T_CODE, DEGREE as T_DEGREE, MOTION as T_MOTION

__all__ = ["new_hypothesis_trie", "build", "child", "child_in", "remove", "overlapping", "longest_overlap", "FIRST",
           "NEXT", "MOTION", "LIVE", "START", "MEMBERS", "AT", "STATE", "RANK", "META", "REMAINING", "GONE", "MARKED"]

FIRST, NEXT, MOTION, LIVE, START, MEMBERS, AT, STATE, RANK, META = range(10)
REMAINING, GONE, MARKED = 0, 1, 2
"""A hypothesis's ``state``: still in H, left H (executed, rejected or pruned), contradicted at this check."""


@kernel
def new_hypothesis_trie(room: int, ucap: int) -> tuple:
    """Room for ``room`` motions (the motion buffer's size) and ``ucap`` hypotheses."""
    return (np.zeros(room + 1, dtype=np.int64), np.zeros(room + 1, dtype=np.int64),
            np.zeros(room + 1, dtype=np.int64), np.zeros(room + 1, dtype=np.int64),
            np.zeros(room + 2, dtype=np.int64), np.zeros(room, dtype=np.int64), np.zeros(room, dtype=np.int64),
            np.zeros(ucap, dtype=np.int64), np.zeros(ucap, dtype=np.int64), np.zeros(1, dtype=np.int64))


@step
def child(Q: tuple, node: int, motion: int) -> int:
    """The child of ``node`` by ``motion``, or -1."""
    return child_in(Q[FIRST], Q[MOTION], Q[NEXT], node, motion)


@step
def child_in(first: np.ndarray, motions: np.ndarray, nxt: np.ndarray, node: int, motion: int) -> int:
    """:func:`child` from the trie's arrays, for a loop that binds them once (numba counts a reference each time
    an array is taken out of a tuple)."""
    c = first[node]
    while c >= 0 and motions[c] != motion:
        c = nxt[c]
    return c


@kernel
def build(Q: tuple, mot: np.ndarray, off: np.ndarray, nh: int, remaining: np.ndarray, count: int) -> None:
    """The trie of the ``nh`` sequences ``mot[off[k]:off[k + 1]]``, the hypotheses ``remaining[:count]`` (in the
    policy's order) remaining."""
    first, nxt, motion, start, members, at = Q[FIRST], Q[NEXT], Q[MOTION], Q[START], Q[MEMBERS], Q[AT]
    live, state, rank = Q[LIVE], Q[STATE], Q[RANK]
    first[0], nodes = -1, 1
    for k in range(nh):
        node = 0
        for s in range(off[k], off[k + 1]):
            c = child_in(first, motion, nxt, node, mot[s])
            if c < 0:
                c, nodes = nodes, nodes + 1
                motion[c], first[c], nxt[c], first[node] = mot[s], -1, first[node], c
            at[s], node = c, c
    Q[META][0] = nodes
    start[:nodes + 2] = 0
    for s in range(off[nh]):
        start[at[s] + 2] += 1
    for c in range(nodes):
        start[c + 2] += start[c + 1]
    for k in range(nh):  # start[c + 1] is c's next free member slot, then start[c + 1] the end of c's
        for s in range(off[k], off[k + 1]):
            members[start[at[s] + 1]] = k
            start[at[s] + 1] += 1
    live[:nodes] = 0
    state[:nh] = GONE
    for r in range(count):
        k = remaining[r]
        state[k], rank[k] = REMAINING, r
        for s in range(off[k], off[k + 1]):
            live[at[s]] += 1


@kernel
def remove(Q: tuple, off: np.ndarray, k: int) -> None:
    """Hypothesis ``k`` leaves H."""
    live, at = Q[LIVE], Q[AT]
    Q[STATE][k] = GONE
    for s in range(off[k], off[k + 1]):
        live[at[s]] -= 1


@kernel
def overlapping(Q: tuple, T: tuple, nodes: np.ndarray, count: int, first: int, off: np.ndarray, degree: np.ndarray,
                code: np.ndarray) -> None:
    """Stage 1 (lines 16–20) along the execution trie's path ``nodes[:count]`` from v_u: every remaining
    hypothesis whose M overlaps the path through a node from ``first`` on that sensed other than its P^E
    (``degree``, ``code`` at the same position of M) is ``MARKED``."""
    kids, nxt, motions, live, start, members, state = Q[FIRST], Q[NEXT], Q[MOTION], Q[LIVE], Q[START], Q[MEMBERS], \
        Q[STATE]
    tmotion, tdeg, tcode = T[T_MOTION], T[T_DEGREE], T[T_CODE]
    node = 0
    for s in range(count):
        x = nodes[s]
        node = child_in(kids, motions, nxt, node, tmotion[x])
        if node < 0 or live[node] == 0:
            return
        if x < first:
            continue
        for q in range(start[node], start[node + 1]):
            k = members[q]
            if state[k] == REMAINING and (degree[off[k] + s] != tdeg[x] or code[off[k] + s] != tcode[x]):
                state[k] = MARKED


@kernel
def longest_overlap(Q: tuple, path: np.ndarray, length: int) -> tuple:
    """Stage 2's choice (lines 23–26): the remaining hypothesis whose M shares the longest prefix with the motions
    ``path[:length]``, the first in the policy's order among those, and that prefix's length; (-1, 0) when none
    shares a first motion."""
    kids, nxt, motions, live, start, members, state, rank = Q[FIRST], Q[NEXT], Q[MOTION], Q[LIVE], Q[START], \
        Q[MEMBERS], Q[STATE], Q[RANK]
    node, depth = 0, 0
    for d in range(length):
        c = child_in(kids, motions, nxt, node, path[d])
        if c < 0 or live[c] == 0:
            break
        node, depth = c, d + 1
    if depth == 0:
        return -1, 0
    best = -1
    for q in range(start[node], start[node + 1]):
        k = members[q]
        if state[k] == REMAINING and (best < 0 or rank[k] < rank[best]):
            best = k
    return best, depth
