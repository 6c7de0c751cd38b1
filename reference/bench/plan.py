"""What a bench sweep runs: the world families, the experiments, and the plan of runs (fixed seeds).

Part of ``topomark bench`` (:mod:`~topomark.reference.bench.experiments` documents the
experiments and the interpretations of the thesis's worlds).  A world of
(world family, size, seed) is built from fixed seeds derived from those three, and
the robot's start (vertex and facing) is drawn from the same seed, so every
algorithm, edge policy and lighthouse of a row explores exactly the same
worlds.  A lighthouse that needs a start vertex of degree >= 2
(``three-undirected-edge``, §6.2) is not planned on a world whose drawn start
has degree 1: that world is *skipped* for that lighthouse (never re-drawn, which
would compare different starts), and the lighthouse report counts the skips.

A part lists algorithms and *option sets*: each option set is a canonical
string ``name=value[,name=value]`` (``""`` = the algorithm's defaults), part of
a run's key, resolved against the world when the run starts
(:func:`resolve_options`): a name the algorithm takes (``markers=4``) is passed
as is; a *derived* option of :data:`DERIVED_OPTIONS` (``marked-fraction=0.25``)
computes the algorithm's options from the world.  A kit algorithm (one that
carries its own kit, §6.2) runs with no lighthouse: its runs are planned with
:data:`NO_LIGHTHOUSE` whatever the part's lighthouses.

"Family" here always means a *world family* (:class:`WorldFamily`: lattice-hole, complete-hole, ...), never
the algorithm family a trace@2 header names (:mod:`topomark.reference.trace.families`).
"""

from __future__ import annotations

import functools
import random
from dataclasses import dataclass
from typing import Callable, Iterable, Sequence

from topomark.spec.errors import InvalidInput, unknown_name
from topomark.spec.world import Start, World

from topomark.reference.worlds import generators as g
from topomark.reference.bench import thesis_figures as tf
from topomark.reference.explorers.counted_markers import sum_to
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.algorithms.registry import algorithm_spec

__all__ = ["FAMILIES", "EXPERIMENTS", "Experiment", "Part", "Run", "plan", "world_for", "is_heavy", "fits",
           "HEAVY_GRAPHS", "HEAVY_MAX_SIZE", "DEFAULT_LIGHTHOUSE", "CERTAIN_LIGHTHOUSES", "LIGHTHOUSE_ALGS", "LIGHTHOUSE_COMPLETE_SIZES",
           "NO_LIGHTHOUSE", "DERIVED_OPTIONS", "resolve_options", "option_set", "marked_fraction_markers",
           "TABLE_61_ALGS", "TABLE_62_ALGS", "CASE_5_K", "UNCUED_MODEL_TREE_GRAPHS", "FRACTIONS", "FIGURE_613_SIZES", "world_seed"]

DEFAULT_LIGHTHOUSE = "directional-vertex"
CERTAIN_LIGHTHOUSES = tuple(name for name, h in LIGHTHOUSES.items() if h.certain)
"""The lighthouses ``bench lighthouses`` compares: those that surely give explicit place and back-link
information or fail (every one with a marker or thread).  §5.2.1's marker-less ones may pick a place whose local
signature repeats, so a wrong map there is the scheme's, not a fault: they are left out of this verdict."""
NO_LIGHTHOUSE = "none"  # the lighthouse column of a kit algorithm's run (it carries its own kit)
HEAVY_GRAPHS = 5
HEAVY_MAX_SIZE = 55

GRIDS = {72: (8, 10), 90: (10, 10), 108: (10, 12), 152: (13, 13), 202: (15, 15), 230: (16, 16),
         260: (17, 17), 324: (19, 19), 360: (20, 20)}


@dataclass(frozen=True)
class WorldFamily:
    """A world family of the bench: its sizes and how its world of (size, seed) is built (no start yet)."""

    name: str
    sizes: tuple[int, ...]
    build: Callable[[int, int], World]  # (size, seed) -> world without start
    figure: str
    log: bool = True
    random_graph: bool = True
    note: str = ""


