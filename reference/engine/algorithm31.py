"""The compiled Algorithm 3.1: the loop of lines 5–28, for unchecked runs (thesis §3.3, §3.4).

The engine's counterpart of
:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer` with
every built-in policy and the ``directional-vertex`` lighthouse (:func:`explore`;
:mod:`.lighthouses` establishes the others, whose marks the map records as
codes, :mod:`.signature`)
(:mod:`~topomark.reference.explorers.policies`: edge ``nearest|fifo|lifo``,
hypothesis ``fifo|lifo|shortest``, path ``shortest|dfs``), making the same
choices in the same order, so that a run does the very same actions
(:mod:`.digest`).  The reference stays the definition; the engine is checked
against it action by action (:mod:`.compare`).

Like the reference explorer, this kernel sees only its robot: it passes the
robot array to :func:`~.robot.move`, :func:`~.robot.sense` and
:func:`~.robot.drop_vertex` and never looks inside (``tests/test_engine.py``).
What it knows is its map (:mod:`.mapstate`) and what those calls returned.

The loop body :func:`iterate` is written once and calls its steps by name, the
points Chapter 4 modifies: :func:`lighthouse_entry` (recognising v0, §3.3),
:func:`hypotheses` (line 8, with line 10's order), :func:`validate` (lines
8–20, one hypothesis at a time) and the two augmentations.  A variant (an
enhancement's validation, another lighthouse) adds a case to the step it
changes, selected by an integer argument, instead of copying the loop.

Outcome codes: :data:`OK` (U emptied: the claimed map, ``claimed = correct``),
:data:`NOT_IN_U` and :data:`DEGENERATE` (a loop augmentation that Lemma 1 rules
out, §3.4: the reference raises :class:`~topomark.spec.errors.ExplorerFault`),
:data:`ROBOT` (the robot refused a motion or a drop) and
:data:`~.mapstate.LIMIT` (the map outgrew its buffers).  Counts (``counts``):
iterations, loop and non-loop augmentations, hypotheses made, rejected (cases
1–2) and confirmed (case 3), as the reference's outcome tallies them.
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.mapstate import (DCAP, LIMIT, NS, PE, PV, ULEN, HEAD, add_vertex, bfs, dfs_toward,
                                                join, known_signature, mark_as_sensed, neighbours, start_map, u_index,
                                                u_pop)
from topomark.reference.engine.signature import rotate
from topomark.reference.engine.robot import (PURPOSE_NEW, PURPOSE_RETRACE, PURPOSE_TRAVEL, PURPOSE_VALIDATION,
                                             drop_vertex, fault, move, sense)

__all__ = ["OK", "NOT_IN_U", "DEGENERATE", "ROBOT", "LIMIT", "ITERATIONS", "LOOP", "NON_LOOP", "HYPOTHESES",
           "REJECTED", "CONFIRMED", "new_scratch", "explore", "iterate", "choose_edge", "lighthouse_entry",
           "hypotheses", "validate"]

OK, NOT_IN_U, DEGENERATE, ROBOT = 0, 1, 2, 3
ITERATIONS, LOOP, NON_LOOP, HYPOTHESES, REJECTED, CONFIRMED = range(6)
DIST, TOWARD, PARENT_V, PARENT_E, QUEUE, TO_V0, SEEN, STACK_V, STACK_I, H_V, H_E, H_LEN, ORDER, DONE, DEGS = range(15)


@kernel
def new_scratch(vcap: int, ucap: int) -> tuple:
    """Working arrays of one run (searches, H, the motions done), reused from run to run."""
    return (np.zeros(vcap, dtype=np.int64), np.zeros(vcap, dtype=np.int64), np.zeros(vcap, dtype=np.int64),
            np.zeros(vcap, dtype=np.int64), np.zeros(vcap, dtype=np.int64), np.zeros(vcap, dtype=np.int64),
            np.zeros(vcap, dtype=np.int64), np.zeros(vcap + 1, dtype=np.int64), np.zeros(vcap + 1, dtype=np.int64),
            np.zeros(ucap, dtype=np.int64), np.zeros(ucap, dtype=np.int64), np.zeros(ucap, dtype=np.int64),
            np.zeros(ucap, dtype=np.int64), np.zeros(vcap + 1, dtype=np.int64), np.zeros(vcap + 2, dtype=np.int64))


@step
def choose_edge(S: tuple, policy: int, dist: np.ndarray) -> int:
    """Line 5: the index in U of e — ``nearest`` (0: the first entry whose end is nearest the robot), ``fifo``
    (1: the oldest), ``lifo`` (2: the newest)."""
    n = S[5][ULEN]
    if policy == 1:
        return 0
    if policy == 2:
        return n - 1
    best, at = dist[S[3][0]], 0
    for k in range(1, n):
        d = dist[S[3][k]]
        if d < best:
            best, at = d, k
    return at


@step
def take_exit(robot: np.ndarray, S: tuple, v: int, exit_: int, purpose: int) -> tuple:
    """Leave map vertex ``v`` (the believed pose's) by its map exit ``exit_``: the motion counts from the entry."""
    return move(robot, (exit_ - S[5][PE]) % S[0][v], purpose)


@kernel
def travel(robot: np.ndarray, S: tuple, W: tuple, target: int) -> None:
    """Line 6: walk S from the believed pose to ``target`` along the breadth-first tree just searched."""
    meta, dcap, path = S[5], S[5][DCAP], W[DONE]
    count, x = 0, target
    while x != meta[PV]:
        path[count] = x
        count += 1
        x = W[PARENT_V][x]
    for t in range(count - 1, -1, -1):
        v, i = W[PARENT_V][path[t]], W[PARENT_E][path[t]]
        take_exit(robot, S, v, i, PURPOSE_TRAVEL)
        if fault(robot):
            return
        meta[PV], meta[PE] = S[1][v * dcap + i], S[2][v * dcap + i]


@step
def lighthouse_entry(S: tuple, degree: int, code: int) -> int:
    """The exit of v0 the robot entered by, if what it sensed (``degree``, the marks' ``code``) is v0's from that
    entry (§3.3: the marker gives place and back-link at once; v0's signatures from its entries differ), else -1."""
    if code == 0 or degree != S[0][0]:
        return -1
    for entry in range(degree):
        if rotate(S[5][HEAD], degree, entry) == code:
            return entry
    return -1


@kernel
def hypotheses(S: tuple, W: tuple, vk: int, degree: int, marks: int, path_policy: int, order_policy: int) -> int:
    """Lines 8, 10–11: H — the darts of U, in U's order, whose end is not v_k and reads what was sensed — in
    ``W[H_V]``, ``W[H_E]``, their validation lengths in ``W[H_LEN]`` and the order to test them in ``W[ORDER]``
    (``fifo`` 0, ``lifo`` 1, ``shortest`` 2: by length, ties by U's order); the tree to v0 of the path policy
    (``shortest`` 0: breadth-first, ``dfs`` 1) in ``W[TO_V0]``.  Returns |H|."""
    uv, ue, h_v, h_e, h_len, order = S[3], S[4], W[H_V], W[H_E], W[H_LEN], W[ORDER]
    nh = 0
    for k in range(S[5][ULEN]):
        v = uv[k]
        if v != vk and S[0][v] == degree and known_signature(S, v, ue[k]) == (degree, marks):
            h_v[nh], h_e[nh] = v, ue[k]
            nh += 1
    if nh == 0:
        return 0
    if path_policy == 0:
        bfs(S, 0, W[DIST], W[TO_V0], W[PARENT_V], W[PARENT_E], W[QUEUE])
    else:
        dfs_toward(S, 0, W[TO_V0], W[SEEN], W[STACK_V], W[STACK_I])
    dcap = S[5][DCAP]
    for k in range(nh):
        x, length = h_v[k], 1
        while True:
            y = S[1][x * dcap + W[TO_V0][x]]
            if y == 0:
                break
            x, length = y, length + 1
        h_len[k] = length
        order[k] = nh - 1 - k if order_policy == 1 else k
    if order_policy == 2:  # a stable insertion sort by length
        for k in range(1, nh):
            j, item = k, order[k]
            while j > 0 and h_len[order[j - 1]] > h_len[item]:
                order[j] = order[j - 1]
                j -= 1
            order[j] = item
    return nh


@kernel
def walk_hypothesis(robot: np.ndarray, S: tuple, W: tuple, v: int, e: int, degree: int, heading: int) -> tuple:
    """Lines 11–16: execute h' = (v, e)'s motions from v_u, its first turned by ``heading``, comparing each
    perception with P^E; stop at the first mismatch.  Returns (confirmed, motions done, v0's entry at the end)."""
    dcap, toward, done, degs = S[5][DCAP], W[TO_V0], W[DONE], W[DEGS]
    degs[0] = degree
    x, entry, step = v, e, 0
    while True:
        exit_ = toward[x]
        y, y_entry = S[1][x * dcap + exit_], S[2][x * dcap + exit_]
        motion = (exit_ - entry) % S[0][x]
        if step == 0:
            motion = (motion - heading) % degree
        got = move(robot, motion, PURPOSE_VALIDATION)
        done[step] = motion
        degs[step + 1] = got[0]
        if fault(robot) or got != known_signature(S, y, y_entry):
            return False, step + 1, -1
        if y == 0:
            return True, step + 1, y_entry
        x, entry, step = y, y_entry, step + 1


@kernel
def retrace(robot: np.ndarray, W: tuple, count: int) -> None:
    """Line 17: the reverse of the ``count`` motions done: 0, then −l mod deg back to v_u."""
    move(robot, 0, PURPOSE_RETRACE)
    for t in range(count - 1, 0, -1):
        move(robot, (-W[DONE][t]) % W[DEGS][t], PURPOSE_RETRACE)


@kernel
def validate(robot: np.ndarray, S: tuple, W: tuple, nh: int, degree: int, counts: np.ndarray) -> tuple:
    """Lines 8–20: test H in order from v_u; returns (the confirmed hypothesis's index or -1, the robot's heading
    at v_u counted from e, v0's entry where the confirmed one ended)."""
    heading = 0
    counts[HYPOTHESES] += nh
    for t in range(nh):
        k = W[ORDER][t]
        confirmed, count, arrival = walk_hypothesis(robot, S, W, W[H_V][k], W[H_E][k], degree, heading)
        if fault(robot):
            return -1, heading, -1
        if confirmed:
            counts[CONFIRMED] += 1
            return k, heading, arrival
        counts[REJECTED] += 1
        retrace(robot, W, count)
        heading = (heading + W[DONE][0]) % degree
    return -1, heading, -1


@kernel
def loop_augment(S: tuple, vk: int, i: int, v: int, e: int) -> int:
    """Lines 24–25: join e = (vk, i) to e' = (v, e), removing e' from U; the believed pose (v, e).  e' must be
    in U and make no self-loop or second edge (Lemma 1, §3.4; §3.1.1)."""
    k = u_index(S, v, e)
    if k < 0:
        return NOT_IN_U
    if v == vk or neighbours(S, vk, v):
        return DEGENERATE
    u_pop(S, k)
    join(S, vk, i, v, e)
    S[5][PV], S[5][PE] = v, e
    return OK


@kernel
def iterate(robot: np.ndarray, S: tuple, W: tuple, edge_policy: int, hypothesis_policy: int, path_policy: int,
            counts: np.ndarray) -> int:
    """One pass through lines 5–28; an outcome code."""
    meta = S[5]
    bfs(S, meta[PV], W[DIST], W[TOWARD], W[PARENT_V], W[PARENT_E], W[QUEUE])
    k = choose_edge(S, edge_policy, W[DIST])  # line 5
    vk, i = S[3][k], S[4][k]
    u_pop(S, k)
    counts[ITERATIONS] += 1
    travel(robot, S, W, vk)  # line 6
    if fault(robot):
        return ROBOT
    degree, marks = take_exit(robot, S, vk, i, PURPOSE_NEW)  # line 7
    if fault(robot):
        return ROBOT
    entry = lighthouse_entry(S, degree, marks)
    if entry >= 0:  # the marker: place and back-link at once (§3.3)
        counts[LOOP] += 1
        return loop_augment(S, vk, i, 0, entry)
    nh = hypotheses(S, W, vk, degree, marks, path_policy, hypothesis_policy)
    k, heading, arrival = validate(robot, S, W, nh, degree, counts)  # lines 8-20
    if fault(robot):
        return ROBOT
    if k >= 0:  # lines 22-25
        counts[LOOP] += 1
        code = loop_augment(S, vk, i, W[H_V][k], W[H_E][k])
        meta[PV], meta[PE] = 0, arrival
        return code
    counts[NON_LOOP] += 1  # lines 26-28
    u = add_vertex(S, vk, i, degree)
    if u < 0:
        return LIMIT
    mark_as_sensed(S, u, marks)  # the far end of a marked edge shows it (§6.1)
    meta[PV], meta[PE] = u, heading
    return OK


@kernel
def explore(robot: np.ndarray, S: tuple, W: tuple, edge_policy: int, hypothesis_policy: int, path_policy: int,
            counts: np.ndarray) -> int:
    """Algorithm 3.1 from the robot's start: drop the directional marker pointing at the faced exit, S = {v0},
    U = its exits (lines 1–3), then iterate until U is empty (line 4); an outcome code."""
    counts[:] = 0
    degree = sense(robot)[0]
    drop_vertex(robot, 0)
    if fault(robot):
        return ROBOT
    code = start_map(S, degree, sense(robot)[1])
    while code == OK and S[5][ULEN] > 0:
        code = iterate(robot, S, W, edge_policy, hypothesis_policy, path_policy, counts)
    return code
