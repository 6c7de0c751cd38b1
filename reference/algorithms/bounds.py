"""Cost bounds of Algorithm 3.1 (thesis §3.5.1–3.5.2).

* lower bound: m — every edge must be traversed (§3.1.2, §3.5.1);
* upper bound: expressions (3.1) + (3.2), evaluated exactly;
* (3.3): the leading terms 2m²n − 2mn² + ⅔n³ − 2m² − 5/2 n², as plotted in
  the thesis's figures (lower-order terms ignored).

>>> upper_bound(3, 3)  # a triangle: (3.1) = 1 + 10, (3.2) = 3 + 8
22
"""

from __future__ import annotations

from fractions import Fraction

__all__ = ["lower_bound", "upper_bound", "expression_3_1", "expression_3_2", "expression_3_3"]


def lower_bound(n: int, m: int) -> int:
    return m


def expression_3_1(n: int, m: int) -> int:
    """Σ_{n_s=1}^{n-1} [n_s + 2(n_s − 1)(2m − 2(n_s − 1))]: the n − 1 non-loop iterations."""
    return sum(ns + 2 * (ns - 1) * (2 * m - 2 * (ns - 1)) for ns in range(1, n))


def expression_3_2(n: int, m: int) -> int:
    """Σ_{i=1}^{m-n+1} [n + 2(n − 1)(2m − 2(n − 1) − 2(i − 1))]: the m − n + 1 loop iterations."""
    return sum(n + 2 * (n - 1) * (2 * m - 2 * (n - 1) - 2 * (i - 1)) for i in range(1, m - n + 2))


def upper_bound(n: int, m: int) -> int:
    """(3.1) + (3.2), exactly."""
    return expression_3_1(n, m) + expression_3_2(n, m)


def expression_3_3(n: int, m: int) -> Fraction:
    """The leading terms (3.3) of the bound, as the thesis plots it."""
    return 2 * m * m * n - 2 * m * n * n + Fraction(2, 3) * n ** 3 - 2 * m * m - Fraction(5, 2) * n * n
