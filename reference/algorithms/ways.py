"""The ways a run can go: the phases an algorithm passes through and the outcomes it can end with, each an
observable predicate over a finished run.

An :class:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec` declares, in ``ways``, the names of
:data:`WAYS` its runs can take — only ways its explorer really has, each with the thesis section that gives it.
:func:`ways_of` classifies a finished run (a :class:`~topomark.reference.run.outcome.Outcome`) into the ways it
went: each predicate reads what the run shows — its ``outcome`` and failure ``reason``, its marker and thread
operations by kind (``marker_operations``), its cost by purpose (``by_purpose``), its hypothesis counts, and
the explorer's own phase attributes (Case 5's ``phase_two_from``, the thread fallback's ``phase``).

A conformance case records the ways topomark's reference run of it went, and every declared way is reached by
some case of the algorithm's suite, except a way no client can be held to (``in_suite`` False: a wrong map is
what the thesis predicts of an idea that fails, not what a program must reproduce).

Examples
--------
>>> WAYS["phase-ii"].thesis
'§6.2.1 Case 5, Algorithm 6.4 lines 16–35, Algorithm 6.5 lines 14–28'
>>> check_ways("x", ("correct", "nope"))
Traceback (most recent call last):
...
ValueError: algorithm x: unknown ways ['nope'] (known: correct, failed-out-of-markers, ...)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Iterable

__all__ = ["Way", "WAYS", "PHASE", "OUTCOME", "ways_of", "check_ways"]

PHASE, OUTCOME = "phase", "outcome"


@dataclass(frozen=True)
class Way:
    """One way a run can go: a ``phase`` it passes through or an ``outcome`` it ends with, what it is in words,
    where the thesis gives it, and ``test``, the predicate over a finished run."""

    name: str
    kind: str
    text: str
    thesis: str
    test: Callable[[Any], bool]
    in_suite: bool = True  # a conformance suite can hold a case that goes this way

    def to_json(self) -> dict[str, Any]:
        return {"kind": self.kind, "text": self.text, "thesis": self.thesis}


def _failed(prefix: str) -> Callable[[Any], bool]:
    return lambda out: out.outcome == "failed" and (out.reason or "").startswith(prefix)


def _ops(kind: str, least: int = 1) -> Callable[[Any], bool]:
    return lambda out: out.marker_operations.get(kind, 0) >= least


def _undecided(out: Any) -> bool:
    """Failed with world models still live (the model tree's explorer keeps them, ``live``)."""
    return out.outcome == "failed" and hasattr(out.explorer, "live")


def _confused(out: Any) -> bool:
    """Failed, and not for want of markers or thread nor with models undecided: the marks the robot senses fit more
    than one place or edge."""
    reason = out.reason or ""
    return out.outcome == "failed" and not reason.startswith(("out of markers", "out of thread")) and not _undecided(out)


def _case5_phase_two(out: Any) -> bool:
    return getattr(out.explorer, "phase_two_from", None) is not None


def _thread_phase_two(out: Any) -> bool:
    return getattr(out.explorer, "phase", 1) == 2


_ALL = (
    Way("correct", OUTCOME, "the map is extended-isomorphic to the world, markers included", "§3.1.3",
        lambda out: out.outcome == "correct"),
    Way("failed-out-of-markers", OUTCOME, "failed: the kit ran out of markers before the map was complete",
        "§6.2.1 (running out of markers)", _failed("out of markers")),
    Way("failed-out-of-thread", OUTCOME, "failed: every edge of the thread was laid with an unexplored edge left",
        "§6.3.2, Algorithm 6.7 (l = c(G)); §6.3.3 (l < c(G))", _failed("out of thread")),
    Way("failed-marks-ambiguous", OUTCOME, "failed: the marks the robot senses fit more than one place or edge",
        "§6.2.1 Case 4, Figure 6.10", _confused),
    Way("failed-models-undecided", OUTCOME, "failed: the world models left cannot be told apart, or none is left",
        "§5.2.2, Algorithm 5.1", _undecided),
    Way("wrong-map", OUTCOME, "the run ends with a map that is not the world's", "§6.2.2, Figure 6.15",
        lambda out: out.outcome == "wrong-map", in_suite=False),
    Way("limit", OUTCOME, "a cap on steps, models or search traversals was reached before the run ended",
        "§5.2.2; §5.3", lambda out: out.outcome == "limit", in_suite=False),
    Way("hypothesis-rejected", PHASE, "a hypothesis's motion sequence met a perception it did not expect "
        "(Algorithm 3.1, cases 1 and 2)", "§3.3, Algorithm 3.1", lambda out: out.hypotheses_rejected > 0),
    Way("hypothesis-confirmed", PHASE, "a hypothesis was confirmed and a loop edge closed (Algorithm 3.1, case 3)",
        "§3.3, Algorithm 3.1", lambda out: out.hypotheses_confirmed > 0),
    Way("leaf-search", PHASE, "the walk that searches for the single leaf before the mapping starts", "§5.3",
        lambda out: out.by_purpose.get("establish", 0) > 0),
    Way("phase-i", PHASE, "phase I: markers dropped, each place named by its unique marks", "§6.2.1 Case 5",
        _ops("drop")),
    Way("phase-ii", PHASE, "phase II: markers ran short, places told by Algorithm 3.1's hypotheses",
        "§6.2.1 Case 5, Algorithm 6.4 lines 16–35, Algorithm 6.5 lines 14–28", _case5_phase_two),
    Way("drop-trip", PHASE, "traversals made only to drop markers on an edge's far end", "§6.2.1 Case 3b",
        lambda out: out.by_purpose.get("drop", 0) > 0),
    Way("marker-moved", PHASE, "the movable marker picked up and dropped again elsewhere", "§2.3.1",
        _ops("pick_up")),
    Way("thread-laid", PHASE, "the thread tied and laid along the robot's path", "§6.3", _ops("tie")),
    Way("thread-rewound", PHASE, "the thread rewound back along its laid edges", "§6.3.2, Algorithm 6.7",
        _ops("rewind")),
    Way("thread-retied", PHASE, "the thread untied and tied again at another place", "§6.3.1; §6.3.3, Algorithm 6.8",
        _ops("tie", 2)),
    Way("thread-knots", PHASE, "knots tied in the thread to name places", "§6.3.2, Figure 6.20", _ops("knot")),
    Way("thread-phase-ii", PHASE, "phase II: the thread is all laid, left as an immovable mark, and places are "
        "told by Algorithm 3.1's hypotheses", "§6.3.3", _thread_phase_two),
)
WAYS: dict[str, Way] = {way.name: way for way in _ALL}
"""Every way a run can go, by name (module docstring)."""


def ways_of(outcome: Any, declared: Iterable[str] | None = None) -> list[str]:
    """The ways (of ``declared``, or of every way) the finished run ``outcome`` went, in :data:`WAYS`'s order."""
    names = WAYS if declared is None else set(declared)
    return [way.name for way in _ALL if way.name in names and way.test(outcome)]


def check_ways(algorithm: str, ways: Iterable[str]) -> None:
    """Refuse (``ValueError``) a declaration naming a way :data:`WAYS` does not know, or no outcome at all."""
    ways = tuple(ways)
    unknown = sorted(set(ways) - set(WAYS))
    if unknown:
        raise ValueError(f"algorithm {algorithm}: unknown ways {unknown} (known: {', '.join(list(WAYS)[:2])}, ...)")
    if not any(WAYS[w].kind == OUTCOME for w in ways):
        raise ValueError(f"algorithm {algorithm}: its ways name no outcome (one of "
                         f"{', '.join(w.name for w in _ALL if w.kind == OUTCOME)})")
