"""Mapping a world known to have exactly one leaf: the leaf as Algorithm 3.1's directional lighthouse (thesis §5.3).

§5.3: "if we know that there exists exactly one 'leaf vertex' in the world, then by searching and using the
leaf vertex as the directional lighthouse the world can be mapped deterministically."  No marker is carried:

1. **Search** (:mod:`.leaf_search`): a deterministic walk over every non-backtracking walk from the start, by
   increasing length, until the robot senses a place of degree 1 — the leaf, the only one.  Its moves are
   ``establish`` moves, reported in the run's cost.
2. **Lighthouse** (:data:`LEAF`): the leaf is v0.  It gives *explicit place information* — the prior makes
   ``[1,A,A]`` the signature of one place only — and *explicit back-link information* — one exit, so one entry
   (§5.1: "a vertex of degree one provides explicit back-link information at the vertex (Figure 5.1(a))"):
   a directional lighthouse (§3.2.2) with nothing dropped, like §5.2.1's marker-less ones but certain, and
   recognised without probing (its one signature is its table of back-links, :meth:`Lighthouse.beacon`).
3. **Mapping**: Algorithm 3.1 (§3.3) from v0, unchanged (:class:`~.algorithm31.LighthouseExplorer`): each
   hypothesis is validated by walking S to the leaf; arriving at a place of degree 1 is arriving at v0 by its
   exit 0.  Its loop conditions (§3.4) and its bound (3.1)+(3.2) (§3.5.2) hold as for any lighthouse.

§5.3 gives no listing: steps 1–2 follow its text, the search's order being the choice it leaves open; step 3 is
Algorithm 3.1 line by line (the correspondence in :mod:`.algorithm31`), with the leaf's ``[1,A,A]`` in place of
the marker's signature at line 7.

A world without exactly one leaf is refused before the run (the prior is false: bad input, as for the model
tree's ``--prior single-leaf``): with two leaves the signature ``[1,A,A]`` names two places, and with none
the search never ends.

Examples
--------
>>> LEAF.certain, LEAF.kit.describe()
(True, 'no marker')
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Callable

from topomark.spec.kit import Kit
from topomark.spec.mapstate import PartialMap

from topomark.reference.explorers.algorithm31 import Iteration, LighthouseExplorer
from topomark.reference.explorers.leaf_search import SEARCH_LIMIT, find_leaf
from topomark.reference.explorers.lighthouses import Beacon, Lighthouse
from topomark.reference.explorers.policies import Policies
from topomark.reference.explorers.robot import Robot

__all__ = ["LEAF", "LeafLighthouse", "LeafBeacon", "SingleLeafExplorer", "search_leaf"]


@dataclass
class LeafBeacon(Beacon):
    """v0 at the leaf, with the length of the walk that reached it (the leaf's distance from the start)."""

    depth: int = 0


@dataclass(frozen=True)
class LeafLighthouse(Lighthouse):
    """The single leaf as a lighthouse: no marker, yet certain — the prior makes its place explicit (§5.3)."""

    @property
    def certain(self) -> bool:
        """Always: the world has exactly one place of degree 1 (the registration refuses any other world)."""
        return True


def search_leaf(light: Lighthouse, robot: Robot, S: PartialMap) -> LeafBeacon:
    """Walk to the leaf (:func:`~.leaf_search.find_leaf`, at most ``light.walk_limit`` traversals) and make it
    v0, map exit 0 its only edge; the robot stands there, entered by it."""
    found = find_leaf(robot, light.walk_limit)
    v0 = S.add_vertex(1)
    S.mark_as_sensed(v0, found.signature, 0)
    beacon = light.beacon(S, v0, found.steps)
    return LeafBeacon(beacon.table, beacon.perceived, walk_steps=found.steps, depth=found.depth)


LEAF = LeafLighthouse("leaf", "§5.3", Kit(), (), "no marker (§5.3: the world's one place of degree 1)",
                      search=search_leaf, walk_limit=SEARCH_LIMIT)
"""The leaf lighthouse; ``walk_limit`` caps the search's traversals (``--search-limit``)."""


class SingleLeafExplorer(LighthouseExplorer):
    """Algorithm 3.1 with the leaf as its lighthouse, found by :func:`search_leaf` (module docstring); built as a
    kit algorithm, ``options`` giving ``search-limit``."""

    name = "single-leaf"

    def __init__(self, robot: Robot, policies: Policies | None = None,
                 observer: Callable[[LighthouseExplorer, Iteration], None] | None = None,
                 options: dict[str, Any] | None = None):
        limit = (options or {}).get("search-limit") or SEARCH_LIMIT
        super().__init__(robot, policies, observer, replace(LEAF, walk_limit=limit))

    @property
    def search_depth(self) -> int | None:
        """The leaf's distance from the start, once found (the length of the walk that reached it)."""
        return self.beacon.depth if isinstance(self.beacon, LeafBeacon) else None
