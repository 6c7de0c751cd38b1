"""Decoding and re-checking a model of the Z3 search (thesis §3.1.1, §3.1.3, §3.2).

Every model is decoded into two :class:`World` objects and re-checked with
the specification's own predicates (World validation, class placement,
:func:`find_isomorphism`, :mod:`topomark.proofs.bisim`); a failure raises
:class:`CheckFailure` because it means this encoding is wrong.  The reported
relation is the reachable product of the two starts (the least
bisimulation), and the reported motion sequence is a common walk entering
every state of both worlds, with the perception sequence both produce.

:func:`reachable_relation` and :func:`covering_walk` compute the reported
relation and motion sequence of a :class:`~topomark.proofs.z3results.SearchResult`.
"""

from __future__ import annotations

from collections import deque

import z3

from topomark.spec.errors import CheckFailure
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.spec.robot import sense, step
from topomark.spec.signature import Signature
from topomark.spec.world import Start, World

from topomark.proofs.z3pair import PairEncoding
from topomark.proofs.z3world import WorldVars

__all__ = ["decode_pair", "reachable_relation", "covering_walk", "recheck"]


def _true(model: z3.ModelRef, lit) -> bool:
    return lit if isinstance(lit, bool) else z3.is_true(model.eval(z3.Bool(lit), model_completion=True))


def _value(model: z3.ModelRef, onehot: dict):
    hits = [c for c, lit in onehot.items() if _true(model, lit)]
    if len(hits) != 1:
        raise CheckFailure(f"z3 model violates a one-hot constraint: {hits}")
    return hits[0]


def _name(v: int) -> str:
    return f"v{v}"


def _decode_world(model: z3.ModelRef, wv: WorldVars) -> World:
    rotation = {}
    for v in range(wv.n):
        d = _value(model, wv.deg[v])
        rotation[_name(v)] = [_name(_value(model, wv.tv[v, i])) for i in range(d)]
    v0 = _name(0)
    markers: list = []
    m = wv.marker
    if m in ("undirected-vertex", "two-undirected-vertex", "three-undirected-vertex", "vertex-and-edge"):
        markers.append(VertexMarker(v0))
    if wv.e is None:  # every other class has the exit variable e (z3markers._NEEDS_EXIT)
        return World(rotation, markers, Start(v0, rotation[v0][0]))
    other = _name(_value(model, wv.tv[0, _value(model, wv.e)]))
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


def decode_pair(model: z3.ModelRef, enc: PairEncoding) -> tuple[World, World, frozenset]:
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
    from topomark.proofs import bisim

    cls = MARKER_CLASSES[marker]
    for name, w in (("A", a), ("B", b)):
        if w not in set(cls.placements(World(w.rotation))):
            raise CheckFailure(f"decoded world {name} does not carry the {marker} markers and start: {w!r}")
    iso = find_isomorphism(a, b, markers=True)
    if iso.isomorphic:
        raise CheckFailure(f"decoded worlds are extended-isomorphic ({iso.witness and iso.witness.to_json()}), "
                           "not a counterexample")
    violation = bisim.check_relation(a, b, relation)
    if violation is not None:
        raise CheckFailure(f"decoded relation is not a bisimulation: {violation}")
    dist = bisim.distinguishing_sequence(a, b)
    if dist is not None:
        raise CheckFailure(f"decoded worlds are distinguished by motions {list(dist.motions)}")
    for p, q in relation:
        if sense(a, p) != sense(b, q):
            raise CheckFailure(f"related states {p} and {q} have different signatures")
