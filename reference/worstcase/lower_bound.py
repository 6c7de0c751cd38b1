"""A proved lower bound: Algorithm 3.1 costs Ω(n³) = Ω(m²n) on the 4-regular circulant C_n(1, 2), so its O(m²n)
bound is tight up to a constant factor on worlds of maximum degree 4 (thesis §3.4, §3.5.2, §7.2).

§7.2 asks whether the O(m²n) bound of §3.5.2 is tight.  The families of
:mod:`.family_costs` cost a constant share of it at every size *run*; the
argument here proves a share at *every* n, for ``basic`` with its default
policies on ``circulant:n=N,k=2``
(:func:`~topomark.reference.worlds.expensive.circulant`: place ``i`` lists
clockwise ``i+1, i−1, i−2, i+2`` mod n; the robot starts at 0 facing n−1).

**Lemma A (a rejected hypothesis).**  In a world whose places all have degree
4 and where only v0 is marked, a false hypothesis whose path to v0 in S has ℓ
edges costs at least 2·min(ℓ, dist(v_u, v0)) traversals, dist measured in the
world.  Its walk (Algorithm 3.1, lines 11–16) senses degree 4 and no mark,
exactly as P^E expects, at every place but v0; so it stops only on reaching
v0 (at least dist(v_u, v0) motions) or after its ℓ motions, and line 17
retraces every motion made.

**Lemma B (the first walk).**  From its start the robot discovers n−1, n−2,
…, 1 in its first n − 1 iterations, in that order, and every one is a
non-loop iteration.  Iteration 0 takes v0's faced exit (U's first entry) to
n−1.  At v_k = n−k, entered from n−k+1 = v_k + 1, exit 1 (the next clockwise)
leads to v_k − 1 = v_{k+1}, and ``nearest`` takes it: v_k's exits 1, 2, 3 are
the only entries of U at distance 0 from the robot, appended in that order
(lines 27–28).  v_{k+1} is not yet in S, so every hypothesis is false, and none
is accepted (a hypothesis is identified by its motions and expected
perceptions, Lemma 1 and §3.4): all are rejected.

**The bound.**  At iteration k (1 ≤ k ≤ n − 2), S is the path v0 … v_k and U
holds exits 2 and 3 of each of v_1 … v_k besides v0's three.  H is those of
v_1 … v_{k−1} (v0's read its marker, v_k's are excluded, line 8): 2(k − 1)
false hypotheses, the two at v_j with a path of j edges.  With
D_k = dist(v_{k+1}, v0) = ⌈min(k + 1, n − 1 − k)/2⌉ in C_n(1, 2), Lemma A
gives

    cost ≥ Σ_{k=1}^{n−2} [1 + 4·Σ_{j=1}^{k−1} min(j, D_k)]     (:func:`circulant_bound`)

which is a quasi-polynomial of degree 3 and period 4 in n (the limits of its
pieces are linear in n with one halving), so four values per residue fix it:

    24·bound = 5n³ − 9n² − c₁n + c₀   ((c₁, c₀) = (20, 48), (29, 105), (20, 36), (17, 21) for n ≡ 0, 1, 2, 3 mod 4)

(:func:`circulant_bound_formula`, equal to the sum at every n from 5 to
2,000 in the tests).  With m = 2n the bound (3.1)+(3.2) is 14n³/3 + O(n²),
so Algorithm 3.1 costs at least 5/112 ≈ 0.045 of it as n grows, at every n:
Θ(m²n) on worlds of maximum degree 4.  The runs cost more (0.155 of the bound
at n = 100: not every walk stops at D_k), and the strip more still (0.205,
measured); the proof gives the order, not the constant.

Examples
--------
>>> [circulant_bound(n) for n in (5, 6, 7, 8)]
[15, 28, 49, 78]
>>> all(circulant_bound(n) == circulant_bound_formula(n) for n in range(5, 60))
True
"""

from __future__ import annotations

from fractions import Fraction

__all__ = ["first_walk_bound", "circulant_distances", "circulant_bound", "circulant_bound_formula", "CIRCULANT_FROM"]

CIRCULANT_FROM = 5
"""The least n of ``circulant:n=N,k=2`` (k < n/2)."""

_TERMS = {0: (20, 48), 1: (29, 105), 2: (20, 36), 3: (17, 21)}
"""(c₁, c₀) of 24·bound = 5n³ − 9n² − c₁n + c₀, per n mod 4."""


def first_walk_bound(distances: list[int]) -> int:
    """Σ_k [1 + 4·Σ_{j=1}^{k−1} min(j, D_k)] over k = 1, 2, … with ``distances[k − 1]`` = D_k: Lemma A's bound on
    the non-loop iterations of a first walk v0, v1, … in a 4-regular world, D_k the world distance of v_{k+1}
    from v0."""
    assert all(d >= 1 for d in distances), "every new place is at distance >= 1 from v0"
    total = 0
    for k, d in enumerate(distances, start=1):
        below = min(d, k - 1)  # j = 1 … below count j; the others count d
        total += 1 + 4 * (below * (below + 1) // 2 + (k - 1 - below) * d)
    return total


def circulant_distances(n: int) -> list[int]:
    """D_k = ⌈min(k + 1, n − 1 − k)/2⌉ for k = 1 … n − 2: the distance in C_n(1, 2) from v_{k+1} = n − 1 − k to 0."""
    assert n >= CIRCULANT_FROM, f"circulant:n=N,k=2 needs n >= {CIRCULANT_FROM}"
    return [-(-min(k + 1, n - 1 - k) // 2) for k in range(1, n - 1)]


def circulant_bound(n: int) -> int:
    """Lemma A's bound on the first walk of ``basic`` on ``circulant:n=N,k=2``: a lower bound on its cost."""
    return first_walk_bound(circulant_distances(n))


def circulant_bound_formula(n: int) -> int:
    """(5n³ − 9n² − c₁n + c₀)/24, the closed form of :func:`circulant_bound` (exact, an integer)."""
    assert n >= CIRCULANT_FROM, f"circulant:n=N,k=2 needs n >= {CIRCULANT_FROM}"
    c1, c0 = _TERMS[n % 4]
    value = Fraction(5 * n**3 - 9 * n**2 - c1 * n + c0, 24)
    assert value.denominator == 1, f"24·bound is a multiple of 24 at n = {n}"
    return int(value)
