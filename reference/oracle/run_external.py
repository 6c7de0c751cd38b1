"""``run-external``: another program explores a world that topomark plays (thesis §3.1, §3.3–3.4).

topomark is the world side of ``topomark/protocol@1`` and ``@2`` (``spec/protocol.md``): it holds the world in a
:class:`~topomark.reference.run.simulator.Simulator`, answers every ``move`` and ``drop`` with the signature reached
(§3.1.1), counts the cost in edge traversals (§3.1.2), enforces the marker kit (``@1``: Algorithm 3.1's one
directional vertex marker, §3.3; ``@2``: any :class:`~topomark.spec.kit.Kit`) and the limits, checks I-1 and I-2
(§3.4) on every ``snapshot`` of (S, U), and judges the final ``map`` by extended isomorphism (§3.1.3) against the
world with the markers the program left in it, and by whether what the program sensed determines it
(:mod:`~topomark.reference.oracle.determination`).

Time is the program's time: the ``--timeout`` and ``--message-timeout`` limits count only the time topomark waits
for the program (:class:`~topomark.reference.oracle.peer.Peer`); what topomark spends checking snapshots and judging
the map is reported apart (:attr:`ExternalResult.program_seconds`, :attr:`ExternalResult.topomark_seconds`) and
never makes a ``timeout``.  With ``record``, what the program's robot did is kept as a trace
(:class:`~topomark.reference.oracle.program_trace.ProgramTrace`, ``ExternalResult.program``), for the run viewer.

The world is played without markers: the program drops its own from its kit.  A world file may carry the marker
Algorithm 3.1's robot drops at the start (a directional vertex marker pointing at the faced exit, §3.3: the marker
of a map written by an explorer), which is taken away whatever the kit; any other marker, or a thread, is bad input.

Whatever the program does, the session ends with an :class:`ExternalResult`:
a crash, a hang, garbage on stdout, an exit that does not exist, a second
marker — each is a ``fail`` verdict with a reason and a message, never a
hang or a traceback.
"""

from __future__ import annotations

import json
import time
from dataclasses import dataclass, field
from typing import Any, Sequence, cast

from topomark.spec.errors import CheckFailure, InvalidInput, InvalidWorld, TopomarkFault, Violation, clip
from topomark.spec.invariants import check_invariants, lighthouse_anchor
from topomark.spec.isomorphism import Witness, find_isomorphism, verify_witness
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.marker import VertexMarker
from topomark.spec.worldfile import marker_to_json
from topomark.spec.world import World
from topomark.spec.worldfile import world_from_json

from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.run.explore import dropped_at_start, prepare_world
from topomark.reference.run.map_check import MapVerdict
from topomark.reference.oracle.program_trace import ProgramTrace
from topomark.reference.oracle.peer import Peer
from topomark.reference.oracle.protocol import MAX_MESSAGE, PROTOCOL, PROTOCOL2, Expect, ProtocolError, shape_error
from topomark.reference.run.simulator import Simulator
from topomark.reference.oracle.snapshot_wire import MalformedSnapshot, snapshot_to_map
from topomark.reference.oracle.marker_messages import op_from_message, refusal
from topomark.reference.oracle.determination import REWIND, Action, Determination, determination

__all__ = ["Limits", "ExternalResult", "run_external", "REASONS", "LIGHTHOUSE_KIT", "START_ANCHOR", "GAVE_UP"]

LIGHTHOUSE_KIT = Kit(vertex=1, directional=True)  # Algorithm 3.1's kit: @1's only one, @2's default
GAVE_UP = "the program gave up"  # how a verdict starts when the program reported failure (sent ``error``)
COMPARED = "the markers the program left in the world are compared with the map's"
START_ANCHOR = ("topomark/protocol@2 anchors φ at the start: map vertex 0 is the vertex the robot started at "
                "and its exit 0 the exit the robot faced there")

