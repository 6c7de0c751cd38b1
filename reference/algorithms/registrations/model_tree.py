"""Registration of Algorithm 5.1, marker-less mapping with a tree of world models (thesis §5.2.2, §5.3).

Two entries: ``model-tree``, topomark's explorer, which changes Algorithm 5.1 as its ``changes`` says, and
beside it ``model-tree-listing`` (its ``listing_entry``), Algorithm 5.1 as listed: the same explorer with the
listing's three switches on (:class:`~topomark.reference.explorers.model_tree.ListingModelTreeExplorer`), the same
options, checks and ways.  Each is ``model-tree`` below: an empty kit (no marker), no cost bound and no
marker bound stated by the thesis (the marker budget is 0), not
deterministic (§5.2.2: "the algorithm is still not deterministic … we cannot
determine which world model is the correct one").  The explorer is
:class:`~topomark.reference.explorers.model_tree.ModelTreeExplorer`.

Checks: ``models`` (the true world survives among the live models after
every step; topomark's own explorer voiding it is exit 3), ``marker-budget``
(0 markers) and ``isomorphism`` (the returned model against the world).

Cues are prior knowledge, so a false one is bad input: the kit function sees
n and m and refuses a false ``--cue-n``/``--cue-m`` before anything runs;
:func:`check_cues` also checks ``--cue-diameter`` and ``--cue-planar``
against a world, for a caller that has the world (the CLI).

For the CLI: :func:`summary` gives the ``--json`` fields
``completed_models``, ``peak_models`` and ``true_world_completed`` (and, with ``--rank yes``,
``ranked_models``: :func:`ranked_models`);
:func:`write_models` writes every completed model, in completion order, as
world files (``--models DIR``).

Examples
--------
>>> spec = SPECS[0]
>>> spec.name, spec.thesis, spec.kit.describe(), spec.deterministic
('model-tree', '§5.2.2, Algorithm 5.1', 'no marker', False)
>>> spec.parse_options({"signatures": "local"})["window"]
100
>>> spec.listing_entry, SPECS[1].name, SPECS[1].thesis, SPECS[1].follows_listing
('model-tree-listing', 'model-tree-listing', '§5.2.2, Algorithm 5.1, as listed', True)
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from topomark.spec.errors import InvalidInput
from topomark.spec.isomorphism import anchored
from topomark.spec.kit import Kit
from topomark.spec.worldfile import dumps_world
from topomark.spec.spelling import option

from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec, Parameter
from topomark.reference.explorers.model_prior import posteriors
from topomark.reference.explorers.model_tree import DEFAULTS, ListingModelTreeExplorer, ModelTreeExplorer

__all__ = ["SPECS", "PARAMETERS", "MAX_MODELS", "MAX_STEPS", "check_cues", "summary", "ranked_models", "write_models", "simple"]

MAX_MODELS = 100_000
"""The largest ``--max-models``: 10 times the default of 10,000.  Every live model is a partial map kept in
memory and every step extends each of them, so the cap bounds memory (a few kilobytes a model: about a gigabyte
at the cap) and the work per step; the bench's uncued runs (``max-models=1000``) and the default stay below it."""

MAX_STEPS = 1_000_000
"""The largest ``--max-steps``: 500 times the default of 2,000.  A step explores one edge of the tree of models
(§5.2.2, Algorithm 5.1), each costing work for every live model, so a million steps is already far longer
than any run the thesis reports; a larger cap only postpones the limit outcome."""

