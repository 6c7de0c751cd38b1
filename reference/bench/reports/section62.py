"""Tables 6.1 and 6.2 measured: the reports of ``topomark bench table-6.1``, ``table-6.2``, ``figure-6.13``, ``section-6.2``.

The thesis's Tables 6.1 and 6.2 (§6.2, §6.2–§6.2.2; quoted verbatim in
:data:`CLAIMS`) state, per class of markers, a marker count and an asymptotic
cost bound; its Figures 6.11–6.13, 6.17 and 6.18 are lost, only their captions
and the prose findings remain (§6.2.1, Algorithm 6.5, §6.2.2, Algorithm 6.6).  These reports put
beside each claim what the kit algorithms (:mod:`~topomark.reference.algorithms.registrations`)
measure on the bench's lattice-hole and complete-hole worlds
(:mod:`~topomark.reference.bench.plan`), and say whether it held:

* **maps** — every world mapped correctly (the checked outcome ``correct``);
* **markers** — the markers used (the sum of counts dropped, max and mean) never
  above the thesis's stated count for that n and m, and never above the bound the
  registry checks after every drop (the two differ where the thesis is
  corrected: Case 3a's Σ^{n}, Case 4's ⌊(n−1)/2⌋, extension's ceilings);
* **cost** — an asymptotic bound cannot be checked on finite worlds; ours is the
  test "cost grows no faster than the bound's function f": the least-squares
  slope of log(mean cost) against log(mean f) over the sizes is ≤ 1.1
  (:data:`SLOPE_TOLERANCE`), where f is m, mn, m·d_max or m²n.  The O(mn)
  algorithms report cost/(mn), the O(m) ones cost/m.

Every cost is every edge traversal, drop trips (walks made only to drop
markers, purpose ``drop``) included; they are also shown in their own column,
and the findings compare costs without them (the accounting rule and why:
:mod:`topomark.reference.run.simulator`).  The O(m) algorithms (Case 3b,
Σ k directional V-markers, extension-1/2) get the breakdown of cost/m — new
edges (exactly m), drop trips, travel between frontier edges — and every
lattice-hole world above 3m is listed.  The figures' findings and plots are
:mod:`~topomark.reference.bench.reports.section62_figures`'s.

Examples
--------
>>> CLAIMS["case-3b"].cost, CLAIMS["case-3b"].stated(5, 7)
('m', 10)
>>> slope([(10, 100), (20, 200), (40, 400)])
1.0
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, cast

from topomark.reference.bench.plan import EXPERIMENTS, FAMILIES
from topomark.reference.bench.reports import section62_case5 as case5
from topomark.reference.bench.reports import section62_figures as figures
from topomark.reference.bench.reports.kit import Body, write
from topomark.reference.bench.reports.plots import Draw
from topomark.reference.bench.reports.section62_figures import EDGEINFO
from topomark.reference.bench.reports.stats import (SLOPE_TOLERANCE, cost_f, cost_per_m, drop_trips, finished, groups,
                                                    mean, measured, net_cost, num, sd, slope)
from topomark.reference.bench.reports.text import fmt_pm, yes
from topomark.reference.explorers.counted_markers import sum_to

__all__ = ["CLAIMS", "REPORTS", "Claim", "write_report", "correct", "O_M", "GROUP"]

O_M = ("case-3b", "case-dv-sum", "extension-1", "extension-2")


@dataclass(frozen=True)
class Claim:
    """One algorithm's row of Table 6.1 / 6.2: the row verbatim, its cost bound, the marker count it states."""

    table: str
    row: str  # the thesis's row, verbatim (Table 6.1 / Table 6.2)
    cost: str | None  # "m", "mn", "m·d_max", "m²n"; None: no bound (Case 0 fails)
    stated_text: str
    stated: Callable[[int, int], int] | None  # the thesis's count for (n, m); None: not a count (Case 5)
    checked_text: str  # the bound the registry checks after every drop


