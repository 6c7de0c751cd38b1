#!/usr/bin/env python3
"""A minimal explorer speaking topomark/protocol@2 with a thread of length l = ε that it carries and ties
again where it needs it: thesis §6.3.1, "Mapping by carrying a l = ε thread".

Standalone on purpose (standard library only, no topomark import): copy it and
change it.  Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD --kit '{"thread": 0}' -- python3 client_thread.py

An l = ε thread is only long enough to be tied at a vertex and laid out toward
one of its exits (§6.3.1): a directional marker that the robot can carry, so
the algorithm is Dudek's single movable marker algorithm with the thread as a
directional marker (§6.3.1, after [27]; see client_dudek.py).  The robot keeps
a map S of the explored part and the set U of unexplored darts (v, i): exit i
of map vertex v.  Each step takes the nearest e = (v_k, i) from U, walks S to
v_k and follows e to the unknown end v_u.  "At each new place v_u via e, the
robot ties the thread at v_u and lays it out toward the entry edge.  The robot
then searches S looking for the thread" (§6.3.1):

* not found: v_u is new.  The robot walks back to v_k, over e once more,
  unties the thread, and adds v_u to S with e as its exit 0;
* found tied at v_k', sensed as ``T-p`` (laid out p exits clockwise from the
  edge the robot entered by): "both the place and back-link can be determined
  immediately" -- e' is the exit the thread points at.  The robot unties it.

On the wire, tying is ``{"type": "thread", "op": "tie", "direction": 0}``
(toward the entry edge); the robot then lets go of the free end
(``"op": "leave"``), since an l = ε thread cannot be laid along an edge: a
move holding it is refused.  ``"op": "untie"`` at the tied vertex puts the
thread back in hand.  The world is a simple graph (§2.3.1), so v_u is neither
v_k nor a neighbour of v_k in S: those are not searched.  The thread is back
in the robot's hand at the end of every step, so the snapshots' S and the
final map show no thread.  Map vertex 0 is where the robot started, its exit 0
the exit it faced (the anchor @2's snapshots check); every other vertex
numbers its exits clockwise from the edge it was found by.
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
    """'[3,A,A,T-1,F]' -> (3, 1): the degree and where the thread tied here points (p exits clockwise from the
    entry edge); '[3,A,A]' -> (3, None).  The thread's items follow the edge part."""
    items = sig.strip("[]").split(",")
    tied = [int(item[2:]) for item in items[3:] if item.startswith("T-")]
    return int(items[0]), tied[0] if tied else None


class Explorer:
    def __init__(self):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or "thread" not in hello["kit"]:
            send({"type": "error", "message": "I need topomark/protocol@2 and a thread"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)

    def thread(self, op, **fields):
        """One thread operation here: "tie" (with a direction), "leave", "untie"."""
        send(dict(type="thread", op=op, **fields))
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
        """Walk S to ``target``; with ``look``, stop where the thread is seen and return its direction p."""
        toward = self.tree(target)
        while self.pos[0] != target:
            sig = self.move(toward[self.pos[0]])
            if look and sig[1] is not None:
                return sig[1]
        return None

    def candidates(self, vk, degree):
        """The known vertices that could be v_u, nearest v_k first: its degree, an unexplored exit, not v_k or
        a neighbour of v_k (a simple graph has no loop and no second edge between two vertices)."""
        near = {vk} | {w_j[0] for w_j in self.exits[vk] if w_j}
        return [v for v in self.tree(vk) if v not in near and len(self.exits[v]) == degree
                and any(h[0] == v for h in self.U)]

    def search(self, candidates):
        """Search S for the thread: the dart e' = (v_k', j) it points at, or None."""
        for v in candidates:
            p = self.walk_to(v, look=True)
            if p is not None:  # found at v_k', entered by exit ``entry``: the thread points at e'
                x, entry = self.pos
                return x, (entry + p) % len(self.exits[x])
        return None

    def iterate(self):
        order = {v: k for k, v in enumerate(self.tree(self.pos[0]))}  # BFS order from the robot
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: order[self.U[k][0]]))  # the nearest e
        self.walk_to(vk)
        degree = self.step((i - self.pos[1]) % len(self.exits[vk]))[0]
        candidates = self.candidates(vk, degree)
        if candidates:  # v_u may be known
            self.thread("tie", direction=0)  # tie the thread at v_u, toward e ...
            self.thread("leave")
            self.step(0)  # ... and come back over e
            self.pos = (vk, i)
            found = self.search(candidates)
            if found is not None:  # loop augmentation: e/e' = (v_k, v_k')
                self.thread("untie")
                x, j = found
                self.U.remove((x, j))
                self.exits[vk][i], self.exits[x][j] = [x, j], [vk, i]
                return
            self.walk_to(vk)  # not found: fetch the thread from v_u, which is new
            self.step((i - self.pos[1]) % len(self.exits[vk]))
            self.thread("untie")
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
