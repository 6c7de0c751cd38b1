"""What the worst-case report says per algorithm, in three sentences: proved, shown, and what it means for §7.2.

§7.2 asks whether the O(m²n) bound of Algorithm 3.1 (§3.5.2) is tight, for which classes of graphs, and whether
a bound in the diameter or the maximum degree could hold.  :func:`verdicts` answers per algorithm from the runs
the report summarises, each sentence from its own evidence:

* **proved** — the exhaustive runs: the largest cost / exact bound over every world up to their size, exact;
  for ``basic`` also the lower bound :mod:`.lower_bound` proves at every n on the circulant C_n(1, 2);
* **shown** — the search runs: the best world found per size (a lower bound on the worst case), its cost / exact
  bound and its generator text; for ``basic`` also the strip's cost formula
  (:func:`~.family_costs.strip_cost`, fitted on the sizes up to 60 and checked at every size from 9 to 200), for
  ``case-1a`` and ``case-4`` the split strip's (:func:`~.family_costs.split_strip_cost`, checked at every even
  size from 18 to 300).  Both formulas are measured at those sizes, not proved for every n, and the report says
  so.  For ``enh1``, ``enh2`` and ``enh3`` the pendant strip's costs (:data:`~.family_costs.PENDANT_COSTS`, no
  formula), whose cost / bound rises from each size run to the next (:func:`pendant_statement`);
* **says** — what that means for the thesis's questions, stated no further than the evidence goes: a ratio that
  does not fall as n grows on worlds of maximum degree 4 says the algorithm's bound (O(m²n) for Algorithm 3.1
  and Chapter 4, O(mn) for the footprint searches of §6.2.1) is tight up to a constant there,
  so no bound in the degree alone can be smaller; worlds that all have diameter Θ(n) leave a bound in the
  diameter open.

>>> verdicts([], [])
[]
"""

from __future__ import annotations

import re
from typing import Any, Iterable

__all__ = ["verdicts", "best_per_size", "one_per_size", "STRIP_STATEMENT", "STRIP_SAYS", "SPLIT_STATEMENT",
           "SPLIT_SAYS", "FORMULAS", "CIRCULANT_PROOF", "PROOFS", "pendant_statement"]

STRIP_STATEMENT = ("on the triangulated strip `strip:n=N` (maximum degree 4, m = 2n − 3, diameter ⌊n/2⌋, "
                   "the start at an end) the cost is a cubic in n per n mod 6, 23/24·n³ + O(n²), at every n from 9 "
                   "to 200 (fitted on n ≤ 60, each size run; measured, not proved for larger n), so cost / bound "
                   "rises there towards 23/112 ≈ 0.205")

STRIP_SAYS = ("says: on worlds of maximum degree 4 the O(m²n) bound is tight up to a constant factor, proved at "
              "every n by the circulant (at least 5/112 of the bound as n grows) and measured on the strip, whose "
              "cost grows as m²n at every size run; so no bound in the degree alone below it fits them; and on "
              "the chorded cycle `chorded-cycle:n=N,seed=S`, of diameter 3 to 7 from n = 20 to 300, the cost "
              "grows as n³ too (measured, about 0.12 of the bound), so no bound of the form O(m²·diameter) fits "
              "either")

CIRCULANT_PROOF = ("proved for every n ≥ 5 (`topomark.reference.worstcase.lower_bound`): on the 4-regular "
                   "circulant `circulant:n=N,k=2` (m = 2n, diameter ⌈⌊n/2⌋/2⌉, the default policies) the cost "
                   "is at least (5n³ − 9n² − c₁n + c₀)/24 with c₁, c₀ fixed by n mod 4, so at least 5/112 ≈ 0.045 "
                   "of the bound as n grows")

PROOFS = {"basic": CIRCULANT_PROOF}
"""algorithm ↦ a lower bound proved at every n (:mod:`.lower_bound`), added to the exhaustive runs' proof."""

