#!/usr/bin/env python3
"""Dudek et al.'s single movable marker exploration (thesis §2.3.1) as a
topomark/protocol@2 explorer.  Standard library only; written from
spec/protocol.md, spec/*.schema.json and the thesis alone.

Map S: vertex v has deg[v] exits numbered clockwise; vertex 0 is the start
and its exit 0 the exit faced in hello (the @2 anchor convention).  A new
vertex's exit 0 is the edge the robot entered it by.

One iteration (thesis §2.3.1):
  take an unexplored dart e = (vk, i) from U, walk S to vk, traverse e to the
  unknown end vu, drop the marker there, come back along e and visit the
  vertices of S that could be vu, looking for the marker.
  * not found: vu is new; go back to vu, pick the marker up, add vu and e.
  * found at vk': pick it up, carry it to vk and drop it, return to vk' and
    try the unexplored exits of vk' until one leads to the marker (back-link
    validation); pick the marker up there; add e = (vk, i)-(vk', j).
Pruning (does not change the answer): only vertices of S with vu's degree
and at least one unexplored exit, other than vk and vk's explored
neighbours, can be vu (no loops, no multiple edges); if there is none, vu is
new without a search; if vk' has one unexplored exit, it is e'.
"""
import json
import sys
from collections import deque

def log(*a):
    print(*a, file=sys.stderr, flush=True)


class Session:
    def __init__(self):
        self.inp = sys.stdin
        self.out = sys.stdout
        self.ops = 0

    def send(self, obj):
        self.out.write(json.dumps(obj, separators=(",", ":")) + "\n")
        self.out.flush()

    def recv(self):
        line = self.inp.readline()
        if not line:
            log("world closed the pipe")
            sys.exit(1)
        msg = json.loads(line)
        if msg.get("type") in ("error", "bye"):
            log("world ended the session:", msg)
            sys.exit(0 if msg.get("verdict") == "pass" else 1)
        return msg

    def ask(self, obj):
        """Send a move/drop/pick_up and return the signature answering it."""
        self.send(obj)
        msg = self.recv()
        if msg.get("type") != "signature":
            log("expected a signature, got", msg)
            sys.exit(1)
        return parse_signature(msg["value"])


def parse_signature(value):
    """Return (degree, vertex_marker_present)."""
    s = value.strip()
    if not (s.startswith("[") and s.endswith("]")):
        raise ValueError("bad signature %r" % value)
    items = [x.strip() for x in s[1:-1].split(",")]
    degree = int(items[0])
    return degree, items[1].startswith("V")


