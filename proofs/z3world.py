"""The world encoding of the Z3 search: one world with exactly n vertices as Boolean variables (thesis §3.1.1, §3.2).

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
connectivity.  The markers are placed at vertex 0 as described in
:mod:`topomark.proofs.z3markers`.

*Motions.*  One-hot ``sv[v,j,l]``/``se[v,j,l]``: the state reached from
(v, j) by motion l (NULL vertex when l >= deg), used by the
indistinguishability relation of :mod:`topomark.proofs.z3pair`.

*Planarity (optional).*  The thesis allows any embedding ("not necessarily a
planar surface", §3.1.1), so by default a world may have any genus; with
``planar=True`` it also satisfies Euler's formula n - m + f = 2,
where the faces f are counted through a face label per dart (constant along
the face permutation, a representative per face forced by a rank) and a
pseudo-Boolean equation.
"""

from __future__ import annotations

from topomark.proofs.z3formula import Builder, iff, literal, not_, or_
from topomark.proofs.z3markers import MarkerVars

__all__ = ["WorldVars"]  # for the z3search modules

NULL = -1


class WorldVars(MarkerVars):
    """The variables and constraints of one world with exactly ``n`` vertices (see module docstring)."""

    def __init__(self, b: Builder, tag: str, n: int, dmax: int, marker: str, planar: bool = False):
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
        return not_(self.tv[v, i][NULL])

    def _graph(self) -> None:
        b, n, D = self.b, self.n, self.D
        for v in range(n):
            for i in range(D):
                b.add(iff(self.tv[v, i][NULL], or_(self.deg[v][d] for d in range(1, i + 1))))
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
                        b.implies([lit], not_(self.tv[u2, i2][v]))
        for v in range(1, n - 1):
            for a, la in self.par[v].items():
                for c, lc in self.par[v + 1].items():
                    if a >= c:
                        b.implies([la, lc], False)


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
            b.add(iff(lab[v, i][NULL], self.tv[v, i][NULL]))
            rank[v, i] = b.onehot(f"{self.tag}rank{v},{i}", range(len(darts)))
            rep[v, i] = lab[v, i][idx[v, i]]
        for (v, i) in darts:
            for w, lw in phw[v, i].items():
                if w == NULL:
                    continue
                for k, lk in phk[v, i].items():
                    for c, lc in lab[v, i].items():
                        if c != NULL:
                            b.implies([lw, lk, lc], literal(lab[w, k], c))
                    for r, lr in rank[v, i].items():
                        nxt = literal(rank[w, k], r + 1)
                        b.implies([lw, lk, lr, not_(rep[w, k])], nxt)
        weights = [(2, rep[d]) for d in darts] + [(D - d, self.deg[v][d]) for v in range(n)
                                                   for d in range(1, D + 1) if D - d > 0]
        total = 4 - 2 * n + n * D
        coeffs = " ".join(str(c) for c, _ in weights)
        b.asserts.append(f"(assert ((_ pbeq {total} {coeffs}) {' '.join(l for _, l in weights)}))")

