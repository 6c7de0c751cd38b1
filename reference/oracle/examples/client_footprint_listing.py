#!/usr/bin/env python3
"""The footprint searches of §6.2.1 as listed: Algorithm 6.1 (Case 2, m + n E-markers), Algorithm 6.3 (Case 4,
closest-first) and the text of Cases 1a and 1b; with ``--edgeinfo`` their §6.2.2 directional versions; with
``--case footprints`` §2.3.1's footprints model as written; speaking topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import), written from the listings and the text of
§6.2.1 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm case-2-listing -- python3 client_footprint_listing.py --case 2

``--case`` picks the algorithm (and the entry whose suite it plays): ``2`` Algorithm 6.1 (``case-2-listing``),
``4`` Algorithm 6.3 (``case-4-listing``), ``4-mn`` Case 4's closest-first extension of Case 2
(``case-4-mn-listing``), ``1a`` Case 1a's m E-markers (``case-1a-listing``), ``1b`` Case 1b's V-E-markers
(``case-1b-listing``), ``footprints`` (``footprints-listing``).  The markers are undirected (``--edgeinfo``:
directional); the kit is read from ``hello``.  Line by line (Algorithm 6.1;
Algorithm 6.3's numbers in brackets):

* line 1 [1]: S = {v0}, U = v0's exits in order (exit 0 the one faced).  Case 1b: "Initially the robot drops a
  marker at its starting vertex v0";
* line 3 [3]: e = (v_k, i) is the entry of U whose known end is closest to the robot (hops over S), ties by U's
  order.  Algorithm 6.3 requires it (rule 1); Algorithm 6.1 and Cases 1a/1b take "an unexplored edge", and
  the closest is the choice made for them too;
* line 4 [4]: the robot walks S to v_k by a shortest path (a breadth-first tree of S rooted where the robot
  stands, exits scanned in order) and follows e, sensing v_u with e unmarked ("excluding entry edge e");
* lines 5-8 [8-13]: v_u shows no marked edge (Case 1b: no V-marker): a new place, e its exit 0, its other exits
  clockwise appended to U.  Markers on e: two (Algorithm 6.1 line 7), one (Case 1a), none (Case 1b, which
  drops one at v_u "but not on the entry edge e"); Algorithm 6.3 lines 5-6: one if v_k had no marked edge when
  e was chosen, else none (the extension of Case 2: two, else none);
* lines 9-10 [14-17]: v_u shows marked edges (counts c_1 single, c_2 double; c in Cases 1a, 1b, 4): one marker
  is dropped on e and the robot goes back to v_k over e;
* lines 11-13 [18-19]: the candidates are the vertices of S other than v_k with an unexplored edge, v_u's degree
  and, as S shows them, v_u's marks (the multiset of marker counts on its marked edges); each is visited in
  turn by a shortest path of S from where the robot stands, and sensed only there, on arrival;
* lines 14-19 [20-24]: the candidate that shows a marked edge S does not show is v_k', that edge e'; S gets
  e/e' with one marker, e' leaves U, the search stops; the robot stands at v_k'.

Decisions where the listings are silent (each the one topomark's ``-listing`` entries make):

* the markers "during transit on e" (Algorithm 6.1 lines 7 and 10, Algorithm 6.3 lines 6 and 17) are dropped
  from v_u on its entry edge right after v_u is sensed: the same edge, no traversal, and the sensing excludes
  them.  So a loop edge of the extension of Case 2 carries one marker, as every loop edge does, even from an
  unmarked v_k; in Algorithm 6.3 one marker goes on e either way, as lines 6 and 17 together say;
* the candidates are visited in the preorder of a breadth-first tree of S rooted at v_k (children by the exit
  their parent reaches them by), v_k's known neighbours included (the listing excludes v_k only); a vertex
  the robot passes on its way to a candidate is not looked at;
* Case 1b's markers are one pool and the robot counts what it holds.  Out of markers (the thesis's extension
  to m markers) it still walks to v_k and follows e, and only then does without the drop: a new v_u must be a
  leaf with U empty (it stays unmarked); a known v_u must be the far end of the one entry left in U (S predicts
  what v_u showed there), joined with no search.  The thesis processes the last edge(s) "without further
  motion", but then the robot never crosses that edge, and nothing it sensed tells the world from one with a
  vertex added on that edge: the oracle fails such a map as a guess.  Any other drop it cannot make ends the
  run: it sends ``error`` (it gave up: the ``failed`` outcome), after following e, where the drop would be.

``--case footprints`` is §2.3.1's footprints model (Deng and Mirzaian, m + n homogeneous markers, Figure 2.4;
entry ``footprints-listing``), written from its text: a footprint at v0 and at each new vertex, one on every
edge; v_u "contains no marker" is a new place; otherwise one footprint on e, back to v_k, and "each (other)
known vertex in S which has the same degree as v_u" is a candidate, visited and checked as above (not filtered
by marks or an unexplored edge: the text names the degree only).  Its kit is one pool of m + n, never short.

``--edgeinfo`` is §6.2.2's improvement with directional markers (Figure 6.14; entries
``case-*-edgeinfo-listing``, every case but footprints): the same drops, each with a direction, and one more
filter on the candidates.  Decisions where §6.2.2 is silent (topomark's edgeINFO entries make the same):

* a V-marker points at the edge the robot entered by (v0: the exit it faces), so at map exit 0 everywhere;
* every E-marker's head is at v_u, where it is dropped: a non-loop e reads ``-H`` at the new vertex, ``-T``
  at v_k; a loop e reads ``-H`` at v_k' and ``-T`` at v_k;
* edgeINFO made exact: a candidate stays only if, from one of its unexplored exits j, S's marks read (heads,
  counts, ends, relative to j) exactly what the robot sensed on arriving at v_u, before the drop on e.  For
  Cases 2, 1a and 4, which drop no V-marker, the reading is anchored at the entry; the filter never excludes
  the true v_k' (S holds every marker in the world), and a single candidate left is still visited.

Map vertices are numbered 0, 1, ... and each vertex's exits clockwise from the edge it was first entered by
(v0: the exit it faced, the anchor @2's snapshots check).  After each iteration it sends a snapshot of (S, U).
"""
import argparse
import json
import re
import sys
from collections import deque

