"""Bounded search for indistinguishable, non-isomorphic world pairs with Z3 (thesis §3.2, §3.7, §6.1).

The thesis shows that some marker classes do not let a robot map every world
(§3.2.1 Figure 3.3: no marker; §3.2.2 Figure 3.4: one undirected vertex marker;
§3.7 Figure 3.21(a): two undirected vertex markers; §6.1 Figure 6.1(a): one
undirected edge marker) by exhibiting two worlds that are *indistinguishable*
(every motion sequence gives the same perception sequence, §3.1.1) but not
extended-isomorphic.  It argues that the other classes (a directional vertex
marker §3.3, three undirected markers Figure 3.21(b), a directional edge marker
§6.1, a vertex and an edge marker §6.2) always suffice.  This module asks Z3
the same question within bounds: *is there a pair of worlds with at most N
vertices and degrees at most D that is indistinguishable and not isomorphic?*

:func:`search` answers ``found`` (with a re-checked pair), ``none`` (UNSAT for
every size pair: no counterexample within the bounds) or ``unknown`` (the
solver gave up or timed out — never reported as ``none``).  :func:`prove`
runs the same search for a sufficient class and reports it as a bounded proof.

Encoding (one solver per size pair n_A <= n_B; the relation is symmetric)
-----------------------------------------------------------------------------
*Worlds.*  For each world, vertex v < n, exit i < D: one-hot ``deg[v]`` in
1..D, one-hot target vertex ``tv[v,i]`` in {NULL} ∪ (V \\ {v}) (no self-loops)
and target entry ``te[v,i]``.  Exit i exists iff i < deg(v) iff tv[v,i] is not
NULL.  The involution ``target(target(d)) = d`` is asserted dart by dart; two
exits of one vertex never reach the same vertex (no multi-edges).

*Symmetry breaking (complete for a world with its start).*  The start is
vertex 0 facing exit 0 (cyclically shifting a rotation list is an extended
isomorphism, so the facing exit can be renamed 0).  Vertices are numbered in
breadth-first order from vertex 0, exploring the exits of each vertex in
index order, and every vertex v >= 1 has its exit 0 on its BFS-tree parent
edge (again a rotation shift): ``par[v] = (u, i)`` with u < v, the dart (u, i)
arrives at (v, 0), no vertex below u is adjacent to v, and the pairs
``par[1] < par[2] < ...`` increase lexicographically.  Every connected world
with a start has exactly one such labelling, and the parent pointers prove
connectivity.  The class's markers sit at the start vertex 0; a variable exit
``e`` of vertex 0 says where the directional head, the marked neighbour
(vertices 0 and ``tv[0,e]`` for two/three undirected markers) or the marked
edge (0, tv[0,e]) is; ``head0`` says whether a directional edge marker points
at vertex 0.

*Indistinguishability.*  Bool ``R[(v,j),(w,k)]`` over valid state pairs with
``R[(0,0),(0,0)]``; R(p,q) implies equal signatures (degree, vertex-marker
count, ``V-dir``, ``E-p`` position and H/T, exactly as :func:`signature_at`
computes them); R(p,q) implies R(step(p,l), step(q,l)) for every motion l <
deg.  Step targets are one-hot ``S[v,j,l]`` variables and the closure is
factored through a half-step ``H[p',q,l]`` (A moved, B not yet) to keep the
clause count at O(n^3 D^4).  A relation with these properties exists iff the
two start states are bisimilar, i.e. indistinguishable (§3.1.1).

*Non-isomorphism (the part a blocking loop could not do).*  An extended
isomorphism f: A -> B is fixed by the image t of the start dart (0, 0), since
A is connected.  Along A's BFS tree the candidate f_t is *propagated*
functionally: ``IM[t][v]`` = image of the dart (v, 0), the image of (u, i) is
(w, (k + i) mod deg) when IM[t][u] = (w, k), and IM[t][v] is the far end of
the image of its parent dart.  f_t is an isomorphism iff there is no *defect*:
(a) a vertex v whose signature entering by exit 0 differs from the signature
of its image state IM[t][v] (degree or markers not preserved, rotated by the
offset); (b) a dart (v, i) whose image's far end differs from the image of
its own far end (an edge not preserved); (c) two vertices with the same image
vertex.  Proof: with no defect f_t preserves degrees, markers and every dart
with its reverse, so it is a covering map, injective on vertices, hence (n_A
= n_B, B connected) a bijection, i.e. an extended isomorphism with markers;
conversely an isomorphism sending (0, 0) to t *is* f_t (forced along the
tree) and has no defect.  The formula asserts a defect for every anchor t in
which vertex 0 could be mapped: any B dart for ``none``; darts of vertex 0
for a uniquely marked start vertex; darts of vertex 0 or of the other marked
vertex / other edge end for two undirected markers or an undirected edge
marker (an isomorphism preserves markers, so nothing else can be an image of
vertex 0).  For the four sufficient classes the markers fix the start dart
itself: a directional vertex/edge marker or the edge of vertex-and-edge pins
the offset at vertex 0, and for three undirected markers the exit towards
the V2 neighbour does; since R relates the starts, their signatures (and,
after one motion, the V2 exit) agree, so the only possible image of (0, 0)
is (0, 0) and that single anchor is used.  (Dropping anchors only weakens
the formula, so UNSAT stays a proof; a spurious model would be caught by the
re-check.)  Anchors that are not darts (k >= deg) are excused.  If n_A != n_B
the worlds cannot be isomorphic and no anchor is needed.  Values downstream
of a genuine defect may be arbitrary (domains include NULL so nothing is
forced to be unsatisfiable), but a defect in an isomorphism is impossible
because there every value is forced.  Note that a closed relation R alone
could not decide isomorphism: the largest bisimulation may relate states
that no automorphism relates.

*Planarity (optional).*  The thesis allows any embedding ("not necessarily a
planar surface", §3.1.1), so by default both worlds may have any genus; with
``planar=True`` each world also satisfies Euler's formula n - m + f = 2,
where the faces f are counted through a face label per dart (constant along
the face permutation, a representative per face forced by a rank) and a
pseudo-Boolean equation.

*Bounds.*  Size pairs are tried smallest first (larger world, then total),
so the first ``found`` is smallest in the larger world's size; for a pair
the degree bound is clamped to n_B - 1 (a simple graph has no larger degree).

*Validation* (``tests/test_z3search.py``, :mod:`topomark.proofs.bench_z3`):
the single-world encoding has exactly one model per placed world up to
start-preserving isomorphism (model counting, with and without planarity);
found/none and the smallest size agree with brute-force enumeration for all
eight classes up to 5 vertices and degree 4; with both worlds pinned
(:func:`pair_is_model`) the formula accepts the thesis's counterexample
pairs (Figures 3.3, 3.4, 3.21(a), 6.1(a)) and rejects the distinguishable
ones (Figures 3.6, 3.21(b), 6.1(b)) and isomorphic pairs.

Every model is decoded into two :class:`World` objects and re-checked with
the specification's own predicates (World validation, class placement,
:func:`find_isomorphism`, :mod:`topomark.proofs.bisim`); a failure raises
:class:`CheckFailure` because it means this encoding is wrong.  The reported
relation is the reachable product of the two starts (the least
bisimulation), and the reported motion sequence is a common walk entering
every state of both worlds, with the perception sequence both produce.

>>> r = search("none", 4, 2)   # Figure 3.3: cycles of different lengths
>>> r.outcome, sorted(w.n for w in r.worlds), str(r.perceptions[0])
('found', [3, 4], '[2,A,A]')
"""

