"""Language digests of all starts of a marked world at once (thesis §3.2; the census of §3.3–§6.1).

:func:`topomark.proofs.census.language_code` writes, per start, the minimal
machine reachable from it, numbered breadth-first from the start: one
breadth-first search per start.  The sharded census
(:mod:`topomark.proofs.census_map`) uses an equivalent code computed once per
marked world:

* the quotient machine ``Q`` (blocks of Moore equivalence, :func:`quotient`)
  is strongly connected — the robot can reach every state of a connected
  world — so a start's language is the pair ``(Q, its block)`` up to machine
  isomorphism;
* the *anchors* are the blocks whose output is the rarest in ``Q`` (ties: the
  least output text) — a set every isomorphism preserves;
* the code of start block ``b`` is the least, over anchors ``a``, of
  ``(breadth-first code of Q from a, number of b in that numbering)``.

Two equal codes give an isomorphism of the quotients mapping one start block
onto the other (the two numberings), hence equal languages; isomorphic pairs
give equal codes (the anchors correspond).  A marker usually makes one output
unique (a directional marker: ``V-0`` is sensed from one entry only), so one
search serves every start instead of one per start.  :func:`start_digests`
returns a 128-bit BLAKE2b digest per block; ``tests/test_census_shards.py``
checks that digests are equal iff :func:`language_code` is.

Examples
--------
>>> from topomark.proofs.census import machine, minimise
>>> from topomark.spec.world import World
>>> tri = machine(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}))
>>> d = start_digests(tri, minimise(tri), [0, 1, 2])
>>> len(set(d.values()))  # every start of the plain triangle perceives the same
1
"""

from __future__ import annotations

import hashlib
import sys
from array import array
from typing import Any, Iterable

__all__ = ["quotient", "anchors", "anchored_code", "start_digests"]


def quotient(mach: Any, block: list[int]) -> tuple[list[list[int]], list[str]]:
    """Successor blocks and output of every block of Moore equivalence ``block`` of ``mach``."""
    q = max(block) + 1
    succ: list[list[int]] = [[] for _ in range(q)]
    out: list[str] = [""] * q
    done = [False] * q
    for s, b in enumerate(block):
        if not done[b]:
            done[b] = True
            succ[b] = [block[t] for t in mach.succ[s]]
            out[b] = mach.out[s]
    return succ, out


def anchors(out: list[str]) -> list[int]:
    """The blocks with the rarest output (ties broken by the least output text)."""
    counts: dict[str, int] = {}
    for o in out:
        counts[o] = counts.get(o, 0) + 1
    rare = min(counts, key=lambda o: (counts[o], o))
    return [b for b, o in enumerate(out) if o == rare]


def anchored_code(succ: list[list[int]], out: list[str], anchor: int) -> tuple[bytes, list[int]]:
    """Breadth-first code of the quotient from ``anchor`` (exits in input order) and every block's number.

    The code is the outputs in visiting order (each ``[...]``, so their
    concatenation is unambiguous), a NUL, then the successor numbers.
    """
    number = [-1] * len(out)
    number[anchor] = 0
    order = [anchor]
    flat: list[int] = []
    for b in order:  # grows while we walk it
        for c in succ[b]:
            x = number[c]
            if x < 0:
                x = number[c] = len(order)
                order.append(c)
            flat.append(x)
    rows = array("I", flat)
    if sys.byteorder == "big":  # digests must agree across the machines of a cluster
        rows.byteswap()
    return "".join([out[b] for b in order]).encode() + b"\0" + rows.tobytes(), number


def start_digests(mach: Any, block: list[int], starts: Iterable[int]) -> dict[int, bytes]:
    """Block of each start state ↦ the digest of its language (see the module docstring)."""
    succ, out = quotient(mach, block)
    codes = [anchored_code(succ, out, a) for a in anchors(out)]
    least = min(code for code, _ in codes)
    numberings = [number for code, number in codes if code == least]
    head = hashlib.blake2b(least, digest_size=16).digest()
    digests: dict[int, bytes] = {}
    for s in starts:
        b = block[s]
        if b not in digests:
            x = min(number[b] for number in numberings)
            digests[b] = hashlib.blake2b(head + x.to_bytes(4, "little"), digest_size=16).digest()
    return digests