NON_LOOP = {"1a": 1, "1b": 0, "2": 2, "4": 1, "4-mn": 2, "footprints": 1}  # on a non-loop edge (4: unmarked v_k)
FOOTPRINTED = {"1b", "footprints"}  # the cases that drop a marker at every vertex (v0 first)


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def receive():
    msg = json.loads(sys.stdin.readline())
    if msg["type"] in ("error", "bye"):
        sys.exit(0 if msg.get("verdict") == "pass" else 1)
    return msg


def parse(sig):
    """'[4,V-1,E-0-H,E2-2]' -> (4, 1, {0: 1, 2: 2}, (1, ((0, 1, 'H'), (2, 2, None)))): degree, V-markers, marker
    count per marked exit (relative), and the whole reading (V-marker's head, (exit, count, end) per marked exit)."""
    items = sig.strip("[]").split(",")
    v = re.match(r"V(\d*)(?:-(\d+))?$", items[1])
    vertex, head = (int(v.group(1) or 1), v.group(2) and int(v.group(2))) if v else (0, None)
    marks, reading = {}, []
    for item in items[2:]:
        m = re.match(r"E(\d*)-(\d+)(?:-([HT]))?$", item)
        if m:
            marks[int(m.group(2))] = int(m.group(1) or 1)
            reading.append((int(m.group(2)), int(m.group(1) or 1), m.group(3)))
    return int(items[0]), vertex, marks, (head, tuple(sorted(reading)))


def give_up(message):
    send({"type": "error", "message": message})
    sys.exit(1)