from __future__ import annotations

import itertools
import re
import time
from collections import deque
from dataclasses import dataclass, field
from typing import Any, Iterable, Iterator

import z3

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.robot import sense, step
from topomark.spec.signature import Signature
from topomark.spec.world import Start, World

from topomark.spec.markerclass import MARKER_CLASSES, marker_class

__all__ = [
    "SearchResult", "ProofReport", "SizeCheck", "search", "prove", "size_pairs", "decode_pair",
    "recheck", "covering_walk", "canonical_labelling", "pair_is_model", "reachable_relation", "relation_to_json",
    "SUFFICIENT", "SYMMETRY_BREAKING", "MAX_VERTICES",
]

NULL = -1
MAX_VERTICES = 8
SUFFICIENT = ("directional-vertex", "directional-edge", "vertex-and-edge", "three-undirected-vertex")
SYMMETRY_BREAKING = (
    "start = vertex 0 facing exit 0",
    "vertices numbered in BFS order from the start (exits explored in index order)",
    "exit 0 of every other vertex is its BFS-parent edge (canonical: one encoding per world and start)",
    "markers anchored at vertex 0 (head/marked neighbour/marked edge via one exit variable)",
    "pairs ordered n_A <= n_B",
)

# which vertex of B an isomorphism may send A's start vertex to
_ANCHORS = {
    "none": "any", "undirected-vertex": "same", "directional-vertex": "start",
    "two-undirected-vertex": "pair", "three-undirected-vertex": "start", "undirected-edge": "pair",
    "directional-edge": "start", "vertex-and-edge": "start",
}
_NEEDS_EXIT = {"directional-vertex", "two-undirected-vertex", "three-undirected-vertex", "undirected-edge",
               "directional-edge", "vertex-and-edge"}


# -- results ------------------------------------------------------------------
@dataclass(frozen=True)
class SizeCheck:
    """The verdict of one solver call: world sizes, 'sat'/'unsat'/'unknown', wall and CPU seconds."""

    n_a: int
    n_b: int
    verdict: str
    seconds: float
    cpu_seconds: float = 0.0

    def to_json(self) -> dict[str, Any]:
        return {"n_a": self.n_a, "n_b": self.n_b, "verdict": self.verdict, "seconds": round(self.seconds, 3),
                "cpu_seconds": round(self.cpu_seconds, 3)}


@dataclass
class SearchResult:
    """Outcome ``found`` | ``none`` | ``unknown`` with, when found, the re-checked witness."""

    outcome: str
    marker: str
    max_vertices: int
    max_degree: int
    seconds: float
    checks: list[SizeCheck] = field(default_factory=list)
    worlds: tuple[World, World] | None = None
    relation: frozenset | None = None
    motions: tuple[int, ...] | None = None
    perceptions: tuple[Signature, ...] | None = None
    reason: str = ""
    planar: bool = False

    @property
    def found(self) -> bool:
        return self.outcome == "found"

    def to_json(self) -> dict[str, Any]:
        from topomark.spec.worldfile import world_to_json

        out: dict[str, Any] = {
            "outcome": self.outcome, "found": self.found, "marker": self.marker,
            "max_vertices": self.max_vertices, "max_degree": self.max_degree, "planar": self.planar,
            "seconds": round(self.seconds, 3), "checks": [c.to_json() for c in self.checks],
        }
        if self.reason:
            out["reason"] = self.reason
        if self.found:
            out["worlds"] = [world_to_json(w) for w in self.worlds]
            out["relation"] = relation_to_json(self.relation)
            out["motions"] = list(self.motions)
            out["perceptions"] = [str(p) for p in self.perceptions]
        return out


