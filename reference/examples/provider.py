#!/usr/bin/env python3
"""A world provider speaking topomark/protocol@1: it plays a world file to an explorer.

Standalone on purpose (standard library only, no topomark import).  A bridge
to a real robot (thesis §3.6) has the same shape: replace ``step`` with
"drive out of the junction by the motion-th exit clockwise from the entry,
follow the corridor, stop at the next junction" and ``signature`` with what
the robot's sensors report there.

    topomark drive -- python3 provider.py WORLD.json

The world file is ``topomark/world@1``: ``rotation`` lists each vertex's
neighbours clockwise; the robot starts at ``start.at`` facing ``start.facing``
(default: the first vertex, facing its exit 0).
"""
import json
import sys


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def main(path):
    world = json.load(open(path))
    rot = world["rotation"]
    start = world.get("start") or {"at": next(iter(rot)), "facing": rot[next(iter(rot))][0]}
    here = start["at"]
    entry = rot[here].index(start["facing"])  # the state: (vertex, exit index of the entry edge)
    marker = {}  # vertex -> exit index the directional marker points at
    kit = 1

    def signature():
        d = len(rot[here])
        if here not in marker:
            return "[%d,A,A]" % d
        return "[%d,V-%d,A]" % (d, (marker[here] - entry) % d)

    send({"type": "hello", "protocol": "topomark/protocol@1", "role": "world",
          "markers": {"directional-vertex": kit}, "signature": signature()})
    for line in sys.stdin:
        msg = json.loads(line)
        d = len(rot[here])
        if msg["type"] == "move":
            if not 0 <= msg["motion"] < d:
                send({"type": "error", "message": "motion %s does not exist at degree %d" % (msg["motion"], d)})
                return 1
            there = rot[here][(entry + msg["motion"]) % d]
            here, entry = there, rot[there].index(here)
            send({"type": "signature", "value": signature()})
        elif msg["type"] == "drop":
            if kit < 1 or msg["direction"] is None or here in marker:
                send({"type": "error", "message": "this drop is not allowed"})
                return 1
            kit -= 1
            marker[here] = (entry + msg["direction"]) % d
            send({"type": "signature", "value": signature()})
        elif msg["type"] == "map":
            send({"type": "bye"})
            return 0
        else:
            send({"type": "error", "message": "unexpected message %r" % msg["type"]})
            return 1
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
