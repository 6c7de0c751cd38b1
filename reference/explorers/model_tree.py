"""Mapping with no markers by a tree of world models: Algorithm 5.1 (thesis §5.2.2; §5.3 cues).

The robot carries nothing (an empty kit) and senses only degrees.  Each step
(:meth:`ModelTreeExplorer.step`) is one pass of Algorithm 5.1:

1. the robot walks the traversal map TM (:mod:`.traversal_map`) to the next
   frontier vertex in breadth-first order and explores its next exit; TM is
   always augmented non-loop (lines 1–2);
2. every world model made in the previous step is processed (lines 3–34,
   Figure 5.2): walked virtually along the motions of the step, it is
   *voided* on a degree mismatch, *passed* (one child, same map, new pose)
   when the explored edge is already explored in it, and otherwise gets one
   child per accepted loop-closing hypothesis and, always last, the non-loop
   child.  ``--signatures global`` accepts a hypothesis only when the robot,
   walking to every known vertex of the hypothesised model, meets no
   mismatch (:mod:`.global_signatures`); ``--signatures local`` accepts every
   degree-matching one without moving (§5.2.2's "simplest approach", the
   thesis's comparison of §5.2.2); ``--entry-check yes`` (default) adds the
   entry-edge information of §5.2.2 to the global validation.

Termination, all decided here since the thesis gives one heuristic only (§5.2.2):

* §5.2.2: a model that is the only completed model for ``--window`` steps
  (default 100, the thesis's example) is returned;
* a sole live model that is completed is returned at once: the true model
  is never voided (the ``models`` check asserts it), so it is the truth,
  and it can only pass from then on — the window rule would return it
  ``window`` steps later, at more cost and with no more information;
* every live model completed and no walk telling any two apart
  (:func:`.model_shapes.walk_equivalent`): no step can ever void one, so the
  window rule can never fire; :class:`AlgorithmFailed` says so at once
  (e.g. the Figure 3.4 pair from the centre, every cycle length with no
  cue: the latter never gets there, its longer cycles still growing);
* TM complete (the world is a tree: its breadth-first unfolding is finite):
  the sole completed model is returned;
* ``--max-steps`` / ``--max-models`` reached: :class:`LimitReached` (the
  thesis's "never terminates", §5.2.1), naming the cap, the step and the
  counts; every model voided: :class:`AlgorithmFailed` (cannot happen
  unless a cue is false).

As listed (``model-tree-listing``): three switches, class attributes each off here, undo the three ways this
explorer changes Algorithm 5.1; :class:`ListingModelTreeExplorer` turns all three on.

* ``listing_hypotheses`` (line 17): a hypothesis that would make a multi-edge is formed too, as line 17 takes
  every unexplored edge whose known end shows v_u's degree.  Decision: one that would make a self-loop (e' at
  v_k itself) is still not formed, as §3.3's text has it for the same loop closing ("Every vertex (except v_k)
  in S could potentially correspond to v_u"; Algorithm 3.1's ``basic`` follows it), and a map edge may not be
  one (:class:`~topomark.spec.mapstate.PartialMap`).
* ``listing_paths`` (lines 18–23): one path from v_k' to each known vertex v_l in turn, out and back
  (:func:`.global_signatures.validate_paths`), not one breadth-first tree.
* ``listing_stops`` (§5.2.2's heuristic): a run ends only by the window rule, the caps, every model voided,
  the traversal map completed (decision: no step is left to walk, so no model can change and the sole
  completed one would stay so for any window; as here) and the §5.3 cues (with ``cue-n`` or ``cue-m``, "the
  exploration process can terminate as soon as all the current models have n vertices": a sole live
  completed model ends it, as here).  Without a cue a live model may stay completed beside another forever
  (walk-equivalent ones, Figure 3.4): the listing never terminates, so the run ends at ``--max-steps``
  (:class:`LimitReached`, §5.2.1's "never terminates").

Cues of §5.3 (none was run in the thesis).  The registry's
options are single-valued, so each cue is its own option: ``cue-n``, ``cue-m``, ``cue-diameter`` (integers)
and ``cue-planar`` (yes/no).  A cue is prior knowledge, true of the world:
the registration refuses a false ``cue-n``/``cue-m`` as bad input.

* ``cue-n`` / ``cue-m``: a model with more vertices / edges is voided, and so
  is a *completed* one with fewer (it would be the whole world); the run
  ends as soon as one model is left and it is completed (§5.3: "terminate
  as soon as all the current models have n vertices").
* ``cue-diameter D``: a completed model of diameter > D is voided (a partial
  model's diameter can still shrink, so §5.3's rejection of "a model with too
  large a diameter" waits for it to be completed); once TM has been
  explored to depth D (every exit of every TM vertex at depth ≤ D taken,
  §5.3: "cease exploration after depth d of the traversal map"), every
  world edge has been walked, so each model not completed is voided and the
  run ends: with the sole model left, or as :class:`AlgorithmFailed` naming
  how many completed models it cannot tell apart.
* ``prior single-leaf`` (§5.3: "we know that there exists exactly one
  'leaf vertex' in the world"): a model with two places of degree 1 is
  voided, and so is a completed one with none.  This is a model-tree prior:
  it prunes the tree like a cue and keeps Algorithm 5.1's termination and
  caps, so it is not §5.3's method.  The thesis's use of the knowledge — search
  for the leaf and use it as Algorithm 3.1's directional lighthouse, mapping
  deterministically — is the ``single-leaf`` algorithm
  (:mod:`.single_leaf`).
* ``rank yes``: the completed models are ranked by P(model | perceptions)
  (:mod:`.model_prior`, §5.3), for the run's summary; it voids nothing.
* ``cue-planar yes``: a model whose rotation system has genus > 0 is voided
  (planar = a genus-0 embedding, the world being an embedded graph §3.1.1;
  a sub-embedding never has a larger genus than the world).

The explorer keeps every live model as a (shape, pose) pair
(:mod:`.model_shapes`, shared structure) and exposes them by :meth:`models`
as (PartialMap, pose) pairs for the checker's ``models`` check; each names
the start place (0, 0), as ``position`` does after :meth:`start`.  At the end
``S``/``position`` are the returned model's.  ``completed_models`` (every
model that became completed, as PartialMaps, in completion order) and
``peak_models`` are attributes for the CLI.

Example: ``topomark explore chain:n=5 --algorithm model-tree --window 5``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, cast

from topomark.spec.errors import AlgorithmFailed, LimitReached, TopomarkFault
from topomark.spec.mapstate import MapDart, PartialMap

from topomark.reference.explorers.robot import Robot
from topomark.reference.explorers.global_signatures import Walker, validate, validate_paths
from topomark.reference.explorers.model_shapes import Model, Shape, walk_equivalent
from topomark.reference.explorers.traversal_map import TraversalMap
from topomark.reference.explorers.walker import ExplorerState

__all__ = ["ModelTreeExplorer", "ListingModelTreeExplorer", "Step", "Closing", "DEFAULTS"]

DEFAULTS = {"signatures": "global", "entry-check": "yes", "window": 100, "max-models": 10000, "max-steps": 2000,
            "cue-n": None, "cue-m": None, "cue-diameter": None, "cue-planar": "no", "prior": "none", "rank": "no"}
"""The options and their defaults (the registration's parameters carry the same)."""


@dataclass
class Closing:
    """One loop-closing hypothesis e' of a model (line 17) and what became of it."""

    model: int  # index of the model among the step's models
    dart: MapDart
    outcome: str = "untested"  # "case 3" accepted by validation, "case 2" a mismatch, "local", "cue"
    moves: int = 0

    def to_json(self) -> dict:
        return {"model": self.model, "dart": list(self.dart), "outcome": self.outcome, "moves": self.moves}


@dataclass
class Step:
    """One step of Algorithm 5.1: the TM edge explored and what the model tree did."""

    number: int
    edge: MapDart  # (TM vertex, exit)
    motions: tuple[int, ...] = ()
    degrees: tuple[int, ...] = ()
    hypotheses: list[Closing] = field(default_factory=list)
    kind: str = "model-tree"
    processed: int = 0
    passed: int = 0
    voided: int = 0
    live: int = 0
    completed: int = 0

    def to_json(self) -> dict:
        return {"step": self.number, "edge": list(self.edge), "motions": list(self.motions),
                "degrees": list(self.degrees), "hypotheses": [h.to_json() for h in self.hypotheses],
                "processed": self.processed, "passed": self.passed, "voided": self.voided, "live": self.live,
                "completed": self.completed}


class ModelTreeExplorer(ExplorerState):
    """Algorithm 5.1 on a robot with no marker; ``observer(explorer, step)`` runs after every step (recorded as
    every explorer records one, :class:`~.walker.ExplorerState`; its map is the model tree's, not one S)."""

    name = "model-tree"
    listing_hypotheses = listing_paths = listing_stops = False  # the listing's ways (module docstring)
    literal = False  # all three: Algorithm 5.1 as listed

    def __init__(self, robot: Robot, policies=None, observer: Callable | None = None, options: dict | None = None):
        super().__init__(robot, observer)  # S (the returned model's at the end), position, iterations
        self.options = {**DEFAULTS, **{k: v for k, v in (options or {}).items() if v is not None}}
        self.live: list[Model] = []
        self.completed_models: list[PartialMap] = []
        self.peak_models = 0
        self.finished = False
        self.tm: TraversalMap | None = None
        self.walker: Walker | None = None
        self._tm_pose: MapDart = (0, 0)
        self._sole: tuple[Shape | None, int] = (None, 0)  # the sole completed shape and the step it became so
        self._checked: tuple[tuple, bool] = ((), False)  # the live shapes last compared walk by walk, and the answer

    @property
    def _tm(self) -> TraversalMap:
        """TM, made by :meth:`start`, which runs before every step."""
        return cast(TraversalMap, self.tm)

    @property
    def _walker(self) -> Walker:
        return cast(Walker, self.walker)

    # -- the explorer contract -------------------------------------------------------
    def start(self) -> None:
        """TM and the one model hold the start vertex, entered by exit 0 (the exit the robot faces)."""
        degree = self.robot.sense().degree
        self.tm = TraversalMap(degree)
        self.walker = Walker(self.robot, degree)
        self.live = [Model(Shape.start(degree), (0, 0))]
        self.S = self.live[0].shape.partial_map()
        self.position = (0, 0)
        self.peak_models = 1

    def done(self) -> bool:
        return self.finished

    def models(self) -> list[tuple[PartialMap, MapDart]]:
        """The live models as (map, believed pose) pairs; each names the start place (0, 0).  The pose is where
        the robot really stands: a validation walk brings it back by another edge (the walker's ``turn``)."""
        return [(m.shape.partial_map(), self._physical(m)) for m in self.live]

    def _physical(self, model: Model) -> MapDart:
        v, e = model.pose
        return (v, (e + self.walker.turn) % model.shape.degree(v)) if self.walker is not None else (v, e)

    def step(self) -> Step:
        """One pass of Algorithm 5.1 (lines 1–34), then the termination rules."""
        number = len(self.iterations) + 1
        if number > self.options["max-steps"]:
            raise LimitReached(f"--max-steps {self.options['max-steps']} reached: {len(self.live)} live model(s), "
                               f"{self._completed_count()} completed, none returned")
        frontier = self._tm.frontier()
        if frontier is None:
            return self._tm_complete(number)
        record = Step(number, frontier)
        motions, degrees = self._walk_tm(frontier)
        record.motions, record.degrees = tuple(motions), tuple(degrees)
        self.live = self._process(record, motions, degrees)
        self._apply_cues_after(record)
        self.peak_models = max(self.peak_models, len(self.live))
        record.live, record.completed = len(self.live), self._completed_count()
        self.record(record)  # the models check sees this step's models before any stop
        self._terminate(number)
        return record

    # -- lines 1-2: TM -----------------------------------------------------------------
    def _walk_tm(self, frontier: MapDart) -> tuple[list[int], list[int]]:
        """Walk TM to the frontier vertex and take its next exit; the logical motions and the degrees sensed."""
        tm, (here, entry) = self._tm, self._tm_pose
        motions, degrees = [], []
        for v, x in tm.path(here, frontier[0]) + [frontier]:
            k = (x - entry) % tm.degree[v]
            new = (v, x) == frontier
            degree = self._walker.move(k, "new" if new else "travel")
            motions.append(k)
            degrees.append(degree)
            if new:
                here, entry = tm.add(v, x, degree), 0
            else:
                here, entry = tm.arrive((v, x))
                if tm.degree[here] != degree:
                    raise TopomarkFault(f"the traversal map's vertex {here} has degree {tm.degree[here]}, "
                                        f"the robot sensed {degree}: TM is not the world's unfolding")
        self._tm_pose = (here, entry)
        return motions, degrees

    # -- lines 3-34: the models of the previous step -----------------------------------
    def _process(self, record: Step, motions: list[int], degrees: list[int]) -> list[Model]:
        children: list[Model] = []
        for index, model in enumerate(self.live):
            record.processed += 1
            shape, (v, e) = model.shape, model.pose
            for t, (k, degree) in enumerate(zip(motions, degrees)):
                x = (e + k) % shape.degree(v)
                reached = shape.arc((v, x))
                if reached is None:  # line 15: e is unexplored in M
                    if t != len(motions) - 1:
                        raise TopomarkFault(f"model {index} has no edge for travel motion {t} of step "
                                            f"{record.number}: every TM edge was explored in every model")
                    self._augment(record, index, shape, (v, x), degree, children)
                    break
                v, e = reached
                if shape.degree(v) != degree:  # lines 6-7, 9-10: void M
                    record.voided += 1
                    break
            else:  # lines 11-13: pass M
                record.passed += 1
                self._add(children, Model(shape, (v, e)), new=False)
        return children

    def _augment(self, record: Step, index: int, shape: Shape, dart: MapDart, degree: int,
                 children: list[Model]) -> None:
        """Lines 17–33: a child per accepted loop closing, then the non-loop child (Figure 5.2(c))."""
        vk = dart[0]
        for hyp in shape.open_darts():
            w = hyp[0]
            if w == vk or shape.degree(w) != degree or not self.listing_hypotheses and shape.adjacent(vk, w):
                continue  # degree mismatch, or a self-loop / multi-edge, which no world has (§3.1.1)
            closing = Closing(index, hyp)
            record.hypotheses.append(closing)
            child = shape.join(dart, hyp)
            if not self._admissible(child):
                closing.outcome = "cue"
                continue
            if self.options["signatures"] == "local":
                closing.outcome = "local"
            else:
                walk = validate_paths if self.listing_paths else validate
                ok, closing.moves = walk(self._walker, child, w, hyp[1], self.options["entry-check"] == "yes")
                closing.outcome = "case 3" if ok else "case 2"
                if not ok:
                    continue
            self._add(children, Model(child, hyp))
        child = shape.add_vertex(degree, dart)
        if self._admissible(child):
            self._add(children, Model(child, (child.n - 1, 0)))

    def _add(self, children: list[Model], model: Model, new: bool = True) -> None:
        """A child into the next level; a new model that is completed is recorded, in completion order."""
        children.append(model)
        if new and model.shape.complete():
            self.completed_models.append(model.shape.partial_map())
        if len(children) > self.options["max-models"]:
            raise LimitReached(f"--max-models {self.options['max-models']} exceeded at step "
                               f"{len(self.iterations) + 1}: {len(children)} live models so far")

    # -- §5.3 cues ------------------------------------------------------------------------
    def _admissible(self, shape: Shape) -> bool:
        """A model augmented this step survives the cues given."""
        o = self.options
        if o["cue-n"] is not None and (shape.n > o["cue-n"] or shape.complete() and shape.n != o["cue-n"]):
            return False
        if o["cue-m"] is not None and (shape.edges > o["cue-m"] or shape.complete() and shape.edges != o["cue-m"]):
            return False
        if o["prior"] == "single-leaf":
            leaves = sum(shape.degree(v) == 1 for v in range(shape.n))
            if leaves > 1 or shape.complete() and leaves == 0:
                return False
        if o["cue-planar"] == "yes" and shape.genus() > 0:
            return False
        return o["cue-diameter"] is None or not shape.complete() or shape.diameter() <= o["cue-diameter"]

    def _apply_cues_after(self, record: Step) -> None:
        """``cue-diameter``: once TM is explored to depth D, every model not completed is voided."""
        D = self.options["cue-diameter"]
        if D is not None and self._tm.explored_depth() >= D:
            kept = [m for m in self.live if m.shape.complete()]
            record.voided += len(self.live) - len(kept)
            self.live = kept

    # -- termination ------------------------------------------------------------------------
    def _completed(self) -> list[Model]:
        return [m for m in self.live if m.shape.complete()]

    def _completed_count(self) -> int:
        return len({id(m.shape) for m in self._completed()})

    def _terminate(self, number: int) -> None:
        """The termination rules of the module docstring, after step ``number``."""
        if not self.live:
            raise AlgorithmFailed(f"every world model was voided at step {number} (a cue is false for this world)")
        o = self.options
        told = not self.listing_stops or o["cue-n"] is not None or o["cue-m"] is not None
        if told and len(self.live) == 1 and self.live[0].shape.complete():  # the truth is never voided: it is this
            return self._finish(self.live[0])
        if o["cue-diameter"] is not None and self._tm.explored_depth() >= o["cue-diameter"]:
            shapes = {id(m.shape) for m in self.live}
            if len(shapes) == 1:
                return self._finish(self.live[0])
            raise AlgorithmFailed(f"TM explored to depth {o['cue-diameter']} (the diameter cue) with "
                                  f"{len(shapes)} completed models left, which it cannot tell apart")
        if not self.listing_stops and all(m.shape.complete() for m in self.live) and self._indistinguishable():
            raise AlgorithmFailed(f"{len(self.live)} completed models are left at step {number} and no walk "
                                  f"can tell them apart: the world cannot be mapped without a marker or a cue")
        completed = self._completed()
        if len({id(m.shape) for m in completed}) != 1:
            self._sole = (None, number)
            return None
        if self._sole[0] is not completed[0].shape:
            self._sole = (completed[0].shape, number)
        if number - self._sole[1] >= o["window"]:
            self._finish(completed[0])
        return None

    def _indistinguishable(self) -> bool:
        """Every live model (all completed) senses what the first one does on every walk (checked once per set)."""
        key = tuple(id(m.shape) for m in self.live)
        if key != self._checked[0]:
            first = self.live[0]
            self._checked = (key, all(walk_equivalent(first.shape, first.pose, m.shape, m.pose)
                                      for m in self.live[1:]))
        return self._checked[1]

    def _tm_complete(self, number: int) -> Step:
        """TM has no unexplored exit: the world is a tree and has been walked whole; its model is returned."""
        completed = self._completed()
        if len({id(m.shape) for m in completed}) != 1:
            raise AlgorithmFailed(f"the traversal map is complete at step {number} but {len(completed)} "
                                  f"completed models remain")
        self._finish(completed[0])
        return Step(number, (-1, -1))

    def _finish(self, model: Model) -> None:
        self.S = model.shape.partial_map().copy()
        self.position = self._physical(model)
        self.finished = True


class ListingModelTreeExplorer(ModelTreeExplorer):
    """Algorithm 5.1 as listed (``model-tree-listing``): the three switches of the module docstring on."""

    name = "model-tree-listing"
    listing_hypotheses = listing_paths = listing_stops = literal = True
