#!/usr/bin/env python3
"""Algorithm 6.4 of the thesis as listed (§6.2.1 Case 5, k > 3 undirected markers, Version-1), and with
``--directional`` Table 6.2's "unknown k > 3" row (§6.2.2: Version-1 with directional V-markers), speaking
topomark/protocol@2.  Algorithm 6.5 (Version-2) is ``client_case5_v2_listing.py``, which builds on this one.

Standalone on purpose (standard library only, no topomark import), written from the listing of Algorithm 6.4
and the text of §6.2.1 Case 5 and §6.2.2 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm case-5-v1-listing -- python3 client_case5_listing.py
    topomark conformance run SUITE --algorithm case-5-directional-listing -- python3 client_case5_listing.py \
        --directional

The listing is followed *to the letter, where it fails too*: its counter (lines 1, 3, 13, 15) gives v0 one
marker and, since i starts at 1 and grows only after a drop, the first new place one marker as well — two
places share the label "one marker", which line 9 (Algorithm 6.2 line 18, "the unique count names v_u") cannot
tell apart.  Where that label must name v_u the client gives up (``error``), exactly where topomark's literal
entries end ``failed`` (the triangle, for one); elsewhere it maps the world.  The listing, line by line:

* line 1: one marker at v0 (``--directional``: pointing at the exit the robot faces, v0's exit 0);
* lines 2-3: S is v0, U its exits (in order); i = 1;
* lines 5-6: the unexplored edge e = (v_k, i) of U whose known end is closest to the robot (hops over S), ties by
  U's order (U lists v0's exits, then each new place's exits clockwise from its entry); the robot walks a shortest
  path of S to v_k (the breadth-first tree of S rooted at the robot, exits in index order) and follows e;
* lines 7-10: v_u shows markers: their count names the known place v_k' (a count two places share names none:
  give up).  Undirected, the back-link is found by probing (Algorithm 6.2 lines 19-35): the robot leaves v_k' by
  its other edges in turn, clockwise from e (relative exits 1, 2, ...), and senses the far end; a marked far end
  that is a neighbour of v_k' over an explored edge (line 25's "c ∈ s"; a count two places share is read as the
  one of them that is such a neighbour, and names none when both are) gives e'' = (v_k', t), so e' = t − p; loop
  augmentation e/e', e' leaves U, and the robot stays at that neighbour.  Any other far end (unmarked, or marked
  but over no explored edge of v_k') sends the robot straight back.  ``--directional``: the head names e' at once,
  j = −h mod deg for a head sensed h exits clockwise from the entry (§6.2.2), no probe;
* lines 11-15: v_u shows no marker before phase II: a new place, e its exit 0; if the robot still holds i markers
  (it counts them from ``hello``'s kit), it drops i there (``--directional``: pointing at e) and i grows;
* line 16: else phase II starts, for good; at that first refusal every known place is marked, so line 17's H is
  empty and v_u joins S unmarked at once (line 35), no motion.  Later unmarked places are not offered a drop;
* lines 17-30 (phase II, an unmarked v_u): H is every unexplored edge e' = (v_k', i') of U, v_k' ≠ v_k, whose known
  end is unmarked and of v_u's degree, in U's order.  For each in turn: v_l is the marked place of S nearest
  v_k' (ties: the lower map vertex; a breadth-first search from v_k', exits in index order), v_n the marked
  neighbour of v_l by v_l's lowest explored exit; M_h' follows that search's path from v_k' to v_l, then the
  edge to v_n (``--directional``: the path ends at v_l, whose head gives its entry), and P^E is what S predicts
  after each motion (degree, count and, directional, the head).  The robot executes M_h' from v_u (its first
  motion turned by where the robot now stands at v_u), stopping at the first perception that differs; a full
  match confirms h' (lines 29-30); a mismatch rejects it and the robot retraces its motions back to v_u
  (line 28): back through the edge it came by, then each earlier motion reversed;
* lines 31-35: loop augmentation e/e' (the robot stays where M_h' ended), or v_u joins S unmarked, e its exit 0,
  the robot at v_u where the last retrace left it.

Where the listing is silent (topomark's literal entries, ``case-5-v1-listing`` and
``case-5-directional-listing``, decide the same way): line 5's choice (the ``nearest`` edge policy), the order of
line 8's probes (clockwise from e), line 12 as the count of markers left, the lighthouse's tie-break and v_n's
choice, and the retrace of a rejected hypothesis.  Anything the map contradicts (a count no place shows, a degree
that differs, no probe finding a known neighbour, an e' not in U) makes the robot give up.

Map vertices are numbered 0, 1, ... and each vertex's exits clockwise from the edge it was first entered by (v0:
the exit it faced).  After each iteration it sends a snapshot of (S, U).
"""
import json
import re
import sys
from collections import deque

