"""The compiled Chapter 4 compositions: validation on the execution trie (thesis §4.1–4.3, Algorithms 4.1–4.5).

The engine's counterpart of :class:`~topomark.reference.explorers.enhanced.EnhancedExplorer`
with the compositions ``enh1`` (overlap stages 1 and 2, Algorithm 4.1),
``enh2`` (overlap stage 2 and the executed paths traced on S, Algorithm 4.2),
``enh3`` (… and on T, Algorithm 4.3), ``enh4``, ``enh5-d1``, ``enh5-d2``
(expanded signatures, Algorithms 4.4–4.5, :mod:`.expansion`) and ``enh3+4``,
``enh3+5`` (§4.3), as :mod:`~topomark.reference.explorers.compositions`
registers them.  The loop
is Algorithm 3.1's (:mod:`.algorithm31`: lines 5–7, H and its order, the two
augmentations); lines 8–20 run on the execution trie (:mod:`.trie`):

* each hypothesis h' has its motion sequence M and expected perceptions P^E
  (:func:`motion_sequences`, the same path to v0 as Algorithm 3.1's);
* :func:`attempt` executes M from the overlapped node the robot retraced to,
  stopping at the first mismatch (Algorithm 4.1 lines 8–13);
* after each mismatch, the remaining hypotheses the trie contradicts are
  rejected without motion (:mod:`.tracing`): stage 1 compares the executed
  paths overlapping M with P^E (Algorithm 4.1 lines 16–20); tracing maps
  every executed path onto S from h's dart, the hypothesized edge e''/e
  included, and compares each place it maps onto (Algorithm 4.2 lines 16–20);
* stage 2: the robot stays where the mismatch stopped it and takes next the
  remaining hypothesis overlapping its path longest, ties in the hypothesis
  policy's order (Algorithm 4.1 lines 15, 23–26), retracing only to the last
  overlapped node (:func:`choose`, through the hypothesis trie of
  :mod:`.hypothesis_trie`).

Enhancements 4 and 5 (:mod:`.expansion`) add, on entering v_u, the ``virtual``
node for v_k behind e, T's records beyond e and (Enhancement-5) the expansion,
then prune H before validation by tracing the whole trie on S and T
(:func:`_prune`); Enhancement-4 expands a new vertex after the non-loop
augmentation; what is recorded into T after the join goes to depth d, for a
new v_u only (:func:`~.expansion.recorded_depth`).

A technique set is an integer of :data:`STAGE1`, :data:`STAGE2`,
:data:`TRACE_S`, :data:`TRACE_T` and :mod:`.expansion`'s bits (:data:`TECHNIQUES`
by registered name).
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.algorithm31 import (CONFIRMED, DIST, H_E, H_V, HYPOTHESES, ITERATIONS, LOOP,
                                                   NON_LOOP, OK, ORDER, PARENT_E, PARENT_V, QUEUE, REJECTED, ROBOT,
                                                   TO_V0, TOWARD, choose_edge, hypotheses, lighthouse_entry,
                                                   loop_augment, take_exit, travel)
from topomark.reference.engine.compiled import kernel
from topomark.reference.engine.expansion import (DEPTH2, EVERY_DEPTH, EXPAND_NEW, EXPAND_PLACE, PRUNE, add_virtual,
                                                 expand, expansion_depth, recorded_depth)
from topomark.reference.engine.hypothesis_trie import (MARKED, STATE, build, longest_overlap, new_hypothesis_trie,
                                                       overlapping, remove)
from topomark.reference.engine.lighthouses import establish
from topomark.reference.engine.mapstate import (DCAP, LIMIT, PE, PV, ULEN, add_vertex, bfs, known_signature,
                                                mark_as_sensed, start_map, u_pop)
from topomark.reference.engine.records import (R_FULL, R_META, clear_records, graft, migrate, new_records,
                                               record_trie)
from topomark.reference.engine.robot import PURPOSE_NEW, PURPOSE_RETRACE, PURPOSE_VALIDATION, fault, sense
from topomark.reference.engine.tracing import (ECODE, EDEG, H_ARR, H_OFF, HERE, MOT, NODES, PREV, REM, STAGE1,
                                               STAGE2, TRACE_S, TRACE_T, new_buffers, shared_depth, stage_one,
                                               to_check, trace)
from topomark.reference.engine.trie import AT, COUNT, FULL, META, OFFSET, forward, goto, new_trie, path_to, start_trie

__all__ = ["STAGE1", "STAGE2", "TRACE_S", "TRACE_T", "TECHNIQUES", "RECORDS", "new_enhanced", "motion_sequences",
           "choose", "attempt", "validate_on_trie", "iterate_enhanced", "explore_enhanced"]

_ENH3 = STAGE2 | TRACE_S | TRACE_T
TECHNIQUES = {"enh1": STAGE1 | STAGE2, "enh2": STAGE2 | TRACE_S, "enh3": _ENH3,
              "enh4": PRUNE | EXPAND_NEW, "enh5-d1": PRUNE | EXPAND_PLACE, "enh5-d2": PRUNE | EXPAND_PLACE | DEPTH2,
              "enh3+4": _ENH3 | PRUNE | EXPAND_NEW, "enh3+5": _ENH3 | PRUNE | EXPAND_PLACE | DEPTH2}
"""Each compiled composition's techniques (:mod:`~topomark.reference.explorers.compositions`); ``TRACE_T``:
tracing continues into T, which records every executed path after the join (Enhancement-3); the bits of
Enhancements 4 and 5 are :mod:`.expansion`'s."""
EXPANDS = EXPAND_NEW | EXPAND_PLACE
REJECTS = STAGE1 | TRACE_S
"""The techniques that reject hypotheses without motion (:mod:`.tracing`)."""
RECORDS = TRACE_T | EXPANDS
"""The techniques that keep T (Enhancement-3's T, or D of Enhancements 4/5)."""


