"""What a conformance suite holds: Algorithm 3.1's cases (§3.3–3.5) and one suite per registered algorithm.

:func:`default_cases` are Algorithm 3.1's worlds — the thesis's figures (the
Figure 3.4/3.6 wheel pair, the trace.md triangle, the Figure 3.3 cycles,
chains), generated world families of §3.5.3 across sizes, and the worst worlds
``topomark worst-case`` found for Algorithm 3.1 and its §4.1 enhancements
(stress cases, §7.2) — each run under
every named policy of :data:`POLICIES` (§3.3 leaves the edge, hypothesis and
path choices open).

:func:`algorithm_cases` are one algorithm's: a few small worlds (the triangle,
C4, the 2×3 lattice, K4, a chiral world, a chain, a triangle with one leaf) under the kit the registry gives that algorithm on
each (``kit_for(n, m, options)``: the thesis's exact budgets, e.g. Case 3a's
Σ_{k=1}^{n−1} k), and, for an algorithm whose kit size is an
option (``--markers``, ``--thread-length``), the 2×3 lattice with the smallest kit it takes — where
most run out of markers or thread and must report failure (§6.2.1: "running out is the
``failed`` outcome"; §6.3.2), and where Case 5 is forced into phase II; and, as stress cases, the worst worlds
``topomark worst-case`` found for it (:mod:`topomark.reference.worlds.worst_cases`,
§7.2).  The export keeps the cases that cover the ways the algorithm's runs can go
(:mod:`~topomark.reference.oracle.conformance.coverage`).  Only deterministic algorithms have suites: a reference
run of a randomised one fixes nothing a client could be held to.

:data:`FAMILIES` groups the algorithms for ``--family``: a family's members
share their worlds and the kind of kit they carry (§3.3 and Chapter 4's
lighthouse algorithms; §2.3.1's movable marker; §6.2.1's undirected and §6.2.2's
directional markers; §6.3's threads; §2.3.1's classic baselines, whose markers stay where dropped).
"""

from __future__ import annotations

from typing import Any, Iterable

from topomark.spec.errors import InvalidInput, unknown_name
from topomark.spec.kit import Kit
from topomark.spec.world import Start, World

from topomark.reference.algorithms.registry import REGISTRY, AlgorithmSpec, algorithm_spec
from topomark.reference.explorers.policies import Policies
from topomark.reference.worlds import generators as g
from topomark.reference.worlds.worst_cases import worst_case_worlds

__all__ = ["POLICIES", "FAMILIES", "default_cases", "algorithm_cases", "accepts", "family_of", "suite_algorithms", "started"]

POLICIES: dict[str, Policies] = {  # the default, and each other named policy of policies.py alone
    "default": Policies(),
    "edge-fifo": Policies(edge="fifo"),
    "edge-lifo": Policies(edge="lifo"),
    "hypothesis-lifo": Policies(hypothesis="lifo"),
    "hypothesis-shortest": Policies(hypothesis="shortest"),
    "path-dfs": Policies(path="dfs"),
}
FAMILIES: dict[str, str] = {  # family ↦ what its members share (their thesis sections)
    "algorithm-3.1": "§3.3, Chapter 4: one directional vertex marker (the lighthouse)",
    "movable-markers": "§2.3.1: one movable marker, dropped and picked up again",
    "undirected-markers": "§6.2.1: many undirected vertex, edge or vertex-or-edge markers",
    "directional-markers": "§6.2.2: many directional vertex or edge markers",
    "threads": "§6.3: a thread",
    "marker-less": "§5.2: no marker",
    "baselines": "§2.3.1, Table 2.3: the classic models the thesis compares with (footprints, a labelled graph)",
    "other": "an algorithm of none of the families above (one added by a registration module of its own)",
}
_SECTIONS = (("§2.3.1", "movable-markers"), ("§5", "marker-less"), ("§6.2.1", "undirected-markers"),
             ("§6.2.2", "directional-markers"), ("§6.3", "threads"))


CHIRAL = World({"0": ("1", "2", "4"), "1": ("0", "2"), "2": ("1", "0", "3"), "3": ("2",), "4": ("0",)}, (),
               Start("0", "1"))
