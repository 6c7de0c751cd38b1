"""The thesis's indistinguishable pairs, rebuilt as worlds (Figures 3.3, 3.4, 3.6, 3.21, 6.1).

The drawings are lost from the text; every pair here is reconstructed from its
caption and checked against it (``tests/test_figures.py``):

* Figure 3.3 (§3.2.1): cycles of different lengths, no marker; every vertex
  reads ``[2,A,A]``.  :func:`figure_3_3` gives C3 and C4; :func:`figure_3_3_cycles`
  gives C3, C4, C5 (the figure shows three).
* Figure 3.4 (§3.2.2): the wheel W4, planar and "twisted" (all corner rotations
  reversed, genus 1), an undirected marker at the centre ``"0"`` —
  :func:`topomark.proofs.wheels.wheel_pair`.  ``M = (x,1,2,2,1)`` gives
  ``([3,A,A] x4, [4,V,A])`` on both.
* Figure 3.6 (§3.3): the same with a directional marker, start facing its head:
  ``M = (0,1,2,2,1)`` ends ``[4,V-3,A]`` on the planar wheel and ``[4,V-1,A]``
  on the twisted one (the caption lists the two sequences without saying
  which graph is which).
* Figure 3.21(a) (§3.7) and Figure 6.1 (§6.1): the triangular prism, planar
  (:data:`PRISM_PLANAR`) and with a twisted rotation system of genus 1
  (:data:`PRISM_TWISTED`), the rung v0–v1 marked.  We searched every world
  with ≤ 6 vertices and max degree 3 (:func:`search_pairs`) for non-isomorphic
  indistinguishable placements whose ``M = (1,1,2,2,1)`` perceptions equal the
  caption's; for two adjacent vertex markers and for an edge marker, with the
  start facing the marked neighbour / marked edge, the prism pair is the only
  answer up to isomorphism (the same pair for both figures, as §6.1 says the
  E-marker case is "similar to the case of two undirected V-markers").

  Perception model note (Figure 3.21(a)): the thesis writes the last
  signature as ``[3,V-1,A]``, "the marked neighbour is present and is the next
  on the left" — an expanded signature that includes the neighbours.  Our
  robot senses markers only at its own vertex (§3.1.1), so it reads
  ``[3,V,A]``; the two worlds remain indistinguishable under either reading,
  because the marked neighbour is the same exit in both.

* Figure 3.21(b): one marker on v0 and two on v1 make the pair distinguishable
  (:func:`figure_3_21b`); Figure 6.1(b): a directional edge marker with its
  head at v0 ends ``[3,A,E-1-H]`` on the planar prism and ``[3,A,E-1-T]`` on
  the twisted one (:func:`figure_6_1b`).
"""

from __future__ import annotations

from collections import defaultdict
from typing import Iterator, Sequence

from topomark.proofs.enumerate import embedded_worlds
from topomark.proofs.wheels import wheel_pair, wheel_pair_directional
from topomark.spec.markerclass import marker_class
from topomark.spec.errors import InvalidInput
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.robot import perceive
from topomark.spec.world import Start, World

__all__ = ["CYCLE_MOTIONS", "PRISM_MOTIONS", "PRISM_PLANAR", "PRISM_TWISTED", "cycle_world", "figure_3_3",
           "figure_3_3_cycles", "figure_3_4", "figure_3_6", "figure_3_21a", "figure_3_21b", "figure_6_1a",
           "figure_6_1b", "search_pairs", "FIGURES"]

CYCLE_MOTIONS = (1, 1, 1, 1, 1)
PRISM_MOTIONS = (1, 1, 2, 2, 1)  # the captions of Figures 3.21 and 6.1

PRISM_PLANAR: dict[str, tuple[str, ...]] = {
    "v0": ("v1", "v2", "v3"),
    "v1": ("v0", "v4", "v5"),
    "v2": ("v0", "v5", "v3"),
    "v3": ("v0", "v2", "v4"),
    "v4": ("v1", "v3", "v5"),
    "v5": ("v1", "v4", "v2"),
}
"""The planar triangular prism: triangles v0 v2 v3 and v1 v4 v5, rungs v0-v1, v2-v5, v3-v4 (genus 0)."""

PRISM_TWISTED: dict[str, tuple[str, ...]] = {
    "v0": ("v1", "v2", "v3"),
    "v1": ("v0", "v4", "v5"),
    "v2": ("v0", "v3", "v5"),
    "v3": ("v0", "v4", "v2"),
    "v4": ("v1", "v5", "v3"),
    "v5": ("v1", "v2", "v4"),
}
"""The same graph with v2, v3, v4, v5 reversed (genus 1)."""


