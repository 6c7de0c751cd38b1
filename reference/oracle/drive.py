"""``drive``: topomark's Algorithm 3.1 explorer drives an external world (thesis §3.3, §3.6).

The other direction of ``topomark/protocol@1`` and ``@2`` (``spec/protocol.md``): the
external program is the *world provider* — another simulator, or a bridge to
a physical robot as in §3.6, where a vertex is a junction recognised by the
robot's sensors and a motion is "leave by the l-th exit clockwise from the
one you came in by".  The provider says ``hello`` with the marker kit and
the initial signature, then answers every ``move`` and ``drop`` with the
signature reached.  topomark runs :class:`~topomark.reference.explorers.algorithm31.
LighthouseExplorer` over a :class:`~topomark.reference.explorers.robot.Robot` whose
three operations are those messages, and ends by sending its ``map``.

The provider's ``hello`` chooses the version: ``@1`` offers ``markers`` and
allows only the directional-vertex lighthouse; ``@2`` offers a ``kit``, which
must hold what the chosen lighthouse drops (``lighthouse=``,
:data:`~topomark.reference.explorers.lighthouses.LIGHTHOUSES`), and drops
are sent in the ``@2`` form.  The trace is ``topomark/trace@1`` for the
directional-vertex lighthouse and ``topomark/trace@2`` for any other
(``spec/trace.md``), so ``replay`` verifies either.

The trace is streamed: with a file (``trace=``, ``--trace``) every record
goes to a :class:`~topomark.reference.trace.sink.SpoolSink` as it happens
and the file is written when the run ends (its header gives the map's n and
m); without one no record is kept at all, only the counters (``record=True``
keeps them in :attr:`DriveResult.trace`, for tests and library callers).
So memory does not grow with the number of moves, whatever the provider.

No ground truth is available here (the provider *is* the world), so the
run is judged only if the caller supplies the world (``check=``), by
:func:`topomark.reference.run.map_check.check_map`; the trace it records can also
be verified later with ``topomark replay``.
"""

from __future__ import annotations

import contextlib
import json
import time
from pathlib import Path
from types import SimpleNamespace
from dataclasses import dataclass, field
from typing import Any, Callable, Sequence, cast

from topomark.spec.errors import (AlgorithmStopped, CheckFailure, ExplorerFault, InvalidInput, OutOfMarkers,
                                  TopomarkFault, Violation, clip)
from topomark.spec.kit import Kit, MarkerOp, ThreadOp
from topomark.spec.signature import Signature
from topomark.spec.world import World
from topomark.spec.worldfile import world_to_json

from topomark.reference.trace.records import op_record, trace_header
from topomark.reference.trace.sink import ListSink, SpoolSink, TeeSink, TraceSink
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse
from topomark.reference.run.map_check import MapVerdict, check_map
from topomark.reference.explorers.policies import Policies
from topomark.reference.oracle.peer import Peer
from topomark.reference.oracle.protocol import MAX_MESSAGE, VERSIONS, Expect, ProtocolError
from topomark.reference.explorers.robot import Robot
from topomark.reference.oracle.marker_messages import op_to_message

__all__ = ["DriveResult", "drive"]


@dataclass
class DriveResult:
    verdict: str  # "pass" (map made, and verified if a world was given) or "fail"
    reason: str
    message: str
    cost: int = 0
    map: World | None = None
    trace: list[dict] = field(default_factory=list)
    check: MapVerdict | None = None
    wall: float = 0.0
    stderr: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return self.verdict == "pass"

    def to_json(self) -> dict[str, Any]:
        return {"verdict": self.verdict, "reason": self.reason, "message": self.message, "cost": self.cost,
                "n": None if self.map is None else self.map.n, "m": None if self.map is None else self.map.m,
                "check": None if self.check is None else self.check.to_json(), "wall_seconds": round(self.wall, 3),
                "stderr_tail": self.stderr}


