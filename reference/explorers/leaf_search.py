"""The search for the single leaf of §5.3: a deterministic walk that is sure to reach it.

§5.3: "if we know that there exists exactly one 'leaf vertex' in the world, then by searching and using the
leaf vertex as the directional lighthouse the world can be mapped deterministically".  The thesis does not say
how to search (§5.1's search is a random walk that may give up); this module's walk is deterministic and
always ends at the leaf:

* **What it walks.**  The robot walks every *non-backtracking* walk from the start (each step leaves by any exit
  but the edge it came by) of length at most L, depth first, for L = 1, 2, 3, … (iterative deepening).  A
  shortest path from the start to the leaf is such a walk, so the round L = (the leaf's distance) reaches it at
  the latest, whatever the world and the start.  A walk cannot know where it has been (there is no marker):
  the same place may be reached by many walks, and each is walked.
* **How it knows the leaf.**  The only place of degree 1 is the leaf: the signature sensed on arriving there,
  ``[1,A,A]``, gives explicit place information, and a place with one exit has one entry, so it gives explicit
  back-link information too (§5.1: "a vertex of degree one provides explicit back-link information at the
  vertex (Figure 5.1(a))").  The walk stops the moment it senses degree 1 — or at once, if the robot starts
  there.
* **How it moves.**  From a place the walk leaves by its exits other than the entry edge, in clockwise order;
  after each it comes back over the same edge, which is then its entry edge, and the robot knows that exit's
  offset, so the next exit's motion is the difference (§3.1.1's relative motions).  Every move is an
  ``establish`` move: it sets up the lighthouse before Algorithm 3.1's loop starts.

Cost (ours; the thesis bounds no search): with W(j) the number of non-backtracking walks of length j from the
start and k the leaf's distance, round L walks each of its walks out and back, at most 2·Σ_{j=1}^{L} W(j)
traversals, so the search is at most 2·Σ_{L=1}^{k} Σ_{j=1}^{L} W(j).  W(j) ≤ d(d−1)^{j−1} for a start of
degree d in a world of maximum degree d: the search grows exponentially with the leaf's distance, the price
of a deterministic search with nothing to mark where it has been.  It is capped by ``limit`` traversals
(:class:`~topomark.spec.errors.LimitReached`, the ``limit`` outcome): a world without a leaf is refused before
the run (the prior is false), but a world whose leaf is far may need more than a run can afford.

Examples
--------
>>> search_bound([1, 2, 2])  # W(1) = 1, W(2) = 2, W(3) = 2, a leaf at distance 3: 2·(1 + 3 + 5)
18
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.spec.errors import LimitReached
from topomark.spec.signature import Signature

from topomark.reference.explorers.robot import Robot

__all__ = ["LeafFound", "find_leaf", "search_bound", "SEARCH_LIMIT", "MAX_SEARCH_LIMIT"]

SEARCH_LIMIT = 1_000_000
"""The default cap on the search's traversals: far more than any world of the thesis's sizes with its leaf a
few steps away needs (a world of degree 4 with the leaf 6 steps away: at most 4,344, :func:`search_bound`)."""

MAX_SEARCH_LIMIT = 100_000_000
"""The largest cap: each traversal is a simulator step, and 10^8 of them take minutes."""


@dataclass
class LeafFound:
    """The search's end: the leaf's signature as sensed (entered by its only edge) and the traversals walked."""

    signature: Signature
    steps: int
    depth: int  # the round that reached it: the length of the walk that ended there (0: the start is the leaf)


class _Walk:
    """One search: the robot, the traversals so far, and the cap."""

    def __init__(self, robot: Robot, limit: int):
        self.robot, self.limit, self.steps = robot, limit, 0

    def move(self, motion: int) -> Signature:
        if self.steps >= self.limit:
            raise LimitReached(f"no place of degree 1 within {self.limit:,} search traversals (--search-limit): the "
                               "leaf is further than non-backtracking walks of this budget reach (§5.3)")
        self.steps += 1
        return self.robot.move(motion, "establish")

    def below(self, degree: int, first: int, depth: int, offset: int = 0) -> tuple[Signature | None, int]:
        """Walk every non-backtracking walk of length ≤ ``depth`` onward from here, a place of ``degree`` whose
        exits ``first``.. (counted from its reference edge) are taken, the robot entered by exit ``offset``.
        Returns the leaf's signature if a walk reached it (the robot stays there), else None and the exit the
        robot is entered by afterwards (the last one taken: it came back by it)."""
        for r in range(first, degree):
            sig = self.move((r - offset) % degree)
            if sig.degree == 1:
                return sig, 0
            found, back = (None, 0) if depth == 1 else self.below(sig.degree, 1, depth - 1)
            if found is not None:
                return found, 0
            self.move((-back) % sig.degree)  # back by the edge it came by
            offset = r
        return None, offset


def find_leaf(robot: Robot, limit: int = SEARCH_LIMIT) -> LeafFound:
    """Walk to the place of degree 1 (module docstring); the robot ends there, entered by its only edge."""
    here = robot.sense()
    if here.degree == 1:
        return LeafFound(here, 0, 0)
    walk = _Walk(robot, limit)
    depth, offset = 0, 0  # the start's exits are counted from the one the robot faces
    while True:
        depth += 1
        found, offset = walk.below(here.degree, 0, depth, offset)
        if found is not None:
            return LeafFound(found, walk.steps, depth)


def search_bound(walks: list[int]) -> int:
    """The search's traversals at most, 2·Σ_{L=1}^{k} Σ_{j=1}^{L} W(j), for ``walks`` = [W(1), …, W(k)]: the
    numbers of non-backtracking walks of each length from the start up to the leaf's distance k."""
    return 2 * sum(sum(walks[:L]) for L in range(1, len(walks) + 1))
