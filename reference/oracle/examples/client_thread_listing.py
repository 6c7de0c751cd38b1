#!/usr/bin/env python3
"""Algorithm 6.7 of the thesis, "Mapping with a l = c(G) thread" (§6.3.2), as listed — and with
``--explore`` Algorithm 6.8, "Mapping with a l < c(G) thread. Explore-explore approach" (§6.3.3), as
listed — speaking topomark/protocol@2 with a thread kit.

Standalone on purpose (standard library only, no topomark import): it is written from the listing, not
from topomark's explorer, so that the conformance suite can be checked against an independent reading.
Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD --kit '{"thread": N}' -- python3 client_thread_listing.py
    topomark conformance run SUITE --algorithm thread-circumference-listing -- python3 client_thread_listing.py
    topomark conformance run SUITE --algorithm thread-explore-listing -- python3 client_thread_listing.py --explore

The listing, line by line:

1. the robot ties the thread at v0 (``thread`` ``tie``);
2. S <- v0; U <- the edges of v0;
3. while U is not empty:
4. remove a closest edge e = (v_k, v_u) from U — with the robot standing at
   the end of the thread, the lowest-numbered unexplored exit where it stands;
5. follow e to v_u, unwinding the thread along e (a ``move`` holding the free
   end lays it);
6. if v_u shows no thread other than e's (no ``T``, one ``S-0``):
7. non-loop augmentation: v_u joins S, e its exit 0;
8. if v_u is fully explored now,
9. rewind the thread to a vertex that is not fully explored;
10. else (v_u shows the thread already):
11. search back along the thread for the vertex with one more marked edge than
    S says it should have: leave the free end at v_u (``leave``), go back over
    e, and walk the thread back toward v0, sensing at each vertex; the vertex
    whose sensed thread edges exceed the ones recorded by exactly one is v_u,
    that edge is e';
13. loop augmentation with e' (removed from U); take the free end (``take``)
    and rewind e;
14. rewind the thread to a vertex that is not fully explored.

When U is empty the thread is all rewound to v0; the robot unties it there and
sends the map.

Algorithm 6.8 (``--explore``) ties the thread at v_s (first v0) and runs the
same loop, with three changes the listing makes (§6.3.3):

* the robot knows its thread's length l (the kit's) and rewinds also when all
  l edges are laid (line 16: it stops at a vertex that is not fully explored
  with thread left to lay);
* at v_u without thread (line 10) v_u may be a visited place the thread was
  rewound from: line 11 "searches non-thread vertices on S that has
  unexplored edges and has the same degree as v_u, looking for the vertex
  containing the thread's free end".  The robot leaves the free end at v_u
  (``leave``), goes back over e and visits those vertices, walking shortest
  paths of S; the first place entered that shows the free end (``F``) is v_u,
  and its one thread-marked edge is e' (line 13: take the free end, rewind e).
  Not found: v_u is new (line 15); the robot walks back to v_k and over e,
  and takes the free end;
* with every vertex along the thread fully explored (lines 18-21) the robot
  rewinds to v_s, unties the thread, walks to a closest vertex of S that is
  not fully explored, and ties the thread there (a new v_s).

Choices the listing leaves open, made here as topomark's own runs make them:
a closest edge is the lowest-numbered unexplored exit where the thread ends;
line 11 visits its vertices in the preorder of a breadth-first tree of S
rooted at v_k (children by exit); shortest paths are breadth-first, exits in
order; the new v_s is the closest, the lowest-numbered among equals.  The laid thread is at most a simple path of S (n − 1 edges)
plus e, and topomark's default kit gives n edges (§6.3.2 assumes l = c(G)
suffices); with a shorter thread, once every edge of it is laid and line 5
would lay one more, the robot gives up (sends ``error``: out of thread).  The world is a simple graph, as the thesis's worlds
are.
"""
import json
import sys
from collections import Counter, deque


def send(msg):
    sys.stdout.write(json.dumps(msg) + "\n")
    sys.stdout.flush()


def receive():
    msg = json.loads(sys.stdin.readline())
    if msg["type"] in ("error", "bye"):
        sys.exit(0 if msg.get("verdict") == "pass" else 1)
    return msg