class _Link:
    """The robot's three operations, as protocol messages to the provider."""

    def __init__(self, peer: Peer, max_traversals: int, sink: TraceSink | None, light: Lighthouse):
        self.peer, self.max_traversals, self.sink, self.light = peer, max_traversals, sink, light
        self.cost = 0
        self.version = 1
        self.here: Signature = cast(Signature, None)  # what the robot senses now: set by the hello, before moves

    def hello(self) -> None:
        msg = self.peer.receive(Expect(("hello",), None))  # any version this topomark speaks
        self.version = VERSIONS[msg["protocol"]]
        if msg["role"] != "world":
            raise ProtocolError("protocol", f"hello from a {clip(msg['role'])!r} speaking {clip(msg['protocol'])!r} "
                                            f"(expected role 'world')")
        if self.version == 1:
            self._markers(msg["markers"])
        else:
            self._kit(msg["kit"])
        self.here = self._signature(msg["signature"])

    def _markers(self, markers: dict) -> None:
        """@1: Algorithm 3.1's directional vertex marker, the one lighthouse @1 can drop."""
        if self.light.name != "directional-vertex":
            raise ProtocolError("protocol", f"the {self.light.name} lighthouse drops {self.light.kit.describe()}, "
                                            "which needs a provider speaking topomark/protocol@2; this one speaks @1")
        kit = markers.get("directional-vertex", 0)
        if not isinstance(kit, int) or isinstance(kit, bool) or kit < 1:
            raise ProtocolError("protocol", f"Algorithm 3.1 needs one directional vertex marker; the provider "
                                            f"offers {clip(str(markers))}")

    def _kit(self, obj: dict) -> None:
        """@2: the provider's kit must hold every marker the lighthouse drops."""
        try:
            kit = Kit.from_json(obj)
        except InvalidInput as exc:
            raise ProtocolError("garbage", f"hello.kit: {clip(str(exc), 300)}") from None
        past_caps = kit.cap_refusal()
        if past_caps is not None:
            raise ProtocolError("garbage", f"hello.kit: {past_caps}")
        held = {"vertex": 0, "edge": 0, "either": 0}  # dropped so far: each kind's own, the pool (Kit.draw)
        for op in self.light.ops:
            if op.kind == "thread":  # §6.3: the kit must have a thread
                why = kit.thread_refusal()
                if why is not None:
                    raise ProtocolError("protocol", f"the {self.light.name} lighthouse needs a thread: {why}")
                continue
            why = kit.refusal(op.kind, op.direction is not None, op.count, held[op.kind], held["either"])
            if why is not None:
                raise ProtocolError("protocol", f"the {self.light.name} lighthouse ({self.light.kit.describe()}) "
                                                f"cannot be dropped with the provider's kit: {why}")
            own, pooled = kit.draw(op.kind, op.count, held[op.kind])
            held[op.kind] += own
            held["either"] += pooled

    def _signature(self, text: str) -> Signature:
        try:
            return Signature.parse(text)
        except InvalidInput as exc:
            raise ProtocolError("garbage", f"the provider sent a bad signature: {clip(str(exc), 300)}") from None

    def _answer(self) -> Signature:
        msg = self.peer.receive(Expect(("signature", "error"), self.version))
        if msg["type"] == "error":
            raise ProtocolError("crash", f"the provider reported an error: {clip(msg['message'], 500)}")
        return self._signature(msg["value"])

    def move(self, motion: int, purpose: str) -> Signature:
        if self.cost >= self.max_traversals:
            raise ProtocolError("limit", f"more than {self.max_traversals} traversals")
        if not 0 <= motion < self.here.degree:
            raise CheckFailure(Violation("robot interface", f"step {self.cost + 1}", "an existing exit",
                                         f"motion {motion} at degree {self.here.degree}"))
        self.peer.send({"type": "move", "motion": motion})
        self.here = self._answer()
        self.cost += 1
        if self.sink is not None:
            self.sink.emit({"event": "move", "step": self.cost, "motion": motion, "perception": str(self.here),
                            "purpose": purpose})
        return self.here

    def operate(self, op: MarkerOp) -> None:
        """@1: a vertex marker drop, its one marker operation; @2: any operation, as ``MarkerOp.to_json`` says."""
        single = op.kind == "vertex" and not op.pick_up and op.count == 1
        if self.version == 1 and not single:
            raise TopomarkFault(f"drive speaks topomark/protocol@1, which has no {json.dumps(op.to_json())}")
        self.peer.send({"type": "drop", "direction": op.direction} if self.version == 1 else op_to_message(op))
        self.here = self._answer()
        if self.sink is not None:
            self.sink.emit(op_record({"step": self.cost, **op.to_json(), "signature": str(self.here)}, self.light))

    def robot(self) -> Robot:
        operate = cast("Callable[[MarkerOp | ThreadOp], None]", self.operate)  # the protocol carries no thread
        return Robot(self.move, lambda: self.here, operate)


