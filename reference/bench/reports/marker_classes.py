"""The marker classes side by side: ``topomark bench comparison-markers`` (thesis §2.3.1, Table 2.3;
§6.2.1 Cases 1 and 2; the experiment is :mod:`~topomark.reference.bench.plan_marker_classes`).

Table 2.3 states, per marker class, whether exploration is solvable and its known cost bound; the thesis never
measures its classic rows.  This report runs them — the footprints model with m + n homogeneous markers [18] and
the labelled graph explored depth first — beside the thesis's own algorithms on the same lattice-hole and
complete-hole worlds, and gives, per world family and size, the mean cost, cost/m and the markers each algorithm
left in the world per vertex (the kit of a lighthouse algorithm: its lighthouse's markers).  The stated bound and
the kit are the registry's (:mod:`~topomark.reference.algorithms`), never restated here.

Examples
--------
>>> marker_class("labelled-dfs").startswith("n distinct labels")
True
"""

from __future__ import annotations

from pathlib import Path
from typing import cast

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.bench.plan_marker_classes import BASELINES, COMPARED, NAME, SIZES
from topomark.reference.bench.reports.kit import Body, write
from topomark.reference.bench.reports.stats import groups, lighthouse_of, mean, mean_sd, num
from topomark.reference.bench.reports.text import fmt_pm, row, table
from topomark.reference.explorers.lighthouses import LIGHTHOUSES

__all__ = ["write_report", "marker_class", "NAME", "GROUP"]

GROUP = ("family", "algorithm", "size")
"""The runs are grouped by (world family, algorithm, size)."""


def marker_class(algorithm: str) -> str:
    """What the algorithm carries, as its registration states it."""
    spec = algorithm_spec(algorithm)
    return "one lighthouse marker (" + spec.kit.describe() + ")" if spec.uses_lighthouse else spec.markers


def markers_left(r: dict) -> float:
    """The markers a run left in the world: the row's count, or a lighthouse algorithm's lighthouse kit."""
    if r.get("markers_used") not in (None, ""):
        return num(r, "markers_used")
    kit = LIGHTHOUSES[lighthouse_of(r)].kit
    return kit.vertex + kit.edge + kit.either


def kit_size(r: dict) -> float | None:
    """The markers the algorithm is stated to need on this world (its marker bound; a lighthouse algorithm's
    lighthouse kit), or None if the registry states no count."""
    if r.get("marker_bound") not in (None, ""):
        return num(r, "marker_bound")
    if algorithm_spec(r["algorithm"]).uses_lighthouse:
        return markers_left(r)
    return None


def write_report(out: Path, wall: float | None = None, plots: bool = True) -> Path:
    """``out/comparison-markers.md`` from ``out/runs.csv`` (no plots: the tables are the report)."""
    return write(NAME, out, wall, plots,
                 " (thesis §3.1.2). Every algorithm of a size explores the same worlds from the same start; means "
                 "are over the worlds mapped correctly (checked and verified), the worlds column says how many of "
                 "how many. Markers left/vertex: the markers lying in the world at the end, divided by n (a movable "
                 "marker is carried away, a thread is no marker); stated/vertex: the algorithm's stated marker "
                 "bound for the world (a lighthouse algorithm: its lighthouse), divided by n.", _body,
                 plot_line=False)


def _body(rows: list[dict]) -> tuple[list[str], None]:
    gr = groups(rows, GROUP)
    lines = ["## The marker classes (registry)", ""]
    lines += table("| algorithm | thesis | markers | cost bound as stated |", "|---|---|---|---|",
                   [row(a + (" (baseline)" if a in BASELINES else ""), algorithm_spec(a).thesis, marker_class(a),
                        algorithm_spec(a).bound or "none stated") for a in COMPARED])
    for family, sizes in SIZES.items():
        lines += [f"## {family}", ""]
        body = [_line(a, s, gr.get((family, a, s), [])) for s in sizes for a in COMPARED]
        lines += table("| size | n | m | algorithm | worlds | mean cost ± sd | cost/m | markers left/vertex | "
                       "stated/vertex |", "|---:|---:|---:|---|---:|---:|---:|---:|---:|", [b for b in body if b])
    return lines, None


def _line(algorithm: str, size: int, rs: list[dict]) -> str | None:
    ok = [r for r in rs if r.get("outcome") == "correct" and str(r.get("verified")) == "True"]
    if not rs:
        return None
    if not ok:
        return row(size, "", "", algorithm, f"0/{len(rs)}", "", "", "", "")
    cost, sd = mean_sd([num(r, "cost") for r in ok])
    return row(size, f"{mean(ok, 'n'):.0f}", f"{mean(ok, 'm'):.1f}", algorithm, f"{len(ok)}/{len(rs)}",
               fmt_pm(cost, sd), f"{mean(ok, lambda r: num(r, 'cost') / num(r, 'm')):.2f}",
               f"{mean(ok, lambda r: markers_left(r) / num(r, 'n')):.2f}", _stated(ok))


def _stated(ok: list[dict]) -> str:
    sizes = [kit_size(r) for r in ok]
    if any(k is None for k in sizes):
        return "—"
    return f"{sum(cast(int, k) / num(r, 'n') for k, r in zip(sizes, ok)) / len(ok):.2f}"

