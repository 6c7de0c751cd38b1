#!/usr/bin/env python3
"""Dudek et al.'s single movable marker algorithm as the thesis describes it (§2.3.1, Figure 2.2), with an
undirected marker or, given a directional one, the directional variant [27] (§2.3.1, §6.3.1), speaking
topomark/protocol@2.

Standalone on purpose (standard library only, no topomark import): it is written from §2.3.1's text, not
from topomark's explorer, so that the conformance suites can be checked against an independent reading.
Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD --kit '{"undirected-vertex": 1, "movable": true}' -- python3 client_dudek_listing.py
    topomark conformance run SUITE --algorithm dudek-listing -- python3 client_dudek_listing.py
    topomark conformance run SUITE --algorithm dudek-directional-listing -- python3 client_dudek_listing.py

The description, sentence by sentence:

* "selecting (and removing) an unexplored edge e = (v_k, v_u) from U, and having the robot travel to the
  unknown end v_u" — the nearest entry of U (the first in U's order among those whose end is nearest the
  robot), reached by a shortest path of S;
* "placing the marker at v_u and then visiting known vertices in S, looking for the marker" — the robot
  drops the marker (a directional one pointing back along e), comes back over e, and visits every known
  vertex: depth first over a breadth-first tree of S rooted at v_k, each by a shortest path, looking at
  every vertex it enters; it stops where it sees the marker;
* "If the marker is not found ... v_u is added to S" — the robot walks back to v_k, follows e again and
  picks the marker up; v_u joins S, e its exit 0, its other exits (clockwise) joining U;
* "if the marker is found at some vertex v_k' ... the robot drops the marker at v_k and goes back to v_k'
  along the shortest known path in S.  At v_k', the robot traverses each of the (unexplored) incident
  edges at v_k', looking for the marker" — it picks the marker up at v_k', carries it to v_k, comes back
  and tries v_k''s unexplored exits in clockwise order, coming back over each that does not lead to the
  marker; the one that does is e' (the robot is at v_k, entered by e, and picks the marker up there).
  With a directional marker the marker's direction names e' where it is found, and it is picked up there.

The search is made at every step and the back-link search at every loop step, as the text says, even
where only one known vertex, or one unexplored exit, is left.  The world is a simple graph (§2.3.1:
"Redundant or self-referential edges are prohibited").
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
    """'[3,A,A]' -> (3, None); '[3,V,A]' -> (3, 0); '[3,V-2,A]' -> (3, 2): the degree, and the marker here
    (None: none; else the exit it points at, counted from the entry edge, 0 for an undirected one)."""
    items = sig.strip("[]").split(",")
    if items[1] == "A":
        return int(items[0]), None
    _, _, direction = items[1].partition("-")
    return int(items[0]), int(direction) if direction else 0


class Explorer:
    def __init__(self):
        hello = receive()
        kit = hello.get("kit", {})
        self.directional = kit.get("directional-vertex", 0) >= 1
        if hello["protocol"] != "topomark/protocol@2" or not kit.get("movable") or \
                not (self.directional or kit.get("undirected-vertex", 0) >= 1):
            send({"type": "error", "message": "I need topomark/protocol@2 and one movable vertex marker"})
            sys.exit(2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, the exit it was entered by)

    # -- moving and marking ------------------------------------------------------------
    def operate(self, op):
        msg = {"type": op, "kind": "vertex"}
        if op == "drop" and self.directional:
            msg["direction"] = 0  # toward the edge the robot came by
        send(msg)
        receive()

    def turn_and_go(self, exit_):
        """Leave the current vertex by its exit ``exit_``; the signature sensed where the robot arrives."""
        v, entry = self.pos
        send({"type": "move", "motion": (exit_ - entry) % len(self.exits[v])})
        return parse(receive()["value"])

    def back(self):
        """Straight back the way the robot came (motion 0)."""
        send({"type": "move", "motion": 0})
        receive()

    def go(self, exit_):
        """Along an explored exit: the robot knows where it arrives."""
        sig = self.turn_and_go(exit_)
        self.pos = tuple(self.exits[self.pos[0]][exit_])
        return sig

    def parents(self, root):
        """Breadth-first search of S from ``root``, exits in clockwise order: vertex -> (parent, exit), and
        the vertices in the order met."""
        parent, order, todo = {root: None}, [root], deque([root])
        while todo:
            v = todo.popleft()
            for i, w_j in enumerate(self.exits[v]):
                if w_j and w_j[0] not in parent:
                    parent[w_j[0]] = (v, i)
                    order.append(w_j[0])
                    todo.append(w_j[0])
        return parent, order

    def path_to(self, target):
        """The exits of a shortest path of S from where the robot stands to ``target``."""
        parent, _ = self.parents(self.pos[0])
        path, v = [], target
        while parent[v] is not None:
            v, i = parent[v]
            path.append(i)
        return path[::-1]

    def walk_to(self, target):
        for i in self.path_to(target):
            self.go(i)

    # -- the description ------------------------------------------------------------------
    def known_vertices(self, vk):
        """Every known vertex but v_k, depth first over a breadth-first tree of S rooted at v_k (children in
        the order of the exits that reach them)."""
        parent, _ = self.parents(vk)
        children = {}
        for child, up in sorted(((c, p) for c, p in parent.items() if p is not None), key=lambda cp: cp[1][1]):
            children.setdefault(up[0], []).append(child)
        order, stack = [], [vk]
        while stack:
            v = stack.pop()
            order.append(v)
            stack.extend(reversed(children.get(v, [])))
        return order[1:]

    def search(self, vk):
        """"visiting known vertices in S, looking for the marker": (where it lies, the direction it points in,
        counted from the robot's entry), or None."""
        seen = set()
        for target in self.known_vertices(vk):
            if target in seen:
                continue
            for i in self.path_to(target):
                marker = self.go(i)[1]
                if marker is not None:
                    return self.pos[0], marker
                seen.add(self.pos[0])
        return None

    def back_link(self, vk, i, x, direction):
        """The exit e' of v_k' = x (where the robot stands, the marker found) that e leads to."""
        self.operate("pick_up")
        if self.directional:
            return (self.pos[1] + direction) % len(self.exits[x])
        self.walk_to(vk)
        self.operate("drop")
        self.walk_to(x)
        for j in sorted(j for v, j in self.U if v == x):
            if self.turn_and_go(j)[1] is not None:  # the marker: the robot is at v_k, entered by e
                self.pos = (vk, i)
                self.operate("pick_up")
                return j
            self.back()  # not this one: straight back to x
            self.pos = (x, j)
        send({"type": "error", "message": "back-link validation found no marker (not a simple graph?)"})
        sys.exit(1)

    def iterate(self):
        parent, order = self.parents(self.pos[0])
        depth = {}
        for v in order:
            depth[v] = 0 if parent[v] is None else depth[parent[v][0]] + 1
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: (depth[self.U[k][0]], k)))  # nearest, first in U
        self.walk_to(vk)
        degree, _ = self.turn_and_go(i)
        self.operate("drop")  # "placing the marker at v_u"
        self.back()  # over e to v_k
        self.pos = (vk, i)
        found = self.search(vk)
        if found is not None:  # loop augmentation: e/e' = (v_k, v_k')
            x, direction = found
            j = self.back_link(vk, i, x, direction)
            self.U.remove((x, j))
            self.exits[vk][i], self.exits[x][j] = [x, j], [vk, i]
            return
        self.walk_to(vk)  # not found: fetch the marker from v_u, which is new
        self.turn_and_go(i)
        self.operate("pick_up")
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
