"""The pair encoding of the Z3 search: two worlds indistinguishable but not extended-isomorphic (thesis §3.1.1, §3.1.3, §3.2).

One :class:`PairEncoding` per size pair n_A <= n_B (the relation is
symmetric): two :class:`~topomark.proofs.z3world.WorldVars` sharing one
formula builder, plus the two properties below.

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
"""

from __future__ import annotations

import itertools
from typing import Iterator

from topomark.proofs.z3formula import Builder, and_, iff, literal, not_, or_
from topomark.proofs.z3markers import sig_equal
from topomark.proofs.z3world import NULL, WorldVars

__all__ = ["PairEncoding"]  # for the z3search modules

# which vertex of B an isomorphism may send A's start vertex to
_ANCHORS = {
    "none": "any", "undirected-vertex": "same", "directional-vertex": "start",
    "two-undirected-vertex": "pair", "three-undirected-vertex": "start", "undirected-edge": "pair",
    "directional-edge": "start", "vertex-and-edge": "start",
}


class PairEncoding:
    """Bisimilar and non-isomorphic: worlds A (n_a vertices) and B (n_b vertices)."""

    def __init__(self, marker: str, n_a: int, n_b: int, dmax: int, planar: bool = False):
        self.b = Builder()
        self.marker, self.D = marker, dmax
        self.A = WorldVars(self.b, "A", n_a, dmax, marker, planar)
        self.B = WorldVars(self.b, "B", n_b, dmax, marker, planar)
        self._sigcache: dict = {}
        self._relation()
        if n_a == n_b:
            self._non_isomorphic()

    def sig_eq(self, p, q):
        if (p, q) not in self._sigcache:
            expr = sig_equal(self.A, p, self.B, q)
            if not isinstance(expr, bool):
                lit = self.b.var(f"SE{p},{q}")
                self.b.add(iff(lit, expr))
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
    def _anchors(self) -> Iterator[tuple[int | str, int]]:  # (B vertex or "other", exit)
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
            self.b.add(or_([self._excused(anchor)] + self._defects(t, anchor)))

    def _anchor_vertex(self, anchor):
        w0, _ = anchor
        return {w: (w == w0) if w0 != "other" else self.B.nb[w] for w in range(self.B.n)}

    def _excused(self, anchor):
        """The anchor is not a dart of B (its entry index is beyond the degree)."""
        B, (_, k0) = self.B, anchor
        return or_(and_([lit, or_(B.deg[w][d] for d in range(1, k0 + 1))])
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
        return [and_([lw, lk, not_(self.sig_eq((v, 0), (w, k)))])
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
                        mism = or_([and_([rdw[w], not_(literal(im["iw"][v2], w))]) for w in rdw] +
                                   [and_([rdk[k], not_(im["idk"][v2, j2][k])]) for k in range(D)])
                        out.append(and_([lv, lj, mism]))
        return out

    def _collisions(self, im: dict) -> list:
        """(c) two vertices of A with the same image vertex."""
        iw = im["iw"]
        return [and_([iw[v][w], iw[v2][w]]) for v, v2 in itertools.combinations(range(self.A.n), 2)
                for w in range(self.B.n)]
