"""The compiled footprint search of §6.2.1: Cases 1a, 1b, 2 and the two closest-first searches of Case 4, as
one loop with the case as a parameter (thesis §6.2.1 Cases 1a, 1b, 2, 4; Algorithms 6.1 and 6.3).

The engine's counterpart of
:class:`~topomark.reference.explorers.edge_footprints.FootprintSearch` and its
registered subclasses (``case-1a``, ``case-1b``, ``case-2``; ``case-4`` and
``case-4-mn`` of :mod:`~topomark.reference.explorers.closest_first`), making
the same choices in the same order so that a run does the very same actions
(:mod:`.digest`); the reference stays the definition (:mod:`.compare`).  The
cases differ in three numbers only (:data:`CASES`): the markers on a non-loop
edge (1, 0, 2, 1, 2), whether a new place gets a V-marker (Case 1b), and
whether a non-loop edge is marked only from a v_k with no marked edge yet,
the edge chosen closest first (Case 4's rules 1 and 3).

One iteration (:func:`iterate`): walk S to v_k and follow e = (v_k, v_u) (the
loop of :mod:`.algorithm31`: :func:`~.algorithm31.choose_edge`,
:func:`~.algorithm31.travel`); v_u new (Case 1b: no V-marker; else no marked
edge) — add it and drop its case's markers (:func:`arrive_new`); v_u known —
drop the loop marker on e, go back over e and search S for the vertex showing
a marked edge S does not show (:func:`validate`): the candidates are the
known vertices with an unexplored edge, v_u's degree and v_u's marks (the
counts on its marked edges), neither v_k nor a neighbour of v_k, in the
preorder of a breadth-first tree of S rooted at v_k (:func:`candidates`);
each is walked to by a shortest path of S, every vertex passed looked at, the
search stopping wherever v_k' shows (:func:`walk_looking`).  Those two
functions are the seam for the search as Algorithm 6.1 lines 11–19 list it
(every candidate visited, v_k's neighbours included, each checked where the
robot goes and nowhere on the way): a literal variant would keep v_k's
neighbours in :func:`candidates` and look only at the target in
:func:`walk_looking`, selected by one more integer argument; the engine runs
the registered searches, not the listings.

The kernel sees only its robot and the robot's marks (:mod:`.robot`,
:mod:`.marks`); what it knows is its map (:mod:`.mapstate`) and ``mk``, the
markers S shows on each map dart.  Outcome codes: :mod:`.algorithm31`'s, and
:data:`FAILED` (no candidate shows the footprint, or the one that does is not
an unexplored edge carrying the loop marker) and :data:`OUT_OF_MARKERS` (a drop
the kit cannot cover), both the reference's ``failed``.  Case 1b's extension
to m markers is compiled as its reference runs it: a refused drop ends the run
only where the last iteration's edge cannot be processed without it
(:func:`last_edge`; :func:`arrive_new`).
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.algorithm31 import (DIST, ITERATIONS, LOOP, NON_LOOP, OK, PARENT_E,
                                                   PARENT_V, QUEUE, ROBOT, TOWARD, DONE, choose_edge, loop_augment,
                                                   take_exit, travel)
from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.mapstate import DCAP, LIMIT, NS, PE, PV, ULEN, add_vertex, bfs, neighbours, start_map, u_index, u_pop
from topomark.reference.engine.robot import PURPOSE_NEW, PURPOSE_RETRACE, PURPOSE_VALIDATION, fault, move, sense
from topomark.reference.engine.marks import drop_edge, drop_place, place_marks, sensed_edges

__all__ = ["CASES", "FAILED", "OUT_OF_MARKERS", "new_footprint_scratch", "explore", "iterate", "arrive_new",
           "validate", "last_edge", "candidates", "walk_looking"]

FAILED, OUT_OF_MARKERS = 10, 11
CASES = {"case-1a": 0, "case-1b": 1, "case-2": 2, "case-4": 3, "case-4-mn": 4}
"""Each registered footprint search's case number, the kernel's parameter."""
_NON_LOOP_MARKERS = (1, 0, 2, 1, 2)
_MARKS_PLACES = (False, True, False, False, False)
_CLOSEST_FIRST = (False, False, False, True, True)
LOOP_MARKERS = 1
"""Markers on a loop edge, every case (§6.2.1)."""
MK, SENSED, ORDER, LOOKED, STACK, CHOSEN = range(6)


@kernel
def new_footprint_scratch(vcap: int, dcap: int) -> tuple:
    """The markers S shows per map dart (``MK``), what was sensed per relative exit, and the search's arrays."""
    return (np.zeros(vcap * dcap, dtype=np.int64), np.zeros(dcap, dtype=np.int64), np.zeros(vcap, dtype=np.int64),
            np.zeros(vcap, dtype=np.int64), np.zeros(vcap + 1, dtype=np.int64), np.zeros(vcap, dtype=np.int64))


