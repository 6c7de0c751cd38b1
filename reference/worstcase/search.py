"""Adversarial search for bad worlds past exhaustive sizes, a lower bound on the worst case (§7.2).

§7.2 finds the O(m²n) bound of Algorithm 3.1 "quite loose", asks whether its pessimistic assumptions can
happen together and on which classes of graphs, and suggests bounds in terms of the diameter and the maximum
degree (§7.2).  Exhaustive enumeration (:mod:`.exhaustive`) answers for small worlds; past them this module
searches: :func:`adversarial_search` looks, for a registered algorithm, for a world of n vertices and maximum
degree <= D (its start included) that maximises one objective —

* ``cost``: the run's cost (traversals, as ``topomark explore`` counts them);
* ``cost-per-m``: cost ÷ m;
* ``ratio``: cost ÷ the algorithm's exact bound on that world (``AlgorithmSpec.bound_for(n, m)``); refused
  for an algorithm whose bound is asymptotic only or none (there is nothing exact to divide by).

A run that does not end with the algorithm claiming ``correct`` scores −∞ and is counted in ``failures`` (a
world the algorithm refuses, e.g. a start its lighthouse cannot use, counts the same way).  Every run is
unchecked (``check=False``): the search measures cost, the checks are ``topomark explore``'s job.

The optimiser is DEAP's (μ+λ) evolution strategy (``deap.algorithms.eaMuPlusLambda``), mutation only, with the
moves of :mod:`.moves` as its mutation. Its first generation is a quarter of the budget of random candidates, of
which the best μ go on: a single move changes a large world little, and on n = 100 a search started from only μ
random worlds was beaten by the best of as many random worlds. A population keeps several different bad worlds
alive (a graph family and its embedding are found together, and one annealing walk tends to lock into one of
them), and DEAP is maintained, documented and small. ``simanneal`` was the alternative; its last release is from
2019 and its own auto-tuning of temperatures spends evaluations we count. DEAP draws from the global ``random``
module: the search seeds it with ``seed`` and restores its state afterwards, and the moves draw from their own
``random.Random`` — the same seed gives the same best world and cost (in one process, as runs are
deterministic). With a restart family (:mod:`.structural`) the first generation is that family's world at n places
and μ − 1 neighbours of it instead: a search from structure that is already expensive, moved by the structural
moves that keep degrees, gains where random worlds barely beat chance. The budget is exact: the generations are sized to it and an offspring past the budget is not run
(it scores −∞ and is not counted).

:func:`random_baseline` is the comparison the search must beat: the best of as many random worlds
(:func:`~.moves.random_world`, or random hole patterns for the ``lattice-hole`` family).  :func:`adversarial_search`
runs both and reports them side by side (:meth:`AdversarialResult.to_json`); :func:`~.fit.fit_exponents` fits the
growth of the best found over several n.
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
import random
from dataclasses import dataclass
from typing import Any, Callable, Iterator

from deap import algorithms, base, tools

from topomark.spec.errors import AlgorithmStopped, CheckFailure, InvalidInput
from topomark.spec.world import World

from topomark.reference.algorithms.registry import AlgorithmSpec, algorithm_spec
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import explore
from topomark.reference.worlds.deterministic import integer_param, seed_param
from topomark.reference.worstcase.fit import fit_exponents
from topomark.reference.worstcase.found import AdversarialResult, Found
from topomark.reference.worstcase.moves import (ALL_MOVES, LatticeHoles, move_lattice, move_world, random_lattice,
                                                random_world)
from topomark.reference.worstcase.structural import RESTART_FAMILIES, restart_world

__all__ = ["adversarial_search", "random_baseline", "unchecked_run", "fit_exponents", "AdversarialResult", "Found", "OBJECTIVES",
           "FAMILIES", "MU", "LAMBDA", "START_SHARE"]

OBJECTIVES = ("cost", "cost-per-m", "ratio")
FAMILIES = ("general", "lattice-hole")
MU, LAMBDA = 8, 16  # the (μ+λ) sizes: 8 parents, 16 offspring per generation
START_SHARE = 4  # the first generation: a quarter of the budget (at least μ) of random candidates
HISTORY_POINTS = 20  # the history holds the best score after about every 1/20 of the budget


# -- the problem: checked parameters and the score of one candidate -------------------------
@dataclass
class _Problem:
    spec: AlgorithmSpec
    objective: str
    n: int
    max_degree: int
    evaluations: int
    seed: int
    family: str
    lighthouse: str | None
    policies: Policies | None
    shape: tuple[int, int] = (0, 0)
    restart: str | None = None  # what the first generation starts from (structural.restart_world: a family or a world)
    start_world: World | None = None  # the restart world, resolved once
    engine: bool = False  # runs through the compiled Algorithm 3.1 (topomark.reference.engine), equal to the reference

    def world_of(self, cand: World | LatticeHoles) -> World:
        return cand.world if isinstance(cand, LatticeHoles) else cand

    def draw(self, rng: random.Random) -> World | LatticeHoles:
        if self.restart is not None:  # the restart world, or a neighbour of it a few moves away
            world = self.start_world
            assert world is not None, "a restart's world is resolved with its parameters"
            for _ in range(rng.randrange(4)):
                world = move_world(world, self.max_degree, rng, ALL_MOVES)
            return world
        if self.family == "lattice-hole":
            return random_lattice(*self.shape, rng)
        return random_world(self.n, self.max_degree, rng)

    def move(self, cand: World | LatticeHoles, rng: random.Random) -> World | LatticeHoles:
        if isinstance(cand, LatticeHoles):
            return move_lattice(cand, rng)
        return move_world(cand, self.max_degree, rng, ALL_MOVES)

    def outcome(self, world: World) -> tuple[str, int, dict[str, int]]:
        """(claimed, cost, cost by purpose) of the unchecked run on ``world`` from its start."""
        return unchecked_run(world, self.spec, self.engine, self.lighthouse, self.policies)

    def run(self, cand: World | LatticeHoles) -> tuple[float, tuple[int, int] | None]:
        """(score, (cost, counted cost)) of one run; (−∞, None) for a run that does not end ``correct``."""
        world = self.world_of(cand)
        try:
            claimed, cost, by_purpose = self.outcome(world)
        except (InvalidInput, AlgorithmStopped, CheckFailure):
            return -math.inf, None
        if claimed != "correct":
            return -math.inf, None
        costs = (cost, self.spec.counted_cost(cost, by_purpose))
        if self.objective == "cost":
            return float(cost), costs
        if self.objective == "cost-per-m":
            return cost / world.m, costs
        return costs[1] / self.spec.bound_for(world.n, world.m), costs  # type: ignore[operator]


def _problem(algorithm: str, n: Any, max_degree: Any, objective: str, evaluations: Any, seed: Any,
             lighthouse: str | None, policies: Policies | None, family: str | None, restart: str | None = None,
             engine: str = "reference") -> _Problem:
    """The parameters checked: each wrong one is bad input naming it."""
    spec = algorithm_spec(algorithm)
    n = integer_param("n", n, 3)
    max_degree = integer_param("max_degree", max_degree, 2)
    evaluations = integer_param("evaluations", evaluations, 1)
    seed = seed_param(seed)
    if objective not in OBJECTIVES:
        raise InvalidInput(f"unknown objective {objective!r} (choose from {', '.join(OBJECTIVES)})")
    if objective == "ratio" and spec.bound_fn is None:
        raise InvalidInput(f"the objective ratio needs an exact cost bound, and the algorithm {spec.name} has "
                           f"none ({spec.bound_note}): use cost or cost-per-m")
    family = family or "general"
    if family not in FAMILIES:
        raise InvalidInput(f"unknown family {family!r} (choose from {', '.join(FAMILIES)})")
    spec.lighthouse_for(lighthouse)
    problem = _Problem(spec, objective, n, max_degree, evaluations, seed, family, lighthouse, policies)
    if restart is not None:
        if family != "general":
            raise InvalidInput(f"a restart replaces the random worlds of the general search, not the "
                               f"{family} family's")
        world = restart_world(restart, n)  # an unknown family or world, or a wrong size: bad input, before the runs
        largest = max(world.degree(v) for v in world.vertices)
        if largest > max_degree:
            raise InvalidInput(f"the restart {'family' if restart in RESTART_FAMILIES else 'world'} {restart} has "
                               f"places of degree {largest}: max_degree must be >= {largest}, got {max_degree}")
        problem.restart, problem.start_world = restart, world
    problem.engine = _compiled(engine, spec.name, lighthouse, policies)
    if family == "lattice-hole":
        if max_degree < 4:
            raise InvalidInput(f"the lattice-hole family has cells of degree 4: max_degree must be >= 4, "
                               f"got {max_degree}")
        rows = math.isqrt(n)
        problem.shape = (rows, n // rows)
    return problem


def _compiled(engine: str, algorithm: str, lighthouse: str | None, policies: Policies | None) -> bool:
    """Whether the runs go through the compiled engine (``engine``: reference, compiled or auto, as
    :func:`topomark.reference.engine.choose` resolves it)."""
    from topomark.reference.engine import choose
    p = policies or Policies()
    return choose(engine, algorithm, lighthouse, (p.edge, p.hypothesis, p.path))[0] == "compiled"


# -- counting evaluations, the best so far and the history -----------------------------------
def unchecked_run(world: World, spec: Any, engine: bool, lighthouse: str | None = None,
                  policies: Policies | None = None) -> tuple[str, int, dict[str, int]]:
    """(claimed, cost, cost by purpose) of ``spec``'s unchecked run on ``world`` from its start: on the compiled
    engine when ``engine`` (see :func:`_compiled`), else on the reference."""
    if engine:
        from topomark.proofs.world_arrays import to_arrays
        from topomark.reference.engine.runs import run_starts
        at, entry = world.start_state()
        chosen = policies or Policies()
        run = run_starts(to_arrays(world), [(world.vertices.index(at), entry)],
                         (chosen.edge, chosen.hypothesis, chosen.path), lighthouse=lighthouse, algorithm=spec.name)[0]
        return run.claimed, run.cost, run.by_purpose
    out = explore(world, spec, lighthouse=lighthouse, policies=policies, check=False, record=False)
    return out.claimed, out.cost, out.by_purpose


class _Tally:
    def __init__(self, problem: _Problem, progress: Callable[[int, float], None] | None):
        self.problem, self.progress = problem, progress
        self.done = self.failures = 0
        self.best: tuple[float, World | LatticeHoles, tuple[int, int]] | None = None
        self.every = max(1, problem.evaluations // HISTORY_POINTS)
        self.history: list[tuple[int, float]] = []

    @property
    def best_score(self) -> float:
        return -math.inf if self.best is None else self.best[0]

    def evaluate(self, cand: World | LatticeHoles) -> float:
        """The score of ``cand`` (−∞, not run and not counted, once the budget is spent)."""
        if self.done >= self.problem.evaluations:
            return -math.inf
        score, costs = self.problem.run(cand)
        self.done += 1
        if costs is None:
            self.failures += 1
        elif score > self.best_score:
            self.best = (score, cand, costs)
        if self.done % self.every == 0 or self.done == self.problem.evaluations:
            self.history.append((self.done, self.best_score))
            if self.progress is not None:
                self.progress(self.done, self.best_score)
        return score

    def result(self) -> AdversarialResult:
        p = self.problem
        found = None
        if self.best is not None:
            score, cand, (cost, counted) = self.best
            holes = cand.hole_names() if isinstance(cand, LatticeHoles) else None
            found = Found(p.world_of(cand), score, cost, counted, holes)
        return AdversarialResult(p.spec.name, p.objective, p.n, p.max_degree, self.done, p.seed, p.family, found,
                            self.failures, self.history, spec=p.spec, restart=p.restart)


# -- the random baseline and the (μ+λ) search ------------------------------------------------------
def random_baseline(algorithm: str = "basic", n: int = 20, max_degree: int = 4, objective: str = "cost",
                    evaluations: int = 200, seed: int = 0, lighthouse: str | None = None,
                    policies: Policies | None = None, family: str | None = None,
                    progress: Callable[[int, float], None] | None = None, engine: str = "reference") -> AdversarialResult:
    """The best of ``evaluations`` random candidates (:func:`~.moves.random_world`, or
    :func:`~.moves.random_lattice` for ``family="lattice-hole"``), drawn from ``random.Random(seed)``."""
    problem = _problem(algorithm, n, max_degree, objective, evaluations, seed, lighthouse, policies, family,
                       engine=engine)
    return _baseline(problem, progress)


def _baseline(problem: _Problem, progress: Callable[[int, float], None] | None) -> AdversarialResult:
    problem = dataclasses.replace(problem, restart=None, start_world=None)  # random worlds, whatever the search started from
    rng = random.Random(f"random-baseline:{problem.seed}")
    tally = _Tally(problem, progress)
    for _ in range(problem.evaluations):
        tally.evaluate(problem.draw(rng))
    return tally.result()


class _Fitness(base.Fitness):
    weights = (1.0,)


class _Individual(list):
    """A DEAP individual: a list holding one candidate (a world, or a lattice with holes)."""

    def __init__(self, items: Any = ()):
        super().__init__(items)
        self.fitness = _Fitness()


def _clone(ind: _Individual) -> _Individual:
    copy = _Individual(ind)  # candidates are immutable: a shallow copy is a clone
    if ind.fitness.valid:
        copy.fitness.values = ind.fitness.values
    return copy


@contextlib.contextmanager
def _global_random(seed: int) -> Iterator[None]:
    """DEAP draws from the global ``random`` module: seed it for the search, then put its state back."""
    state = random.getstate()
    random.seed(seed)
    try:
        yield
    finally:
        random.setstate(state)


def adversarial_search(algorithm: str = "basic", n: int = 20, max_degree: int = 4, objective: str = "cost",
                       evaluations: int = 200, seed: int = 0, lighthouse: str | None = None,
                       policies: Policies | None = None, family: str | None = None,
                       progress: Callable[[int, float], None] | None = None, baseline: bool = True,
                       restart: str | None = None, engine: str = "reference") -> AdversarialResult:
    """Search for a world (start included) of ``n`` vertices and degrees <= ``max_degree`` maximising
    ``objective`` for ``algorithm``, in ``evaluations`` runs, by DEAP's (μ+λ) strategy (:data:`MU`,
    :data:`LAMBDA`) from a first generation of a quarter of the budget (at least μ) of random candidates
    (:data:`START_SHARE`), the best μ of which the strategy keeps; with ``baseline`` (the default),
    :func:`random_baseline` with the same budget and seed is run too and kept in ``.random``.
    ``family="lattice-hole"`` searches hole patterns of the ⌊√n⌋ x ⌊n/⌊√n⌋⌋ lattice (8 x 8 for n = 64) instead.
    ``restart`` (one of :data:`~.structural.RESTART_FAMILIES`, or a world of n places that ``topomark explore``
    accepts) starts from that world (:func:`~.structural.restart_world`) and μ of its neighbours instead of random
    worlds.  ``engine`` (reference,
    compiled or auto) says what runs the candidates: the compiled Algorithm 3.1, which agrees with the reference
    exactly, runs ``basic`` some hundred times faster.
    ``progress(evaluations_done, best_score)`` is called after about every 1/20 of the budget.  Bad parameters
    raise InvalidInput naming the first wrong one."""
    problem = _problem(algorithm, n, max_degree, objective, evaluations, seed, lighthouse, policies, family, restart,
                       engine)
    tally = _Tally(problem, progress)
    rng = random.Random(f"adversarial-search:{problem.seed}")
    toolbox = base.Toolbox()
    toolbox.register("evaluate", lambda ind: (tally.evaluate(ind[0]),))
    toolbox.register("mutate", lambda ind: (_mutated(ind, problem, rng),))
    toolbox.register("select", lambda inds, k: tools.selBest(inds[::-1], k))  # ties: the newer (a plateau walks)
    toolbox.register("clone", _clone)
    first = min(problem.evaluations, MU if problem.restart else max(MU, problem.evaluations // START_SHARE))
    population = [_Individual([problem.draw(rng)]) for _ in range(first)]
    if problem.restart is not None:  # the restart world itself among them: a restart can only gain on it
        population[0] = _Individual([problem.start_world])
    generations = math.ceil((problem.evaluations - first) / LAMBDA)
    with _global_random(problem.seed):
        algorithms.eaMuPlusLambda(population, toolbox, mu=min(MU, first), lambda_=LAMBDA, cxpb=0.0, mutpb=1.0,
                                  ngen=generations, verbose=False)
    result = tally.result()
    if baseline:
        result.random = _baseline(problem, None)
    return result


def _mutated(ind: _Individual, problem: _Problem, rng: random.Random) -> _Individual:
    ind[0] = problem.move(ind[0], rng)
    return ind
