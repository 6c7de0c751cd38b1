"""Distinguishing sequences by Z3 bounded model checking (thesis §3.2) — a second opinion.

:func:`topomark.proofs.bisim.distinguishing_sequence` finds the shortest
motion sequence whose perceptions differ by breadth-first search of the
product of the two robots' state machines.  This module asks Z3 the same
question one length at a time: *is there a motion sequence of length k whose
first k − 1 perceptions agree and whose k-th differs?*  The robot semantics
enter only through tables built with the spec's own :func:`~topomark.spec.robot.step`
and :func:`~topomark.spec.robot.sense`; the search itself is Z3's.

The first k that is satisfiable must equal the BFS answer's length, and when
BFS finds none, no k up to the product's state count may be satisfiable
(a shortest distinguishing sequence never revisits a product state).
``tests/test_bmc.py`` holds the two to that.

>>> from topomark.spec.world import World, Start
>>> c3 = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, start=Start("a", "b"))
>>> c4 = World({"p": ["q", "s"], "q": ["r", "p"], "r": ["s", "q"], "s": ["p", "r"]}, start=Start("p", "q"))
>>> shortest_by_bmc(c3, c4, 6) is None
True
"""

from __future__ import annotations

import z3

from topomark.spec.robot import sense, step
from topomark.spec.world import World

__all__ = ["distinguishes_at", "shortest_by_bmc"]


def _tables(world: World, signatures: dict) -> tuple[list, dict, int]:
    """States numbered; per state its signature id, degree and successor under each motion."""
    states = [(v, j) for v in world.vertices for j in range(world.degree(v))]
    index = {s: k for k, s in enumerate(states)}
    rows = []
    for s in states:
        sig = signatures.setdefault(sense(world, s), len(signatures))
        rows.append((sig, world.degree(s[0]), [index[step(world, s, l)] for l in range(world.degree(s[0]))]))
    return rows, index, max(world.degree(v) for v in world.vertices)


def _lookup(rows: list, state: z3.ArithRef, pick) -> z3.ArithRef:
    expr = z3.IntVal(pick(rows[-1]))
    for k in range(len(rows) - 2, -1, -1):
        expr = z3.If(state == k, z3.IntVal(pick(rows[k])), expr)
    return expr


def _next(rows: list, state: z3.ArithRef, motion: z3.ArithRef, degree: int) -> z3.ArithRef:
    expr = z3.IntVal(0)
    for k in range(len(rows) - 1, -1, -1):
        succ = z3.IntVal(rows[k][2][-1])
        for l in range(len(rows[k][2]) - 2, -1, -1):
            succ = z3.If(motion == l, z3.IntVal(rows[k][2][l]), succ)
        expr = z3.If(state == k, succ, expr)
    return expr


def distinguishes_at(a: World, b: World, k: int) -> tuple[int, ...] | None:
    """A motion sequence of length ``k`` whose first k−1 perceptions agree and k-th differs, or None."""
    signatures: dict = {}
    ra, ia, da = _tables(a, signatures)
    rb, ib, db = _tables(b, signatures)
    s = z3.Solver()
    xa, xb = z3.IntVal(ia[a.start_state()]), z3.IntVal(ib[b.start_state()])
    s.add(_lookup(ra, xa, lambda r: r[0]) == _lookup(rb, xb, lambda r: r[0]))
    motions = [z3.Int(f"m{t}") for t in range(k)]
    for t, m in enumerate(motions):
        s.add(m >= 0, m < _lookup(ra, xa, lambda r: r[1]))
        xa, xb = _next(ra, xa, m, da), _next(rb, xb, m, db)
        same = _lookup(ra, xa, lambda r: r[0]) == _lookup(rb, xb, lambda r: r[0])
        s.add(z3.Not(same) if t == k - 1 else same)
    if s.check() != z3.sat:
        return None
    model = s.model()
    return tuple(model.eval(m).as_long() for m in motions)


def shortest_by_bmc(a: World, b: World, bound: int) -> tuple[int, ...] | None:
    """The shortest distinguishing motion sequence of length ≤ ``bound``, found by Z3, or None."""
    for k in range(1, bound + 1):
        found = distinguishes_at(a, b, k)
        if found is not None:
            return found
    return None