DIRECTIONAL = "--directional" in sys.argv[1:]
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
    """The listing cannot go on (its shared count, or a map it contradicts): the run ends failed."""
    send({"type": "error", "message": "Algorithm 6.4 as listed cannot go on: " + why})
    sys.exit(1)


class Explorer:
    def __init__(self):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or set(hello.get("kit", {})) != {KIT}:
            send({"type": "error", "message": "I speak topomark/protocol@2 with %s markers only" % KIT})
            sys.exit(2)
        self.markers = hello["kit"][KIT]
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]  # line 2
        self.count_of = {}  # marked map vertex -> its count
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)
        self.phase = 1
        self.drop(0, 1)  # line 1
        self.i = 1  # line 3

    # -- the robot -----------------------------------------------------------------------------------
    def step(self, motion):
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def degree(self, v):
        return len(self.exits[v])

    def drop(self, v, count):
        """``count`` markers at map vertex v (directional: pointing at its exit 0)."""
        self.markers -= count
        send({"type": "drop", "kind": "vertex", "count": count, "direction": 0 if DIRECTIONAL else None})
        receive()
        self.count_of[v] = count

    def expect(self, v, entry):
        """The signature S predicts at map vertex v entered by exit ``entry``."""
        count = self.count_of.get(v, 0)
        head = (0 - entry) % self.degree(v) if DIRECTIONAL and count else None
        return self.degree(v), count, head

    def places(self, count):
        """The places of S marked with ``count`` markers (two for count 1: the listing's counter)."""
        return [v for v, c in self.count_of.items() if c == count]

    def search(self, root, stop=None):
        """Breadth-first over S's explored edges from ``root``, exits in index order, layer by layer: hops and
        parent darts; with ``stop`` (a set of places), ended after the first layer that reaches one of them."""
        dist, parent, layer = {root: 0}, {}, [root]
        if stop is not None and root in stop:
            return dist, parent, [root]
        while layer:
            following, found = [], []
            for v in layer:
                for i, w_j in enumerate(self.exits[v]):
                    if w_j and w_j[0] not in dist:
                        dist[w_j[0]], parent[w_j[0]] = dist[v] + 1, (v, i)
                        following.append(w_j[0])
                        if stop is not None and w_j[0] in stop:
                            found.append(w_j[0])
            if found:
                return dist, parent, found
            layer = following
        return dist, parent, []

    def path(self, parent, source, target):
        """The darts of the search tree from ``source`` (its root) to ``target``."""
        out = []
        while target != source:
            out.append(parent[target])
            target = parent[target][0]
        return out[::-1]

    # -- augmentation ----------------------------------------------------------------------------------
    def join(self, e, far):
        """Loop augmentation e/e' = ``far``, e' removed from U."""
        if far not in self.U:
            give_up("e' = %s is not in U" % (far,))
        self.U.remove(far)
        self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)

    def new_place(self, e, degree, heading=0):
        """Non-loop augmentation: v_u joins S, e its exit 0; the robot at v_u entered ``heading`` clockwise of e."""
        u = len(self.exits)
        self.exits.append([list(e)] + [None] * (degree - 1))
        self.exits[e[0]][e[1]] = [u, 0]
        self.U += [(u, j) for j in range(1, degree)]
        self.pos = (u, heading)
        return u

    # -- one iteration ---------------------------------------------------------------------------------
    def iterate(self):
        dist, parent, _ = self.search(self.pos[0])
        e = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 5
        vk, i = e
        for v, x in self.path(parent, self.pos[0], vk):  # line 6
            self.step((x - self.pos[1]) % self.degree(v))
            self.pos = tuple(self.exits[v][x])
        degree, count, head = self.step((i - self.pos[1]) % self.degree(vk))
        if count:  # lines 7-10
            places = self.places(count)
            if len(places) != 1:
                give_up("%d marker(s) mark %d places of S: the count does not name v_u" % (count, len(places)))
            x = places[0]
            if self.degree(x) != degree:
                give_up("[%d] with %d markers fits no place of S" % (degree, count))
            if head is not None:  # --directional: the head points at x's exit 0 (§6.2.2)
                self.join(e, (x, -head % degree))
                self.pos = (x, -head % degree)
            else:
                self.probe(e, x, degree)
        elif self.phase == 1:  # lines 11-15
            u = self.new_place(e, degree)
            if self.markers >= self.i:  # line 12
                self.drop(u, self.i)  # line 13
                self.i += 1  # line 15
            else:  # line 16: phase II; every known place is marked, so H is empty: line 35 at once
                self.phase = 2
        else:  # lines 17-35
            self.phase_two(e, degree)

    def probe(self, e, x, degree):
        """Lines 8-10 (Algorithm 6.2 lines 19-35): the other edges of v_k' = x, clockwise from e, until a known
        neighbour over an explored edge is sensed."""
        for p in range(1, degree):
            far_degree, count, head = self.step(1)  # relative exit p: one clockwise from the edge last taken
            t = self.explored_exit(x, far_degree, count, head)
            if t is not None:  # e'' = (x, t), entered p exits clockwise of e', the entry edge
                self.join(e, (x, (t - p) % degree))
                self.pos = tuple(self.exits[x][t])
                return
            self.step(0)  # back to v_k'
        give_up("no edge of map vertex %d leads to a known neighbour" % x)

    def explored_exit(self, x, degree, count, head):
        """Line 9: the exit t of x over an explored edge to the marked place sensed, or None."""
        if count == 0:
            return None  # an unmarked far end: new, or a phase-II place; either way it names nothing
        places = self.places(count)
        if len(places) > 1:  # the listing's shared count
            if DIRECTIONAL:
                give_up("%d marker(s) mark %d places of S" % (count, len(places)))
            ends = [t for t, w_j in enumerate(self.exits[x]) if w_j and w_j[0] in places]
            if len(ends) > 1:
                give_up("%d marker(s) mark %d neighbours of map vertex %d" % (count, len(ends), x))
            return ends[0] if ends else None
        y = places[0] if places else None
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

    # -- phase II (lines 17-35) --------------------------------------------------------------------------
    def hypotheses(self, vk, degree):
        """Lines 17-18 and 21-24: H in U's order, each with M_h' and P^E."""
        out = []
        for v, j in self.U:
            if v == vk or v in self.count_of or self.degree(v) != degree:
                continue
            _, parent, found = self.search(v, set(self.count_of))
            if not found:
                give_up("no marked place is connected to map vertex %d" % v)
            light = min(found)  # line 21: the nearest marked place, the lowest of them
            darts = self.path(parent, v, light)
            if not DIRECTIONAL:  # line 22: v_n, the marked neighbour by v_l's lowest explored exit
                ends = [t for t, w_j in enumerate(self.exits[light]) if w_j and w_j[0] in self.count_of]
                if not ends:
                    give_up("the lighthouse %d has no marked neighbour" % light)
                darts.append((light, ends[0]))
            motions, expected, entry = [], [], j
            for x, t in darts:  # line 23: M_h' and P^E along the darts
                motions.append((t - entry) % self.degree(x))
                w, entry = self.exits[x][t]
                expected.append(self.expect(w, entry))
            out.append({"dart": (v, j), "motions": motions, "expected": expected, "end": (w, entry)})
        return out

    def phase_two(self, e, degree):
        heading = 0  # where the robot stands at v_u: its entry edge counted clockwise from e
        for h in self.hypotheses(e[0], degree):  # lines 19-20
            matched, done, degrees = self.execute(h, degree, heading)
            if matched:  # lines 29-33
                self.join(e, h["dart"])
                self.pos = h["end"]
                return
            heading = self.retrace(done, degrees, heading, degree)
        self.new_place(e, degree, heading)  # line 35: v_u unmarked

    def execute(self, h, degree, heading):
        """Line 25: M_h' from v_u, its first motion turned by where the robot stands there, up to the first
        perception that differs from P^E; whether all matched, the motions made and the degrees met."""
        done, degrees = [], [degree]
        for k, (motion, want) in enumerate(zip(h["motions"], h["expected"])):
            physical = (motion - heading) % degree if k == 0 else motion
            got = self.step(physical)
            done.append(physical)
            degrees.append(got[0])
            if got != want:
                return False, done, degrees
        return True, done, degrees

    def retrace(self, done, degrees, heading, degree):
        """Line 28: back to v_u, the last motion first; where the robot then stands at v_u."""
        self.step(0)
        for t in range(len(done) - 1, 0, -1):
            self.step(-done[t] % degrees[t])
        return (heading + done[0]) % degree

    def marks(self):
        return [{"vertex": v, "count": c, "head": 0 if DIRECTIONAL else None} for v, c in sorted(self.count_of.items())]

    def run(self):
        while self.U:  # line 4
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
        receive()  # line 37


if __name__ == "__main__":
    Explorer().run()
