"""The algorithm families of ``topomark/trace@2``: which algorithms each covers and its algorithm layer.

A trace@2 (``spec/trace.md``) has two layers: the *robot layer* — every
``move`` and every marker ``op``, what the robot did, the same for every
algorithm — and an *algorithm layer* whose records a *family* of algorithms
defines.  ``topomark replay`` verifies the robot layer of any trace and the
algorithm layer where the header's family defines one.  (These are families of
algorithms; the bench's families of worlds are
:data:`topomark.reference.bench.plan.FAMILIES`.)

=================  ================================================  ======================  ==================
family             algorithms                                        algorithm layer         thesis
=================  ================================================  ======================  ==================
``algorithm-3.1``  ``basic`` and the Chapter 4 enhancements          ``iteration`` records   §3.3, Chapter 4
                   (registered with ``family="algorithm-3.1"``)
``robot``          any (the header names it; topomark need not       none                    —
                   know it)
=================  ================================================  ======================  ==================

Decision (the thesis is silent): the ``robot`` family is for a recorder
whose algorithm has no algorithm layer here yet (e.g. the Chapter 6
algorithms, which drop markers mid-run); its trace is verified as far as
what the robot did, and its ``end`` only for the cost — unless topomark
runs the algorithm itself (registered with ``family="robot"``), when replay
re-runs it beside the trace (:mod:`topomark.reference.replay.rerun_layer`);
for any other name an end that claims anything about the run is refused.  Threads (§6.3) are
not in the robot kernel yet, so no record for them is reserved.

Examples
--------
>>> family_of("enh3+4").name
'algorithm-3.1'
>>> ALGORITHM_FAMILIES["robot"].events
()
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.reference.algorithms.registry import in_family

__all__ = ["AlgorithmFamily", "ALGORITHM_FAMILIES", "ROBOT_EVENTS", "family_of"]

ROBOT_EVENTS = ("op", "move")
"""The robot layer's events, in every family."""


@dataclass(frozen=True)
class AlgorithmFamily:
    """A family of algorithms sharing one algorithm layer (``events``; none if empty)."""

    name: str
    thesis: str
    events: tuple[str, ...]
    registered: bool  # its algorithms are topomark's registered ones (else the header's name is free)
    lighthouse: bool  # the start's marker operations are the lighthouse's, and none follows them

    def covers(self, algorithm: str) -> bool:
        return algorithm in in_family(self.name) if self.registered else bool(algorithm)

    @property
    def layers(self) -> tuple[str, ...]:
        """The layers replay verifies for this family."""
        return ("robot", self.name) if self.events else ("robot",)


ALGORITHM_FAMILIES: dict[str, AlgorithmFamily] = {f.name: f for f in (
    AlgorithmFamily("algorithm-3.1", "§3.3, Algorithm 3.1 and the Chapter 4 enhancements", ("iteration",), True, True),
    AlgorithmFamily("robot", "the robot layer alone", (), False, False),
)}


def family_of(algorithm: str) -> AlgorithmFamily:
    """The family an algorithm's traces are written in: Algorithm 3.1's for it and the Chapter 4 enhancements,
    the robot layer alone for every other algorithm (until its family defines an algorithm layer)."""
    return ALGORITHM_FAMILIES["algorithm-3.1"] if algorithm in in_family("algorithm-3.1") else ALGORITHM_FAMILIES["robot"]
