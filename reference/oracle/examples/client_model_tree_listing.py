#!/usr/bin/env python3
"""Algorithm 5.1 of the thesis as listed, "Mapping with no markers, world model processing process" (§5.2.2),
speaking topomark/protocol@2 with an empty kit.

Standalone on purpose (standard library only, no topomark import), written from the listing of Algorithm 5.1 and
the text of §5.2.2 and §5.3 alone.  topomark plays the world and judges the map through its Python API (the
``run-external`` command asks for a kit of at least one marker or a thread):

    from topomark.spec.kit import Kit
    from topomark.reference.oracle.run_external import run_external
    run_external(world, ["python3", "client_model_tree_listing.py", "--cue-n", "4"], version=2, kit=Kit())

The map is judged as any map is: on a tree world what the robot sensed determines it, but on a world with a
cycle the oracle fails a right map as a ``guess`` (a two-fold cover of the world senses the same degrees on
every walk; the vertex count the client was told is no part of the protocol), so compare its cost with
``topomark explore WORLD --algorithm model-tree-listing`` given the same options.

The robot carries nothing and senses degrees only.  It keeps a traversal map TM (a tree: every edge it explores
is a new place in TM) and a level of world models, each a partial map with the robot's believed pose (map
vertex, entry exit).  Each step is one pass of the listing:

1. based on BFS, the robot walks TM to a known vertex v_k (motions M) and traverses an unexplored exit e of it;
2. TM is augmented non-loop with e and v_u (always);
3-4. every world model of the previous step's level, in order, is processed:
5-7. walked virtually along M, a degree that differs from the one sensed voids it;
8-14. if e is explored in M: the degree at its other end differs: void M; else pass M (a child with the same
   map and the new pose);
15-17. else each loop-closing hypothesis e' = (v_k', i') is formed: every unexplored exit of M whose vertex
   has v_u's degree;
18-23. for each known vertex v_l of M' (M with e joined to e') the robot computes a path from v_k' to v_l and
   executes it; a degree it senses that M' does not predict rejects the hypothesis;

Lines 24–33 of the listing and every decision where it is silent: client_model_tree_listing.md, beside this file.
"""
import json
import sys
from collections import deque

OPTIONS = {"--signatures": "global", "--entry-check": "yes", "--window": 100, "--max-models": 10000,
           "--max-steps": 2000, "--cue-n": None, "--cue-m": None, "--cue-diameter": None, "--cue-planar": "no"}


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def receive():
    msg = json.loads(sys.stdin.readline())
    if msg["type"] in ("error", "bye"):
        sys.exit(0 if msg.get("verdict") == "pass" else 1)
    return msg


def degree_of(sig):
    """'[3,A,A]' -> 3: the robot carries no marker, so a signature is its degree."""
    return int(sig[1:sig.index(",")])


class Stop(Exception):
    """The run ends without a map (a cap, or every model voided)."""


