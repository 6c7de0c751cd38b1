#!/usr/bin/env python3
"""A complete explorer of Algorithm 3.1 of the thesis (§3.3), speaking topomark/protocol@1 or @2.

Standalone on purpose (standard library only, no topomark import): copy it and
change it.  Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD.json -- python3 client.py
    topomark conformance run SUITE --algorithm basic -- python3 client.py

The second plays the suite of the registered algorithm ``basic`` over @2, each
case's kit in ``hello``: the same one directional vertex marker, dropped with
@2's ``drop`` (``kind: "vertex"``).  Any other kit is refused with ``error``.

The robot drops its directional marker at v0 pointing at the exit it faces;
each iteration takes an unexplored dart e = (v_k, i) from U, walks S to v_k,
follows e, and either recognises v0 by the marker (the marker's direction
gives the back-link), confirms a hypothesis h' = (e', v_k') by walking the
path from v_k' to v0 that S predicts, or adds a new vertex.  Map vertices are
numbered 0, 1, ... and each vertex's exits clockwise from the edge it was
first entered by.  After each iteration it sends a snapshot of (S, U).
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
    """'[3,V-1,A]' -> (3, 1); '[3,A,A]' -> (3, None)."""
    m = re.match(r"\[(\d+),(A|V-(\d+)),A\]$", sig)
    return int(m.group(1)), None if m.group(3) is None else int(m.group(3))


def directional_vertex_only(kit):
    """Whether an @2 kit gives the robot Algorithm 3.1's marker: directional vertex markers and nothing else."""
    return kit.get("directional-vertex", 0) >= 1 and set(kit) == {"directional-vertex"}


class Explorer:
    def __init__(self):
        hello = receive()
        at2 = hello["protocol"] == "topomark/protocol@2"
        if not (hello["protocol"] == "topomark/protocol@1" or at2 and directional_vertex_only(hello["kit"])):
            send({"type": "error", "message": "I speak topomark/protocol@1, or @2 with one directional vertex "
                                              "marker (Algorithm 3.1's kit) only"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, entry exit)
        drop = {"type": "drop", "direction": 0}  # the lighthouse points at exit 0 of v0 (line 1)
        send(dict(drop, kind="vertex") if at2 else drop)  # @2 names the marker's kind
        receive()

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
        return (d, (0 - entry) % d if v == 0 else None)

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
        if sig[1] is not None:  # the lighthouse: v_u is v0, entered by exit (head - direction)
            far = (0, (0 - sig[1]) % sig[0])
            self.pos = far
        else:
            far, heading = self.validate(vk, sig)
        if far is not None:  # loop augmentation with the existing indices; e' leaves U
            self.U.remove(far)
            self.exits[vk][i], self.exits[far[0]][far[1]] = list(far), [vk, i]
        else:  # non-loop augmentation: e is exit 0 of the new vertex, its other exits join U
            u = len(self.exits)
            self.exits.append([[vk, i]] + [None] * (sig[0] - 1))
            self.exits[vk][i] = [u, 0]
            self.U += [(u, j) for j in range(1, sig[0])]
            self.pos = (u, heading)

    def run(self):
        while self.U:
            self.iterate()
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": [{"vertex": 0, "head": 0}]},
                  "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": [{"kind": "vertex", "at": "s0", "points_to": names[self.exits[0][0][0]]}]}})
        receive()


if __name__ == "__main__":
    Explorer().run()
