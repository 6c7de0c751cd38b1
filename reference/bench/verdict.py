"""The bench's verdict: every run judged against what its algorithm's registry entry expects of it.

A run is *as expected* when its outcome is one its algorithm's expectation for that world family and lighthouse
accepts (:meth:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec.expectation`,
:mod:`~topomark.reference.algorithms.expectation`): Case 0's failed runs and §5.2.1's wrong maps
are as expected; a wrong map of Algorithm 3.1 is not.  ``topomark bench`` exits 0 when every run of the sweep is as
expected and 1 when one is not; the command's summary and every report count both, by outcome (:class:`Tally`).

A row of a runs file written before the ``outcome`` column existed ends ``correct`` when verified, else
``wrong-map``; a row of an algorithm no longer registered is expected to be ``correct``.

Examples
--------
>>> t = Tally()
>>> for row in ({"algorithm": "case-0", "experiment": "complete-hole", "lighthouse": "none", "outcome": "failed",
...              "checked": "True"},
...             {"algorithm": "basic", "experiment": "lattice-hole", "lighthouse": "directional-vertex",
...              "outcome": "wrong-map", "checked": "True"}):
...     _ = t.add(row)
>>> t.failures, t.line()
(1, 'as expected: 1 (failed 1); not as expected: 1 (wrong-map 1)')
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from topomark.spec.errors import InvalidInput

from topomark.reference.algorithms.expectation import CORRECT, as_expected
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.bench.run_store import read_runs, row_key
from topomark.reference.bench.reports.stats import latest

__all__ = ["Tally", "expectation_of", "row_as_expected", "outcome_of", "tally", "judge_plan"]


def outcome_of(row: dict) -> str:
    """The row's outcome (one written before the column existed: ``correct`` if verified, else ``wrong-map``)."""
    if row.get("outcome"):
        return str(row["outcome"])
    return "correct" if str(row.get("verified")) == "True" else "wrong-map"


def expectation_of(row: dict) -> tuple[str, str]:
    """What the row's algorithm expects on its world family with its lighthouse, and why."""
    try:
        spec = algorithm_spec(row["algorithm"])
    except InvalidInput:  # no longer registered: held to the strictest expectation
        return CORRECT, ""
    return spec.expectation(row.get("experiment"), row.get("lighthouse") or None)


def row_as_expected(row: dict) -> bool:
    """Whether the row's outcome is one its expectation accepts (an unchecked run always is)."""
    return as_expected(expectation_of(row)[0], outcome_of(row), str(row.get("checked")) == "True")


@dataclass
class Tally:
    """Runs counted by outcome, as expected and not as expected."""

    expected: Counter = field(default_factory=Counter)
    unexpected: Counter = field(default_factory=Counter)

    def add(self, row: dict) -> bool:
        """Count ``row``; whether it is as expected."""
        ok = row_as_expected(row)
        (self.expected if ok else self.unexpected)[outcome_of(row)] += 1
        return ok

    @property
    def failures(self) -> int:
        """The runs not as expected (``bench`` exits 1 when there is one)."""
        return sum(self.unexpected.values())

    def to_json(self) -> dict:
        """``{"as_expected": {outcome: count}, "not_as_expected": {outcome: count}}``."""
        return {"as_expected": dict(sorted(self.expected.items())),
                "not_as_expected": dict(sorted(self.unexpected.items()))}

    def line(self) -> str:
        """The counts in words, e.g. ``as expected: 5 (correct 4, failed 1); not as expected: 0``."""
        def part(c: Counter) -> str:
            inner = ", ".join(f"{k} {v}" for k, v in sorted(c.items()))
            return f"{sum(c.values())}" + (f" ({inner})" if inner else "")
        return f"as expected: {part(self.expected)}; not as expected: {part(self.unexpected)}"


def tally(rows) -> Tally:
    """The :class:`Tally` of ``rows``."""
    t = Tally()
    for row in rows:
        t.add(row)
    return t


def judge_plan(keys, path: Path) -> Tally:
    """The :class:`Tally` of the planned runs (their ``keys``) found in the runs file ``path`` (the latest row of
    each: a resumed sweep judges the runs it skipped as well as those it ran)."""
    wanted = set(keys)
    rows = read_runs(path).rows if path.exists() else []
    return tally(r for r in latest(rows) if row_key(r) in wanted)