@dataclass
class ProofReport:
    """A bounded proof attempt: ``proved`` | ``counterexample`` | ``unknown``."""

    outcome: str
    marker: str
    bounds: dict[str, int]
    symmetry_breaking: tuple[str, ...]
    solver: str
    seconds: float
    search: SearchResult

    @property
    def proved(self) -> bool:
        return self.outcome == "proved"

    def to_json(self) -> dict[str, Any]:
        out = self.search.to_json()
        out.update({"proof": self.outcome, "proved": self.proved, "bounds": self.bounds,
                    "symmetry_breaking": list(self.symmetry_breaking), "solver": self.solver,
                    "seconds": round(self.seconds, 3)})
        return out


def relation_to_json(relation) -> list[list[list[Any]]]:
    return [[list(p), list(q)] for p, q in sorted(relation)]


# -- small propositional helpers -------------------------------------------------
# Formulas are built as SMT-LIB text (literals are symbol names or Python bools) and
# handed to Z3 in one piece: far faster than one Python API call per clause.
class _Builder:
    """Collects declarations and assertions; one-hot variables are dicts value -> literal."""

    def __init__(self):
        self.decls: list[str] = []
        self.asserts: list[str] = []
        self._names: set[str] = set()

    @property
    def count(self) -> int:
        return len(self.asserts)

    def var(self, name: str) -> str:
        name = re.sub(r"[^A-Za-z0-9_]", "_", name)
        if name in self._names:
            raise CheckFailure(f"encoding bug: variable {name} declared twice")
        self._names.add(name)
        self.decls.append(f"(declare-const {name} Bool)")
        return name

    def add(self, *constraints) -> None:
        for c in constraints:
            if c is True:
                continue
            self.asserts.append(f"(assert {'false' if c is False else c})")

    def onehot(self, name: str, values: Iterable) -> dict:
        vs = {c: self.var(f"{name}_{c}") for c in values}
        lits = list(vs.values())
        self.add(_or(lits))
        if len(lits) > 1:
            self.asserts.append(f"(assert ((_ at-most 1) {' '.join(lits)}))")
        return vs

    def implies(self, premises: list, conclusion) -> None:
        """Clause: AND premises => conclusion (constant premises folded)."""
        ps = [p for p in premises if p is not True]
        if any(p is False for p in ps) or conclusion is True:
            return
        self.add(_or([_not(p) for p in ps] + [conclusion]))

    def text(self) -> str:
        return "\n".join(self.decls + self.asserts)


def _lit(onehot: dict, value):
    """The literal 'variable = value' (False if the value is outside the domain)."""
    return onehot.get(value, False)


def _connective(op: str, unit: bool, items):
    """``(op items...)`` simplified: ``unit`` items dropped, the absorbing ``not unit`` wins, arity 0/1 collapsed."""
    items = [x for x in items if x is not unit]
    if any(x is (not unit) for x in items):
        return not unit
    if not items:
        return unit
    return items[0] if len(items) == 1 else f"({op} {' '.join(items)})"


def _or(items):
    return _connective("or", False, items)


def _and(items):
    return _connective("and", True, items)


def _not(x):
    if isinstance(x, bool):
        return not x
    return x[5:-1] if x.startswith("(not ") else f"(not {x})"


def _iff(a, b):
    if isinstance(a, bool) and isinstance(b, bool):
        return a == b
    if isinstance(a, bool):
        return b if a else _not(b)
    if isinstance(b, bool):
        return a if b else _not(a)
    return f"(= {a} {b})"


