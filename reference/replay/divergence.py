"""A replay's divergence: the first claim of a trace that the world or the specification contradicts.

:mod:`~topomark.reference.replay.replay`'s layers (:mod:`~topomark.reference.replay.robot_layer`,
:mod:`~topomark.reference.replay.algorithm31_layer`) raise :class:`Diverged` carrying a
:class:`~topomark.spec.errors.Violation` — where, what the world or the spec
expected, what the trace claims — and the replay turns it into a negative
verdict (exit 1) naming the line.
"""

from __future__ import annotations

from typing import NoReturn

from topomark.spec.errors import Violation

__all__ = ["Diverged", "diverge"]


class Diverged(Exception):
    def __init__(self, violation: Violation):
        super().__init__(str(violation))
        self.violation = violation


def diverge(where: str, expected: str, found: str, detail: str = "", check: str = "replay") -> NoReturn:
    """Raise the divergence ``check`` at ``where``: ``expected`` by the world or the spec, ``found`` in the trace."""
    raise Diverged(Violation(check, where, expected, found, detail))