class Model:
    """A partial map: rows[v][i] = (w, j) when exit i of v is joined to exit j of w, None while unexplored.
    Never changed once made: a pass child shares its parent's Model, an augmented child is a new one."""

    def __init__(self, rows, edges, unexplored):
        self.rows, self.edges, self.unexplored = rows, edges, unexplored

    def degree(self, v):
        return len(self.rows[v])

    def complete(self):
        return self.unexplored == 0

    def joined(self, a, b):
        """Loop augmentation: the unexplored exits a and b joined by an edge."""
        rows = list(self.rows)
        for (v, i), far in ((a, b), (b, a)):
            row = list(rows[v])
            row[i] = far
            rows[v] = row
        return Model(rows, self.edges + 1, self.unexplored - 2)

    def grown(self, at, degree):
        """Non-loop augmentation: a new vertex of ``degree`` whose exit 0 is joined to the unexplored exit at."""
        rows = list(self.rows)
        new = len(rows)
        row = list(rows[at[0]])
        row[at[1]] = (new, 0)
        rows[at[0]] = row
        rows.append([at] + [None] * (degree - 1))
        return Model(rows, self.edges + 1, self.unexplored + degree - 2)

    def tree(self, root):
        """One breadth-first tree from root: vertex -> (its parent, the parent's exit to it)."""
        up, todo = {root: None}, deque([root])
        while todo:
            v = todo.popleft()
            for i, far in enumerate(self.rows[v]):
                if far is not None and far[0] not in up:
                    up[far[0]] = (v, i)
                    todo.append(far[0])
        return up

    def diameter(self):
        best = 0
        for v in range(len(self.rows)):
            up = self.tree(v)
            best = max([best] + [len(_path(up, w, v)) for w in up])
        return best

    def genus(self):
        """Faces traced (v, i) -> (w, j + 1); an unexplored exit is an edge to a leaf of its own."""
        seen, faces = set(), 0
        for v, row in enumerate(self.rows):
            for i in range(len(row)):
                if (v, i) in seen:
                    continue
                faces += 1
                dart = (v, i)
                while dart not in seen:
                    seen.add(dart)
                    w, j = self.rows[dart[0]][dart[1]] or dart
                    dart = (w, (j + 1) % len(self.rows[w]))
        return (2 - len(self.rows) + self.edges - faces) // 2

    def shows_entry(self, v):
        """§5.2.2 / §5.1: every neighbour known and no proper rotation of their degrees onto themselves."""
        if None in self.rows[v]:
            return False
        D = [self.degree(w) for w, _ in self.rows[v]]
        return all(D[r:] + D[:r] != D for r in range(1, len(D)))


def _path(up, target, root):
    """The exits (vertex, exit) from root down to target along the tree ``up``."""
    out = []
    while target != root:
        out.append(up[target])
        target = up[target][0]
    return out[::-1]