# -- one world ----------------------------------------------------------------------
class _WorldVars:
    """The variables and constraints of one world with exactly ``n`` vertices (see module docstring)."""

    def __init__(self, b: _Builder, tag: str, n: int, dmax: int, marker: str, planar: bool = False):
        self.b, self.tag, self.n, self.D, self.marker = b, tag, n, dmax, marker
        V, D = range(n), range(dmax)
        self.deg = {v: b.onehot(f"{tag}deg{v}", range(1, dmax + 1)) for v in V}
        self.tv = {(v, i): b.onehot(f"{tag}tv{v},{i}", [NULL] + [w for w in V if w != v]) for v in V for i in D}
        self.te = {(v, i): b.onehot(f"{tag}te{v},{i}", D) for v in V for i in D}
        self._graph()
        self._bfs()
        self._marker_vars()
        self._steps()
        if planar:
            self._genus_zero()

    def exists(self, v: int, i: int):
        """Literal: exit i of v exists."""
        return _not(self.tv[v, i][NULL])

    def _graph(self) -> None:
        b, n, D = self.b, self.n, self.D
        for v in range(n):
            for i in range(D):
                b.add(_iff(self.tv[v, i][NULL], _or(self.deg[v][d] for d in range(1, i + 1))))
                b.implies([self.tv[v, i][NULL]], self.te[v, i][0])
                for w in range(n):
                    if w == v:
                        continue
                    for j in range(D):
                        prem = [self.tv[v, i][w], self.te[v, i][j]]
                        b.implies(prem, self.tv[w, j][v])
                        b.implies(prem, self.te[w, j][i])
                    for i2 in range(i + 1, D):
                        b.implies([self.tv[v, i][w], self.tv[v, i2][w]], False)

    def _bfs(self) -> None:
        b, n, D = self.b, self.n, self.D
        self.par = {}
        for v in range(1, n):
            self.par[v] = b.onehot(f"{self.tag}par{v}", [(u, i) for u in range(v) for i in range(D)])
            for (u, i), lit in self.par[v].items():
                b.implies([lit], self.tv[u, i][v])
                b.implies([lit], self.te[u, i][0])
                for u2 in range(u):
                    for i2 in range(D):
                        b.implies([lit], _not(self.tv[u2, i2][v]))
        for v in range(1, n - 1):
            for a, la in self.par[v].items():
                for c, lc in self.par[v + 1].items():
                    if a >= c:
                        b.implies([la, lc], False)

    def _marker_vars(self) -> None:
        b, n, D = self.b, self.n, self.D
        self.e = b.onehot(f"{self.tag}e", range(D)) if self.marker in _NEEDS_EXIT else None
        self.head0 = b.var(f"{self.tag}head0") if self.marker == "directional-edge" else None
        self.nb = {v: False for v in range(n)}  # v is the marked neighbour / other end of the marked edge
        self.mk = {(v, y): False for v in range(n) for y in range(D)}  # dart (v, y) carries the edge marker
        if self.e is None:
            return
        for x in range(D):
            b.implies([self.e[x]], self.exists(0, x))
        for v in range(1, n):
            self.nb[v] = b.var(f"{self.tag}nb{v}")
            b.add(_iff(self.nb[v], _or([_and([self.e[x], self.tv[0, x][v]]) for x in range(D)])))
        if self.marker in ("undirected-edge", "directional-edge", "vertex-and-edge"):
            for y in range(D):
                self.mk[0, y] = self.e[y]
            for v in range(1, n):
                for y in range(D):
                    self.mk[v, y] = b.var(f"{self.tag}mk{v},{y}")
                    b.add(_iff(self.mk[v, y], _or([_and([self.e[x], self.tv[0, x][v], self.te[0, x][y]])
                                                      for x in range(D)])))

    def _steps(self) -> None:
        """S[v,j,l]: the state reached from (v, j) by motion l (NULL vertex when l >= deg)."""
        b, n, D = self.b, self.n, self.D
        self.sv, self.se = {}, {}
        for v in range(n):
            for j in range(D):
                for l in range(D):
                    others = [NULL] + [w for w in range(n) if w != v]
                    sv = self.sv[v, j, l] = b.onehot(f"{self.tag}sv{v},{j},{l}", others)
                    se = self.se[v, j, l] = b.onehot(f"{self.tag}se{v},{j},{l}", range(D))
                    for d in range(1, D + 1):
                        dl = self.deg[v][d]
                        if l >= d:
                            b.implies([dl], sv[NULL])
                            b.implies([dl], se[0])
                            continue
                        x = (j + l) % d
                        for w, lit in self.tv[v, x].items():
                            if w in sv:
                                b.implies([dl, lit], sv[w])
                        for k in range(D):
                            b.implies([dl, self.te[v, x][k]], se[k])

    def _genus_zero(self) -> None:
        """Euler's formula n - m + f = 2 (a planar embedding, §3.1.1), with f counted by face labels.

        The face permutation is phi(v, i) = (w, j + 1) for target (w, j).  Every
        dart carries the label L of its face (constant along phi, at most its own
        index); the darts with L = own index are the representatives, and a rank
        that grows by one along phi except at a representative forces every face
        to contain one.  So f = number of representatives.
        """
        b, n, D = self.b, self.n, self.D
        darts = [(v, i) for v in range(n) for i in range(D)]
        idx = {d: k for k, d in enumerate(darts)}
        phw, phk, lab, rank, rep = {}, {}, {}, {}, {}
        for (v, i) in darts:
            phw[v, i] = self.tv[v, i]
            phk[v, i] = b.onehot(f"{self.tag}phk{v},{i}", range(D))
            for w, lw in self.tv[v, i].items():
                if w == NULL:
                    continue
                for d in range(1, D + 1):
                    for j in range(D):
                        b.implies([lw, self.deg[w][d], self.te[v, i][j]], phk[v, i][(j + 1) % d])
            b.implies([self.tv[v, i][NULL]], phk[v, i][0])
            lab[v, i] = b.onehot(f"{self.tag}lab{v},{i}", [NULL] + list(range(idx[v, i] + 1)))
            b.add(_iff(lab[v, i][NULL], self.tv[v, i][NULL]))
            rank[v, i] = b.onehot(f"{self.tag}rank{v},{i}", range(len(darts)))
            rep[v, i] = lab[v, i][idx[v, i]]
        for (v, i) in darts:
            for w, lw in phw[v, i].items():
                if w == NULL:
                    continue
                for k, lk in phk[v, i].items():
                    for c, lc in lab[v, i].items():
                        if c != NULL:
                            b.implies([lw, lk, lc], _lit(lab[w, k], c))
                    for r, lr in rank[v, i].items():
                        nxt = _lit(rank[w, k], r + 1)
                        b.implies([lw, lk, lr, _not(rep[w, k])], nxt)
        weights = [(2, rep[d]) for d in darts] + [(D - d, self.deg[v][d]) for v in range(n)
                                                   for d in range(1, D + 1) if D - d > 0]
        total = 4 - 2 * n + n * D
        coeffs = " ".join(str(c) for c, _ in weights)
        b.asserts.append(f"(assert ((_ pbeq {total} {coeffs}) {' '.join(l for _, l in weights)}))")

    # -- signature features (each a dict value -> literal/bool, exactly one true) --
    def features(self, v: int, j: int) -> list[dict]:
        """Everything but the degree that :func:`signature_at` reads at state (v, j)."""
        m, feats = self.marker, []
        if m in ("undirected-vertex", "directional-vertex", "vertex-and-edge"):
            feats.append({1: v == 0, 0: v != 0})
        elif m == "two-undirected-vertex":
            feats.append({1: True} if v == 0 else {1: self.nb[v], 0: _not(self.nb[v])})
        elif m == "three-undirected-vertex":
            feats.append({1: True} if v == 0 else {2: self.nb[v], 0: _not(self.nb[v])})
        if m == "directional-vertex":
            feats.append(self._relative(v, j, {y: self.e[y] for y in range(self.D)}) if v == 0 else {None: True})
        if m in ("undirected-edge", "directional-edge", "vertex-and-edge"):
            feats.append(self._relative(v, j, {y: self.mk[v, y] for y in range(self.D)}))
        if m == "directional-edge":
            if v == 0:
                feats.append({"H": self.head0, "T": _not(self.head0)})
            else:
                feats.append({"H": _and([self.nb[v], _not(self.head0)]), "T": _and([self.nb[v], self.head0]),
                              None: _not(self.nb[v])})
        return feats

    def _relative(self, v: int, j: int, marked: dict) -> dict:
        """Value (y - j) mod deg(v) of the marked exit y at v, None if no exit is marked."""
        out: dict = {None: _not(_or(marked.values()))}
        for c in range(self.D):
            out[c] = _or(_and([self.deg[v][d], marked[y]]) for d in range(1, self.D + 1)
                         for y in range(d) if (y - j) % d == c)
        return out


