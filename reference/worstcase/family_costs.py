"""What Algorithm 3.1 costs on the triangulated strip, exactly at every size run, and why that cost keeps within a
constant factor of the (3.1)+(3.2) bound (thesis §3.5.2, §7.2).

§7.2 asks whether the O(m²n) bound of §3.5.2 is tight, and for which graphs.
On the strip P_n² (:func:`~topomark.reference.worlds.expensive.strip`: m =
2n − 3, maximum degree 4, started at an end) ``basic`` with its default
policies costs exactly :func:`strip_cost` — a cubic in n for each residue of
n mod 6, measured on every n from 5 to 60 and fitted exactly (four sizes fix
each cubic, the other sizes of its residue check it):

    24·cost = 23n³ − 318n² + 1724n − c₀   (n even; c₀ = 3144, 3176, 3160 for n ≡ 0, 2, 4 mod 6)
    24·cost = 23n³ − 321n² + 1757n − c₁   (n odd;  c₁ = 3355, 3339, 3323 for n ≡ 1, 3, 5 mod 6)

from n = 9 (:data:`STRIP_FROM`), checked against a run at every n from 9
to 200 (the tests).  That is measured, not proved: the explanation below
says why the cost is cubic, but no argument shows the formula at every n.
The bound (3.1)+(3.2) with m = 2n − 3 is 14n³/3 + O(n²), so over those
sizes cost/bound rises towards 23/112 ≈ 0.205: as far as the runs go the
bound is tight up to that constant on this family (diameter Θ(n), degree 4).

Why (the cost breakdown of ``topomark explore --breakdown`` shows it): every
inner place has degree 4 and no marker, so all of them look alike.  Exit 1
at each new place is the next place of the path ``0, 1, …, n−1``, which the
``nearest`` policy follows to its end: S is a path, each inner place keeps two
open exits in U, and at each new place every one of them is a hypothesis
whose walk matches P^E until v0 should appear — case (2) at the end of a walk
as long as its path in S, or case (1) where the real walk, on the way back
along the second side, passes v0 first — each retraced as far.  The rungs and
diagonals left open each join a place x of the way out to n−1−x or n−2−x of
the way back (the path folds back on itself): closing one shortens the paths
to v0 of the places near the walk's far end, and each loop closing tests, in
U's order, the open exits of every place before its v_u.
Measured and fitted the same way, the n − 1 non-loop iterations cost
5/12·n³ + O(n²) and the n − 2 loop iterations 13/24·n³ + O(n²).

The split strip (:func:`~topomark.reference.worlds.split_strip.split_strip`: m = 2n − 3, maximum degree 4)
does for the footprint searches of §6.2.1 what the strip does for ``basic``: Cases 1a and 4 (``case-1a``,
``case-4``, default policies) cost exactly :func:`split_strip_cost`,

    4·cost = 5n² − 31n + c   (c = 12, 14, 8, −6 for n ≡ 0, 2, 4, 6 mod 8)

from n = 18 (:data:`SPLIT_STRIP_FROM`): fitted on three sizes of each
residue and checked against a run at every even n from 18 to 300 (measured,
not proved for larger n).  Their bound (n − 1)² + (m − n + 1)(3n − 1) is
4n² − 9n + 3 here, so cost / bound rises towards 5/16 over those sizes: as
far as the runs go the O(mn) bound of both cases is tight up to that constant
on worlds of maximum degree 4 and diameter Θ(n).  Why: of the n − 2 loops,
about three quarters are validated by a walk of about 1.5 n moves (out along
the breadth-first tree's short branch, back through v_k, along the long one).

The pendant strip (:func:`~topomark.reference.worlds.pendant.pendant_strip`: m about 1.8 n, maximum degree 4)
does it for the Chapter 4 enhancements: :data:`PENDANT_COSTS` holds what ``enh1``, ``enh2`` and ``enh3``
(default policies) cost there at the sizes the tests re-run.  No formula fits them; cost / bound rises from each
of those sizes to the next for all three, so as far as the runs go the O(m²n) bound is tight up to a constant for
them as well (:mod:`~topomark.reference.worlds.pendant` says why).

Examples
--------
>>> strip_cost(10), strip_cost(20)
(220, 3671)
>>> split_strip_cost(50), split_strip_cost(100)
(2741, 11727)
>>> PENDANT_COSTS[100]
(219759, 202499, 200935)
"""

