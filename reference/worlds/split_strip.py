"""The split strip: the closed strip cut so that a footprint search walks about 1.5 n moves for each loop it
closes, a family of worlds on which the O(mn) bound of §6.2.1's Cases 1a and 4 is tight (thesis §6.2.1, §7.2).

§7.2 asks whether the cost bounds of the thesis are tight and for which graphs.
For the footprint searches of §6.2.1 the bound topomark holds its explorers to
is (n − 1)² + (m − n + 1)(3n − 1) (every edge reached over a path of S, every
loop validated by a walk through S's candidates).  On the closed strip
``strip:n=N,cap=1`` each loop's validation walk ends after about n moves and
cost / bound falls towards 9/64.  A structural search for ``case-4``
(``topomark worst-case --search --algorithm case-4 --restart-family strip``)
found, at n = 50, a world 60% costlier that differs from the closed strip in
three edges and one rotation; :func:`split_strip` is that world at every even
n: with L = n/2 and k = 2⌊n/8⌋,

* the edges (0, L−1), (k, k+1) and (k, n−1−k) are removed — place k keeps
  only its path step back (k−1) and its diagonal (n−2−k), so the path of
  the strip is split at k; and
* place n−1 lists clockwise L, L−1, n−2, 0 (the closed strip: n−2, L, L−1, 0).

m = 2n − 3, maximum degree 4; started at place 0 facing place 1.

Why it costs more (``topomark explore split-strip:n=N --algorithm case-4 --breakdown`` and the robot's walk show
it): the first walk visits every place (0 … k, n−2−k, k+1 … n−3−k, n−2−k, n−1−k … n−1, 0), and the loops
are then closed alternately at the two ends of the folded path, each time between places far apart in S.  The
candidates are visited in the preorder of a breadth-first tree of S rooted at v_k: its first branch is the short
one, towards places already explored, and the place sought lies at the far end of the long one, so each of
these validation walks goes out along the short branch, back through v_k and along the whole long branch —
about 1.5 n moves (147 at n = 100) where the closed strip's take about n.  Cases 1a and 4 cost exactly
:func:`~topomark.reference.worstcase.family_costs.split_strip_cost` here, 5n²/4 + O(n), so cost / bound
rises towards 5/16 (0.2999 at n = 100, 0.3063 at n = 200).  Cases 1b and 2 and the m-marker Case 4, whose
markers tell loop edges from the others (a candidate must show as many marked loop edges as v_u), find no
candidate on the short branch and cost less here than on the closed strip.

Examples
--------
>>> w = split_strip(50)
>>> (w.n, w.m, w.start_state()), w.rotation["49"], w.rotation["12"]
((50, 97, ('0', 0)), ('25', '24', '48', '0'), ('11', '36'))
"""

from __future__ import annotations

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World, check_size

from topomark.reference.worlds.deterministic import integer_param
from topomark.reference.worlds.expensive import strip

__all__ = ["split_strip", "SPLIT_FROM", "split_place"]

SPLIT_FROM = 16
"""The least n: below it the split place k = 2⌊n/8⌋ is too near the start and the fold."""


def split_place(n: int) -> int:
    """The place k = 2⌊n/8⌋ where the strip's path is split (about n/4, and even: an odd k costs half as much)."""
    return 2 * (n // 8)


def split_strip(n: int) -> World:
    """``strip:n=N,cap=1`` less the edges (0, L−1), (k, k+1), (k, N−1−k) (L = N/2, k = :func:`split_place`), with
    place N−1 listing L, L−1, N−2, 0; N even, N ≥ :data:`SPLIT_FROM`; started at place 0 facing place 1."""
    n = integer_param("n", n, SPLIT_FROM)
    if n % 2:
        raise InvalidInput(f"n must be even (the closed strip it splits is), got {n}")
    check_size(n, 2 * n - 3, f"split-strip:n={n}")
    half, k = n // 2, split_place(n)
    rotation = {int(v): [int(x) for x in ns] for v, ns in strip(n, 1).rotation.items()}
    for a, b in ((0, half - 1), (k, k + 1), (k, n - 1 - k)):
        rotation[a].remove(b)
        rotation[b].remove(a)
    rotation[n - 1] = [half, half - 1, n - 2, 0]
    world = World({str(v): tuple(str(x) for x in ns) for v, ns in rotation.items()}, (), Start("0", "1"))
    assert world.m == 2 * n - 3 and max(world.degree(v) for v in world.vertices) == 4, "three edges removed"
    return world