PARAMETERS = (
    Parameter("signatures", "global: validate each loop closing against every known vertex (§5.2.2); local: accept "
              "every degree-matching one (the thesis's comparison)", DEFAULTS["signatures"], None,
              ("global", "local")),
    Parameter("entry-check", "global signatures: at each vertex whose neighbours are known and whose neighbour "
              "degrees have no proper rotation onto themselves, visit the neighbours to check the entry edge (§5.2.2)",
              DEFAULTS["entry-check"], None, ("yes", "no")),
    Parameter("window", "return a model once it has been the only completed model for this many steps (§5.2.2)",
              DEFAULTS["window"], 1),
    Parameter("max-models", f"cap on live models: past it the run ends with the limit outcome (at most "
              f"{MAX_MODELS:,})", DEFAULTS["max-models"], 1, maximum=MAX_MODELS),
    Parameter("max-steps", f"cap on steps (TM edges explored): past it the run ends with the limit outcome (at most "
              f"{MAX_STEPS:,})", DEFAULTS["max-steps"], 1, maximum=MAX_STEPS),
    Parameter("cue-n", "cue (§5.3): the world has this many vertices", None, 1),
    Parameter("cue-m", "cue (§5.3): the world has this many edges", None, 1),
    Parameter("cue-diameter", "cue (§5.3): the world's diameter", None, 1),
    Parameter("cue-planar", "cue (§5.3): the world is planar (a genus-0 embedding)", DEFAULTS["cue-planar"], None,
              ("yes", "no")),
    Parameter("prior", "prior knowledge (§5.3) as a model-tree prior: single-leaf voids every model with two "
              "vertices of degree 1 (the world has exactly one); §5.3's deterministic use of the leaf, as Algorithm "
              "3.1's lighthouse, is --algorithm single-leaf",
              DEFAULTS["prior"], None, ("none", "single-leaf")),
    Parameter("rank", "rank the completed models by P(model | perceptions), the prior 2^-(n+m+genus) (§5.3), "
              "in the summary", DEFAULTS["rank"], None, ("yes", "no")),
)


def _kit(n: int, m: int, options: dict) -> Kit:
    """No marker; a false n or m cue is refused here, where n and m are known (before anything runs)."""
    for name, true in (("cue-n", n), ("cue-m", m)):
        given = options.get(name)
        if given is not None and given != true:
            raise InvalidInput(f"{option(name, given)} is false for this world ({name[4:]} = {true}): a cue is prior "
                               f"knowledge of the world")
    return Kit()


def check_cues(world, options: dict) -> None:
    """Refuse, as bad input, any cue in ``options`` that is false for ``world`` (n, m, diameter, planarity)."""
    _kit(world.n, world.m, options)
    D = options.get("cue-diameter")
    if D is not None:
        true = _diameter(world)
        if true != D:
            raise InvalidInput(f"{option('cue-diameter', D)} is false for this world (diameter = {true})")
    if options.get("cue-planar") == "yes" and world.genus() != 0:
        raise InvalidInput(f"{option('cue-planar', 'yes')} is false for this world (its embedding has genus {world.genus()})")
    leaves = sum(len(world.rotation[v]) == 1 for v in world.vertices)
    if options.get("prior") == "single-leaf" and leaves != 1:
        raise InvalidInput(f"{option('prior', 'single-leaf')} is false for this world (it has {leaves} vertices of degree 1)")


def _diameter(world) -> int:
    best = 0
    for source in world.vertices:
        dist = {source: 0}
        queue = [source]
        for v in queue:
            for w in world.rotation[v]:
                if w not in dist:
                    dist[w] = dist[v] + 1
                    queue.append(w)
        best = max(best, max(dist.values()))
    return best


def summary(explorer, world) -> dict:
    """The model tree's counts for ``--json``: how many models became completed, the most live at once, and
    whether the true world (anchored at the start, as the checker anchors it) is among the completed ones."""
    start = world.start_state()
    truth = [S.n == world.n and anchored(S, world, (0, 0), start, markers=False, partial=False).isomorphic
             for S in explorer.completed_models]
    out = {"completed_models": len(explorer.completed_models), "peak_models": explorer.peak_models,
           "true_world_completed": any(truth)}
    if explorer.options.get("rank") == "yes":
        out["ranked_models"] = ranked_models(explorer.completed_models, world, truth)
    return out