def _sig_equal(a: _WorldVars, p: tuple[int, int], bw: _WorldVars, q: tuple[int, int]):
    """Expression: the signature at A-state p equals the one at B-state q."""
    parts = [_iff(a.deg[p[0]][d], bw.deg[q[0]][d]) for d in range(1, a.D + 1)]
    for fa, fb in zip(a.features(*p), bw.features(*q)):
        parts += [_iff(fa.get(c, False), fb.get(c, False)) for c in set(fa) | set(fb)]
    return _and(parts)


# -- the pair ----------------------------------------------------------------------------
class _PairEncoding:
    """Bisimilar and non-isomorphic: worlds A (n_a vertices) and B (n_b vertices)."""

    def __init__(self, marker: str, n_a: int, n_b: int, dmax: int, planar: bool = False):
        self.b = _Builder()
        self.marker, self.D = marker, dmax
        self.A = _WorldVars(self.b, "A", n_a, dmax, marker, planar)
        self.B = _WorldVars(self.b, "B", n_b, dmax, marker, planar)
        self._sigcache: dict = {}
        self._relation()
        if n_a == n_b:
            self._non_isomorphic()

    def sig_eq(self, p, q):
        if (p, q) not in self._sigcache:
            expr = _sig_equal(self.A, p, self.B, q)
            if not isinstance(expr, bool):
                lit = self.b.var(f"SE{p},{q}")
                self.b.add(_iff(lit, expr))
                expr = lit
            self._sigcache[p, q] = expr
        return self._sigcache[p, q]

    def _relation(self) -> None:
        A, B, b, D = self.A, self.B, self.b, self.D
        sa = [(v, j) for v in range(A.n) for j in range(D)]
        sb = [(w, k) for w in range(B.n) for k in range(D)]
        self.R = {(p, q): self.b.var(f"R{p},{q}") for p in sa for q in sb}
        b.add(self.R[(0, 0), (0, 0)])
        for (p, q), r in self.R.items():
            b.implies([r], A.exists(*p))
            b.implies([r], B.exists(*q))
            b.implies([r], self.sig_eq(p, q))
        half = {(p2, q, l): self.b.var(f"H{p2},{q},{l}") for p2 in sa for q in sb for l in range(D)}
        for (p, q), r in self.R.items():
            for l in range(D):
                for v2, lv in A.sv[p[0], p[1], l].items():
                    if v2 == NULL:
                        continue
                    for j2, lj in A.se[p[0], p[1], l].items():
                        b.implies([r, lv, lj], half[(v2, j2), q, l])
        for ((p2, q, l), h) in half.items():
            for w2, lw in B.sv[q[0], q[1], l].items():
                if w2 == NULL:
                    b.implies([h, lw], False)  # the motion exists in A, so it must exist in B
                    continue
                for k2, lk in B.se[q[0], q[1], l].items():
                    b.implies([h, lw, lk], self.R[p2, (w2, k2)])

    # -- non-isomorphism by anchored propagation -------------------------------------
    def _anchors(self) -> Iterator[tuple[str, int]]:
        kind = _ANCHORS[self.marker]
        if kind == "start":
            yield (0, 0)
            return
        for k in range(self.D):
            if kind == "any":
                for w in range(self.B.n):
                    yield (w, k)
            else:
                yield (0, k)
                if kind == "pair":
                    yield ("other", k)

    def _non_isomorphic(self) -> None:
        for t, anchor in enumerate(self._anchors()):
            self.b.add(_or([self._excused(anchor)] + self._defects(t, anchor)))

    def _anchor_vertex(self, anchor):
        w0, _ = anchor
        return {w: (w == w0) if w0 != "other" else self.B.nb[w] for w in range(self.B.n)}

    def _excused(self, anchor):
        """The anchor is not a dart of B (its entry index is beyond the degree)."""
        B, (_, k0) = self.B, anchor
        return _or(_and([lit, _or(B.deg[w][d] for d in range(1, k0 + 1))])
                   for w, lit in self._anchor_vertex(anchor).items())

    def _defects(self, t: int, anchor) -> list:
        """Literals whose disjunction says: f_t (the propagation from ``anchor``) is not an isomorphism."""
        im = self._propagate(t, anchor)
        return self._signature_defects(im) + self._dart_defects(im) + self._collisions(im)

    def _propagate(self, t: int, anchor) -> dict:
        """One-hots of f_t: image (iw, ik) of each dart (v, 0), entry idk of each image dart, far end (rdw, rdk)."""
        A, B, b, D = self.A, self.B, self.b, self.D
        iw = {0: self._anchor_vertex(anchor)}
        ik = {0: {k: k == anchor[1] for k in range(D)}}
        for v in range(1, A.n):
            iw[v] = b.onehot(f"I{t}w{v}", range(B.n))
            ik[v] = b.onehot(f"I{t}k{v}", range(D))
        idk, rdw, rdk = {}, {}, {}
        for u in range(A.n):
            imdeg = b.onehot(f"I{t}deg{u}", range(1, D + 1))
            for w, lw in iw[u].items():
                for d in range(1, D + 1):
                    b.implies([lw, B.deg[w][d]], imdeg[d])
            for i in range(D):
                idk[u, i] = b.onehot(f"I{t}dk{u},{i}", range(D))
                for k, lk in ik[u].items():
                    for d in range(1, D + 1):
                        b.implies([lk, imdeg[d]], idk[u, i][(k + i) % d])
                rdw[u, i], rdk[u, i] = self._far_end(f"I{t}r{u},{i}", iw[u], idk[u, i])
        for v in range(1, A.n):  # the tree edge: (v, 0) maps to the far end of its parent dart's image
            for (u, i), lp in A.par[v].items():
                for w2, l2 in rdw[u, i].items():
                    if w2 != NULL:
                        b.implies([lp, l2], iw[v][w2])
                for k2, l2 in rdk[u, i].items():
                    b.implies([lp, l2], ik[v][k2])
        return {"iw": iw, "ik": ik, "idk": idk, "rdw": rdw, "rdk": rdk}

    def _far_end(self, name: str, vertex: dict, entry: dict) -> tuple[dict, dict]:
        """One-hots for target((vertex, entry)) in B (NULL vertex if that dart does not exist)."""
        B, b, D = self.B, self.b, self.D
        rw = b.onehot(f"{name}w", [NULL] + list(range(B.n)))
        rk = b.onehot(f"{name}k", range(D))
        for w, lw in vertex.items():
            for y in range(D):
                for w2, l2 in B.tv[w, y].items():
                    b.implies([lw, entry[y], l2], rw[w2])
                for k2 in range(D):
                    b.implies([lw, entry[y], B.te[w, y][k2]], rk[k2])
        return rw, rk

    def _signature_defects(self, im: dict) -> list:
        """(a) degree or markers not preserved: sig(v, 0) differs from the sig of its image state."""
        return [_and([lw, lk, _not(self.sig_eq((v, 0), (w, k)))])
                for v in range(self.A.n) for w, lw in im["iw"][v].items() for k, lk in im["ik"][v].items()]

    def _dart_defects(self, im: dict) -> list:
        """(b) a dart of A whose far end's image is not the far end of its image."""
        A, D, out = self.A, self.D, []
        for v in range(A.n):
            for i in range(D):
                rdw, rdk = im["rdw"][v, i], im["rdk"][v, i]
                for v2, lv in A.tv[v, i].items():
                    if v2 == NULL:
                        continue
                    for j2, lj in A.te[v, i].items():
                        mism = _or([_and([rdw[w], _not(_lit(im["iw"][v2], w))]) for w in rdw] +
                                   [_and([rdk[k], _not(im["idk"][v2, j2][k])]) for k in range(D)])
                        out.append(_and([lv, lj, mism]))
        return out

    def _collisions(self, im: dict) -> list:
        """(c) two vertices of A with the same image vertex."""
        iw = im["iw"]
        return [_and([iw[v][w], iw[v2][w]]) for v, v2 in itertools.combinations(range(self.A.n), 2)
                for w in range(self.B.n)]


