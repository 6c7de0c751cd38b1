"""What a run was doing when topomark itself failed: its world and the last of its trace, kept on the exception.

A run keeps a :class:`FlightRecorder` beside the sink its caller chose: every trace record the run makes
(``spec/trace.md``) goes to both.  The recorder keeps the last :data:`FLIGHT_RECORDS` of them (the trace up to
the failure, cut at its start when the run was long, and saying so); an ``iteration`` record older than the
last :data:`FULL_ITERATIONS` keeps its counts but not its hypotheses, whose motions and perceptions grow with
the world, so the recorder's memory stays bounded whatever the run.  It makes no record of its own: a run made
without a trace (``record=False``) has none to keep.

When an exception escapes the run (:class:`~topomark.spec.errors.TopomarkFault`, or any unexpected one),
:meth:`FlightRecorder.attach` puts :meth:`FlightRecorder.to_json` on it as the attribute :data:`ATTRIBUTE`
(the innermost run's, when runs nest); :func:`run_of` finds it again, along the exception's causes, for the
fault report (:mod:`topomark.reference.cli.fault_report`).  An API caller finds it there too.

>>> from topomark.spec.world import World
>>> flight = FlightRecorder(World({"a": ("b",), "b": ("a",)}), "basic", limit=2)
>>> for step in range(3):
...     flight.emit({"event": "move", "step": step})
>>> error = flight.attach(RuntimeError("boom"))
>>> run = run_of(error)
>>> run["algorithm"], run["trace"]["records"], run["trace"]["made"], run["trace"]["cut"]
('basic', [{'event': 'move', 'step': 1}, {'event': 'move', 'step': 2}], 3, True)
"""

from __future__ import annotations

from collections import deque
from typing import Any

from topomark.spec.world import World
from topomark.spec.worldfile import world_to_json

__all__ = ["FlightRecorder", "FLIGHT_RECORDS", "FULL_ITERATIONS", "ATTRIBUTE", "run_of"]

FLIGHT_RECORDS = 10_000
"""The most trace records a fault report holds: the last ones the run made."""

FULL_ITERATIONS = 3
"""The iteration records kept whole (hypotheses included); older ones keep their counts only."""

ATTRIBUTE = "topomark_run"
"""The exception attribute the run in progress is kept on (:meth:`FlightRecorder.attach`)."""


class FlightRecorder:
    """The last ``limit`` records of a run on ``world`` by ``algorithm`` (a trace sink: :meth:`emit`)."""

    def __init__(self, world: World, algorithm: str, limit: int = FLIGHT_RECORDS,
                 full_iterations: int = FULL_ITERATIONS) -> None:
        self.world, self.algorithm = world, algorithm
        self._ring: deque[dict] = deque(maxlen=limit)
        self._whole: deque[dict] = deque(maxlen=full_iterations)
        self.made = 0
        self.slimmed = 0

    def emit(self, record: dict) -> None:
        self.made += 1
        if isinstance(record.get("hypotheses"), list):
            record = dict(record)  # a copy: the caller's sink may keep the record whole
            if self._whole.maxlen is not None and len(self._whole) == self._whole.maxlen:
                self._slim(self._whole[0])
            self._whole.append(record)
        self._ring.append(record)

    def _slim(self, record: dict) -> None:
        record["hypotheses_left_out"] = len(record.pop("hypotheses"))
        self.slimmed += 1

    def to_json(self) -> dict[str, Any]:
        """The run in words a fault report holds: the algorithm, the world, and the trace kept."""
        try:
            world: Any = world_to_json(self.world)
        except Exception as exc:  # noqa: BLE001 - the run's fault may be the world's own: say so, keep the rest
            world = {"unavailable": f"{exc.__class__.__name__}: {exc}"}
        records = list(self._ring)
        cut = self.made > len(records)
        note = (f"the last {len(records):,} of the {self.made:,} records the run made" if cut
                else f"all {self.made:,} records the run made" if self.made
                else "the run made no trace records (it was run without a trace)")
        if self.slimmed:
            note += (f"; iteration records before the last {FULL_ITERATIONS} keep their counts, not their "
                     "hypotheses (hypotheses_left_out)")
        return {"algorithm": self.algorithm, "world": world,
                "trace": {"records": records, "made": self.made, "cut": cut, "note": note}}

    def attach(self, exc: BaseException) -> BaseException:
        """``exc`` with this run kept on it (:data:`ATTRIBUTE`), unless an inner run's is there already."""
        if getattr(exc, ATTRIBUTE, None) is not None:
            return exc  # an inner run's record is the one in progress when the fault began
        try:
            setattr(exc, ATTRIBUTE, self.to_json())
        except Exception:  # noqa: BLE001 - an exception that takes no attribute (__slots__, a built-in's instance)
            return exc  # is reported without the run (the report's "run" is null)
        return exc


def run_of(exc: BaseException | None) -> dict[str, Any] | None:
    """The run in progress when ``exc`` was raised (:meth:`FlightRecorder.attach`), looked for along its causes."""
    seen: set[int] = set()
    while exc is not None and id(exc) not in seen:
        seen.add(id(exc))
        run = getattr(exc, ATTRIBUTE, None)
        if isinstance(run, dict):
            return run
        exc = exc.__cause__ or exc.__context__
    return None
