"""Fixing a given pair in the Z3 encoding, to test it on the thesis's figure pairs (thesis §3.2, §3.7, §6.1).

:func:`canonical_labelling` numbers a world's vertices as the symmetry
breaking of :mod:`topomark.proofs.z3world` does (BFS from the start, exit 0
on the parent edge); :func:`pair_is_model` pins both worlds of a
:class:`~topomark.proofs.z3pair.PairEncoding` to given worlds and asks Z3
whether the formula accepts them.  With both worlds pinned the formula
accepts the thesis's counterexample pairs (Figures 3.3, 3.4, 3.21(a),
6.1(a)) and rejects the distinguishable ones (Figures 3.6, 3.21(b), 6.1(b))
and isomorphic pairs (``tests/test_z3search.py``).
"""

from __future__ import annotations

from collections import deque

import z3

from topomark.spec.marker import EdgeMarker
from topomark.spec.world import World

from topomark.proofs.z3formula import not_
from topomark.proofs.z3pair import PairEncoding
from topomark.proofs.z3world import WorldVars

__all__ = ["canonical_labelling", "pair_is_model"]


def canonical_labelling(world: World) -> tuple[dict[str, int], dict[str, int]]:
    """The BFS numbering of the symmetry breaking and, per vertex, the rotation shift making exit 0 canonical."""
    at, facing = world.start_state()
    order, shift, queue = {at: 0}, {at: facing}, deque([at])
    while queue:
        u = queue.popleft()
        d = world.degree(u)
        for i in range(d):
            w = world.neighbour(u, (i + shift[u]) % d)
            if w not in order:
                order[w], shift[w] = len(order), world.index(w, u)
                queue.append(w)
    return order, shift


def _other_marked(world: World) -> str | None:
    """The vertex the exit variable e of vertex 0 leads to (head, marked neighbour, far end of the marked edge)."""
    assert world.start is not None, "a census world has its start"
    at = world.start.at
    for m in world.markers:
        if isinstance(m, EdgeMarker):
            return m.between[1] if m.between[0] == at else m.between[0]
        if m.points_to is not None:
            return m.points_to
        if m.at != at:
            return m.at
    return None


def _fixing_literals(wv: WorldVars, world: World) -> list[str]:
    """Literals that pin the variables of ``wv`` to ``world`` (in its canonical labelling)."""
    order, shift = canonical_labelling(world)
    lits = []
    for v, k in order.items():
        d = world.degree(v)
        lits.append(wv.deg[k][d])
        for i in range(d):
            w = world.neighbour(v, (i + shift[v]) % d)
            lits += [wv.tv[k, i][order[w]], wv.te[k, i][(world.index(w, v) - shift[w]) % world.degree(w)]]
    other = _other_marked(world)
    start = world.start
    assert start is not None, "a census world has its start"
    if wv.e is not None and other is not None:
        at, d0 = start.at, world.degree(start.at)
        lits.append(wv.e[next(i for i in range(d0) if world.neighbour(at, (i + shift[at]) % d0) == other)])
    if wv.head0 is not None:
        head = next(m.head for m in world.markers if isinstance(m, EdgeMarker))
        lits.append(wv.head0 if head == start.at else not_(wv.head0))
    return [x for x in lits if x is not True]


def pair_is_model(marker: str, a: World, b: World, planar: bool = False) -> str:
    """'sat' if the encoding accepts exactly this pair as a counterexample, else 'unsat' (or 'unknown').

    Both worlds must carry the class's markers and a start; the D bound is their
    largest degree.  Used to test the encoding on the thesis's figure pairs.
    """
    dmax = max(w.degree(v) for w in (a, b) for v in w.vertices)
    enc = PairEncoding(marker, a.n, b.n, dmax, planar)
    solver = z3.SolverFor("QF_FD")
    solver.from_string(enc.b.text())
    lits = _fixing_literals(enc.A, a) + _fixing_literals(enc.B, b)
    if any(x is False for x in lits):
        return "unsat"
    return str(solver.check([z3.Not(z3.Bool(x[5:-1])) if x.startswith("(not ") else z3.Bool(x) for x in lits]))

