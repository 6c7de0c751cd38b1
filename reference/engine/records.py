"""The compiled store T of Enhancement-3: perceptions recorded beyond unexplored darts (thesis §4.1, Algorithm 4.3).

The engine's counterpart of :mod:`~topomark.reference.explorers.records`:
"T: a container to store perceptions of unexplored edges" (Algorithm 4.3
line 2).  A record is a trie of perceptions (Figure 4.5), its root keyed by
the unexplored map dart its paths leave S by, children indexed by relative
exits.  ``R`` is a tuple of arrays: the records' ``degree`` and ``code``
(:mod:`.signature`), their ``motion`` from the parent and children (``first``
child, ``next`` sibling), ``at`` (the root under map dart ``x * D + t``, or
-1), ``meta`` (the count, and 1 once full) and two work stacks.

* :func:`record_trie` — lines 36–37: route the iteration's execution trie
  from the validated (v_u, e) through S; what lies beyond an unexplored dart
  joins its record (to depth d for D of Enhancements 4/5, Algorithm 4.4
  line 22, 4.5 line 23, which lives in the same store);
* :func:`migrate` — when a dart with a record becomes explored, the record is
  routed on from where the dart now leads;
* :func:`graft` — the record beyond e holds paths from v_u: they join the
  iteration's trie as known perceptions before any motion.

Where the reference copies a record that moves (:func:`migrate`), this store
relinks it: the records reached are the same, only the order of siblings may
differ, which no choice of the algorithm reads (a hypothesis is rejected by
any contradiction; the next one is chosen by the robot's own path).  Records
left behind are not reused: a run that fills the store ends with
:data:`~.mapstate.LIMIT`.
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.mapstate import DCAP
from topomark.reference.engine.trie import CODE, DEGREE, DEPTH, FIRST, MOTION, NEXT, add_child, find_child

__all__ = ["new_records", "clear_records", "new_record", "record_child", "child_in", "record_trie", "migrate", "graft", "R_AT",
           "R_FULL"]

R_DEGREE, R_CODE, R_MOTION, R_FIRST, R_NEXT, R_AT, R_META, R_STACK_A, R_STACK_B, R_STACK_C = range(10)
R_COUNT, R_FULL = 0, 1


@kernel
def new_records(capacity: int, darts: int, stack: int) -> tuple:
    """An empty store with room for ``capacity`` records, keyed by ``darts`` map darts."""
    z = np.zeros(capacity, dtype=np.int64)
    return (z, z.copy(), z.copy(), z.copy(), z.copy(), np.full(darts, -1, dtype=np.int64), np.zeros(2, dtype=np.int64),
            np.zeros(stack, dtype=np.int64), np.zeros(stack, dtype=np.int64), np.zeros(stack, dtype=np.int64))


@kernel
def clear_records(R: tuple) -> None:
    """T = ∅ (a new run)."""
    R[R_AT][:] = -1
    R[R_META][R_COUNT], R[R_META][R_FULL] = 0, 0


@step
def new_record(R: tuple, motion: int, degree: int, code: int) -> int:
    """A record of the perception (``degree``, ``code``) reached by ``motion``, no children; -1 when full."""
    n = R[R_META][R_COUNT]
    if n >= R[R_DEGREE].shape[0]:
        R[R_META][R_FULL] = 1
        return -1
    R[R_DEGREE][n], R[R_CODE][n], R[R_MOTION][n], R[R_FIRST][n], R[R_NEXT][n] = degree, code, motion, -1, -1
    R[R_META][R_COUNT] = n + 1
    return n


@step
def record_child(R: tuple, rec: int, motion: int) -> int:
    """The child of record ``rec`` by ``motion``, or -1."""
    return child_in(R[R_FIRST], R[R_MOTION], R[R_NEXT], rec, motion)


@step
def child_in(first: np.ndarray, motions: np.ndarray, nxt: np.ndarray, rec: int, motion: int) -> int:
    """:func:`record_child` from T's arrays, for a loop that binds them once."""
    c = first[rec]
    while c >= 0 and motions[c] != motion:
        c = nxt[c]
    return c


@step
def _attach(R: tuple, rec: int, child: int) -> None:
    """Make record ``child`` the first child of ``rec``."""
    R[R_NEXT][child], R[R_FIRST][rec] = R[R_FIRST][rec], child


