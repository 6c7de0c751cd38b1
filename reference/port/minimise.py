"""The smallest map equivalent to a port world under plans without marks, and its copy structure.

Partition refinement (:func:`topomark.reference.port.plain.refine`) puts the rooms into blocks of plainly
equivalent rooms; the *quotient* has a room per block, with the block's colour, and door ``d`` of a block leads to
the block door ``d`` of any of its rooms leads to.  That is the smallest Moore machine with the world's records.
It is a port world only when its door-ends can be paired: a door of block ``B`` leading to block ``B'`` must be
joined to a door of ``B'`` leading back to ``B``.  Every room of ``B`` has the same number ``m(B, B')`` of doors
into ``B'``, and counting the passages between the two blocks from each side gives ``|B| m(B, B') = |B'| m(B',
B)``; so the pairing exists exactly when every two blocks joined by a passage have the same size — in a connected
world, when all blocks have one size ``k`` and the world is a ``k``-copy map of its quotient.  :func:`minimise`
then pairs the door-ends in door order (doors of one block leading to itself are paired among themselves, the last
one to itself when their number is odd) and verifies with the judge that the quotient is plainly equivalent to the
world; otherwise it reports the block sizes and gives no quotient.

>>> from topomark.reference.port.generate import random_port_world, cover
>>> base = random_port_world(3, rooms=4)
>>> m = minimise(cover(base, 2, seed=5))
>>> m.quotient.rooms, m.copies, m.fibres[0]
(4, 2, (0, 1))
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.reference.port.judge import judge
from topomark.reference.port.plain import refine
from topomark.spec.errors import TopomarkFault
from topomark.spec.port_world import DoorEnd, PortWorld, from_joins

__all__ = ["Minimised", "minimise"]


@dataclass(frozen=True)
class Minimised:
    """What :func:`minimise` found."""

    quotient: PortWorld | None
    """The smallest plainly equivalent port world (``None`` when the blocks differ in size)."""
    fibres: tuple[tuple[int, ...], ...]
    """The rooms of each block, in the quotient's room order; layer ``i`` of a block is its ``i``-th room."""
    copies: int | None
    """The common block size ``k`` (the world is a ``k``-copy map of its quotient), ``None`` if sizes differ."""
    layers: tuple[tuple[int, ...], ...]
    """``layers[B * doors + d][i]``: the layer door ``d`` of layer ``i`` of block ``B`` leads to (a permutation of
    the layers when the world is a cover), empty when ``copies`` is ``None``."""


def minimise(w: PortWorld) -> Minimised:
    """The quotient of ``w`` by plain equivalence and its copy structure (see the module's docstring)."""
    _, block = refine(w, w)
    block = block[:w.rooms]
    order = list(dict.fromkeys(block[w.start:] + block[:w.start]))  # the start's block first
    number = {b: k for k, b in enumerate(order)}
    fibres = tuple(tuple(r for r in range(w.rooms) if number[block[r]] == k) for k in range(len(order)))
    sizes = {len(f) for f in fibres}
    if len(sizes) != 1:
        return Minimised(None, fibres, None, ())
    of = [number[block[r]] for r in range(w.rooms)]
    layer = {r: i for f in fibres for i, r in enumerate(f)}
    quotient = _quotient(w, fibres, of)
    verdict = judge(quotient, w, names=("the quotient", "the world"))
    if verdict.witness is not None and "[" not in verdict.witness:
        raise TopomarkFault(f"the quotient of a port world is not plainly equivalent to it: plan {verdict.witness!r}"
                            " tells them apart", "quotient equivalent")
    layers = tuple(tuple(layer[w.target(r, d)] for r in f) for f in fibres for d in range(w.doors))
    return Minimised(quotient, fibres, sizes.pop(), layers)


def _quotient(w: PortWorld, fibres: tuple[tuple[int, ...], ...], of: list[int]) -> PortWorld:
    doors = w.doors
    wants: dict[tuple[int, int], list[int]] = {}
    for b, f in enumerate(fibres):
        for d in range(doors):
            wants.setdefault((b, of[w.target(f[0], d)]), []).append(d)
    passages: list[tuple[DoorEnd, DoorEnd]] = []
    for (b, b2), ds in sorted(wants.items()):
        if b == b2:
            pairs = list(zip(ds[0::2], ds[1::2])) + ([(ds[-1], ds[-1])] if len(ds) % 2 else [])
            passages += [((b, d), (b, e)) for d, e in pairs]
        elif b < b2:
            passages += [((b, d), (b2, e)) for d, e in zip(ds, wants[(b2, b)])]
    return from_joins([w.colours[f[0]] for f in fibres], passages, 0, doors=doors, alphabet=w.alphabet)
