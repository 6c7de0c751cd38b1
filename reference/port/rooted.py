"""Equivalence of two port worlds under plans with charcoal marks: rooted isomorphism, two independent deciders,
and the shortest one-mark witness.

Two worlds (of one alphabet of at least two colours) give the same record for every plan, marks included, exactly
when there is a bijection of rooms that maps start to start, keeps colours, and sends door ``d``'s target to door
``d``'s target — a *rooted isomorphism of doors, targets and colours*.  How the door-ends of parallel passages are
paired is not part of it: a record never shows by which door the robot came in.  The proof is in the docs (the
port judge's page); :func:`marked_witness` is its construction.

* :func:`isomorphism` maps rooms breadth-first from the two starts and fails on the first conflict.
* :func:`canonical_form` numbers a world's rooms breadth-first from its start (doors in order) and writes colours
  and targets in that numbering; two worlds are rootedly isomorphic when their forms are equal.

>>> from topomark.spec.port_world import from_joins
>>> a = from_joins([0, 0], [((0, 0), (1, 0)), ((0, 1), (1, 1)), ((1, 2), (1, 2)), ((0, 2), (0, 2))], 0, doors=3,
...                alphabet=2)
>>> b = from_joins([0, 0], [((0, 0), (1, 1)), ((0, 1), (1, 0)), ((1, 2), (1, 2)), ((0, 2), (0, 2))], 0, doors=3,
...                alphabet=2)
>>> isomorphism(a, b), canonical_form(a) == canonical_form(b)
({0: 0, 1: 1}, True)
"""

from __future__ import annotations

from collections import deque

from topomark.reference.port.plain import common_doors, product_pairs
from topomark.spec.port_world import PortWorld

__all__ = ["isomorphism", "canonical_form", "marked_witness", "MarkedWitness"]

MarkedWitness = tuple[tuple[int, ...], int, tuple[int, ...]]
"""``(u, c, x)``: the plan ``u [c] x`` — doors ``u``, a mark of colour ``c``, doors ``x``."""


def isomorphism(a: PortWorld, b: PortWorld) -> dict[int, int] | None:
    """The rooted isomorphism from ``a`` to ``b`` (room of ``a`` → room of ``b``), or ``None`` when there is none."""
    if a.rooms != b.rooms or a.doors != b.doors:
        return None
    phi, back = {a.start: b.start}, {b.start: a.start}
    queue = deque([a.start])
    while queue:
        r = queue.popleft()
        if a.colours[r] != b.colours[phi[r]]:
            return None
        for d in range(a.doors):
            s, t = a.target(r, d), b.target(phi[r], d)
            if phi.get(s, t) != t or back.get(t, s) != s:
                return None
            if s not in phi:
                phi[s], back[t] = t, s
                queue.append(s)
    return phi


def canonical_form(w: PortWorld) -> tuple[int, tuple[int, ...], tuple[tuple[int, ...], ...]]:
    """``(doors, colours, targets)`` of ``w`` with rooms numbered in breadth-first order from the start (doors
    taken in order); two worlds have equal forms exactly when they are rootedly isomorphic."""
    number = {w.start: 0}
    order = [w.start]
    k = 0
    while k < len(order):
        for d in range(w.doors):
            t = w.target(order[k], d)
            if t not in number:
                number[t] = len(order)
                order.append(t)
        k += 1
    colours = tuple(w.colours[r] for r in order)
    targets = tuple(tuple(number[w.target(r, d)] for d in range(w.doors)) for r in order)
    return w.doors, colours, targets


def marked_witness(a: PortWorld, b: PortWorld) -> MarkedWitness | None:
    """The shortest plan with one mark (fewest doors) whose records on ``a`` and
    ``b`` differ, or ``None`` when no plan with at most one mark tells them apart.  Marks use the colours both
    alphabets share.

    For plainly equivalent worlds: the robot walks ``u`` to a pair of rooms ``(p, q)`` the two starts reach
    together, marks it, and walks ``x`` until exactly one of the two robots is back in its marked room while the
    other sees a different colour."""
    colours = min(a.alphabet, b.alphabet)
    doors = common_doors(a, b)
    best: tuple[int, tuple[int, ...], int, tuple[int, ...]] | None = None
    for (p, q), u in product_pairs(a, b).items():
        if best is not None and len(u) >= best[0]:
            break  # pairs come in breadth-first order: no later prefix can beat the best
        for c in range(colours):
            x = _after_mark(a, b, p, q, c, doors)
            if x is not None and (best is None or len(u) + len(x) < best[0]):
                best = (len(u) + len(x), u, c, x)
    return None if best is None else (best[1], best[2], best[3])


def _after_mark(a: PortWorld, b: PortWorld, p: int, q: int, c: int, doors: int) -> tuple[int, ...] | None:
    """The shortest door sequence from ``(p, q)``, with ``p`` and ``q`` marked ``c``, after which the robots see
    different colours."""
    def shown(w: PortWorld, room: int, marked: int) -> int:
        return c if room == marked else w.colours[room]

    first = (p, q)
    words: dict[tuple[int, int], tuple[int, ...]] = {first: ()}
    queue = deque([first])
    while queue:
        pair = queue.popleft()
        for d in range(doors):
            nxt = (a.target(pair[0], d), b.target(pair[1], d))
            if nxt in words:
                continue
            words[nxt] = words[pair] + (d,)
            if shown(a, nxt[0], p) != shown(b, nxt[1], q):
                return words[nxt]
            queue.append(nxt)
    return None
