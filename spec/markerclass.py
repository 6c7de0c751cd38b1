"""Marker classes: a kit placed in a world — which markers the world carries and where the robot starts
(thesis §3.2, §3.3, Figure 3.21, §6.1–6.2).

Searches and the census range over every world, every placement of the
class's markers and every starting exit; :meth:`MarkerClass.placements`
enumerates exactly those.

=========================  ==========================================================  ==========
name                       markers and start                                           thesis
=========================  ==========================================================  ==========
none                       no marker; start anywhere                                   §3.2.1, Fig 3.3
undirected-vertex          one undirected marker at the start vertex                   §3.2.2, Fig 3.4
directional-vertex         one directional marker at the start vertex                  §3.3, Fig 3.6
two-undirected-vertex      one marker each on two adjacent vertices; start at one      Fig 3.21(a)
three-undirected-vertex    one marker on the start vertex, two on a neighbour          Fig 3.21(b)
undirected-edge            one marker on an edge; start at an end of it                §6.1, Fig 6.1(a)
directional-edge           one directional marker on an edge; start at an end          §6.1, Fig 6.1(b)
vertex-and-edge            one marker at the start vertex, one on an incident edge     §6.2
=========================  ==========================================================  ==========

Examples
--------
>>> from topomark.spec.world import World
>>> tri = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})
>>> len(list(MARKER_CLASSES["directional-vertex"].placements(tri)))  # 3 vertices x 2 heads x 2 facings
12
>>> MARKER_CLASSES["directional-vertex"].kit.to_json()
{'directional-vertex': 1}
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterator

from topomark.spec.errors import unknown_name
from topomark.spec.kit import Kit
from topomark.spec.marker import EdgeMarker, Marker, VertexMarker
from topomark.spec.world import Start, World

__all__ = ["MarkerClass", "MARKER_CLASSES", "marker_class"]


@dataclass(frozen=True)
class MarkerClass:
    """A kit placed in a world: the placements searches and the census range over."""

    name: str
    kit: Kit
    description: str
    section: str
    sufficient: bool  # what the thesis shows: a single class member maps every world
    layouts: Callable[[World, str], Iterator[list[Marker]]]  # (world, vertex) -> marker layouts at that vertex

    def placements(self, world: World) -> Iterator[World]:
        """Every placement of this class's markers on ``world`` with every starting exit."""
        for v in world.vertices:
            for markers in self.layouts(world, v):
                for facing in world.rotation[v]:
                    yield World(world.rotation, markers, Start(v, facing))


def _none(world, v):
    yield []


def _undirected_vertex(world, v):
    yield [VertexMarker(v)]


def _directional_vertex(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v, 1, w)]


def _two_undirected(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v), VertexMarker(w)]


def _three_undirected(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v), VertexMarker(w, 2)]


def _undirected_edge(world, v):
    for w in world.rotation[v]:
        yield [EdgeMarker((v, w))]


def _directional_edge(world, v):
    for w in world.rotation[v]:
        for head in (v, w):
            yield [EdgeMarker((v, w), 1, head)]


def _vertex_and_edge(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v), EdgeMarker((v, w))]


MARKER_CLASSES: dict[str, MarkerClass] = {c.name: c for c in (
    MarkerClass("none", Kit(), "no marker", "§3.2.1", False, _none),
    MarkerClass("undirected-vertex", Kit(vertex=1), "one undirected vertex marker at the start", "§3.2.2", False,
                _undirected_vertex),
    MarkerClass("directional-vertex", Kit(vertex=1, directional=True), "one directional vertex marker at the start",
                "§3.3", True, _directional_vertex),
    MarkerClass("two-undirected-vertex", Kit(vertex=2), "undirected markers on the start and an adjacent vertex",
                "§3.7, Figure 3.21(a)", False, _two_undirected),
    MarkerClass("three-undirected-vertex", Kit(vertex=3), "one undirected marker at the start, two on a neighbour",
                "§3.7, Figure 3.21(b)", True, _three_undirected),
    MarkerClass("undirected-edge", Kit(edge=1), "one undirected edge marker; start at an end",
                "§6.1, Figure 6.1(a)", False, _undirected_edge),
    MarkerClass("directional-edge", Kit(edge=1, directional=True), "one directional edge marker; start at an end",
                "§6.1, Figure 6.1(b)", True, _directional_edge),
    MarkerClass("vertex-and-edge", Kit(vertex=1, edge=1), "one undirected marker at the start and one on an "
                "incident edge", "§6.2", True, _vertex_and_edge),
)}


def marker_class(name: str) -> MarkerClass:
    """The marker class called ``name``; an unknown name is :class:`InvalidInput` listing the known ones."""
    if name not in MARKER_CLASSES:
        raise unknown_name("marker class", name, MARKER_CLASSES)
    return MARKER_CLASSES[name]
