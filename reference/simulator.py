"""The simulator: the world, the ground truth and the cost (thesis §3.1.1–3.1.2).

It holds the world and where the robot really is, executes motions, counts
every edge traversal (the thesis's cost metric), enforces the marker class
(what the robot carries and may drop), and records the true state after every
motion so the checker can compare the explorer's beliefs with the truth.
Explorers only ever receive :meth:`Simulator.robot`.
"""

from __future__ import annotations

from collections import Counter

from topomark.spec.errors import CheckFailure, InvalidInput, Violation
from topomark.spec.marker import VertexMarker
from topomark.spec.robot import State, sense, step
from topomark.spec.signature import Signature
from topomark.spec.world import World

from .robot import PURPOSES, Robot

__all__ = ["Simulator"]


class Simulator:
    """Plays ``world`` to a robot starting in ``state`` and carrying ``kit`` markers.

    ``kit`` maps a marker kind (``"directional-vertex"``, ``"undirected-vertex"``)
    to how many the robot carries.  ``listener`` (optional) is called with
    ``(motion, purpose, signature, true_state)`` after every traversal.
    """

    def __init__(self, world: World, state: State, kit: dict[str, int] | None = None, listener=None):
        self.world = world
        self.state = state
        self.kit = Counter(kit or {})
        self.cost = 0
        self.by_purpose: Counter[str] = Counter()
        self.listener = listener
        self.drops: list[VertexMarker] = []

    # -- the explorer's side -------------------------------------------------
    def robot(self) -> Robot:
        return Robot(self._move, self._sense, self._drop)

    def _move(self, motion: int, purpose: str) -> Signature:
        if purpose not in PURPOSES:
            raise CheckFailure(Violation("robot interface", "move", f"a purpose in {PURPOSES}", repr(purpose)))
        try:
            self.state = step(self.world, self.state, motion)
        except InvalidInput as exc:
            raise CheckFailure(Violation("robot interface", f"step {self.cost + 1}", "an existing exit",
                                         str(exc), "the explorer asked for an exit that does not exist")) from None
        self.cost += 1
        self.by_purpose[purpose] += 1
        sig = sense(self.world, self.state)
        if self.listener is not None:
            self.listener(motion, purpose, sig, self.state)
        return sig

    def _sense(self) -> Signature:
        return sense(self.world, self.state)

    def _drop(self, direction: int | None) -> None:
        kind = "undirected-vertex" if direction is None else "directional-vertex"
        v, entry = self.state
        if self.kit[kind] < 1:
            raise CheckFailure(Violation("marker class", f"vertex {v!r}", f"a {kind} marker in the kit",
                                         "none left"))
        if self.world.vertex_mark(v) is not None:
            raise CheckFailure(Violation("marker class", f"vertex {v!r}", "an unmarked vertex", "a marker already there"))
        self.kit[kind] -= 1
        points = None if direction is None else self.world.neighbour(v, (entry + direction) % self.world.degree(v))
        marker = VertexMarker(v, 1, points)
        self.drops.append(marker)
        self.world = self.world.with_markers(self.world.markers + (marker,), self.world.start)
