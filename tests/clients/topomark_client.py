#!/usr/bin/env python3
"""topomark's own registered algorithm as a topomark/protocol@2 client: ``topomark_client.py ALGORITHM[,...] [FAULT]``.

The explorer of ``ALGORITHM`` (any registered one; of several, the first whose kit has the kinds of the kit in
``hello``: e.g. ``dudek,dudek-directional`` for a family's suites) runs over a robot whose
moves, senses and marker operations are @2 messages on stdin/stdout, with the
kit the world's ``hello`` gives; its map goes out as ``map``.  Like the
simulator, the client refuses itself a drop its kit cannot pay for: the
algorithm then stops (out of markers, the ``failed`` outcome) and the client
reports it with ``error``.  The thread's length is the kit's (the robot knows
it, §6.3).

FAULT (a seeded wrong client): ``overdraw`` sends a drop its kit cannot pay for
instead of stopping; ``map-anyway`` sends its partial map instead of reporting
failure.
"""
import json
import sys
from collections import Counter

from topomark.spec.errors import AlgorithmStopped, OutOfMarkers, Violation
from topomark.spec.kit import Kit, ThreadOp
from topomark.spec.signature import Signature
from topomark.spec.worldfile import world_to_json

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.policies import Policies
from topomark.reference.explorers.robot import Robot
from topomark.reference.oracle.marker_messages import op_to_message

FAULT = sys.argv[2] if len(sys.argv) > 2 else None


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def receive():
    msg = json.loads(sys.stdin.readline())
    if msg["type"] in ("error", "bye"):
        sys.exit(0 if msg.get("verdict") == "pass" else 1)
    return msg


class Link:
    """The robot's operations as @2 messages; the kit gated here as the simulator gates it."""

    def __init__(self, kit: Kit, signature: str):
        self.kit, self.here = kit, Signature.parse(signature)
        self.dropped = Counter()  # each kind's own markers dropped, and the pool's ("either")

    def answer(self):
        self.here = Signature.parse(receive()["value"])
        return self.here

    def move(self, motion, purpose="other"):
        send({"type": "move", "motion": motion})
        return self.answer()

    def rewind(self, purpose="retrace"):
        send({"type": "thread", "op": "rewind"})
        return self.answer()

    def operate(self, op):
        if not isinstance(op, ThreadOp):
            self.gate(op)
        send(op_to_message(op))
        self.answer()

    def gate(self, op):
        if op.pick_up:
            self.dropped[op.kind] -= op.count
            return
        left = self.kit.count(op.kind) - self.dropped[op.kind] + self.kit.either - self.dropped["either"]
        if left < op.count and FAULT != "overdraw":
            raise OutOfMarkers(Violation("marker kit", "here", "an operation the kit allows",
                                         json.dumps(op.to_json()), f"{left} left, {op.count} asked for"))
        own, pooled = self.kit.draw(op.kind, op.count, self.dropped[op.kind])
        self.dropped[op.kind] += own
        self.dropped["either"] += pooled


def told(spec, kit):
    """The options the robot is told: the thread's length, the kit's (§6.3)."""
    if any(p.name == "thread-length" for p in spec.parameters) and kit.thread:
        return {"thread-length": kit.thread}
    return {}


def chosen(kit):
    """The first algorithm named whose registered kit has the kinds (and directions) of ``kit``."""
    specs = [algorithm_spec(name) for name in sys.argv[1].split(",")]
    return next((s for s in specs if set(s.kit.to_json()) == set(kit.to_json())), specs[0])


def main():
    hello = receive()
    if hello["protocol"] != "topomark/protocol@2":
        send({"type": "error", "message": "this client speaks topomark/protocol@2 only"})
        return 2
    link = Link(Kit.from_json(hello["kit"]), hello["signature"])
    spec = chosen(link.kit)
    robot = Robot(link.move, lambda: link.here, link.operate, link.rewind)
    if spec.uses_lighthouse:
        explorer = spec.factory(robot, Policies(), None, LIGHTHOUSES["directional-vertex"])
    else:
        explorer = spec.factory(robot, Policies(), lambda ex, it: None, spec.parse_options(told(spec, link.kit)))
    try:
        explorer.start()
        while not explorer.done():
            explorer.step()
    except (AlgorithmStopped, OutOfMarkers) as stop:
        if FAULT != "map-anyway":
            send({"type": "error", "message": f"the algorithm stopped: {stop.reason}"})
            return 1
        send({"type": "map", "world": {"format": "topomark/world@1",  # a guess in place of the map it lacks
                                       "rotation": {"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}}})
        receive()
        return 1
    send({"type": "map", "world": world_to_json(explorer.S.to_world())})
    receive()
    return 1


if __name__ == "__main__":
    sys.exit(main())
