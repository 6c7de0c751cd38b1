"""Running a checked exploration: world → simulator → explorer (+ checker, trace, cost).

:func:`explore` wires the pieces together for Algorithm 3.1 (``basic``):

1. validate the world for the algorithm (§3.3: one directional immovable
   vertex marker, dropped by the robot at v0 pointing at the exit it faces);
2. build the simulator, hand the explorer only its robot;
3. after every iteration run the :class:`~topomark.reference.checker.Checker`
   (unless ``check=False``) and hand the trace records to a sink
   (:mod:`~topomark.reference.tracesink`: kept in a list, streamed to a file,
   or only the last few kept) as they are made;
4. return an :class:`Outcome` with the map, the cost split by purpose and the
   counts the CLI reports.

The trace format is documented in ``spec/trace.md``.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, Callable

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.marker import VertexMarker
from topomark.spec.world import World
from topomark.spec.worldfile import marker_to_json

from .bounds import upper_bound
from .checker import Checker
from .algorithms import ALGORITHMS
from .policies import Policies
from .simulator import Simulator
from .tracesink import ListSink, TraceSink, trace_line

__all__ = ["ALGORITHMS", "Outcome", "explore", "prepare_world", "dump_trace", "TRACE_FORMAT"]

TRACE_FORMAT = "topomark/trace@1"


@dataclass
class Outcome:
    n: int
    m: int
    cost: int
    verified: bool
    iterations: int
    loop_iterations: int
    nonloop_iterations: int
    hypotheses: int
    hypotheses_rejected: int
    hypotheses_confirmed: int
    checks: int
    by_purpose: dict[str, int]
    upper_bound: int
    explorer: Any = None
    trace: list[dict] = field(default_factory=list)
    violation: Any = None

    def summary(self) -> dict[str, Any]:
        out = {k: getattr(self, k) for k in (
            "n", "m", "cost", "verified", "iterations", "loop_iterations", "nonloop_iterations", "hypotheses",
            "hypotheses_rejected", "hypotheses_confirmed", "checks", "by_purpose", "upper_bound")}
        out["cost_per_m"] = round(self.cost / self.m, 3)
        if self.violation is not None:
            out["violation"] = self.violation.to_json()
        return out


def prepare_world(world: World) -> tuple[World, tuple[str, int]]:
    """The world without markers and the start state, checked against §3.3's marker class.

    A directional vertex marker already in the world at v0 must point at the
    faced exit; any other marker is an error for this algorithm.
    """
    state = world.start_state()
    v0, facing = state
    for marker in world.markers:
        if not isinstance(marker, VertexMarker) or not marker.directional or marker.at != v0:
            raise InvalidInput(
                f"the basic algorithm (one directional vertex marker dropped at the start) cannot use the marker "
                f"{json.dumps(marker_to_json(marker))} in the world file: only a directional vertex marker at the "
                f"start vertex {v0!r} is allowed")
        if marker.count != 1 or world.index(v0, marker.points_to) != facing:
            raise InvalidInput(
                f"the directional marker at {v0!r} points to {marker.points_to!r}, but the robot starts facing "
                f"{world.neighbour(v0, facing)!r}: the robot drops its marker pointing at the exit it faces")
    return World(world.rotation, (), world.start), state


def explore(world: World, algorithm: str = "basic", policies: Policies | None = None, check: bool = True,
            record: bool = True, progress: Callable[[int, int, int], None] | None = None,
            check_mode: str = "incremental", sink: TraceSink | None = None,
            keep_hypotheses: bool = True) -> Outcome:
    """Explore ``world`` and return the outcome; a violated check ends the run with ``outcome.violation`` set.

    The trace records go to ``sink`` as they are made; without one, ``record=True`` keeps them all in
    ``outcome.trace`` and ``record=False`` makes none.  ``keep_hypotheses=False`` drops each iteration's
    hypotheses (their M, P^E and perceptions) from ``outcome.explorer.iterations`` once they are traced,
    checked and counted, so memory stays proportional to the world.  ``progress(explored_edges, m, cost)``
    is called after every iteration.
    """
    if algorithm not in ALGORITHMS:
        raise InvalidInput(f"unknown algorithm {algorithm!r} (choose from {', '.join(ALGORITHMS)})")
    policies = policies or Policies()
    bare, state = prepare_world(world)
    trace: list[dict] = []
    if sink is None and record:
        sink = ListSink()
        trace = sink.records
    emit = sink.emit if sink is not None else None
    tally = _Tally()
    if emit:
        emit({"event": "header", "format": TRACE_FORMAT, "algorithm": algorithm,
              "policies": policies.to_json(), "n": world.n, "m": world.m})

    def on_move(motion, purpose, sig, true_state):
        if emit:
            emit({"event": "move", "step": sim.cost, "motion": motion, "perception": str(sig),
                  "purpose": purpose})

    sim = Simulator(bare, state, {"directional-vertex": 1}, listener=on_move)
    if check_mode not in Checker.MODES:
        raise InvalidInput(f"unknown check mode {check_mode!r} (choose from {', '.join(Checker.MODES)})")
    checker = Checker(sim, check_mode) if check else None

    def observer(explorer, it):
        if emit:
            emit({"event": "iteration", **it.to_json()})
        tally.add(it)  # counted before the check: an iteration that fails it is in explorer.iterations too
        if checker is not None:
            checker.after_iteration(explorer, it)
        if not keep_hypotheses:
            it.hypotheses = []
        if progress is not None:
            progress(explorer.S.explored_edges(), world.m, sim.cost)

    explorer = ALGORITHMS[algorithm](sim.robot(), policies, observer)
    violation = None
    try:
        explorer.start()
        if emit:
            emit({"event": "drop", "direction": 0, "signature": str(sim._sense())})
        if checker is not None:
            checker.after_start(explorer)
        while explorer.S.unexplored:
            explorer.iterate()
        if checker is not None:
            checker.at_end(explorer)
    except CheckFailure as exc:
        violation = exc.violation
    outcome = _outcome(world, sim, explorer, checker, violation, trace, tally)
    if emit:
        emit({"event": "end", "cost": sim.cost, "verified": outcome.verified,
              "violation": violation.to_json() if violation else None})
    return outcome


class _Tally:
    """The iteration and hypothesis counts of a run, kept as the iterations come."""

    def __init__(self) -> None:
        self.iterations = self.loop = self.nonloop = self.hypotheses = self.rejected = self.confirmed = 0

    def add(self, it) -> None:
        self.iterations += 1
        self.loop += it.kind == "loop"
        self.nonloop += it.kind == "non-loop"
        self.hypotheses += len(it.hypotheses)
        self.rejected += sum(h.outcome in ("case 1", "case 2") for h in it.hypotheses)
        self.confirmed += sum(h.outcome == "case 3" for h in it.hypotheses)


def _outcome(world: World, sim: Simulator, explorer, checker: Checker | None, violation, trace: list[dict],
             tally: _Tally) -> Outcome:
    """The counts the CLI reports, from the finished (or stopped) run."""
    return Outcome(
        n=world.n, m=world.m, cost=sim.cost, verified=checker is not None and violation is None,
        iterations=tally.iterations, loop_iterations=tally.loop, nonloop_iterations=tally.nonloop,
        hypotheses=tally.hypotheses, hypotheses_rejected=tally.rejected, hypotheses_confirmed=tally.confirmed,
        checks=checker.passed if checker else 0, by_purpose=dict(sorted(sim.by_purpose.items())),
        upper_bound=upper_bound(world.n, world.m), explorer=explorer, trace=trace, violation=violation)


def dump_trace(trace: list[dict]) -> str:
    """JSON Lines, keys sorted, no whitespace: byte-for-byte reproducible (what a FileSink streams)."""
    return "".join(trace_line(rec) for rec in trace)

