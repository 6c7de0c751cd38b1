#!/usr/bin/env python3
"""Algorithm 6.6 of the thesis as listed (§6.2.2, extension-2 of Case 3b, Figure 6.16), speaking
topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import), written from the listing of Algorithm 6.6
and the text of §6.2.2 alone.  Run it under topomark, which plays the world and judges the map:

    topomark conformance run SUITE --algorithm extension-2-listing -- python3 client_ext_listing.py

The robot carries directional edge markers (Σ_{k=1}^{⌈(n−1)/2⌉} k of them).  The listing, line by line:

* lines 1-2: S is v0 alone, U its exits; the next count i is 1;
* line 4: the unexplored edge e = (v_k, i) of U whose known end is closest to the robot (hops over S),
  ties by U's order (U lists v0's exits, then each new place's exits clockwise from its entry);
* line 5: whether v_k has a marked edge is read from S (the robot made every mark itself);
* line 6: the robot walks a shortest path of S to v_k (one breadth-first tree rooted at v_k, exits in order)
  and follows e;
* lines 8-13: v_u shows no marked edge: a new place, e its exit 0; if v_k has no marked edge the robot goes
  back on e, drops i markers on e with the tail at v_k (the head at v_u: the listing does not say which; the
  choice is free, an identification only needs the count and the end), and comes back (two traversals);
* lines 14-18: v_u shows marked edges: one of them, its count and end, names a dart of S; its exit relative to
  the entry names e' = (v_k', j) (line 16); loop augmentation e/e';
* lines 19-20: if v_k has no marked edge the robot goes back over e to v_k, *whether or not* v_k has an
  unexplored edge left (the listing's line; §6.2.2's text adds "unless v_k has no unexplored edges now",
  which topomark's ``extension-2`` follows and this listing does not).

Map vertices are numbered 0, 1, ... and each vertex's exits clockwise from the edge it was first entered by
(v0: the exit it faced).  After each iteration it sends a snapshot of (S, U).
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
    """'[3,A,E2-1-H]' -> (3, [(1, 2, 'H')]): the degree and the edge marks (relative exit, count, end)."""
    items = sig.strip("[]").split(",")
    marks = []
    for item in items[2:]:
        m = re.match(r"E(\d*)-(\d+)(?:-([HT]))?$", item)
        if m:
            marks.append((int(m.group(2)), int(m.group(1) or 1), m.group(3)))
    return int(items[0]), marks


class Explorer:
    def __init__(self):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or set(hello.get("kit", {})) != {"directional-edge"}:
            send({"type": "error", "message": "I speak topomark/protocol@2 with directional edge markers only"})
            sys.exit(2)
        self.markers = hello["kit"]["directional-edge"]
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]  # line 1
        self.count = 1  # line 2: i
        self.ends = {}  # count -> ((v_k, exit) its tail, (v_u, exit) its head)
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)

    def step(self, motion):
        send({"type": "move", "motion": motion})
        return parse(receive()["value"])

    def move(self, exit_):
        v, entry = self.pos
        self.step((exit_ - entry) % len(self.exits[v]))
        self.pos = tuple(self.exits[v][exit_])

    def tree(self, root):
        """Breadth-first over explored edges: hops from ``root`` and the exit one step toward it."""
        toward, dist, todo = {root: None}, {root: 0}, deque([root])
        while todo:
            v = todo.popleft()
            for w_j in self.exits[v]:
                if w_j and w_j[0] not in toward:
                    toward[w_j[0]], dist[w_j[0]] = w_j[1], dist[v] + 1
                    todo.append(w_j[0])
        return toward, dist

    def marked(self, v):
        """Line 5 (and 9, 19): whether map vertex v has a marked edge, read from S."""
        return any(v in (tail[0], head[0]) for tail, head in self.ends.values())

    def drop(self):
        """Line 10's drop: i markers on the entry edge (relative exit 0), the tail here."""
        if self.markers < self.count:
            send({"type": "error", "message": "out of edge markers"})
            sys.exit(1)
        self.markers -= self.count
        send({"type": "drop", "kind": "edge", "exit": 0, "direction": "T", "count": self.count})
        receive()

    def identify(self, degree, marks):
        """Lines 15-16: the dart e' = (v_k', j) that a sensed mark (exit p, count, end) names."""
        p, count, end = marks[0]
        tail, head = self.ends[count]
        x, t = head if end == "H" else tail
        return x, (t - p) % len(self.exits[x])

    def iterate(self):
        _, dist = self.tree(self.pos[0])
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: dist[self.U[k][0]]))  # line 4
        was_marked = self.marked(vk)  # line 5
        toward, _ = self.tree(vk)
        while self.pos[0] != vk:  # line 6
            self.move(toward[self.pos[0]])
        degree, marks = self.step((i - self.pos[1]) % len(self.exits[vk]))  # line 7
        if not marks:  # lines 8-13: a new place, e its exit 0
            u = len(self.exits)
            self.exits.append([[vk, i]] + [None] * (degree - 1))
            self.exits[vk][i] = [u, 0]
            self.U += [(u, j) for j in range(1, degree)]
            self.pos = (u, 0)
            if not was_marked:  # lines 9-11: back on e, drop i markers on e, and back
                self.step(0)
                self.drop()
                self.ends[self.count] = ((vk, i), (u, 0))
                self.count += 1
                self.step(0)
            return
        x, j = self.identify(degree, marks)  # lines 15-16
        self.U.remove((x, j))  # line 18
        self.exits[vk][i], self.exits[x][j] = [x, j], [vk, i]  # line 17: loop augmentation
        self.pos = (x, j)
        if not was_marked:  # lines 19-20: back to v_k
            self.step(0)
            self.pos = (vk, i)

    def run(self):
        while self.U:
            self.iterate()
            marks = [{"vertex": t[0], "exit": t[1], "count": c, "end": "T"} for c, (t, h) in self.ends.items()]
            marks += [{"vertex": h[0], "exit": h[1], "count": c, "end": "H"} for c, (t, h) in self.ends.items()]
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": marks}, "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": [{"kind": "edge", "between": [names[t[0]], names[h[0]]], "count": c, "head": names[h[0]]}
                        for c, (t, h) in self.ends.items()]}})
        receive()


if __name__ == "__main__":
    Explorer().run()
