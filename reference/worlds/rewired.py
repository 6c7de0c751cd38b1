"""The rewired strip: the closed strip with the rewiring a structural search found at n = 100 moved to any size, a
family of 4-regular worlds costlier for Algorithm 3.1 than the strip (thesis §3.5.2, §7.2).

§7.2 asks whether the O(m²n) bound of §3.5.2 is tight and for which graphs.
``topomark worst-case --search --restart-family strip`` started from the
closed strip ``strip:n=100,cap=1`` and found a world 16% costlier for
``basic`` (``worst-case:case=basic-n100-d4-search``).  It differs from the
closed strip in fifteen edges, all at 24 places: near the start (places 0–12),
around the fold (the middle, places 41–57) and near the far end (places
87–99).  Those 24 places' rotations, with every other place as in the closed
strip, are :data:`REWIRING` — and cost a little more than the searched world
(996,034 against 992,842).  :func:`rewired_strip` moves them to n places:
a place below n₀/4 (n₀ = 100) keeps its number, one from 3n₀/4 on keeps its
distance from the far end, one between keeps its distance from the middle,
and each neighbour a rotation lists moves the same way.  No rewired place lies
near n₀/4 or 3n₀/4, so a path step, rung (x ↔ n₀−1−x) or diagonal
(x ↔ n₀−2−x) of the strip stays one at every size.

Why it costs more (``topomark explore --breakdown`` shows it): the robot's
first walk along the path skips the fold (place 44 leads to 56, not 45) and
never reaches three of v0's four neighbours (places 49, 98, 99), so after
the loop it closes at the end of that walk it stands at v0 (a confirmed
hypothesis ends there) and discovers those places — next to v0 in the world,
last in U's order — when U holds nearly every open exit, each still far from
v0 in S.  Each such iteration walks and retraces most open exits' whole path
to v0: at n = 100 sixteen loop iterations cost more than half the costliest
iteration (one does on the closed strip), up to about 14,000 traversals each
against 2,400–5,000 for the closed strip's, and the loop iterations cost
410,520 in all against 258,580.  The rewiring is of fixed size, so its gain
grows more slowly than the cost: cost / bound peaks at n = 124 (0.2146).

Examples
--------
>>> w = rewired_strip(100)
>>> (w.n, w.m, w.start_state()), w.rotation["44"]
((100, 200, ('0', 2)), ('43', '56', '55', '95'))
>>> rewired_strip(200).rotation["94"], rewired_strip(200).rotation["0"]
(('93', '106', '105', '195'), ('199', '99', '1', '198'))
"""

from __future__ import annotations

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World, check_size

from topomark.reference.worlds.deterministic import integer_param
from topomark.reference.worlds.expensive import strip

__all__ = ["rewired_strip", "REWIRING", "FOUND_AT", "REWIRED_FROM"]

FOUND_AT = 100
"""The size n₀ the rewiring was found at (``worst-case:case=basic-n100-d4-search``)."""

REWIRED_FROM = 46
"""The least n the rewiring fits at: below it the places near the start, the fold and the far end collide."""

REWIRING: dict[int, tuple[int, ...]] = {
    0: (99, 49, 1, 98), 3: (2, 4, 52, 53), 4: (3, 5, 54, 94), 5: (4, 6, 52, 94), 7: (6, 8, 96, 91),
    8: (7, 9, 45, 90), 12: (11, 13, 41, 86), 41: (40, 42, 12, 58), 44: (43, 56, 55, 95), 45: (55, 8, 53, 54),
    46: (91, 52, 53, 47), 51: (50, 96, 48, 47), 52: (5, 3, 47, 46), 53: (3, 46, 45, 54), 54: (53, 55, 4, 45),
    55: (54, 43, 44, 45), 56: (44, 57, 42, 43), 57: (56, 58, 87, 42), 87: (86, 88, 57, 11), 91: (90, 92, 46, 7),
    92: (91, 93, 6, 95), 93: (92, 94, 95, 6), 95: (94, 92, 44, 93), 96: (97, 7, 2, 51),
}
"""The 24 places, numbered as at n₀ = 100, whose clockwise rotations differ from ``strip:n=100,cap=1``'s."""


def _moved(x: int, n: int) -> int:
    """Place ``x`` of the n₀-place world at n places: near the start, the middle or the far end alike."""
    shift = (n - FOUND_AT) // 2
    if x < FOUND_AT // 4:
        return x
    return x + shift if x < FOUND_AT - FOUND_AT // 4 else x + 2 * shift


def rewired_strip(n: int) -> World:
    """``strip:n=N,cap=1`` with the places of :data:`REWIRING` rewired (n even, n ≥ :data:`REWIRED_FROM`), started
    at place 0 facing place 1; 4-regular, m = 2n.  At n = 100 only those places differ from the closed strip."""
    n = integer_param("n", n, REWIRED_FROM)
    if n % 2:
        raise InvalidInput(f"n must be even (the closed strip it rewires is), got {n}")
    check_size(n, 2 * n, f"rewired-strip:n={n}")
    rotation = dict(strip(n, 1).rotation)
    for x, listed in REWIRING.items():
        rotation[str(_moved(x, n))] = tuple(str(_moved(y, n)) for y in listed)
    return World(rotation, (), Start("0", "1"))
