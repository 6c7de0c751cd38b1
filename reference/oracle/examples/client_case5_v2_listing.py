#!/usr/bin/env python3
"""Algorithm 6.5 of the thesis as listed (§6.2.1 Case 5, Version-2, undirected V-E-markers), speaking
topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import): it builds on ``client_case5_listing.py``,
Algorithm 6.4 as listed, which must lie beside it; both are written from the listings and the text of §6.2.1
Case 5 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm case-5-v2-listing -- python3 client_case5_v2_listing.py

It follows Algorithm 6.5 (Version-2, undirected V-E-markers, ``case-5-v2-listing``), line by line:

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

The map's numbering and snapshots are Algorithm 6.4's client's.
"""
import re
import sys

from client_case5_listing import Explorer, receive, send  # type: ignore[import-not-found]  # the script beside it

LINE_23_AS_PRINTED = True  # Algorithm 6.5 line 23 confirms on "do not match throughout", after line 21 rejected it


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
    """Algorithm 6.5 as listed : Case 1b's footprint search with a double-marked v0 and e0 while the
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
            matched, done, degrees = self.execute(h, degree, heading)  # lines 19-22: a mismatch rejects
            if matched != LINE_23_AS_PRINTED:  # line 23: "case P and P^E do not match throughout -> confirm"
                self.join(e, h["dart"])
                self.pos = h["end"]
                return
            heading = self.retrace(done, degrees, heading, degree)
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
    Version2().run()