# -- decoding and re-checking -------------------------------------------------------------
def _true(model: z3.ModelRef, lit) -> bool:
    return lit if isinstance(lit, bool) else z3.is_true(model.eval(z3.Bool(lit), model_completion=True))


def _value(model: z3.ModelRef, onehot: dict):
    hits = [c for c, lit in onehot.items() if _true(model, lit)]
    if len(hits) != 1:
        raise CheckFailure(f"z3 model violates a one-hot constraint: {hits}")
    return hits[0]


def _name(v: int) -> str:
    return f"v{v}"


def _decode_world(model: z3.ModelRef, wv: _WorldVars) -> World:
    rotation = {}
    for v in range(wv.n):
        d = _value(model, wv.deg[v])
        rotation[_name(v)] = [_name(_value(model, wv.tv[v, i])) for i in range(d)]
    v0 = _name(0)
    markers: list = []
    m = wv.marker
    other = _name(_value(model, wv.tv[0, _value(model, wv.e)])) if wv.e is not None else None
    if m in ("undirected-vertex", "two-undirected-vertex", "three-undirected-vertex", "vertex-and-edge"):
        markers.append(VertexMarker(v0))
    if m == "directional-vertex":
        markers.append(VertexMarker(v0, 1, other))
    if m == "two-undirected-vertex":
        markers.append(VertexMarker(other))
    if m == "three-undirected-vertex":
        markers.append(VertexMarker(other, 2))
    if m in ("undirected-edge", "vertex-and-edge"):
        markers.append(EdgeMarker((v0, other)))
    if m == "directional-edge":
        markers.append(EdgeMarker((v0, other), 1, v0 if _true(model, wv.head0) else other))
    return World(rotation, markers, Start(v0, rotation[v0][0]))


def decode_pair(model: z3.ModelRef, enc: _PairEncoding) -> tuple[World, World, frozenset]:
    """The two worlds and the relation R of a model (states named as in the worlds)."""
    a, b = _decode_world(model, enc.A), _decode_world(model, enc.B)
    rel = frozenset(((_name(p[0]), p[1]), (_name(q[0]), q[1])) for (p, q), lit in enc.R.items()
                    if _true(model, lit))
    return a, b, rel