def drive(command: Sequence[str], policies: Policies | None = None, world: World | None = None,
          max_traversals: int = 1_000_000, wall: float = 600.0, message: float = 10.0,
          light: Lighthouse = LIGHTHOUSES["directional-vertex"], trace: str | Path | None = None,
          record: bool = False) -> DriveResult:
    """Explore the provider's world from the ``light`` lighthouse; ``world`` (optional) is the truth to judge
    the map against.  ``trace`` is a file the trace is streamed to; ``record`` keeps it in ``result.trace``."""
    policies = policies or Policies()
    started = time.monotonic()
    kept = ListSink() if record else None
    with contextlib.ExitStack() as stack:
        spool = stack.enter_context(SpoolSink(trace)) if trace is not None else None
        sinks = [s for s in (kept, spool) if s is not None]
        sink = sinks[0] if len(sinks) == 1 else TeeSink(*sinks) if sinks else None
        with Peer(command, message, wall) as peer:  # on leaving: the provider and all it started are killed
            link = _Link(peer, max_traversals, sink, light)
            result = _run(link, policies, sink, world)
        result.message = clip(result.message, MAX_MESSAGE)
        size = result.map if result.map is not None else SimpleNamespace(n=0, m=0)
        header = trace_header("basic", policies, light, cast(World, size))  # n and m read; trace@1 or @2
        end = {"event": "end", "cost": link.cost, "verified": result.check is not None and result.check.isomorphic,
               "violation": None}
        if kept is not None:
            result.trace = [header] + kept.records + [end]
        if spool is not None:
            spool.finish(header, end)
    result.wall, result.stderr = time.monotonic() - started, peer.stderr_tail()
    return result


def _run(link: _Link, policies: Policies, sink: TraceSink | None, world: World | None) -> DriveResult:
    """The session's result: a map, or how it failed."""
    try:
        return _explore(link, policies, sink, world)
    except ProtocolError as exc:
        return DriveResult("fail", exc.kind, str(exc), link.cost)
    except (AlgorithmStopped, OutOfMarkers) as stop:  # an outcome, as under explore: no map, FAIL, exit 1
        return DriveResult("fail", stop.outcome, f"the algorithm stopped: {stop.reason}", link.cost)
    # the explorer's map cannot be a world: what the thesis proves of any world (ExplorerFault) fails here
    except (CheckFailure, ExplorerFault, InvalidInput, LookupError) as exc:
        return DriveResult("fail", "inconsistent", "the provider's answers are inconsistent with any "
                           f"world: {exc}", link.cost)


def _explore(link: _Link, policies: Policies, sink: TraceSink | None, world: World | None) -> DriveResult:
    """Algorithm 3.1 over the link, the map sent, ``bye`` awaited; judged against ``world`` if given."""
    link.hello()
    listen = None if sink is None else (lambda ex, it: sink.emit({"event": "iteration", **it.to_json()}))
    explorer = LighthouseExplorer(link.robot(), policies, listen, link.light)
    map_ = explorer.explore().to_world()
    link.peer.send({"type": "map", "world": world_to_json(map_)})
    link.peer.receive(("bye",))
    link.peer.finish()
    result = DriveResult("pass", "ok", f"mapped {map_.n} vertices and {map_.m} edges", link.cost, map_)
    if world is not None:
        result.check = check_map(world, map_)
        if not result.check.isomorphic:
            result.verdict, result.reason = "fail", "not-isomorphic"
        result.message += f"; against the given world: {result.check.words()}"
    return result
