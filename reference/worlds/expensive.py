"""World families that make Algorithm 3.1 expensive: maximum degree 4, a long walk to v0 for every hypothesis
(thesis §3.5.2, §7.2).

§3.5.2 bounds Algorithm 3.1's cost by (3.1)+(3.2) = O(m²n); §7.2 leaves
open whether the bound is tight and for which graphs.  With its one
directional marker at v0 the robot tells places apart only by their degree
and by the marker (§3.3), so in a world where (nearly) every place has
degree 4 a wrong hypothesis h' is refuted only when its validation walk M
reaches — or should have reached — v0: case (2) at the end of M, or case (1)
when the real walk passes v0 first (Algorithm 3.1 lines 13–17).  Each
rejected h' then costs twice the length of its path in S, walk and retrace.
These families make those paths long and the hypotheses many: the start, and
so the marker, at an end of a long world, and a rotation system under which
the default ``nearest`` edge policy walks S out as one long path.

* :func:`strip` — the triangulated strip, the square P_n² of a path: places
  ``0 … n−1`` on a path (the robot's route), each place ``i`` also joined to
  ``n−1−i`` and ``n−2−i`` (the "rungs" and "diagonals" of a ladder folded
  in two).  The robot walks out along one side, round the fold and back along
  the other, so S is a path whose every inner place keeps two open exits.
  Each rung or diagonal joins a place x of the way out to n−1−x or n−2−x of
  the way back, far apart on that path: closing one shortens the paths to
  v0 from the places near the far end of the walk.  The worst family found for
  ``basic``: its cost is a cubic in n (per n mod 6), about 23/24·n³, some
  0.2 of the bound (:mod:`topomark.reference.worstcase.family_costs`).
  ``cap=1`` joins its two ends so that every place has degree 4; that costs
  more at small n.
* :func:`circulant` — C_n(1, k), 4-regular: ``i`` joined to ``i±1`` and
  ``i±k`` (mod n).
* :func:`k5e_chain` — a chain of ``gadgets`` copies of K5 − e (the complete
  graph on 5 places less one edge), the two 3-valent places of each joined to
  the next and the previous copy: every place but the chain's two ends has
  degree 4.
* :func:`cylinder` — C_size × P_rings: ``rings`` rings (cycles of ``size``
  places) stacked, each place joined to the one above and below it: degree 4
  but in the two end rings.

Every family is generated with its start: place ``"0"``, at an end, facing
the place its rotation lists first (the robot drops its marker there,
§3.3).  Each rotation is stated in its generator's docstring.

Examples
--------
>>> w = strip(8)
>>> (w.n, w.m, w.start_state()), w.rotation["1"]
((8, 13, ('0', 0)), ('0', '2', '5', '6'))
>>> sorted(len(w.rotation[v]) for v in w.vertices)
[2, 2, 3, 3, 4, 4, 4, 4]
>>> circulant(10, 2).m, k5e_chain(3).n, cylinder(4, 3).m
(20, 15, 21)
"""

from __future__ import annotations

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World, check_size

from topomark.reference.worlds.deterministic import integer_param

__all__ = ["strip", "circulant", "k5e_chain", "cylinder"]


def _world(rotation: dict[int, list[int]], facing: int) -> World:
    """The world of ``rotation`` (integer places, clockwise lists), started at place 0 facing ``facing``."""
    return World({str(v): tuple(str(x) for x in ns) for v, ns in rotation.items()}, (), Start("0", str(facing)))