REASONS = {
    "ok": "the map is extended-isomorphic to the world",
    "crash": "the program died or closed its output before sending its map",
    "timeout": "the program did not answer in time (its own time: topomark's checking is not counted)",
    "garbage": "the program printed something that is not a protocol message",
    "protocol": "the program sent a valid message at the wrong time",
    "limit": "the program exceeded the maximum number of traversals or of marker operations, or kept topomark busy "
             "past the session's ceiling",
    "bad-exit": "the program asked for an exit that does not exist",
    "marker": "the program did a marker operation its kit (or the markers lying there) does not allow, or a move "
              "its thread does not allow",
    "invariant": "a snapshot of (S, U) violated I-1 or I-2",
    "snapshot": "a snapshot is malformed",
    "map-invalid": "the final map is not a valid world",
    "not-isomorphic": "the final map is not extended-isomorphic to the world",
    "guess": "the final map is right, but what the program sensed does not determine it (a witness world shows it)",
}


@dataclass
class Limits:
    """Traversal, operation and time limits; ``max_traversals`` None means 4 × the (3.1)+(3.2) bound, at least
    1000; ``max_operations`` None means 2 × the traversal limit, at least 1000.

    Marker and thread operations are not traversals (§3.1.2: only edge traversals are the cost), so a program
    could drop and pick up a marker forever at no cost; the operation cap ends such a run with reason ``limit``.
    """

    max_traversals: int | None = None
    wall: float = 60.0
    message: float = 10.0
    max_operations: int | None = None

    def traversals(self, world: World) -> int:
        if self.max_traversals is not None:
            return self.max_traversals
        return max(1000, 4 * upper_bound(world.n, world.m))

    def operations(self, world: World) -> int:
        if self.max_operations is not None:
            return self.max_operations
        return max(1000, 2 * self.traversals(world))


@dataclass
class ExternalResult:
    verdict: str  # "pass" or "fail"
    reason: str  # a key of REASONS
    message: str
    cost: int = 0
    snapshots: int = 0
    operations: int = 0  # marker and thread operations: counted apart from the cost (§3.1.2)
    gave_up: bool = False  # the program reported failure itself (sent ``error``)
    marker_operations: dict[str, int] = field(default_factory=dict)  # the same by kind (drop, pick_up, tie, ...)
    wall: float = 0.0  # the whole run: program_seconds + topomark_seconds
    program_seconds: float = 0.0  # topomark waiting for the program: what --timeout limits
    topomark_seconds: float = 0.0  # topomark checking (snapshots, the map) and starting up: not limited
    stderr: list[str] = field(default_factory=list)
    violation: Violation | None = None
    map: World | None = None
    rule: str | None = None
    determination: Determination | None = None  # the search for a witness that the map was a guess
    program: ProgramTrace | None = None  # with record=: what the program's robot did, as a trace

    @property
    def passed(self) -> bool:
        return self.verdict == "pass"

    def to_json(self) -> dict[str, Any]:
        return {"verdict": self.verdict, "reason": self.reason, "message": self.message, "cost": self.cost,
                "operations": self.operations, "marker_operations": self.marker_operations,
                "snapshots": self.snapshots, "wall_seconds": round(self.wall, 3),
                "program_seconds": round(self.program_seconds, 3),
                "topomark_seconds": round(self.topomark_seconds, 3), "stderr_tail": self.stderr,
                "violation": None if self.violation is None else self.violation.to_json(), "marker_rule": self.rule,
                "determination": None if self.determination is None else self.determination.to_json()}


class _Fail(Exception):
    def __init__(self, reason: str, message: str, violation: Violation | None = None, gave_up: bool = False):
        super().__init__(clip(message, MAX_MESSAGE))
        self.reason, self.violation, self.gave_up = reason, violation, gave_up


