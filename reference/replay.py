"""``replay``: verify a ``topomark/trace@1`` trace recorded by any implementation (thesis §3.1–3.4).

A trace (``spec/trace.md``) claims a run of Algorithm 3.1: the marker drop,
every motion with the perception it produced, every iteration's join and the
cost.  :func:`replay` re-executes it on the world and checks, in order:

* every ``move`` and the ``drop``: replaying the motions from the world's
  start (:mod:`topomark.spec.robot`) gives exactly the claimed perceptions;
  the step numbers run 1, 2, ...;
* every ``iteration``: S and U are rebuilt from the joins (a non-loop join
  adds a vertex whose degree is that of the iteration's ``signature``, its
  other exits join U; a loop join removes e' from U; e itself is taken from
  U) — or U is taken from the record's optional ``unexplored`` field — and
  I-1 and I-2 (§3.4) must hold, φ anchored at the lighthouse (checked per
  journalled addition to S by :class:`~topomark.spec.invariants.
  IncrementalInvariants`, as the checker does; the end uses the full
  isomorphism);
* the ``end``: the claimed cost equals the traversals replayed; U is empty,
  there were m iterations and the rebuilt map is extended-isomorphic to the
  world with the dropped marker (§3.1.3).

The first divergence is reported with its step or iteration, what the world
(or the spec) expected and what the trace claims.  A trace that is not
well-formed, has the wrong format version, or was recorded on a world of a
different size is bad input (:class:`~topomark.spec.errors.InvalidInput`).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from topomark.spec.errors import CheckFailure, InvalidInput, Violation
from topomark.spec.invariants import IncrementalInvariants, lighthouse_anchor
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature
from topomark.spec.world import World

from .explore import TRACE_FORMAT, prepare_world
from .mapcheck import check_map
from .simulator import Simulator

__all__ = ["ReplayResult", "replay", "load_trace", "parse_trace", "EVENTS"]

_I, _S, _B, _O, _L, _D = "integer", "string", "boolean", "object", "list", "dart"
EVENTS: dict[str, tuple[dict[str, str], dict[str, str]]] = {  # event -> (required fields, optional fields)
    "header": ({"format": _S, "algorithm": _S, "policies": _O, "n": _I, "m": _I}, {}),
    "drop": ({"direction": _I, "signature": _S}, {}),
    "move": ({"step": _I, "motion": _I, "perception": _S, "purpose": _S}, {}),
    "iteration": ({"iteration": _I, "edge": _D, "signature": _S, "hypotheses": _L, "augmentation": _S,
                   "joined": _L, "by_marker": _B}, {"unexplored": _L, "enhancement": _O}),  # both optional
    "end": ({"cost": _I, "verified": _B, "violation": "object or null"}, {}),
}


@dataclass(frozen=True)
class ReplayResult:
    ok: bool
    message: str
    cost: int
    iterations: int
    divergence: Violation | None = None
    line: int | None = None

    def to_json(self) -> dict[str, Any]:
        return {"verified": self.ok, "message": self.message, "cost": self.cost, "iterations": self.iterations,
                "line": self.line, "divergence": None if self.divergence is None else self.divergence.to_json()}


# -- reading --------------------------------------------------------------------
def _typed(value: Any, kind: str) -> bool:
    if kind == _I:
        return isinstance(value, int) and not isinstance(value, bool)
    if kind == _D:
        return isinstance(value, list) and len(value) == 2 and all(_typed(x, _I) for x in value)
    if kind == "object or null":
        return value is None or isinstance(value, dict)
    return isinstance(value, {_S: str, _B: bool, _O: dict, _L: list}[kind])


def _check_record(rec: Any, where: str) -> dict[str, Any]:
    if not isinstance(rec, dict) or rec.get("event") not in EVENTS:
        found = rec.get("event") if isinstance(rec, dict) else type(rec).__name__
        raise InvalidInput(f"{where}: expected a trace event ({', '.join(EVENTS)}), found {json.dumps(found)}")
    required, optional = EVENTS[rec["event"]]
    for key in sorted(set(rec) - {"event"}):
        kind = required.get(key) or optional.get(key)
        if kind is None:
            raise InvalidInput(f"{where}: unknown field {key!r} in a {rec['event']} event")
        if not _typed(rec[key], kind):
            raise InvalidInput(f"{where}: {rec['event']}.{key} must be {'[vertex, exit]' if kind == _D else kind}, "
                               f"got {json.dumps(rec[key])}")
    missing = [k for k in required if k not in rec]
    if missing:
        raise InvalidInput(f"{where}: {rec['event']} event without field {missing[0]!r}")
    return rec


def parse_trace(text: str, source: str = "<trace>") -> list[dict[str, Any]]:
    """Parse and structurally validate a trace; any defect is one :class:`InvalidInput`."""
    records = []
    for k, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            raise InvalidInput(f"{source} line {k}: empty line (a trace has one JSON object per line)")
        try:
            rec = json.loads(line)
        except json.JSONDecodeError as exc:
            raise InvalidInput(f"{source} line {k}: malformed JSON ({exc.msg} at column {exc.colno})") from None
        records.append(_check_record(rec, f"{source} line {k}"))
    if not records or records[0]["event"] != "header":
        raise InvalidInput(f"{source}: the first line must be the header event")
    fmt = records[0]["format"]
    if fmt != TRACE_FORMAT:
        raise InvalidInput(f"{source} line 1: unknown trace format {fmt!r} (this is {TRACE_FORMAT})")
    ends = [k for k, r in enumerate(records, 1) if r["event"] == "end"]
    if ends != [len(records)]:
        raise InvalidInput(f"{source}: there must be exactly one end event, on the last line"
                           + (f" (found at lines {ends})" if ends else " (found none: truncated trace?)"))
    for k, rec in enumerate(records[1:], 2):
        if rec["event"] == "header":
            raise InvalidInput(f"{source} line {k}: a second header")
    return records


def load_trace(path: str | Path) -> list[dict[str, Any]]:
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InvalidInput(f"{path}: cannot read the trace ({exc.__class__.__name__})") from None
    return parse_trace(text, str(path))


def _signature(text: str, where: str) -> Signature:
    try:
        return Signature.parse(text)
    except InvalidInput as exc:
        raise InvalidInput(f"{where}: {exc}") from None


# -- replaying ------------------------------------------------------------------
class _Diverged(Exception):
    def __init__(self, violation: Violation):
        super().__init__(str(violation))
        self.violation = violation


def _diverge(where: str, expected: str, found: str, detail: str = "", check: str = "replay") -> None:
    raise _Diverged(Violation(check, where, expected, found, detail))


class _Replayer:
    def __init__(self, world: World, source: str):
        bare, state = prepare_world(world)
        self.sim = Simulator(bare, state, {"directional-vertex": 1})
        self.robot = self.sim.robot()
        self.source = source
        self.S: PartialMap | None = None
        self.steps = 0
        self.iterations = 0
        self.new_perception: str | None = None
        self.invariants: IncrementalInvariants | None = None

    def drop(self, rec: dict) -> None:
        if self.S is not None:
            _diverge("drop", "one marker drop (Algorithm 3.1 line 1)", "a second drop")
        v, entry = self.sim.state
        degree = self.sim.world.degree(v)
        if not 0 <= rec["direction"] < degree:
            _diverge("drop", f"a direction 0..{degree - 1}", str(rec["direction"]))
        self.robot.drop_marker(rec["direction"])
        got = str(self.robot.sense())
        if rec["signature"] != got:
            _diverge("drop", f"signature {got}", rec["signature"])
        self.S = PartialMap()
        v0 = self.S.add_vertex(degree)
        self.S.mark_vertex(v0, head=rec["direction"])
        self.S.unexplored = [(v0, i) for i in range(degree)]

    def move(self, rec: dict) -> None:
        self.steps += 1
        where = f"step {self.steps}"
        if rec["step"] != self.steps:
            _diverge(where, f"step number {self.steps}", str(rec["step"]), "steps must run 1, 2, 3, ...")
        v, _ = self.sim.state
        degree = self.sim.world.degree(v)
        if not 0 <= rec["motion"] < degree:
            _diverge(where, f"a motion 0..{degree - 1} (the robot is at a vertex of degree {degree})",
                     f"motion {rec['motion']}")
        got = str(self.robot.move(rec["motion"], "other"))
        if rec["perception"] != got:
            _diverge(where, f"perception {got} (motion {rec['motion']} on the world)",
                     f"perception {rec['perception']}")
        if rec["purpose"] == "new":
            self.new_perception = got

    def iteration(self, rec: dict, where: str) -> None:
        self.iterations += 1
        it = f"iteration {self.iterations}"
        S = self.S
        if S is None:
            _diverge(it, "the marker drop before the first iteration", "no drop")
        if rec["iteration"] != self.iterations:
            _diverge(it, f"iteration number {self.iterations}", str(rec["iteration"]))
        sig = _signature(rec["signature"], where)
        if self.new_perception is not None and rec["signature"] != self.new_perception:
            _diverge(it, f"v_u's signature {self.new_perception} (perceived on the new edge)", rec["signature"])
        self.new_perception = None
        self.join(rec, sig, it)
        if "unexplored" in rec:
            U = rec["unexplored"]
            if not all(_typed(d, _D) for d in U):
                raise InvalidInput(f"{where}: iteration.unexplored must be a list of [vertex, exit]")
            S.unexplored = [tuple(d) for d in U]
        if self.invariants is None:
            self.invariants = IncrementalInvariants(S, self.sim.world, lighthouse_anchor(S, self.sim.world))
        bad = self.invariants.update()
        if bad is not None:
            raise _Diverged(Violation(bad.check, bad.where, bad.expected, bad.found,
                                      f"{it}" + (f"; {bad.detail}" if bad.detail else "")))

    def join(self, rec: dict, sig: Signature, it: str) -> None:
        S = self.S
        e = tuple(rec["edge"])
        joined = rec["joined"]
        if len(joined) != 2 or not all(_typed(d, _D) for d in joined):
            _diverge(it, "joined = [[v_k, exit], [v, exit]]", json.dumps(joined))
        a, b = tuple(joined[0]), tuple(joined[1])
        if e not in S.unexplored:
            _diverge(it, f"e = {list(e)} taken from U", "an edge not in U", "Algorithm 3.1 line 5")
        S.unexplored.remove(e)
        if a != e:
            _diverge(it, f"the join to start at e = {list(e)}", str(list(a)))
        kind = rec["augmentation"]
        if kind == "non-loop":
            if b[0] != S.n:
                _diverge(it, f"a non-loop join to the new vertex {S.n}", f"a join to vertex {b[0]}")
            if not 0 <= b[1] < sig.degree:
                _diverge(it, f"an exit 0..{sig.degree - 1} of the new vertex", str(b[1]))
            u = S.add_vertex(sig.degree)
            S.unexplored.extend((u, j) for j in range(sig.degree) if j != b[1])
        elif kind == "loop":
            if b not in S.unexplored:
                _diverge(it, f"e' = {list(b)} in U", "a dart not in U", "Algorithm 3.1 line 25")
            S.unexplored.remove(b)
        else:
            _diverge(it, "augmentation \"loop\" or \"non-loop\"", json.dumps(kind))
        try:
            S.add_edge(a, b)
        except CheckFailure as exc:
            _diverge(it, "a join of two open darts of S", str(exc))

    def end(self, rec: dict, world: World) -> None:
        if rec["cost"] != self.steps:
            _diverge("end", f"cost {self.steps} (the traversals replayed)", f"cost {rec['cost']}")
        if self.S is None:
            _diverge("end", "a marker drop and m iterations", "no drop")
        if self.iterations != world.m:
            _diverge("end", f"m = {world.m} iterations", str(self.iterations))
        if self.S.unexplored or not self.S.complete():
            _diverge("end", "U empty and S complete", f"U = {self.S.unexplored[:5]}")
        verdict = check_map(self.sim.world.with_start(world.start), self.S.to_world())
        if not verdict.isomorphic:
            m = verdict.result.mismatch
            raise _Diverged(Violation("extended isomorphism", m.where, m.expected, m.found, "the final map"))


def replay(world: World, records: list[dict[str, Any]], source: str = "<trace>") -> ReplayResult:
    """Verify a parsed trace against ``world``; the first divergence, or a positive verdict."""
    header = records[0]
    if (header["n"], header["m"]) != (world.n, world.m):
        raise InvalidInput(f"{source}: the trace was recorded on a world with n={header['n']}, m={header['m']}, "
                           f"but this world has n={world.n}, m={world.m}")
    r = _Replayer(world, source)
    line = 1
    try:
        for line, rec in enumerate(records[1:], 2):
            kind = rec["event"]
            if kind == "drop":
                r.drop(rec)
            elif kind == "move":
                r.move(rec)
            elif kind == "iteration":
                r.iteration(rec, f"{source} line {line}")
            elif kind == "end":
                r.end(rec, world)
    except _Diverged as exc:
        return ReplayResult(False, f"line {line}: {exc.violation}", r.steps, r.iterations, exc.violation, line)
    return ReplayResult(True, f"{r.steps} traversals, {r.iterations} iterations, every perception "
                              f"matches the world, I-1/I-2 held after every iteration, the map is "
                              f"extended-isomorphic", r.steps, r.iterations)