def parse(sig):
    """'[3,A,A,T,S-1]' -> (3, tied, {relative exit: times the thread lies along it}).  With a thread-only kit
    the vertex and edge parts are 'A'; the thread items follow them.  Whether the free end lies here: 'F' in
    ``sig``."""
    items = sig.strip("[]").split(",")
    tied, edges = False, Counter()
    for item in items[3:]:
        if item == "T" or item.startswith("T-"):
            tied = True
        elif item.startswith("S"):
            times, _, p = item[1:].partition("-")
            edges[int(p)] += int(times) if times else 1
    return int(items[0]), tied, edges



class Explorer:
    def __init__(self, explore=False):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or not hello["kit"].get("thread"):
            send({"type": "error", "message": "I need topomark/protocol@2 and a thread of at least one edge"})
            sys.exit(2)
        self.explore = explore  # Algorithm 6.8 (§6.3.3) rather than Algorithm 6.7 (§6.3.2)
        self.exits = [[None] * parse(hello["signature"])[0]]  # S: exits[v][i] = [w, j] or None
        self.U = [(0, i) for i in range(len(self.exits[0]))]
        self.pos = (0, 0)  # (map vertex, the exit it was entered by); v0 faces its exit 0
        self.vs = None  # where the thread is tied (v_s), None while it is untied
        self.laid = []  # the thread: darts (v, i) of S from v_s, in the order laid
        self.length = hello["kit"]["thread"]  # the robot knows its thread's length (§6.3)
        self.seen = ""  # the last signature sensed, as sent

    def op(self, name):
        send({"type": "thread", "op": name})
        return parse(receive()["value"])

    def move(self, exit_):
        """Leave the current map vertex by exit ``exit_``; return what is sensed at the other end."""
        v, entry = self.pos
        send({"type": "move", "motion": (exit_ - entry) % len(self.exits[v])})
        self.seen = receive()["value"]
        return parse(self.seen)

    def record(self):
        """What S says the thread marks: map vertex -> Counter of exits (both ends of every laid edge whose far
        end is known, and the near end of e)."""
        marks = {}
        for v, i in self.laid:
            marks.setdefault(v, Counter())[i] += 1
            if self.exits[v][i] is not None:
                w, j = self.exits[v][i]
                marks.setdefault(w, Counter())[j] += 1
        return marks

    def rewind(self):
        self.op("rewind")
        self.pos = self.laid.pop()

    def is_open(self, v):
        return any(w == v for w, _ in self.U)

    def rewind_to_open(self):
        """Lines 9 and 14 (Algorithm 6.8: 9 and 16-17): rewind until the robot stands at a vertex with an
        unexplored edge — with thread left to lay, in Algorithm 6.8 — or at v_s."""
        while self.laid and not (self.is_open(self.pos[0]) and (not self.explore or len(self.laid) < self.length)):
            self.rewind()

    def search_back(self, vk, i):
        """Line 11 (Algorithm 6.8: 7): leave the free end at v_u, go back over e, walk the thread back: (v_u, e')."""
        self.op("leave")
        self.move_back(vk, i)
        marks = self.record()
        for v, x in reversed(self.laid[:-1]):
            j = self.exits[v][x][1]  # the robot stands at the far end of (v, x); its exit j leads back to v
            degree, _, edges = self.move(j)
            self.pos = (v, x)
            sensed = Counter({(x + p) % degree: k for p, k in edges.items()})
            extra = sensed - marks.get(v, Counter())
            if sum(extra.values()) == 1:
                return v, next(iter(extra))
        raise SystemExit("no vertex on the thread has one more marked edge")

    def move_back(self, vk, i):
        """Back over e, not holding the thread: the robot entered v_u by e, so motion 0."""
        send({"type": "move", "motion": 0})
        receive()
        self.pos = (vk, i)

    def tree(self, root):
        """A breadth-first tree of S from ``root``, exits in order: vertex -> (parent, its exit), in the order met."""
        parent, todo = {root: None}, deque([root])
        while todo:
            v = todo.popleft()
            for x, w_j in enumerate(self.exits[v]):
                if w_j is not None and w_j[0] not in parent:
                    parent[w_j[0]] = (v, x)
                    todo.append(w_j[0])
        return parent

    def walk_to(self, target, look=False):
        """Walk a shortest path of S to ``target``; with ``look``, stop where the free end is sensed: its place
        and the exit the thread lies along there, or None."""
        parent, path = self.tree(self.pos[0]), []
        v = target
        while parent[v] is not None:
            path.append(parent[v])
            v = parent[v][0]
        for v, x in reversed(path):
            degree, _, edges = self.move(x)
            self.pos = tuple(self.exits[v][x])
            if look and "F" in self.seen[1:-1].split(","):
                return self.pos[0], (self.pos[1] + next(iter(edges))) % degree
        return None

    def search_off_thread(self, vk, i, degree):
        """Line 11 (Algorithm 6.8): (v_u, e') if the free end lies on a vertex off the thread, else None (new)."""
        on = {self.vs} | {self.exits[v][x][0] for v, x in self.laid[:-1]}
        parent = self.tree(vk)

        def exits_from_vk(v):  # the preorder of the breadth-first tree: the path's exits, compared as sequences
            path = []
            while parent[v] is not None:
                v, x = parent[v]
                path.append(x)
            return path[::-1]
        like = sorted({v for v, _ in self.U if v not in on and len(self.exits[v]) == degree}, key=exits_from_vk)
        if not like:
            return None
        self.op("leave")
        self.move_back(vk, i)
        for target in like:
            found = self.walk_to(target, look=True)
            if found is not None:
                return found
        self.walk_to(vk)  # not found: v_u is new; back to it for the free end
        self.move(i)
        self.op("take")
        return None

    def join(self, vk, i, degree):
        """Non-loop augmentation (line 7; Algorithm 6.8: 15): v_u joins S, e its exit 0; the robot stands there."""
        u = len(self.exits)
        self.exits.append([[vk, i]] + [None] * (degree - 1))
        self.exits[vk][i] = [u, 0]
        self.U += [(u, j) for j in range(1, degree)]
        self.pos = (u, 0)

    def iterate(self):
        vk = self.pos[0]
        i = min(x for v, x in self.U if v == vk)  # line 4: the closest edge, where the thread ends
        if len(self.laid) == self.length:  # line 5 needs one more edge of thread than the robot has
            send({"type": "error", "message": "out of thread: all %d edges are laid" % self.length})
            sys.exit(1)
        self.U.remove((vk, i))
        self.laid.append((vk, i))  # line 5
        degree, tied, edges = self.move(i)
        found = None
        if tied or edges != Counter({0: 1}):  # v_u shows the thread already (Algorithm 6.7 line 10; 6.8 line 6)
            found = self.search_back(vk, i)
        elif self.explore:  # Algorithm 6.8 lines 10-15
            found = self.search_off_thread(vk, i, degree)
        if found is None:
            self.join(vk, i, degree)
        else:  # loop augmentation with e' (removed from U); take the free end and rewind e
            self.U.remove(found)
            self.exits[vk][i], self.exits[found[0]][found[1]] = list(found), [vk, i]
            self.op("take")
            self.rewind()
        self.rewind_to_open()

    def retie(self):
        """Algorithm 6.8 lines 18-21: at v_s fully explored, untie; tie again at a closest vertex not fully explored."""
        self.op("untie")
        parent = self.tree(self.pos[0])  # in breadth-first order: the closest first
        depth = {}
        for v, up in parent.items():
            depth[v] = 0 if up is None else depth[up[0]] + 1
        self.walk_to(min((v for v in parent if self.is_open(v)), key=lambda v: (depth[v], v)))
        self.vs = self.pos[0]
        self.op("tie")

    def run(self):
        self.op("tie")  # line 1
        self.vs = 0
        while self.U:  # line 3
            if self.explore and not self.laid and not self.is_open(self.pos[0]):
                self.retie()
            self.iterate()
        while self.laid:
            self.rewind()
        self.op("untie")
        names = ["s%d" % v for v in range(len(self.exits))]
        send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)},
            "markers": []}})
        receive()


if __name__ == "__main__":
    Explorer(explore="--explore" in sys.argv[1:]).run()
