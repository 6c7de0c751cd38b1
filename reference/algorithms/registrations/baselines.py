"""The classic baselines of Table 2.3 (thesis §2.3.1; Table 2.3): the footprints
model with m + n homogeneous markers and the labelled graph explored depth first.  Explorers:
:mod:`topomark.reference.explorers.footprints` and :mod:`topomark.reference.explorers.labelled_graph`.

============  ============================================  ==============================  ======================
algorithm     Table 2.3 row                                 kit (default)                   exact bound (ours)
============  ============================================  ==============================  ======================
footprints    m + n homogeneous markers, O(mn) (Table 2.3)  m + n vertex-or-edge, one pool  the footprint search's
labelled-dfs  m + n distinct markers, O(m) (Table 2.3)      n(n + 1)/2 directional V        2m
============  ============================================  ==============================  ======================

Both are kit algorithms: the simulator computes the kit from n and m, the
robot never learns them.  Every run of either drops its whole kit (the
``marker-budget`` check holds it to that count after every step).

* ``footprints``: the thesis states O(mn) (§2.3.1, Table 2.3) with no constant; the
  bound checked is
  :func:`~topomark.reference.algorithms.registrations.markers_621.footprints_bound`,
  the exact worst case of the footprint search (its candidates are visited
  within the Euler tour of a breadth-first tree of S, whichever they are).
  It takes the edge policy (``--policy edge=...``), as Cases 1a and 2 do.
  ``footprints-listing`` is §2.3.1's text as written beside it (each candidate checked only where the robot
  goes), held to the same formula as a bound of the text (``docs/bounds.md``).
* ``labelled-dfs``: the thesis states O(m) (§2.3.1, Table 2.3); 2m is ours, exact
  for depth-first search (the explorer's docstring derives it).  It takes no
  policy: depth first is what the bound needs.

Examples
--------
>>> [s.name for s in SPECS]
['footprints', 'footprints-listing', 'labelled-dfs']
>>> [s.kit_for(4, 4, {}).describe() for s in SPECS[1:]]  # the 4-cycle
['8 undirected vertex-or-edge markers', '10 directional vertex markers']
>>> [s.bound_for(4, 4) for s in SPECS[1:]]
[20, 8]
"""

from __future__ import annotations

from dataclasses import replace

from topomark.spec.kit import Kit

from topomark.reference.algorithms.algorithm_spec import STEPWISE_MAP_CHECKS, AlgorithmSpec
from topomark.reference.algorithms.registrations.markers_621 import footprint_spec, footprints_bound, with_listing
from topomark.reference.explorers.footprints import Footprints, ListingFootprints
from topomark.reference.explorers.labelled_graph import LabelledGraphDFS

__all__ = ["SPECS", "labels"]


def labels(n: int) -> int:
    """The homogeneous markers that label n places 1, 2, …, n: n(n + 1)/2."""
    return n * (n + 1) // 2


_FOOTPRINTS = footprint_spec(
    "footprints", "§2.3.1, the footprints model of Deng and Mirzaian [18], m + n homogeneous markers ("
    "Figure 2.4; Tables 2.2 and 2.3)", "m + n undirected homogeneous markers, one on every vertex and edge (§2.3.1)",
    Footprints, lambda n, m, o: Kit(either=m + n), lambda n, m: m + n, "§2.3.1, Table 2.3", options=("policy edge",),
    kind=Kit(either=1))

SPECS = (
    *with_listing(replace(_FOOTPRINTS, parameters=(), checks=STEPWISE_MAP_CHECKS, ways=("correct",),  # never runs short
            changes="§2.3.1 gives no listing and has the robot visit \"each (other) known vertex in S which has the "
                    "same degree as v_u\": this explorer checks every vertex it passes, so one passed is not visited "
                    "again and the search stops wherever v_k' is seen"), ListingFootprints,
                  "its search as §2.3.1 writes it, each candidate checked where the robot goes"),
    AlgorithmSpec(
        name="labelled-dfs",
        thesis="§2.3.1, a labelled graph explored depth first, every place distinctly marked (Tables 2.2 and 2.3)",
        kit=Kit(vertex=1, directional=True),
        bound="O(m) (§2.3.1, Table 2.3); bound_fn: ours, exact for depth-first search",
        markers="n distinct labels: n(n + 1)/2 directional V-markers (label i = i markers, §2.3.1)",
        deterministic=True,
        options=(),
        checks=STEPWISE_MAP_CHECKS,
        explorer=LabelledGraphDFS,
        bound_fn=lambda n, m: 2 * m,
        bound_formula="2m, ours: depth-first search walks each tree edge down and up, each other edge there and "
                      "back (§2.3.1)",
        uses_lighthouse=False,
        kit_fn=lambda n, m, o: Kit(vertex=labels(n), directional=True),
        marker_bound_fn=lambda n, m: labels(n),
        family="robot",
    ),
)
