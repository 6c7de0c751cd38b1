"""The algorithm registry: every explorer with its thesis reference, kit, bounds, options and checks.

Each :class:`AlgorithmSpec` records what the thesis says of one algorithm —
its section and listing, the marker kit it needs (:mod:`topomark.spec.kit`),
its cost bound and marker bound *as the thesis states them* (``None`` where
the thesis states none), whether it is deterministic, the options it takes,
the checks the checker applies to it — and a factory that builds its
explorer over the robot interface.  ``topomark algorithms [--json]`` lists
the registry.

Decision (the thesis is silent): Chapter 4 states no worst-case bound for
its enhancements (§4.1–4.3 report measured reductions only).  Enhancements
1–3 change only how hypotheses are validated and retraced, so the registry
gives them Algorithm 3.1's bound (3.1)+(3.2) as a stated *inheritance*, and
the checker measures it; Enhancements 4 and 5 add expansion traversals the
thesis does not bound, so their ``bound`` is ``None``.

Examples
--------
>>> spec = algorithm_spec("basic")
>>> spec.thesis
'§3.3, Algorithm 3.1'
>>> spec.bound_for(3, 3)  # a triangle: (3.1) + (3.2)
22
>>> algorithm_spec("nope")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: unknown algorithm 'nope' (choose from basic, enh1, enh2, enh3, enh4, enh5-d1, enh5-d2, enh3+4, enh3+5)
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Callable

from topomark.spec.errors import InvalidInput
from topomark.spec.kit import Kit

from . import algorithms
from .bounds import upper_bound
from .explorers.lighthouses import LIGHTHOUSES
from .explorers.compositions import ENHANCEMENTS

__all__ = ["AlgorithmSpec", "REGISTRY", "algorithm_spec", "variant", "CHECKS"]

CHECKS: dict[str, str] = {
    "pose": "the explorer's believed position is the robot's true state (φ anchored at the believed pose)",
    "I-1": "S is extended-isomorphic to the subgraph of G it maps onto (§3.4, I-1)",
    "I-2": "U holds exactly the unexplored edges at known vertices, with their exit indices (§3.4, I-2)",
    "bound-function": "t = |E_G| − |E_S| decreases by one per iteration (§3.4)",
    "lemma-1": "each hypothesis's (M, P^E) is unique (§3.4, Lemma 1)",
    "marker": "no marker is dropped, moved or picked up after the lighthouse is established (the kit itself is "
              "enforced by the simulator)",
    "iterations": "n − 1 non-loop and m − n + 1 loop iterations (§3.1.3)",
    "isomorphism": "the final map is extended-isomorphic to the world, markers included (§3.1.3)",
}
"""Every check the checker knows, by name, with the condition it states."""

_ALGORITHM_3_1_CHECKS = ("pose", "I-1", "I-2", "bound-function", "lemma-1", "marker", "iterations", "isomorphism")
_POLICY_OPTIONS = ("policy edge=nearest|fifo|lifo", "policy hypothesis=fifo|lifo|shortest", "policy path=shortest|dfs",
                   "lighthouse " + "|".join(LIGHTHOUSES))


@dataclass(frozen=True)
class AlgorithmSpec:
    """One registered algorithm; ``factory(robot, policies, observer)`` builds its explorer."""

    name: str
    thesis: str
    kit: Kit
    bound: str | None
    markers: str
    deterministic: bool
    options: tuple[str, ...]
    checks: tuple[str, ...]
    bound_fn: Callable[[int, int], int] | None = None
    explorer: type | None = None  # an explorer class of one's own (see :func:`variant`); else the registered one

    @property
    def factory(self) -> Callable[..., Any]:
        """The explorer class (a registered one is looked up at call time, so a test may substitute a faulty one)."""
        return self.explorer if self.explorer is not None else algorithms.ALGORITHMS[self.name]

    def bound_for(self, n: int, m: int) -> int | None:
        """The cost bound evaluated on a world of n vertices and m edges, or None if the thesis states none."""
        return None if self.bound_fn is None else self.bound_fn(n, m)

    def to_json(self) -> dict[str, Any]:
        """The listing of ``topomark algorithms --json``; ``kit`` is the default lighthouse's, ``lighthouses`` the
        kits the algorithm runs with."""
        return {"name": self.name, "thesis": self.thesis, "kit": self.kit.to_json(), "bound": self.bound,
                "markers": self.markers, "deterministic": self.deterministic, "options": list(self.options),
                "checks": list(self.checks),
                "lighthouses": {h.name: {"thesis": h.thesis, "kit": h.kit.to_json()} for h in LIGHTHOUSES.values()}}


_LIGHTHOUSE = LIGHTHOUSES["directional-vertex"].kit
_BOUND_3 = "(3.1)+(3.2) = O(m²n), §3.5.2"


def _enhancement(name: str) -> AlgorithmSpec:
    enh = ENHANCEMENTS[name]
    inherits = not (enh.prune or enh.expand_new or enh.expand_place)
    bound = f"{_BOUND_3}, inherited (§4.1 changes validation only)" if inherits else None
    return AlgorithmSpec(name, enh.section,
                         _LIGHTHOUSE, bound, "1", True, _POLICY_OPTIONS, _ALGORITHM_3_1_CHECKS,
                         upper_bound if inherits else None)


REGISTRY: dict[str, AlgorithmSpec] = {
    "basic": AlgorithmSpec("basic", "§3.3, Algorithm 3.1", _LIGHTHOUSE, _BOUND_3, "1", True, _POLICY_OPTIONS,
                           _ALGORITHM_3_1_CHECKS, upper_bound),
    **{name: _enhancement(name) for name in ENHANCEMENTS},
}


def variant(name: str, explorer: type, like: str = "basic") -> AlgorithmSpec:
    """An explorer class of one's own, run and checked like the registered algorithm ``like``.

    For trying a modification of an algorithm under the full checker
    (``explore(world, variant("mine", MyExplorer))``) without registering it.
    """
    return replace(algorithm_spec(like), name=name, explorer=explorer)


def algorithm_spec(name: str) -> AlgorithmSpec:
    """The registered algorithm called ``name``; an unknown name is bad input listing the known ones."""
    if name not in REGISTRY:
        raise InvalidInput(f"unknown algorithm {name!r} (choose from {', '.join(REGISTRY)})")
    return REGISTRY[name]
