#!/usr/bin/env python3
"""A world provider speaking topomark/protocol@1 or @2: it plays a world file to an explorer.

Standalone on purpose (standard library only, no topomark import).  A bridge
to a real robot (thesis §3.6) has the same shape: replace ``step`` with
"drive out of the junction by the motion-th exit clockwise from the entry,
follow the corridor, stop at the next junction" and ``signature`` with what
the robot's sensors report there.

    topomark drive -- python3 provider.py WORLD.json
    topomark drive --lighthouse directional-edge -- python3 provider.py WORLD.json --protocol 2 \\
        --kit '{"directional-edge": 1}'

The world file is ``topomark/world@1``: ``rotation`` lists each vertex's
neighbours clockwise (a simple graph: no loops or parallel edges here); the
robot starts at ``start.at`` facing ``start.facing`` (default: the first
vertex, facing its exit 0).  With ``--protocol 2`` the hello offers ``--kit``
(default ``{"directional-vertex": 1}``) and the explorer may drop and pick up
vertex and edge markers as that kit allows, and use a thread of length ε
(``{"thread": 0}``: tie, leave, take, untie — enough for the ``thread``
lighthouse; a longer thread is refused with a message saying so).
"""
import json
import sys


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


class World:
    def __init__(self, world, kit):
        self.rot = world["rotation"]
        first = next(iter(self.rot))
        start = world.get("start") or {"at": first, "facing": self.rot[first][0]}
        self.here = start["at"]
        self.entry = self.rot[self.here].index(start["facing"])  # the state: (vertex, exit index of the entry edge)
        self.kit = kit
        self.directional = any(k.startswith("directional-") for k in kit)
        self.held = {"vertex": kit.get(self.word() + "-vertex", 0), "edge": kit.get(self.word() + "-edge", 0)}
        self.pool = kit.get(self.word() + "-either", 0)  # markers for a vertex or an edge, drawn after the kind's own
        self.vmark = {}  # vertex -> [count, absolute exit pointed at or None]
        self.emark = {}  # frozenset of the edge's two darts -> [count, head vertex or None]
        self.tied = None  # a thread of length ε (the only one this example knows): [vertex, absolute exit or None]
        self.end = "held"  # where its free end is: "held", or the vertex it was left at

    def word(self):
        return "directional" if self.directional else "undirected"

    def degree(self):
        return len(self.rot[self.here])

    def edge(self, i):
        """The edge at absolute exit i of the current vertex, as the set of its two darts."""
        there = self.rot[self.here][i]
        return frozenset(((self.here, i), (there, self.rot[there].index(self.here))))

    def signature(self):
        d, mark = self.degree(), self.vmark.get(self.here)
        vpart = "A"
        if mark:
            vpart = "V" + (str(mark[0]) if mark[0] > 1 else "") + ("" if mark[1] is None else
                                                                  "-%d" % ((mark[1] - self.entry) % d))
        items = []
        for p in range(d):
            em = self.emark.get(self.edge((self.entry + p) % d))
            if em:
                end = "" if em[1] is None else ("-H" if em[1] == self.here else "-T")
                items.append("E" + (str(em[0]) if em[0] > 1 else "") + "-%d" % p + end)
        thread = []
        if self.tied and self.tied[0] == self.here:
            thread.append("T" + ("" if self.tied[1] is None else "-%d" % ((self.tied[1] - self.entry) % d)))
        if self.end == self.here:
            thread.append("F")
        return "[%s]" % ",".join([str(d), vpart, ",".join(items) or "A"] + thread)

    def move(self, motion):
        d = self.degree()
        if not 0 <= motion < d:
            return "motion %s does not exist at degree %d" % (motion, d)
        if self.tied and self.end == "held":
            return "the thread would run out: the kit's thread has length 0 (ε)"
        there = self.rot[self.here][(self.entry + motion) % d]
        self.here, self.entry = there, self.rot[there].index(self.here)
        return None

    def operate(self, msg):
        """An @2 drop or pick_up; returns why it is refused, or None."""
        kind, count, d = msg.get("kind"), msg.get("count", 1), self.degree()
        pick, direction = msg["type"] == "pick_up", msg.get("direction")
        if kind not in self.held or not isinstance(count, int) or count < 1:
            return "bad marker operation %s" % json.dumps(msg)
        if pick and not self.kit.get("movable"):
            return "the kit's markers cannot be picked up"
        if not pick and (self.held[kind] + self.pool < count or (direction is not None) != self.directional):
            return "the kit %s does not allow %s" % (json.dumps(self.kit), json.dumps(msg))
        if kind == "vertex":
            place, table = self.here, self.vmark
            value = None if direction is None else (self.entry + direction) % d
        else:
            if not isinstance(msg.get("exit"), int) or not 0 <= msg["exit"] < d:
                return "no exit %s here" % msg.get("exit")
            place, table = self.edge((self.entry + msg["exit"]) % d), self.emark
            value = None if direction is None else (self.here if direction == "H" else
                                                    self.rot[self.here][(self.entry + msg["exit"]) % d])
        old = table.get(place, [0, value])
        if (not pick and old[1] != value) or (pick and old[0] < count):
            return "this %s is not possible here" % msg["type"]
        old[0] += -count if pick else count
        table[place] = old
        if old[0] == 0:
            del table[place]
        own = count if pick else min(count, self.held[kind])
        self.held[kind] += own if pick else -own
        self.pool -= count - own
        return None


    def thread(self, msg):
        """An @2 thread operation, for a thread of length ε (l = 0, §6.3.1) only; returns why refused, or None."""
        op, d = msg.get("op"), self.degree()
        if self.kit.get("thread") != 0:
            return "this example provider knows only a thread of length ε (kit {\"thread\": 0})"
        if op == "tie" and not self.tied and self.end == "held":
            direction = msg.get("direction")
            self.tied = [self.here, None if direction is None else (self.entry + direction) % d]
        elif op == "leave" and self.end == "held":
            self.end = self.here
        elif op == "take" and self.end == self.here:
            self.end = "held"
        elif op == "untie" and self.tied and self.tied[0] == self.here and self.end == "held":
            self.tied = None
        else:
            return "thread operation %s is not possible here" % json.dumps(msg)
        return None


def main(argv):
    path, options = argv[0], dict(zip(argv[1::2], argv[2::2]))
    version = int(options.get("--protocol", "1"))
    kit = json.loads(options.get("--kit", '{"directional-vertex": 1}'))
    world = World(json.load(open(path, encoding="utf-8")), kit)
    hello = {"type": "hello", "protocol": "topomark/protocol@%d" % version, "role": "world",
             "signature": world.signature()}
    hello["markers" if version == 1 else "kit"] = kit
    send(hello)
    for line in sys.stdin:
        msg = json.loads(line)
        if msg["type"] == "move":
            why = world.move(msg["motion"])
        elif msg["type"] == "drop" and version == 1:
            why = ("this drop is not allowed" if msg["direction"] is None else
                   world.operate({"type": "drop", "kind": "vertex", "direction": msg["direction"]}))
        elif msg["type"] in ("drop", "pick_up") and version == 2:
            why = world.operate(msg)
        elif msg["type"] == "thread" and version == 2:
            why = world.thread(msg)
        elif msg["type"] == "map":
            send({"type": "bye"})
            return 0
        else:
            why = "unexpected message %r" % msg["type"]
        if why is not None:
            send({"type": "error", "message": why})
            return 1
        send({"type": "signature", "value": world.signature()})
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