class _Session:
    """One game of the world side against one program."""

    def __init__(self, world: World, peer: Peer, limits: Limits, check_snapshots: bool, version: int = 1,
                 kit: Kit = LIGHTHOUSE_KIT, record: bool = False):
        self.world = world
        bare, self.start = prepare_world(world)
        self.version, self.kit = version, kit
        self.program = ProgramTrace(bare, kit) if record else None
        self.sim = Simulator(bare, self.start, kit, *(self.program.listeners() if self.program else ()))
        self.robot = self.sim.robot()  # the program gets exactly the robot interface, over the pipe
        self.peer = peer
        self.max_traversals = limits.traversals(world)
        self.max_operations = limits.operations(world)
        self.limits = limits
        self.check_snapshots = check_snapshots
        self.snapshots = 0
        self.actions: list[Action] = []  # what the program did, replayed on other worlds (determination)

    def hello(self) -> None:
        kit = {"markers": self.kit.to_json()} if self.version == 1 else {"kit": self.kit.to_json()}
        self.peer.send({"type": "hello", "protocol": PROTOCOL if self.version == 1 else PROTOCOL2, "role": "world",
                        **kit, "signature": str(self.robot.sense()),
                        "limits": {"max_traversals": self.max_traversals, "wall_seconds": self.limits.wall,
                                   "message_seconds": self.limits.message}})

    def play(self) -> World:
        """Answer messages until the map arrives; returns the map."""
        self.hello()
        expect = Expect(("move", "drop", "snapshot", "map", "error")
                        + (("pick_up", "thread") if self.version >= 2 else ()), self.version)
        while True:
            msg = self.peer.receive(expect)
            kind = msg["type"]
            if kind == "move":
                self.move(msg["motion"])
            elif kind in ("drop", "pick_up", "thread") and self.version >= 2:
                self.operate(msg)
            elif kind == "drop":
                self.drop(msg["direction"])
            elif kind == "snapshot":
                self.snapshot(msg)
            elif kind == "error":
                raise _Fail("crash", f"{GAVE_UP}: {clip(msg['message'], 500)}", gave_up=True)
            else:
                return self.read_map(msg["world"])

    def move(self, motion: int) -> None:
        if self.sim.cost >= self.max_traversals:
            raise _Fail("limit", f"traversal {self.sim.cost + 1} exceeds the limit of {self.max_traversals}")
        v, _ = self.sim.state
        degree = self.sim.world.degree(v)
        if not 0 <= motion < degree:
            raise _Fail("bad-exit", f"step {self.sim.cost + 1}: motion {motion} does not exist at a vertex of "
                                    f"degree {degree} (allowed 0..{degree - 1})")
        try:
            sig = self.robot.move(motion, "other")
        except CheckFailure as exc:  # the thread would run out (§6.3): the kit refuses the move
            raise _Fail("marker", refusal({"type": "move", "motion": motion}, self.sim.cost,
                                          exc.violation.detail or str(exc)), exc.violation) from None
        self.actions.append(motion)
        self.peer.send({"type": "signature", "value": str(sig), "step": self.sim.cost})

    def _count_operation(self) -> None:
        """The operation cap: one more marker or thread operation than ``max_operations`` ends the run."""
        done = self.sim.operations.total()
        if done >= self.max_operations:
            raise _Fail("limit", f"marker operation {done + 1} (after {self.sim.cost} traversals) exceeds the limit "
                                 f"of {self.max_operations} operations (--max-operations)")

    def drop(self, direction: int | None) -> None:
        self._count_operation()
        v, _ = self.sim.state
        degree = self.sim.world.degree(v)
        if direction is not None and not 0 <= direction < degree:
            raise _Fail("marker", f"drop: direction {direction} does not exist at a vertex of degree {degree}")
        if direction is None:
            raise _Fail("marker", "drop: an undirected marker, but the marker class is one directional vertex "
                                  "marker (direction must be an exit)")
        try:
            self.robot.operate(MarkerOp("vertex", direction=direction))
        except CheckFailure as exc:
            raise _Fail("marker", refusal({"type": "drop", "direction": direction}, self.sim.cost,
                                          exc.violation.detail or str(exc)), exc.violation) from None
        self.actions.append(MarkerOp("vertex", direction=direction))
        self.peer.send({"type": "signature", "value": str(self.robot.sense()), "step": self.sim.cost})

    def operate(self, msg: dict) -> None:
        """An @2 ``drop`` or ``pick_up``: malformed fields are garbage, refusals the simulator's ``marker``."""
        self._count_operation()
        v, _ = self.sim.state
        op = op_from_message(msg, self.sim.world.degree(v))
        if getattr(op, "op", None) == "rewind" and self.sim.cost >= self.max_traversals:  # a rewind is a move
            raise _Fail("limit", f"traversal {self.sim.cost + 1} exceeds the limit of {self.max_traversals}")
        sensed = self.robot.sense()
        try:
            if getattr(op, "op", None) == "rewind":
                self.robot.rewind("other")
            else:
                self.robot.operate(op)
        except CheckFailure as exc:
            words = refusal(msg, self.sim.cost, exc.violation.detail or str(exc), op, sensed, self.kit)
            raise _Fail("marker", words, exc.violation) from None
        self.actions.append(REWIND if getattr(op, "op", None) == "rewind" else op)
        self.peer.send({"type": "signature", "value": str(self.robot.sense()), "step": self.sim.cost})

    def snapshot(self, msg: dict) -> None:
        self.snapshots += 1
        label = f"snapshot {self.snapshots}" + (f" (iteration {msg['iteration']})" if "iteration" in msg else "")
        if not self.check_snapshots:
            return
        try:
            S = snapshot_to_map(msg["S"], msg["U"], self.version)
            bad = self._invariants(S)
        except MalformedSnapshot as exc:  # the schema names the field where it can (run on every snapshot, slow)
            raise _Fail("snapshot", f"{label} is malformed: {shape_error(msg, self.version) or exc}",
                        exc.violation) from None
        except CheckFailure as exc:  # a vertex marked twice: I-1 (snapshot_wire)
            bad = exc.violation
        if bad is not None:
            note = f" ({START_ANCHOR})" if self.version >= 2 else ""
            raise _Fail("invariant", f"{label}, after {self.sim.cost} traversals: {bad}{note}", bad)

    def _invariants(self, S) -> Violation | None:
        """I-1 and I-2, φ anchored at the lighthouse (@1) or at the start (@2)."""
        if self.version >= 2:
            if S.n == 0 or S.degree(0) != self.sim.world.degree(self.start[0]):
                found = "an empty map" if S.n == 0 else f"degree {S.degree(0)}"
                return Violation("I-1", "map vertex 0 (the start)", f"degree {self.sim.world.degree(self.start[0])}",
                                 found)
            return check_invariants(S, self.sim.world, ((0, 0), self.start))
        anchor = lighthouse_anchor(S, self.sim.world)
        if anchor is None:
            return Violation("I-1", "v0", "one directional marker in S and in the world", "none or several")
        return check_invariants(S, self.sim.world, anchor)

    def read_map(self, obj: Any) -> World:
        try:
            return world_from_json(obj)
        except InvalidWorld as exc:
            raise _Fail("map-invalid", f"the map is not a valid world: {exc}") from None


