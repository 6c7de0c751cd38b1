"""The thesis's figure worlds: the wheel pair of Figure 3.4 (§3.2.2) and its directional version, Figure 3.6 (§3.3).

Two embeddings of the wheel W4 that a robot with one undirected vertex
marker cannot tell apart although they are not extended-isomorphic; with a
directional marker it can.  Unlike the other generators these worlds carry
the marker the thesis places on them, and a start.
"""

from __future__ import annotations

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.marker import VertexMarker
from topomark.spec.world import Start, World

__all__ = ["WHEEL_A_ROTATION", "WHEEL_B_ROTATION", "WHEEL_MARKERS", "wheel_pair", "wheel_pair_directional", "wheel_a",
           "wheel_b"]


WHEEL_A_ROTATION: dict[str, tuple[str, ...]] = {
    "0": ("1", "2", "3", "4"),
    "1": ("0", "4", "2"),
    "2": ("0", "1", "3"),
    "3": ("0", "2", "4"),
    "4": ("0", "3", "1"),
}
"""Figure 3.4(a): the planar wheel W4 (centre "0", corners "1".."4" clockwise)."""

WHEEL_B_ROTATION: dict[str, tuple[str, ...]] = {
    "0": ("1", "2", "3", "4"),
    "1": ("0", "2", "4"),
    "2": ("0", "3", "1"),
    "3": ("0", "4", "2"),
    "4": ("0", "1", "3"),
}
"""Figure 3.4(b): the same graph with every corner's rotation reversed (genus 1)."""


def wheel_pair() -> tuple[World, World]:
    """The two embedded graphs of Figure 3.4 (§3.2.2), each with an undirected marker at v0.

    Both are the wheel W4: a centre v0 = ``"0"`` (degree 4) joined to four
    corners ``"1".."4"`` (degree 3) that form the 4-cycle 1-2-3-4-1.  The
    centre's clockwise order is (1, 2, 3, 4) in both.

    * (a) :data:`WHEEL_A_ROTATION`, the ordinary planar wheel: corner ``c``
      lists (centre, previous corner, next corner), e.g. 1: (0, 4, 2) -- genus 0.
    * (b) :data:`WHEEL_B_ROTATION`, the twisted wheel: every corner lists
      (centre, next corner, previous corner), e.g. 1: (0, 2, 4) -- genus 1.

    How they were derived: the §3.2.2 proof (Figure 3.5) only fixes that both
    are a marked degree-4 centre with four degree-3 corners forming a cycle,
    and that they differ in the rotations at the corners.  We enumerated every
    world with centre order (1, x, y, z) and each of the 2^4 corner
    orientations, kept those not extended-isomorphic to (a) (no vertex
    bijection with cyclic relabelling of exits; mirror images not allowed),
    and checked robot indistinguishability by a BFS over pairs of robot states
    (vertex, entry) from the marked centre, comparing degree and marker
    presence after every motion.  Up to extended isomorphism exactly one
    embedding survives: all corners reversed, (b).  For it every starting
    facing in (a) is indistinguishable from every starting facing in (b), and
    M = (x, 1, 2, 2, 1) yields degrees 3, 3, 3, 3, 4 with the marker seen
    only at the end, as in the Figure 3.4 caption.  A mixed orientation (some
    corners reversed) is distinguishable from (a).

    Both worlds start at v0 facing corner "1" (any facing gives the same
    perceptions, both worlds being symmetric under rotating the corners).
    """
    marker = (VertexMarker("0"),)
    start = Start("0", "1")
    return World(WHEEL_A_ROTATION, marker, start), World(WHEEL_B_ROTATION, marker, start)


def wheel_pair_directional() -> tuple[World, World]:
    """Figure 3.6: the wheel pair with a directional marker at v0, pointing at corner "1".

    The robot starts at v0 facing the marker head (``Start("0", "1")``).  A
    directional marker whose head is exit h, read by a robot that entered
    through exit j, reads V-((h - j) mod deg).  With the motion convention of
    §3.1.1 (motion l leaves through exit (entry + l) mod deg, l = 0 goes back
    / leaves through the faced exit):

    * M = (0, 1, 2, 2, 1) (Figure 3.6 caption) ends at v0 reading V-3 on (a)
      and V-1 on (b);
    * M = (0, 1, 1) (§3.3 text) ends at v0 reading V-1 on (a) and V-3 on (b).

    The thesis lists V-1 first in both places; under one fixed reading
    convention the two examples cannot both list the left graph first, so the
    caption's order of the two perception sequences is taken as unspecified.
    The readings do not depend on which corner the head points to (both
    worlds are symmetric under rotating the corners).
    """
    marker = (VertexMarker("0", points_to="1"),)
    start = Start("0", "1")
    return World(WHEEL_A_ROTATION, marker, start), World(WHEEL_B_ROTATION, marker, start)


WHEEL_MARKERS = ("undirected", "directional", "none")
"""The marker a wheel world carries at v0: Figure 3.4's undirected one (§3.2.2: the pair a robot with it cannot
tell apart), Figure 3.6's directional one pointing at the faced corner (§3.3: the marker Algorithm 3.1 drops, so
``topomark explore`` with its default lighthouse accepts the world), or none (every lighthouse drops its own)."""


def _marked(index: int, marker: str) -> World:
    if marker not in WHEEL_MARKERS:
        raise InvalidInput(f"wheel: marker must be one of {', '.join(WHEEL_MARKERS)}, got {clip(repr(marker), 60)}")
    world = (wheel_pair_directional() if marker == "directional" else wheel_pair())[index]
    return world.with_markers([]) if marker == "none" else world


def wheel_a(marker: str = "undirected") -> World:
    """Figure 3.4(a), the planar wheel with an undirected marker at v0 (see :func:`wheel_pair`); ``marker``
    "directional" gives Figure 3.6's left wheel, "none" the bare wheel (:data:`WHEEL_MARKERS`)."""
    return _marked(0, marker)


def wheel_b(marker: str = "undirected") -> World:
    """Figure 3.4(b), the twisted wheel with an undirected marker at v0 (see :func:`wheel_pair`); ``marker`` as
    for :func:`wheel_a`."""
    return _marked(1, marker)