SPLIT_STATEMENT = ("on the split strip `split-strip:n=N` (maximum degree 4, m = 2n − 3, diameter Θ(n), the start "
                   "at an end) the cost is (5n² − 31n + c)/4 with c fixed by n mod 8 at every even n from 18 to "
                   "300 (each size run; measured, not proved for larger n), so cost / bound rises there towards "
                   "5/16 = 0.3125")

SPLIT_SAYS = ("says: on the split strip the cost grows as mn at every size run, so on worlds of maximum degree 4 "
              "the O(mn) bound is tight up to a constant factor as far as the runs go (for every n if the formula "
              "holds for every n, which is not proved); its diameter is Θ(n), so whether a bound in the diameter "
              "holds stays open")

FORMULAS = {"basic": (STRIP_STATEMENT, STRIP_SAYS), "case-1a": (SPLIT_STATEMENT, SPLIT_SAYS),
            "case-4": (SPLIT_STATEMENT, SPLIT_SAYS)}
"""algorithm ↦ (a family's cost formula, what it says): the families whose cost a formula gives exactly at every
size run (:mod:`.family_costs`): measured, not proved for every n."""


def pendant_statement(algorithm: str) -> tuple[str, str] | None:
    """(what the pendant strip shows for ``algorithm``, what it says), from :data:`~.family_costs.PENDANT_COSTS`;
    None for an algorithm it was not run for, or if its cost / bound does not rise from each size to the next."""
    from topomark.reference.worstcase.family_costs import PENDANT_ALGORITHMS, pendant_ratios
    if algorithm not in PENDANT_ALGORITHMS:
        return None
    ratios = pendant_ratios(algorithm)
    if any(b <= a for (_, a), (_, b) in zip(ratios, ratios[1:])):
        return None
    shown = ", ".join(f"{float(r):.4f}" for _, r in ratios)
    sizes = ", ".join(str(n) for n, _ in ratios)
    return (f"on the pendant strip `pendant-strip:n=N` (maximum degree 4, m about 1.8 n, diameter about n/3, the "
            f"start at the end of its stem) cost / bound rises from each size run to the next: {shown} at n = "
            f"{sizes} (each size run; measured, no formula)",
            "says: on the pendant strip the cost grows as m²n at every size run, so on worlds of maximum degree 4 "
            "the O(m²n) bound is tight up to a constant factor for this enhancement too, as far as the runs go, "
            "and no bound in the degree alone below it fits them; the pendant strip's diameter is Θ(n), so "
            "whether a bound in the diameter holds stays open")


def _order(algorithm: str) -> str:
    """The order of ``algorithm``'s bound as its registration states it (``O(m²n)``, ``O(mn)``, …)."""
    from topomark.reference.algorithms.registry import algorithm_spec  # the registry: only when a report is made
    found = re.search(r"O\([^)]*\)", algorithm_spec(algorithm).bound or "")
    return found.group(0) if found else "stated"


def _proved(runs: list[dict[str, Any]]) -> str | None:
    rows = [(r["ratio_exact"][0] / r["ratio_exact"][1], r["n"], d["max_degree"]) for d in runs for r in d["per_n"]
            if r["n"] >= 4 and r.get("ratio_exact")]
    if not rows:
        return None
    top = max(rows)
    sizes = max(r[1] for r in rows)
    return (f"proved (every world up to n = {sizes}): the largest cost is {top[0]:.4f} of the exact bound "
            f"(at n = {top[1]}, degree ≤ {top[2]})")


def _rank(s: dict[str, Any]) -> tuple[bool, float, int]:
    """Which of two worlds found at one size is the better: the larger cost / exact bound (a world without one
    ranks below every world with one), then the larger cost."""
    return s.get("ratio_to_bound") is not None, s.get("ratio_to_bound") or 0.0, s["cost"]