@kernel
def new_enhanced(vcap: int, dcap: int, ucap: int, records: bool) -> tuple:
    """The hypothesis trie (:mod:`.hypothesis_trie`), the execution trie, the store T (:mod:`.records`; room
    when ``records``: Enhancement-3's T, D of Enhancements 4/5) and the buffers of M, P^E and the remaining
    hypotheses, with room for every hypothesis's path."""
    room = ucap * (vcap + 1) + dcap * (dcap + 1) + 2  # every hypothesis's path, the expansion, v_u and v_k
    rooms = min(16 * room, 1 << 21) if records else 1
    return (new_hypothesis_trie(room, ucap), new_trie(room),
            new_records(rooms, vcap * dcap if records else 1, max(room, rooms)), new_buffers(room, vcap, ucap))


@kernel
def motion_sequences(S: tuple, W: tuple, X: tuple, nh: int) -> None:
    """Lines 11–12: each h' = (v, e)'s M and P^E along the tree to v0 (as Algorithm 3.1's walk), from
    ``X[H_OFF][k]``, and the entry of v0 where it ends (``X[H_ARR]``)."""
    dcap, toward = S[5][DCAP], W[TO_V0]
    at = 0
    for k in range(nh):
        X[H_OFF][k] = at
        x, entry = W[H_V][k], W[H_E][k]
        while True:
            exit_ = toward[x]
            y, y_entry = S[1][x * dcap + exit_], S[2][x * dcap + exit_]
            X[MOT][at] = (exit_ - entry) % S[0][x]
            X[EDEG][at], X[ECODE][at] = known_signature(S, y, y_entry)
            at += 1
            if y == 0:
                break
            x, entry = y, y_entry
        X[H_ARR][k] = y_entry
    X[H_OFF][nh] = at


@kernel
def choose(T: tuple, X: tuple, Q: tuple, remaining: int, techniques: int) -> tuple:
    """Line 10, or with stage 2 lines 23–26: the position in the remaining list of the hypothesis to execute next
    and the depth of the overlapped node to start from (:func:`~.hypothesis_trie.longest_overlap`)."""
    if not techniques & STAGE2:
        return 0, 0
    here = path_to(T, T[META][AT], X[HERE])
    k, depth = longest_overlap(Q, X[HERE], here)
    for r in range(remaining if k >= 0 else 0):
        if X[REM][r] == k:
            return r, depth
    return 0, 0


@kernel
def attempt(robot: np.ndarray, T: tuple, X: tuple, k: int, start: int) -> bool:
    """Lines 13–20 from the overlapped node at depth ``start`` (retracing there first): True on case (3)."""
    goto(robot, T, start, PURPOSE_RETRACE)
    off, length = X[H_OFF][k], X[H_OFF][k + 1] - X[H_OFF][k]
    for s in range(start, length):
        got = forward(robot, T, X[MOT][off + s], PURPOSE_VALIDATION)
        if fault(robot) or T[META][FULL]:
            return False
        if got[0] != X[EDEG][off + s] or got[1] != X[ECODE][off + s]:
            return False
    return True


