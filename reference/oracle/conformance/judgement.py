"""Whose bound a conformance case holds a program to, and which variant its reference run was made with
(thesis §3.1.2 for the cost; Algorithm 3.1's (3.1)+(3.2), §3.5.2; Table 6.3 for the threads).

Two judgements are kept apart:

* **FAIL** — only what the thesis forbids: a wrong map, a broken run, or a
  cost above a bound *of the thesis's own listing*: one the thesis states
  (``source`` ``thesis``) or one topomark derives for the listing as written
  (``listing``: ``docs/bounds.md``, checked against a literal run of the
  listing on every small world of a family).  Such a bound *binds*.
* **difference** — a correct map whose cost is above topomark's own figure for
  its variant of the listing (its reference run on the case, when that run is
  made with a variant that changes the listing; or a bound topomark states for
  its variant only, ``source`` ``variant``) but within any binding bound: the
  program is not topomark's variant, and may still be the thesis's algorithm.
  The row passes and reports both figures.

A case of a ``topomark/conformance@2`` suite written by version 2.1 or later
carries ``bound_source`` (:func:`bound_source_json`) and ``variant``
(:meth:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec.variant_json`).
A case of an older 2.0 suite has neither: its bound's source was not recorded,
so it is not taken to bind (a cost above it is a difference) and its reference
run's variant is unknown.

>>> bound_source_json("listing", "2(n − 1) + (m − n + 1)(n + 2)")["author"]
'topomark'
"""

from __future__ import annotations

from typing import Any

from topomark.reference.algorithms.algorithm_spec import BOUND_SOURCES, AlgorithmSpec

__all__ = ["SOURCES", "bound_source_json", "spec_bound_source", "binding_bound", "bound_words", "difference",
           "variant_words"]

SOURCES = tuple(BOUND_SOURCES)
"""The values of a case's ``bound_source.source``."""
_UNRECORDED = "a bound whose source the suite does not record (a topomark/conformance 2.0 suite)"


def bound_source_json(source: str, formula: str | None) -> dict[str, Any]:
    """A case's ``bound_source``: who states the bound (``author``), what it bounds (``bounds``), whether it
    binds a program (``binds``), the phrase messages quote (``whose``) and the formula with its references."""
    return {"source": source, "author": "the thesis" if source == "thesis" else "topomark",
            "bounds": "topomark's variant" if source == "variant" else "the thesis's listing",
            "binds": source != "variant", "whose": BOUND_SOURCES[source], "formula": formula}


def spec_bound_source(spec: AlgorithmSpec) -> dict[str, Any] | None:
    """The ``bound_source`` of a case of ``spec``'s suite, or None when it has no exact bound."""
    return None if spec.bound_fn is None else bound_source_json(spec.bound_source, spec.bound_formula)


def binding_bound(case: dict[str, Any]) -> int | None:
    """The bound a case holds a program to (a cost above it FAILs), or None: no bound, or one that does not
    bind (topomark's bound for its variant, or one whose source is not recorded)."""
    source = case.get("bound_source")
    return case["bound"] if source is not None and source.get("binds") else None


def bound_words(case: dict[str, Any]) -> str:
    """Whose the case's bound is and what it bounds, for a message or a legend."""
    source = case.get("bound_source")
    return _UNRECORDED if source is None else source["whose"]


def variant_words(case: dict[str, Any], algorithm: str) -> str:
    """Which explorer made the case's reference run: ``"thread-circumference (topomark's variant)"``."""
    variant = case.get("variant")
    follows = "its variant not recorded" if variant is None else variant["follows"]
    return f"{algorithm} ({follows})"


def difference(case: dict[str, Any], algorithm: str, cost: int) -> dict[str, Any] | None:
    """How a correct map's ``cost`` differs from topomark's variant without breaking a binding bound, or None.

    Above the reference cost of a run made with topomark's variant (one that changes the listing), or above a
    bound that does not bind: the two figures, whose each is, and a sentence saying so."""
    limit = binding_bound(case)
    if limit is not None and cost > limit:
        return None  # a FAIL, not a difference
    variant = case.get("variant")
    reference = case["reference"]["cost"]
    ours = variant is not None and variant["follows"] == "topomark's variant" and cost > reference
    over = case["bound"] is not None and limit is None and cost > case["bound"]
    if not (ours or over):
        return None
    figure, what = ((case["bound"], bound_words(case)) if over else
                    (reference, f"the cost of topomark's run of {variant_words(case, algorithm)} on this case"))
    within = (f"within {limit}, {bound_words(case)}" if limit is not None else
              "no bound of the thesis's listing is stated here")
    return {"cost": cost, "variant_figure": figure, "variant_figure_is": what, "listing_bound": limit,
            "message": f"a difference, not a failure: the map is right and it cost {cost} edge traversals, more "
                       f"than {figure} ({what}), {within}"}
