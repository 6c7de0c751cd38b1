#!/usr/bin/env python3
"""Algorithm 6.7 of the thesis, "Mapping with a l = c(G) thread" (§6.3.2), as listed — and with
``--explore`` Algorithm 6.8, "Mapping with a l < c(G) thread. Explore-explore approach" (§6.3.3), as
listed — and with ``--fallback`` §6.3.3's phase-I/phase-II fallback, its phase I as Algorithm 6.7 is
listed — speaking topomark/protocol@2 with a thread kit.

Standalone on purpose (standard library only, no topomark import): it is written from the listing, not
from topomark's explorer, so that the conformance suite can be checked against an independent reading.
Run it under topomark, which plays the world and judges the map:

    topomark run-external WORLD --kit '{"thread": N}' -- python3 client_thread_listing.py
    topomark conformance run SUITE --algorithm thread-circumference-listing -- python3 client_thread_listing.py
    topomark conformance run SUITE --algorithm thread-explore-listing -- python3 client_thread_listing.py --explore
    topomark conformance run SUITE --algorithm thread-fallback-listing -- python3 client_thread_listing.py --fallback

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
order; the new v_s is the closest, the lowest-numbered among equals.

The fallback (``--fallback``, §6.3.3: "the robot uses thread to do
validations when it possesses thread (phase-I), and when it runs out of
thread (phase-II), it applies the hypothesis-based traversal strategy
developed for the single immovable marker algorithm") runs Algorithm 6.7 as
above until the robot stands at a place with an unexplored edge and all l
edges are laid.  There it leaves the free end (``leave``) and the thread
stays where it lies: tied at v0 along one edge, v0 is Algorithm 3.1's
lighthouse (§3.3).  Each phase-II step takes a nearest unexplored edge (the
first of U among the closest), walks a breadth-first tree of S to v_k and
follows e; v_u showing v0's marks (``T`` and its one thread edge) is v0,
entered by the exit they name; otherwise every unexplored dart of S (not at
v_k) whose place, entered by it, shows what v_u shows — thread marks and free
end included — is a hypothesis, taken in U's order and tested by walking the
breadth-first tree to v0 and comparing every place; a failed one is
retraced; none confirmed, v_u is new.  The laid thread is at most a simple path of S (n − 1 edges)
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
    def __init__(self, explore=False, fallback=False):
        hello = receive()
        if hello["protocol"] != "topomark/protocol@2" or not hello["kit"].get("thread"):
            send({"type": "error", "message": "I need topomark/protocol@2 and a thread of at least one edge"})
            sys.exit(2)
        self.explore = explore  # Algorithm 6.8 (§6.3.3) rather than Algorithm 6.7 (§6.3.2)
        self.fallback = fallback  # Algorithm 6.7, then Algorithm 3.1 once the thread is all laid (§6.3.3)
        self.phase = 1
        self.end, self.marks = None, {}  # phase II: where the free end lies, and the thread's marks
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

    def sensed(self):
        """The last signature as (degree, tied, thread edges by relative exit, free end here)."""
        degree, tied, edges = parse(self.seen)
        return degree, tied, edges, "F" in self.seen[1:-1].split(",")

    def expect(self, v, entry):
        """Phase II: what S says map vertex v shows, entered by exit ``entry`` (the thread lies as recorded)."""
        d = len(self.exits[v])
        marks = Counter({(x - entry) % d: k for x, k in self.marks.get(v, Counter()).items()})
        return d, v == 0, marks, v == self.end

    def step(self, motion):
        send({"type": "move", "motion": motion})
        self.seen = receive()["value"]
        return self.sensed()

    def run_out(self):
        """The thread is all laid at a place with an unexplored edge: leave the free end, start phase II."""
        self.op("leave")
        self.phase, self.end, self.marks = 2, self.pos[0], self.record()

    def phase_two(self):
        """One pass of Algorithm 3.1's loop with v0, where the thread is tied, as the lighthouse (§3.3)."""
        parent = self.tree(self.pos[0])
        depth = {}
        for v, up in parent.items():
            depth[v] = 0 if up is None else depth[up[0]] + 1
        vk, i = self.U.pop(min(range(len(self.U)), key=lambda k: (depth[self.U[k][0]], k)))  # nearest e
        self.walk_to(vk)
        self.move(i)
        sig = self.sensed()
        far, heading = next(((0, e) for e in range(len(self.exits[0])) if self.expect(0, e) == sig), None), 0
        if far is not None:
            self.pos = far
        else:
            far, heading = self.validate(vk, sig)
        if far is not None:  # loop augmentation with the existing indices; e' leaves U
            self.U.remove(far)
            self.exits[vk][i], self.exits[far[0]][far[1]] = list(far), [vk, i]
        else:
            self.join(vk, i, sig[0])
            self.pos = (self.pos[0], heading)

    def validate(self, vk, sig):
        """Algorithm 3.1 lines 8-20: the confirmed e' (the robot then at v0) or None, and the heading at v_u."""
        toward = {v: self.exits[up[0]][up[1]][1] for v, up in self.tree(0).items() if up is not None}
        heading = 0
        for v, i in [h for h in self.U if h[0] != vk and len(self.exits[h[0]]) == sig[0] and self.expect(*h) == sig]:
            path, x, entry = [], v, i  # the motions from v (entered by e') to v0, with what each place shows
            while x != 0:
                motion = (toward[x] - entry) % len(self.exits[x])
                x, entry = self.exits[x][toward[x]]
                path.append((motion, self.expect(x, entry)))
            done = []  # (physical motion, degree reached)
            for k, (motion, want) in enumerate(path):
                physical = (motion - heading) % sig[0] if k == 0 else motion  # turned by the heading at v_u
                got = self.step(physical)
                done.append((physical, got[0]))
                if got != want:
                    break
            else:
                self.pos = (0, entry)
                return (v, i), heading
            self.step(0)  # retrace (line 17): back along the last edge, then every motion reversed
            degrees = [sig[0]] + [d for _, d in done]
            for k in range(len(done) - 1, 0, -1):
                self.step((-done[k][0]) % degrees[k])
            heading = (heading + done[0][0]) % sig[0]
        return None, heading

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
            if self.fallback and self.phase == 1 and len(self.laid) == self.length:
                self.run_out()
            if self.phase == 2:
                self.phase_two()
            else:
                self.iterate()
        while self.laid and self.phase == 1:
            self.rewind()
        if self.phase == 1:
            self.op("untie")
        names = ["s%d" % v for v in range(len(self.exits))]
        world = {"format": "topomark/world@1",
                 "rotation": {names[v]: [names[w] for w, _ in row] for v, row in enumerate(self.exits)}, "markers": []}
        if self.phase == 2:  # the fallback leaves the thread where it lies: the map shows it
            world["thread"] = {"walk": ["s0"] + [names[self.exits[v][x][0]] for v, x in self.laid], "end": "left"}
        send({"type": "map", "world": world})
        receive()


if __name__ == "__main__":
    Explorer(explore="--explore" in sys.argv[1:], fallback="--fallback" in sys.argv[1:]).run()
