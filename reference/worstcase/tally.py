"""What the worst-case search keeps of its runs, per world size: counts, maxima and the cost/m distribution (§7.2).

A :class:`SizeTally` is what one size n of worlds gave: how many worlds and
runs, how each run ended, the largest cost, the largest cost per edge
(``cost/m``) and the largest ratio of the cost to the algorithm's exact bound,
each with the run that reached it (its *witness*), and every run's
``(m, cost)`` pair counted, from which the distribution of ``cost/m`` is read
exactly (quantiles and histogram).  Tallies of disjoint runs merge
(:meth:`SizeTally.merge`); ties are broken towards the least witness, so the
merged maxima do not depend on the order in which tasks finish.

A witness is ``(gi, rank, vertex, exit)``: the world of rank ``rank`` of graph
``gi`` of :func:`topomark.proofs.enumerate.connected_graphs` (n, D) (the
census's naming, :func:`topomark.proofs.census_map.world_at`) and the start
dart — the robot at ``vertex`` facing its exit ``exit``.

Costs per edge and ratios are compared as fractions (``a/b > c/d`` iff
``a·d > c·b``), never as floats, so a maximum is exact.

Examples
--------
>>> t = SizeTally(4)
>>> t.add_world(); t.add_run((0, 3, "v0", 1), m=5, cost=12, counted=12, bound=40, claimed="correct")
>>> t.add_run((0, 3, "v1", 0), m=5, cost=15, counted=15, bound=40, claimed="correct")
>>> t.max_cost, t.argmax_cost, t.quantiles((0.5, 1.0))
(15, (0, 3, 'v1', 0), [2.4, 3.0])
"""

from __future__ import annotations

import math
from collections import Counter
from fractions import Fraction
from typing import Any

__all__ = ["Witness", "SizeTally", "merge_tallies"]

Witness = tuple[int, int, str, int]


def _better(value: tuple[int, int], witness: Witness, best: tuple[int, int] | None, best_at: Witness | None) -> bool:
    """Whether the fraction ``value`` at ``witness`` beats ``best`` at ``best_at`` (larger, then least witness)."""
    if best is None or best_at is None:
        return True
    left, right = value[0] * best[1], best[0] * value[1]
    return left > right or (left == right and _key(witness) < _key(best_at))


def _key(w: Witness) -> tuple[int, int, int, int]:
    """Witnesses in enumeration order: graph, rank, then the start vertex by number (``v10`` after ``v9``)."""
    return (w[0], w[1], int(w[2].lstrip("v") or 0), w[3])


class SizeTally:
    """The runs on the worlds of one size n (see the module docstring)."""

    def __init__(self, n: int):
        self.n = n
        self.worlds = self.runs = 0
        self.outcomes: Counter[str] = Counter()
        self.pairs: Counter[tuple[int, int]] = Counter()  # (m, cost) of every run that ended correct
        self.max_cost: int | None = None
        self.argmax_cost: Witness | None = None
        self.cost_m: tuple[int, int] | None = None  # (cost, m) of the largest cost/m
        self.argmax_cost_m: Witness | None = None
        self.ratio: tuple[int, int] | None = None  # (counted cost, bound) of the largest ratio
        self.argmax_ratio: Witness | None = None

    def add_world(self) -> None:
        self.worlds += 1

    def add_run(self, witness: Witness, m: int, cost: int, counted: int, bound: int | None, claimed: str) -> None:
        """One run from ``witness``: its cost, the part of it the bound counts, the bound (None: no exact bound)."""
        self.runs += 1
        self.outcomes[claimed] += 1
        if claimed != "correct":
            return  # a run that did not map the world has no cost to compare with a bound
        self.pairs[(m, cost)] += 1
        if _better((cost, 1), witness, None if self.max_cost is None else (self.max_cost, 1), self.argmax_cost):
            self.max_cost, self.argmax_cost = cost, witness
        if _better((cost, m), witness, self.cost_m, self.argmax_cost_m):
            self.cost_m, self.argmax_cost_m = (cost, m), witness
        if bound is not None and _better((counted, bound), witness, self.ratio, self.argmax_ratio):
            self.ratio, self.argmax_ratio = (counted, bound), witness

    def merge(self, other: "SizeTally") -> None:
        """Add the runs of ``other`` (disjoint from ours) to this tally."""
        assert other.n == self.n, f"tallies of sizes {self.n} and {other.n} do not merge"
        self.worlds += other.worlds
        self.runs += other.runs
        self.outcomes.update(other.outcomes)
        self.pairs.update(other.pairs)
        if other.argmax_cost is not None and other.max_cost is not None and _better(
                (other.max_cost, 1), other.argmax_cost,
                None if self.max_cost is None else (self.max_cost, 1), self.argmax_cost):
            self.max_cost, self.argmax_cost = other.max_cost, other.argmax_cost
        if other.argmax_cost_m is not None and other.cost_m is not None and _better(
                other.cost_m, other.argmax_cost_m, self.cost_m, self.argmax_cost_m):
            self.cost_m, self.argmax_cost_m = other.cost_m, other.argmax_cost_m
        if other.argmax_ratio is not None and other.ratio is not None and _better(
                other.ratio, other.argmax_ratio, self.ratio, self.argmax_ratio):
            self.ratio, self.argmax_ratio = other.ratio, other.argmax_ratio

    def quantiles(self, qs: tuple[float, ...] = (0.0, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0)) -> list[float]:
        """The ``q``-quantiles of cost/m over the correct runs (the least value with at least q of the runs at or
        below it), rounded to 3 decimals."""
        values = sorted((Fraction(cost, m), k) for (m, cost), k in self.pairs.items())
        total = sum(k for _, k in values)
        out = []
        for q in qs:
            need, seen = max(1, math.ceil(q * total - 1e-9)), 0
            for value, k in values:
                seen += k
                if seen >= need:
                    out.append(round(float(value), 3))
                    break
        return out

    def to_json(self) -> dict[str, Any]:
        return {"n": self.n, "worlds": self.worlds, "runs": self.runs, "outcomes": dict(sorted(self.outcomes.items())),
                "pairs": sorted([m, cost, k] for (m, cost), k in self.pairs.items()),
                "max_cost": self.max_cost, "argmax_cost": self.argmax_cost,
                "cost_m": self.cost_m, "argmax_cost_m": self.argmax_cost_m,
                "ratio": self.ratio, "argmax_ratio": self.argmax_ratio}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> "SizeTally":
        t = cls(int(data["n"]))
        t.worlds, t.runs = data["worlds"], data["runs"]
        t.outcomes = Counter(data["outcomes"])
        t.pairs = Counter({(m, cost): k for m, cost, k in data["pairs"]})
        t.max_cost = data["max_cost"]
        t.argmax_cost = _witness(data["argmax_cost"])
        t.cost_m, t.argmax_cost_m = _pair(data["cost_m"]), _witness(data["argmax_cost_m"])
        t.ratio, t.argmax_ratio = _pair(data["ratio"]), _witness(data["argmax_ratio"])
        return t


def _witness(raw: Any) -> Witness | None:
    return None if raw is None else (int(raw[0]), int(raw[1]), str(raw[2]), int(raw[3]))


def _pair(raw: Any) -> tuple[int, int] | None:
    return None if raw is None else (int(raw[0]), int(raw[1]))


def merge_tallies(parts: list[dict[int, SizeTally]]) -> dict[int, SizeTally]:
    """One tally per size from many tasks' tallies."""
    out: dict[int, SizeTally] = {}
    for part in parts:
        for n, tally in part.items():
            out.setdefault(n, SizeTally(n)).merge(tally)
    return dict(sorted(out.items()))
