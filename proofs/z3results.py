"""The result records of the Z3 search: per size pair, per search, per bounded proof (thesis §3.2, §3.7, §6.1).

:class:`SizeCheck` is one solver call, :class:`SearchResult` the outcome of
:func:`~topomark.proofs.z3search.search` (``found`` with the re-checked
witness pair, ``none`` or ``unknown``) and :class:`ProofReport` that of
:func:`~topomark.proofs.z3search.prove`; each has a ``to_json`` for the
``search`` command.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from topomark.spec.errors import clip

from topomark.spec.signature import Signature
from topomark.spec.world import World

__all__ = ["SizeCheck", "SearchResult", "ProofReport", "relation_to_json"]


@dataclass(frozen=True)
class SizeCheck:
    """The verdict of one solver call: world sizes, 'sat'/'unsat'/'unknown', wall and CPU seconds."""

    n_a: int
    n_b: int
    verdict: str
    seconds: float
    cpu_seconds: float = 0.0

    def to_json(self) -> dict[str, Any]:
        return {"n_a": self.n_a, "n_b": self.n_b, "verdict": self.verdict, "seconds": round(self.seconds, 3),
                "cpu_seconds": round(self.cpu_seconds, 3)}


def _worlds(pair: tuple[World, World] | None) -> str:
    return "" if pair is None else f", worlds n={pair[0].n} and n={pair[1].n}"


@dataclass(repr=False)
class SearchResult:
    """Outcome ``found`` | ``none`` | ``unknown`` with, when found, the re-checked witness.

    ``worlds`` is the pair found (indistinguishable and not extended-isomorphic, re-checked), ``motions``
    and ``perceptions`` a walk covering both, ``relation`` the bisimulation; ``checks`` holds one
    :class:`SizeCheck` per solver call and ``reason`` why the search answered ``unknown``.
    """

    outcome: str
    marker: str
    max_vertices: int
    max_degree: int
    seconds: float
    checks: list[SizeCheck] = field(default_factory=list)
    worlds: tuple[World, World] | None = None
    relation: frozenset | None = None
    motions: tuple[int, ...] | None = None
    perceptions: tuple[Signature, ...] | None = None
    reason: str = ""
    planar: bool = False

    @property
    def found(self) -> bool:
        return self.outcome == "found"

    def __repr__(self) -> str:
        """``SearchResult(found, marker='none', max_vertices=4, max_degree=3, worlds n=3 and n=4, 5 size checks,
        0.3 s)``: the answer in one short line (the worlds and the walk stay attributes)."""
        reason = f", reason: {clip(self.reason, 300)}" if self.reason else ""
        return (f"SearchResult({self.outcome}, marker={self.marker!r}, max_vertices={self.max_vertices}, "
                f"max_degree={self.max_degree}{', planar' if self.planar else ''}{_worlds(self.worlds)}, "
                f"{len(self.checks)} size checks, {self.seconds:.1f} s{reason})")

    def to_json(self) -> dict[str, Any]:
        from topomark.spec.worldfile import world_to_json

        out: dict[str, Any] = {
            "outcome": self.outcome, "found": self.found, "marker": self.marker,
            "max_vertices": self.max_vertices, "max_degree": self.max_degree, "planar": self.planar,
            "seconds": round(self.seconds, 3), "checks": [c.to_json() for c in self.checks],
        }
        if self.reason:
            out["reason"] = self.reason
        if self.found:
            assert self.worlds is not None and self.motions is not None and self.perceptions is not None
            out["worlds"] = [world_to_json(w) for w in self.worlds]
            out["relation"] = relation_to_json(self.relation)
            out["motions"] = list(self.motions)
            out["perceptions"] = [str(p) for p in self.perceptions]
        return out


@dataclass(repr=False)
class ProofReport:
    """A bounded proof attempt: ``proved`` | ``counterexample`` | ``unknown``.

    ``bounds`` are the sizes it covers, ``symmetry_breaking`` the constraints added to the solver's problem,
    ``search`` the search behind it (its pair when there is a counterexample).
    """

    outcome: str
    marker: str
    bounds: dict[str, int]
    symmetry_breaking: tuple[str, ...]
    solver: str
    seconds: float
    search: SearchResult

    @property
    def proved(self) -> bool:
        return self.outcome == "proved"

    def __repr__(self) -> str:
        """``ProofReport(proved, marker='directional-vertex', max_vertices=3, max_degree=2, 0.1 s)``."""
        bounds = ", ".join(f"{k}={v}" for k, v in self.bounds.items())
        return (f"ProofReport({self.outcome}, marker={self.marker!r}, {clip(bounds, 200)}"
                f"{_worlds(self.search.worlds)}, {self.seconds:.1f} s)")

    def to_json(self) -> dict[str, Any]:
        out = self.search.to_json()
        out.update({"proof": self.outcome, "proved": self.proved, "bounds": self.bounds,
                    "symmetry_breaking": list(self.symmetry_breaking), "solver": self.solver,
                    "seconds": round(self.seconds, 3)})
        return out


def relation_to_json(relation) -> list[list[list[Any]]]:
    return [[list(p), list(q)] for p, q in sorted(relation)]
