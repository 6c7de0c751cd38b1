"""Running an implementation against a conformance suite (thesis §3.1.2–3.1.3, §6.2).

:func:`run` plays Algorithm 3.1's worlds to an external implementation through
``topomark/protocol@1`` or ``@2`` with any kit; :func:`run_algorithms` plays
the cases of the chosen algorithms' suites through ``@2``, each with its own
kit in ``hello`` (:func:`topomark.reference.oracle.run_external.run_external`).
A crash, a hang or garbage is a failure like a wrong map.

A case that expects ``correct`` passes when the program's map is extended-
isomorphic to the world with the markers it left (§3.1.3).  A case that
expects ``failed`` — topomark's run of the algorithm gives up: its markers or
its thread run out before the map is complete (§6.2.1, §6.3.2) — is a *must
fail* case: the program passes it when it gives up too (sends ``error``, which
the verdict quotes as ":data:`~topomark.reference.oracle.run_external.GAVE_UP`:
...") without overdrawing its kit, or when it maps the world correctly with
that kit anyway (reason ``mapped``: better than the reference); a wrong map, an
overdrawn kit or a crash fails it.
A correct map that cost more edge traversals than a bound *of the thesis's
listing* on that world — one the thesis states (Algorithm 3.1's (3.1)+(3.2),
§3.5.2) or one topomark derives for the listing as written (``docs/bounds.md``)
— fails with reason ``bound``: it is not that algorithm.  A correct map that
costs more than topomark's own figure for its *variant* of the listing (its
reference run, or a bound topomark states for its variant only) but within any
bound of the listing passes, reported as a **difference** with both figures
(:mod:`~topomark.reference.oracle.conformance.judgement`).  Each row compares the program's cost (edge
traversals, §3.1.2) and marker operations with topomark's own run *of the same algorithm* on the same case,
names the variant that run was made with, and says whose its bound is.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Sequence, cast

from topomark.spec.errors import InvalidInput
from topomark.spec.kit import Kit
from topomark.spec.worldfile import load_world

from topomark.reference.oracle.conformance.judgement import binding_bound, bound_words, difference, variant_words
from topomark.reference.oracle.conformance.lint import lint
from topomark.reference.oracle.conformance.manifest import SUITE_FORMAT
from topomark.reference.oracle.run_external import ExternalResult, Limits, run_external

__all__ = ["Row", "AlgorithmRow", "run", "run_algorithms", "render_table", "render_algorithm_table", "timed_run"]


def _ratio(cost: int, reference: int, passed: bool) -> float | None:
    return round(cost / reference, 3) if passed and reference > 0 else None


@dataclass
class Row:
    """One Algorithm 3.1 case: the program's result against ``basic``'s costs."""

    name: str
    n: int
    m: int
    result: ExternalResult
    reference: int  # the default policy's cost
    best: int  # the cheapest named policy's cost

    @property
    def passed(self) -> bool:
        return self.result.passed

    def to_json(self) -> dict[str, Any]:
        r = self.result
        return {"case": self.name, "n": self.n, "m": self.m, "verdict": r.verdict, "reason": r.reason,
                "message": r.message, "cost": r.cost, "reference_algorithm": "basic", "reference_cost": self.reference,
                "best_reference_cost": self.best, "ratio": _ratio(r.cost, self.reference, r.passed),
                "ratio_best": _ratio(r.cost, self.best, r.passed), "wall_seconds": round(r.wall, 3)}


def run(directory: str | Path, command: Sequence[str], limits: Limits | None = None,
        select: str | None = None, progress: Callable[[Row], None] | None = None, version: int = 1,
        kit: Kit | None = None, record: bool = False) -> list[Row]:
    """Run ``command`` on every Algorithm 3.1 case (or those whose name contains ``select``), speaking protocol
    ``version`` with ``kit``; ``record``: each result keeps the program's trace (the run viewer's)."""
    root = Path(directory)
    manifest = lint(root, replay_traces=False)
    rows = []
    for case in manifest["cases"]:
        if select and select not in case["name"]:
            continue
        world = load_world(root / case["world"])
        costs = {k: v["cost"] for k, v in case["reference"].items()}
        row = Row(case["name"], world.n, world.m, run_external(world, command, limits, version=version, kit=kit, record=record),
                  costs.get("default", min(costs.values())), min(costs.values()))
        rows.append(row)
        if progress is not None:
            progress(row)
    if not rows:
        raise InvalidInput(f"no case of {root} matches {select!r}")
    return rows


@dataclass
class AlgorithmRow:
    """One case of an algorithm's suite: the program's result against that algorithm's reference run."""

    algorithm: str
    case: dict[str, Any]
    result: ExternalResult

    @property
    def within_bound(self) -> bool:
        """The program's cost is at most the case's *binding* bound — of the thesis's listing, stated by the
        thesis or derived by topomark for the listing as written (:func:`.judgement.binding_bound`): an
        implementation that maps correctly but spends more is not that algorithm."""
        limit = binding_bound(self.case)
        return limit is None or self.result.cost <= limit

    @property
    def passed(self) -> bool:
        if self.case["expected"] == "correct":
            return self.result.passed and self.within_bound
        return self.result.gave_up or self.result.passed  # a must-fail case: giving up, or a correct map

    @property
    def difference(self) -> dict[str, Any] | None:
        """A passing correct map that costs more than topomark's variant's figure (:func:`.judgement.difference`),
        or None."""
        if self.case["expected"] != "correct" or not self.passed:
            return None
        return difference(self.case, self.algorithm, self.result.cost)

    @property
    def reason(self) -> str:
        """The program's reason; ``mapped`` when it sent a correct map where topomark's run gives up (a pass);
        ``bound`` when its correct map cost more than the bound of the thesis's listing; ``difference`` when it
        passes but costs more than topomark's variant."""
        if self.case["expected"] == "failed" and self.result.passed:
            return "mapped"
        if self.case["expected"] == "correct" and self.result.passed and not self.within_bound:
            return "bound"
        if self.difference is not None:
            return "difference"
        return "failed" if self.passed and self.case["expected"] == "failed" else self.result.reason

    @property
    def message(self) -> str:
        if self.reason == "bound":
            return (f"the map is right, but it cost {self.result.cost} edge traversals, more than "
                    f"{binding_bound(self.case)}, a bound of the thesis's listing — {bound_words(self.case)} — "
                    f"({self.algorithm}, n = {self.case['n']}, m = {self.case['m']}): not {self.algorithm}")
        if self.reason == "difference":
            return cast(dict, self.difference)["message"]
        if self.reason == "mapped":
            return (f"the map is right: the program mapped the world with a kit on which topomark's run of "
                    f"{self.algorithm} gives up ({self.case['reason']}), better than the reference")
        return self.result.message

    def to_json(self) -> dict[str, Any]:
        r, ref = self.result, self.case["reference"]
        return {"algorithm": self.algorithm, "case": self.case["name"], "n": self.case["n"], "m": self.case["m"],
                "kit": self.case["kit"], "options": self.case["options"], "bound": self.case["bound"],
                "bound_source": self.case.get("bound_source"), "bound_binds": binding_bound(self.case) is not None,
                "expected": self.case["expected"], "verdict": "pass" if self.passed else "fail",
                "reason": self.reason, "message": self.message, "cost": r.cost,
                "marker_operations": r.marker_operations, "difference": self.difference,
                "reference": {"algorithm": self.algorithm, "variant": self.case.get("variant"),
                              "made_with": variant_words(self.case, self.algorithm), "outcome": self.case["expected"],
                              "cost": ref["cost"], "marker_operations": ref["marker_operations"]},
                "ratio": _ratio(r.cost, ref["cost"], self.passed), "wall_seconds": round(r.wall, 3)}


