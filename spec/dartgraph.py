"""Extended isomorphism, second implementation: the dart graph on networkx (§3.1.3).

Independent of :mod:`topomark.spec.isomorphism`.  Each dart ``(v, i)`` of an
embedded graph becomes a node; a ``"rot"`` arc goes to the next exit
clockwise ``(v, i + 1 mod deg)`` and a ``"rev"`` arc to the reverse dart at the
other end of the edge.  Node labels carry the degree and the marks seen from
that dart.  A label- and arc-kind-preserving isomorphism of dart graphs maps
each vertex's rotation cycle onto a rotation cycle in order (so onto a cyclic
rotation of its exits) and each edge onto an edge: exactly an extended
isomorphism.  networkx's VF2 (``DiGraphMatcher``) decides it.

Examples
--------
>>> from topomark.spec.world import World
>>> a = World({"x": ["y", "z"], "y": ["z", "x"], "z": ["x", "y"]})
>>> find_isomorphism_nx(a, a).isomorphic
True
"""

from __future__ import annotations

from typing import Any

import networkx as nx
from networkx.algorithms.isomorphism import DiGraphMatcher

from topomark.spec.errors import Violation
from topomark.spec.isomorphism import IsoResult, Witness
from topomark.spec.signature import Embedded, signature_at

__all__ = ["dart_graph", "find_isomorphism_nx"]


def _label(g: Embedded, v: Any, i: int, markers: bool) -> tuple[Any, ...]:
    """What a robot entering ``v`` by exit ``i`` senses (:func:`~topomark.spec.signature.signature_at`), or
    only the degree when markers are ignored: an extended isomorphism maps darts to darts of equal label."""
    if not markers:
        return (g.degree(v),)
    return (signature_at(g, v, i),)


def dart_graph(g: Embedded, markers: bool = True) -> nx.DiGraph[tuple[Any, int]]:
    """The labelled dart graph of a complete world or map."""
    dg: nx.DiGraph[tuple[Any, int]] = nx.DiGraph()
    for v in g.vertices:
        for i in range(g.degree(v)):
            dg.add_node((v, i), label=_label(g, v, i, markers))
    for v in g.vertices:
        d = g.degree(v)
        for i in range(d):
            dg.add_edge((v, i), (v, (i + 1) % d), kind="rot")
            dg.add_edge((v, i), g.arc((v, i)), kind="rev")
    return dg


def find_isomorphism_nx(a: Embedded, b: Embedded, markers: bool = True) -> IsoResult:
    """Decide extended isomorphism by VF2 on dart graphs; the witness is read off (v, 0)'s image."""
    ga, gb = dart_graph(a, markers), dart_graph(b, markers)
    matcher = DiGraphMatcher(
        ga, gb,
        node_match=lambda x, y: x["label"] == y["label"],
        edge_match=lambda x, y: x["kind"] == y["kind"],
    )
    if not matcher.is_isomorphic():
        return IsoResult(False, mismatch=Violation(
            "extended isomorphism (dart graph)", "dart graphs", "an isomorphism of the labelled dart graphs",
            "none exists"))
    vertex_map: dict[Any, Any] = {}
    offsets: dict[Any, int] = {}
    for v in a.vertices:
        w, k = matcher.mapping[(v, 0)]
        vertex_map[v], offsets[v] = w, k
    return IsoResult(True, Witness(vertex_map, offsets), mapped=len(vertex_map))