def world_seed(world_family: str, size: int, seed: int) -> int:
    """The fixed seed a world of (world family, size, seed) is generated from."""
    return (sum(ord(c) * 31 ** k for k, c in enumerate(world_family)) % 100_003) * 1_000_003 + size * 10_007 + seed


def _lattice_hole(size: int, seed: int) -> World:
    rows, cols = GRIDS[size]
    return g.lattice_hole(rows, cols, 0.1, "vertices", world_seed("lattice-hole", size, seed))


def _lattice(size: int, seed: int) -> World:
    return g.lattice(*GRIDS[size])


FAMILIES: dict[str, WorldFamily] = {f.name: f for f in (  # the world families, by name
    WorldFamily("lattice", tf.LATTICE_HOLE_SIZES, _lattice, "Figure 3.10(a)", random_graph=False,
           note="8x10, 10x10, 10x12, 13x13, 15x15, 16x16, 17x17, 19x19, 20x20 grids (labelled by the "
                "lattice-hole size they give); the worlds of a size differ only in the start"),
    WorldFamily("complete", tf.COMPLETE_HOLE_SIZES, lambda n, s: g.complete(n), "Figure 3.10(b)", random_graph=False,
           note="K_n; the worlds of a size differ only in the start"),
    WorldFamily("lattice-hole", tf.LATTICE_HOLE_SIZES, _lattice_hole, "Figure 3.10(c)",
           note="size s = an 8x10, 10x10, 10x12, 13x13, 15x15, 16x16, 17x17, 19x19 or 20x20 grid with 10% of "
                "its vertices removed at random (kept connected), so n = s"),
    WorldFamily("complete-hole", tf.COMPLETE_HOLE_SIZES,
           lambda n, s: g.complete_hole(n, 0.1, world_seed("complete-hole", n, s)), "Figure 3.10(d)",
           note="K_n with 10% of its edges removed at random (kept connected)"),
    WorldFamily("small-world-k2-p10", (20, 40, 60, 80, 100, 150, 200),
           lambda n, s: g.small_world(n, 2, 0.1, world_seed("small-world-k2-p10", n, s)), "Figure 3.11"),
    WorldFamily("small-world-k4-p20", (20, 40, 60, 80, 100, 150, 200),
           lambda n, s: g.small_world(n, 4, 0.2, world_seed("small-world-k4-p20", n, s)), "Figure 3.11"),
    WorldFamily("random-20", (15, 20, 25, 30, 35, 40, 50),
           lambda n, s: g.random_graph(n, 0.2, world_seed("random-20", n, s)), "Figure 3.12"),
    WorldFamily("random-40", (15, 20, 25, 30, 35, 40, 50),
           lambda n, s: g.random_graph(n, 0.4, world_seed("random-40", n, s)), "Figure 3.12"),
)}

LATTICE_TABLE_ALGS = ("basic", "enh1", "enh2", "enh3", "enh4", "enh5-d1", "enh5-d2", "enh3+5")
COMPLETE_TABLE_ALGS = ("basic", "enh1", "enh2", "enh3", "enh4", "enh5-d1", "enh5-d2", "enh3+4")


@dataclass(frozen=True)
class Part:
    family: str  # a world family: a key of FAMILIES
    algorithms: tuple[str, ...] = ("basic",)
    sizes: tuple[int, ...] | None = None  # None: the world family's sizes
    policies: tuple[str, ...] = ("nearest",)
    lighthouses: tuple[str, ...] = (DEFAULT_LIGHTHOUSE,)
    options: tuple[str, ...] = ("",)  # option sets (module docstring); "" = the algorithm's defaults
    graphs: int | None = None  # at most this many worlds per size for this part (None: --graphs)


@dataclass(frozen=True)
class Experiment:
    name: str
    parts: tuple[Part, ...]
    title: str
    tables: tuple[str, ...] = ()


def _tables_parts(numbers: Iterable[str]) -> tuple[Part, ...]:
    by_family: dict[str, list[str]] = {}
    for t in numbers:
        fam, algs = tf.TABLE_SOURCES[t]
        lst = by_family.setdefault(fam, ["basic"])
        lst.extend(a for a in algs if a not in lst)
    return tuple(Part(f, tuple(a)) for f, a in by_family.items())