def cycle_world(n: int, start: bool = True) -> World:
    """The cycle C_n (vertices v0..v{n-1}), starting at v0 facing v1."""
    if n < 3:
        raise InvalidInput(f"a cycle needs at least 3 vertices (no multi-edges, §3.1.1), not {n}")
    rot = {f"v{k}": (f"v{(k + 1) % n}", f"v{(k - 1) % n}") for k in range(n)}
    return World(rot, (), Start("v0", "v1") if start else None)


def figure_3_3() -> tuple[World, World]:
    """Figure 3.3: C3 and C4, no marker — every perception is ``[2,A,A]``."""
    return cycle_world(3), cycle_world(4)


def figure_3_3_cycles() -> tuple[World, World, World]:
    """Figure 3.3's three graphs: C3, C4 and C5 (any two are indistinguishable)."""
    return cycle_world(3), cycle_world(4), cycle_world(5)


def _wheels(directional: bool) -> tuple[World, World]:
    return wheel_pair_directional() if directional else wheel_pair()


def figure_3_4() -> tuple[World, World]:
    """Figure 3.4: planar and twisted W4, undirected marker at the centre, start at it."""
    return _wheels(False)


def figure_3_6() -> tuple[World, World]:
    """Figure 3.6: the Figure 3.4 pair with a directional marker, start facing the marker head."""
    return _wheels(True)


def _prisms(markers: Sequence) -> tuple[World, World]:
    start = Start("v0", "v1")
    return World(PRISM_PLANAR, markers, start), World(PRISM_TWISTED, markers, start)


def figure_3_21a() -> tuple[World, World]:
    """Figure 3.21(a): undirected markers on v0 and v1; start at v0 facing the marked neighbour v1."""
    return _prisms((VertexMarker("v0"), VertexMarker("v1")))


def figure_3_21b() -> tuple[World, World]:
    """Figure 3.21(b): one marker on v0, two on v1 — the pair becomes distinguishable."""
    return _prisms((VertexMarker("v0"), VertexMarker("v1", 2)))


def figure_6_1a() -> tuple[World, World]:
    """Figure 6.1(a): an undirected edge marker on v0-v1; start at v0 having entered by it."""
    return _prisms((EdgeMarker(("v0", "v1")),))


def figure_6_1b() -> tuple[World, World]:
    """Figure 6.1(b): the edge marker directed with its head at v0 — now distinguishable."""
    return _prisms((EdgeMarker(("v0", "v1"), head="v0"),))


FIGURES = {
    "3.3": figure_3_3,
    "3.4": figure_3_4,
    "3.6": figure_3_6,
    "3.21a": figure_3_21a,
    "3.21b": figure_3_21b,
    "6.1a": figure_6_1a,
    "6.1b": figure_6_1b,
}


def _facing_marked(world: World) -> bool:
    """The start faces a marked neighbour or a marked edge."""
    s = world.start
    assert s is not None, "a census world has its start"
    for m in world.markers:
        if isinstance(m, EdgeMarker) and set(m.between) == {s.at, s.facing}:
            return True
        if isinstance(m, VertexMarker) and m.at == s.facing:
            return True
    return False


def _matches(world: World, motions: Sequence[int], perceptions: Sequence[str]) -> bool:
    try:
        return [str(p) for p in perceive(world, world.start_state(), motions)] == list(perceptions)
    except InvalidInput:  # a motion does not exist at some vertex
        return False


def search_pairs(class_name: str, max_vertices: int, max_degree: int, motions: Sequence[int],
                 perceptions: Sequence[str], facing_marked: bool = False) -> Iterator[tuple[World, World]]:
    """Non-isomorphic indistinguishable placements matching a caption: how the figures were rebuilt.

    Every placement of the class whose perception sequence for ``motions``
    equals ``perceptions`` is grouped by its robot language
    (:func:`topomark.proofs.census.language_code`); yields one pair per two
    non-isomorphic marked worlds in a group.
    """
    from topomark.proofs.census import language_code, language_digest, machine, minimise

    groups: dict[bytes, list[World]] = defaultdict(list)
    for world in embedded_worlds(max_vertices, max_degree):
        for placed in marker_class(class_name).placements(world):
            if (facing_marked and not _facing_marked(placed)) or not _matches(placed, motions, perceptions):
                continue
            mach = machine(placed.with_start(None))
            code = language_code(mach, minimise(mach), mach.index[placed.start_state()])
            groups[language_digest(code)].append(placed)
    for members in groups.values():
        reps: list[World] = []
        for placed in members:
            if not any(find_isomorphism(placed, r, markers=True).isomorphic for r in reps):
                reps.append(placed)
        for k in range(1, len(reps)):
            yield reps[0], reps[k]