def run_external(world: World, command: Sequence[str], limits: Limits | None = None, check_snapshots: bool = True,
                 version: int = 1, kit: Kit | None = None, record: bool = False) -> ExternalResult:
    """Play ``world`` to ``command`` and judge it; bad input (world, command, kit) raises InvalidInput.

    ``version`` is the protocol spoken (1 or 2); ``kit`` what the program carries (default Algorithm 3.1's one
    directional vertex marker; another kit needs ``version=2``); ``record`` keeps its trace (``result.program``).

    The program and everything it started are killed when the session ends,
    whatever the verdict (:class:`~topomark.reference.oracle.peer.Peer`).
    """
    limits = limits or Limits()
    kit = _checked_kit(version, kit)
    _check_world_markers(world, kit)  # bad input before anything is started
    prepare_world(world)
    started = time.monotonic()
    session = None
    with Peer(command, limits.message, limits.wall) as peer:
        try:
            session = _Session(world, peer, limits, check_snapshots, version, kit, record)
            result = _judge(world, session)
            _say(peer, {"type": "bye", "verdict": result.verdict, "cost": session.sim.cost})
            peer.finish()
        except ProtocolError as exc:
            result = ExternalResult("fail", exc.kind, str(exc))
            _say(peer, {"type": "error", "message": str(exc)})
        except _Fail as exc:
            result = ExternalResult("fail", exc.reason, str(exc), violation=exc.violation, gave_up=exc.gave_up)
            _say(peer, {"type": "error", "message": str(exc)})
    if session is not None:
        result.cost, result.snapshots = session.sim.cost, session.snapshots
        result.operations = session.sim.operations.total()
        result.marker_operations = dict(sorted(session.sim.operations.items()))
        result.program = session.program
    result.message = clip(result.message, MAX_MESSAGE)
    result.wall = time.monotonic() - started
    result.program_seconds = min(peer.waited, result.wall)
    result.topomark_seconds = result.wall - result.program_seconds
    result.stderr = peer.stderr_tail()
    return result