@kernel
def _push(R: tuple, top: int, a: int, b: int, c: int) -> int:
    if top >= R[R_STACK_A].shape[0]:
        R[R_META][R_FULL] = 1
        return top
    R[R_STACK_A][top], R[R_STACK_B][top], R[R_STACK_C][top] = a, b, c
    return top + 1


@kernel
def record_trie(S: tuple, R: tuple, T: tuple, x0: int, entry0: int, depth: int, virtual: bool) -> None:
    """Lines 36–37: trace the trie from the validated (v_u, e) = map dart (``x0``, ``entry0``) and add to T the
    perceptions from unknown places, of the nodes to ``depth`` (Enhancements 4/5: d), the ``virtual`` node (the
    root's child by motion 0, when ``virtual``) left out (stack items: trie node, map vertex and entry, or -1 and
    a record)."""
    dcap = S[5][DCAP]
    top = _push(R, 0, 0, x0, entry0)
    while top > 0 and not R[R_META][R_FULL]:
        top -= 1
        node, x, entry = R[R_STACK_A][top], R[R_STACK_B][top], R[R_STACK_C][top]
        c = T[FIRST][node]
        while c >= 0:
            m = T[MOTION][c]
            if T[DEPTH][c] > depth or (virtual and node == 0 and m == 0):
                c = T[NEXT][c]
                continue
            if x >= 0:
                t = x * dcap + (entry + m) % S[0][x]
                if S[1][t] >= 0:
                    top = _push(R, top, c, S[1][t], S[2][t])
                    c = T[NEXT][c]
                    continue
                rec = R[R_AT][t]
                if rec < 0:
                    rec = R[R_AT][t] = new_record(R, m, T[DEGREE][c], T[CODE][c])
            else:
                rec = record_child(R, entry, m)
                if rec < 0:
                    rec = new_record(R, m, T[DEGREE][c], T[CODE][c])
                    if rec >= 0:
                        _attach(R, entry, rec)
            if rec < 0:
                return
            top = _push(R, top, c, -1, rec)
            c = T[NEXT][c]


@kernel
def migrate(S: tuple, R: tuple, x0: int, t0: int) -> None:
    """The record under map dart (``x0``, ``t0``), just explored, moves to where the dart leads: its children are
    routed on through S, into T beyond unexplored darts (stack items: record, map vertex and entry, or -1 and the
    record it merges into)."""
    dcap = S[5][DCAP]
    rec = R[R_AT][x0 * dcap + t0]
    if rec < 0:
        return
    R[R_AT][x0 * dcap + t0] = -1
    top = _push(R, 0, rec, S[1][x0 * dcap + t0], S[2][x0 * dcap + t0])
    while top > 0 and not R[R_META][R_FULL]:
        top -= 1
        src, x, entry = R[R_STACK_A][top], R[R_STACK_B][top], R[R_STACK_C][top]
        c = R[R_FIRST][src]
        while c >= 0:
            after, m = R[R_NEXT][c], R[R_MOTION][c]
            if x >= 0:
                t = x * dcap + (entry + m) % S[0][x]
                if S[1][t] >= 0:
                    top = _push(R, top, c, S[1][t], S[2][t])
                elif R[R_AT][t] < 0:
                    R[R_AT][t], R[R_NEXT][c] = c, -1  # the subtree moves as it is
                else:
                    top = _push(R, top, c, -1, R[R_AT][t])
            else:
                into = record_child(R, entry, m)
                if into < 0:
                    _attach(R, entry, c)
                else:
                    top = _push(R, top, c, -1, into)
            c = after


@kernel
def graft(R: tuple, T: tuple, dart: int) -> None:
    """The paths recorded beyond e (map dart index ``dart``) join the trie below v_u as known perceptions (the
    trie's root must have just been started; stack items: record, trie node)."""
    rec = R[R_AT][dart]
    if rec < 0:
        return
    top = _push(R, 0, rec, 0, 0)
    while top > 0 and not R[R_META][R_FULL]:
        top -= 1
        src, node = R[R_STACK_A][top], R[R_STACK_B][top]
        c = R[R_FIRST][src]
        while c >= 0:
            m = R[R_MOTION][c]
            known = find_child(T, node, m)
            if known < 0:
                known = add_child(T, node, m, R[R_DEGREE][c], R[R_CODE][c])
                if known < 0:
                    return
            top = _push(R, top, c, known, 0)
            c = R[R_NEXT][c]
