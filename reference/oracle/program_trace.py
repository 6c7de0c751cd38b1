"""What another program's robot did in ``run-external`` and ``conformance run``, kept as a trace (``spec/trace.md``).

topomark plays the world (thesis §3.1); the program only moves and operates
markers.  :class:`ProgramTrace` listens to the simulator of that game and
keeps its robot layer as ``topomark/trace@2`` records of the ``robot``
family — every move with its perception, every marker or thread operation
with the signature sensed after it — under the algorithm name
``external program``, its end unjudged, so that replay (and the run viewer
that draws a failing case) re-checks the robot layer on the world and the
conformance verdict is shown beside it.
"""

from __future__ import annotations

from typing import Any

from topomark.spec.kit import Kit
from topomark.spec.world import World

from topomark.reference.trace.records import TRACE_FORMAT_2

__all__ = ["ProgramTrace"]


class ProgramTrace:
    """The simulator's listeners (:meth:`moved`, :meth:`operated`) and the trace they make (:meth:`records`)."""

    def __init__(self, world: World, kit: Kit):
        self.world, self.kit = world, kit  # the world as played: its rotation and start, no markers
        self.kept: list[dict[str, Any]] = []
        self.steps = 0

    def listeners(self) -> tuple[Any, Any]:
        """The simulator's move listener and op listener."""
        return self.moved, self.operated

    def moved(self, motion: int, purpose: str, sig: Any, state: Any) -> None:
        self.steps += 1
        self.kept.append({"event": "move", "step": self.steps, "motion": motion, "perception": str(sig),
                          "purpose": purpose})

    def operated(self, event: dict[str, Any]) -> None:
        self.kept.append({"event": "op", **event})

    def records(self) -> list[dict[str, Any]]:
        """The whole trace: the header, what was kept, an unjudged end."""
        header = {"event": "header", "format": TRACE_FORMAT_2, "family": "robot", "algorithm": "external program",
                  "policies": {}, "lighthouse": None, "kit": self.kit.to_json(), "n": self.world.n, "m": self.world.m}
        return [header, *self.kept, {"event": "end", "cost": self.steps, "verified": False, "violation": None}]