def strip(n: int, cap: int = 0) -> World:
    """The triangulated strip P_n² on n ≥ 5 places, started at place 0 facing place 1 (§3.5.2, §7.2).

    Place ``i`` lists clockwise ``i−1, i+1, n−2−i, n−1−i``, each where it is a place other than ``i`` and not
    already listed (places ``0``, ``n−1`` and the two at the fold have degree 2 or 3; m = 2n − 3).  Entered
    from ``i−1``, exit 1 (the next clockwise) leads to ``i+1``: the ``nearest`` policy walks the path
    ``0, 1, …, n−1`` — out along one side of the folded ladder, back along the other — before it closes a loop.

    ``cap=1`` (n even, n ≥ 8) closes the strip into a 4-regular world (m = 2n): with L = n/2, the fold places
    L−1 and L are joined to the end places 0 and n−1 by the three edges (0, L−1), (n−1, L−1), (n−1, L), and
    those four places list clockwise 0: 1, n−1, n−2, L−1; n−1: n−2, L, L−1, 0; L−1: L−2, L, 0, n−1;
    L: L−1, L+1, n−1, L−2.  The robot still walks the path first; the loops closed last are the three joins.
    """
    n = integer_param("n", n, 5)
    cap = integer_param("cap", cap, 0)
    if cap > 1 or (cap and (n % 2 or n < 8)):
        raise InvalidInput(f"strip: cap is 0 or 1, and cap=1 needs an even n >= 8 (n = {n}, cap = {cap})")
    check_size(n, 2 * n - 3 + 3 * cap, f"strip:n={n},cap={cap}")
    rotation: dict[int, list[int]] = {}
    for i in range(n):
        listed: list[int] = []
        for j in (i - 1, i + 1, n - 2 - i, n - 1 - i):
            if 0 <= j < n and j != i and j not in listed:
                listed.append(j)
        rotation[i] = listed
    if cap:
        half = n // 2
        rotation[0], rotation[n - 1] = [1, n - 1, n - 2, half - 1], [n - 2, half, half - 1, 0]
        rotation[half - 1], rotation[half] = [half - 2, half, 0, n - 1], [half - 1, half + 1, n - 1, half - 2]
    return _world(rotation, 1)


def circulant(n: int, k: int) -> World:
    """The circulant C_n(1, k) (n ≥ 5, 2 ≤ k < n/2): place ``i`` lists clockwise ``i+1, i−1, i−k, i+k`` (mod n);
    started at place 0 facing place n−1.  4-regular, m = 2n."""
    n = integer_param("n", n, 5)
    k = integer_param("k", k, 2)
    if 2 * k >= n:
        raise InvalidInput(f"circulant: k must be < n/2 (k = {k}, n = {n}): i ± k would repeat or meet i ± 1")
    check_size(n, 2 * n, f"circulant:n={n},k={k}")
    return _world({i: [(i + 1) % n, (i - 1) % n, (i - k) % n, (i + k) % n] for i in range(n)}, n - 1)


def k5e_chain(gadgets: int) -> World:
    """A chain of ``gadgets`` ≥ 1 copies of K5 − e, started at place 0 (an end) facing place 1.

    Copy t has places a = 5t, b, c, d = 5t+1, 5t+2, 5t+3 and e = 5t+4: every pair joined but a–e, and e joined
    to the next copy's a.  Clockwise: a lists (previous e,) b, d, c; b lists a, c, e, d; c lists a, b, e, d; d
    lists a, b, e, c; e lists b, c, (next a,) d.  n = 5·gadgets, m = 10·gadgets − 1.
    """
    g = integer_param("gadgets", gadgets, 1)
    check_size(5 * g, 10 * g - 1, f"k5e-chain:gadgets={g}")
    rotation: dict[int, list[int]] = {}
    for t in range(g):
        a, b, c, d, e = range(5 * t, 5 * t + 5)
        rotation[a] = ([a - 1] if t else []) + [b, d, c]
        rotation[b], rotation[c], rotation[d] = [a, c, e, d], [a, b, e, d], [a, b, e, c]
        rotation[e] = [b, c] + ([e + 1] if t + 1 < g else []) + [d]
    return _world(rotation, 1)


def cylinder(rings: int, size: int) -> World:
    """C_size × P_rings: ``rings`` ≥ 2 rings of ``size`` ≥ 3 places, started at place 0 (first ring) facing place 1.

    Place ``r·size + s`` (ring r, position s) lists clockwise the place above (ring r+1), ring position s−1,
    ring position s+1, the place below (ring r−1), each that exists.  n = rings·size, m = size·(2·rings − 1).
    """
    rings = integer_param("rings", rings, 2)
    size = integer_param("size", size, 3)
    check_size(rings * size, size * (2 * rings - 1), f"cylinder:rings={rings},size={size}")
    rotation: dict[int, list[int]] = {}
    for r in range(rings):
        for s in range(size):
            above = [(r + 1) * size + s] if r + 1 < rings else []
            below = [(r - 1) * size + s] if r else []
            rotation[r * size + s] = above + [r * size + (s - 1) % size, r * size + (s + 1) % size] + below
    return _world(rotation, 1)