"""The smallest connected planar world (networkx's atlas) not extended-isomorphic to its mirror image: a map
with every rotation reversed fails on it, where on the wheels, the cycles and K4 it would pass."""

PAW = World({"0": ("1", "2", "3"), "1": ("0", "2"), "2": ("1", "0"), "3": ("0",)}, (), Start("1", "2"))
"""A triangle with one leaf (the paw), entered away from the leaf: the shared world with exactly one place of
degree 1, where §5.3's single-leaf search walks before it maps."""


def started(world: World) -> World:
    """The world with an explicit start: its own, or its first vertex facing exit 0."""
    if world.start is not None:
        return world
    v = world.vertices[0]
    return world.with_start(Start(v, world.rotation[v][0]))


def default_cases() -> list[tuple[str, str, World]]:
    """(name, description, world) of Algorithm 3.1's suite: thesis figures, then world families across sizes."""
    wa, wb = g.wheel_pair_directional()
    cases = [
        ("figure-3.6-wheel-a", "Figure 3.4/3.6(a): planar wheel W4, directional marker at the centre", wa),
        ("figure-3.6-wheel-b", "Figure 3.4/3.6(b): twisted wheel W4 (genus 1)", wb),
        ("triangle", "the spec/trace.md example: C3 at 0 facing 1", g.cycle(3)),
    ]
    for n in (4, 7, 12):
        cases.append((f"cycle-{n}", f"Figure 3.3: the cycle C{n}", g.cycle(n)))
    for n in (2, 6):
        cases.append((f"chain-{n}", f"a chain of {n} vertices", g.chain(n)))
    for r, c in ((2, 3), (3, 3), (4, 4)):
        cases.append((f"lattice-{r}x{c}", f"§3.5.3: the {r}x{c} lattice", g.lattice(r, c)))
    cases.append(("lattice-hole-5x5-s1", "§3.5.3: 5x5 lattice, 10% of cells removed, seed 1",
                  g.lattice_hole(5, 5, 0.1, "vertices", 1)))
    cases.append(("lattice-hole-6x6-edges-s2", "§3.5.3: 6x6 lattice, 10% of edges removed, seed 2",
                  g.lattice_hole(6, 6, 0.1, "edges", 2)))
    for n in (4, 6):
        cases.append((f"complete-{n}", f"§3.5.3: the complete graph K{n} (non-planar rotation)", g.complete(n)))
    cases.append(("complete-hole-7-s3", "§3.5.3: K7 with 10% of edges removed, seed 3", g.complete_hole(7, 0.1, 3)))
    cases.append(("small-world-12-s4", "§3.5.3: small-world n=12 k=4 p=0.2, seed 4", g.small_world(12, 4, 0.2, 4)))
    for seed in (5, 6):
        cases.append((f"random-9-s{seed}", f"§3.5.3: random graph n=9, 40% density, seed {seed}",
                      g.random_graph(9, 0.4, seed)))
    cases += _stress_cases(("basic", "enh1", "enh2", "enh3"))
    return [(name, text, started(w)) for name, text, w in cases]


def _stress_cases(algorithms: Iterable[str]) -> list[tuple[str, str, World]]:
    """The worst worlds ``topomark worst-case`` found for ``algorithms`` (§7.2), each from its worst start: stress
    cases, where an implementation walks the longest of any world of that size."""
    return [case for name in algorithms for case in worst_case_worlds(name)]


def _algorithm_worlds() -> list[tuple[str, str, World]]:
    """The worlds every algorithm's suite uses (the same files as Algorithm 3.1's cases of the same name)."""
    return [(name, text, started(w)) for name, text, w in (
        ("triangle", "C3 at 0 facing 1", g.cycle(3)),
        ("cycle-4", "Figure 3.3: the cycle C4", g.cycle(4)),
        ("lattice-2x3", "§3.5.3: the 2x3 lattice", g.lattice(2, 3)),
        ("complete-4", "§3.5.3: the complete graph K4 (non-planar rotation)", g.complete(4)),
        ("chiral-5", "a triangle with a leaf at two of its corners: its mirror image is another world", CHIRAL),
        ("chain-6", "a chain of 6 vertices: a tree", g.chain(6)),
        ("paw-4", "a triangle with one leaf, entered away from it", PAW),
    )]


