"""What an adversarial search returns: the best world it found and the run's outcome (§7.2).

:class:`Found` is one candidate world with its cost and the part of the cost the algorithm's exact bound counts;
:class:`AdversarialResult` is one search (or one random baseline) at one size, with its history and failures.
Both write the JSON that ``topomark worst-case --search`` stores and ``--summarise`` reads back
(:mod:`.summary_input`). The search itself is :mod:`.search`.

>>> from topomark.spec.world import World
>>> Found(World({"a": ["b"], "b": ["a"]}), score=1.0, cost=1, counted=1)
Found(world n=2 m=1, cost=1, score=1)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import networkx as nx

from topomark.spec.world import World
from topomark.spec.worldfile import world_to_json

from topomark.reference.algorithms.registry import AlgorithmSpec, algorithm_spec

__all__ = ["Found", "AdversarialResult"]


@dataclass(repr=False)
class Found:
    """The best candidate of a run: its world (start included), score, cost and the part of the cost its exact
    bound counts (``AlgorithmSpec.counted_cost``); ``holes`` for a lattice."""

    world: World
    score: float
    cost: int
    counted: int
    holes: list[str] | None = None

    def __repr__(self) -> str:
        return f"Found(world n={self.world.n} m={self.world.m}, cost={self.cost}, score={self.score:g})"

    def to_json(self, spec: AlgorithmSpec) -> dict[str, Any]:
        w = self.world
        graph = nx.Graph(w.edges())
        bound = spec.bound_for(w.n, w.m)
        out: dict[str, Any] = {"cost": self.cost, "m": w.m, "n": w.n, "diameter": nx.diameter(graph),
               "max_degree": max(w.degree(v) for v in w.vertices), "cost_per_m": round(self.cost / w.m, 3),
               "ratio_to_bound": None if bound is None else round(self.counted / bound, 6), "world": world_to_json(w)}
        if self.holes is not None:
            out["holes"] = self.holes
        return out


@dataclass(repr=False)
class AdversarialResult:
    """One search's (or one baseline's) outcome; ``random`` is the random baseline run beside a search.

    ``best`` is the worst world found (:class:`Found`: the world with its start, its cost and score), a lower
    bound on the worst case at ``n`` vertices; ``history`` the best score after about every twentieth of the
    ``evaluations``; ``failures`` the runs that did not map their world.
    """

    algorithm: str
    objective: str
    n: int
    max_degree: int
    evaluations: int
    seed: int
    family: str
    best: Found | None
    failures: int
    history: list[tuple[int, float]]
    random: "AdversarialResult | None" = None
    spec: AlgorithmSpec | None = field(default=None, repr=False)
    restart: str | None = None

    def __repr__(self) -> str:
        """``AdversarialResult(algorithm='basic', objective='cost', n=8, best cost=59 on n=8 m=11, 20 evaluations,
        seed=4)`` and the baseline's best: the answer in one short line (the worlds stay attributes)."""
        top = self.best
        best = "no best" if top is None else f"best cost={top.cost} on n={top.world.n} m={top.world.m}"
        rival = self.random.best if self.random is not None else None
        baseline = "" if rival is None else f", random baseline's best cost={rival.cost}"
        return (f"AdversarialResult(algorithm={self.algorithm!r}, objective={self.objective!r}, n={self.n}, "
                f"max_degree={self.max_degree}, family={self.family!r}, {best}, {self.evaluations} evaluations, "
                f"{self.failures} failures, seed={self.seed}{baseline})")

    def to_json(self) -> dict[str, Any]:
        spec = self.spec or algorithm_spec(self.algorithm)
        out: dict[str, Any] = {
            "algorithm": self.algorithm, "objective": self.objective, "n": self.n, "max_degree": self.max_degree,
            "evaluations": self.evaluations, "seed": self.seed, "family": self.family, "restart": self.restart,
            "best": None if self.best is None else self.best.to_json(spec), "failures": self.failures,
            "history": [{"evaluations": k, "best": None if math.isinf(s) else s} for k, s in self.history]}
        if self.random is not None:
            out["random"] = {"best": None if self.random.best is None else self.random.best.to_json(spec),
                             "failures": self.random.failures}
        return out
