"""Every run on every small world: the exhaustive worst case of an algorithm's cost (thesis §7.2).

The thesis bounds the cost of Algorithm 3.1 by (3.1) + (3.2) = O(m²n)
(§3.5.2) and calls the bound "quite loose" (§7.2).  Over
every embedded world with n ≤ N vertices and degrees ≤ D — one per
extended-isomorphism class, from the census's enumeration
(:func:`topomark.proofs.census_map.unit_worlds`) — and every start, this
module runs the algorithm unchecked and keeps, per n, the largest cost, cost
per edge and cost ÷ bound (:class:`~topomark.reference.worstcase.tally.SizeTally`).
For n ≤ N those maxima are exact: the worst case itself, not an estimate.

A *start* is a dart: the robot at v facing its exit i (§3.1.1; under a
lighthouse it drops its kit there, §3.3).  Two starts that an automorphism of
the world maps onto each other give the same run up to renaming, so only the
least dart of each orbit runs (:func:`start_darts`).  A start the algorithm
cannot use (a lighthouse needing a start vertex of higher degree, §6.1) is
counted as *refused*, not run.

A seeded sample of the runs (:func:`sampled`) runs again checked — every
invariant the algorithm's entry names, after every step — and must give the
same cost and a verified map; the argmax runs are re-checked by the caller
(:mod:`~topomark.reference.worstcase.resumable`).

Examples
--------
>>> from topomark.proofs.census_map import world_at
>>> world = world_at(3, 2, 0, 0)  # the path v1 - v0 - v2, whose automorphisms swap v1 and v2
>>> world.rotation
{'v0': ('v1', 'v2'), 'v1': ('v0',), 'v2': ('v0',)}
>>> start_darts(world, ({0: 0, 1: 1, 2: 2}, {0: 0, 1: 2, 2: 1}))
[('v0', 0), ('v1', 0)]
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Any

from topomark.proofs.census_map import Unit, unit_worlds
from topomark.proofs.start_orbits import start_darts
from topomark.proofs.world_arrays import to_arrays
from topomark.spec.errors import InvalidInput, TopomarkFault
from topomark.spec.world import Start, World

from topomark.reference.algorithms.registry import AlgorithmSpec, algorithm_spec
from topomark.reference.engine.runs import run_starts
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import explore
from topomark.reference.worstcase.tally import SizeTally, Witness

__all__ = ["Setup", "start_darts", "sampled", "run_start", "run_task", "unchecked_runs"]


@dataclass(frozen=True)
class Setup:
    """What every run of one worst-case search shares: the algorithm, its lighthouse and policies, the
    checked sample (``sample``: the fraction of runs re-run checked, drawn by ``seed``), and the engine of the
    unchecked runs (:func:`unchecked_runs`).  The engine is not part of the search's identity (``to_json``, the
    manifest): the compiled engine agrees with the reference run for run (:mod:`topomark.reference.engine`), so a
    search resumes with either."""

    algorithm: str
    lighthouse: str | None = None
    policies: tuple[str, str, str] = ("nearest", "fifo", "shortest")
    sample: float = 0.001
    seed: int = 0
    engine: str = "reference"  # or "compiled" (topomark.reference.engine); not in to_json: both give the same runs

    @property
    def spec(self) -> AlgorithmSpec:
        return algorithm_spec(self.algorithm)

    def policy(self) -> Policies:
        return Policies(*self.policies)

    def to_json(self) -> dict[str, Any]:
        return {"algorithm": self.algorithm, "lighthouse": self.lighthouse, "policies": list(self.policies),
                "sample": self.sample, "seed": self.seed}


def sampled(setup: Setup, n: int, witness: Witness) -> bool:
    """Whether the run from ``witness`` is in the checked sample: a hash of the seed and the run, not a
    random draw, so a resumed search samples the same runs."""
    if setup.sample <= 0:
        return False
    h = hashlib.blake2b(f"{setup.seed}:{n}:{witness}".encode(), digest_size=8).digest()
    return int.from_bytes(h, "little") < setup.sample * 2 ** 64


def run_start(setup: Setup, world: World, dart: tuple[str, int], check: bool = False):
    """The outcome of one run of the algorithm from ``dart`` on ``world`` (unchecked unless ``check``)."""
    v, i = dart
    started = world.with_start(Start(v, world.neighbour(v, i)))
    return explore(started, setup.spec, setup.policy(), check=check, record=False, lighthouse=setup.lighthouse)


def _recheck(setup: Setup, world: World, dart: tuple[str, int], unchecked, witness: Witness) -> dict | None:
    """Run again checked; the disagreement with the unchecked run, or None."""
    checked = run_start(setup, world, dart, check=True)
    if checked.cost != unchecked.cost or checked.claimed != unchecked.claimed:
        return {"witness": list(witness), "kind": "disagree", "unchecked": [unchecked.cost, unchecked.claimed],
                "checked": [checked.cost, checked.claimed]}
    if unchecked.claimed == "correct" and not checked.verified:
        detail = checked.violation.to_json() if checked.violation is not None else checked.outcome
        return {"witness": list(witness), "kind": "violation", "detail": detail}
    return None


def unchecked_runs(setup: Setup, world: World, darts: list[tuple[str, int]]) -> list:
    """The unchecked run from each of ``darts`` (None: a start the algorithm refuses), by the setup's engine.

    The compiled engine converts the world to arrays once and runs every start in one call; a run it ends with
    a fault code is run again by the reference, which raises its own error, or — if it does not — shows the
    engine wrong (:class:`~topomark.spec.errors.TopomarkFault`, exit 3)."""
    if setup.engine != "compiled":
        out = []
        for dart in darts:
            try:
                out.append(run_start(setup, world, dart))
            except InvalidInput:
                out.append(None)
        return out
    least = LIGHTHOUSES[setup.lighthouse or "directional-vertex"].min_degree if setup.spec.uses_lighthouse else 0
    number = {v: k for k, v in enumerate(world.vertices)}
    usable = [d for d in darts if world.degree(d[0]) >= least]
    runs = iter(run_starts(to_arrays(world), [(number[v], i) for v, i in usable], setup.policies,
                           setup.lighthouse, setup.algorithm))
    out = [next(runs) if world.degree(d[0]) >= least else None for d in darts]
    for dart, run in zip(darts, out):
        if run is not None and run.claimed != "correct":
            checked = run_start(setup, world, dart)  # the reference's own error, if it has one
            raise TopomarkFault(f"the compiled engine ended the run from {dart} on {world.rotation} with "
                                f"{run.claimed!r}, the reference with {checked.claimed!r}: the engine and its "
                                "reference disagree", check="the engine agrees with the reference")
    return out


def run_task(setup: Setup, max_degree: int, units: list[Unit]) -> dict[str, Any]:
    """Every world of ``units`` and every start: the tallies per n, the refused starts, the checked sample."""
    tallies: dict[int, SizeTally] = {}
    refused = checked = 0
    problems: list[dict] = []
    for unit in units:
        n, gi = unit[0], unit[1]
        tally = tallies.setdefault(n, SizeTally(n))
        for rank, world, autos in unit_worlds(unit, max_degree):
            tally.add_world()
            bound = setup.spec.bound_for(world.n, world.m)
            darts = start_darts(world, autos)
            for dart, out in zip(darts, unchecked_runs(setup, world, darts)):
                witness = (gi, rank, dart[0], dart[1])
                if out is None:
                    refused += 1
                    continue
                tally.add_run(witness, world.m, out.cost, setup.spec.counted_cost(out.cost, out.by_purpose), bound,
                              out.claimed)
                if sampled(setup, n, witness):
                    checked += 1
                    problem = _recheck(setup, world, dart, out, witness)
                    if problem is not None:
                        problems.append({"n": n, **problem})
    return {"tallies": [t.to_json() for t in tallies.values()], "refused": refused, "checked": checked,
            "problems": problems[:20], "problem_count": len(problems)}
