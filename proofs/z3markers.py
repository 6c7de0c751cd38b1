"""The marker encoding of the Z3 search: where a class's markers sit and what the robot senses (thesis §3.1.1, §3.2, §3.7, §6.1).

Part of the symmetry breaking of :mod:`topomark.proofs.z3world`: the class's
markers sit at the start vertex 0; a variable exit ``e`` of vertex 0 says
where the directional head, the marked neighbour (vertices 0 and ``tv[0,e]``
for two/three undirected markers) or the marked edge (0, tv[0,e]) is;
``head0`` says whether a directional edge marker points at vertex 0.

The *features* of a state (v, j) are everything but the degree that
:func:`~topomark.spec.signature.signature_at` reads there (vertex-marker
count, ``V-dir``, ``E-p`` position and H/T), each a one-hot dict value ->
literal; :func:`sig_equal` says two states have equal signatures, as the
indistinguishability relation of :mod:`topomark.proofs.z3pair` requires.
"""

from __future__ import annotations

from typing import Any, Callable

from topomark.proofs.z3formula import and_, iff, not_, or_

__all__ = ["MarkerVars", "sig_equal"]  # for the z3search modules

_NEEDS_EXIT = {"directional-vertex", "two-undirected-vertex", "three-undirected-vertex", "undirected-edge",
               "directional-edge", "vertex-and-edge"}


class MarkerVars:
    """The marker variables ``e``, ``head0``, ``nb``, ``mk`` of a world and its signature features.

    A mixin of :class:`~topomark.proofs.z3world.WorldVars`, which supplies the
    builder ``b``, ``n``, ``D``, ``marker``, ``deg``, ``tv``, ``te`` and ``exists``.
    """

    # supplied by WorldVars (z3 expressions are untyped)
    b: Any
    tag: str
    n: int
    D: int
    marker: str
    deg: dict[int, dict[int, Any]]
    tv: dict[tuple[int, int], dict[int, Any]]
    te: dict[tuple[int, int], dict[int, Any]]
    exists: Callable[[int, int], Any]

    def _marker_vars(self) -> None:
        b, n, D = self.b, self.n, self.D
        self.e: dict[int, Any] | None = b.onehot(f"{self.tag}e", range(D)) if self.marker in _NEEDS_EXIT else None
        self.head0 = b.var(f"{self.tag}head0") if self.marker == "directional-edge" else None
        self.nb: dict[int, Any] = {v: False for v in range(n)}  # v is the marked neighbour / other end of the marked edge
        self.mk: dict[tuple[int, int], Any] = {(v, y): False for v in range(n) for y in range(D)}  # dart (v, y) carries the edge marker
        e = self.e
        if e is None:
            return
        for x in range(D):
            b.implies([e[x]], self.exists(0, x))
        for v in range(1, n):
            self.nb[v] = b.var(f"{self.tag}nb{v}")
            b.add(iff(self.nb[v], or_([and_([e[x], self.tv[0, x][v]]) for x in range(D)])))
        if self.marker in ("undirected-edge", "directional-edge", "vertex-and-edge"):
            for y in range(D):
                self.mk[0, y] = e[y]
            for v in range(1, n):
                for y in range(D):
                    self.mk[v, y] = b.var(f"{self.tag}mk{v},{y}")
                    b.add(iff(self.mk[v, y], or_([and_([e[x], self.tv[0, x][v], self.te[0, x][y]])
                                                      for x in range(D)])))

    # -- signature features (each a dict value -> literal/bool, exactly one true) --
    def features(self, v: int, j: int) -> list[dict[Any, Any]]:
        """Everything but the degree that :func:`signature_at` reads at state (v, j)."""
        m, e = self.marker, self.e
        feats: list[dict[Any, Any]] = []
        if m in ("undirected-vertex", "directional-vertex", "vertex-and-edge"):
            feats.append({1: v == 0, 0: v != 0})
        elif m == "two-undirected-vertex":
            feats.append({1: True} if v == 0 else {1: self.nb[v], 0: not_(self.nb[v])})
        elif m == "three-undirected-vertex":
            feats.append({1: True} if v == 0 else {2: self.nb[v], 0: not_(self.nb[v])})
        if m == "directional-vertex":
            assert e is not None, "a directional vertex marker has its exit"
            feats.append(self._relative(v, j, {y: e[y] for y in range(self.D)}) if v == 0 else {None: True})
        if m in ("undirected-edge", "directional-edge", "vertex-and-edge"):
            feats.append(self._relative(v, j, {y: self.mk[v, y] for y in range(self.D)}))
        if m == "directional-edge":
            if v == 0:
                feats.append({"H": self.head0, "T": not_(self.head0)})
            else:
                feats.append({"H": and_([self.nb[v], not_(self.head0)]), "T": and_([self.nb[v], self.head0]),
                              None: not_(self.nb[v])})
        return feats

    def _relative(self, v: int, j: int, marked: dict[int, Any]) -> dict[int | None, Any]:
        """Value (y - j) mod deg(v) of the marked exit y at v, None if no exit is marked."""
        out: dict[int | None, Any] = {None: not_(or_(marked.values()))}
        for c in range(self.D):
            out[c] = or_(and_([self.deg[v][d], marked[y]]) for d in range(1, self.D + 1)
                         for y in range(d) if (y - j) % d == c)
        return out


def sig_equal(a: MarkerVars, p: tuple[int, int], bw: MarkerVars, q: tuple[int, int]):
    """Expression: the signature at A-state p equals the one at B-state q."""
    parts = [iff(a.deg[p[0]][d], bw.deg[q[0]][d]) for d in range(1, a.D + 1)]
    for fa, fb in zip(a.features(*p), bw.features(*q)):
        parts += [iff(fa.get(c, False), fb.get(c, False)) for c in set(fa) | set(fb)]
    return and_(parts)

