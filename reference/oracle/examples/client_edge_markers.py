#!/usr/bin/env python3
"""A minimal explorer speaking topomark/protocol@2 with m undirected immovable edge markers: thesis §6.2.1
Case 1a, the E-marker algorithm (Figure 6.4; the footprints model of [18]).

Standalone on purpose (standard library only, no topomark import): copy it and
change it.  Run it under topomark, which plays the world and judges the map;
the kit is one marker per edge of the world (M = m):

    topomark run-external WORLD --kit '{"undirected-edge": M}' -- python3 client_edge_markers.py

The robot keeps a map S of the explored part and the set U of unexplored
darts (v, i): exit i of map vertex v.  Each step takes the nearest e = (v_k, i)
from U, walks S to v_k, follows e to the unknown end v_u and drops one marker
on e there (on its entry edge, once v_u's signature is sensed), so every
explored edge carries one marker and nothing else does.

* No other edge of v_u marked: v_u was never visited (every visited vertex has
  a marked edge: the one it was found by, or at v0 the first edge explored,
  §6.2.1 Case 1a).  It joins S with e as its exit 0.
* c other edges marked: v_u is known.  The robot goes back over e to v_k and
  visits the known vertices with v_u's degree, an unexplored exit and c
  explored (marked) edges, "looking for the vertex which has one more marked
  edge than is shown on the map" (§6.2.1 Case 1a): that vertex is v_k', the unexpected
  marked edge is e'.

The world is a simple graph, as the map file's edge markers (``between``)
assume; so v_u is neither v_k nor a neighbour of v_k in S, and those are not
searched.  The robot uses exactly m markers (one per edge) and counts them: it
stops with an error rather than ask for one more than the kit holds.  Map
vertex 0 is where the robot started, its exit 0 the exit it faced (the anchor
@2's snapshots check); every other vertex numbers its exits clockwise from the
edge it was found by.
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
    """'[4,A,E-0,E-2]' -> (4, {0, 2}): the degree and the marked exits, counted clockwise from the entry edge."""
    items = sig.strip("[]").split(",")
    return int(items[0]), {int(item.split("-")[1]) for item in items[2:] if item.startswith("E")}


class Explorer:
    def __init__(self):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or hello["kit"].get("undirected-edge", 0) < 1:
            send({"type": "error", "message": "I need topomark/protocol@2 and undirected edge markers"})
            sys.exit(2)
        self.markers = hello["kit"]["undirected-edge"]  # the budget: one per edge of the world
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)

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

    def drop_on_entry(self):
        """Drop one marker on the edge the robot just came by (relative exit 0)."""
        if self.markers == 0:
            send({"type": "error", "message": "out of edge markers: the kit holds fewer than the world's edges"})
            sys.exit(1)
        self.markers -= 1
        send({"type": "drop", "kind": "edge", "exit": 0, "count": 1})
        receive()

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

    def walk_to(self, target):
        toward = self.tree(target)
        while self.pos[0] != target:
            self.move(toward[self.pos[0]])

    def unexpected(self, sig):
        """The exit of the current vertex marked in the world but unexplored in S (e'), or None."""
        v, entry = self.pos
        marked = {(entry + p) % sig[0] for p in sig[1]}
        extra = [j for j in marked if self.exits[v][j] is None]
        return extra[0] if extra else None

    def search(self, vk, degree, c):
        """Place and back-link validation at once (§6.2.1 Case 1a): the dart e' = (v_k', j) that e leads to."""
        near = {vk} | {w_j[0] for w_j in self.exits[vk] if w_j}
        for v in self.tree(vk):  # nearest first
            explored = sum(1 for w_j in self.exits[v] if w_j)
            if v not in near and len(self.exits[v]) == degree and explored == c and explored < degree:
                toward = self.tree(v)
                while self.pos[0] != v:
                    sig = self.move(toward[self.pos[0]])
                    j = self.unexpected(sig)
                    if j is not None and self.pos[0] != vk:  # (v_k's own new mark is e's near end)
                        return self.pos[0], j  # seen here, maybe on the way: the search stops
        send({"type": "error", "message": "no known vertex shows the new marker (not a simple graph?)"})
        sys.exit(1)

    def iterate(self):
        order = {v: k for k, v in enumerate(self.tree(self.pos[0]))}  # BFS order from the robot
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: order[self.U[k][0]]))  # the nearest e
        self.walk_to(vk)
        degree, marked = self.step((i - self.pos[1]) % len(self.exits[vk]))
        self.drop_on_entry()
        if marked:  # c = len(marked) other edges marked: v_u is known
            self.step(0)  # back over e to v_k
            self.pos = (vk, i)
            x, j = self.search(vk, degree, len(marked))
            self.U.remove((x, j))  # loop augmentation: e/e' = (v_k, v_k')
            self.exits[vk][i], self.exits[x][j] = [x, j], [vk, i]
            return
        u = len(self.exits)  # non-loop augmentation: v_u joins S, e its exit 0
        self.exits.append([[vk, i]] + [None] * (degree - 1))
        self.exits[vk][i] = [u, 0]
        self.U += [(u, j) for j in range(1, degree)]
        self.pos = (u, 0)

    def edges(self):
        """Every explored edge once, as (v, i, w): each carries one marker."""
        return [(v, i, w_j[0]) for v, row in enumerate(self.exits) for i, w_j in enumerate(row)
                if w_j and (v, i) < tuple(w_j)]

    def run(self):
        while self.U:
            self.iterate()
            marks = [{"vertex": v, "exit": i, "count": 1} for v, i, _ in self.edges()]
            send({"type": "snapshot", "S": {"exits": self.exits, "marks": marks}, "U": [list(d) for d in self.U]})
        names = ["s%d" % v for v in range(len(self.exits))]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": [{"kind": "edge", "between": [names[v], names[w]], "count": 1} for v, _, w in self.edges()]}})
        receive()


if __name__ == "__main__":
    Explorer().run()
