"""What the §6.3 sweeps run (thesis §6.3, §6.3–§6.4; §2.3.1): the thread classes of Table 6.3, the
``lattice-edge-hole`` world family of Figures 6.23(b) and 6.24, and the experiments ``table-6.3``, ``figure-6.24``,
``comparison`` and ``section-6.3``, registered in :mod:`~topomark.reference.bench.plan`'s tables when this module
is imported.  Their reports are :mod:`~topomark.reference.bench.reports.section63`.

Examples
--------
>>> [c.name for c in CLASSES]
['fixed ε', 'carried ε', 'explore-explore l=8', 'l = c(G)', 'l ≫ m, knots']
>>> LENGTHS[-1] >= 400 > LENGTHS[-2]
True
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.reference.worlds import generators as g
from topomark.reference.bench.plan import (EXPERIMENTS, FAMILIES, GRIDS, NO_LIGHTHOUSE, Experiment, Part, WorldFamily,
                                           world_seed)

__all__ = ["CLASSES", "ThreadClass", "LENGTHS", "SIZES", "COMPARED", "MOVABLE", "IMMOVABLE", "EDGE_HOLE",
           "FIGURE_624_SIZE", "REPORTS"]

EDGE_HOLE = "lattice-edge-hole"
SIZES = (90, 202, 360)
FIGURE_624_SIZE = 360
LENGTHS = (1, 2, 4, 8, 16, 32, 64, 128, 256, 512)
COMPARED = ("dudek", "dudek-directional", "basic", "enh3", "case-3b", "case-dv-sum", "extension-2", "thread-knots",
            "thread-circumference")
MOVABLE, IMMOVABLE = ("dudek", "dudek-directional"), ("basic", "enh3")

@dataclass(frozen=True)
class ThreadClass:
    """A row of Table 6.3 and the run that measures it: algorithm, lighthouse, option set, cost bound f."""

    name: str
    row: str  # the first column of Table 6.3
    algorithm: str
    lighthouse: str
    options: str
    bound: str  # "m²n", "mn", "m"


CLASSES = (
    ThreadClass("fixed ε", "a very short thread l = ε (no retying)", "basic", "thread", "", "m²n"),
    ThreadClass("carried ε", "(l = ε) (retying)", "thread-carried", NO_LIGHTHOUSE, "", "mn"),
    ThreadClass("explore-explore l=8", "an arbitrary length thread l < c(G)", "thread-explore", NO_LIGHTHOUSE,
                "thread-length=8", "mn"),
    ThreadClass("l = c(G)", "a long thread l = c(G)", "thread-circumference", NO_LIGHTHOUSE, "", "mn"),
    ThreadClass("l ≫ m, knots", "a very long thread l ≫ m", "thread-knots", NO_LIGHTHOUSE, "", "m"),
)


def _lattice_edge_hole(size: int, seed: int):
    rows, cols = GRIDS[size]
    return g.lattice_hole(rows, cols, 0.1, "edges", world_seed(EDGE_HOLE, size, seed))


def _parts(world_family: str, sizes: tuple[int, ...]) -> tuple[Part, ...]:
    by_options: dict[tuple[str, str], list[str]] = {}
    for c in CLASSES:
        by_options.setdefault((c.lighthouse, c.options), []).append(c.algorithm)
    return tuple(Part(world_family, tuple(algs), sizes, lighthouses=(lh,), options=(opt,))  # a kit algorithm's is ignored
                 for (lh, opt), algs in by_options.items())


def _register() -> None:
    """The world family and the experiments, in :mod:`~topomark.reference.bench.plan`'s tables."""
    FAMILIES[EDGE_HOLE] = WorldFamily(
        EDGE_HOLE, tuple(GRIDS), _lattice_edge_hole, "Figures 6.23(b), 6.24",
        note="the grids of the lattice family (size 90 = 10x10, 202 = 15x15, 360 = 20x20, ...) with 10% of their "
             "edges removed at random (kept connected), so n = rows x cols")
    EXPERIMENTS["table-6.3"] = Experiment(
        "table-6.3", _parts("lattice", SIZES) + _parts(EDGE_HOLE, SIZES),
        "Table 6.3 and Figure 6.23: every thread class on lattices and lattices with 10% of the edges removed")
    EXPERIMENTS["figure-6.24"] = Experiment(
        "figure-6.24", (Part(EDGE_HOLE, ("thread-explore",), (FIGURE_624_SIZE,),
                             options=tuple(f"thread-length={n}" for n in LENGTHS)),
                        Part(EDGE_HOLE, ("thread-circumference", "thread-knots"), (FIGURE_624_SIZE,))),
        "Figure 6.24: explore-explore (Algorithm 6.8) on 20x20 lattices with 10% of the edges removed, cost against l")
    EXPERIMENTS["comparison"] = Experiment(
        "comparison", (Part("lattice-hole", COMPARED, SIZES),),
        "Movable and immovable markers and threads on the same lattice-hole worlds (§2.3.1, Chapter 3, §6.2, §6.3)")
    EXPERIMENTS["section-6.3"] = Experiment(
        "section-6.3", tuple(p for n in ("table-6.3", "figure-6.24", "comparison") for p in EXPERIMENTS[n].parts),
        "§6.3 and §2.3.1: Table 6.3, Figures 6.23 and 6.24, and the comparison of movable and immovable markers")


_register()
REPORTS = ("table-6.3", "figure-6.24", "comparison", "section-6.3")
