#!/usr/bin/env python3
"""A complete explorer speaking topomark/protocol@2: Algorithm 3.1 with an edge-marker lighthouse (§3.3, §6.1).

Standalone on purpose (standard library only, no topomark import): copy it and
change it.  Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD.json --protocol 2 --kit '{"directional-edge": 1}' -- python3 client2.py

It is ``client.py`` with the lighthouse of Figure 6.1(b): instead of a
directional vertex marker, the robot drops one directional *edge* marker on
the exit it faces, its head at v0.  Entering v0 by exit e it senses
``[d,A,E-p-H]`` with p = (0 - e) mod d — place and back-link at once — so
v0 is recognised by the ``H`` end; the far end of that edge reads ``E-p-T``,
a mark like any other that S records where it is sensed and that every
expected signature includes.  Each iteration takes an unexplored dart
e = (v_k, i) from U, walks S to v_k, follows e, and either recognises v0,
confirms a hypothesis h' = (e', v_k') by walking the path from v_k' to v0
that S predicts, or adds a new vertex.  Map vertices are numbered 0, 1, ...
(v0 = where the robot started) and each vertex's exits clockwise from the
edge it was first entered by (at v0: the faced exit) — the convention @2's
snapshot check anchors at.  After each iteration it sends a snapshot of (S, U).
"""
import json
import re
import sys
from collections import deque


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def receive():
    msg = json.loads(sys.stdin.readline())
    if msg["type"] in ("error", "bye"):
        sys.exit(0 if msg.get("verdict") == "pass" else 1)
    return msg


def parse(sig):
    """'[3,A,E-1-H]' -> (3, ((1, 'H'),)); '[3,A,A]' -> (3, ()): the degree and the marked exits with their ends."""
    m = re.match(r"\[(\d+),A,(A|E-\d+(?:-[HT])?(?:,E-\d+(?:-[HT])?)*)\]$", sig)
    if m is None:
        send({"type": "error", "message": "unexpected signature %s" % sig[:80]})
        sys.exit(1)
    items = [] if m.group(2) == "A" else [item.split("-") for item in m.group(2).split(",")]
    return int(m.group(1)), tuple(sorted((int(x[1]), x[2] if len(x) > 2 else None) for x in items))


class Explorer:
    def __init__(self):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or hello["kit"].get("directional-edge", 0) < 1:
            send({"type": "error", "message": "I speak topomark/protocol@2 with a directional edge marker only"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.marks = [{}]  # marks[v][i] = "H"/"T"/None: a marker on exit i of v, and its end at v
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, entry exit)
        send({"type": "drop", "kind": "edge", "exit": 0, "direction": "H"})  # the lighthouse: exit 0, head at v0
        self.sense(0, parse(receive()["value"]), 0)

    def sense(self, v, sig, entry):
        """Record at map vertex v the marks of ``sig``, sensed when entered by exit ``entry``."""
        for p, end in sig[1]:
            self.marks[v][(entry + p) % sig[0]] = end

    def step(self, motion):
        """One traversal by relative ``motion``; return the signature reached."""
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def move(self, exit_):
        """Leave the current vertex by its absolute exit ``exit_``."""
        v, entry = self.pos
        self.step((exit_ - entry) % len(self.exits[v]))
        self.pos = tuple(self.exits[v][exit_])

    def expect(self, v, entry):
        """The signature S predicts at map vertex v entered by exit ``entry``."""
        d = len(self.exits[v])
        return (d, tuple(sorted(((x - entry) % d, end) for x, end in self.marks[v].items())))

    def tree(self, root):
        """BFS over explored edges: for each vertex, the exit leading one step toward ``root``."""
        toward, todo = {root: None}, deque([root])
        while todo:
            v = todo.popleft()
            for w_j in self.exits[v]:
                if w_j and w_j[0] not in toward:
                    toward[w_j[0]] = w_j[1]
                    todo.append(w_j[0])
        return toward

    def walk_to(self, target):
        toward = self.tree(target)
        while self.pos[0] != target:
            self.move(toward[self.pos[0]])

    def validate(self, vk, sig):
        """Test hypotheses (lines 8-20): the confirmed e' (robot now at v0) or None, and the heading at v_u."""
        heading, toward = 0, self.tree(0)
        for v, i in [h for h in self.U if h[0] != vk and self.expect(*h) == sig]:
            path, x, entry = [], v, i  # the motions M from v (entered by e') to v0, with P^E
            while x != 0:
                motion = (toward[x] - entry) % len(self.exits[x])
                x, entry = self.exits[x][toward[x]]
                path.append((motion, self.expect(x, entry)))
            done = []  # (physical motion, degree reached)
            for k, (motion, want) in enumerate(path):
                physical = (motion - heading) % sig[0] if k == 0 else motion  # M starts from e, not the heading
                got = self.step(physical)
                done.append((physical, got[0]))
                if got != want:
                    break
            else:
                self.pos = (0, entry)
                return (v, i), heading
            self.step(0)  # retrace (line 17): back along the last edge, then every motion reversed
            degrees = [sig[0]] + [d for _, d in done]
            for k in range(len(done) - 1, 0, -1):
                self.step((-done[k][0]) % degrees[k])
            heading = (heading + done[0][0]) % sig[0]  # re-align to e
        return None, heading

    def iterate(self):
        order = {v: k for k, v in enumerate(self.tree(self.pos[0]))}  # BFS order from the robot
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: order[self.U[k][0]]))  # nearest e
        self.walk_to(vk)
        sig = self.step((i - self.pos[1]) % len(self.exits[vk]))
        heads = [p for p, end in sig[1] if end == "H"]
        if heads:  # the lighthouse: v_u is v0, entered by the exit p places before its marked exit 0
            far = (0, (0 - heads[0]) % sig[0])
            self.pos = far
        else:
            far, heading = self.validate(vk, sig)
        if far is not None:  # loop augmentation with the existing indices; e' leaves U
            self.U.remove(far)
            self.exits[vk][i], self.exits[far[0]][far[1]] = list(far), [vk, i]
        else:  # non-loop augmentation: e is exit 0 of the new vertex, its other exits join U
            u = len(self.exits)
            self.exits.append([[vk, i]] + [None] * (sig[0] - 1))
            self.marks.append({})
            self.sense(u, sig, 0)
            self.exits[vk][i] = [u, 0]
            self.U += [(u, j) for j in range(1, sig[0])]
            self.pos = (u, heading)

    def run(self):
        while self.U:
            self.iterate()
            marks = [{"vertex": v, "exit": i, "count": 1, "end": end}
                     for v, row in enumerate(self.marks) for i, end in sorted(row.items())]
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": marks}, "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": [{"kind": "edge", "between": ["s0", names[self.exits[0][0][0]]], "count": 1, "head": "s0"}]}})
        receive()


if __name__ == "__main__":
    Explorer().run()
