"""How large a worst-case search or census may be asked to be: bounds refused before any work (thesis §7.2).

Every size option has an upper bound, checked before anything is planned, so a command either fits in memory
or stops at once with exit 2 naming the option.  This module imports nothing heavy: the option modules of the
command line import it to state the bounds in ``--help``.

* **Exhaustive** (``worst-case --max-vertices N --max-degree D``, ``census``): the plan lists every graph's
  rotation systems in tasks of about 2,000 worlds, so its memory (and the manifest written to disk) grows with
  the number of worlds the enumeration produces (:func:`topomark.proofs.census_map.plan`'s estimate: rotation
  systems over automorphisms).  The bound is :data:`MAX_WORLDS` estimated worlds at the largest n; as those
  numbers need the graphs of n vertices (seconds to compute at n = 8), they are kept as a table,
  :data:`LARGEST_DEGREE`: the largest degree allowed at each n (tests/test_worst_case_hostile.py recomputes the
  estimates and checks the table against them).  Estimated worlds at the table's edges:
  n = 7: 212,415 at D = 4, 193,668,931 at D = 5; n = 8: 7,137,879 at D = 4, 60,210,762,463 at D = 5;
  n = 9 (census only): 10,468 at D = 3, 267,180,162 at D = 4; n = 10 (census only): 61,782 at D = 3.
* **Search** (``worst-case --search``): the first generation holds a quarter of ``--evaluations`` worlds of
  ``--vertices`` vertices at once, so memory grows with their product: ``--vertices`` ≤
  :data:`MAX_SEARCH_VERTICES`, ``--evaluations`` ≤ :data:`MAX_EVALUATIONS`, and their product ≤
  :data:`MAX_SEARCH_PRODUCT`.

Examples
--------
>>> exhaustive_refusal(8, 4) is None, exhaustive_refusal(6, 9) is None
(True, True)
>>> exhaustive_refusal(7, 6)
'--max-degree 6 with --max-vertices 7 enumerates more than 100,000,000 worlds at n = 7 (at most 4 there; the largest degree at each n: 2-6: any, 7: 4, 8: 4, 9: 3, 10: 3)'
>>> print(search_refusal(20, 1_000_000))
--evaluations 1000000 is more than 100,000 (the search holds a quarter of its runs' worlds at once)
"""

from __future__ import annotations

from topomark.spec.spelling import option

__all__ = ["MAX_EXHAUSTIVE", "MAX_WORLDS", "LARGEST_DEGREE", "MAX_SEARCH_VERTICES", "MAX_EVALUATIONS",
           "MAX_SEARCH_PRODUCT", "exhaustive_refusal", "search_refusal", "degree_table"]

MAX_EXHAUSTIVE = 8  # the worst case's exhaustive search reaches n = 8
MAX_WORLDS = 100_000_000
"""The most worlds (estimated) an exhaustive search or census may enumerate at its largest n."""

LARGEST_DEGREE = {7: 4, 8: 4, 9: 3, 10: 3}
"""The largest degree allowed at each n (any below 7): the largest D whose estimated worlds at n stay within
:data:`MAX_WORLDS`."""

MAX_SEARCH_VERTICES = 500
MAX_EVALUATIONS = 100_000
MAX_SEARCH_PRODUCT = 2_000_000
"""The most ``--vertices`` × ``--evaluations`` of one size of ``worst-case --search``."""


def degree_table() -> str:
    return "2-6: any, " + ", ".join(f"{n}: {d}" for n, d in sorted(LARGEST_DEGREE.items()))


def exhaustive_refusal(max_vertices: int, max_degree: int) -> str | None:
    """Why ``--max-vertices``/``--max-degree`` would enumerate too many worlds, or None if they fit."""
    largest = LARGEST_DEGREE.get(max_vertices)
    degree = min(max_degree, max_vertices - 1)  # a degree above n - 1 is n - 1
    if largest is None or degree <= largest:
        return None
    return (f"{option('max-degree', max_degree)} with {option('max-vertices', max_vertices)} enumerates more than {MAX_WORLDS:,} worlds "
            f"at n = {max_vertices} (at most {largest} there; the largest degree at each n: {degree_table()})")


def search_refusal(vertices: int, evaluations: int) -> str | None:
    """Why one size of ``--search`` would not fit in memory, or None if it fits."""
    if vertices > MAX_SEARCH_VERTICES:
        return f"{option('vertices', vertices)} is more than {MAX_SEARCH_VERTICES:,} (the search's largest world size)"
    if evaluations > MAX_EVALUATIONS:
        return (f"{option('evaluations', evaluations)} is more than {MAX_EVALUATIONS:,} (the search holds a quarter of its "
                "runs' worlds at once)")
    if vertices * evaluations > MAX_SEARCH_PRODUCT:
        return (f"{option('vertices', vertices)} with {option('evaluations', evaluations)}: their product is more than "
                f"{MAX_SEARCH_PRODUCT:,} (the search holds a quarter of its runs' worlds at once)")
    return None
