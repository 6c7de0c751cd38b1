"""The explorer contract: what every explorer offers the run that drives it and the checker that judges it
(thesis §3.1.1 the robot, §3.1.3 S and U, §3.4 the loop conditions, §5.2.2 several models).

An explorer is built by its registry entry's factory as
``cls(robot, policies, observer, lighthouse_or_options)`` and is given nothing
else: the :class:`~topomark.reference.explorers.robot.Robot` is all it knows of
the world.  :func:`topomark.reference.run.explore.explore` then drives it —
``start()``, then ``step()`` until ``done()`` — and the checker reads its
public state after the start, after every step and at the end.  What each part
may do:

``start()``
    Lines 1–3 of Algorithm 3.1 and their counterparts (§6.2's opening for its
    listings, Algorithm 5.1's TM root): S ← {v0}, U ← v0's exits, the believed
    pose (v0, exit 0), exit 0 being the exit the robot faces; the algorithm's
    first drops, or the lighthouse established (§3.3, §6.1).  Only through the
    robot.  Afterwards the checker anchors φ at ``position`` and snapshots the
    world's markers.
``step()``
    One iteration of the algorithm's loop (Algorithm 3.1 lines 5–28; one
    pass of Algorithm 5.1) — only through the robot — that ends by appending
    its record to ``iterations`` and calling ``observer(explorer, record)``
    once (the trace, the tally and the checker run there).  It may raise
    :class:`~topomark.spec.errors.AlgorithmFailed` or
    :class:`~topomark.spec.errors.LimitReached` to stop with a reason; a
    refused drop (:class:`~topomark.spec.errors.OutOfMarkers`) ends the run as
    ``failed``.  The return value is the record (nobody needs it).
``done()``
    The loop condition (Algorithm 3.1 line 4: U is empty, §3.1.3), asked
    before every step.  No side effects: it neither moves the robot nor
    changes S.
``models()``
    The (map, believed pose) pairs the explorer holds, each naming the start
    place as ``position`` named it after ``start()``: one, ``[(S,
    position)]``, for an algorithm with a single map; Algorithm 5.1's live
    world models (§5.2.2).  The checker's ``models`` check (and nobody else)
    reads them; they belong to the explorer, which may change them at the
    next step, so a reader copies what it keeps.

Attributes read from outside:

``S`` (:class:`~topomark.spec.mapstate.PartialMap`) and ``position`` (a map dart)
    The map and the believed pose (map vertex, entry exit), judged by the
    ``pose``, ``I-1``, ``I-2``, ``bound-function`` and ``isomorphism`` checks;
    ``S.unexplored`` is U.  ``S`` is also the map the run writes
    (``explore --map``).
``iterations``
    Every step's record, in order (an :class:`IterationRecord`); the
    ``iterations`` and ``isomorphism`` checks count them at the end.

Optional attributes (read with ``getattr`` where the run needs them):

* ``lighthouse`` and ``beacon`` — a lighthouse algorithm's
  :class:`~topomark.reference.explorers.lighthouses.Lighthouse` (its name is
  reported) and the established beacon (its ``walk_steps``, §5.1/§6.1);
* ``explore()`` — run to termination and return S (Algorithm 3.1's explorer,
  driven this way by the protocol oracle);
* whatever an algorithm's registry entry reads in its ``summary_fn`` /
  ``write_models`` (``phase_two_from``, ``dropped``, ``completed_models``, ...).

Examples
--------
>>> from topomark.reference.explorers.algorithm31 import LighthouseExplorer
>>> from topomark.reference.explorers.movable_marker import MovableMarkerExplorer
>>> conforms(LighthouseExplorer), conforms(MovableMarkerExplorer)
(True, True)
>>> conforms(int)
False
"""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

from topomark.spec.mapstate import MapDart, PartialMap

__all__ = ["Explorer", "IterationRecord", "EXPLORER_ATTRIBUTES", "EXPLORER_METHODS", "conforms"]

EXPLORER_ATTRIBUTES = ("S", "position", "iterations")
"""The attributes every explorer has once built (the checker reads them; :class:`Explorer` names them)."""

EXPLORER_METHODS = ("start", "step", "done", "models")
"""The methods of the contract, in the order the run calls them."""


@runtime_checkable
class IterationRecord(Protocol):
    """One step's record: ``number`` (1, 2, ...), ``kind`` (``"loop"``, ``"non-loop"``, or the algorithm's own
    word), ``hypotheses`` (objects with ``outcome`` — ``"case 1"``/``"case 2"`` rejected, ``"case 3"``
    confirmed — and, for the ``lemma-1`` check, ``dart``, ``motions`` and ``expected``; an empty list where
    the algorithm makes none; the run may replace it by ``[]`` once traced) and ``to_json()`` (the trace's
    ``iteration`` record, ``spec/trace.md``)."""

    number: int
    kind: str
    hypotheses: list

    def to_json(self) -> dict[str, Any]: ...


@runtime_checkable
class Explorer(Protocol):
    """``start``, then ``step`` until ``done``; ``models``; ``S``, ``position``, ``iterations`` (module docstring).

    ``isinstance(explorer, Explorer)`` checks a built explorer, attributes included; ``issubclass(cls,
    Explorer)`` is not available for a protocol with attributes, so :func:`conforms` checks a class's methods.
    """

    S: PartialMap
    position: MapDart
    iterations: list

    def start(self) -> None: ...

    def step(self) -> Any: ...

    def done(self) -> bool: ...

    def models(self) -> list[tuple[PartialMap, MapDart]]: ...


def conforms(cls: type) -> bool:
    """Whether the class ``cls`` offers the contract's methods (its instances' attributes are checked by
    ``isinstance(explorer, Explorer)`` once built)."""
    return all(callable(getattr(cls, name, None)) for name in EXPLORER_METHODS)
