"""Equivalence of two port worlds under plans without charcoal marks: two independent deciders.

Without marks a port world is a Moore machine: its states are the rooms, its inputs the doors, its output the
room's colour (the thesis's labelled-graph model, Table 2.3, read as an automaton).  Two worlds are *plainly
equivalent* when every plan without marks gives the same record on both, that is when their start states are
equivalent states of the disjoint union of the two machines.

* :func:`refine` decides it by partition refinement (Moore's algorithm) on the disjoint union: rooms start in
  blocks by colour, and a block splits while two of its rooms send some door into different blocks.
* :func:`separating_word` decides it independently by breadth-first search over the pair product from the two
  starts; it also gives the *shortest* plan without marks that tells the worlds apart.

Both use the doors the two worlds share (``0 .. min(doors) - 1``): a plan must be valid on both.

>>> from topomark.spec.port_world import from_joins
>>> a = from_joins([0, 1], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=2)
>>> b = from_joins([0, 1], [((0, 0), (1, 1)), ((0, 1), (0, 1)), ((1, 0), (1, 0))], 0, doors=2, alphabet=2)
>>> refine(a, b)[0], separating_word(a, b)
(False, (0, 0))
"""

from __future__ import annotations

from collections import deque

from topomark.spec.port_world import PortWorld

__all__ = ["refine", "separating_word", "product_pairs", "common_doors"]


def common_doors(a: PortWorld, b: PortWorld) -> int:
    """How many doors a plan valid on both worlds may use."""
    return min(a.doors, b.doors)


def refine(a: PortWorld, b: PortWorld) -> tuple[bool, list[int]]:
    """Whether the starts of ``a`` and ``b`` are equivalent states, and the block of every state of the disjoint
    union (rooms of ``a`` first, then rooms of ``b`` shifted by ``a.rooms``) in the coarsest stable partition."""
    doors = common_doors(a, b)
    shift = a.rooms
    colours = list(a.colours) + list(b.colours)
    succ = [[a.target(r, d) for d in range(doors)] for r in range(a.rooms)]
    succ += [[shift + b.target(r, d) for d in range(doors)] for r in range(b.rooms)]
    block = _numbered(list(colours))
    count = len(set(block))
    while True:
        signature: list[object] = [(block[s], *(block[t] for t in succ[s])) for s in range(len(colours))]
        new = _numbered(signature)
        new_count = len(set(new))
        block = new
        if new_count == count:
            break
        count = new_count
    return block[a.start] == block[shift + b.start], block


def _numbered(keys: list[object]) -> list[int]:
    """Each key replaced by the order in which its value first appears."""
    index: dict[object, int] = {}
    return [index.setdefault(k, len(index)) for k in keys]


def separating_word(a: PortWorld, b: PortWorld) -> tuple[int, ...] | None:
    """The shortest door sequence (least in door order among the shortest) whose records on ``a`` and ``b``
    differ, or ``None`` when the worlds are plainly equivalent."""
    doors = common_doors(a, b)
    first = (a.start, b.start)
    if a.colours[a.start] != b.colours[b.start]:
        return ()
    parent: dict[tuple[int, int], tuple[tuple[int, int], int]] = {}
    seen, queue = {first}, deque([first])
    while queue:
        pair = queue.popleft()
        for d in range(doors):
            nxt = (a.target(pair[0], d), b.target(pair[1], d))
            if nxt in seen:
                continue
            seen.add(nxt)
            parent[nxt] = (pair, d)
            if a.colours[nxt[0]] != b.colours[nxt[1]]:
                return _path(parent, first, nxt)
            queue.append(nxt)
    return None


def _path(parent: dict[tuple[int, int], tuple[tuple[int, int], int]], first: tuple[int, int],
          last: tuple[int, int]) -> tuple[int, ...]:
    word: list[int] = []
    while last != first:
        last, d = parent[last]
        word.append(d)
    return tuple(reversed(word))


def product_pairs(a: PortWorld, b: PortWorld) -> dict[tuple[int, int], tuple[int, ...]]:
    """Every pair of rooms some door sequence reaches from the two starts, with the shortest such sequence (least
    in door order), in breadth-first order."""
    doors = common_doors(a, b)
    first = (a.start, b.start)
    words: dict[tuple[int, int], tuple[int, ...]] = {first: ()}
    queue = deque([first])
    while queue:
        pair = queue.popleft()
        for d in range(doors):
            nxt = (a.target(pair[0], d), b.target(pair[1], d))
            if nxt not in words:
                words[nxt] = words[pair] + (d,)
                queue.append(nxt)
    return words