EXPERIMENTS: dict[str, Experiment] = {}
for _f in FAMILIES.values():
    EXPERIMENTS[_f.name] = Experiment(_f.name, (Part(_f.name),), f"{_f.figure}: {_f.name} worlds, basic algorithm")
EXPERIMENTS["figure-3.10"] = Experiment("figure-3.10", tuple(Part(f) for f in ("lattice", "complete", "lattice-hole",
                                                                               "complete-hole")),
                                        "Figure 3.10: homogeneous and hole worlds, basic algorithm")
EXPERIMENTS["figure-3.11"] = Experiment("figure-3.11", (Part("small-world-k2-p10"), Part("small-world-k4-p20")),
                                        "Figure 3.11: small-world worlds, basic algorithm")
EXPERIMENTS["figure-3.12"] = Experiment("figure-3.12", (Part("random-20"), Part("random-40")),
                                        "Figure 3.12: random worlds, basic algorithm")
for _t in tf.TABLE_SOURCES:
    EXPERIMENTS[f"table-{_t}"] = Experiment(f"table-{_t}", _tables_parts([_t]), f"Table {_t}", (_t,))
EXPERIMENTS["tables"] = Experiment("tables", (Part("lattice-hole", LATTICE_TABLE_ALGS),
                                              Part("complete-hole", COMPLETE_TABLE_ALGS)),
                                   "Tables 4.1-4.8: the enhancements of Chapter 4", tuple(tf.TABLE_SOURCES))
EXPERIMENTS["policies"] = Experiment("policies", (Part("lattice-hole", ("basic", "enh3"), (90, 260),
                                                       ("nearest", "fifo", "lifo")),),
                                     "Edge-selection policies side by side (lattice-hole 90 and 260)")
LIGHTHOUSE_ALGS = ("basic", "enh3")
LIGHTHOUSE_COMPLETE_SIZES = (24, 40, 55)
EXPERIMENTS["lighthouses"] = Experiment(
    "lighthouses", (Part("lattice-hole", LIGHTHOUSE_ALGS, lighthouses=CERTAIN_LIGHTHOUSES),
                    Part("complete-hole", LIGHTHOUSE_ALGS, LIGHTHOUSE_COMPLETE_SIZES, lighthouses=CERTAIN_LIGHTHOUSES)),
    "The lighthouses of §3.3, §6.1 and §6.2 side by side (lattice-hole and complete-hole worlds)")
TABLE_61_ALGS = ("case-1a", "case-1b", "case-2", "case-3a", "case-3b", "case-4", "case-4-mn", "case-5-v1",
                 "case-5-v2", "case-5-edge", "case-0")
TABLE_62_ALGS = ("case-dv-sum", "case-dv-sum-listing", "extension-1", "extension-2", "extension-2-listing", "case-3b",  # case-3b: the undirected original
                 "case-1b-edgeinfo", "case-1b", "case-2-edgeinfo", "case-2",  # §6.2.2's edgeINFO and their originals
                 "case-1a-edgeinfo", "case-1a", "case-4-edgeinfo", "case-4", "case-4-mn-edgeinfo", "case-4-mn",
                 "case-5-directional")
FRACTIONS = ("0", "0.1", "0.25", "0.5", "0.75", "1")
FIGURE_613_SIZES = {"lattice-hole": (72, 90, 108, 152, 202), "complete-hole": (24, 28, 32, 36, 40)}
CASE_5_K = ("markers=4", "markers=6", "markers=10")
"""Case 5's few-markers kits (Figure 6.13's low end): K too small to mark every place, so phase II does the work."""
EXPERIMENTS["table-6.1"] = Experiment(
    "table-6.1", tuple(Part(f, TABLE_61_ALGS) for f in ("lattice-hole", "complete-hole"))
    + tuple(Part(f, ("case-5-v1", "case-5-v2", "case-5-edge"), sizes, options=CASE_5_K)
            for f, sizes in FIGURE_613_SIZES.items()),
    "Table 6.1 and Figures 6.11, 6.12: §6.2.1's undirected marker algorithms, measured")