def ranked_models(completed, world, truth: list[bool]) -> list[dict]:
    """The completed models, the most probable first (:mod:`~topomark.reference.explorers.model_prior`): each
    its number in completion order (``--models``' file), n, m, genus, posterior, and whether it is the world
    (``truth``, in completion order)."""
    shapes = [_nmg(S) for S in completed]
    return [{"model": k + 1, "n": shapes[k][0], "m": shapes[k][1], "genus": shapes[k][2], "posterior": round(p, 4),
             "true": truth[k]} for k, p in posteriors(shapes)]


def _nmg(S) -> tuple[int, int, int]:
    """A completed model's n, m and genus, read from the map itself (a multi-edge model is no world, §3.1.1):
    its faces traced as :meth:`World.faces` does, (v, i) → (w, j + 1)."""
    seen: set = set()
    faces = 0
    for dart in S.darts():
        if dart in seen:
            continue
        faces += 1
        while dart not in seen:
            seen.add(dart)
            w, j = S.target(dart)
            dart = (w, (j + 1) % S.degree(w))
    m = len(seen) // 2
    return S.n, m, (2 - S.n + m - faces) // 2


def simple(S) -> bool:
    """No two exits of one vertex of ``S`` lead to the same vertex: the model is a world (§3.1.1).  Only
    ``model-tree-listing`` forms a model with a multi-edge (Algorithm 5.1 line 17 as listed)."""
    return all(len({x[0] for x in S.links(v)}) == S.degree(v) for v in S.vertices)


def write_models(explorer, directory: str | Path) -> list[Path]:
    """Every completed model, in completion order, as ``model-0001.json`` … in ``directory`` (created); a model
    with a multi-edge is no world (§3.1.1), so no world file holds it: its number is left out."""
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for k, S in enumerate(explorer.completed_models, 1):
        if not simple(S):
            continue
        path = out / f"model-{k:04d}.json"
        path.write_text(dumps_world(S.to_world(start=(0, 0))), encoding="utf-8")
        paths.append(path)
    return paths


_MODEL_TREE = AlgorithmSpec(
    name="model-tree", thesis="§5.2.2, Algorithm 5.1", kit=Kit(), bound=None, markers="0", deterministic=False,
    options=("signatures global|local", "entry-check yes|no", "window=N", "max-models=N", "max-steps=N",
             "cue-n=N", "cue-m=M", "cue-diameter=D", "cue-planar=yes|no",
             "prior none|single-leaf", "rank yes|no"),
    checks=("models", "marker-budget", "isomorphism"),
    explorer=ModelTreeExplorer, uses_lighthouse=False, parameters=PARAMETERS, kit_fn=_kit,
    marker_bound_fn=lambda n, m: 0, family="robot", check_world=check_cues, summary_fn=summary,
    write_models=write_models, expected="may-fail", ways=("correct", "limit", "failed-models-undecided", "wrong-map"),
    changes="Algorithm 5.1 line 17 takes every unexplored edge whose known end shows v_u's degree: this explorer "
            "forms no hypothesis that would make a multi-edge (§3.1.1; a self-loop neither entry forms, as §3.3's "
            "text excludes v_k), and walks lines 18–23's paths to every known vertex as one breadth-first tree "
            "(§5.2.2's captured path overlap); and besides §5.2.2's stopping rule (one completed model for the "
            "window) it stops as soon as the sole live model is completed, with no cue given too, and, failed, "
            "when every live model is completed and no walk tells them apart",
    expected_reason="\"Without a marker, the robot cannot map a world deterministically\" (§5.2): the "
                    "models may never meet the termination window (§5.2.2) and end at a cap, or the sole "
                    "completed model may be wrong (Figure 3.4, §5.2.2)")

SPECS = (
    replace(_MODEL_TREE, listing_entry="model-tree-listing"),
    replace(_MODEL_TREE, name="model-tree-listing", thesis="§5.2.2, Algorithm 5.1, as listed",
            explorer=ListingModelTreeExplorer, changes=None, listing_entry=None),
)