def run_algorithms(directory: str | Path, command: Sequence[str], algorithms: Sequence[str],
                   limits: Limits | None = None, select: str | None = None,
                   progress: Callable[[AlgorithmRow], None] | None = None, record: bool = False) -> list[AlgorithmRow]:
    """Run ``command`` on every case of the suites of ``algorithms`` (or those whose name contains ``select``),
    through ``topomark/protocol@2`` with each case's kit."""
    root = Path(directory)
    manifest = lint(root, replay_traces=False)
    if manifest["format"] != SUITE_FORMAT:
        raise InvalidInput(f"suite {root} is {manifest['format']}: only {SUITE_FORMAT} holds algorithm suites; "
                           "export a new one (topomark conformance export DIR)")
    suites = {s["algorithm"]: s for s in manifest["suites"]}
    missing = [a for a in algorithms if a not in suites]
    if missing:
        raise InvalidInput(f"suite {root} has no suite of {', '.join(missing)} (it has: "
                           f"{', '.join(suites) or 'none'})")
    rows = []
    for name in algorithms:
        for case in suites[name]["cases"]:
            if select and select not in case["name"]:
                continue
            world = load_world(root / case["world"])
            result = run_external(world, command, limits, version=2, kit=Kit.from_json(case["kit"]), record=record)
            rows.append(AlgorithmRow(name, case, result))
            if progress is not None:
                progress(rows[-1])
    if not rows:
        raise InvalidInput(f"no case of {root} matches {select!r}")
    return rows


