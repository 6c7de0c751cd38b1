#!/usr/bin/env python3
"""Algorithm 6.2 of the thesis as listed (§6.2.1 Case 3a, Σ_{k=1}^{n−1} k markers, the V-marker algorithm) with
§6.2.2's directional V-markers (Table 6.2), speaking topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import), written from the listing of Algorithm 6.2
and the text of §6.2.1 Case 3a and §6.2.2 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm case-dv-sum-listing -- python3 client_dv_sum_listing.py
    topomark conformance run SUITE --algorithm case-3a -- python3 client_dv_sum_listing.py --undirected

The robot carries Σ_{k=1}^{n−1} k vertex markers (read from ``hello``; it never learns n) and drops a different
number at each place it discovers, so a marked place names itself.  §6.2.2: "the robot drops the markers in such
a way that the entry edge is indicated", so every marked place is a directional lighthouse (place and back-link
at once).  With ``--undirected`` the markers have no direction: Algorithm 6.2 as listed for Case 3a.  The
listing, line by line:

* lines 1-4: i = 1; one marker at v0 (pointing at the exit it faces, v0's exit 0); S is v0, U its exits;
  visitedAllVertices is false (here: no blank place yet);
* line 6: the unexplored edge e = (v_k, i) of U whose known end is closest to the robot (hops over S), ties by
  U's order (U lists v0's exits, then each new place's exits clockwise from its entry);
* line 7: the robot walks a shortest path of S to v_k (the breadth-first tree of S rooted at the robot, exits in
  index order) and follows e;
* lines 8-13: v_u shows no marker and no place was left blank: a new place, e its exit 0; if the robot still holds
  i + 1 markers it drops them there, pointing at e (the entry edge, its exit 0), and i grows;
* lines 14-16: else it leaves v_u blank (the last new place; visitedAllVertices is true);
* line 18: otherwise the count sensed names v_k' (no marker: the blank); a directional count also names the
  entry edge e' = (v_k', j), j = −h mod deg for a head sensed h places clockwise from the entry; loop
  augmentation e/e' with no motion (§6.2.2), then line 30's removal of e' from U;
* lines 19-35: the blank (or, ``--undirected``, any known place) gives no back-link: the robot leaves v_k' by the
  other edges in turn, clockwise from e (relative exits 1, 2, ...), and senses the far end.  A far end whose count
  is a known neighbour of v_k' over an explored edge (c in s, lines 25-31; a directional far end: its head names
  the edge the robot came in by, which S must know) gives e'' = (v_k', t), so the entry edge is t − p; loop
  augmentation, e' leaves U, and the robot stays at that neighbour.  Any other far end (lines 32-35: an unknown
  count, an edge of U, or an unmarked place before the blank exists) sends the robot straight back.

Where the listing is silent (topomark's literal explorer, ``case-dv-sum-listing``, decides the same way):

* line 6 is the ``nearest`` edge policy alone: a loop edge into the blank is probed as lines 19-35 say
  (topomark's ``case-dv-sum`` takes the blank's own edges first once it is blank, so it never probes);
* line 10's "enough markers" is the count the robot still holds; the blank has no marker and no direction;
* too few markers: a second unmarked place, a sensed count no place of S shows, a place whose degree or whose
  marked neighbour contradicts S, a probe that finds no known neighbour, or an e' that is not in U (or would make
  a self-loop or a second edge): the robot gives up (``error``), as topomark's run ends ``failed``.

Map vertices are numbered 0, 1, ... and each vertex's exits clockwise from the edge it was first entered by (v0:
the exit it faced).  After each iteration it sends a snapshot of (S, U).
"""
import json
import re
import sys
from collections import deque

DIRECTIONAL = "--undirected" not in sys.argv[1:]
KIT = "directional-vertex" if DIRECTIONAL else "undirected-vertex"


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def receive():
    msg = json.loads(sys.stdin.readline())
    if msg["type"] in ("error", "bye"):
        sys.exit(0 if msg.get("verdict") == "pass" else 1)
    return msg


def parse(sig):
    """'[3,V2-1,A]' -> (3, 2, 1); '[3,V4,A]' -> (3, 4, None); '[3,A,A]' -> (3, 0, None)."""
    items = sig.strip("[]").split(",")
    m = re.match(r"V(\d*)(?:-(\d+))?$", items[1])
    if not m:
        return int(items[0]), 0, None
    return int(items[0]), int(m.group(1) or 1), None if m.group(2) is None else int(m.group(2))


def give_up(why):
    """Too few markers (fewer than the assured Σ k): the run ends failed, as the listing cannot go on."""
    send({"type": "error", "message": "out of markers: " + why})
    sys.exit(1)