def reachable_relation(a: World, b: World) -> frozenset:
    """The pairs of states reachable from the two starts by common motions (the least bisimulation)."""
    start = (a.start_state(), b.start_state())
    seen, todo = {start}, deque([start])
    while todo:
        p, q = todo.popleft()
        if a.degree(p[0]) != b.degree(q[0]):
            continue
        for l in range(a.degree(p[0])):
            nxt = (step(a, p, l), step(b, q, l))
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return frozenset(seen)


def covering_walk(a: World, b: World) -> tuple[tuple[int, ...], tuple[Signature, ...]]:
    """A common motion sequence whose walk enters every state of both worlds, and its perceptions in A."""
    start = (a.start_state(), b.start_state())
    missing = {s for s in _states(a)} | {("B", s) for s in _states(b)}
    cur, motions = start, []

    def mark(pair):
        missing.discard(pair[0])
        missing.discard(("B", pair[1]))

    mark(cur)
    while missing:
        path = _path_to_new(a, b, cur, missing)
        if path is None:
            raise CheckFailure("the related pairs do not cover both worlds")
        for l in path:
            cur = (step(a, cur[0], l), step(b, cur[1], l))
            motions.append(l)
            mark(cur)
    seq = tuple(motions)
    from topomark.spec.robot import perceive
    return seq, tuple(perceive(a, a.start_state(), seq))


def _states(w: World):
    return [(v, j) for v in w.vertices for j in range(w.degree(v))]


def _path_to_new(a, b, cur, missing):
    prev = {cur: None}
    todo = deque([cur])
    while todo:
        pair = todo.popleft()
        if pair[0] in missing or ("B", pair[1]) in missing:
            path = []
            while prev[pair] is not None:
                pair, l = prev[pair]
                path.append(l)
            return path[::-1]
        for l in range(a.degree(pair[0][0])):
            nxt = (step(a, pair[0], l), step(b, pair[1], l))
            if nxt not in prev:
                prev[nxt] = (pair, l)
                todo.append(nxt)
    return None


def recheck(marker: str, a: World, b: World, relation: frozenset) -> None:
    """Re-check a decoded pair with the specification's predicates; CheckFailure if anything fails."""
    from . import bisim

    cls = MARKER_CLASSES[marker]
    for name, w in (("A", a), ("B", b)):
        if w not in set(cls.placements(World(w.rotation))):
            raise CheckFailure(f"decoded world {name} does not carry the {marker} markers and start: {w!r}")
    iso = find_isomorphism(a, b, markers=True)
    if iso.isomorphic:
        raise CheckFailure(f"decoded worlds are extended-isomorphic ({iso.witness.to_json()}), not a counterexample")
    violation = bisim.check_relation(a, b, relation)
    if violation is not None:
        raise CheckFailure(f"decoded relation is not a bisimulation: {violation}")
    dist = bisim.distinguishing_sequence(a, b)
    if dist is not None:
        raise CheckFailure(f"decoded worlds are distinguished by motions {list(dist.motions)}")
    for p, q in relation:
        if sense(a, p) != sense(b, q):
            raise CheckFailure(f"related states {p} and {q} have different signatures")


# -- fixing a given pair (to test the encoding on the thesis figures) ----------------------
def canonical_labelling(world: World) -> tuple[dict[str, int], dict[str, int]]:
    """The BFS numbering of the symmetry breaking and, per vertex, the rotation shift making exit 0 canonical."""
    at, facing = world.start_state()
    order, shift, queue = {at: 0}, {at: facing}, deque([at])
    while queue:
        u = queue.popleft()
        d = world.degree(u)
        for i in range(d):
            w = world.neighbour(u, (i + shift[u]) % d)
            if w not in order:
                order[w], shift[w] = len(order), world.index(w, u)
                queue.append(w)
    return order, shift


def _other_marked(world: World) -> str | None:
    """The vertex the exit variable e of vertex 0 leads to (head, marked neighbour, far end of the marked edge)."""
    at = world.start.at
    for m in world.markers:
        if isinstance(m, EdgeMarker):
            return m.between[1] if m.between[0] == at else m.between[0]
        if m.points_to is not None:
            return m.points_to
        if m.at != at:
            return m.at
    return None


def _fixing_literals(wv: _WorldVars, world: World) -> list[str]:
    """Literals that pin the variables of ``wv`` to ``world`` (in its canonical labelling)."""
    order, shift = canonical_labelling(world)
    lits = []
    for v, k in order.items():
        d = world.degree(v)
        lits.append(wv.deg[k][d])
        for i in range(d):
            w = world.neighbour(v, (i + shift[v]) % d)
            lits += [wv.tv[k, i][order[w]], wv.te[k, i][(world.index(w, v) - shift[w]) % world.degree(w)]]
    other = _other_marked(world)
    if wv.e is not None and other is not None:
        at, d0 = world.start.at, world.degree(world.start.at)
        lits.append(wv.e[next(i for i in range(d0) if world.neighbour(at, (i + shift[at]) % d0) == other)])
    if wv.head0 is not None:
        head = next(m.head for m in world.markers if isinstance(m, EdgeMarker))
        lits.append(wv.head0 if head == world.start.at else _not(wv.head0))
    return [x for x in lits if x is not True]