def _best_by(found: Iterable[tuple[Any, dict[str, Any]]]) -> dict[Any, dict[str, Any]]:
    """key ↦ the best world (:func:`_rank`) of the (key, world) pairs ``found``."""
    best: dict[Any, dict[str, Any]] = {}
    for key, s in found:
        if key not in best or _rank(s) > _rank(best[key]):
            best[key] = s
    return best


def best_per_size(searched: list[dict[str, Any]]) -> dict[tuple[str, int], dict[str, Any]]:
    """(algorithm, n) ↦ the best world found there over every search run (the ``lattice-hole`` family left out):
    the largest cost / exact bound, the larger cost between equal ratios.  The verdict's figure and the world its
    generator text names are the same world, and the same rule as the families page (the largest ratio)."""
    return _best_by(((d["algorithm"], r["n"]), r["search"]["best"]) for d in searched for r in d["per_n"]
                    if r["search"].get("best") and r["search"]["best"].get("ratio_to_bound") is not None
                    and not d.get("family"))


def one_per_size(found: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The best of the worlds ``found`` (each with its ``n``) at each size, by n, ranked as :func:`best_per_size`
    ranks them: the points a growth fit may use, one per size."""
    best = _best_by((s["n"], s) for s in found)
    return [best[n] for n in sorted(best)]


def _shown(runs: list[dict[str, Any]], names: dict[tuple[str, int], str | None]) -> tuple[str | None, list[float]]:
    best = sorted(best_per_size(runs).items(), key=lambda item: item[0][1])  # one algorithm's runs: by n
    if not best:
        return None, []
    parts = [f"n = {key[1]}: {s['ratio_to_bound']:.4f}" + (f" (`{names[key]}`)" if names.get(key) else "")
             for key, s in best]
    return "shown (the best world found per size, cost / exact bound): " + "; ".join(parts), \
        [s["ratio_to_bound"] for _, s in best]


def _says(ratios: list[float], degree: int | None, bound: str) -> str:
    if len(ratios) < 2:
        return "says: too few sizes searched to tell how cost / bound moves with n"
    falling = any(b < a for a, b in zip(ratios, ratios[1:]))
    if falling:
        return ("says: cost / bound falls somewhere over the sizes searched, so these worlds do not show the "
                f"{bound} bound tight; the search may have missed worse worlds")
    return (f"says: cost / bound does not fall with n on worlds of maximum degree {degree}, so the {bound} bound "
            "is reached up to a constant factor there and no bound in the degree alone can be smaller; every world "
            "shown has diameter Θ(n), so whether a bound in the diameter holds stays open")


def verdicts(exhaustive: list[dict[str, Any]], searched: list[dict[str, Any]],
             names: dict[tuple[str, int], str | None] | None = None) -> list[str]:
    """One line per algorithm: ``- `name`: proved …; shown …; says …`` (the parts it has evidence for).
    ``names`` maps (algorithm, n) to the generator text of the best world found there, if it has one."""
    names = names or {}
    out = []
    for algorithm in sorted({d["algorithm"] for d in exhaustive} | {d["algorithm"] for d in searched}):
        proved = _proved([d for d in exhaustive if d["algorithm"] == algorithm])
        if algorithm in PROOFS:
            proved = f"{proved}; and {PROOFS[algorithm]}" if proved else PROOFS[algorithm]
        runs = [d for d in searched if d["algorithm"] == algorithm and not d.get("family")]
        shown, ratios = _shown(runs, names)
        statement, said = FORMULAS.get(algorithm) or pendant_statement(algorithm) or (None, None)
        if statement:
            shown = f"{shown}; and {statement}" if shown else f"shown: {statement}"
        degree = max((d["max_degree"] for d in runs), default=None)
        says = said or (_says(ratios, degree, _order(algorithm)) if runs else None)
        parts = [p for p in (proved, shown, says) if p]
        out.append(f"- `{algorithm}`: " + ". ".join(p[0].upper() + p[1:] for p in parts) + ".")
    return out