@step
def _marks_key(counts: np.ndarray, size: int) -> tuple:
    """The search's key (``marks_key``): how many marked edges carry one marker, and how many more."""
    one, more = 0, 0
    for p in range(size):
        if counts[p] == 1:
            one += 1
        elif counts[p] > 1:
            more += 1
    return one, more


@step
def _map_key(S: tuple, mk: np.ndarray, v: int) -> tuple:
    dcap = S[5][DCAP]
    return _marks_key(mk[v * dcap:(v + 1) * dcap], S[0][v])


@step
def _marked(S: tuple, mk: np.ndarray, v: int) -> bool:
    dcap = S[5][DCAP]
    for i in range(S[0][v]):
        if mk[v * dcap + i]:
            return True
    return False


@kernel
def arrive_new(robot: np.ndarray, marks: np.ndarray, S: tuple, F: tuple, case: int, vk: int, i: int,
               degree: int) -> int:
    """v_u is new (Algorithm 6.1 lines 5–8): add it, e its exit 0, the robot there; drop the case's markers on e
    (Case 4: only from a v_k with no marked edge yet) and Case 1b's V-marker."""
    count = _NON_LOOP_MARKERS[case]
    if _CLOSEST_FIRST[case] and _marked(S, F[MK], vk):
        count = 0
    u = add_vertex(S, vk, i, degree)
    if u < 0:
        return LIMIT
    S[5][PV], S[5][PE] = u, 0
    if count:
        if not drop_edge(robot, marks, 0, count):
            return OUT_OF_MARKERS
        dcap = S[5][DCAP]
        F[MK][u * dcap], F[MK][vk * dcap + i] = count, count
    if _MARKS_PLACES[case] and not drop_place(robot, marks):  # Case 1b's extension: the last iteration only
        return FAILED if degree != 1 or S[5][ULEN] > 0 else OK
    return OK


@kernel
def last_edge(S: tuple, F: tuple, vk: int, i: int, degree: int) -> int:
    """Case 1b's extension (§6.2.1 Case 1b): out of markers at a known v_u, the one edge left in U must be e'
    (its vertex showing v_u's degree and marks as seen from it), and e/e' is added with no further motion."""
    v, e, dcap = S[3][0], S[4][0], S[5][DCAP]
    if S[5][ULEN] != 1 or S[0][v] != degree:
        return FAILED
    for p in range(degree):
        if F[SENSED][p] != F[MK][v * dcap + (e + p) % degree]:
            return FAILED
    return loop_augment(S, vk, i, v, e)  # the robot stands at v_k', entered by e'


@kernel
def candidates(S: tuple, W: tuple, F: tuple, vk: int, degree: int, key: tuple) -> int:
    """The known vertices that could be v_u — an end in U, neither v_k nor its neighbour, ``degree`` exits,
    marks ``key`` — in ``F[ORDER]``, in the preorder of the breadth-first tree of S rooted at v_k (children by
    exit); returns how many."""
    chosen, dcap = F[CHOSEN], S[5][DCAP]
    chosen[:S[5][NS]] = 0
    for k in range(S[5][ULEN]):
        v = S[3][k]
        if v != vk and not neighbours(S, vk, v) and S[0][v] == degree and _map_key(S, F[MK], v) == key:
            chosen[v] = 1
    bfs(S, vk, W[DIST], W[TOWARD], W[PARENT_V], W[PARENT_E], W[QUEUE])
    stack, order = F[STACK], F[ORDER]
    stack[0], top, count = vk, 1, 0
    while top > 0:
        top -= 1
        v = stack[top]
        if chosen[v]:
            order[count] = v
            count += 1
        for e in range(S[0][v] - 1, -1, -1):  # children pushed last exit first, so popped first exit first
            w = S[1][v * dcap + e]
            if w >= 0 and w != vk and W[PARENT_V][w] == v and W[PARENT_E][w] == e:  # S is connected: all reached
                stack[top] = w
                top += 1
    return count