EXPERIMENTS["table-6.2"] = Experiment(
    "table-6.2", tuple(Part(f, TABLE_62_ALGS) for f in ("lattice-hole", "complete-hole"))
    + tuple(Part(f, ("case-5-directional",), sizes, options=CASE_5_K) for f, sizes in FIGURE_613_SIZES.items()),
    "Table 6.2 and Figures 6.17, 6.18: §6.2.2's directional marker algorithms, measured")
EXPERIMENTS["figure-6.13"] = Experiment(
    "figure-6.13", tuple(p for f, sizes in FIGURE_613_SIZES.items() for p in (
        Part(f, ("case-5-v1", "case-5-v2"), sizes, options=tuple(f"marked-fraction={x}" for x in FRACTIONS)),
        Part(f, ("basic", "case-3a", "case-1b"), sizes))),
    "Figure 6.13: Version-1 (Algorithm 6.4) and Version-2 (Algorithm 6.5) with different fractions of marked "
    "vertices")
EXPERIMENTS["section-6.2"] = Experiment(
    "section-6.2", EXPERIMENTS["table-6.1"].parts + EXPERIMENTS["table-6.2"].parts + EXPERIMENTS["figure-6.13"].parts,
    "§6.2: every marker algorithm of Tables 6.1 and 6.2 and Figures 6.11-6.13, 6.17, 6.18")
EXPERIMENTS["all"] = Experiment("all", EXPERIMENTS["figure-3.10"].parts + EXPERIMENTS["figure-3.11"].parts
                                + EXPERIMENTS["figure-3.12"].parts + EXPERIMENTS["tables"].parts
                                + EXPERIMENTS["policies"].parts + EXPERIMENTS["lighthouses"].parts,
                                "Every experiment", tuple(tf.TABLE_SOURCES))


# Chapter 5 (report :mod:`~topomark.reference.bench.reports.chapter5`): §5.1/§6.1 and §5.2.1's lighthouses on the
# Chapter 3 world families; Algorithm 5.1 on small worlds (lattice-hole up to 5x5, random up to 12 vertices) and Figure 3.4.
SMALL_GRIDS = {8: (3, 3), 11: (3, 4), 14: (4, 4), 18: (4, 5), 23: (5, 5)}  # n of a grid with 10% of vertices removed
FAMILIES.update({f.name: f for f in (
    WorldFamily("small-lattice-hole", tuple(SMALL_GRIDS), lambda n, s: g.lattice_hole(
        *SMALL_GRIDS[n], 0.1, "vertices", world_seed("small-lattice-hole", n, s)), "§5.2.2",
        note="3x3, 3x4, 4x4, 4x5, 5x5 grids with 10% of their vertices removed (kept connected), n = size"),
    WorldFamily("small-random-40", (6, 8, 10, 12), lambda n, s: g.random_graph(n, 0.4, world_seed("small-random-40", n, s)),
           "§5.2.2", note="random connected graphs with 40% of all vertex pairs as edges"),
    WorldFamily("figure-3.4a", (5,), lambda n, s: g.wheel_a(), "Figure 3.4(a)", random_graph=False,
           note="the planar wheel; the worlds differ only in the start"),
    WorldFamily("figure-3.4b", (5,), lambda n, s: g.wheel_b(), "Figure 3.4(b)", random_graph=False,
           note="the twisted (genus-1) wheel; the worlds differ only in the start"),
)})
CHAPTER_5_FAMILIES = ("lattice-hole", "random-20", "random-40", "small-world-k2-p10", "small-world-k4-p20")
SEARCHED = ("directional-vertex", "undirected-vertex", "undirected-edge", "local-pair", "local-degree-list")
WALK_SEEDS = ("seed=1", "seed=2")  # §5.2.1's further walks on each world (the default walk is seed 0)
MODEL_TREE_OPTIONS = ("cue=n", "max-models=1000")  # n cue; none (then it ends at the cap, §5.2.2's window never met)
# Uncued Algorithm 5.1 never met §5.2.2's window on these worlds: every run ends at a cap, and one on a 6-cycle costs
# about 200 CPU-s (2,000 steps with hundreds of completed models), so those runs take at most this many worlds a size.
UNCUED_MODEL_TREE_GRAPHS = 5
EXPERIMENTS["chapter-5"] = Experiment("chapter-5", tuple(
    [Part(f, ("basic",), lighthouses=SEARCHED) for f in CHAPTER_5_FAMILIES + ("figure-3.4a", "figure-3.4b")]
    + [Part(f, ("basic",), lighthouses=SEARCHED[3:], options=WALK_SEEDS) for f in CHAPTER_5_FAMILIES]
    + [Part(f, ("model-tree",), options=MODEL_TREE_OPTIONS[:1]) for f in ("small-lattice-hole", "small-random-40")]
    + [Part(f, ("model-tree",), options=MODEL_TREE_OPTIONS[1:], graphs=UNCUED_MODEL_TREE_GRAPHS)
       for f in ("small-lattice-hole", "small-random-40")]
    + [Part(f, ("model-tree",), options=MODEL_TREE_OPTIONS + ("cue=n,signatures=local",))
       for f in ("figure-3.4a", "figure-3.4b")]),
    "Chapter 5: mapping with less marker information (§5.1, §6.1, §5.2.1, Algorithm 5.1)")


