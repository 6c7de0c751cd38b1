#!/usr/bin/env python3
"""Algorithm 6.4 of the thesis as listed (§6.2.1 Case 5, k > 3 undirected markers, Version-1), with
``--version 2`` Algorithm 6.5 as listed (Version-2), and with ``--directional`` Table 6.2's "unknown k > 3" row
(§6.2.2: Version-1 with directional V-markers), speaking topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import), written from the listing of Algorithm 6.4
and the text of §6.2.1 Case 5 and §6.2.2 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm case-5-v1-listing -- python3 client_case5_listing.py
    topomark conformance run SUITE --algorithm case-5-directional-listing -- python3 client_case5_listing.py \
        --directional
    topomark conformance run SUITE --algorithm case-5-v2-listing -- python3 client_case5_listing.py --version 2

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

``--version 2`` follows Algorithm 6.5 (Version-2, undirected V-E-markers, ``case-5-v2-listing``), line by line:

* line 1: two markers at v0 and two on the edge it faces, e0 (v0's exit 0);
* lines 2-4: S, U and e as above (the nearest edge, a shortest path of S to v_k);
* lines 5-7: v_u shows two V-markers: v0, entered p exits clockwise of e0 where the robot senses e0's two
  markers at relative exit p; loop augmentation with no motion.  (e0 taken again from v0 once its far end is
  known joins that far end, the other place showing e0's two markers; under the nearest policy e0 is the first
  edge taken, so this never happens);
* lines 8-13: one V-marker and markers left: one marker on e (from v_u, on its entry edge), back to v_k over e,
  and the search of Case 1 (Algorithm 6.1 lines 11-19 as listed): every vertex of S but v_k with an unexplored
  edge, v_u's degree and v_u's edge marks as S shows them, in the preorder of a breadth-first tree of S rooted at
  v_k, each reached by a shortest path from where the robot stands and sensed on arrival only; the one showing
  a marked edge S does not show is v_k' and that edge e'.  Loop augmentation, e/e' carrying one marker;
* lines 29-33: no V-marker and markers left: a new place, e its exit 0, one marker there;
* lines 14-28, 34-37 (phase II, the markers spent): H is every unexplored edge e' = (v_k', i'), v_k' ≠ v_k, whose
  known end, entered by e', shows v_u's whole signature (degree, V-markers, edge marks); M_h' follows a shortest
  path of S from v_k' to v0 (the breadth-first search from v_k'), P^E what S predicts along it, v0's two markers
  on e0 fixing the entry.  Each is executed and retraced as in Version-1.  **Line 23 as printed** ("case P and
  P^E do not match throughout → confirm hypothesis") repeats line 21's condition, so a hypothesis that matched
  throughout is not confirmed: the client follows the line (``LINE_23_AS_PRINTED``), retraces every hypothesis,
  and v_u always joins S as a new place with the marks it showed (line 28).  Where phase II must close a loop
  this adds a known place again, a wrong map the oracle fails — as topomark's ``case-5-v2-listing`` ends
  ``wrong-map`` (the paw entered from its pendant with K = 4).

Version-2's decisions where the listing is silent (topomark's ``case-5-v2-listing`` makes the same): with one
pool of K markers (``{"undirected-either": K}``) the robot counts what it dropped, and "has one or more markers"
(lines 9, 31) is K minus that; with a split kit (vertex and edge markers apart) the pool is not counted, the kit
being enough for phase I; the marker on e is dropped from v_u right after sensing it, no traversal.

Map vertices are numbered 0, 1, ... and each vertex's exits clockwise from the edge it was first entered by (v0:
the exit it faced).  After each iteration it sends a snapshot of (S, U).
"""
import json
import re
import sys
from collections import deque

DIRECTIONAL = "--directional" in sys.argv[1:]
KIT = "directional-vertex" if DIRECTIONAL else "undirected-vertex"
LINE_23_AS_PRINTED = True  # Algorithm 6.5 line 23 confirms on "do not match throughout", after line 21 rejected it


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
            done, degrees, matched = [], [degree], True
            for k, (motion, want) in enumerate(zip(h["motions"], h["expected"])):  # line 25
                physical = (motion - heading) % degree if k == 0 else motion
                got = self.step(physical)
                done.append(physical)
                degrees.append(got[0])
                if got != want:
                    matched = False
                    break
            if matched:  # lines 29-33
                self.join(e, h["dart"])
                self.pos = h["end"]
                return
            self.step(0)  # line 28: back to v_u, the last motion first
            for t in range(len(done) - 1, 0, -1):
                self.step(-done[t] % degrees[t])
            heading = (heading + done[0]) % degree
        self.new_place(e, degree, heading)  # line 35: v_u unmarked

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


