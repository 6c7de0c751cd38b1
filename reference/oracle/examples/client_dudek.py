#!/usr/bin/env python3
"""A minimal explorer speaking topomark/protocol@2 with one undirected *movable* vertex marker: Dudek et al.'s
algorithm (thesis §2.3.1, Figure 2.2).

Standalone on purpose (standard library only, no topomark import): copy it and
change it.  Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD --kit '{"undirected-vertex": 1, "movable": true}' -- python3 client_dudek.py

The robot keeps a map S of the explored part and the set U of unexplored
darts (v, i): exit i of map vertex v.  Each step takes the nearest e = (v_k, i)
from U, walks S to v_k and follows e to the unknown end v_u.  "Have I been
here before?" (§2.3.1): it drops the marker at v_u, comes back over e and visits
the known vertices that could be v_u, looking for the marker.

* Not found: v_u is new.  The robot walks back to v_k, over e once more, picks
  the marker up, and adds v_u to S with e as its exit 0.
* Found at v_k': a loop.  Back-link validation (§2.3.1): the robot picks the
  marker up, drops it at v_k, goes back to v_k' and tries v_k''s unexplored
  exits one by one; the one that leads to the marker is e'.  It picks the
  marker up at v_k.

The world is a simple graph (§2.3.1: "Redundant or self-referential edges are
prohibited"), so v_u is neither v_k nor a neighbour of v_k in S: those are not
searched.  The marker is back in the robot's hand at the end of every step, so
the snapshots' S and the final map show no marker.  Map vertex 0 is where the
robot started, its exit 0 the exit it faced (the anchor @2's snapshots check);
every other vertex numbers its exits clockwise from the edge it was found by.
"""
import json
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
    """'[3,V,A]' -> (3, True); '[3,A,A]' -> (3, False): the degree, and whether the marker lies here."""
    items = sig.strip("[]").split(",")
    return int(items[0]), items[1] != "A"


class Explorer:
    def __init__(self):
        hello = receive()
        kit = hello.get("kit", {})
        if hello["protocol"] != "topomark/protocol@2" or kit.get("undirected-vertex", 0) < 1 or not kit.get("movable"):
            send({"type": "error", "message": "I need topomark/protocol@2 and one movable undirected vertex marker"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)

    def operate(self, op):
        """Drop or pick up the marker here ("drop" / "pick_up")."""
        send({"type": op, "kind": "vertex"})
        receive()

    def step(self, motion):
        """One traversal by relative ``motion``; return the signature reached."""
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def move(self, exit_):
        """Leave the current map vertex by its exit ``exit_`` (an explored one); return the signature reached."""
        v, entry = self.pos
        sig = self.step((exit_ - entry) % len(self.exits[v]))
        self.pos = tuple(self.exits[v][exit_])
        return sig

    def tree(self, root):
        """BFS over S from ``root``: each vertex (in BFS order) with the exit leading one step toward ``root``."""
        toward, todo = {root: None}, deque([root])
        while todo:
            v = todo.popleft()
            for w_j in self.exits[v]:
                if w_j and w_j[0] not in toward:
                    toward[w_j[0]] = w_j[1]
                    todo.append(w_j[0])
        return toward

    def walk_to(self, target, look=False):
        """Walk S to ``target``; with ``look``, stop where the marker is seen and return True."""
        toward = self.tree(target)
        while self.pos[0] != target:
            if self.move(toward[self.pos[0]])[1] and look:
                return True
        return False

    def candidates(self, vk, degree):
        """The known vertices that could be v_u, nearest v_k first: its degree, an unexplored exit, not v_k or
        a neighbour of v_k (a simple graph has no loop and no second edge between two vertices)."""
        near = {vk} | {w_j[0] for w_j in self.exits[vk] if w_j}
        return [v for v in self.tree(vk) if v not in near and len(self.exits[v]) == degree
                and any(h[0] == v for h in self.U)]

    def search(self, candidates):
        """Place validation (§2.3.1): visit the candidates looking for the marker; where it lies, or None."""
        for v in candidates:
            if self.walk_to(v, look=True):
                return self.pos[0]
        return None

    def back_link(self, vk, i, x):
        """Back-link validation (§2.3.1), the robot at v_k' = x with the marker: the exit e' of x that e leads to."""
        self.operate("pick_up")
        open_exits = [j for v, j in self.U if v == x]
        if len(open_exits) == 1:  # one candidate: no search needed
            return open_exits[0]
        self.walk_to(vk)
        self.operate("drop")
        self.walk_to(x)
        for j in open_exits:
            if self.step((j - self.pos[1]) % len(self.exits[x]))[1]:  # the marker: we are at v_k, entered by e
                self.pos = (vk, i)
                self.operate("pick_up")
                return j
            self.step(0)  # not this one: back to x
            self.pos = (x, j)
        send({"type": "error", "message": "back-link validation found no marker (not a simple graph?)"})
        sys.exit(1)

    def iterate(self):
        order = {v: k for k, v in enumerate(self.tree(self.pos[0]))}  # BFS order from the robot
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: order[self.U[k][0]]))  # the nearest e
        self.walk_to(vk)
        degree = self.step((i - self.pos[1]) % len(self.exits[vk]))[0]
        candidates = self.candidates(vk, degree)
        if candidates:  # v_u may be known
            self.operate("drop")  # mark v_u ...
            self.step(0)  # ... and come back over e
            self.pos = (vk, i)
            x = self.search(candidates)
            if x is not None:  # loop augmentation: e/e' = (v_k, v_k')
                j = self.back_link(vk, i, x)
                self.U.remove((x, j))
                self.exits[vk][i], self.exits[x][j] = [x, j], [vk, i]
                return
            self.walk_to(vk)  # not found: fetch the marker from v_u, which is new
            self.step((i - self.pos[1]) % len(self.exits[vk]))
            self.operate("pick_up")
        u = len(self.exits)  # non-loop augmentation: v_u joins S, e its exit 0
        self.exits.append([[vk, i]] + [None] * (degree - 1))
        self.exits[vk][i] = [u, 0]
        self.U += [(u, j) for j in range(1, degree)]
        self.pos = (u, 0)

    def run(self):
        while self.U:
            self.iterate()
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": []}, "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": []}})
        receive()


if __name__ == "__main__":
    Explorer().run()