class Explorer:
    def __init__(self, case, edgeinfo=False):
        self.case, self.edgeinfo = case, edgeinfo
        self.word = "directional-" if edgeinfo else "undirected-"
        hello = receive()
        kit = hello.get("kit", {})
        kinds = {self.word + k for k in ("edge", "vertex", "either")}
        if hello["protocol"] != "topomark/protocol@2" or not kit or not set(kit) <= kinds:
            send({"type": "error", "message": f"I speak topomark/protocol@2 with {self.word[:-1]} markers only"})
            sys.exit(2)
        self.kit = dict(kit)  # what the robot still holds, by kind
        self.ends = {}  # --edgeinfo: (v, i) -> "H"/"T", the end of the E-markers on exit i that lies at v
        degree, _, _, _ = parse(hello["signature"])
        self.exits = [[None] * degree]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(degree)]  # line 1
        self.marks = {}  # S's edge marks: (v, i) -> count, at both darts of an explored edge
        self.vmarks = []  # Case 1b: the vertices of S carrying a V-marker
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)
        if case in FOOTPRINTED:
            if not self.drop("vertex", 1, 0):  # "Initially the robot drops a marker at its starting vertex v0"
                give_up("no marker for v0")
            self.vmarks.append(0)

    # -- the robot ----------------------------------------------------------------------------------------
    def step(self, motion):
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def move(self, exit_):
        """Leave the current map vertex by its explored exit ``exit_``; the signature sensed there."""
        v, entry = self.pos
        sig = self.step((exit_ - entry) % len(self.exits[v]))
        self.pos = tuple(self.exits[v][exit_])
        return sig

    def drop(self, kind, count, head=None):
        """Drop ``count`` markers on the entry edge (``edge``) or here (``vertex``), the kind's own markers
        first, then the pool; False, nothing sent, if the robot does not hold that many.  --edgeinfo: pointing
        at ``head`` (a V-marker: the entry, 0; E-markers: "H", their head here)."""
        own, pool = self.kit.get(self.word + kind, 0), self.kit.get(self.word + "either", 0)
        if own + pool < count:
            return False
        taken = min(own, count)
        if own:
            self.kit[self.word + kind] = own - taken
        if count > taken:
            self.kit[self.word + "either"] = pool - (count - taken)
        op = {"type": "drop", "kind": kind, "count": count}
        if self.edgeinfo:
            op["direction"] = head
        if kind == "edge":
            op["exit"] = 0
        send(op)
        receive()
        return True

    # -- S ------------------------------------------------------------------------------------------------
    def bfs(self, root):
        """Breadth-first over explored edges from ``root``, exits in order: hops and the parent dart of each."""
        dist, parent, todo = {root: 0}, {}, deque([root])
        while todo:
            v = todo.popleft()
            for i, w_j in enumerate(self.exits[v]):
                if w_j and w_j[0] not in dist:
                    dist[w_j[0]], parent[w_j[0]] = dist[v] + 1, (v, i)
                    todo.append(w_j[0])
        return dist, parent

    @staticmethod
    def path(parent, root, target):
        """The darts of the tree ``parent`` (rooted at ``root``) from ``root`` to ``target``, in order."""
        darts = []
        while target != root:
            darts.append(parent[target])
            target = parent[target][0]
        return darts[::-1]

    def walk_to(self, target):
        """A shortest path of S from the robot to ``target``; the signature sensed on arrival."""
        _, parent = self.bfs(self.pos[0])
        sig = None
        for _, i in self.path(parent, self.pos[0], target):
            sig = self.move(i)
        return sig

    def shown(self, v):
        """v's marks as S shows them: the marker counts on its marked edges, sorted."""
        return sorted(self.marks[(v, i)] for i in range(len(self.exits[v])) if (v, i) in self.marks)

    def predicted(self, v, entry):
        """What S says a robot entering v by exit ``entry`` senses (Case 1b's extension; --edgeinfo's filter)."""
        d, here = len(self.exits[v]), [(i, c) for (x, i), c in self.marks.items() if x == v]
        head = (-entry) % d if self.edgeinfo and v in self.vmarks else None  # every V-marker points at exit 0
        reading = tuple(sorted(((i - entry) % d, c, self.ends.get((v, i))) for i, c in here))
        return d, int(v in self.vmarks), {(i - entry) % d: c for i, c in here}, (head, reading)

    def join(self, e, far):
        self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)

    # -- one iteration ------------------------------------------------------------------------------------
    def iterate(self):
        dist, parent = self.bfs(self.pos[0])
        e = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 3 [3]: the closest
        vk, i = e
        vk_marked = bool(self.shown(vk))  # Algorithm 6.3 line 5
        for _, x in self.path(parent, self.pos[0], vk):  # line 4 [4]
            self.move(x)
        sig = self.step((i - self.pos[1]) % len(self.exits[vk]))
        if (sig[1] == 0) if self.case in FOOTPRINTED else not sig[2]:
            self.new_place(e, sig[0], vk_marked)  # lines 5-8 [8-13]
        else:
            self.known_place(e, sig)  # lines 9-19 [14-24]

    def new_place(self, e, degree, vk_marked):
        """Non-loop augmentation: v_u joins S, e its exit 0; the markers on e (and Case 1b's at v_u)."""
        count = NON_LOOP[self.case]
        if self.case in ("4", "4-mn") and vk_marked:
            count = 0  # Algorithm 6.3 lines 5-6: "if v_k has marked edges, leave e blank"
        u = len(self.exits)
        if count:
            if not self.drop("edge", count, "H"):
                give_up("out of edge markers for a non-loop edge")
            self.marks[e], self.marks[(u, 0)] = count, count
            if self.edgeinfo:
                self.ends[e], self.ends[(u, 0)] = "T", "H"
        self.exits.append([list(e)] + [None] * (degree - 1))
        self.exits[e[0]][e[1]] = [u, 0]
        self.U += [(u, j) for j in range(1, degree)]
        self.pos = (u, 0)
        if self.case in FOOTPRINTED:
            if self.drop("vertex", 1, 0):
                self.vmarks.append(u)
            elif self.case == "footprints" or degree != 1 or self.U:  # Case 1b's extension: only the last vertex, a leaf, may stay blank
                give_up("out of markers with exploration not over")

    def known_place(self, e, sig):
        """Place and back-link validation by the footprint search (lines 9-19, Algorithm 6.3 lines 14-24)."""
        vk, i = e
        degree, _, marks, _ = sig
        if not self.drop("edge", 1, "H"):  # line 10 [17]: one marker on e
            if self.case == "1b" and len(self.U) == 1 and self.predicted(*self.U[0]) == sig:
                far = self.U.pop()  # Case 1b's extension: the one edge left is e', no further motion
                self.join(e, far)
                self.pos = far
                return
            give_up("out of edge markers for a loop edge")
        self.marks[e] = 1
        if self.edgeinfo:
            self.ends[e] = "T"
        self.step(0)  # line 10 [15]: back to v_k over e
        self.pos = e
        found = None
        for target in self.candidates(vk, degree, sorted(marks.values()), sig):  # lines 11-13 [18-19]
            got = self.walk_to(target)
            v, entry = self.pos
            extra = [(entry + p) % got[0] for p, c in got[2].items() if self.marks.get((v, (entry + p) % got[0])) != c]
            if extra:  # lines 14-18 [20-23]: v_k' and its unexpectedly marked edge e'
                found = (v, extra[0])
                if len(extra) != 1 or found not in self.U or found in self.marks:
                    give_up(f"map vertex {v} shows an unexpected mark that is not one loop marker on U")
                break  # line 19 [24]: exit for loop
        if found is None:
            give_up("no candidate shows the new marker")
        self.U.remove(found)
        self.join(e, found)
        self.marks[found] = 1
        if self.edgeinfo:
            self.ends[found] = "H"

    def candidates(self, vk, degree, key, sig):
        """Lines 11-12 [18]: the vertices of S but v_k with an unexplored edge, v_u's degree and v_u's marks as S
        shows them, in the preorder of a breadth-first tree of S rooted at v_k.  --edgeinfo (§6.2.2): only those
        with an unexplored entry j from which S reads what was sensed at v_u (edgeINFO)."""
        chosen = {v for v, _ in self.U if v != vk and len(self.exits[v]) == degree and self.shown(v) == key}
        if self.case == "footprints":  # §2.3.1: "each (other) known vertex in S which has the same degree as v_u"
            chosen = {v for v in range(len(self.exits)) if v != vk and len(self.exits[v]) == degree}
        if self.edgeinfo:
            chosen = {v for v, j in self.U if v in chosen and self.predicted(v, j)[3] == sig[3]}
        _, parent = self.bfs(vk)
        return sorted(chosen, key=lambda v: [x for _, x in self.path(parent, vk, v)])

    # -- the wire -----------------------------------------------------------------------------------------
    def edges(self):
        """Every marked explored edge once: (v, i, w, count)."""
        return [(v, i, self.exits[v][i][0], c) for (v, i), c in sorted(self.marks.items())
                if self.exits[v][i] and (v, i) < tuple(self.exits[v][i])]

    def run(self):
        while self.U:
            self.iterate()
            marks = [{"vertex": v, "exit": i, "count": c, "end": self.ends.get((v, i))} for v, i, _, c in self.edges()]
            marks += [{"vertex": v, "head": 0 if self.edgeinfo else None} for v in self.vmarks]
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": marks}, "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        markers = [{"kind": "edge", "between": [names[v], names[w]], "count": c} for v, _, w, c in self.edges()]
        markers += [{"kind": "vertex", "at": names[v]} for v in self.vmarks]
        if self.edgeinfo:  # the heads: an E-marker's at the end that reads "H", a V-marker's at exit 0
            for marker, (v, i, w, _) in zip(markers, self.edges()):
                marker["head"] = names[v] if self.ends[(v, i)] == "H" else names[w]
            for marker, v in zip(markers[len(self.edges()):], self.vmarks):
                marker["points_to"] = names[self.exits[v][0][0]]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": markers}})
        receive()


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="§6.2.1's footprint searches as listed (topomark/protocol@2)")
    parser.add_argument("--case", choices=sorted(NON_LOOP), default="2")
    parser.add_argument("--edgeinfo", action="store_true", help="§6.2.2's directional markers (case-*-edgeinfo-listing)")
    args = parser.parse_args()
    Explorer(args.case, args.edgeinfo).run()