class Explorer:
    def __init__(self):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or set(hello.get("kit", {})) != {KIT}:
            send({"type": "error", "message": "I speak topomark/protocol@2 with %s markers only" % KIT})
            sys.exit(2)
        self.markers = hello["kit"][KIT]
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]  # line 3
        self.count_of, self.vertex_of = {}, {}  # map vertex <-> its count (0: the blank)
        self.blank = None  # line 4: visitedAllVertices once set
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)
        if not self.mark(0):  # lines 1-2: one marker at v0
            give_up("no marker for v0")

    def step(self, motion):
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def degree(self, v):
        return len(self.exits[v])

    def mark(self, v):
        """Lines 10-13 (and 2): the next count at map vertex v, pointing at its exit 0, if the robot holds it."""
        count = len(self.count_of) + 1
        if self.markers < count:
            return False
        self.markers -= count
        send({"type": "drop", "kind": "vertex", "count": count, "direction": 0 if DIRECTIONAL else None})
        receive()
        self.count_of[v], self.vertex_of[count] = count, v
        return True

    def tree(self):
        """Breadth-first over S's explored edges from the robot: hops and the parent dart of each place."""
        root = self.pos[0]
        dist, parent, todo = {root: 0}, {}, deque([root])
        while todo:
            v = todo.popleft()
            for i, w_j in enumerate(self.exits[v]):
                if w_j and w_j[0] not in dist:
                    dist[w_j[0]], parent[w_j[0]] = dist[v] + 1, (v, i)
                    todo.append(w_j[0])
        return dist, parent

    def walk_to(self, target, parent):
        """Line 7: along the tree from the robot to ``target``."""
        path = []
        while target != self.pos[0]:
            path.append(parent[target])
            target = parent[target][0]
        for v, i in reversed(path):
            self.step((i - self.pos[1]) % self.degree(v))
            self.pos = tuple(self.exits[v][i])

    def join(self, e, far):
        """Lines 29-30: loop augmentation e/e' = ``far``, e' removed from U."""
        if far not in self.U:
            give_up("e' = %s is not in U" % (far,))
        if far[0] == e[0] or any(w_j and w_j[0] == far[0] for w_j in self.exits[e[0]]):
            give_up("e/e' = %s/%s would make a self-loop or a second edge" % (e, far))
        self.U.remove(far)
        self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)

    def iterate(self):
        dist, parent = self.tree()
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 6
        self.walk_to(vk, parent)
        degree, count, head = self.step((i - self.pos[1]) % self.degree(vk))  # line 7
        if count == 0 and self.blank is None:  # lines 8-16: a new place, e its exit 0
            u = len(self.exits)
            self.exits.append([[vk, i]] + [None] * (degree - 1))
            self.exits[vk][i] = [u, 0]
            self.U += [(u, j) for j in range(1, degree)]
            self.pos = (u, 0)
            if not self.mark(u):  # lines 14-16: not enough markers: the last new place, left blank
                self.blank, self.count_of[u], self.vertex_of[0] = u, 0, u
            return
        x = self.vertex_of.get(count)  # line 18: the unique count (0: the blank) names v_k'
        if x is None or self.degree(x) != degree:
            give_up("[%d] with %d markers fits no place of the map" % (degree, count))
        if head is not None:  # a directional lighthouse: its head points at x's exit 0 (§6.2.2)
            self.join((vk, i), (x, -head % degree))
            self.pos = (x, -head % degree)
            return
        self.probe((vk, i), x, degree)

    def probe(self, e, x, degree):
        """Lines 19-35: the other edges of v_k' = x, clockwise from e, until a known neighbour over an explored
        edge is sensed."""
        for p in range(1, degree):
            far_degree, count, head = self.step(1)  # relative exit p: one clockwise from the edge last taken
            t = self.explored_exit(x, far_degree, count, head)
            if t is not None:  # lines 25-31: e'' = (x, t), entered p exits clockwise of e', the entry edge
                self.join(e, (x, (t - p) % degree))
                self.pos = tuple(self.exits[x][t])
                return
            self.step(0)  # lines 33, 35: back to v_k'
        give_up("no edge of map vertex %d leads to a known neighbour" % x)

    def explored_exit(self, x, degree, count, head):
        """Line 25: the exit t of x over an explored edge to the place sensed, or None (not an explored edge)."""
        if count == 0 and self.blank is None:
            return None  # line 34: an unmarked place before the blank: a new one
        y = self.vertex_of.get(count)
        if y is None or y == x or self.degree(y) != degree:
            give_up("a neighbour of map vertex %d shows [%d] with %d markers" % (x, degree, count))
        if head is not None:  # its head names the edge of y the robot came in by
            far = self.exits[y][-head % degree]
            if far is not None and far[0] != x:
                give_up("map vertex %d's marked exit leads to %d, not to %d" % (y, far[0], x))
            return None if far is None else far[1]
        for t, w_j in enumerate(self.exits[x]):  # c in s: the counts at the far ends of x's explored edges
            if w_j and w_j[0] == y:
                return t
        return None

    def marks(self):
        return [{"vertex": v, "count": c, "head": 0 if DIRECTIONAL else None}
                for v, c in sorted(self.count_of.items()) if c]

    def run(self):
        while self.U:  # line 5
            self.iterate()
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": self.marks()},
                  "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        markers = []
        for mark in self.marks():
            v = mark["vertex"]
            markers.append({"kind": "vertex", "at": names[v], "count": mark["count"]})
            if DIRECTIONAL:
                markers[-1]["points_to"] = names[self.exits[v][0][0]]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": markers}})
        receive()  # line 36


if __name__ == "__main__":
    Explorer().run()