def _judge(world: World, session: _Session) -> ExternalResult:
    """Play the session to its map and judge the map against the world."""
    map_ = session.play()
    verdict = _dropped_markers(session.sim.world.with_start(world.start), map_)
    if not verdict.isomorphic:
        return ExternalResult("fail", "not-isomorphic", f"not isomorphic ({COMPARED}): {verdict.result.mismatch}",
                              violation=verdict.result.mismatch, map=map_, rule=verdict.rule)
    found = determination(session.sim.base_world, session.start, session.kit, session.actions, map_)
    if found.witness is not None:
        return ExternalResult("fail", "guess", found.words(map_.n), map=map_, rule=verdict.rule, determination=found)
    words = f"isomorphic (extended isomorphism; {COMPARED}; witness verified) and {found.words(map_.n)}"
    return ExternalResult("pass", "ok", words, map=map_, rule=verdict.rule, determination=found)


def _checked_kit(version: int, kit: Kit | None) -> Kit:
    if version not in (1, 2):
        raise InvalidInput(f"protocol version must be 1 or 2, got {version!r}")
    if kit is None:
        return LIGHTHOUSE_KIT
    if version == 1 and kit != LIGHTHOUSE_KIT:
        raise InvalidInput(f"a kit other than {LIGHTHOUSE_KIT.to_json()} needs topomark/protocol@2 "
                           f"(--protocol 2), got {kit.to_json()}")
    return kit


def _dropped_markers(truth: World, map_: World) -> MapVerdict:
    """The map must show exactly the markers the program left in the world, where it left them (both versions:
    ``spec/protocol.md``, "Verdicts of run-external"); a witness that fails its own re-verification is topomark's
    fault (exit 3)."""
    result = find_isomorphism(truth, map_, markers=True)
    if result.isomorphic:
        bad = verify_witness(truth, map_, cast(Witness, result.witness), markers=True)  # isomorphic: witnessed
        if bad is not None:
            raise TopomarkFault(f"the isomorphism witness found for the map fails its re-verification: {bad}",
                                check="witness re-verification")
    return MapVerdict(result.isomorphic, "markers", result)


def _check_world_markers(world: World, kit: Kit) -> None:
    """A world file's markers: none, or the lighthouse Algorithm 3.1's robot drops at the start (taken away).

    The world is played bare and the program drops its own markers, whatever its kit, so any other marker or a
    thread in the file is bad input, worded as what run-external judges (the module docstring).
    """
    thread = getattr(world, "thread", None)
    if not world.markers and thread is None:
        return
    lighthouse = None
    if world.start is not None:
        bare = World(world.rotation, (), world.start)
        [lighthouse] = dropped_at_start(bare, world.start_state(), LIGHTHOUSES["directional-vertex"]).markers()
        if thread is None and world.markers == (lighthouse,):
            return
    others = [m for m in world.markers if m != lighthouse]
    found = json.dumps(marker_to_json(others[0])) if others else "a thread"
    wheel = (" (Figure 3.4's wheels: wheel-a:marker=none)"
             if others and isinstance(others[0], VertexMarker) and not others[0].directional else "")
    allowed = (f"none, or the one Algorithm 3.1's robot drops at the start ("
               f"{json.dumps(marker_to_json(lighthouse))}, taken away)" if lighthouse is not None else "none")
    raise InvalidInput(f"run-external plays the world without markers and the program drops its own, from its kit "
                       f"({kit.describe()}); the world file may carry {allowed}, but it carries {found}: remove "
                       f"the file's markers{wheel}")


def _say(peer: Peer, msg: dict) -> None:
    """Tell the program how it ended, if it still listens."""
    try:
        peer.send(msg, timeout=0.2)
    except ProtocolError:
        pass