def _table(head: tuple[str, ...], body: list[tuple[str, ...]]) -> list[str]:
    widths = [max(len(r[k]) for r in [head] + body) for k in range(len(head) - 1)]
    return ["  ".join(c.ljust(w) for c, w in zip(r[:-1], widths)) + "  " + r[-1] for r in [head] + body]


def _number(value: float | None) -> str:
    return "-" if value is None else f"{value:.2f}"


def render_table(rows: list[Row], wall: float) -> str:
    head = ("case", "n", "m", "verdict", "cost", "ref cost (basic)", "ratio", "best cost (basic)", "ratio",
            "reason")
    body: list[tuple[str, ...]] = []
    for row in rows:
        j = row.to_json()
        body.append((row.name, str(row.n), str(row.m), j["verdict"].upper(), str(j["cost"]), str(row.reference),
                     _number(j["ratio"]), str(row.best), _number(j["ratio_best"]),
                     "" if row.result.passed else f"{row.result.reason}: {row.result.message}"[:100]))
    lines = _table(head, body)
    passed = sum(r.result.passed for r in rows)
    lines.append(f"{passed}/{len(rows)} passed in {wall:.1f} s (ref cost (basic): topomark's Algorithm 3.1 under "
                 "the default policy; best cost (basic): under the cheapest named policy)")
    return "\n".join(line.rstrip() for line in lines)


def _ops(ops: dict[str, int]) -> str:
    return ",".join(f"{k}={v}" for k, v in sorted(ops.items())) or "-"


def render_algorithm_table(rows: list[AlgorithmRow], wall: float) -> str:
    """The rows, the reference columns labelled with the algorithm they compare with."""
    names = sorted({r.algorithm for r in rows})
    label = names[0] if len(names) == 1 else "its algorithm"
    head = ("algorithm", "case", "n", "m", "expected", "verdict", "cost", f"ref cost ({label})", "ratio", "bound",
            "ops", f"ref ops ({label})", "reason")
    body: list[tuple[str, ...]] = []
    for row in rows:
        j = row.to_json()
        note = "" if row.passed and j["reason"] not in ("difference", "failed") and row.case["expected"] == "correct" \
            else f"{j['reason']}: {j['message']}"[:160]
        body.append((row.algorithm, j["case"], str(j["n"]), str(j["m"]), j["expected"], j["verdict"].upper(),
                     str(j["cost"]), str(j["reference"]["cost"]), _number(j["ratio"]), _bound_cell(j),
                     _ops(j["marker_operations"]), _ops(j["reference"]["marker_operations"]), note))
    lines = _table(head, body)
    passed = sum(r.passed for r in rows)
    differ = sum(r.difference is not None for r in rows)
    made = "; ".join(sorted({f"{r.algorithm}: {variant_words(r.case, r.algorithm)}" for r in rows}))
    lines.append(f"{passed}/{len(rows)} passed ({differ} with a difference) in {wall:.1f} s (ref: topomark's own run "
                 f"of {label} on the case, with the case's kit — made with {made}; ratio: cost / ref cost; bound: "
                 "L = a bound of the thesis's listing (stated by the thesis, or derived by topomark for the listing "
                 "as written, docs/bounds.md), a cost above it fails; V = topomark's bound for its own variant, a "
                 "cost above it is a difference; ? = source not recorded (a 2.0 suite), a difference; - if none; "
                 "ops: marker and thread operations by kind)")
    return "\n".join(line.rstrip() for line in lines)


def _bound_cell(j: dict[str, Any]) -> str:
    """The bound column: the figure and whose it is (L: of the thesis's listing, V: topomark's variant's)."""
    if j["bound"] is None:
        return "-"
    source = j["bound_source"]
    return f"{j['bound']} {'?' if source is None else 'L' if source['binds'] else 'V'}"


def timed_run(directory, command, limits=None, select=None, progress=None, version: int = 1,
              kit: Kit | None = None, algorithms: Sequence[str] = (), record: bool = False) -> tuple[list, float]:
    """:func:`run` (no ``algorithms``) or :func:`run_algorithms`, and the wall time it took."""
    started = time.monotonic()
    rows: list[Any]  # Row or AlgorithmRow
    if algorithms:
        rows = run_algorithms(directory, command, algorithms, limits, select, progress, record)
    else:
        rows = run(directory, command, limits, select, progress, version, kit, record)
    return rows, time.monotonic() - started
