"""Hypothesis strategies over every world family of the generators (for explorer properties)."""

from __future__ import annotations

from hypothesis import strategies as st

from topomark.reference.worlds import generators as g
from topomark.reference.worlds.strategies import worlds
from topomark.spec.world import Start, World


@st.composite
def family_worlds(draw, small: bool = False) -> World:
    """A world from one of the thesis's families (§3.5.3, Figures 3.3-3.12), at a random start."""
    top = 3 if small else 5
    family = draw(st.sampled_from(["cycle", "chain", "lattice", "lattice-hole", "complete", "complete-hole",
                                   "small-world", "random", "wheel", "arbitrary"]))
    seed = draw(st.integers(0, 10_000))
    if family == "cycle":
        world = g.cycle(draw(st.integers(3, 14)))
    elif family == "chain":
        world = g.chain(draw(st.integers(2, 14)))
    elif family == "lattice":
        world = g.lattice(draw(st.integers(1, top)), draw(st.integers(2, top)))
    elif family == "lattice-hole":
        world = g.lattice_hole(draw(st.integers(3, top + 1)), draw(st.integers(3, top + 1)),
                               draw(st.sampled_from([0.1, 0.2])), draw(st.sampled_from(["vertices", "edges"])), seed)
    elif family == "complete":
        world = g.complete(draw(st.integers(2, 4 if small else 6)))
    elif family == "complete-hole":
        world = g.complete_hole(draw(st.integers(4, 5 if small else 7)), 0.2, seed)
    elif family == "small-world":
        world = g.small_world(draw(st.integers(6, 10 if small else 16)), draw(st.sampled_from([2, 4])),
                              draw(st.sampled_from([0.1, 0.2])), seed)
    elif family == "random":
        n = draw(st.integers(5, 7 if small else 10))
        world = g.random_graph(n, draw(st.sampled_from([0.4, 0.6])), seed)
    elif family == "wheel":
        world = draw(st.sampled_from(g.wheel_pair()))
        world = World(world.rotation)
    else:
        world = draw(worlds(max_vertices=6 if small else 8))
    v = draw(st.sampled_from(world.vertices))
    facing = draw(st.sampled_from(world.rotation[v]))
    return World(world.rotation, (), Start(v, facing))
