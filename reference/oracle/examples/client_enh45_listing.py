#!/usr/bin/env python3
"""Algorithm 4.4 (Enhancement-4) and Algorithm 4.5 with d = 2 (Enhancement-5) of the thesis as listed (§4.2),
speaking topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import), written from the listings of Algorithms 4.4
and 4.5 and the text of §4.2 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm enh4-listing -- python3 client_enh45_listing.py
    topomark conformance run SUITE --algorithm enh5-d2-listing -- python3 client_enh45_listing.py --enh5

Without a switch it follows Algorithm 4.4; ``--enh5`` follows Algorithm 4.5 with d = 2.  The robot carries one
directional vertex marker, Algorithm 3.1's lighthouse.  Line by line (4.4's numbers; 4.5's in brackets):

* line 1 [1]: the marker is dropped at v0 pointing at the exit the robot faces, v0's exit 0;
* line 2 [2]: S = {v0}, U = v0's exits in order;
* line 3 [3]: D, the neighbour signatures of known places, is empty;
* line 5 [5]: e = (v_k, i) is the entry of U whose known end is nearest the robot in S (ties: U's order);
* line 6 [6]: the robot walks a shortest path of S to v_k and follows e to v_u, sensing its signature;
* [line 7]: Algorithm 4.5 only: the robot walks out and back through each other exit of v_u (counted
  clockwise from e) and, from each neighbour x so reached, out and back through each other exit of x: every
  place within distance 2 of v_u reached through v_u's other exits, sensed before or not;
* line 7 [8]: H is every other unexplored edge e' = (v_k', i') of U whose known end v_k' shows v_u's signature as
  the robot would sense it entering by e' (v_k itself left out, §3.3: "Every vertex (except v_k) in S could
  potentially correspond to v_u"), in U's order, less every e' that what is known around v_k' contradicts:
  assuming v_u is v_k' entered by e' and e joins v_k to it, v_k (the place behind e, whose signature S knows)
  and, for 4.5, every place the expansion sensed, are traced from v_k' over S and over D; a place whose
  signature is known (on S, or in D) and differs from what the robot sensed there (for v_k: S's signature of v_k
  entered by e) rejects e'.  For 4.4 that is the listing's test: the far end of e', retrieved from D, shows
  v_k's signature; for 4.5 it is the comparison of expanded signatures, enumerated from e' and from e;
* lines 8-17 [9-18]: each hypothesis of H in turn: its motions are those of a shortest path of S from v_k' to v0
  (one breadth-first tree rooted at v0, exits scanned in order) and its expected perceptions the signatures S
  predicts along it; the robot first retraces to v_u (through the edges it came by, in reverse), then executes
  them from v_u and stops at the first mismatch (rejected); if all match the hypothesis is confirmed and the
  robot stands at v0;
* lines 18-19 [19-20]: loop augmentation: e joined to e', e' leaves U;
* lines 20-21 [21-22]: non-loop augmentation, after the robot retraced to v_u: a new vertex whose exit 0 is e,
  its other exits, clockwise, appended to U;
* line 22: Algorithm 4.4 only: the robot walks out and back through each other exit of the new vertex, each
  one, sensed before in this iteration or not, and what it sensed goes into D;
* [line 23]: Algorithm 4.5 only: what the expansion sensed around the new vertex goes into D, to depth 2, without
  motion.

Decisions where the listings are silent (each the one topomark's ``enh4-listing`` and ``enh5-d2-listing`` make):

* the marker: a v_u showing the marker is v0, its entry read off the marker's direction (§3.3: place and
  back-link at once): loop augmentation at once, no expansion, no hypothesis;
* D is kept as records beyond unexplored darts of S: D[(x, t)] is the signature sensed beyond exit t of x and,
  for 4.5, the signatures sensed beyond that place by motions relative to its entry.  When (x, t) is explored
  its record moves on to the place it now leads to (the record's deeper places are recorded under that place's
  unexplored exits), so what was sensed stays known around places of S;
* what is "known" around v_k' is S and D together: v0 (never new, so never in D) and the edges already explored
  from v_k' are read off S;
* only a new vertex's surroundings are recorded (line 22, line 23 "if v_u is validated to be a new place"), to
  the listing's depth (1 for 4.4, 2 for 4.5), and never v_k's side of v_u (the edge e, v_k is in S);
* Algorithm 4.5 line 7's "distance d neighbours" are reached through v_u's other exits, never back over e.

The motions executed from v_u form a tree rooted at v_u (each node a motion sequence from v_u, the first motion
counted from e); the robot walks it down by motions and up by moving back through the edge it came by, so it
always knows which node it stands at and how its entry is turned there.  Map vertices are numbered 0, 1, ...
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
    """A node of the tree of motions executed from v_u: the signature sensed there, its children by motion."""

    def __init__(self, parent, motion, sig):
        self.parent, self.motion, self.sig, self.children = parent, motion, sig, {}
        self.depth = 0 if parent is None else parent.depth + 1


class Record:
    """A place of D: the signature sensed there and, by relative motion, the places sensed beyond it."""

    def __init__(self, sig):
        self.sig, self.children = sig, {}


class Explorer:
    def __init__(self, depth):
        self.depth = depth  # 1: Algorithm 4.4; 2: Algorithm 4.5 with d = 2
        hello = receive()
        kit = hello.get("kit", {})
        if hello["protocol"] != "topomark/protocol@2" or set(kit) != {"directional-vertex"}:
            send({"type": "error", "message": "I speak topomark/protocol@2 with one directional vertex marker "
                                              "(the kit of Algorithms 4.4 and 4.5) only"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]  # line 2
        self.D = {}  # line 3: (known vertex, unexplored exit) -> Record of the place beyond it
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

    def home(self):
        """Line 17 [17]: retrace to v_u."""
        while self.node is not self.root:
            self.up()

    def around(self, depth):
        """Out and back through every other exit of the robot's node, and so on to ``depth`` (line 22 [7])."""
        for k in range(1, self.node.sig[0]):
            self.down(k)
            if depth > 1:
                self.around(depth - 1)
            self.up()

    def walk(self, h):
        """Lines 10-16 [11-18]: from v_u, execute h's motions until the first mismatch; True if all match."""
        self.home()
        for k, want in zip(h["motions"], h["expected"]):
            if self.down(k) != want:
                return False
        return True

    # -- D ------------------------------------------------------------------------------------------------
    def absorb(self, x, entry, node, deep):
        """Route what ``node`` (a tree node or a record) saw beyond the map place (x, entry) into D, through
        explored edges of S, as far as ``deep`` allows (a tree node's depth; records always)."""
        for k, child in node.children.items():
            if not deep(child):
                continue
            t = (entry + k) % len(self.exits[x])
            far = self.exits[x][t]
            if far is not None:
                self.absorb(far[0], far[1], child, deep)
            else:
                self.merge(self.D.setdefault((x, t), Record(child.sig)), child, deep)

    def merge(self, rec, node, deep):
        for k, child in node.children.items():
            if deep(child):
                self.merge(rec.children.setdefault(k, Record(child.sig)), child, deep)

    def migrate(self, darts):
        """A record under a dart just explored moves on to the place the dart now leads to."""
        for dart in darts:
            rec = self.D.pop(dart, None)
            if rec is not None:
                far = self.exits[dart[0]][dart[1]]
                self.absorb(far[0], far[1], rec, lambda _: True)

    def contradicts(self, h, e):
        """Line 7 [8]: assuming h, some place traced from v_k' (v_k behind e, the expansion) is known, on S or
        in D, with another signature than the robot sensed (or, for v_k, than S gives it entered by e)."""
        joined = {e: h["dart"], h["dart"]: e}
        todo = [(self.root, h["dart"], [])]
        while todo:
            node, place, recs = todo.pop()
            for k, child in node.children.items():
                far, nrecs = None, [r.children[k] for r in recs if k in r.children]
                if place is not None:
                    x, entry = place
                    t = (x, (entry + k) % len(self.exits[x]))
                    far = self.exits[x][t[1]]
                    if far is None:
                        far = joined.get(t)
                        if t in self.D:
                            nrecs.append(self.D[t])
                if far is not None and self.expect(far[0], far[1]) != child.sig:
                    return True
                if any(r.sig != child.sig for r in nrecs):
                    return True
                if far is not None or nrecs:
                    todo.append((child, None if far is None else tuple(far), nrecs))
        return False

    # -- one iteration ------------------------------------------------------------------------------------
    def hypotheses(self, vk, sig):
        """Every other unexplored edge whose known end shows v_u's signature, with its motions to v0 and
        expected perceptions along them (a shortest path of S, one breadth-first tree rooted at v0)."""
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

    def join(self, e, far):
        self.U.remove(far)
        self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)

    def iterate(self):
        dist = self.distances(self.pos[0])
        e = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 5: the nearest
        vk, i = e
        toward = self.tree(vk)
        while self.pos[0] != vk:  # line 6
            self.move(toward[self.pos[0]])
        sig = self.step((i - self.pos[1]) % len(self.exits[vk]))
        if sig[1] is not None:  # the marker: v_u is v0, entered by the exit its direction names
            far = (0, (0 - sig[1]) % sig[0])
            self.join(e, far)
            self.migrate([e, far])
            self.pos = far
            return
        self.root = self.node = Node(None, None, sig)
        self.turn = 0
        self.root.children[0] = Node(self.root, 0, self.expect(vk, i))  # v_k, behind e: no motion
        if self.depth == 2:
            self.around(2)  # Algorithm 4.5 line 7
        H = [h for h in self.hypotheses(vk, sig) if not self.contradicts(h, e)]  # line 7 [8]
        confirmed = None
        for h in H:  # lines 8-17 [9-18]
            if self.walk(h):
                confirmed = h
                break
        if confirmed is not None:  # lines 18-19 [19-20]
            self.join(e, confirmed["dart"])
            self.migrate([e, confirmed["dart"]])
            self.pos = confirmed["end"]
            return
        self.home()  # lines 20-21 [21-22]: e is exit 0 of the new vertex
        u = len(self.exits)
        self.exits.append([[vk, i]] + [None] * (sig[0] - 1))
        self.exits[vk][i] = [u, 0]
        self.U += [(u, j) for j in range(1, sig[0])]
        if self.depth == 1:
            self.around(1)  # Algorithm 4.4 line 22
        self.pos = (u, self.turn)
        self.migrate([e, (u, 0)])
        depth = self.depth  # line 22 / [23]: the new vertex's surroundings into D (not v_k's node: in S)
        self.absorb(u, 0, self.root,
                    lambda n: (n.parent is not self.root or n.motion != 0) and n.depth <= depth)

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
    Explorer(2 if "--enh5" in sys.argv[1:] else 1).run()
