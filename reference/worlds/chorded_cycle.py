"""The chorded cycle: a Hamiltonian cycle the robot walks first, and a seeded random second cycle of chords — a
4-regular world of small diameter on which Algorithm 3.1 still costs a constant share of its O(m²n) bound
(thesis §3.5.2, §7.2).

§7.2 suggests bounding the cost by "other factors such as graph diameter".
The families of :mod:`.expensive` that cost the most all have diameter Θ(n).
This one has the diameter of a random 4-regular graph (4 to 7 from n = 20 to
200 on the seeds measured), yet ``basic`` costs it about 0.12 of (3.1)+(3.2)
at every size measured (docs/worst-case/families.md): a cost that grows as n³
while the diameter grows as log n fits no bound of the form O(m²·diameter).

Why: place ``i`` lists clockwise ``i−1, i+1`` and then its two chords, so
the ``nearest`` policy walks the cycle ``0, 1, …, n−1`` first (exit 1 after
the entry, as on the circulant of :mod:`~topomark.reference.worstcase.lower_bound`)
and every hypothesis of that walk moves back along it by the same turn.  In
the world that turn traces a face of the embedding, and random chords make
the faces few and long, so a validation walk meets v0 late whatever the
diameter.

The chords: a permutation of the places drawn from ``random.Random(seed)``,
read as a cycle, redrawn until no chord joins two places of the cycle that
are already joined (no multi-edge, no chord along the cycle).

Examples
--------
>>> w = chorded_cycle(12, 0)
>>> (w.n, w.m, w.start_state()), sorted({len(w.rotation[v]) for v in w.vertices})
((12, 24, ('0', 1)), [4])
>>> [w.rotation[str(i)][:2] for i in (0, 5)]
[('11', '1'), ('4', '6')]
"""

from __future__ import annotations

import random

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World, check_size

from topomark.reference.worlds.deterministic import integer_param, seed_param

__all__ = ["chorded_cycle", "CHORDED_FROM", "DRAWS"]

CHORDED_FROM = 8
"""The least n: below it too few permutations avoid the cycle's own edges."""

DRAWS = 10_000
"""Permutations drawn at most before giving up (at n ≥ 8 a good one comes within a few dozen)."""


def _chords(n: int, rng: random.Random) -> list[tuple[int, int]]:
    """The second cycle's n chords: a random cyclic order of the places, none joining places already joined."""
    for _ in range(DRAWS):
        order = list(range(n))
        rng.shuffle(order)
        chords = [(order[i], order[(i + 1) % n]) for i in range(n)]
        pairs = {frozenset(c) for c in chords}
        if len(pairs) == n and all((a - b) % n not in (1, n - 1) for a, b in chords):
            return chords
    raise InvalidInput(f"chorded-cycle: no second cycle found for n = {n} in {DRAWS} draws")


def chorded_cycle(n: int, seed: int = 0) -> World:
    """The cycle ``0 … n−1`` with a second, random cycle of chords (n ≥ :data:`CHORDED_FROM`, 4-regular, m = 2n),
    started at place 0 facing place 1; place ``i`` lists clockwise i−1, i+1 and its two chords."""
    n = integer_param("n", n, CHORDED_FROM)
    seed = seed_param(seed)
    check_size(n, 2 * n, f"chorded-cycle:n={n},seed={seed}")
    chords: dict[int, list[int]] = {i: [] for i in range(n)}
    for a, b in _chords(n, random.Random(seed)):
        chords[a].append(b)
        chords[b].append(a)
    rotation = {str(i): tuple(str(x) for x in ((i - 1) % n, (i + 1) % n, *chords[i])) for i in range(n)}
    return World(rotation, (), Start("0", "1"))
