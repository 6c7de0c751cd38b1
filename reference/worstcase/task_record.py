"""What a resumed worst-case search checks in a task file whose seal holds: that its tallies can be true (§7.2).

A task file (``task-T.json``, :mod:`.resumable`) is sealed with a checksum, which finds damage but not an edit
resealed by hand.  :func:`check_record` so checks what can be checked without running the task: every field's
type and range, sizes that are the task's, outcomes that add up to the runs, ``(m, cost)`` pairs that add up to
the correct runs and whose largest cost and cost/m are the tallied maxima, witnesses in the task's graphs.  A file
failing any check is bad input (exit 2) naming the file and what is wrong: it is not topomark's failure.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Any

from topomark.spec.errors import InvalidInput

__all__ = ["check_record"]


def _count(x: Any) -> bool:
    return type(x) is int and x >= 0


def _fraction(x: Any) -> bool:
    return x is None or (isinstance(x, list) and len(x) == 2 and _count(x[0]) and _count(x[1]) and x[1] > 0)


def _witness(x: Any, graphs: set[int]) -> bool:
    return x is None or (isinstance(x, list) and len(x) == 4 and _count(x[0]) and x[0] in graphs
                         and _count(x[1]) and isinstance(x[2], str) and _count(x[3]))


def _tally_problem(t: Any, graphs: dict[int, set[int]]) -> str | None:
    """What is wrong with one size's tally, or None."""
    if not isinstance(t, dict) or not _count(t.get("n")) or t["n"] not in graphs:
        return f"a tally of a size not in the task ({str(t)[:60]})"
    at = f"the tally of n = {t['n']}"
    outcomes, pairs = t.get("outcomes"), t.get("pairs")
    if not (_count(t.get("worlds")) and _count(t.get("runs")) and isinstance(outcomes, dict)
            and all(isinstance(k, str) and _count(v) for k, v in outcomes.items())):
        return f"{at}: its worlds, runs or outcomes are not counts"
    if sum(outcomes.values()) != t["runs"]:
        return f"{at}: its outcomes add up to {sum(outcomes.values())}, not its {t['runs']} runs"
    if not (isinstance(pairs, list) and all(isinstance(p, list) and len(p) == 3 and all(map(_count, p))
                                            and p[0] > 0 and p[2] > 0 for p in pairs)):
        return f"{at}: its pairs are not [m, cost, runs] counts"
    if sum(p[2] for p in pairs) != outcomes.get("correct", 0):
        return f"{at}: its pairs count {sum(p[2] for p in pairs)} runs, not its {outcomes.get('correct', 0)} correct ones"
    if not (_fraction(t.get("cost_m")) and _fraction(t.get("ratio"))
            and all(_witness(t.get(k), graphs[t["n"]]) for k in ("argmax_cost", "argmax_cost_m", "argmax_ratio"))):
        return f"{at}: a maximum or witness is malformed or outside the task's graphs"
    top = max((p[1] for p in pairs), default=None)
    best = max((Fraction(p[1], p[0]) for p in pairs), default=None)
    cost_m = None if t["cost_m"] is None else Fraction(t["cost_m"][0], t["cost_m"][1])
    if t.get("max_cost") != top or cost_m != best or (top is None) != (t["argmax_cost"] is None):
        return f"{at}: its largest cost {t.get('max_cost')} or cost/m {t['cost_m']} is not its pairs' ({top}, {best})"
    return None


def check_record(path: Path, record: dict[str, Any], units: list) -> None:
    """InvalidInput naming ``path`` if the task record ``record`` of the task ``units`` cannot be true."""
    graphs: dict[int, set[int]] = {}
    for unit in units:
        graphs.setdefault(unit[0], set()).add(unit[1])
    tallies, problems = record.get("tallies"), record.get("problems")
    reason = None
    if not (isinstance(tallies, list) and _count(record.get("refused")) and _count(record.get("checked"))
            and isinstance(problems, list) and _count(record.get("problem_count"))
            and all(isinstance(p, dict) and isinstance(p.get("kind"), str) for p in problems)):
        reason = "its tallies, refused, checked or problems are not of their types"
    elif len({t.get("n") if isinstance(t, dict) else None for t in tallies}) != len(tallies):
        reason = "a size is tallied twice"
    else:
        reason = next((r for r in map(lambda t: _tally_problem(t, graphs), tallies) if r), None)
    if reason:
        raise InvalidInput(f"{path}: its seal holds but {reason} (edited and resealed?); remove the file to run the "
                           "task again")
