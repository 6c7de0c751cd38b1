"""The worst-case report: a table per size, the thesis's bound beside it, and the cost/m plots (thesis §7.2).

:func:`table` prints the rows of an exhaustive search
(:func:`topomark.reference.worstcase.result.rows`); :func:`write_report`
writes ``worst-case.md`` with the thesis's statement beside what the search
found, and, with matplotlib, ``worst-case-cost-per-m.png`` (the distribution
of cost/m per n) and ``worst-case-max.png`` (the largest cost per n beside
the exact bound at that world), in the bench's plotting style.

Examples
--------
>>> print(table([{"n": 3, "worlds": 2, "runs": 3, "outcomes": {"correct": 3}, "max_cost": 7, "max_cost_per_m": 2.333,
...               "max_ratio_to_bound": 0.3182, "quantiles_cost_per_m": {"0.5": 1.5, "0.9": 2.333},
...               "argmax_at": {"graph": 1, "rotation": 0, "start": "v0", "exit": 1}}]))
  n    worlds     runs  not correct  max cost  max cost/m  max cost/bound  median c/m  p90 c/m  argmax (graph, rotation, start)
  3         2        3            0         7       2.333          0.3182         1.5    2.333  g1 r0 v0:1
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from topomark.reference.bench.reports.plots import curve, drawn, finish, new, reference

__all__ = ["table", "write_report", "not_correct", "THESIS"]

THESIS = ("Algorithm 3.1 costs at most (3.1) + (3.2) = O(m²n) edge traversals (§3.5.2); the bound "
          "\"is quite loose\", and \"it is worth investigating whether the worst case scenarios exist\" "
          "(§7.2).")


def not_correct(row: dict[str, Any]) -> int:
    """How many of a row's runs did not end with the world mapped (left out of its maxima)."""
    return int(row["runs"]) - int(row.get("outcomes", {}).get("correct", 0))


def _cell(value: Any, width: int) -> str:
    return f"{'-' if value is None else value:>{width}}"


def table(per_n: list[dict[str, Any]]) -> str:
    """The rows as a fixed-width table."""
    head = (f"{'n':>3}  {'worlds':>8}  {'runs':>7}  {'not correct':>11}  {'max cost':>8}  {'max cost/m':>10}  {'max cost/bound':>14}  "
            f"{'median c/m':>10}  {'p90 c/m':>7}  argmax (graph, rotation, start)")
    lines = [head]
    for r in per_n:
        q, at = r.get("quantiles_cost_per_m") or {}, r.get("argmax_at")
        where = "-" if at is None else f"g{at['graph']} r{at['rotation']} {at['start']}:{at['exit']}"
        lines.append(f"{r['n']:>3}  {r['worlds']:>8}  {r['runs']:>7}  {not_correct(r):>11}  {_cell(r['max_cost'], 8)}  "
                     f"{_cell(r['max_cost_per_m'], 10)}  {_cell(r['max_ratio_to_bound'], 14)}  "
                     f"{_cell(q.get('0.5'), 10)}  {_cell(q.get('0.9'), 7)}  {where}")
    return "\n".join(lines)


def _markdown(data: dict[str, Any]) -> str:
    rows = data["per_n"]
    ratio = max((r["max_ratio_to_bound"] for r in rows if r["max_ratio_to_bound"] is not None), default=None)
    held = "no stated exact bound" if ratio is None else (
        f"held: the largest cost / bound is {ratio} (< 1)" if ratio <= 1 else f"did NOT hold: cost / bound reaches {ratio}")
    lines = [f"# Worst case of `{data['algorithm']}`, exhaustive for n ≤ {data['max_vertices']}, "
             f"degree ≤ {data['max_degree']}", "",
             "Every embedded world up to extended isomorphism, every start up to the world's automorphisms; "
             "the maxima below are exact (proved by enumeration), not estimates.", "",
             f"- **Thesis:** {THESIS}", f"- **Here:** the bound {held}.", "",
             "| n | worlds | runs | not correct | max cost | max cost/m | max cost/bound | bound at argmax | median cost/m | "
             "p90 cost/m | argmax world |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        q, at = r.get("quantiles_cost_per_m") or {}, r.get("argmax_at")
        where = "-" if at is None else f"`argmax-cost-n{r['n']}.json` (start {at['start']}, exit {at['exit']})"
        lines.append(f"| {r['n']} | {r['worlds']} | {r['runs']} | {not_correct(r)} | {r['max_cost']} | {r['max_cost_per_m']} | "
                     f"{r['max_ratio_to_bound']} | {r.get('bound_at_argmax')} | {q.get('0.5')} | {q.get('0.9')} | "
                     f"{where} |")
    lines += ["", f"{data['checked_runs']} runs were re-run checked (a seeded sample and every argmax) with every "
                  f"invariant after every step; {data['problem_count']} problems; {data['refused_starts']} starts "
                  f"refused by the algorithm.", ""]
    return "\n".join(lines)


def _plots(out: Path, rows: list[dict[str, Any]], algorithm: str):
    def draw(plt) -> list[Path]:
        fig, ax = new(plt)
        for r in rows:
            hist = r["histogram_cost_per_m"]
            total = sum(k for _, _, k in hist) or 1
            xs = [(lo + hi) / 2 for lo, hi, _ in hist]
            curve(ax, xs, [k / total for _, _, k in hist], f"n = {r['n']}")
        first = finish(plt, fig, ax, out / "worst-case-cost-per-m.png", f"{algorithm}: distribution of cost/m",
                       "cost / m (bins of 0.5)", "fraction of runs", log=False)
        fig, ax = new(plt)
        ns = [r["n"] for r in rows if r["max_cost"] is not None]
        curve(ax, ns, [r["max_cost"] for r in rows if r["max_cost"] is not None], "largest cost (exhaustive)")
        bounds = [(r["n"], r["bound_at_argmax"]) for r in rows if r.get("bound_at_argmax")]
        if bounds:
            reference(ax, [b[0] for b in bounds], [b[1] for b in bounds], "the exact bound at that world")
        second = finish(plt, fig, ax, out / "worst-case-max.png", f"{algorithm}: the worst case per n",
                        "n (vertices)", "edge traversals")
        return [first, second]
    return drawn(draw)


def write_report(out: Path, data: dict[str, Any]) -> list[Path]:
    """``worst-case.md`` and (with matplotlib) its two plots in ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    plots = _plots(out, data["per_n"], data["algorithm"])
    text = _markdown(data)
    if plots is None:
        text += "\n(No plots: matplotlib is not installed; `pip install '.[plot]'` from a checkout.)\n"
    else:
        text += "\n" + "\n".join(f"![{p.stem}]({p.name})" for p in plots) + "\n"
    path = out / "worst-case.md"
    path.write_text(text, encoding="utf-8")
    return [path, *(plots or [])]
