"""The one-mark claim checked exhaustively on small port worlds, by brute force over plans.

The port judge's docs prove that two plainly equivalent port worlds that are not rootedly isomorphic are told
apart by a plan with one charcoal mark.  This module checks that claim, and the length such plans need, without the
judge's reasoning: it enumerates every port world of a few rooms and doors (start room 0, every pairing of
door-ends, every colouring), runs every plan of at most ``max_doors`` doors with at most one mark through
:func:`topomark.spec.port_plan.run_plan`, and sorts the worlds into classes that no such plan of ``k`` doors tells
apart, for ``k = 0, 1, ...``.  :func:`check` then compares the classes with the judge's verdicts.

>>> worlds = enumerate_worlds(1, 2, 2)
>>> len(worlds)
4
>>> check(worlds, max_doors=3)["agree"]
True
"""

from __future__ import annotations

import itertools
import sys
from typing import Iterator

from topomark.reference.port.judge import judge
from topomark.spec.errors import InvalidWorld
from topomark.spec.port_plan import Action, doors_in, parse_plan, run_plan
from topomark.spec.port_world import DoorEnd, PortWorld

__all__ = ["enumerate_worlds", "plans", "levels", "check"]


def _involutions(ends: list[DoorEnd]) -> Iterator[list[tuple[DoorEnd, DoorEnd]]]:
    if not ends:
        yield []
        return
    first, rest = ends[0], ends[1:]
    for rest_pairs in _involutions(rest):  # first joined to itself
        yield [(first, first), *rest_pairs]
    for k, other in enumerate(rest):
        for rest_pairs in _involutions(rest[:k] + rest[k + 1:]):
            yield [(first, other), *rest_pairs]


def enumerate_worlds(rooms: int, doors: int, alphabet: int) -> list[PortWorld]:
    """Every port world of ``rooms`` rooms, ``doors`` doors and ``alphabet`` colours with start room 0 and every
    room reachable (each pairing of door-ends and each colouring once)."""
    ends = [(r, d) for r in range(rooms) for d in range(doors)]
    found = []
    for pairs in _involutions(ends):
        joins: list[list[DoorEnd]] = [[(0, 0)] * doors for _ in range(rooms)]
        for x, y in pairs:
            joins[x[0]][x[1]], joins[y[0]][y[1]] = y, x
        for colours in itertools.product(range(alphabet), repeat=rooms):
            try:
                found.append(PortWorld(tuple(colours), tuple(map(tuple, joins)), 0, doors, alphabet))
            except InvalidWorld:
                break  # reachability does not depend on the colours
    return found


def plans(doors: int, alphabet: int, length: int) -> list[tuple[Action, ...]]:
    """Every plan of exactly ``length`` doors with no mark or one mark (at any place, any colour)."""
    out = []
    for word in itertools.product(range(doors), repeat=length):
        steps = [Action("door", d) for d in word]
        out.append(tuple(steps))
        for at in range(length + 1):
            for c in range(alphabet):
                out.append(tuple(steps[:at] + [Action("mark", c)] + steps[at:]))
    return out


def levels(worlds: list[PortWorld], max_doors: int) -> list[list[int]]:
    """``classes[k][i]``: the class of world ``i`` under every plan of at most ``k`` doors with at most one mark
    (worlds in one class give equal records on all of them)."""
    doors, alphabet = worlds[0].doors, worlds[0].alphabet
    keys: list[tuple[object, ...]] = [() for _ in worlds]
    classes = []
    for k in range(max_doors + 1):
        batch = plans(doors, alphabet, k)
        keys = [(key, tuple(run_plan(w, batch_plan) for batch_plan in batch)) for key, w in zip(keys, worlds)]
        index: dict[object, int] = {}
        numbered = [index.setdefault(key, len(index)) for key in keys]
        keys = [(n,) for n in numbered]
        classes.append(numbered)
    return classes


def check(worlds: list[PortWorld], max_doors: int) -> dict[str, object]:
    """Compare brute force with the judge on every pair of ``worlds``: ``agree`` (the judge returns a witness
    exactly when some plan of at most ``max_doors`` doors and at most one mark tells the pair apart, calls a pair of
    equal room counts equivalent exactly when it returns none, and a witness with a mark has as few doors as the
    shortest separating plan), ``pairs``, ``different`` (pairs told apart), ``longest`` (the most doors the shortest
    separating plan of a pair needs) and ``disagreements`` (up to three pairs of world indices)."""
    classes = levels(worlds, max_doors)
    last = classes[-1]
    different, longest, bad = 0, 0, []
    for i, j in itertools.combinations(range(len(worlds)), 2):
        verdict = judge(worlds[i], worlds[j])
        told = last[i] != last[j]
        shortest = next((k for k in range(max_doors + 1) if classes[k][i] != classes[k][j]), None)
        different += told
        longest = max(longest, shortest or 0)
        ok = told == (verdict.witness is not None)
        if worlds[i].rooms == worlds[j].rooms:
            ok = ok and verdict.equivalent == (verdict.witness is None)
        if verdict.witness is not None and "[" in verdict.witness:
            ok = ok and doors_in(parse_plan(verdict.witness, doors=worlds[i].doors)) == shortest
        if not ok:
            bad.append((i, j))
    return {"agree": not bad, "pairs": len(worlds) * (len(worlds) - 1) // 2, "different": different,
            "longest": longest, "disagreements": bad[:3]}


def main(argv: list[str]) -> int:
    """``python -m topomark.reference.port.exhaustive ROOMS DOORS ALPHABET MAX_DOORS``: print :func:`check` on every
    world of 1 to ``ROOMS`` rooms."""
    rooms, doors, alphabet, max_doors = map(int, argv)
    worlds = [w for n in range(1, rooms + 1) for w in enumerate_worlds(n, doors, alphabet)]
    print(f"rooms<={rooms} doors={doors} alphabet={alphabet} worlds={len(worlds)} max_doors={max_doors}",
          check(worlds, max_doors))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