@kernel
def _reject(S: tuple, T: tuple, W: tuple, X: tuple, R: tuple, Q: tuple, remaining: int, techniques: int, vk: int,
            i: int, counts: np.ndarray, first: int) -> int:
    """Reject without motion the remaining hypotheses the trie's nodes from ``first`` on contradict
    (:mod:`.tracing`), the others keeping their order."""
    count, path = to_check(T, X, first)
    if techniques & STAGE1:
        if path:
            overlapping(Q, T, X[NODES], count, first, X[H_OFF], X[EDEG], X[ECODE])
        else:
            stage_one(T, X, Q, remaining, first)
    if techniques & TRACE_S:
        trace(S, T, X, R, Q, W, remaining, techniques, vk, i, count, first, path,
              shared_depth(X, count) if path else 0)
    X[PREV][0] = count if path and count < X[HERE].shape[0] else 0  # the path the kept traces follow
    X[PREV][1:X[PREV][0] + 1] = X[NODES][:X[PREV][0]]
    kept = _drop_marked(X, Q, remaining)
    counts[REJECTED] += remaining - kept
    return kept


@kernel
def _drop_marked(X: tuple, Q: tuple, remaining: int) -> int:
    """The remaining hypotheses without those marked, the others keeping their order; how many are left."""
    kept = 0
    for r in range(remaining):
        k = X[REM][r]
        if Q[STATE][k] == MARKED:
            remove(Q, X[H_OFF], k)
        else:
            X[REM][kept] = k
            kept += 1
    return kept


@kernel
def _prune(S: tuple, T: tuple, W: tuple, X: tuple, R: tuple, Q: tuple, remaining: int, vk: int, i: int) -> int:
    """H without the hypotheses whose expanded signature disagrees with what is known around v_u — the trie
    (v_k behind e, the records grafted from T, the expansion) traced on S and T — the others keeping their
    order; pruned hypotheses are not counted as made."""
    count, _ = to_check(T, X, 1)
    trace(S, T, X, R, Q, W, remaining, TRACE_S | TRACE_T, vk, i, count, 1, False, 0)
    return _drop_marked(X, Q, remaining)


@kernel
def validate_on_trie(robot: np.ndarray, S: tuple, W: tuple, T: tuple, X: tuple, R: tuple, Q: tuple, nh: int, vk: int,
                     i: int, techniques: int, counts: np.ndarray) -> int:
    """Lines 8–20 on the trie (started at v_u; with T, what T records beyond e grafted): returns the confirmed
    hypothesis's index (the robot at v0) or -1 (the robot back at v_u, its heading counted from e in the trie's
    offset)."""
    motion_sequences(S, W, X, nh)
    for r in range(nh):
        X[REM][r] = W[ORDER][r]
    remaining = nh
    build(Q, X[MOT], X[H_OFF], nh, X[REM], remaining)
    X[PREV][0] = 0  # no trace kept yet
    if techniques & PRUNE:  # Algorithm 4.4 line 7, 4.5 line 8: H keeps what the expanded signature agrees with
        remaining = _prune(S, T, W, X, R, Q, remaining, vk, i)
    counts[HYPOTHESES] += remaining
    if T[META][0] > 1 and techniques & REJECTS:  # perceptions known before any motion
        remaining = _reject(S, T, W, X, R, Q, remaining, techniques, vk, i, counts, 1)
    checked = T[META][COUNT]
    while remaining > 0:
        r, start = choose(T, X, Q, remaining, techniques)
        k = X[REM][r]
        for t in range(r, remaining - 1):
            X[REM][t] = X[REM][t + 1]
        remaining -= 1
        remove(Q, X[H_OFF], k)
        if attempt(robot, T, X, k, start):
            counts[CONFIRMED] += 1
            return k
        if fault(robot) or T[META][FULL]:
            return -1
        counts[REJECTED] += 1
        if techniques & REJECTS and T[META][COUNT] > checked:  # only new nodes can contradict
            remaining = _reject(S, T, W, X, R, Q, remaining, techniques, vk, i, counts, checked)
            checked = T[META][COUNT]
    goto(robot, T, 0, PURPOSE_RETRACE)
    return -1