def parse2(sig):
    """'[4,V2,E2-1,E-3]' -> (4, 2, ((1, 2), (3, 1))): degree, V-markers, (relative exit, count) per marked edge."""
    items = sig.strip("[]").split(",")
    vertex = 0 if items[1] == "A" else int(items[1][1:] or 1)
    marks = []
    for item in items[2:]:
        m = re.match(r"E(\d*)-(\d+)$", item)
        if m:
            marks.append((int(m.group(2)), int(m.group(1) or 1)))
    return int(items[0]), vertex, tuple(sorted(marks))


class Version2(Explorer):
    """Algorithm 6.5 as listed (``--version 2``): Case 1b's footprint search with a double-marked v0 and e0 while the
    pool lasts (phase I), then hypotheses driven to v0, confirmed only as line 23 is printed: never."""

    def __init__(self):
        hello = receive()
        kit = hello.get("kit", {})
        if hello["protocol"] != "topomark/protocol@2" or not kit or not (
                set(kit) <= {"undirected-vertex", "undirected-edge"} or set(kit) == {"undirected-either"}):
            send({"type": "error", "message": "I speak topomark/protocol@2 with undirected vertex and edge markers "
                                              "(or one pool of either) only"})
            sys.exit(2)
        self.pool = kit.get("undirected-either")  # K, one pool the robot counts; None: a split kit, not counted
        self.dropped = 0
        self.exits = [[None] * parse2(hello["signature"])[0]]
        self.U = [(0, i) for i in range(len(self.exits[0]))]  # line 2
        self.count_of, self.emarks = {}, {}  # V-markers per map vertex; E-markers per dart (v, i)
        self.pos = (0, 0)
        self.drop2("vertex", 2)  # line 1: two markers at v0 ...
        self.count_of[0] = 2
        self.drop2("edge", 2)  # ... and two on the edge it faces, e0
        self.emarks[(0, 0)] = 2

    def step(self, motion):
        send({"type": "move", "motion": motion})
        return parse2(receive()["value"])

    def drop2(self, kind, count):
        """``count`` markers here (``vertex``) or on the edge the robot came by (``edge``, its relative exit 0)."""
        op = {"type": "drop", "kind": kind, "count": count}
        if kind == "edge":
            op["exit"] = 0
        self.dropped += count
        send(op)
        receive()

    def has_markers(self):
        """Lines 9 and 31: "if the robot has one or more markers" (a split kit: enough for phase I)."""
        return self.pool is None or self.pool - self.dropped > 0

    def expect(self, v, entry):
        d = self.degree(v)
        marks = sorted(((i - entry) % d, c) for (x, i), c in self.emarks.items() if x == v)
        return d, self.count_of.get(v, 0), tuple(marks)

    def shown(self, v):
        """v's marks as S shows them: the counts on its marked edges, sorted (the search's key)."""
        return sorted(c for (x, _), c in self.emarks.items() if x == v)

    def arrived(self, u, sig):
        """S records at the new map vertex u what the robot sensed entering it by e (its exit 0)."""
        if sig[1]:
            self.count_of[u] = sig[1]
        for p, c in sig[2]:
            self.emarks[(u, p)] = c

    def iterate(self):
        dist, parent, _ = self.search(self.pos[0])
        e = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 4
        vk, i = e
        for v, x in self.path(parent, self.pos[0], vk):
            self.step((x - self.pos[1]) % self.degree(v))
            self.pos = tuple(self.exits[v][x])
        sig = self.step((i - self.pos[1]) % self.degree(vk))
        degree, count, marks = sig
        far = [d for d, c in self.emarks.items() if c == 2 and d[0] != 0] if e == (0, 0) else []
        if far:  # e0 again from v0: its far end, known, shows the other end of e0
            self.join(e, far[0])
            self.pos = far[0]
        elif count == 2:  # lines 5-7: v0, entered p exits clockwise of e0
            p = next(p for p, c in marks if c == 2)
            self.join(e, (0, -p % degree))
            self.pos = (0, -p % degree)
        elif count == 1 and self.has_markers():  # lines 8-13
            self.validate(e, sig)
        elif count == 0 and self.has_markers():  # lines 29-33: a new place, one marker there
            self.arrived(self.new_place(e, degree), sig)
            self.drop2("vertex", 1)
            self.count_of[len(self.exits) - 1] = 1
        else:  # lines 14-28, 34-37: phase II
            self.phase_two(e, sig)

    def validate(self, e, sig):
        """Lines 10-13 (Case 1b's search as Algorithm 6.1 lines 11-19 list it): one marker on e, back to v_k, and
        every vertex of S but v_k with an unexplored edge, v_u's degree and marks, visited in the preorder of a
        breadth-first tree of S rooted at v_k by shortest paths, each sensed on arrival, until one shows a marked
        edge S does not show."""
        vk, _ = e
        degree, _, marks = sig
        key = sorted(c for _, c in marks)
        self.drop2("edge", 1)
        self.step(0)
        self.pos, self.emarks[e] = e, 1
        chosen = {v for v, _ in self.U if v != vk and self.degree(v) == degree and self.shown(v) == key}
        _, tree, _ = self.search(vk)
        looked = set()
        for target in sorted(chosen, key=lambda v: [x for _, x in self.path(tree, vk, v)]):
            if target in looked:
                continue
            _, parent, _ = self.search(self.pos[0])
            got = None
            for v, x in self.path(parent, self.pos[0], target):
                got = self.step((x - self.pos[1]) % self.degree(v))
                self.pos = tuple(self.exits[v][x])
            v, entry = self.pos
            looked.add(v)
            extra = set(got[2]) - set(self.expect(v, entry)[2])
            if extra:  # lines 14-18: v_k' and e', the edge that shows the new marker
                if len(extra) != 1:
                    give_up("map vertex %d shows %d unexpected marks" % (v, len(extra)))
                (p, c), = extra
                found = (v, (entry + p) % degree)
                if c != 1 or found not in self.U:
                    give_up("map vertex %d's unexpected mark is not one loop marker on U" % v)
                self.join(e, found)
                self.emarks[found] = 1
                return
        give_up("no candidate shows the new marker")

    def hypotheses2(self, vk, sig):
        """Lines 15-16: H in U's order (known ends showing v_u's signature), each driven along a shortest path of S
        to v0, with P^E."""
        out = []
        for v, j in self.U:
            if v == vk or self.degree(v) != sig[0] or self.expect(v, j) != sig:
                continue
            _, parent, _ = self.search(v, {0})
            motions, expected, entry = [], [], j
            for x, t in self.path(parent, v, 0):
                motions.append((t - entry) % self.degree(x))
                w, entry = self.exits[x][t]
                expected.append(self.expect(w, entry))
            out.append({"dart": (v, j), "motions": motions, "expected": expected, "end": (w, entry)})
        return out

    def phase_two(self, e, sig):
        """Lines 17-28, 34-37.  Line 23 as printed confirms a hypothesis whose perceptions "do not match throughout",
        which line 21 has rejected already: so no hypothesis is ever confirmed, a full match is retraced as a
        mismatch is, and v_u always joins S as a new place (line 28), with the marks it showed."""
        degree = sig[0]
        heading = 0
        for h in self.hypotheses2(e[0], sig):
            done, degrees, matched = [], [degree], True
            for k, (motion, want) in enumerate(zip(h["motions"], h["expected"])):  # line 19
                physical = (motion - heading) % degree if k == 0 else motion
                got = self.step(physical)
                done.append(physical)
                degrees.append(got[0])
                if got != want:
                    matched = False
                    break  # lines 21-22: reject, continue
            if matched != LINE_23_AS_PRINTED:  # line 23: "case P and P^E do not match throughout -> confirm"
                self.join(e, h["dart"])
                self.pos = h["end"]
                return
            self.step(0)  # back to v_u
            for t in range(len(done) - 1, 0, -1):
                self.step(-done[t] % degrees[t])
            heading = (heading + done[0]) % degree
        self.arrived(self.new_place(e, degree, heading), sig)  # line 28 (line 23 confirmed nothing)

    def run(self):
        while self.U:  # line 3
            self.iterate()
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": self.marks2()},
                  "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        markers = [{"kind": "vertex", "at": names[v], "count": c} for v, c in sorted(self.count_of.items())]
        markers += [{"kind": "edge", "between": [names[v], names[self.exits[v][i][0]]], "count": c}
                    for (v, i), c in sorted(self.emarks.items())
                    if self.exits[v][i] and (v, i) < tuple(self.exits[v][i])]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": markers}})
        receive()

    def marks2(self):
        out = [{"vertex": v, "count": c} for v, c in sorted(self.count_of.items())]
        return out + [{"vertex": v, "exit": i, "count": c} for (v, i), c in sorted(self.emarks.items())
                      if self.exits[v][i] and (v, i) < tuple(self.exits[v][i])]


if __name__ == "__main__":
    (Version2 if "--version" in sys.argv[1:] and sys.argv[sys.argv.index("--version") + 1:][:1] == ["2"]
     else Explorer)().run()
