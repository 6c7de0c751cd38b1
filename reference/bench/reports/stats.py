"""The statistics every bench report computes from ``runs.csv``'s rows: grouping, numbers, means, slopes.

Part of the report kit (:mod:`~topomark.reference.bench.reports.kit`).  A row is a
dict of strings as :func:`~topomark.reference.bench.run_store.read_runs` gives it;
an empty cell reads as 0 (:func:`num`).  The reports group the latest row of
each run key (:func:`latest`) by some of its key columns (:func:`groups`) and
summarise a group by the mean and standard deviation of a column
(:func:`mean`, :func:`sd`).  An asymptotic cost bound is read on finite worlds
as "cost grows no faster than the bound's function f" (:func:`cost_f`,
:func:`slope`, :data:`SLOPE_TOLERANCE`).

Examples
--------
>>> rows = [{"cost": "10", "m": "5"}, {"cost": "30", "m": "5"}]
>>> mean(rows, "cost"), sd(rows, "cost"), mean(rows, cost_per_m)
(20.0, 14.142135623730951, 4.0)
>>> slope([(10, 100), (20, 200), (40, 400)])
1.0
>>> cost_f("m²n", {"n": "3", "m": "4"})
48.0
>>> net_cost({"cost": "50", "drop_trips": "26"}), measured(net_cost({"cost": "50"}))
(24.0, False)
"""

from __future__ import annotations

import math
import statistics
from typing import Callable, Iterable

from topomark.reference.bench.plan import DEFAULT_LIGHTHOUSE
from topomark.reference.bench.run_store import row_key

__all__ = ["latest", "lighthouse_of", "KEY_COLUMNS", "key_of", "finished", "groups", "by_seed", "num", "cost_per_m",
           "cpu_seconds", "mean", "sd", "mean_sd", "COST_F", "cost_f", "slope", "SLOPE_TOLERANCE", "spearman",
           "drop_trips", "net_cost", "measured"]

SLOPE_TOLERANCE = 1.1
"""The largest least-squares slope of log(mean cost) against log(mean f) read as "cost grows no faster than f"."""


def latest(rows: list[dict]) -> list[dict]:
    """One row per key: the last checked row if any, else the last row."""
    best: dict[tuple, dict] = {}
    for r in rows:
        k = row_key(r)
        if k not in best or str(r.get("checked")) == "True" or str(best[k].get("checked")) != "True":
            best[k] = r
    return list(best.values())


def lighthouse_of(row: dict) -> str:
    """The row's lighthouse (a runs file written before the column existed used only Algorithm 3.1's own)."""
    return row.get("lighthouse") or DEFAULT_LIGHTHOUSE


KEY_COLUMNS: dict[str, Callable[[dict], object]] = {
    "family": lambda r: r["experiment"], "algorithm": lambda r: r["algorithm"],
    "policy": lambda r: r.get("policy") or "nearest", "lighthouse": lighthouse_of,
    "options": lambda r: r.get("options") or "", "size": lambda r: int(r["size"]),
}


def key_of(row: dict, columns: tuple[str, ...]) -> tuple:
    """The row's values of these key columns (:data:`KEY_COLUMNS`: an empty cell reads as its default)."""
    return tuple(KEY_COLUMNS[c](row) for c in columns)


def finished(row: dict) -> bool:
    """The run finished (a crashed run's row has no cost)."""
    return row.get("cost") not in ("", None)


def groups(rows: list[dict], columns: tuple[str, ...],
           keep: Callable[[dict], bool] = finished) -> dict[tuple, list[dict]]:
    """:func:`key_of` ``columns`` -> the rows of :func:`latest` that ``keep`` keeps (the finished runs unless
    told), in the order the file first names each key."""
    out: dict[tuple, list[dict]] = {}
    for r in latest(rows):
        if keep(r):
            out.setdefault(key_of(r, columns), []).append(r)
    return out


def by_seed(grouped: dict[tuple, list[dict]]) -> dict[tuple, dict[int, dict]]:
    """Each group's rows by world seed."""
    return {k: {int(r["seed"]): r for r in rs} for k, rs in grouped.items()}


def num(r: dict, column: str) -> float:
    """The row's number in ``column`` (an empty or missing cell: 0)."""
    return float(r.get(column) or 0)


def cost_per_m(r: dict) -> float:
    """The run's cost per edge of its world (the lower bound m: every edge is traversed once)."""
    return num(r, "cost") / num(r, "m")


def drop_trips(r: dict) -> float:
    """The run's drop trips (traversals made only to drop markers, part of its cost); NaN for a row written before
    the column existed (not measured, never read as 0)."""
    value = r.get("drop_trips")
    return math.nan if value in ("", None) else float(value)


def net_cost(r: dict) -> float:
    """The run's cost without its drop trips (NaN where they were not measured)."""
    return num(r, "cost") - drop_trips(r)


def measured(*values: float) -> bool:
    """None of the values is NaN (a drop-trip figure of a runs file that has the column)."""
    return not any(math.isnan(v) for v in values)


def cpu_seconds(r: dict) -> float:
    """The run's CPU time (a row written before the column existed: its wall time)."""
    return float(r.get("cpu_seconds") or r.get("seconds") or 0)


def _values(rs: Iterable[dict], key: str | Callable[[dict], float]) -> list[float]:
    return [num(r, key) if isinstance(key, str) else key(r) for r in rs]


def mean(rs: Iterable[dict], key: str | Callable[[dict], float]) -> float:
    """The mean over the rows of a column (by name) or of ``key(row)``."""
    return statistics.fmean(_values(rs, key))


def sd(rs: Iterable[dict], key: str | Callable[[dict], float]) -> float:
    """The sample standard deviation over the rows of a column or of ``key(row)`` (0 for fewer than two rows)."""
    return mean_sd(_values(rs, key))[1]


def mean_sd(values: list[float]) -> tuple[float, float]:
    """(mean, sample standard deviation) of the values; the deviation of a single value is 0."""
    return statistics.fmean(values), statistics.stdev(values) if len(values) > 1 else 0.0


COST_F: dict[str, Callable[[dict], float]] = {
    "m": lambda r: num(r, "m"), "mn": lambda r: num(r, "m") * num(r, "n"),
    "m·d_max": lambda r: num(r, "m") * num(r, "d_max"), "m²n": lambda r: num(r, "m") ** 2 * num(r, "n"),
}
"""A cost bound O(f) ↦ f of a run's world (n, m, largest degree d_max)."""


def cost_f(bound: str, row: dict) -> float:
    """f of the cost bound O(f) (:data:`COST_F`) for this run's world."""
    return COST_F[bound](row)


def slope(points: list[tuple[float, float]]) -> float | None:
    """Least-squares slope of log y against log x (None with fewer than two distinct x)."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len({p[0] for p in pts}) < 2:
        return None
    mx, my = statistics.fmean(p[0] for p in pts), statistics.fmean(p[1] for p in pts)
    return round(sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts), 3)


def spearman(xs: list[float], ys: list[float]) -> float:
    """Spearman's rank correlation of xs and ys (ties ranked in order; 0 when ys are all equal)."""
    def ranks(v):
        order = sorted(range(len(v)), key=lambda i: v[i])
        r = [0.0] * len(v)
        for k, i in enumerate(order):
            r[i] = k
        return r
    rx, ry = ranks(xs), ranks(ys)
    return statistics.correlation(rx, ry) if len(xs) > 1 and len(set(ys)) > 1 else 0.0