_TIGHT = {  # an option that sizes the kit ↦ (its smallest value, the case's name suffix, what the kit then is)
    "markers": (lambda p: max(2, p.minimum or 0), "markers", "markers (--markers {k}): an exact budget that may run "
                "out, when the algorithm must report failure (§6.2.1), or, for Case 5, force phase II"),
    "thread-length": (lambda p: 1, "thread", "edge of thread (--thread-length {k}): a thread too short for the world, "
                      "when the algorithm must report failure (§6.3.2)"),
}


def algorithm_cases(spec: AlgorithmSpec) -> list[tuple[str, str, str, World, dict[str, Any]]]:
    """(name, world name, description, world, options) of ``spec``'s suite: the shared worlds with the registry's
    default kit, and a smallest kit where the kit's size is an option (``--markers``, ``--thread-length``: the
    export keeps such a case only where its run goes a way the others do not,
    :mod:`~topomark.reference.oracle.conformance.coverage`).  An algorithm for a class
    of worlds (its registration's ``check_world``) has a case on the shared worlds it accepts only (a tree walk:
    the chain); one that accepts none of them has no suite (:func:`suite_algorithms`)."""
    cases: list[tuple[str, str, str, World, dict[str, Any]]] = [
        (name, name, f"{text}, with the kit {spec.name} is given on it", world, {})
        for name, text, world in _algorithm_worlds() + _stress_cases([spec.name]) if accepts(spec, world)]
    name, text, world = _algorithm_worlds()[2]
    for p in spec.parameters:
        if p.name in _TIGHT and accepts(spec, world):
            smallest, suffix, words = _TIGHT[p.name]
            k = smallest(p)
            cases.append((f"{name}-{suffix}-{k}", name, f"{text} with only {k} {words.format(k=k)}", world,
                          {p.name: k}))
    return cases


def accepts(spec: AlgorithmSpec, world: World) -> bool:
    """Whether ``spec``'s registration accepts ``world`` with its default options (``check_world``)."""
    if spec.check_world is None:
        return True
    try:
        spec.check_world(world, spec.parse_options({}))
    except InvalidInput:
        return False
    return True


def family_of(spec: AlgorithmSpec) -> str:
    """The conformance family of an algorithm (:data:`FAMILIES`), from its thesis section; an algorithm of no
    section named there is ``marker-less`` if it carries nothing, else ``other``."""
    if spec.uses_lighthouse:
        return "algorithm-3.1"
    section = spec.thesis.split()[0].rstrip(",")
    empty = spec.kit_fn is None and spec.kit == Kit()
    family = next((family for prefix, family in _SECTIONS if section.startswith(prefix)),
                  "marker-less" if empty else "other")
    return "baselines" if family == "movable-markers" and not spec.kit.movable else family


def suite_algorithms(names: Iterable[str] = (), families: Iterable[str] = ()) -> list[AlgorithmSpec]:
    """The deterministic algorithms named, and those of the families named, in listing order; with neither,
    every deterministic algorithm.  A randomised one, or an unknown name or family, is bad input."""
    names, families = list(names), list(families)
    for family in families:
        if family not in FAMILIES:
            raise unknown_name("family", family, FAMILIES)
    for name in names:
        if not algorithm_spec(name).deterministic:
            raise InvalidInput(f"the algorithm {name} is randomised: it has no conformance suite (its reference run "
                               f"fixes nothing a client could be held to); choose a deterministic one")
    for name in names:
        if not algorithm_cases(algorithm_spec(name)):
            raise InvalidInput(f"the algorithm {name} accepts none of the suite's worlds: it has no conformance suite")
    chosen = [s for s in REGISTRY.values() if s.deterministic and algorithm_cases(s)
              and (not (names or families) or s.name in names or family_of(s) in families)]
    if not chosen:
        raise InvalidInput(f"the families {', '.join(families)} have no deterministic algorithm")
    return chosen
