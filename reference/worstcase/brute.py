"""A second opinion on the exhaustive worst case: every labelled rotation system, no isomorphism reduction (§7.2).

The exhaustive search (:mod:`~topomark.reference.worstcase.exhaustive`) runs
one world per extended-isomorphism class and one start per automorphism
orbit, both decided by the census's enumeration.  A mistake there (a class
skipped, an orbit merged wrongly) would hide a worst case.  This module
shares none of it: it takes each connected graph of networkx's graph atlas
(every graph on at most 7 vertices, one per isomorphism class) and runs the
algorithm on *every* rotation system of it — every cyclic order at every
vertex, written from the vertex's least neighbour — from *every* dart.  Its
maxima (cost, cost/m, cost ÷ bound) and its set of ``(m, cost)`` values must
equal the exhaustive search's (:func:`compare`, exit 3 if not).  It repeats
each world as often as its labelled copies, so it is practical only for
n ≤ 5 (at D ≤ 4, about 20,000 rotation systems).

Examples
--------
>>> from topomark.reference.worstcase.exhaustive import Setup
>>> found = brute_force(Setup("basic", sample=0), 3, 2)
>>> sorted((n, t.max_cost) for n, t in found.items())
[(2, 1), (3, 3)]
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Iterator

import networkx as nx

from topomark.spec.errors import InvalidInput, TopomarkFault
from topomark.spec.world import Start, World

from topomark.reference.run.explore import explore
from topomark.reference.worstcase.exhaustive import Setup
from topomark.reference.worstcase.tally import SizeTally

__all__ = ["BruteTally", "labelled_worlds", "brute_force", "compare"]

MAX_BRUTE = 5


@dataclass
class BruteTally:
    """The brute force's maxima for one n, as fractions, and every ``(m, cost)`` value met."""

    runs: int = 0
    max_cost: int = 0
    max_cost_m: Fraction = Fraction(0)
    max_ratio: Fraction | None = None
    values: set[tuple[int, int]] = field(default_factory=set)

    def to_summary(self) -> dict[str, Any]:
        return {"runs": self.runs, "max_cost": self.max_cost, "max_cost_per_m": str(self.max_cost_m),
                "max_ratio_to_bound": None if self.max_ratio is None else str(self.max_ratio)}


def labelled_worlds(n: int, max_degree: int) -> Iterator[World]:
    """Every rotation system of every connected atlas graph on n vertices with degrees ≤ ``max_degree``."""
    for g in nx.graph_atlas_g():
        if g.number_of_nodes() != n or not nx.is_connected(g) or max(d for _, d in g.degree()) > max_degree:
            continue
        orders = []
        for v in sorted(g):
            first, *rest = sorted(g[v])
            orders.append([(first, *p) for p in itertools.permutations(rest)])
        for choice in itertools.product(*orders):
            yield World({f"u{v}": [f"u{w}" for w in ns] for v, ns in zip(sorted(g), choice)})


def brute_force(setup: Setup, max_vertices: int, max_degree: int, min_vertices: int = 2) -> dict[int, BruteTally]:
    """Run from every dart of every labelled world with ``min_vertices ≤ n ≤ max_vertices``."""
    if max_vertices > MAX_BRUTE:
        raise InvalidInput(f"the brute force runs n <= {MAX_BRUTE} only, not {max_vertices}")
    spec, policies = setup.spec, setup.policy()
    out: dict[int, BruteTally] = {}
    for n in range(max(2, min_vertices), max_vertices + 1):
        tally = out.setdefault(n, BruteTally())
        for world in labelled_worlds(n, max_degree):
            bound = spec.bound_for(world.n, world.m) if spec.bound_fn is not None else None
            for v in world.vertices:
                for w in world.rotation[v]:
                    try:
                        run = explore(world.with_start(Start(v, w)), spec, policies, check=False, record=False,
                                      lighthouse=setup.lighthouse)
                    except InvalidInput:
                        continue  # a start the algorithm refuses: the exhaustive search refuses it too
                    tally.runs += 1
                    if run.claimed != "correct":
                        continue
                    counted = spec.counted_cost(run.cost, run.by_purpose)
                    tally.max_cost = max(tally.max_cost, run.cost)
                    tally.max_cost_m = max(tally.max_cost_m, Fraction(run.cost, world.m))
                    if bound is not None:
                        tally.max_ratio = max(tally.max_ratio or Fraction(0), Fraction(counted, bound))
                    tally.values.add((world.m, run.cost))
    return out


def compare(tallies: dict[int, SizeTally], brute: dict[int, BruteTally]) -> None:
    """Raise :class:`TopomarkFault` unless both searches found the same maxima and the same (m, cost) values."""
    for n, b in brute.items():
        t = tallies.get(n)
        if t is None:
            raise TopomarkFault(f"the brute force ran worlds of n = {n}, the exhaustive search none",
                                check="exhaustive search and brute force agree")
        mine: tuple[Any, ...] = (t.max_cost or 0, Fraction(*t.cost_m) if t.cost_m else Fraction(0),
                Fraction(*t.ratio) if t.ratio else None, set(t.pairs))
        theirs = (b.max_cost, b.max_cost_m, b.max_ratio, b.values)
        for name, a, c in zip(("max cost", "max cost/m", "max ratio to bound", "(m, cost) values"), mine, theirs):
            if a != c:
                shown = (a, c) if name != "(m, cost) values" else (sorted(a ^ c)[:5], "differ")
                raise TopomarkFault(f"at n = {n} the exhaustive search and the brute force disagree on the {name}: "
                                    f"{shown[0]} vs {shown[1]}", check="exhaustive search and brute force agree")
