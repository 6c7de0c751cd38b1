"""How many embedded worlds there are, counted without listing them: Burnside's lemma (thesis §3.1.1, §3.1.3).

:mod:`topomark.proofs.enumerate` lists one world per extended-isomorphism
class: per connected graph G (no start, no markers, mirror images distinct),
one rotation system per orbit of Aut(G) acting on G's ``∏ (deg v - 1)!``
rotation systems by ``(σR)_{σ(v)} = σ ∘ R_v ∘ σ⁻¹``.  What is counted
(thesis §3.1.3, §3.2.2 footnote 8): two worlds are the same when extended-isomorphic, a graph
isomorphism that keeps at every vertex the order of the exits "labelled
starting from different reference edges" under "the same pre-defined
enumeration rule" — so a rotation, never a reversal: a mirror image is another
world unless the two are isomorphic.  No start and no markers: the census
adds those per world.  This module counts
the same orbits a second, independent way (its graphs and automorphism groups
come from :mod:`topomark.proofs.graphs`, not from the atlas or networkx's
matcher):

    orbits(G) = (1 / |Aut G|) · Σ_{σ ∈ Aut G} Fix(σ)

and Fix(σ), the number of rotation systems with σR = R, is a product over the
cycles of σ on the vertices.  On a cycle ``v, σv, …, σ^{k-1}v`` the cyclic
order at v determines the others (``R_{σv} = σ R_v σ⁻¹``), and going round
must give it back: ``R_v`` must commute with ``τ = σ^k`` restricted to N(v).
A cyclic order ρ on d points commutes with τ iff τ is a power of ρ (the
centraliser of a d-cycle is the group it generates), so the count is

* ``(d - 1)!`` when τ is the identity;
* ``φ(L) · (g - 1)! · L^(g-1)`` when τ has g cycles all of one length
  L > 1 (d = gL): for each of the φ(L) exponents u coprime to L, the
  d-cycles ρ with ``ρ^g = τ^u`` interleave τ's cycles: (g - 1)! orders of
  the cycles after the one holding the least point, L starting points each;
* 0 otherwise.

(tests/test_burnside.py checks this per-vertex count against all cyclic
orders, and Fix(σ) against every rotation system, on graphs with symmetry.)

Examples
--------
>>> count_by_size(7, 4)
{2: 1, 3: 2, 4: 9, 5: 275, 6: 7229, 7: 213986}
>>> count_by_size(5, 3)
{2: 1, 3: 2, 4: 9, 5: 22}
"""

from __future__ import annotations

import math
from fractions import Fraction

from topomark.proofs.graphs import GraphClass, classes
from topomark.spec.errors import InvalidInput

__all__ = ["commuting_cyclic_orders", "fixed_rotation_systems", "worlds_on", "count_by_size"]


def commuting_cyclic_orders(tau: dict[int, int]) -> int:
    """How many cyclic orders of ``tau``'s points commute with the permutation ``tau``."""
    d = len(tau)
    lengths = []
    seen: set[int] = set()
    for start in tau:
        if start in seen:
            continue
        length, x = 0, start
        while x not in seen:
            seen.add(x)
            x = tau[x]
            length += 1
        lengths.append(length)
    if all(length == 1 for length in lengths):
        return math.factorial(max(d - 1, 0))
    if len(set(lengths)) > 1:
        return 0
    big_l, g = lengths[0], len(lengths)
    phi = sum(1 for u in range(1, big_l) if math.gcd(u, big_l) == 1)
    return phi * math.factorial(g - 1) * big_l ** (g - 1)


def fixed_rotation_systems(c: GraphClass, sigma: tuple[int, ...]) -> int:
    """Fix(σ): how many rotation systems of ``c`` the automorphism ``sigma`` maps to themselves."""
    total = 1
    seen: set[int] = set()
    for v in range(c.n):
        if v in seen:
            continue
        k, x = 0, v
        while x not in seen:
            seen.add(x)
            x = sigma[x]
            k += 1
        tau = {}
        for w in c.neighbours(v):
            y = w
            for _ in range(k):
                y = sigma[y]
            tau[w] = y
        total *= commuting_cyclic_orders(tau)
        if total == 0:
            return 0
    return total


def worlds_on(c: GraphClass) -> int:
    """The number of Aut-orbits of rotation systems of one graph (Burnside's lemma)."""
    orbits = Fraction(sum(fixed_rotation_systems(c, s) for s in c.automorphisms), len(c.automorphisms))
    if orbits.denominator != 1:  # Burnside's sum is always a multiple of |G|
        raise ArithmeticError(f"Burnside's lemma gave a non-integer {orbits} on {c.adjacency}")
    return int(orbits)


def count_by_size(max_vertices: int, max_degree: int, min_vertices: int = 2) -> dict[int, int]:
    """Embedded worlds with n vertices, for each ``min_vertices ≤ n ≤ max_vertices``, by Burnside's lemma.

    The same numbers as :func:`topomark.proofs.enumerate.count_by_size`, without listing a world.
    """
    if max_degree < 1:
        raise InvalidInput(f"max degree must be at least 1, not {max_degree}")
    if max_vertices < 2:
        raise InvalidInput(f"max vertices must be at least 2 (a world has two or more vertices), not {max_vertices}")
    return {n: sum(worlds_on(c) for c in classes(n, max_degree))
            for n in range(max(min_vertices, 2), max_vertices + 1)}