from __future__ import annotations

from fractions import Fraction

from topomark.spec.errors import InvalidInput, TopomarkFault

__all__ = ["strip_cost", "STRIP_FROM", "split_strip_cost", "SPLIT_STRIP_FROM", "PENDANT_COSTS", "PENDANT_ALGORITHMS",
           "pendant_ratios"]

STRIP_FROM = 9
"""The least n the formula of :func:`strip_cost` is measured for (below it the fold and the start overlap)."""

_EVEN = {0: 3144, 2: 3176, 4: 3160}
_ODD = {1: 3355, 3: 3339, 5: 3323}


def strip_cost(n: int) -> int:
    """The cost of ``basic`` (default policies) on ``strip:n=N``, from the exact fit above; n ≥ :data:`STRIP_FROM`."""
    if n < STRIP_FROM:
        raise InvalidInput(f"strip_cost: the formula is measured for n >= {STRIP_FROM}, not n = {n}")
    if n % 2 == 0:
        total = 23 * n**3 - 318 * n**2 + 1724 * n - _EVEN[n % 6]
    else:
        total = 23 * n**3 - 321 * n**2 + 1757 * n - _ODD[n % 6]
    if total % 24:
        raise TopomarkFault(f"strip_cost({n}): 24·cost = {total} is not a multiple of 24: the formula is wrong")
    return total // 24


SPLIT_STRIP_FROM = 18
"""The least n the formula of :func:`split_strip_cost` is measured for (at n = 16 the split meets the start)."""

_SPLIT = {0: 12, 2: 14, 4: 8, 6: -6}


def split_strip_cost(n: int) -> int:
    """The cost of ``case-1a`` and of ``case-4`` (default policies) on ``split-strip:n=N``, from the exact fit
    above; n even, n ≥ :data:`SPLIT_STRIP_FROM`."""
    if n < SPLIT_STRIP_FROM or n % 2:
        raise InvalidInput(f"split_strip_cost: the formula is measured for even n >= {SPLIT_STRIP_FROM}, not "
                           f"n = {n}")
    total = 5 * n**2 - 31 * n + _SPLIT[n % 8]
    if total % 4:
        raise TopomarkFault(f"split_strip_cost({n}): 4·cost = {total} is not a multiple of 4: the formula is wrong")
    return total // 4


PENDANT_ALGORITHMS = ("enh1", "enh2", "enh3")
"""The algorithms whose cost :data:`PENDANT_COSTS` holds, in its tuples' order."""

PENDANT_COSTS: dict[int, tuple[int, int, int]] = {
    20: (1118, 1086, 1086), 50: (22182, 21448, 21448), 100: (219759, 202499, 200935),
    150: (793400, 718460, 713986), 200: (1943779, 1744893, 1739015), 300: (6776543, 6036437, 6027751)}
"""n ↦ the cost of :data:`PENDANT_ALGORITHMS` (default policies) on ``pendant-strip:n=N``: measured by the compiled
engine, re-run by the tests at every one of these sizes (and by the checked reference at n = 50)."""


def pendant_ratios(algorithm: str) -> list[tuple[int, Fraction]]:
    """(n, cost / exact bound) of ``algorithm`` (one of :data:`PENDANT_ALGORITHMS`) at each size of
    :data:`PENDANT_COSTS`, the bound (3.1)+(3.2) taken at the pendant strip's own m."""
    from topomark.reference.algorithms.bounds import upper_bound
    from topomark.reference.worlds.pendant import pendant_strip
    k = PENDANT_ALGORITHMS.index(algorithm)
    return [(n, Fraction(costs[k], upper_bound(n, pendant_strip(n).m))) for n, costs in sorted(PENDANT_COSTS.items())]