@kernel
def _joined(S: tuple, T: tuple, R: tuple, techniques: int, a: int, i: int, b: int, j: int, record: bool,
            new: bool) -> None:
    """After S is augmented by dart (a, i) joined to (b, j): with T, the records under either dart move on, and
    (``record``) the iteration's trie is recorded from the validated (v_u, e) = (b, j) (Algorithm 4.3
    lines 36–37; to depth d, for a ``new`` v_u only, with Enhancements 4/5 alone)."""
    if techniques & RECORDS:
        migrate(S, R, a, i)
        migrate(S, R, b, j)
        depth = EVERY_DEPTH if techniques & TRACE_T else recorded_depth(techniques, new)
        if record and depth > 0:
            record_trie(S, R, T, b, j, depth, techniques & EXPANDS != 0)


@kernel
def _enter(robot: np.ndarray, S: tuple, T: tuple, R: tuple, techniques: int, vk: int, i: int, degree: int,
           marks: int) -> int:
    """The trie of the iteration at v_u, with what is known there before H is formed: v_k behind e and T's
    records beyond e (Enhancements 3–5), then Enhancement-5's expansion (Algorithm 4.5 line 7); an outcome code."""
    start_trie(T, degree, marks)
    if techniques & EXPANDS:
        add_virtual(S, T, vk, i)
    if techniques & RECORDS:
        graft(R, T, vk * S[5][DCAP] + i)
    if techniques & EXPAND_PLACE:
        expand(robot, T, expansion_depth(techniques))
        if fault(robot):
            return ROBOT
    return LIMIT if T[META][FULL] or R[R_META][R_FULL] else OK


@kernel
def iterate_enhanced(robot: np.ndarray, S: tuple, W: tuple, T: tuple, X: tuple, R: tuple, Q: tuple, techniques: int,
                     edge_policy: int, hypothesis_policy: int, path_policy: int, counts: np.ndarray) -> int:
    """One pass through Algorithm 3.1's lines 5–28 with lines 8–20 on the trie (:func:`validate_on_trie`)."""
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
        code = loop_augment(S, vk, i, 0, entry)
        _joined(S, T, R, techniques, vk, i, 0, entry, False, False)
        return LIMIT if R[R_META][R_FULL] else code
    code = _enter(robot, S, T, R, techniques, vk, i, degree, marks)
    if code != OK:
        return code
    nh = hypotheses(S, W, vk, degree, marks, path_policy, hypothesis_policy)
    k = validate_on_trie(robot, S, W, T, X, R, Q, nh, vk, i, techniques, counts)  # lines 8-20
    if fault(robot):
        return ROBOT
    if T[META][FULL] or R[R_META][R_FULL]:
        return LIMIT
    if k >= 0:  # lines 22-25
        counts[LOOP] += 1
        code = loop_augment(S, vk, i, W[H_V][k], W[H_E][k])
        meta[PV], meta[PE] = 0, X[H_ARR][k]
        _joined(S, T, R, techniques, vk, i, W[H_V][k], W[H_E][k], True, False)
    else:
        counts[NON_LOOP] += 1  # lines 26-28
        u = add_vertex(S, vk, i, degree)
        if u < 0:
            return LIMIT
        mark_as_sensed(S, u, marks)
        if techniques & EXPAND_NEW:  # Algorithm 4.4 line 22
            expand(robot, T, expansion_depth(techniques))
            if fault(robot):
                return ROBOT
            if T[META][FULL]:
                return LIMIT
        meta[PV], meta[PE] = u, T[META][OFFSET]
        code = OK
        _joined(S, T, R, techniques, vk, i, u, 0, True, True)
    return LIMIT if R[R_META][R_FULL] else code


@kernel
def explore_enhanced(robot: np.ndarray, S: tuple, W: tuple, T: tuple, X: tuple, R: tuple, Q: tuple, rows: np.ndarray,
                     techniques: int, edge_policy: int, hypothesis_policy: int, path_policy: int,
                     counts: np.ndarray) -> int:
    """The composition ``techniques`` from the robot's start with the lighthouse of ``rows`` (lines 1–3 as
    :func:`~.lighthouses.explore_lighthouse`; T = ∅), iterating until U is empty; an outcome code."""
    counts[:] = 0
    clear_records(R)
    degree = sense(robot)[0]
    establish(robot, rows)
    if fault(robot):
        return ROBOT
    code = start_map(S, degree, sense(robot)[1])
    while code == OK and S[5][ULEN] > 0:
        code = iterate_enhanced(robot, S, W, T, X, R, Q, techniques, edge_policy, hypothesis_policy, path_policy,
                                counts)
    return code
