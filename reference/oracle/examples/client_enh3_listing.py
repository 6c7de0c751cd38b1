#!/usr/bin/env python3
"""Algorithm 4.3 of the thesis as listed (Enhancement-3, §4.1), speaking topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import), written from the listing of Algorithm 4.3
and the text of §4.1 alone.  Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD.json --kit '{"directional-vertex": 1}' -- python3 client_enh3_listing.py
    topomark conformance run SUITE --algorithm enh3-listing -- python3 client_enh3_listing.py

The robot carries one directional vertex marker, Algorithm 3.1's lighthouse, and drops it at v0 pointing at
the exit it faces (line 1).  Each iteration (lines 3-37):

* lines 4-5: the unexplored edge e = (v_k, i) of U nearest the robot (ties: U's order); the robot walks a
  shortest path of S to v_k and follows e to v_u;
* lines 6-7: H is every other unexplored edge e' = (v_k', i') of U whose known end v_k' shows v_u's signature
  (degree and marker) as the robot would sense it entering by e' (v_k itself left out, §3.3: "Every vertex
  (except v_k) in S could potentially correspond to v_u"), in U's order; each hypothesis's motions are those of a
  shortest path of S from v_k' to v0 (one breadth-first tree rooted at v0) and its expected perceptions the
  signatures S predicts along it;
* lines 8-9: the first hypothesis's motions are executed from v_u;
* lines 10-31: on a match all along the path the hypothesis is confirmed; on a mismatch the robot stays
  (line 15), every remaining hypothesis h'' is traced (lines 16-24): assuming h'' (v_u is v_k'' entered by
  e'', and e joins v_k to it), every motion executed for e so far is followed on S, and, from every known place
  it passes, along the records of T made from there (a record stays a path from its known place when its edge
  is explored later, §4.1); a place whose signature is known (on S, or recorded in T) but differs from what
  the robot sensed there rejects h'' without motion.  If hypotheses remain, the one whose motions share the longest
  prefix with the path the robot has just executed is next (lines 27-29; ties: H's order); the robot retraces
  to the last node of that prefix, the nearest overlapping node, and executes the rest (lines 30-31);
* lines 32-35: loop augmentation (e joined to e'), or a new vertex whose exit 0 is e; the robot then retraces
  to the deepest place of its path whose position S now knows (v0, when a hypothesis was confirmed);
* lines 36-37: every motion executed for e is traced from v_u and e on the augmented S, and what the robot
  sensed past an unexplored edge (x, t) of S is recorded in T under (x, t), as a tree of relative motions and
  signatures (§4.1: "v_x-3-[4,A,A]-2-[2,A,A]...").

The executed motions for e form a tree rooted at v_u (each node a motion sequence from v_u, its first motion
counted from e); the robot walks it down by motions and up by moving back through the edge it came by, so
it always knows which node it stands at and how its entry is turned there.  Map vertices are numbered 0, 1, ...
and each vertex's exits clockwise from the edge it was first entered by.  After each iteration it sends a
snapshot of (S, U).
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


class Node:
    """A node of the tree of motions executed for e: the signature sensed there, its children by motion."""

    def __init__(self, parent, motion, sig):
        self.parent, self.motion, self.sig, self.children = parent, motion, sig, {}
        self.depth = 0 if parent is None else parent.depth + 1

    def path(self):
        out, node = [], self
        while node.parent is not None:
            out.append(node)
            node = node.parent
        return out[::-1]


class Record:
    """A place of T: the signature sensed there and, by relative motion, the places sensed beyond it."""

    def __init__(self, sig):
        self.sig, self.children = sig, {}


class Explorer:
    def __init__(self):
        hello = receive()
        kit = hello.get("kit", {})
        if hello["protocol"] != "topomark/protocol@2" or set(kit) != {"directional-vertex"}:
            send({"type": "error", "message": "I speak topomark/protocol@2 with one directional vertex marker "
                                              "(Algorithm 4.3's kit) only"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.T = {}  # line 2: (known vertex, unexplored exit) -> Record of the place beyond it
        self.pos = (0, 0)  # (map vertex, entry exit): the start counts the faced exit as exit 0
        send({"type": "drop", "kind": "vertex", "direction": 0})  # line 1: pointing at exit 0 of v0
        receive()

    # -- the robot -----------------------------------------------------------------------------------
    def step(self, motion):
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def move(self, exit_):
        """Leave the current map vertex by its exit ``exit_`` (S knows where it leads)."""
        v, entry = self.pos
        self.step((exit_ - entry) % len(self.exits[v]))
        self.pos = tuple(self.exits[v][exit_])

    def expect(self, v, entry):
        """The signature S predicts at map vertex v entered by exit ``entry``."""
        d = len(self.exits[v])
        return (d, (0 - entry) % d if v == 0 else None)

    def tree(self, root):
        """Breadth-first over explored edges: for each vertex, the exit leading one step toward ``root``."""
        toward, todo = {root: None}, deque([root])
        while todo:
            v = todo.popleft()
            for w_j in self.exits[v]:
                if w_j and w_j[0] not in toward:
                    toward[w_j[0]] = w_j[1]
                    todo.append(w_j[0])
        return toward

    def distances(self, root):
        """Hops over explored edges from ``root`` to every vertex of S."""
        dist, todo = {root: 0}, deque([root])
        while todo:
            v = todo.popleft()
            for w_j in self.exits[v]:
                if w_j and w_j[0] not in dist:
                    dist[w_j[0]] = dist[v] + 1
                    todo.append(w_j[0])
        return dist

    # -- walking the tree of executed motions ----------------------------------------------------------
    def down(self, k):
        """Motion k counted from the entry the node was first entered by; the signature sensed."""
        node = self.node
        sig = self.step((k - self.turn) % node.sig[0])
        child = node.children.get(k)
        if child is None:
            child = node.children[k] = Node(node, k, sig)
        self.node, self.turn = child, 0
        return sig

    def up(self):
        """Back through the edge the node was first entered by, to its parent."""
        node = self.node
        self.step((0 - self.turn) % node.sig[0])
        self.node, self.turn = node.parent, node.motion

    def walk(self, h):
        """Retrace to the nearest node h's motions overlap, then execute the rest; True if every perception
        along h's path matches (lines 9, 11-13, 30-31)."""
        here = [n.motion for n in self.node.path()]
        c = 0
        while c < min(len(here), len(h["motions"])) and here[c] == h["motions"][c]:
            c += 1
        while self.node.depth > c:
            self.up()
        for node, want in zip(self.node.path(), h["expected"]):
            if node.sig != want:
                return False
        for k, want in zip(h["motions"][c:], h["expected"][c:]):
            if self.down(k) != want:
                return False  # line 15: the robot stops and remains there
        return True

    # -- tracing the executed motions (lines 16-24, 36-37) ----------------------------------------------
    def beyond(self, state, k, joined):
        """One motion k from a traced ``state``: (the map place (vertex, entry) reached or None, the records of T
        whose paths the traced path has followed so far, reaching the same place)."""
        place, recs = state
        recs = [r.children[k] for r in recs if k in r.children]
        if place is None:
            return None, recs
        x, entry = place
        t = (entry + k) % len(self.exits[x])
        if (x, t) in self.T:  # a record made while (x, t) was unexplored: still a path from the known x
            recs.append(self.T[(x, t)])
        far = joined.get((x, t)) or self.exits[x][t]
        return (None if far is None else (far[0], far[1])), recs

    def contradicts(self, h, e):
        """Lines 17-24: assuming h, some place of the executed motions shows another signature than S or T
        (searched for every record whose path from a known place the traced motions follow)."""
        joined = {e: h["dart"], h["dart"]: e}  # under h, e and e'' are one edge
        todo = [(self.root, (h["dart"], []))]
        while todo:
            node, state = todo.pop()
            for k, child in node.children.items():
                nxt = self.beyond(state, k, joined)
                place, recs = nxt
                if place is None and not recs:
                    continue
                want = self.expect(*place) if place is not None else recs[0].sig
                if want != child.sig or any(r.sig != child.sig for r in recs):
                    return True
                todo.append((child, nxt))
        return False

    def record(self, start):
        """Lines 36-37: trace every executed motion from the validated v_u and e; record unknown places in T."""
        todo = [(self.root, ("S",) + start)]
        while todo:
            node, state = todo.pop()
            for k, child in node.children.items():
                if state[0] == "T":
                    rec = state[1].children.setdefault(k, Record(child.sig))
                    todo.append((child, ("T", rec)))
                    continue
                _, x, entry = state
                t = (entry + k) % len(self.exits[x])
                if self.exits[x][t] is not None:
                    w, j = self.exits[x][t]
                    todo.append((child, ("S", w, j)))
                else:
                    todo.append((child, ("T", self.T.setdefault((x, t), Record(child.sig)))))

    def settle(self, start):
        """Retrace to the deepest node of the robot's path whose place S knows; set the robot's map pose."""
        x, entry = start
        known = [(self.root, x, entry)]
        for node in self.node.path():
            t = (entry + node.motion) % len(self.exits[x])
            if self.exits[x][t] is None:
                break
            x, entry = self.exits[x][t]
            known.append((node, x, entry))
        target, x, entry = known[-1]
        while self.node is not target:
            self.up()
        self.pos = (x, (entry + self.turn) % len(self.exits[x]))

    # -- one iteration ------------------------------------------------------------------------------------
    def hypotheses(self, vk, sig):
        """Lines 6-7: every other unexplored edge whose known end shows v_u's signature, with its motions to v0
        and expected perceptions along them (a shortest path of S, one breadth-first tree rooted at v0)."""
        toward, out = self.tree(0), []
        for v, i in self.U:
            if v == vk or self.expect(v, i) != sig:
                continue
            motions, expected, x, entry = [], [], v, i
            while x != 0:
                motions.append((toward[x] - entry) % len(self.exits[x]))
                x, entry = self.exits[x][toward[x]]
                expected.append(self.expect(x, entry))
            out.append({"dart": (v, i), "motions": motions, "expected": expected, "end": (x, entry)})
        return out

    def iterate(self):
        dist = self.distances(self.pos[0])
        e = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 4: the nearest, first listed
        vk, i = e
        toward = self.tree(vk)
        while self.pos[0] != vk:  # line 5
            self.move(toward[self.pos[0]])
        sig = self.step((i - self.pos[1]) % len(self.exits[vk]))
        self.root = self.node = Node(None, None, sig)
        self.turn = 0
        H, confirmed = self.hypotheses(vk, sig), None
        if H:
            h = H.pop(0)  # line 8
            while True:
                if self.walk(h):
                    confirmed = h  # line 13
                    break
                H = [g for g in H if not self.contradicts(g, e)]  # lines 16-24
                if not H:
                    break
                here = [n.motion for n in self.node.path()]
                h = max(H, key=lambda g: _shared(here, g["motions"]))  # the first of the longest
                H.remove(h)
        if confirmed is not None:  # lines 32-33: loop augmentation
            far = confirmed["dart"]
            self.U.remove(far)
            self.exits[vk][i], self.exits[far[0]][far[1]] = list(far), [vk, i]
            start = far
        else:  # lines 34-35: non-loop augmentation, e is exit 0 of the new vertex
            u = len(self.exits)
            self.exits.append([[vk, i]] + [None] * (sig[0] - 1))
            self.exits[vk][i] = [u, 0]
            self.U += [(u, j) for j in range(1, sig[0])]
            start = (u, 0)
        self.record(start)  # lines 36-37
        self.settle(start)

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


def _shared(a, b):
    """How many motions two motion sequences share from the start."""
    n = 0
    while n < min(len(a), len(b)) and a[n] == b[n]:
        n += 1
    return n


if __name__ == "__main__":
    Explorer().run()