@dataclass(frozen=True, order=True)
class Run:
    family: str  # the world family (runs.csv writes it in the column "experiment")
    size: int
    seed: int
    algorithm: str
    policy: str = "nearest"
    lighthouse: str = DEFAULT_LIGHTHOUSE
    options: str = ""  # an option set (module docstring)

    @property
    def key(self) -> tuple[str, str, str, str, str, str, str]:
        return (self.family, str(self.size), str(self.seed), self.algorithm, self.policy, self.lighthouse,
                self.options)


def marked_fraction_markers(world: World, algorithm: str, value: str) -> dict:
    """``marked-fraction=f`` for Case 5 (Figure 6.13): the K that marks ⌊f·n⌋ places.

    Version-1 gives v0 one marker and the j-th new place j + 1 until a drop is refused
    (:mod:`~topomark.reference.explorers.case5_v1`), so K = Σ_{i=1}^{p} i marks exactly p places.  The
    thesis gives no fractions and no K (neither Figure 6.13's caption, nor its text, §6.2.1); we give
    K = max(4, Σ_{i=1}^{⌊f·n⌋} i).  K ≥ 4 is the algorithm's least kit ("k > 3", §6.2.1 Case 5), which marks 2
    places: "0%" is that least kit (2 of n places marked), and 100% is Σ_{i=1}^{n} i (every place).

    Version-2 ("different fractions of (homogeneously) marked vertices", §6.2.1) drops two markers at v0, two
    on e0 and one at each other new place, and one on each loop edge met while it has markers
    (:mod:`~topomark.reference.explorers.case5_v2`).  Decision: K = max(4, ⌊f·n⌋ + 3), the pool that marks
    ⌊f·n⌋ places if no loop edge took a marker first (loop edges take markers from the same pool, so the
    fraction marked is at most f: the report shows the markers used), and 100% is the default m + 4, which
    marks every place and loop edge (the m V-E-marker algorithm's behaviour, §6.2.1 Case 5, the figure's lower end).
    """
    if algorithm not in ("case-5-v1", "case-5-v2"):
        raise InvalidInput(f"marked-fraction is defined for case-5-v1 and case-5-v2 only (given for {algorithm})")
    f = float(value)
    if not 0 <= f <= 1:
        raise InvalidInput(f"marked-fraction must be in [0, 1] (given {value})")
    places = int(f * world.n + 1e-9)
    if algorithm == "case-5-v2":
        return {"markers": world.m + 4 if places == world.n else max(4, places + 3)}
    return {"markers": max(4, sum_to(places))}


DERIVED_OPTIONS: dict[str, Callable[[World, str, str], dict]] = {"marked-fraction": marked_fraction_markers}
"""A derived option's name ↦ (world, algorithm, value) → the algorithm's options."""