class Explorer:
    def __init__(self, options):
        self.o = options
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or hello.get("kit"):
            send({"type": "error", "message": "I speak topomark/protocol@2 with an empty kit only (Algorithm 5.1 "
                                              "uses no marker)"})
            sys.exit(2)
        d = degree_of(hello["signature"])
        self.here_degree, self.turn = d, 0  # the robot's vertex; its physical entry counted from the logical one
        self.tm_degree, self.tm_up, self.tm_depth, self.tm_down = [d], [None], [0], {}
        self.cursor, self.next_exit, self.tm_pos = 0, 0, (0, 0)
        self.level = [(Model([[None] * d], 0, d), (0, 0))]  # the models made in the previous step
        self.sole = (None, 0)  # the sole completed model and the step it became so
        self.steps = self.hypotheses = self.moves = self.completed = 0

    # -- the robot -----------------------------------------------------------------------------------------
    def move(self, motion):
        """Leave by ``motion`` counted from the physical entry; the degree sensed where the robot arrives."""
        self.moves += 1
        send({"type": "move", "motion": motion})
        return degree_of(receive()["value"])

    def logical(self, k):
        """Leave by exit k counted from the logical entry (e, for v_u), undoing the turn validation left."""
        self.here_degree = self.move((k - self.turn) % self.here_degree)
        self.turn = 0
        return self.here_degree

    # -- lines 1-2: TM ---------------------------------------------------------------------------------------
    def frontier(self):
        while self.cursor < len(self.tm_degree) and self.next_exit >= self.tm_degree[self.cursor]:
            self.cursor, self.next_exit = self.cursor + 1, 1
        return (self.cursor, self.next_exit) if self.cursor < len(self.tm_degree) else None

    def tm_path(self, a, b):
        up, down = [], []
        while self.tm_depth[a] > self.tm_depth[b]:
            up.append((a, 0))
            a = self.tm_up[a][0]
        while self.tm_depth[b] > self.tm_depth[a]:
            down.append(self.tm_up[b])
            b = self.tm_up[b][0]
        while a != b:
            up.append((a, 0))
            a = self.tm_up[a][0]
            down.append(self.tm_up[b])
            b = self.tm_up[b][0]
        return up + down[::-1]

    def walk_tm(self, frontier):
        (here, entry), motions, degrees = self.tm_pos, [], []
        for v, x in self.tm_path(here, frontier[0]) + [frontier]:
            k = (x - entry) % self.tm_degree[v]
            d = self.logical(k)
            motions.append(k)
            degrees.append(d)
            if (v, x) == frontier:  # line 2: always a new TM vertex, entered by its exit 0
                here, entry = len(self.tm_degree), 0
                self.tm_degree.append(d)
                self.tm_up.append((v, x))
                self.tm_depth.append(self.tm_depth[v] + 1)
                self.tm_down[(v, x)] = here
                self.next_exit += 1
            elif x == 0 and v != 0:
                here, entry = self.tm_up[v]
            else:
                here, entry = self.tm_down[(v, x)], 0
        self.tm_pos = (here, entry)
        return motions, degrees

    def tm_explored_depth(self):
        f = self.frontier()
        return max(self.tm_depth) if f is None else self.tm_depth[f[0]] - 1

    # -- lines 3-34 ------------------------------------------------------------------------------------------
    def process(self, motions, degrees):
        children = []
        for model, (v, e) in self.level:
            for t, (k, d) in enumerate(zip(motions, degrees)):
                x = (e + k) % model.degree(v)
                if model.rows[v][x] is None:  # line 15: e is unexplored in M
                    self.augment(model, (v, x), d, children)
                    break
                v, e = model.rows[v][x]
                if model.degree(v) != d:  # lines 6-7, 9-10: void M
                    break
            else:  # lines 11-13: pass M
                self.add(children, model, (v, e), new=False)
        return children

    def augment(self, model, e, d, children):
        vk = e[0]
        for v, row in enumerate(model.rows):  # line 17
            for i, far in enumerate(row):
                if far is not None or v == vk or len(row) != d:
                    continue
                self.hypotheses += 1
                child = model.joined(e, (v, i))
                if not self.admissible(child):
                    continue
                if self.o["--signatures"] == "local" or self.validate(child, v, i):  # lines 18-26
                    self.add(children, child, (v, i))  # lines 27-29
        child = model.grown(e, d)  # lines 31-33
        if self.admissible(child):
            self.add(children, child, (len(child.rows) - 1, 0))

    def add(self, children, model, pose, new=True):
        children.append((model, pose))
        if new and model.complete():
            self.completed += 1
        if len(children) > self.o["--max-models"]:
            raise Stop("--max-models %d exceeded at step %d" % (self.o["--max-models"], self.steps))

    def admissible(self, m):
        o, n = self.o, len(m.rows)
        if o["--cue-n"] is not None and (n > o["--cue-n"] or m.complete() and n != o["--cue-n"]):
            return False
        if o["--cue-m"] is not None and (m.edges > o["--cue-m"] or m.complete() and m.edges != o["--cue-m"]):
            return False
        if o["--cue-planar"] == "yes" and m.genus() > 0:
            return False
        return o["--cue-diameter"] is None or not m.complete() or m.diameter() <= o["--cue-diameter"]

    # -- lines 18-23: a path from v_k' to each known vertex --------------------------------------------------
    def validate(self, m, root, entry):
        """The robot stands at v_u, believed at ``root`` entered by ``entry``; True if no path meets a mismatch."""
        up = m.tree(root)
        ent = (entry + self.turn) % m.degree(root)  # the physical entry, in M''s numbering of root's exits
        ok, ent = self.probe(m, root, ent) if self.check_entry(m, root) else (True, ent)
        for target in range(len(m.rows)):
            if not ok:
                break
            walked = []  # (vertex entered, its exit back toward root)
            for v, y in _path(up, target, root):
                w, j = m.rows[v][y]
                if self.move((y - ent) % m.degree(v)) != m.degree(w):  # line 21: back through the entry edge
                    self.move(0)
                    ok, ent = False, y
                    break
                ent = j
                walked.append((w, j))
                if self.check_entry(m, w):
                    ok, ent = self.probe(m, w, ent)
                    if not ok:
                        break
            for w, j in reversed(walked):  # back to v_k' by the edges the robot came down
                self.move((j - ent) % m.degree(w))
                ent = m.rows[w][j][1]
        self.turn = (ent - entry) % m.degree(root)
        return ok

    def check_entry(self, m, v):
        return self.o["--entry-check"] == "yes" and m.shows_entry(v)

    def probe(self, m, v, ent):
        """Each neighbour of v out and back, exit 0 first; (all degrees as M' says, the entry now)."""
        d = m.degree(v)
        for x in range(d):
            sensed = self.move((x - ent) % d)
            self.move(0)
            ent = x
            if sensed != m.degree(m.rows[v][x][0]):
                return False, ent
        return True, ent

    # -- termination -----------------------------------------------------------------------------------------
    def run(self):
        try:
            model = self.explore()
        except Stop as stop:
            self.stats()
            send({"type": "error", "message": str(stop)})
            sys.exit(1)
        self.stats()
        names = ["s%d" % v for v in range(len(model.rows))]
        send({"type": "map", "world": {"format": "topomark/world@1",
                                        "rotation": {names[v]: [names[w] for w, _ in row]
                                                     for v, row in enumerate(model.rows)}}})
        receive()

    def explore(self):
        o = self.o
        while True:
            if self.steps == o["--max-steps"]:
                raise Stop("--max-steps %d reached: %d live model(s)" % (o["--max-steps"], len(self.level)))
            frontier = self.frontier()
            if frontier is None:  # TM complete: the world is a tree, walked whole
                done = self.distinct(m for m, _ in self.level if m.complete())
                if len(done) != 1:
                    raise Stop("TM complete with %d completed models" % len(done))
                return done[0]
            self.steps += 1
            motions, degrees = self.walk_tm(frontier)
            self.level = self.process(motions, degrees)
            D = o["--cue-diameter"]
            if D is not None and self.tm_explored_depth() >= D:
                self.level = [(m, p) for m, p in self.level if m.complete()]
            if not self.level:
                raise Stop("every world model was voided at step %d" % self.steps)
            told = o["--cue-n"] is not None or o["--cue-m"] is not None
            if told and len(self.level) == 1 and self.level[0][0].complete():
                return self.level[0][0]
            if D is not None and self.tm_explored_depth() >= D:
                left = self.distinct(m for m, _ in self.level)
                if len(left) != 1:
                    raise Stop("TM explored to the diameter cue with %d completed models" % len(left))
                return left[0]
            done = self.distinct(m for m, _ in self.level if m.complete())
            if len(done) != 1:
                self.sole = (None, self.steps)
                continue
            if self.sole[0] is not done[0]:
                self.sole = (done[0], self.steps)
            if self.steps - self.sole[1] >= o["--window"]:
                return done[0]

    @staticmethod
    def distinct(models):
        out = []
        for m in models:
            if not any(m is x for x in out):
                out.append(m)
        return out

    def stats(self):
        if self.o.get("--stats"):
            sys.stderr.write(json.dumps({"steps": self.steps, "hypotheses": self.hypotheses, "moves": self.moves,
                                         "completed_models": self.completed, "live": len(self.level)}) + "\n")


def options(argv):
    o = dict(OPTIONS, **{"--stats": False})
    args = list(argv)
    while args:
        name = args.pop(0)
        if name == "--stats":
            o[name] = True
        elif name in OPTIONS and args:
            value = args.pop(0)
            o[name] = value if name in ("--signatures", "--entry-check", "--cue-planar") else int(value)
        else:
            sys.exit("usage: client_model_tree_listing.py [--stats] " + " ".join("[%s V]" % k for k in OPTIONS))
    return o


if __name__ == "__main__":
    Explorer(options(sys.argv[1:])).run()
