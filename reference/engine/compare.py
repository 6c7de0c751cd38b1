"""The engine against the reference, run by run and action by action (thesis §3.3, §7.2).

The compiled Algorithm 3.1 (:mod:`.algorithm31`) is an accelerator; the
checked reference (:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`
run by :func:`~topomark.reference.run.explore.explore`) is the definition.
Equality is established by running both on the same world from the same start
with the same policies and comparing what each run claimed, its cost and split
by purpose, its marker operations, its iteration and hypothesis counts, and its
trace digest (:mod:`.digest`) — the reference's actions read from the records
its simulator streams as the robot acts (every move and every marker
operation, in order), the engine's from its robot's log.

The runs compared (:func:`check`):

* every world with n ≤ N vertices and degrees ≤ D, one per isomorphism class
  (the census's enumeration, :func:`topomark.proofs.census_map.unit_worlds`),
  from one start per orbit of its automorphisms
  (:func:`topomark.proofs.start_orbits.start_darts`), under each of the 18
  combinations of the built-in policies (:data:`COMBOS`);
* seeded random worlds (:func:`random_cases`: ``random`` and ``small-world``
  generators up to a given n) from a few seeded starts, under every combination.

The footprint searches of §6.2.1 (:mod:`.footprints`) are compared the same
way, each with the kit its registration gives, under the policies that apply
to it (:func:`combos_for`: the three edge policies; Case 4's nearest only).

The command is :mod:`.equality` (``python -m topomark.reference.engine.equality``).
"""

from __future__ import annotations

import itertools
import random
from dataclasses import dataclass
from typing import Any, Iterator

from topomark.proofs.census_map import plan, unit_worlds
from topomark.proofs.start_orbits import start_darts
from topomark.proofs.world_arrays import to_arrays
from topomark.spec.errors import TopomarkError
from topomark.spec.world import Start, World

from topomark.reference.engine import FOOTPRINT_CASES
from topomark.reference.engine.digest import describe, digest, event_code
from topomark.reference.engine.runs import EngineRun, run_logged
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.policies import EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES, Policies
from topomark.reference.run.explore import explore
from topomark.reference.worlds.argument import resolve_world

__all__ = ["COMBOS", "Case", "Disagreement", "reference_run", "combos_for", "compare_case", "census_cases",
           "random_cases", "run_cases", "FIELDS"]

COMBOS = tuple(itertools.product(EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES))
"""Every combination (edge, hypothesis, path) of the built-in policies the engine runs."""
FIELDS = ("claimed", "cost", "by_purpose", "marker_operations", "iterations", "loop_iterations",
          "nonloop_iterations", "hypotheses", "hypotheses_rejected", "hypotheses_confirmed", "digest")
"""What is compared of each pair of runs."""


@dataclass
class Case:
    """One world and the starts to run it from: ``name`` says how to make it again (census graph and rank, or a
    generator text); ``group`` is the size it is counted under (n, or ``random``)."""

    name: str
    group: str
    world: World
    starts: list[tuple[str, int]]


@dataclass
class Disagreement:
    """A pair of runs that differ: where, which fields, and the first differing action."""

    case: str
    start: tuple[str, int]
    policies: tuple[str, str, str]
    fields: dict[str, list]
    step: int
    engine_action: str
    reference_action: str

    def to_json(self) -> dict[str, Any]:
        return {"world": self.case, "start": list(self.start), "policies": list(self.policies),
                "fields": self.fields, "first_differing_action": self.step, "engine": self.engine_action,
                "reference": self.reference_action}

    def __str__(self) -> str:
        return (f"world {self.case}, start {self.start[0]} facing exit {self.start[1]}, policies "
                f"{'/'.join(self.policies)}: {', '.join(self.fields)} differ; first differing action #{self.step}: "
                f"engine {self.engine_action}, reference {self.reference_action}")


class _Actions:
    """A trace sink that keeps only the action codes of the records it is handed (moves and operations)."""

    events = frozenset({"move"})  # the header, marker operations and end record always come

    def __init__(self) -> None:
        self.codes: list[int] = []

    def emit(self, record: dict) -> None:
        code = event_code(record)
        if code is not None:
            self.codes.append(code)


def reference_run(world: World, start: tuple[str, int], policies: tuple[str, str, str],
                  lighthouse: str | None = None, algorithm: str = "basic") -> tuple[dict, list[int]]:
    """The reference's unchecked run of ``algorithm`` with ``lighthouse`` (None: ``directional-vertex``; a footprint
    search uses none, and runs with its registration's kit) from ``start`` (the robot at v facing exit i, as the
    exhaustive search starts it): the compared fields, and the action codes."""
    v, i = start
    sink = _Actions()
    light = None if algorithm in FOOTPRINT_CASES else lighthouse or "directional-vertex"
    try:
        out = explore(world.with_start(Start(v, world.neighbour(v, i))), algorithm, Policies(*policies), check=False,
                      record=False, sink=sink, lighthouse=light)
    except TopomarkError as exc:  # a fault of the explorer (Lemma 1 broken): its message is what it claimed
        return {"claimed": f"{type(exc).__name__}: {exc}", "digest": digest(sink.codes)}, sink.codes
    fields = {"claimed": out.claimed, "cost": out.cost, "by_purpose": out.by_purpose,
              "marker_operations": out.marker_operations, "digest": digest(sink.codes)}
    fields.update({k: getattr(out, k) for k in FIELDS[4:10]})
    return fields, sink.codes


