"""Running a checked exploration: world → simulator → explorer (+ checker, trace, cost).

:func:`explore` wires the pieces together for a registered algorithm
(:mod:`~topomark.reference.algorithms.registry`) and a lighthouse
(:mod:`~topomark.reference.explorers.lighthouses`):

1. validate the world for the lighthouse (§3.3: the robot drops its kit at v0,
   facing the exit it starts facing; a world file may carry exactly those
   markers or none);
2. build the simulator with the lighthouse's kit, build the explorer with the
   registry entry's factory (:attr:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec.factory`),
   handing it only its robot, and drive it by the explorer contract
   (``start``, then ``step`` until ``done``);
3. after every iteration run the :class:`~topomark.reference.run.checker.Checker`
   with the checks the algorithm's registry entry names (unless ``check=False``) and hand the trace records to a sink
   (:mod:`~topomark.reference.trace.sink`: kept in a list, streamed to a file,
   or only the last few kept) as they are made;
4. return an :class:`Outcome` with the map, the cost split by purpose and the
   counts the CLI reports.

The trace format is documented in ``spec/trace.md``.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Callable

from topomark.spec.errors import (AlgorithmStopped, CheckFailure, InvalidInput, LimitReached, OutOfMarkers,
                                   Violation, unknown_name)
from topomark.spec.kit import Kit
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.markerlayer import MarkerLayer, apply_op
from topomark.spec.world import World
from topomark.spec.worldfile import marker_to_json

from topomark.reference.run.breakdown import CostBreakdown
from topomark.reference.run.checker import Checker
from topomark.reference.run.outcome import Outcome
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse
from topomark.reference.algorithms.expectation import CORRECT
from topomark.reference.algorithms.registry import AlgorithmSpec, algorithm_spec
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.simulator import Simulator
from topomark.reference.trace.families import ALGORITHM_FAMILIES
from topomark.reference.trace.flight import FlightRecorder
from topomark.reference.trace.records import end_record, op_record, trace_header
from topomark.reference.trace.sink import ListSink, TraceSink

__all__ = ["Outcome", "explore", "check_run", "prepare_world", "dropped_at_start"]

def dropped_at_start(bare: World, state: tuple[str, int], lighthouse: Lighthouse) -> MarkerLayer:
    """``bare``'s marker layer once the robot, starting at ``state``, has established ``lighthouse``: each of its
    operations done where the robot does it (Figure 3.21(b)'s moves included)."""
    layer = MarkerLayer(bare)
    for place, op in lighthouse.placed_ops(bare, state):
        apply_op(layer, place, op)
    return layer


def prepare_world(world: World, lighthouse: Lighthouse = LIGHTHOUSES["directional-vertex"],
                  algorithm: str = "basic") -> tuple[World, tuple[str, int]]:
    """The world without markers and the start state, checked against the lighthouse (§3.3, §6.1, §6.2).

    A world file may already carry the markers (and the thread) the robot
    would drop at the start (the lighthouse's, where the robot drops them);
    any other marker or thread, or a part of them, is bad input for this
    algorithm.
    """
    state = world.start_state()
    v0, facing = state
    bare = world if type(world) is World and not world.markers else World(world.rotation, (), world.start)
    if bare.degree(v0) < lighthouse.min_degree:
        raise InvalidInput(f"the {lighthouse.name} lighthouse needs a start vertex of degree >= "
                           f"{lighthouse.min_degree}; the start vertex {v0!r} has degree {bare.degree(v0)}")
    thread = getattr(world, "thread", None)
    if world.markers or thread is not None:
        layer = dropped_at_start(bare, state, lighthouse)
        if thread is not None and getattr(layer.world(), "thread", None) != thread:
            raise InvalidInput(f"the {algorithm} algorithm with the {lighthouse.name} lighthouse cannot use the "
                               f"thread in the world file: only {lighthouse.drops}, at the start vertex {v0!r}, "
                               f"may be there")
        if not world.markers:
            return bare, state
        expected = {_place(m): m for m in layer.markers()}
        for marker in world.markers:
            _expect_marker(marker, expected.get(_place(marker)), world, lighthouse, algorithm, v0, facing)
        if len(world.markers) != len(expected):
            raise InvalidInput(f"the world file carries {len(world.markers)} of the {len(expected)} markers the "
                               f"{lighthouse.name} lighthouse drops at the start: give all of them or none")
    return bare, state


def _place(marker) -> Any:
    return ("vertex", marker.at) if isinstance(marker, VertexMarker) else ("edge", frozenset(marker.between))


def _expect_marker(marker, want, world: World, lighthouse: Lighthouse, algorithm: str, v0: str, facing: int) -> None:
    """A world file's marker must be one the lighthouse drops, exactly as it drops it."""
    text = json.dumps(marker_to_json(marker))
    if want is None or marker.directional != want.directional:
        wheel = ("; Figure 3.4's wheels: generate wheel-a:marker=directional (Figure 3.6) or marker=none"
                 if isinstance(marker, VertexMarker) and not marker.directional else "")
        raise InvalidInput(
            f"the {algorithm} algorithm with the {lighthouse.name} lighthouse cannot use the marker {text} in the "
            f"world file: only {lighthouse.drops}, dropped by the robot at the start vertex {v0!r}, may be there; "
            f"remove the file's markers (the robot drops its own{wheel}) or give the --lighthouse that drops them")
    same_edge = isinstance(marker, EdgeMarker) and (marker.count, marker.head) == (want.count, want.head)
    if marker == want or same_edge:
        return
    if isinstance(marker, VertexMarker) and marker.directional:
        raise InvalidInput(
            f"the directional marker at {v0!r} points to {marker.points_to!r}, but the robot starts facing "
            f"{world.neighbour(v0, facing)!r}: the robot drops its marker pointing at the exit it faces")
    raise InvalidInput(f"the world file's marker {text} is not the one the {lighthouse.name} lighthouse drops "
                       f"there: {json.dumps(marker_to_json(want))}")


def explore(world: World, algorithm: "str | AlgorithmSpec" = "basic", policies: Policies | None = None,
            check: bool = True, record: bool = True, progress: Callable[[int, int, int], None] | None = None,
            check_mode: str = "incremental", sink: TraceSink | None = None, keep_hypotheses: bool = True,
            lighthouse: "str | Lighthouse | None" = None, options: dict[str, Any] | None = None) -> Outcome:
    """Explore ``world`` and return the outcome; a violated check ends the run with ``outcome.violation`` set.

    The trace records go to ``sink`` as they are made; without one, ``record=True`` keeps them all in
    ``outcome.trace`` and ``record=False`` makes none.  ``keep_hypotheses=False`` drops each iteration's
    hypotheses (their M, P^E and perceptions) from ``outcome.explorer.iterations`` once they are traced,
    checked and counted, so memory stays proportional to the world.  ``progress(explored_edges, m, cost)``
    is called after every iteration.  ``lighthouse`` (default ``directional-vertex``) is for the lighthouse
    algorithms; ``options`` (name ↦ value) for a kit algorithm's :class:`~topomark.reference.algorithms.algorithm_spec.Parameter`.
    """
    spec = algorithm if isinstance(algorithm, AlgorithmSpec) else algorithm_spec(algorithm)
    run = _setup(world, spec, lighthouse, options or {})
    policies = policies or spec.policies()  # the registration's defaults (its edge policy, if it names one)
    if check_mode not in Checker.MODES:
        raise unknown_name("check mode", check_mode, Checker.MODES)
    sink = ListSink() if sink is None and record else sink
    trace = sink.records if isinstance(sink, ListSink) else []
    flight = FlightRecorder(world, spec.name)  # for a fault report: the world and the trace up to the fault
    emit = _tee(flight.emit, sink.emit) if sink is not None else None
    wanted = getattr(sink, "events", None)  # the record kinds the sink takes (tracesink's docstring); None: all
    try:  # an exception escaping the run is re-raised with the run in progress on it, for a fault report
        return _run(world, spec, run, policies, emit, wanted, trace, check=check, check_mode=check_mode,
                    progress=progress, keep_hypotheses=keep_hypotheses)
    except Exception as exc:
        raise flight.attach(exc)


def _run(world: World, spec: AlgorithmSpec, run: "_Run", policies: Policies, emit: Callable[[dict], None] | None,
         wanted: Any, trace: list[dict], *, check: bool, check_mode: str,
         progress: Callable[[int, int, int], None] | None, keep_hypotheses: bool) -> Outcome:
    """The run :func:`explore` describes, its records made for ``emit`` (those of the kinds ``wanted``)."""
    emit_move = emit if wanted is None or "move" in wanted else None
    tally = _Tally()
    split = CostBreakdown()
    if emit:
        emit(trace_header(spec.name, policies, run.light, world, run.kit, spec.family, _given(spec, run.options)))
    layer = ALGORITHM_FAMILIES[spec.family].events

    def on_move(motion, purpose, sig, true_state):
        if emit_move:
            emit_move({"event": "move", "step": sim.cost, "motion": motion, "perception": str(sig),
                       "purpose": purpose})

    def on_op(event):
        if emit:
            emit(op_record(event, run.light))

    sim = Simulator(run.bare, run.state, run.kit, listener=on_move, op_listener=on_op)
    checker = Checker(sim, check_mode, spec.checks, spec) if check else None

    wrong = _WrongJoins(world, run.light, spec.expectation()[0] != CORRECT)  # the checker's verdict on a
    # lighthouse that may close loops wrongly; an unchecked run of an entry that may end wrong: its map outgrowing G

    def observer(explorer, it):
        if emit and "iteration" in layer and (wanted is None or "iteration" in wanted):
            emit({"event": "iteration", **it.to_json()})
        tally.add(it)  # counted before the check: an iteration that fails it is in explorer.iterations too
        split.after_iteration(sim.by_purpose, it)
        wrong.after_iteration(checker, explorer, it)
        if not keep_hypotheses:
            it.hypotheses = []
        if progress is not None:
            progress(_explored(explorer), world.m, sim.cost)

    explorer = spec.factory(sim.robot(), policies, observer, run.light if spec.uses_lighthouse else run.options)
    started: list = []  # the robot's true state once the explorer has started (v0, for a lighthouse algorithm)
    def on_started() -> None:
        started.append(sim.state)
        split.started(sim.by_purpose)
    violation, stopped = wrong.verdict(*_drive(explorer, checker, on_started))
    split.finish(sim.by_purpose, sim.cost)
    outcome = _outcome(world, sim, explorer, checker, violation, trace, tally, spec, stopped)
    outcome.breakdown = split
    _algorithm_counts(outcome, spec, explorer, world, started[0] if started else None, stopped)
    if emit:
        emit(end_record(outcome))
    return outcome


def _tee(*emits: Callable[[dict], None]) -> Callable[[dict], None]:
    """One ``emit`` handing each record to every one of ``emits``, in order."""
    def emit(record: dict) -> None:
        for each in emits:
            each(record)
    return emit


def _given(spec: AlgorithmSpec, options: dict[str, Any]) -> dict[str, Any]:
    """The options given other than their defaults (the trace header's ``options``: replay re-runs with them)."""
    return {p.name: options[p.name] for p in spec.parameters if options.get(p.name) != p.default}


class _WrongJoins:
    """A wrong loop closing under a lighthouse that is not explicit (§5.2.1): the thesis predicts it, and says
    what the algorithm then does — it "either detects some signature inconsistencies (due to wrong loop closing)
    and thus cannot proceed reporting failure, or, never terminates (when every newly visited place is always
    validated as a new place), or terminates with an incorrect world model" (§5.2.1).

    So under such a lighthouse the checker's first violation after an iteration does not stop the run: it is
    kept, the per-iteration checks stop, and the algorithm runs on to its own end, which the outcome reports —
    ``failed`` (the reason names the iteration where the map went wrong), ``wrong-map`` (the first violation),
    or, once the believed map has more places or edges than the world (it can then never become the world, and
    every new place is being taken for a new one), ``limit``.  A checked run and an unchecked one end alike.
    Under an explicit lighthouse the first violation stops the run: Lemma 1 says it cannot happen.

    An unchecked run (no checker) of an entry not expected to map every world (its registration's expectation
    is not ``correct``) whose believed map outgrows the world ends ``limit`` too, under any lighthouse or none:
    nothing else would stop a listing that keeps adding known places as new ones (Algorithm 6.5 line 23 as
    printed), and the run core, which sees the world, knows that map can never be right.  An entry expected to
    map every world is left to its own consistency checks, which name a bug as topomark's (exit 3)."""

    def __init__(self, world: World, light: Lighthouse | None, may_fail: bool = False):
        self.world, self.deferred, self.may_fail = world, light is not None and not light.certain, may_fail
        self.first: Violation | None = None

    def after_iteration(self, checker: Checker | None, explorer, it) -> None:
        """The checker's per-iteration checks, until the first violation; then whether the map outgrew G."""
        try:
            if checker is not None and self.first is None:
                checker.after_iteration(explorer, it)
        except CheckFailure as exc:
            if not self.deferred:
                raise
            self.first = exc.violation
        S = getattr(explorer, "S", None)
        if (self.deferred or (checker is None and self.may_fail)) and S is not None and (S.n > self.world.n
                                                                      or S.edge_count > self.world.m):
            why = ("every new place is taken for a new one, and the algorithm would never terminate (§5.2.1)"
                   if self.deferred else "it can never become the world's; an unchecked run stops here")
            raise LimitReached(f"the believed map has outgrown the world ({S.n} places, {S.edge_count} edges; the "
                               f"world has {self.world.n} and {self.world.m}): {why}")

    def verdict(self, violation, stopped):
        """The run's violation and stop, the first deferred violation named."""
        if self.first is None:
            return violation, stopped
        if stopped is not None:
            note = f"; the map had gone wrong before it: {self.first.check} violated at {self.first.detail}"
            stopped.reason = f"{stopped.reason}{note}"
            return None, stopped
        return self.first, None


@dataclass(frozen=True)
class _Run:
    """What a run starts from: the world without markers, the start state, the kit, the lighthouse (lighthouse
    algorithms) or the checked options (kit algorithms)."""

    bare: World
    state: tuple[str, int]
    kit: Kit
    light: Lighthouse | None
    options: dict[str, Any]


def check_run(world: World, spec: AlgorithmSpec, lighthouse: "str | Lighthouse | None" = None,
              options: dict | None = None) -> None:
    """Refuse, as bad input, a world, lighthouse or option the algorithm cannot run with (before anything runs)."""
    _setup(world, spec, lighthouse, options or {})


def _setup(world: World, spec: AlgorithmSpec, lighthouse: "str | Lighthouse | None", options: dict) -> _Run:
    """Check the world, lighthouse and options against the algorithm (bad input before anything runs)."""
    opts = spec.parse_options(options)
    light = spec.lighthouse_for(lighthouse)
    if light is not None:
        bare, state = prepare_world(world, light, spec.name)
        return _Run(bare, state, light.kit, light, opts)
    if world.markers or getattr(world, "thread", None) is not None:
        what = f"{len(world.markers)} marker(s)" if world.markers else "a thread"
        raise InvalidInput(f"the algorithm {spec.name} drops its own markers: the world file must carry none "
                           f"(it carries {what})")
    kit = spec.kit_for(world.n, world.m, opts)
    if spec.check_world is not None:
        spec.check_world(world, opts)
    return _Run(World(world.rotation, (), world.start), world.start_state(), kit, None, opts)


def _explored(explorer) -> int:
    """Edges explored so far, for the progress bar (0 for an explorer with no single map)."""
    S = getattr(explorer, "S", None)
    return S.explored_edges() if S is not None else 0


def _drive(explorer, checker: Checker | None, on_started: Callable[[], None] = lambda: None
           ) -> tuple[Any, AlgorithmStopped | OutOfMarkers | None]:
    """The explorer contract: ``start``, then ``step`` until ``done``; the checker after the start and at the
    end.  Returns the first violation (or None) and how the algorithm stopped early (or None)."""
    try:
        explorer.start()
        on_started()
        if checker is not None:
            checker.after_start(explorer)
        while not explorer.done():
            explorer.step()
        if checker is not None:
            checker.at_end(explorer)
    except OutOfMarkers as stop:  # before CheckFailure, its base: the failed outcome, not a violation
        return None, stop
    except CheckFailure as exc:
        return exc.violation, None
    except AlgorithmStopped as stop:
        return None, stop
    return None, None


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
             tally: _Tally, spec: AlgorithmSpec, stopped: AlgorithmStopped | OutOfMarkers | None) -> Outcome:
    """The counts the CLI reports, from the finished (or stopped) run, and its outcome (``spec.errors.OUTCOMES``):
    what the algorithm claimed, and what the checker, which sees the truth, says it is."""
    claimed = stopped.outcome if stopped else "correct" if explorer.done() else "unfinished"  # the checker stopped it
    verified = checker is not None and violation is None and stopped is None
    judged = claimed if stopped else ("correct" if verified else "wrong-map" if checker is not None else "unchecked")
    light = getattr(explorer, "lighthouse", None)
    bound = spec.bound_for(world.n, world.m)  # enh4/enh5 state none exact (their registration's docstring)
    return Outcome(
        n=world.n, m=world.m, cost=sim.cost, drop_trips=sim.drop_trips, verified=verified,
        iterations=tally.iterations, loop_iterations=tally.loop, nonloop_iterations=tally.nonloop,
        hypotheses=tally.hypotheses, hypotheses_rejected=tally.rejected, hypotheses_confirmed=tally.confirmed,
        checks=checker.passed if checker else 0, by_purpose=dict(sorted(sim.by_purpose.items())),
        upper_bound=bound, lighthouse=None if light is None else light.name,
        marker_operations=dict(sorted(sim.operations.items())), explorer=explorer, trace=trace, violation=violation,
        outcome=judged, claimed=claimed, reason=stopped.reason if stopped else None, kit=sim.kit.describe(),
        bound_checked=checker is not None and "cost-bound" in checker.checks, algorithm=spec.name,
        bound_whose=spec.bound_whose)


def _algorithm_counts(outcome: Outcome, spec: AlgorithmSpec, explorer, world: World, v0_state,
                      stopped: AlgorithmStopped | OutOfMarkers | None = None) -> None:
    """What only some algorithms have: their own counts (the registry's ``summary_fn``), and for a lighthouse
    algorithm the walk that found v0 (§5.1, §6.1) — or, when the search gave up, the walk it made before it
    did — and the world vertex v0 is."""
    if spec.summary_fn is not None:
        outcome.extra = spec.summary_fn(explorer, world)
    if spec.uses_lighthouse:
        beacon = getattr(explorer, "beacon", None)
        walked = getattr(stopped, "walk_steps", None)
        outcome.walk_steps = beacon.walk_steps if beacon is not None else walked if walked is not None else 0
        outcome.lighthouse_at = v0_state[0] if v0_state else None