T61 = "| {} | {} | {} | {} |"
CLAIMS: dict[str, Claim] = {
    "case-1a": Claim("6.1", T61.format("(m)", "edge (E-marker)", "none", "O(mn)"), "mn", "m",
                     lambda n, m: m, "m"),
    "case-1b": Claim("6.1", T61.format("(m)", "vertex + edge (V-E-marker)", "none", "O(mn)"), "mn",
                     "m + 1 (§6.2.1 Case 1b; m with the extension, §6.2.1 Case 1b)", lambda n, m: m + 1, "m + 1"),
    "case-2": Claim("6.1", T61.format("m + n", "edge (E-marker)", "none", "O(mn)"), "mn", "m + n",
                    lambda n, m: m + n, "m + n − 1 (§6.2.1 Case 2)"),
    "case-3a": Claim("6.1", T61.format("Σ_{k=1}^{n−1} k", "vertex (V-marker)", "none", "O(m·d_max)"), "m·d_max",
                     "Σ_{k=1}^{n−1} k", lambda n, m: sum_to(n - 1), "Σ_{k=1}^{n} k (§6.2.1 Case 3b, Figure 6.6)"),
    "case-3b": Claim("6.1", T61.format("(Σ_{k=1}^{n−1} k)", "edge (E-marker)", "none", "O(m)"), "m",
                     "Σ_{k=1}^{n−1} k", lambda n, m: sum_to(n - 1), "Σ_{k=1}^{n−1} k"),
    "case-4": Claim("6.1", T61.format("m − ⌊n/2⌋", "edge (E-marker)", "closest-first", "O(mn)"), "mn",
                    "m − ⌊n/2⌋", lambda n, m: m - n // 2, "m − ⌊(n−1)/2⌋ (§6.2.1 Case 4 corrected)"),
    "case-4-mn": Claim("6.1", T61.format("m", "edge (E-marker)", "closest-first", "O(mn)"), "mn", "m",
                       lambda n, m: m, "m + [n even] (§6.2.1 Case 4 corrected)"),
    "case-5-v1": Claim("6.1", T61.format("unknown k > 3", "vertex, edge, or vertex+edge", "none", "O(m²n)"), "m²n",
                       "k > 3, not known relative to the world", None, "Σ_{k=1}^{n} k (K given: any)"),
    "case-5-v2": Claim("6.1", T61.format("unknown k > 3", "vertex, edge, or vertex+edge", "none", "O(m²n)"), "m²n",
                       "k > 3, not known relative to the world", None, "m + 4"),
    "case-5-edge": Claim("6.1", T61.format("unknown k > 3", "vertex, edge, or vertex+edge", "none", "O(m²n)"),
                         "m²n", "k > 3, not known relative to the world", None, "Σ_{k=1}^{n−1} k (K given: any)"),
    "case-0": Claim("6.1", "Case 0 (not a row): \"this approach does not work in general\"", None,
                    "n", lambda n, m: n, "n"),
    "case-dv-sum": Claim("6.2", "| Σ_{k=1}^{n−1} k | vertex (V-marker) | none | O(m·d_max) | O(m) |", "m",
                         "Σ_{k=1}^{n−1} k", lambda n, m: sum_to(n - 1), "Σ_{k=1}^{n} k"),
    "extension-1": Claim("6.2", "| Σ_{k=1}^{⌊m/2⌋} k | edge (E-marker) | closest-first | O(mn)* | O(m) |", "m",
                         "Σ_{k=1}^{⌊m/2⌋} k (table; text ⌈m/2⌉, §6.2.2)", lambda n, m: sum_to(m // 2),
                         "Σ_{k=1}^{⌈m/2⌉} k"),
    "extension-2": Claim("6.2", "| Σ_{k=1}^{⌊(n−1)/2⌋} k | edge (E-marker) | closest-first + 'back to v_k' | O(mn)* "
                                "| O(m) |", "m", "Σ_{k=1}^{⌊(n−1)/2⌋} k (table; text ⌈(n−1)/2⌉, §6.2.2)",
                         lambda n, m: sum_to((n - 1) // 2), "Σ_{k=1}^{⌈(n−1)/2⌉} k"),
}
CLAIMS.update({
    "case-1b-edgeinfo": Claim("6.2", "| (m) | vertex + edge (V-E-marker) | none | O(mn) | O(mn) |", "mn",
                              "m + 1 (§6.2.1 Case 1b; m with the extension, §6.2.1 Case 1b)", lambda n, m: m + 1, "m + 1"),
    "case-2-edgeinfo": Claim("6.2", "| m + n | edge (E-marker) | none | O(mn) | O(mn) |", "mn", "m + n",
                             lambda n, m: m + n, "m + n − 1 (§6.2.1 Case 2)"),
    "case-1a-edgeinfo": Claim("6.2", "| (m) | edge (E-marker) | none | O(mn) | O(mn) |", "mn", "m",
                              lambda n, m: m, "m"),
    "case-4-edgeinfo": Claim("6.2", "| m − ⌊n/2⌋ | edge (E-marker) | closest-first | O(mn) | O(mn) |", "mn",
                             "m − ⌊n/2⌋", lambda n, m: m - n // 2, "m − ⌊(n−1)/2⌋ (§6.2.1 Case 4 corrected)"),
    "case-4-mn-edgeinfo": Claim("6.2", "| m | edge (E-marker) | closest-first | O(mn) | O(mn) |", "mn", "m",
                                lambda n, m: m, "m + [n even] (§6.2.1 Case 4 corrected)"),
    "case-5-directional": Claim("6.2", "| unknown k > 3 | vertex or edge or vertex+edge | none | O(m²n) | O(m²n) |",
                                "m²n", "k > 3, not known relative to the world", None, "Σ_{k=1}^{n} k (K given: any)"),
})
CLAIMS.update({f"{name}-listing": CLAIMS[name] for name in ("case-dv-sum", "extension-2")})
"""The listings as written (``docs/bounds.md``) are measured beside topomark's entries against the same row of Table
6.2: the thesis states one row for each algorithm, listing and all."""
CLAIMS_62_UNDIRECTED = {"case-3b": "| (Σ_{k=1}^{n−1} k) | edge (E-marker) | none | O(m) | O(m) |"}
REPORTS = ("table-6.1", "table-6.2", "figure-6.13", "section-6.2")
GROUP = ("family", "algorithm", "options", "size")
"""The runs are grouped by (family, algorithm, option set, size): the finished runs that mapped their world
correctly (``g``: costs and means are over these) and every finished run (``tried``)."""


def correct(r: dict) -> bool:
    """The run mapped its world correctly (a row without the outcome column: verified)."""
    return r.get("outcome") == "correct" or (not r.get("outcome") and str(r.get("verified")) == "True")


def write_report(experiment: str, out: Path, wall: float | None = None, plots: bool = True) -> Path:
    """``out/EXPERIMENT.md`` (and plots) from ``out/runs.csv``; ``section-6.2`` writes the three reports."""
    if experiment == "section-6.2":
        for name in REPORTS[:3]:
            write_report(name, out, None, plots)
    return write(experiment, out, wall, plots,
                 " (thesis §3.1.2), drop trips included; drop trips = the traversals made only to drop markers "
                 "(Case 3b; extension-2, Algorithm 6.6 line 10), shown apart; "
                 "markers used = the markers the robot dropped (the sum of the counts "
                 "of the simulator's drops). Every algorithm of a size explores the same worlds from the same "
                 "start. The thesis's Figures 6.11–6.13, 6.17, 6.18 are lost: only their captions "
                 "and the prose findings are quoted.", _body(experiment, out), plot_line=experiment != "section-6.2")


def _body(experiment: str, out: Path) -> Body:
    exp = EXPERIMENTS[experiment]

    def body(rows: list[dict]) -> tuple[list[str], Draw | None]:
        g, tried = groups(rows, GROUP, keep=lambda r: finished(r) and correct(r)), groups(rows, GROUP)
        if experiment == "section-6.2":
            return ["The reports: `table-6.1.md`, `table-6.2.md`, `figure-6.13.md` (written beside this one).", ""] \
                + marker_classes(g, tried), None
        if experiment == "figure-6.13":
            lines = figures.figure_613(exp, g) + case5.figure_613_v2(g, figures.FAMILIES6)
        else:
            table = experiment.split("-")[1]
            algs = [a for a in exp.parts[0].algorithms]
            lines = thesis_rows(table, algs) + claims_table(exp, g, tried, algs) + size_tables(exp, g, tried, algs)
            lines += case5.phase_two_shares(g, tried, algs)
            lines += om_breakdown(exp, g, [a for a in algs if a in O_M])
            lines += figures.findings(experiment, exp, g)
        return lines, lambda plt: figures.plots(plt, experiment, g, out)
    return body


def thesis_rows(table: str, algs: list[str]) -> list[str]:
    """The thesis's rows of Table 6.x for these algorithms, verbatim (Table 6.1; 6.2, Table 6.2)."""
    if table == "6.1":
        head = ["| algorithm | Number | Drop Place | Constraints | Upper bounds (edge traversals) |", "|---|---|---|---|---|"]
    else:
        head = ["| algorithm | Number | Drop Place | Constraints | undirected | directional |", "|---|---|---|---|---|---|"]
    body = []
    for a in algs:
        row = CLAIMS_62_UNDIRECTED.get(a) if table == "6.2" and a in CLAIMS_62_UNDIRECTED else CLAIMS[a].row
        row = cast(str, row)  # every measured algorithm has its thesis row
        body.append(f"| `{a}` {row}" if row.startswith("|") else f"| `{a}` | {row} |" + " |" * (3 if table == "6.1" else 4))
    lines = [f"## Table 6.{table[-1]}: the thesis's rows (verbatim) and the algorithm measuring each", ""] + head + body
    if table == "6.2":
        lines += ["", "`case-3b` (undirected, Table 6.1) is run as the original the extensions save markers from; "
                  + ", ".join(f"`{o}`" for o in EDGEINFO.values()) + " as the originals of their edgeINFO variants. "
                  "Table 6.2's rows 1–3 (one, two, three markers) are "
                  "Algorithm 3.1 with a lighthouse: `topomark bench lighthouses`."]
    else:
        lines += ["", "Table 6.1's rows 1–3 (one marker: N/A; 2 V-E and 3 markers: O(m²n)) are Algorithm 3.1 with "
                  "the `vertex-and-edge` and `three-undirected-edge` lighthouses: `topomark bench lighthouses`."]
    return lines + [""]


def _families(exp) -> list[str]:
    """The experiment's world families, each once (a family may have several parts: Case 5's K rows)."""
    return list(dict.fromkeys(part.family for part in exp.parts))


def _family_algs(exp, g: dict, algs: list[str]):
    for family in _families(exp):
        for a in algs:
            sizes = sorted(k[3] for k in g if k[0] == family and k[1] == a and k[2] == "")
            if sizes:
                yield family, a, sizes


def claim_verdicts(family: str, alg: str, g: dict, tried: dict, sizes: list[int]) -> dict:
    """Over every world of (world family, alg) with default options: maps, markers vs stated and checked (every run);
    the cost slope (over the sizes' correct runs)."""
    rs = [r for s in sizes for r in tried[(family, alg, "", s)]]
    c = CLAIMS[alg]
    used = [num(r, "markers_used") for r in rs]
    over_stated = [r for r in rs if c.stated and num(r, "markers_used") > c.stated(int(r["n"]), int(r["m"]))]
    over_checked = [r for r in rs if r.get("marker_bound") not in ("", None) and
                    num(r, "markers_used") > num(r, "marker_bound")]
    f = [(mean(g[(family, alg, "", s)], lambda r: cost_f(cast(str, c.cost), r)), mean(g[(family, alg, "", s)], "cost"))
         for s in sizes if g.get((family, alg, "", s))] if c.cost else []
    sl = slope(f) if f else None
    over_exact = [r for r in rs if r.get("upper_bound") not in ("", None) and num(r, "cost") > num(r, "upper_bound")]
    ok = [r for s in sizes for r in g.get((family, alg, "", s), ())]
    ratio_f = max((num(r, "cost") / cost_f(c.cost, r) for r in ok), default=None) if c.cost else None
    return {"worlds": len(rs), "correct": sum(correct(r) for r in rs),
            "used_max": max(used), "used_mean": statistics.fmean(used),
            "ratio_max": max(num(r, "markers_used") / c.stated(int(r["n"]), int(r["m"])) for r in rs) if c.stated else None,
            "over_stated": over_stated, "over_checked": over_checked, "slope": sl, "over_exact": over_exact,
            "exact": any(r.get("upper_bound") not in ("", None) for r in rs), "ratio_f": ratio_f}


def claims_table(exp, g: dict, tried: dict, algs: list[str]) -> list[str]:
    lines = ["## The claims, and whether they held", "",
             "Markers: used ÷ the thesis's stated count for the world's n and m (max over worlds); checked bound = "
             "the formula the checker enforces after every drop. Cost: slope of log(mean cost) against log(f) over "
             f"the sizes (held if ≤ {SLOPE_TOLERANCE}: the cost grows no faster than the bound's f; with few worlds per "
             "size a world-to-world spread can tip it — compare max cost/f).", "",
             "| family | algorithm | thesis cost | worlds | mapped correctly | markers used max / mean | thesis count "
             "(used ÷ count, max) | ≤ thesis count? | checked bound | ≤ checked? | max cost/f | cost slope vs f | cost held? |",
             "|---|---|---|---:|---:|---:|---|---|---|---|---:|---:|---|"]
    for fam, a, sizes in _family_algs(exp, tried, algs):
        v, c = claim_verdicts(fam, a, g, tried, sizes), CLAIMS[a]
        ratio = f" ({v['ratio_max']:.3f})" if v["ratio_max"] is not None else ""
        stated_ok = ("—" if c.stated is None else yes(not v["over_stated"]) +
                     (f" ({len(v['over_stated'])} worlds over)" if v["over_stated"] else ""))
        cost_ok = ("—" if v["slope"] is None else yes(v["slope"] <= SLOPE_TOLERANCE))
        if v["exact"]:
            cost_ok += f"; ≤ our exact bound on every world: {yes(not v['over_exact'])}"
        lines.append(f"| {fam} | `{a}` | {('O(' + c.cost + ')') if c.cost else 'fails (§6.2.1 Case 0)'} | {v['worlds']} | "
                     f"{v['correct']}/{v['worlds']} | {v['used_max']:,.0f} / {v['used_mean']:,.1f} | {c.stated_text}"
                     f"{ratio} | {stated_ok} | {c.checked_text} | {yes(not v['over_checked'])} | "
                     f"{'—' if v['ratio_f'] is None else format(v['ratio_f'], '.4g')} | "
                     f"{'—' if v['slope'] is None else v['slope']} | {cost_ok} |")
    return lines + ["", "Case 5's count is not a claim (the robot is given any K > 3); these rows run with the default "
                    "K that lets phase I mark every place, and the rows with K = 4, 6, 10 below show phase II at work "
                    "(`figure-6.13` varies K too). Case 0 is expected to stop with "
                    "`failed` on worlds where several unexplored edges fit a marked place (\"the robot cannot "
                    "determine\" which, §6.2.1 Case 0; the certified pairs in `tests/test_markers_case5.py` show that no "
                    "pick could be right).", ""]


def size_tables(exp, g: dict, tried: dict, algs: list[str]) -> list[str]:
    """Per family and size: worlds and correct maps (every run); markers, cost, cost/m, cost/f (correct runs)."""
    lines = []
    for family in _families(exp):
        keys = [k for k in tried if k[0] == family and k[1] in algs and k[2] == ""]
        if not keys:
            continue
        lines += [f"## {family} ({FAMILIES[family].figure} worlds): per size", "",
                  "| size | algorithm | worlds | correct | n | m | markers used mean (max) | thesis count (mean) | "
                  "cost mean ± sd | cost/m | drop trips mean | cost/m without drop trips | cost/f |",
                  "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for size in sorted({k[3] for k in keys}):
            for a in algs:
                rs, every = g.get((family, a, "", size)), tried.get((family, a, "", size))
                if not every:
                    continue
                if not rs:
                    lines.append(f"| {size} | `{a}` | {len(every)} | 0 |" + " — |" * 9)
                    continue
                c = CLAIMS[a]
                bound = cast(Callable[[int, int], float], c.stated)  # read only where there is one
                stated = f"{mean(rs, lambda r: bound(int(r['n']), int(r['m']))):,.1f}" if c.stated else "—"
                f = f"{mean(rs, lambda r: num(r, 'cost') / cost_f(cast(str, c.cost), r)):.4g} (f = {c.cost})" \
                    if c.cost else "—"
                lines.append(f"| {size} | `{a}` | {len(every)} | {len(rs)} | "
                             f"{mean(rs, 'n'):.0f} | {mean(rs, 'm'):.1f} | "
                             f"{mean(rs, 'markers_used'):,.1f} "
                             f"({max(num(r, 'markers_used') for r in rs):,.0f}) | {stated} | "
                             f"{fmt_pm(mean(rs, 'cost'), sd(rs, 'cost'))} | "
                             f"{mean(rs, cost_per_m):.2f} | {trips_text(rs)} | "
                             f"{per_m_text(mean(rs, lambda r: net_cost(r) / num(r, 'm')))} | {f} |")
        lines.append("")
    return lines


def om_breakdown(exp, g: dict, algs: list[str]) -> list[str]:
    """cost/m of the O(m) algorithms and what it is made of; every lattice-hole world above 3m, named."""
    if not algs:
        return []
    lines = ["## The O(m) algorithms against the lower bound m: what cost/m is made of", "",
             "new = the m new edges (1 per edge); drop trips = walks made only to drop markers (Algorithm 6.6 "
             "line 10: back on e to drop markers and back; Case 3b's walk back to drop i markers on e); "
             "travel = walking S between frontier edges; probes = validation + retrace. Means per m over the worlds "
             "of the size; cost/m includes the drop trips.", "",
             "| family | algorithm | size | worlds | cost/m mean | cost/m max | new/m | drop trips/m | "
             "cost/m without drop trips | travel/m | probes/m | worlds > 3m |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    over = []
    for fam, a, sizes in _family_algs(exp, g, algs):
        for s in sizes:
            rs = g[(fam, a, "", s)]
            def per(col, rs=rs):  # a column (by name) or a function of the row, per m, mean over the worlds
                return mean(rs, lambda r: (num(r, col) if isinstance(col, str) else col(r)) / num(r, "m"))
            big = [r for r in rs if num(r, "cost") > 3 * num(r, "m")]
            over += [(fam, a, r) for r in big]
            lines.append(f"| {fam} | `{a}` | {s} | {len(rs)} | {per('cost'):.3f} | "
                         f"{max(cost_per_m(r) for r in rs):.3f} | {per('new'):.2f} | "
                         f"{per_m_text(per(drop_trips))} | {per_m_text(per(net_cost))} | {per('travel'):.2f} | "
                         f"{mean(rs, lambda r: (num(r, 'validation') + num(r, 'retrace')) / num(r, 'm')):.2f} | "
                         f"{len(big)} |")
    lattice = [o for o in over if o[0] == "lattice-hole"]
    lines += ["", f"Lattice-hole worlds above 3m (the target: none at the Chapter 4 sizes): "
              f"**{len(lattice)}**" + ("." if not lattice else ":"), ""]
    for fam, a, r in over:
        parts = {c: num(r, c) / num(r, "m") for c in ("drop_trips", "other", "travel", "validation", "retrace")}
        worst = max(parts, key=lambda c: parts[c])
        lines.append(f"* {fam} size {r['size']} seed {r['seed']} `{a}`: n = {r['n']}, m = {r['m']}, cost/m = "
                     f"{cost_per_m(r):.3f}; the excess over the m new edges is mostly `{worst}` "
                     f"({parts[worst]:.2f} m).")
    return lines + [""]


def trips_text(rs: list[dict]) -> str:
    """The mean drop trips of the runs, or "not measured" (a runs file written before the column)."""
    value = mean(rs, drop_trips)
    return f"{value:,.1f}" if measured(value) else "not measured"


def per_m_text(value: float) -> str:
    """A per-m mean to two places, or "—" where drop trips were not measured."""
    return f"{value:.2f}" if measured(value) else "—"


def runs_by_outcome(rows: list[dict]) -> str:
    """``"3 runs: 2 failed, 1 wrong-map"``: how many runs, and how many ended in each outcome."""
    outs = [r.get("outcome") or "unrecorded" for r in rows]
    return f"{len(rows)} runs: " + ", ".join(f"{outs.count(o)} {o}" for o in sorted(set(outs)))


def marker_classes(g: dict, tried: dict) -> list[str]:
    """Every marker class of Tables 6.1/6.2 with topomark's command, mean cost and markers at the largest sizes."""
    lines = ["## Every marker class of Tables 6.1 and 6.2: topomark's command, measured cost and markers", "",
             "Mean cost (cost/m; mean drop trips, part of the cost) and mean markers used at the largest size run "
             "of each family.", "",
             "| marker class (thesis) | command | lattice-hole: size, cost (cost/m), markers | "
             "complete-hole: size, cost (cost/m), markers |", "|---|---|---|---|"]
    for a, c in CLAIMS.items():
        cells = []
        for fam in ("lattice-hole", "complete-hole"):
            sizes = [k[3] for k in g if k[0] == fam and k[1] == a and k[2] == ""]
            every = [r for k, rs in tried.items() if k[0] == fam and k[1] == a and k[2] == "" for r in rs]
            if not sizes:
                cells.append(f"no world mapped correctly ({runs_by_outcome(every)})" if every else "—")
                continue
            rs = g[(fam, a, "", max(sizes))]
            cells.append(f"{max(sizes)}: {mean(rs, 'cost'):,.0f} "
                         f"({mean(rs, cost_per_m):.2f}; drop trips {trips_text(rs)}), "
                         f"{mean(rs, 'markers_used'):,.0f}")
        lines.append(f"| Table {c.table}: {' · '.join(x.strip() for x in c.row.strip('|').split('|'))} | "
                     f"`topomark explore WORLD --algorithm {a}` | "
                     + " | ".join(cells) + " |")
    return lines + ["", "Rows 1–3 of the tables (one, two, three markers) are Algorithm 3.1 with a lighthouse: "
                    "`topomark explore WORLD --lighthouse vertex-and-edge` / `three-undirected-edge`, measured by "
                    "`topomark bench lighthouses`.", ""]