def true_cue(world: World, algorithm: str, value: str) -> dict:
    """``cue=n`` / ``cue=m`` for Algorithm 5.1 (§5.3): the cue ``cue-n`` / ``cue-m`` with the world's true count."""
    if algorithm != "model-tree" or value not in ("n", "m"):
        raise InvalidInput(f"cue=n|m is defined for model-tree only (given cue={value} for {algorithm})")
    return {f"cue-{value}": world.n if value == "n" else world.m}


DERIVED_OPTIONS["cue"] = true_cue


def option_set(options: str) -> list[tuple[str, str]]:
    """The (name, value) pairs of a canonical option set ``name=value[,name=value]`` (``""``: none)."""
    pairs = []
    for item in filter(None, options.split(",")):
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise InvalidInput(f"option set {options!r}: {item!r} is not name=value")
        pairs.append((name, value))
    return pairs


def resolve_options(options: str, world: World, algorithm: str) -> dict:
    """The options ``explore`` gets for a run with this option set on this world."""
    out: dict = {}
    for name, value in option_set(options):
        if name in DERIVED_OPTIONS:
            out.update(DERIVED_OPTIONS[name](world, algorithm, value))
        else:
            out[name] = value
    return out


@functools.lru_cache(maxsize=8)
def world_for(world_family: str, size: int, seed: int) -> World:
    """The world of (world family, size, seed), with a start drawn from the seed.  Kept for the next runs (a sweep
    runs every algorithm on one world in turn; a World is never changed: a run's markers lie in its own layer)."""
    fam = FAMILIES[world_family]
    world = fam.build(size, seed)
    rng = random.Random(world_seed(world_family + "/start", size, seed))
    v = rng.choice(sorted(world.vertices, key=g.natural_key))
    facing = rng.choice(list(world.rotation[v]))
    return World(world.rotation, (), Start(v, facing))


@functools.lru_cache(maxsize=4096)
def _start_degree(world_family: str, size: int, seed: int) -> int:
    world = world_for(world_family, size, seed)
    return world.degree(world.start_state()[0])


def fits(world_family: str, size: int, seed: int, lighthouse: str) -> bool:
    """Whether the lighthouse can be dropped at the start drawn for this world (its start-degree condition)."""
    if lighthouse == NO_LIGHTHOUSE:
        return True
    need = LIGHTHOUSES[lighthouse].min_degree
    return need <= 1 or _start_degree(world_family, size, seed) >= need


def plan(experiment: str, graphs: int = 30, sizes: list[int] | None = None,
         heavy_graphs: int = HEAVY_GRAPHS, heavy_max_size: int = HEAVY_MAX_SIZE) -> list[Run]:
    """Every run of an experiment: world by world (seed 0 of every size first), largest worlds first within.

    A sweep stopped early thus leaves every size with (about) the same number of worlds done, and the
    largest runs of each round start first (load balance)."""
    if experiment not in EXPERIMENTS:
        raise unknown_name("experiment", experiment, EXPERIMENTS)
    runs: set[Run] = set()
    for part in EXPERIMENTS[experiment].parts:
        fam = FAMILIES[part.family]
        chosen: Sequence[int] = part.sizes or fam.sizes
        if sizes:  # a selection among the world family's (the thesis's) sizes
            chosen = [s for s in chosen if s in sizes]
        for size in chosen:
            for alg in part.algorithms:
                count = graphs if part.graphs is None else min(graphs, part.graphs)
                if is_heavy(part.family, alg):
                    count = min(graphs, heavy_graphs) if size <= heavy_max_size else 0
                lights = part.lighthouses if algorithm_spec(alg).uses_lighthouse else (NO_LIGHTHOUSE,)
                for seed in range(count):
                    runs.update(Run(part.family, size, seed, alg, pol, lh, opt) for pol in part.policies
                                for lh in lights for opt in part.options if fits(part.family, size, seed, lh))
    return sorted(runs, key=lambda r: (r.seed, -_weight(r), r))


def is_heavy(world_family: str, algorithm: str) -> bool:
    return world_family in ("complete-hole", "complete") and algorithm in ("enh5-d2", "enh3+5")


def _weight(r: Run) -> float:
    w = r.size ** 2 if "lattice" in r.family else r.size ** 3
    return w * (r.size if is_heavy(r.family, r.algorithm) else 1)