def _engine_fields(run: EngineRun) -> dict:
    return {"claimed": run.claimed, "cost": run.cost, "by_purpose": run.by_purpose,
            "marker_operations": run.marker_operations, **run.counts, "digest": run.digest()}


def combos_for(algorithm: str) -> tuple:
    """The policy combinations compared for ``algorithm``: all of :data:`COMBOS` for a lighthouse algorithm; a
    footprint search takes the edge policy only (Case 4 none: it chooses the nearest edge whatever it is given)."""
    if algorithm not in FOOTPRINT_CASES:
        return COMBOS
    edges = ("nearest",) if algorithm in ("case-4", "case-4-mn") else EDGE_POLICIES
    return tuple((edge, "fifo", "shortest") for edge in edges)


def compare_case(case: Case, combos: tuple = COMBOS, lighthouse: str | None = None,
                 algorithm: str = "basic") -> tuple[int, list[Disagreement]]:
    """Every start of ``case`` the lighthouse can start from (its ``min_degree``; a footprint search: every start)
    under every policy combination: the number of pairs compared and the disagreements."""
    arrays = to_arrays(case.world)
    number = {v: k for k, v in enumerate(arrays.names)}
    least = 0 if algorithm in FOOTPRINT_CASES else LIGHTHOUSES[lighthouse or "directional-vertex"].min_degree
    found, count = [], 0
    for start in (s for s in case.starts if case.world.degree(s[0]) >= least):
        for policies in combos:
            want, codes = reference_run(case.world, start, policies, lighthouse, algorithm)
            run = run_logged(arrays, (number[start[0]], start[1]), policies, lighthouse, algorithm)
            got = _engine_fields(run)
            count += 1
            differ = {k: [got.get(k), want.get(k)] for k in FIELDS if got.get(k) != want.get(k)}
            if differ:
                mine = [] if run.actions is None else run.actions.tolist()
                found.append(_disagreement(case, start, policies, differ, mine, codes, algorithm))
    return count, found


def _disagreement(case: Case, start, policies, differ: dict, mine: list[int], theirs: list[int],
                  algorithm: str = "basic") -> Disagreement:
    step = next((k for k, (a, b) in enumerate(zip(mine, theirs)) if a != b), min(len(mine), len(theirs)))
    shown = [describe(c[step]) if step < len(c) else "nothing (the run had ended)" for c in (mine, theirs)]
    name = case.name if algorithm == "basic" else f"{case.name} ({algorithm})"  # which algorithm disagreed
    return Disagreement(name, start, policies, differ, step, *shown)


def _variant(job: tuple) -> tuple[str, str | None]:
    """The algorithm and lighthouse a task names (its items after the third; default ``basic`` with Algorithm 3.1's
    own lighthouse)."""
    return (job[3] if len(job) > 3 else "basic"), (job[4] if len(job) > 4 else None)


def census_cases(max_vertices: int, max_degree: int, task_worlds: int = 200) -> list[list[tuple]]:
    """The census's units for n ≤ ``max_vertices``, degrees ≤ ``max_degree``, grouped into tasks."""
    return [[u for u, _ in task] for task in plan(max_vertices, max_degree, 2, task_worlds)]


def _unit_cases(units: list[tuple], max_degree: int) -> Iterator[Case]:
    for unit in units:
        for rank, world, autos in unit_worlds(unit, max_degree):
            n, gi = unit[0], unit[1]
            yield Case(f"census n={n} D={max_degree} graph {gi} rank {rank}", str(n), world, start_darts(world, autos))


def random_cases(count: int, max_vertices: int, seed: int, starts: int = 2) -> list[tuple[str, list]]:
    """``count`` seeded random worlds (``random`` with about 1.5 n edges, ``small-world`` with k = 4), n from 10
    to ``max_vertices``, each with ``starts`` seeded start darts: (generator text, starts as (vertex, exit))."""
    rng = random.Random(seed)
    out = []
    for k in range(count):
        n = rng.randint(min(10, max_vertices), max_vertices)
        if k % 2 == 0:
            text = f"random:n={n},fraction={round(3 / (n - 1), 6)},seed={rng.randrange(10**6)}"
        else:
            text = f"small-world:n={max(n, 5)},k=4,p=0.1,seed={rng.randrange(10**6)}"
        world = resolve_world(text)
        darts = [(v, i) for v in world.vertices for i in range(world.degree(v))]
        out.append((text, rng.sample(darts, min(starts, len(darts)))))
    return out


def run_cases(job: tuple) -> dict[str, Any]:
    """One task: ``("census", units, max_degree[, algorithm, lighthouse])`` or ``("random", text, starts[, algorithm,
    lighthouse])``; the counts per group and the first disagreements."""
    if job[0] == "census":
        cases: Iterator[Case] = _unit_cases(job[1], job[2])
    else:
        cases = iter([Case(job[1], "random", resolve_world(job[1]), [tuple(s) for s in job[2]])])
    counts: dict[str, int] = {}
    found: list[Disagreement] = []
    worlds = 0
    for case in cases:
        worlds += 1
        algorithm, lighthouse = _variant(job)
        count, bad = compare_case(case, combos_for(algorithm), lighthouse, algorithm)
        counts[case.group] = counts.get(case.group, 0) + count
        found += bad
    return {"counts": counts, "worlds": worlds, "disagreements": [d.to_json() for d in found[:5]],
            "disagreement_text": [str(d) for d in found[:5]], "disagreement_count": len(found)}