def pair_is_model(marker: str, a: World, b: World, planar: bool = False) -> str:
    """'sat' if the encoding accepts exactly this pair as a counterexample, else 'unsat' (or 'unknown').

    Both worlds must carry the class's markers and a start; the D bound is their
    largest degree.  Used to test the encoding on the thesis's figure pairs.
    """
    dmax = max(w.degree(v) for w in (a, b) for v in w.vertices)
    enc = _PairEncoding(marker, a.n, b.n, dmax, planar)
    solver = z3.SolverFor("QF_FD")
    solver.from_string(enc.b.text())
    lits = _fixing_literals(enc.A, a) + _fixing_literals(enc.B, b)
    if any(x is False for x in lits):
        return "unsat"
    return str(solver.check([z3.Not(z3.Bool(x[5:-1])) if x.startswith("(not ") else z3.Bool(x) for x in lits]))


# -- driver ---------------------------------------------------------------------------
def size_pairs(max_vertices: int, min_vertices: int = 2) -> list[tuple[int, int]]:
    """Size pairs n_A <= n_B in the order searched: smaller largest world first, then smaller total."""
    pairs = [(x, y) for x in range(min_vertices, max_vertices + 1) for y in range(x, max_vertices + 1)]
    return sorted(pairs, key=lambda p: (p[1], p[0] + p[1], p[0]))


def _validate(marker: str, max_vertices: int, max_degree: int, min_vertices: int) -> None:
    marker_class(marker)
    if not isinstance(max_vertices, int) or max_vertices < 2:
        raise InvalidInput(f"--max-vertices must be an integer >= 2 (a world has at least 2 vertices), "
                           f"got {max_vertices!r}")
    if max_vertices > MAX_VERTICES:
        raise InvalidInput(f"--max-vertices {max_vertices} is too large for the solver (at most {MAX_VERTICES})")
    if not isinstance(max_degree, int) or max_degree < 1:
        raise InvalidInput(f"--max-degree must be an integer >= 1, got {max_degree!r}")
    if not isinstance(min_vertices, int) or not 2 <= min_vertices <= max_vertices:
        raise InvalidInput(f"min_vertices must be between 2 and {max_vertices}, got {min_vertices!r}")


def _check_pair(marker, n_a, n_b, dmax, remaining, planar=False):
    started = time.monotonic()
    enc = _PairEncoding(marker, n_a, n_b, dmax, planar)
    solver = z3.SolverFor("QF_FD")
    if remaining is not None:
        left = remaining - (time.monotonic() - started)
        if left <= 0:
            return z3.unknown, None, enc
        solver.set("timeout", max(1, int(left * 1000)))
    solver.from_string(enc.b.text())
    verdict = solver.check()
    return verdict, solver, enc


def search(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
           min_vertices: int = 2, planar: bool = False) -> SearchResult:
    """Look for a counterexample of ``marker`` with at most ``max_vertices`` vertices and degree ``max_degree``.

    Size pairs are tried smallest first, so a ``found`` pair is smallest in
    the larger world's size.  ``timeout`` (seconds) bounds the whole search.
    With ``planar=True`` both worlds must be planar embeddings (genus 0, like
    the thesis's drawings); by default any orientable embedding is allowed
    (§3.1.1: "not necessarily a planar surface").
    """
    _validate(marker, max_vertices, max_degree, min_vertices)
    t0 = time.monotonic()
    result = SearchResult("none", marker, max_vertices, max_degree, 0.0, planar=planar)
    for n_a, n_b in size_pairs(max_vertices, min_vertices):
        remaining = None if timeout is None else timeout - (time.monotonic() - t0)
        if remaining is not None and remaining <= 0:
            result.outcome, result.reason = "unknown", "timeout"
            break
        t1, c1 = time.monotonic(), time.process_time()
        dmax = min(max_degree, n_b - 1)  # a simple graph on n_b vertices has no larger degree
        verdict, solver, enc = _check_pair(marker, n_a, n_b, dmax, remaining, planar)
        result.checks.append(SizeCheck(n_a, n_b, str(verdict), time.monotonic() - t1, time.process_time() - c1))
        if verdict == z3.sat:
            _fill_found(result, marker, solver.model(), enc, planar)
            break
        if verdict == z3.unknown:
            why = solver.reason_unknown() if solver is not None else "timeout"
            result.outcome, result.reason = "unknown", "timeout" if "timeout" in why or "canceled" in why else why
            if remaining is not None:
                break
    result.seconds = time.monotonic() - t0
    return result


def _fill_found(result: SearchResult, marker: str, model, enc, planar: bool = False) -> None:
    a, b, rel = decode_pair(model, enc)
    if planar and (a.genus(), b.genus()) != (0, 0):
        raise CheckFailure(f"decoded worlds have genus {a.genus()} and {b.genus()}, not planar")
    recheck(marker, a, b, rel)
    reach = reachable_relation(a, b)
    recheck(marker, a, b, reach)
    motions, perceptions = covering_walk(a, b)
    from topomark.spec.robot import perceive
    if list(perceptions) != perceive(b, b.start_state(), motions):
        raise CheckFailure("the covering walk perceives differently in the two worlds")
    result.outcome, result.reason = "found", ""
    result.worlds, result.relation = (a, b), reach
    result.motions, result.perceptions = motions, perceptions


def prove(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
          planar: bool = False) -> ProofReport:
    """Show there is no counterexample for ``marker`` within the bounds (UNSAT for every size pair)."""
    t0 = time.monotonic()
    res = search(marker, max_vertices, max_degree, timeout, planar=planar)
    outcome = {"none": "proved", "found": "counterexample", "unknown": "unknown"}[res.outcome]
    bounds = {"max_vertices": max_vertices, "max_degree": max_degree, "min_vertices": 2,
              "size_pairs": len(size_pairs(max_vertices)), "planar_only": planar}
    return ProofReport(outcome, marker, bounds, SYMMETRY_BREAKING, f"z3 {z3.get_version_string()}",
                       time.monotonic() - t0, res)
