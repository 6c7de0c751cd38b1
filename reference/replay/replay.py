"""``replay``: verify a trace recorded by any implementation — ``topomark/trace@1`` or ``@2`` (``spec/trace.md``).

A trace claims a run: what the robot did (the *robot layer*: every move with
the perception it produced, every marker operation with the signature sensed
after it) and, for a family of algorithms that defines one, what the
algorithm did (the *algorithm layer*: for Algorithm 3.1's family, every
iteration's hypotheses and join), then the cost and the recorder's verdict.
:func:`replay` re-executes it on the world and checks every claim, in order
(well-formedness — the header's format, family, algorithm, policies,
lighthouse and kit, vocabularies, field sets, signatures, JSON limits — is
:mod:`topomark.reference.trace.reader`'s, exit 2):

* the robot layer, for every trace: :class:`~topomark.reference.replay.robot_layer.
  RobotLayer` (moves and ops re-executed by a simulator carrying the header's
  kit; steps; the claimed cost);
* the algorithm layer where the header's family has one: for
  ``algorithm-3.1`` (and every trace@1) :class:`~topomark.reference.
  alg31layer.Algorithm31Layer` (the lighthouse's operations at the start, the
  purposes of the moves, ``by_marker``, the hypotheses re-checked by
  :mod:`~topomark.reference.replay.hypotheses`, S and U rebuilt, I-1/I-2 after every
  iteration, m iterations, U empty, the final map extended-isomorphic to the
  world with the markers dropped);
* where a Chapter 4 listing is registered beside topomark's variant of it (``enh3`` and ``enh3-listing``, …),
  whose moves the trace made: :class:`~topomark.reference.replay.variant_match.VariantMatch` re-runs both and
  names the one it follows (``rerun``), or none — it judges nothing, the algorithm layer does;
* the recorder's verdict: ``verified: true`` claims all of this;
  ``verified: false`` with a ``violation`` claims a failure — if replay finds
  none that claim is false (exit 1, check ``"trace claim"``), if replay
  diverges the trace is *consistent* (it records its own failure:
  ``recorded_failure``) and the verdict is still negative (exit 1);
  ``verified: false`` with ``violation: null`` is an unjudged run
  (``explore --no-check``, ``drive`` without a world) and replay's own
  verdict stands.  Which check the recorder names is not compared with
  replay's: a recorder stops at its first failure, so replay typically finds
  the run truncated rather than the same check.

The verdict names the layers verified (``layers``).  Not checked, because the
trace does not determine it: which e the edge policy picks (it needs the
explorer's believed position between moves), the ``known`` counter of
Enhancement 3 (perceptions recorded in its private T), and what
:mod:`~topomark.reference.replay.hypotheses` lists.  Nothing else a record carries is
left unchecked.

The first divergence is reported with its line and step, op or iteration,
what the world (or the spec) expected and what the trace claims.  The trace
is read lazily, line by line (:func:`load_trace`); after a divergence the
rest is still read, because bad input anywhere (:class:`~topomark.spec.
errors.InvalidInput`) outranks a divergence.  A trace recorded on a world of
a different size is bad input too.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Any, Callable, Iterable, Iterator, cast

from topomark.spec.errors import InvalidInput, Violation, clip
from topomark.spec.world import World

from topomark.reference.explorers.lighthouses import Lighthouse
from topomark.reference.replay.algorithm31_layer import Algorithm31Layer
from topomark.reference.replay.divergence import Diverged
from topomark.reference.replay.rerun_layer import RerunLayer, rerun_spec
from topomark.reference.replay.robot_layer import RobotLayer
from topomark.reference.replay.variant_match import VariantMatch, paired
from topomark.reference.trace.header import header_family, header_kit, header_lighthouse
from topomark.reference.trace.reader import EVENTS, EVENTS_2, _records, load_trace, parse_trace
from topomark.reference.trace.sink import trace_line

__all__ = ["ReplayResult", "Observer", "replay", "load_trace", "parse_trace", "parse_records", "EVENTS", "EVENTS_2"]


def parse_records(records: Iterable[Any], source: str = "<records>") -> Iterator[dict[str, Any]]:
    """``records`` (trace records as objects: an ``Outcome.trace``, or a generator) checked as a trace file's
    lines are (:func:`load_trace`): each is written as its line and read back, one at a time, so a stream of
    records is never held whole and the first bad one is refused when reached.  A record that cannot be written
    as JSON (a set, a cycle, nesting past Python's limit) is :class:`InvalidInput` naming its line."""
    def lines() -> Iterator[tuple[int, str]]:
        for k, rec in enumerate(records, 1):
            try:
                line = trace_line(rec)
            except (TypeError, ValueError, RecursionError) as exc:
                raise InvalidInput(f"{source} line {k}: not a JSON object ({type(exc).__name__}: "
                                   f"{clip(str(exc), 80)})") from None
            yield k, line[:-1]

    return _records(lines(), source)


@dataclass(frozen=True, repr=False)
class ReplayResult:
    """The verdict of replaying a trace against its world: does every claim of the trace hold?

    ``ok`` is the verdict and ``message`` says what was verified or where the trace first diverges from the
    world; ``divergence`` is that first failed check (a :class:`~topomark.spec.errors.Violation`) and
    ``line`` its line in the trace.  ``cost`` and ``iterations`` are what the replay counted, ``layers`` the
    layers replayed (the robot's, and the algorithm family's where it has one), ``recorded_failure`` whether
    the trace's end itself records the failure found.
    """

    ok: bool
    message: str
    cost: int
    iterations: int
    divergence: Violation | None = None
    line: int | None = None
    recorded_failure: bool = False  # the trace's end claims the failure replay found
    layers: tuple[str, ...] = ("robot", "algorithm-3.1")  # the layers replayed: the robot's and the family's, if any
    rerun: dict[str, Any] | None = None  # the re-run the trace follows (variant_json: the listing or topomark's)

    def __repr__(self) -> str:
        """``ReplayResult(ok, cost=5522, iterations=148, layers=robot+algorithm-3.1)``, or the divergence and its
        line: the verdict in one short line."""
        where = "" if self.line is None else f"line {self.line}: "
        verdict = "ok" if self.ok else f"diverged at {where}{clip(self.message, 500)}"
        return (f"ReplayResult({verdict}, cost={self.cost}, iterations={self.iterations}, "
                f"layers={'+'.join(self.layers)})")

    def to_json(self) -> dict[str, Any]:
        return {"verified": self.ok, "message": self.message, "cost": self.cost, "iterations": self.iterations,
                "line": self.line, "divergence": None if self.divergence is None else self.divergence.to_json(),
                "recorded_failure": self.recorded_failure, "layers": list(self.layers), "rerun": self.rerun}


# -- replaying ------------------------------------------------------------------
class _Replay:
    """The layers a trace's header asks for: the robot layer always, Algorithm 3.1's where the family has it."""

    def __init__(self, world: World, header: dict[str, Any], source: str):
        light, family = header_lighthouse(header), header_family(header)
        self.robot = RobotLayer(world, light, header_kit(header))
        self.algorithm = Algorithm31Layer(self.robot, world, header, cast(Lighthouse, light), source) \
            if family.events else None  # Algorithm 3.1's family always has its lighthouse
        spec = rerun_spec(header)
        self.rerun = RerunLayer(world, header, spec, source) if spec is not None else None
        pair = paired(header) if self.algorithm is not None else None  # Chapter 4: the listing and the variant
        self.match = VariantMatch(world, header, pair) if pair is not None else None
        self.layers = family.layers + (("re-run",) if self.rerun is not None else ())
        self.family = family.name
        self.name = header["algorithm"]
        self.trace2 = "family" in header

    def begin(self) -> None:
        if self.rerun is not None:
            self.rerun.begin()

    def close(self) -> None:
        if self.rerun is not None:
            self.rerun.close()
        if self.match is not None:
            self.match.close()

    @property
    def iterations(self) -> int:
        return self.algorithm.iterations if self.algorithm is not None else 0

    def record(self, rec: dict[str, Any], where: str) -> None:
        kind, alg, robot = rec["event"], self.algorithm, self.robot
        if kind == "move":
            step = robot.step(rec)
            if alg is not None:
                alg.purpose(rec["purpose"], step)
            perception = robot.move(rec, step)
            if alg is not None:
                alg.moved(rec, perception)
        elif kind == "op":
            sensed = robot.op(rec)
            if alg is not None:
                alg.op(rec, sensed)
        elif kind == "drop":  # Algorithm 3.1's events: alg is there (the trace's checked family records them)
            cast(Algorithm31Layer, alg).drop(rec)
        elif kind == "iteration":
            cast(Algorithm31Layer, alg).iteration(rec, where)
        elif kind == "end":
            robot.end(rec)
            if alg is not None:
                alg.end(rec)
        if self.rerun is not None:
            self.rerun.record(rec, where)
        if self.match is not None:
            self.match.record(rec)


def _claim(end: dict) -> str:
    v = end["violation"]
    return "a verified run" if end["verified"] else "an unjudged run" if v is None else \
        f"a failed run: {Violation(v['check'], v['where'], v['expected'], v['found'], v['detail'])}"


Observer = Callable[[Any, dict[str, Any], int], None]
"""Called with the replay's layers (``robot``: the :class:`RobotLayer`; ``algorithm``: the
:class:`Algorithm31Layer` or None), a record and its line, once the record is replayed — or has diverged."""


def replay(world: World, records: Iterable[dict[str, Any]], source: str = "<trace>",
           observe: Observer | None = None) -> ReplayResult:
    """Verify checked trace records (:func:`load_trace`, :func:`parse_trace`) against ``world``.

    The first divergence, or a positive verdict; a claimed failure replay does
    not reproduce is a divergence.  Bad input anywhere in the trace (even after
    the divergence) is raised as :class:`InvalidInput`.  ``observe`` (the run
    viewer's) sees the layers after every record up to the divergence, the
    header's included.
    """
    records = iter(records)
    header = next(records)
    if (header["n"], header["m"]) != (world.n, world.m):
        raise InvalidInput(f"{source}: the trace was recorded on a world with n={header['n']}, m={header['m']}, "
                           f"but this world has n={world.n}, m={world.m}")
    r = _Replay(world, header, source)
    line, rec = 1, header
    try:
        if observe is not None:
            observe(r, header, 1)
        r.begin()
        for line, rec in enumerate(records, 2):
            try:
                r.record(rec, f"{source} line {line}")
            except Diverged:
                if observe is not None:
                    observe(r, rec, line)
                raise
            if observe is not None:
                observe(r, rec, line)
    except Diverged as exc:
        r.close()
        rest = deque(records, maxlen=1)  # read (and so check) every later line: bad input outranks a divergence
        rec = rest[0] if rest else rec  # the trace's own last record: its end, with the recorder's verdict
        failed = rec["violation"] is not None
        note = f"; consistent: the trace records its own failure ({_claim(rec)})" if failed else ""
        return ReplayResult(False, f"line {line}: {exc.violation}{note}", r.robot.steps, r.iterations, exc.violation,
                            line, failed, r.layers)
    r.close()
    if r.algorithm is None and r.rerun is None and (rec["verified"] or rec["violation"] is not None or "outcome" in rec):
        return _refused(r, rec, line)
    if rec["violation"] is not None:
        false = Violation("trace claim", "end", "no violation (replay verifies the run)", _claim(rec),
                          "the trace claims a failure but replay finds none")
        return ReplayResult(False, f"line {line}: {false}", r.robot.steps, r.iterations, false, line, layers=r.layers)
    note = "" if rec["verified"] else " (the recorder did not judge the run: verified false, no violation)"
    followed = r.rerun.followed.variant_json() if r.rerun is not None else \
        _matched(r.match) if r.match is not None else None
    if "outcome" in rec:
        return ReplayResult(True, _stopped(r, rec), r.robot.steps, r.iterations, layers=r.layers, rerun=followed)
    return ReplayResult(True, _verified(r) + note, r.robot.steps, r.iterations, layers=r.layers, rerun=followed)


def _refused(r: _Replay, end: dict, line: int) -> ReplayResult:
    """A robot-layer-only trace whose end claims what replay cannot check: refused, not accepted (exit 1)."""
    claim = _claim(end) if "outcome" not in end else f"a stopped run: {end['outcome']} ({end['reason']})"
    v = Violation("trace claim", "end", "an unjudged end (verified false, no violation, no outcome): the "
                  f"family {r.family} defines no algorithm layer and topomark does not run {r.name}, so replay "
                  "judges what the robot did only", claim,
                  f"{r.robot.steps} traversals and {_ops(r.robot.ops)} match the world (robot layer only); the "
                  "claim about the run cannot be checked, so it is refused")
    return ReplayResult(False, f"line {line}: {v}", r.robot.steps, r.iterations, v, line, layers=r.layers)


def _verified(r: _Replay) -> str:
    """What a positive verdict verified: every layer the trace's family has (trace@1's words as they were)."""
    steps = r.robot.steps
    if r.rerun is not None:
        run = r.rerun.followed
        whose = f"{run.name}'s own run ({run.variant_json()['follows']})" if run.name == r.name else \
            f"the run of {run.name} ({run.variant_json()['follows']}, registered beside {r.name})"
        return (f"{steps} traversals and {_ops(r.robot.ops)}, every perception and signature matches the world, "
                f"the header's kit is {r.name}'s, and every record and the end are {whose}, re-run on "
                "the world and checked (robot and re-run layers)")
    if r.algorithm is None:
        return (f"{steps} traversals and {_ops(r.robot.ops)}, every perception and signature matches "
                f"the world (robot layer only: the family {r.family} defines no algorithm layer)")
    ops = f" and {_ops(r.robot.ops)}" if r.trace2 else ""
    layers = " (robot and algorithm-3.1 layers)" if r.trace2 else ""
    return (f"{steps} traversals{ops}, {r.iterations} iterations, every perception matches the world, every "
            f"purpose and hypothesis record holds, Lemma 1, I-1/I-2 held after every iteration, the map is "
            f"extended-isomorphic{layers}{_whose_moves(r.match)}")


def _matched(match: VariantMatch) -> dict[str, Any] | None:
    run = match.followed
    return None if run is None else run.variant_json()


def _whose_moves(match: VariantMatch | None) -> str:
    """Where a Chapter 4 listing is registered beside topomark's variant: whose moves the trace made."""
    if match is None:
        return ""
    run = match.followed
    if run is None:
        return ("; its moves are neither " + " nor ".join(f"{s.name}'s" for s in match.specs) +
                " (another choice where the thesis leaves one open: the claims above are what is judged)")
    return f"; its moves are {run.name}'s ({run.variant_json()['follows']}), re-run on the world"


def _stopped(r: _Replay, end: dict) -> str:
    """A run that stopped before it had a map (trace@2 ``end.outcome``): what replay verified up to there."""
    layers = " and the algorithm-3.1 layer's records" if r.algorithm is not None else \
        f" and the re-run of {r.rerun.followed.name} stops here too" if r.rerun is not None else ""
    return (f"{r.robot.steps} traversals and {_ops(r.robot.ops)}, every perception and signature matches the world"
            f"{layers}; the run stopped before it had a map: {end['outcome']} ({end['reason']})")


def _ops(k: int) -> str:
    return f"{k} marker operation{'s' if k != 1 else ''}"
