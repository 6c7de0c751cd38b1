"""Registration of ``single-leaf``: a world known to have exactly one leaf, mapped with the leaf as Algorithm
3.1's directional lighthouse (thesis §5.3; explorer :mod:`topomark.reference.explorers.single_leaf`).

A kit algorithm with an empty kit (nothing is dropped: the leaf is its own lighthouse), deterministic: the
search for the leaf always ends there (:mod:`topomark.reference.explorers.leaf_search`) and Algorithm 3.1 from
a directional lighthouse maps every world (§3.4).  It takes Algorithm 3.1's three policies and ``search-limit``,
the cap on the search's traversals.  A world without exactly one vertex of degree 1 is refused before the run:
the prior is false for it.

Decisions:

* **Bound.**  (3.1)+(3.2) (§3.5.2) bounds Algorithm 3.1's loop body, which starts with the lighthouse found:
  every checked run holds the cost less the search's ``establish`` moves to it, as for the lighthouses found by
  a walk (§5.1, §6.1; :mod:`~topomark.reference.algorithms.registrations.algorithm31`).  The thesis bounds no
  search; ours is in :mod:`~topomark.reference.explorers.leaf_search` (exponential in the leaf's distance),
  and the run's cost and ``walk_steps`` report it.
* **Not the model tree's prior.**  ``model-tree --prior single-leaf`` (§5.2.2) uses the same knowledge to void
  world models with two leaves; it keeps Algorithm 5.1's termination heuristic and caps, and is not §5.3's
  deterministic method.  This is.
* **Trace family** ``robot``: the run is Algorithm 3.1's loop, but the trace family ``algorithm-3.1`` is for
  the lighthouse algorithms, whose start is a marker drop; replay re-runs this one beside its trace.

Examples
--------
>>> SPECS[0].bound_for(4, 4), SPECS[0].bound_excludes  # a triangle with a pendant: (3.1)+(3.2), less the search
(50, ('establish',))
"""

from __future__ import annotations

from topomark.spec.errors import InvalidInput
from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import ALGORITHM_3_1_CHECKS, AlgorithmSpec, Parameter
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.explorers.leaf_search import MAX_SEARCH_LIMIT, SEARCH_LIMIT
from topomark.reference.explorers.single_leaf import SingleLeafExplorer

__all__ = ["SPECS", "single_leaf_only", "summary"]


def single_leaf_only(world, options: dict) -> None:
    """Refuse, as bad input, a world without exactly one vertex of degree 1: the prior of §5.3 is false for it."""
    leaves = sum(len(world.rotation[v]) == 1 for v in world.vertices)
    if leaves != 1:
        raise InvalidInput(f"single-leaf maps worlds with exactly one vertex of degree 1 (§5.3); this world has "
                           f"{leaves}")


def summary(explorer, world) -> dict:
    """The search's counts for ``--json``: its traversals (``walk_steps``), the length of the walk that reached
    the leaf (its distance from the start) and the world vertex the leaf is (``lighthouse_at``, from the world)."""
    beacon = explorer.beacon
    leaf = next(v for v in world.vertices if len(world.rotation[v]) == 1)
    return {"walk_steps": 0 if beacon is None else beacon.walk_steps, "leaf_distance": explorer.search_depth,
            "lighthouse_at": leaf}


SPECS = (
    AlgorithmSpec(
        name="single-leaf",
        thesis="§5.3, the single leaf as the directional lighthouse of Algorithm 3.1",
        kit=Kit(), markers="0", deterministic=True,
        bound="(3.1)+(3.2) (§3.5.2) after the search; the search: ours, exponential in the leaf's distance",
        bound_fn=upper_bound,
        bound_formula="(3.1)+(3.2) (§3.5.2), Algorithm 3.1's loop from the leaf; the search for the leaf not counted",
        bound_excludes=("establish",),
        options=("policy edge=nearest|fifo|lifo", "policy hypothesis=fifo|lifo|shortest", "policy path=shortest|dfs",
                 "search-limit=N"),
        parameters=(Parameter("search-limit", f"cap on the traversals of the search for the leaf: past it the run "
                              f"ends with the limit outcome (at most {MAX_SEARCH_LIMIT:,})", SEARCH_LIMIT, 1,
                              maximum=MAX_SEARCH_LIMIT),),
        checks=(*ALGORITHM_3_1_CHECKS, "marker-budget"),
        explorer=SingleLeafExplorer, uses_lighthouse=False, marker_bound_fn=lambda n, m: 0, family="robot",
        check_world=single_leaf_only, summary_fn=summary, ways=("correct", "limit", "leaf-search"),
    ),
)