@kernel
def walk_looking(robot: np.ndarray, marks: np.ndarray, S: tuple, W: tuple, F: tuple, target: int) -> tuple:
    """Walk a shortest path of S to ``target``, looking at every vertex entered; at the first showing a marked
    edge S does not show: (code, that vertex, the marked exit, the entry); (OK, -1, ...) if none does."""
    meta, dcap, path, mk, sensed = S[5], S[5][DCAP], W[DONE], F[MK], F[SENSED]
    bfs(S, meta[PV], W[DIST], W[TOWARD], W[PARENT_V], W[PARENT_E], W[QUEUE])
    count, x = 0, target
    while x != meta[PV]:
        path[count] = x
        count += 1
        x = W[PARENT_V][x]
    for t in range(count - 1, -1, -1):
        v, i = W[PARENT_V][path[t]], W[PARENT_E][path[t]]
        degree = take_exit(robot, S, v, i, PURPOSE_VALIDATION)[0]
        if fault(robot):
            return ROBOT, -1, -1, -1
        w, entry = S[1][v * dcap + i], S[2][v * dcap + i]
        meta[PV], meta[PE] = w, entry
        F[LOOKED][w] = 1
        sensed_edges(robot, marks, sensed)
        extra, found, shown = 0, -1, 0
        for p in range(degree):
            j = (entry + p) % degree
            if sensed[p] and sensed[p] != mk[w * dcap + j]:
                extra, found, shown = extra + 1, j, sensed[p]
        if extra:
            if extra > 1 or shown != LOOP_MARKERS or u_index(S, w, found) < 0:
                return FAILED, w, found, entry
            return OK, w, found, entry
    return OK, -1, -1, -1


@kernel
def validate(robot: np.ndarray, marks: np.ndarray, S: tuple, W: tuple, F: tuple, case: int, vk: int, i: int,
             degree: int) -> int:
    """v_u is known (Algorithm 6.1 lines 9–19, Algorithm 6.3 lines 14–24): the loop marker on e, back to v_k over
    e, the candidates searched for v_k'; then e/e' joined, the robot at v_k'."""
    key = _marks_key(F[SENSED], degree)  # what v_u showed on arrival, e not yet marked
    if not drop_edge(robot, marks, 0, LOOP_MARKERS):
        return last_edge(S, F, vk, i, degree) if _MARKS_PLACES[case] else OUT_OF_MARKERS
    move(robot, 0, PURPOSE_RETRACE)
    if fault(robot):
        return ROBOT
    meta, dcap = S[5], S[5][DCAP]
    meta[PV], meta[PE] = vk, i
    F[MK][vk * dcap + i] = LOOP_MARKERS  # v_k now shows the marker on e
    F[LOOKED][:meta[NS]] = 0
    for t in range(candidates(S, W, F, vk, degree, key)):
        target = F[ORDER][t]
        if F[LOOKED][target]:
            continue
        code, x, j, entry = walk_looking(robot, marks, S, W, F, target)
        if code != OK:
            return code
        if x >= 0:
            code = loop_augment(S, vk, i, x, j)
            meta[PV], meta[PE] = x, entry
            F[MK][x * dcap + j] = LOOP_MARKERS  # v_k' now shows the marker on e'
            return code
    return FAILED


@kernel
def iterate(robot: np.ndarray, marks: np.ndarray, S: tuple, W: tuple, F: tuple, case: int, edge_policy: int,
            counts: np.ndarray) -> int:
    """One iteration: e from U (Case 4: the nearest), S walked to v_k, e followed, v_u new or searched for."""
    meta = S[5]
    bfs(S, meta[PV], W[DIST], W[TOWARD], W[PARENT_V], W[PARENT_E], W[QUEUE])
    k = choose_edge(S, 0 if _CLOSEST_FIRST[case] else edge_policy, W[DIST])
    vk, i = S[3][k], S[4][k]
    u_pop(S, k)
    travel(robot, S, W, vk)
    if fault(robot):
        return ROBOT
    degree = take_exit(robot, S, vk, i, PURPOSE_NEW)[0]
    if fault(robot):
        return ROBOT
    sensed_edges(robot, marks, F[SENSED])
    if _MARKS_PLACES[case]:
        new = place_marks(robot, marks) == 0  # Case 1b: no V-marker
    else:
        new = _marks_key(F[SENSED], degree) == (0, 0)  # no marked edge
    if new:
        code = arrive_new(robot, marks, S, F, case, vk, i, degree)
    else:
        code = validate(robot, marks, S, W, F, case, vk, i, degree)
    if code == OK:  # the reference counts the iterations it records: the finished ones
        counts[ITERATIONS] += 1
        counts[NON_LOOP if new else LOOP] += 1
    return code


@kernel
def explore(robot: np.ndarray, marks: np.ndarray, S: tuple, W: tuple, F: tuple, case: int, edge_policy: int,
            counts: np.ndarray) -> int:
    """The footprint search from the robot's start: S = {v0}, U = its exits (Algorithm 6.1 line 1); Case 1b's
    V-marker at v0; then iterate until U is empty; an outcome code."""
    counts[:] = 0
    code = start_map(S, sense(robot)[0], 0)
    F[MK][:] = 0
    if code == OK and _MARKS_PLACES[case] and not drop_place(robot, marks):
        code = OUT_OF_MARKERS
    while code == OK and S[5][ULEN] > 0:
        code = iterate(robot, marks, S, W, F, case, edge_policy, counts)
    return code
