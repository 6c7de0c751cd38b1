"""Markers: the marking aids of thesis §3.1.1 (vertex markers) and §6.1 (edge markers).

A marker lies at a vertex (a *V-marker*) or on an edge (an *E-marker*).  Either
kind may be *undirected* or *directional*:

* a directional V-marker points at one exit of its vertex (``points_to`` names
  the neighbour that exit leads to);
* a directional E-marker has a head end (``head`` names that end vertex).

``count`` is the number of homogeneous markers placed together (the ``#`` in
the thesis notation ``V#``; §3.1.1, §6.2).  Markers are immovable here; the
movable marker of [26] is a later addition.

Examples
--------
>>> VertexMarker("c", points_to="a")
VertexMarker(at='c', count=1, points_to='a')
>>> EdgeMarker(("a", "b"), head="b").directional
True
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["VertexMarker", "EdgeMarker", "Marker"]


@dataclass(frozen=True)
class VertexMarker:
    """``count`` markers at vertex ``at``; directional iff ``points_to`` is set."""

    at: str
    count: int = 1
    points_to: str | None = None

    @property
    def directional(self) -> bool:
        return self.points_to is not None


@dataclass(frozen=True)
class EdgeMarker:
    """``count`` markers on the edge ``between``; directional iff ``head`` is set."""

    between: tuple[str, str]
    count: int = 1
    head: str | None = None

    @property
    def directional(self) -> bool:
        return self.head is not None

    @property
    def edge(self) -> frozenset[str]:
        return frozenset(self.between)


Marker = VertexMarker | EdgeMarker