class Explorer:
    def __init__(self, sess, hello):
        self.sess = sess
        kit = hello.get("kit", {})
        if kit.get("undirected-vertex", 0) >= 1:
            self.drop_msg = {"type": "drop", "kind": "vertex"}
        elif kit.get("directional-vertex", 0) >= 1:
            # a directional marker works as an undirected one; point at the entry edge
            self.drop_msg = {"type": "drop", "kind": "vertex", "direction": 0}
        else:
            raise SystemExit(self.refuse("kit %s has no vertex marker" % json.dumps(kit)))
        if not kit.get("movable"):
            raise SystemExit(self.refuse("kit %s is not movable" % json.dumps(kit)))
        d, _ = parse_signature(hello["signature"])
        self.exits = [[None] * d]      # exits[v][i] = (w, j) or None
        self.pos = 0                   # map vertex the robot is at
        self.entry = 0                 # map exit of pos the robot faces (its entry edge)
        self.marker_at = None          # map vertex holding the marker, None = in hand
        self.iteration = 0

    def refuse(self, why):
        self.sess.send({"type": "error", "message": "dudek client: " + why})
        log(why)
        return 1

    # ---------------------------------------------------------------- moves
    def deg(self, v):
        return len(self.exits[v])

    def move_exit(self, x):
        """Leave pos by map exit x; returns (degree, marker) sensed."""
        motion = (x - self.entry) % self.deg(self.pos)
        sig = self.sess.ask({"type": "move", "motion": motion})
        dest = self.exits[self.pos][x]
        if dest is not None:
            w, j = dest
            self.pos, self.entry = w, j
            if sig[0] != self.deg(w):
                log("degree mismatch at map vertex", w, sig)
        else:
            self.pos, self.entry = None, None   # off the map
        return sig

    def back(self, v, x):
        """Off the map after leaving v by exit x: take motion 0 back to v."""
        self.sess.ask({"type": "move", "motion": 0})
        self.pos, self.entry = v, x

    def drop(self):
        if self.marker_at is not None:
            raise RuntimeError("marker already down")
        sig = self.sess.ask(dict(self.drop_msg))
        self.marker_at = self.pos if self.pos is not None else -1
        return sig

    def pick_up(self):
        sig = self.sess.ask({"type": "pick_up", "kind": "vertex"})
        self.marker_at = None
        return sig

    def path(self, src, dst):
        """Shortest list of map exits leading from src to dst over explored edges."""
        if src == dst:
            return []
        prev = {src: None}
        q = deque([src])
        while q:
            v = q.popleft()
            for i, d in enumerate(self.exits[v]):
                if d is not None and d[0] not in prev:
                    prev[d[0]] = (v, i)
                    if d[0] == dst:
                        q.clear()
                        break
                    q.append(d[0])
        out = []
        v = dst
        while prev[v] is not None:
            u, i = prev[v]
            out.append(i)
            v = u
        return out[::-1]

    def dist_all(self, src):
        dist = {src: 0}
        q = deque([src])
        while q:
            v = q.popleft()
            for d in self.exits[v]:
                if d is not None and d[0] not in dist:
                    dist[d[0]] = dist[v] + 1
                    q.append(d[0])
        return dist

    def walk_to(self, dst):
        for x in self.path(self.pos, dst):
            self.move_exit(x)
        assert self.pos == dst

    # ---------------------------------------------------------------- state
    def unexplored(self):
        return [[v, i] for v in range(len(self.exits))
                for i, d in enumerate(self.exits[v]) if d is None]

    def snapshot(self):
        U = self.unexplored()
        marks = [] if self.marker_at is None else [{"vertex": self.marker_at}]
        self.sess.send({"type": "snapshot", "iteration": self.iteration,
                        "S": {"exits": [[None if d is None else [d[0], d[1]] for d in ex]
                                        for ex in self.exits],
                              "marks": marks},
                        "U": U})

    def join(self, v, i, w, j):
        self.exits[v][i] = (w, j)
        self.exits[w][j] = (v, i)

    # ---------------------------------------------------------------- algorithm
    def choose(self):
        dist = self.dist_all(self.pos)
        best = None
        for v, i in self.unexplored():
            key = (dist[v], v, i)
            if best is None or key < best:
                best = key
        return best[1], best[2]

    def iterate(self, vk, i):
        self.walk_to(vk)
        d, _ = self.move_exit(i)          # at vu, entered by its relative exit 0
        cands = [w for w in range(len(self.exits))
                 if w != vk and self.deg(w) == d and None in self.exits[w]
                 and all(e is None or e[0] != w for e in self.exits[vk])]
        if not cands:
            self.add_vertex(vk, i, d)
            return
        self.drop()                        # the marker lies at vu
        self.back(vk, i)
        found = None
        todo = set(cands)
        while todo and found is None:
            dist = self.dist_all(self.pos)
            w = min(todo, key=lambda u: (dist[u], u))
            for x in self.path(self.pos, w):
                _, marker = self.move_exit(x)
                if self.pos in todo:       # a candidate is checked whenever visited
                    todo.discard(self.pos)
                    if marker:
                        found = self.pos
                        break
        if found is None:
            # vu is new: back to vk, out by e, pick the marker up
            self.walk_to(vk)
            self.move_exit(i)
            self.pick_up()
            self.add_vertex(vk, i, d)
            return
        # the loop closes at vk' = found: which exit of vk' is e'?
        vkp = found
        self.pick_up()
        free = [j for j, e in enumerate(self.exits[vkp]) if e is None]
        if len(free) == 1:
            self.join(vk, i, vkp, free[0])
            return
        self.walk_to(vk)
        self.drop()
        self.walk_to(vkp)
        for j in free:
            _, marker = self.move_exit(j)
            if marker:
                self.pick_up()
                self.join(vk, i, vkp, j)
                self.pos, self.entry = vk, i
                return
            self.back(vkp, j)
        raise RuntimeError("back-link validation found no exit of %d leading to %d" % (vkp, vk))

    def add_vertex(self, vk, i, d):
        vu = len(self.exits)
        self.exits.append([None] * d)
        self.join(vk, i, vu, 0)
        self.pos, self.entry = vu, 0

    def run(self):
        self.snapshot()
        while True:
            U = self.unexplored()
            if not U:
                break
            vk, i = self.choose()
            self.iterate(vk, i)
            self.iteration += 1
            self.snapshot()
        self.send_map()

    def send_map(self):
        names = ["s%d" % v for v in range(len(self.exits))]
        rot = {}
        for v, ex in enumerate(self.exits):
            lst = [names[w] for (w, j) in ex]
            rot[names[v]] = lst
        world = {"format": "topomark/world@1", "rotation": rot}
        if self.marker_at is not None:
            world["markers"] = [{"kind": "vertex", "at": names[self.marker_at]}]
        self.sess.send({"type": "map", "world": world})
        self.sess.recv()   # bye (recv exits on it)


def main():
    sess = Session()
    hello = sess.recv()
    if hello.get("type") != "hello" or hello.get("protocol") != "topomark/protocol@2":
        sess.send({"type": "error", "message": "dudek client speaks topomark/protocol@2 only"})
        return 1
    ex = Explorer(sess, hello)
    ex.run()
    return 0


if __name__ == "__main__":
    sys.exit(main())
