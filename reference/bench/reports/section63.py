"""Table 6.3, Figure 6.24 and the comparison the thesis never prints: ``topomark bench table-6.3``, ``figure-6.24``,
``comparison``, ``section-6.3`` (thesis §6.3, §6.3–§6.4; §2.3.1).

The thesis's Table 6.3 ("Solvability and cost bounds of different threads", quoted verbatim in
:data:`TABLE_63`) states an upper cost bound per thread class; its Figures 6.23 and 6.24 are lost, only their
captions and the prose findings remain (§6.3.3, §6.4).  These reports put beside each statement what the thread
algorithms measure on the bench's worlds, and say whether it held:

* **table-6.3** — every thread class (:data:`CLASSES`: the fixed l = ε thread is Algorithm 3.1 with the ``thread``
  lighthouse; l = ε carried, l = c(G), l ≫ m with knots and, for l < c(G), explore-explore with l = 8) on
  homogeneous lattices (Figure 6.23(a)) and lattices with 10% of the *edges* removed (Figure 6.23(b),
  world family ``lattice-edge-hole``).  Against its bound: cost/f with f = m²n, mn or m, and the test "cost grows no
  faster than f" (the least-squares slope of log mean cost against log mean f over the sizes ≤ 1.1, as for Tables
  6.1/6.2, :mod:`~topomark.reference.bench.reports.section62`).  The three findings of Figure 6.23 are checked size by size;
  l ≫ m with knots must stay under 3m on every world (each world above it is listed).
* **figure-6.24** — Algorithm 6.8 (explore-explore) on the 20×20 lattices with 10% of the edges removed, l = 1,
  2, 4, …, 512 (the first power of two ≥ n = 400); "the longer the thread, the lower the cost" and "when l ≥ c(G)
  it acts as the l = c(G) algorithm" are checked (the latter world by world against Algorithm 6.7's cost).
* **comparison** — Dudek et al.'s movable marker (undirected and directional), Algorithm 3.1 and its best
  enhancement (enh3), §6.2's O(m) markers (Case 3b, Σ k directional V-markers, extension-2) and two threads on the
  same lattice-hole worlds (10% of the *vertices* removed, the Chapter 3/§6.2 world family): cost and cost/m per size, and
  where a single movable marker beats the single immovable one of Algorithm 3.1 and by how much.

Sizes (the thesis gives none for Figure 6.23): 90, 202 and 360 — the 10×10, 15×15 and 20×20 grids (a size labels
the grid as in the ``lattice`` world family); Figure 6.24 is size 360.  The experiments and the
``lattice-edge-hole`` world family are registered by :mod:`~topomark.reference.bench.plan_threads` (imported here; its examples show the classes
and lengths).
"""

from __future__ import annotations

import statistics
from pathlib import Path

from topomark.reference.bench.plan import NO_LIGHTHOUSE
from topomark.reference.bench.plan_threads import (CLASSES, COMPARED, EDGE_HOLE, FIGURE_624_SIZE, IMMOVABLE, LENGTHS, MOVABLE,
                          REPORTS, SIZES, ThreadClass)
from topomark.reference.bench.reports.kit import Body, write
from topomark.reference.bench.reports.plots import Draw, errorbars, finish, new
from topomark.reference.bench.reports.stats import (SLOPE_TOLERANCE, cost_f, cost_per_m, groups, mean, mean_sd, num,
                                                    slope, spearman)
from topomark.reference.bench.reports.text import fmt_pm, yes

__all__ = ["CLASSES", "ThreadClass", "TABLE_63", "LENGTHS", "SIZES", "COMPARED", "REPORTS", "write_report", "GROUP"]

TABLE_63 = """| Length of thread | Need for retying | Upper bounds |
|---|---|---|
| a very short thread l = ε | no | O(m²n) |
| (l = ε) | yes | O(mn) |
| an arbitrary length thread l < c(G) | yes | O(mn) |
| a long thread l = c(G) | no | O(mn) |
| a very long thread l ≫ m | no | O(m) |"""
SUMMARY_64 = ("\"Given the simplest form of thread, deterministic mapping is possible with cost O(m²n). The minimum "
              "cost for mapping is O(m) and this can be obtained with a sufficiently long thread. Overall the longer "
              "the thread the lower the cost.\" (§6.4)")




GROUP = ("family", "algorithm", "lighthouse", "options", "size")
"""The runs are grouped by (family, algorithm, lighthouse, option set, size): the finished runs, every outcome."""


def _correct(r: dict) -> bool:
    return r.get("outcome") == "correct" and str(r.get("verified")) == "True"


def _stats(rs: list[dict], bound: str | None = None) -> dict | None:
    ok = [r for r in rs if _correct(r)]
    if not ok:
        return None
    cost, cost_sd = mean_sd([num(r, "cost") for r in ok])
    out = {"runs": len(rs), "ok": len(ok), "mean": cost, "sd": cost_sd, "n": mean(ok, "n"), "m": mean(ok, "m"),
           "per_m": mean(ok, cost_per_m),
           "per_mn": mean(ok, lambda r: num(r, "cost") / (num(r, "m") * num(r, "n"))),
           "by_seed": {int(r["seed"]): num(r, "cost") for r in ok}}
    if bound:
        out["per_f"] = mean(ok, lambda r: num(r, "cost") / cost_f(bound, r))
        out["f"] = mean(ok, lambda r: cost_f(bound, r))
    return out


def _class_stats(gr: dict, family: str, c: ThreadClass, size: int) -> dict | None:
    return _stats(gr.get((family, c.algorithm, c.lighthouse, c.options, size), []), c.bound)


# -- the reports ---------------------------------------------------------------------------------------------------
def write_report(experiment: str, out: Path, wall: float | None = None, plots: bool = True) -> Path:
    """``out/EXPERIMENT.md`` (and plots) from ``out/runs.csv``; ``section-6.3`` writes the three reports too."""
    if experiment == "section-6.3":
        for name in REPORTS[:3]:
            write_report(name, out, None, plots)
    return write(experiment, out, wall, plots,
                 " (thesis §3.1.2), rewinding and walking back along the thread included. Every algorithm of "
                 "a size explores the same worlds from the same start. The thesis's Figures 6.23 and 6.24 are "
                 "lost: only their captions and the prose findings are quoted. Means are over the "
                 "worlds mapped correctly (checked and verified); the worlds column says how many of how many.",
                 _body(experiment, out))


def _body(experiment: str, out: Path) -> Body:
    def body(rows: list[dict]) -> tuple[list[str], Draw | None]:
        if experiment == "section-6.3":  # the three reports' index; it draws no plots of its own
            return ["The reports: `table-6.3.md`, `figure-6.24.md`, `comparison.md` (written beside this one).",
                    ""], None
        build = {"table-6.3": _table63, "figure-6.24": _figure624, "comparison": _comparison}[experiment]
        lines, figures = build(groups(rows, GROUP))
        return lines, lambda plt: _plot(plt, experiment, figures, out)
    return body


def _table63(gr: dict) -> tuple[list[str], dict]:
    lines = ["## Table 6.3 (thesis, verbatim; caption \"Solvability and cost bounds of different threads.\")", "",
             TABLE_63, "", SUMMARY_64, "",
             "Ours: the fixed l = ε thread is Algorithm 3.1 (basic) with the `thread` lighthouse; l < c(G) is "
             "explore-explore (Algorithm 6.8) with l = 8; explore-merge (Algorithm 6.9) is not implemented (its merge "
             "procedure is in [59, 61], not in the thesis). cost/f is cost divided by the bound's function f "
             "(m²n, mn or m).", ""]
    figures: dict = {}
    for family, title in (("lattice", "Figure 6.23(a): homogeneous lattices"),
                          (EDGE_HOLE, "Figure 6.23(b): lattices with 10% of the edges removed")):
        lines += [f"## {title} (`{family}`)", "",
                  "| size | n | m | thread class | bound | worlds | mean cost ± sd | cost/m | cost/f |",
                  "|---:|---:|---:|---|---|---:|---:|---:|---:|"]
        stats = {(c.name, s): _class_stats(gr, family, c, s) for c in CLASSES for s in SIZES}
        for s in SIZES:
            for c in CLASSES:
                st = stats[(c.name, s)]
                if st is None:
                    continue
                lines.append(f"| {s} | {st['n']:.0f} | {st['m']:.1f} | {c.name} | O({c.bound}) | {st['ok']}/{st['runs']}"
                             f" | {fmt_pm(st['mean'], st['sd'])} | {st['per_m']:.2f} | {st['per_f']:.4g} |")
        lines += [""] + _bound_lines(stats) + _finding_lines(stats)
        figures[family] = {c.name: [(s, stats[(c.name, s)]) for s in SIZES if stats[(c.name, s)]] for c in CLASSES}
    lines += _knots_lines(gr)
    return lines, figures


def _bound_lines(stats: dict) -> list[str]:
    lines = ["Against the bound (an asymptotic bound cannot be checked on finite worlds; ours: the least-squares slope "
             f"of log mean cost against log mean f over the sizes is at most {SLOPE_TOLERANCE}):", "",
             "| thread class | Table 6.3 | slope | held |", "|---|---|---:|---|"]
    for c in CLASSES:
        pts = [(st["f"], st["mean"]) for (name, _), st in stats.items() if name == c.name and st]
        k = slope(pts)
        lines.append(f"| {c.name} | O({c.bound}) | {'' if k is None else f'{k:.2f}'} | "
                     f"{yes(None if k is None else k <= SLOPE_TOLERANCE)} |")
    return lines + [""]


def _finding_lines(stats: dict) -> list[str]:
    """Figure 6.23's three findings (§6.3.3) and §6.4's ordering, size by size."""
    def cost(name, s):  # the mean cost of a class at a size
        st = stats.get((name, s))
        return st["mean"] if st else None

    claims = (("\"carrying the short (l = ε) thread which has O(mn) cost, obtains a reduced exploration cost over "
               "exploring with a fixed short thread which has O(m²n) cost\"", lambda s: _lt(cost("carried ε", s),
                                                                                             cost("fixed ε", s))),
              ("\"Exploring with l = c(G) thread … provides a further cost reduction over exploring with short "
               "threads\"", lambda s: _lt(cost("l = c(G)", s), cost("carried ε", s), cost("fixed ε", s))),
              ("\"a very long thread (with knots) … provides the lowest cost over all the thread classes considered\"",
               lambda s: _lt(cost("l ≫ m, knots", s), *(cost(c.name, s) for c in CLASSES[:4]))),
              ("§6.4 \"the longer the thread the lower the cost\" (carried ε > l = 8 > l = c(G) > knots)",
               lambda s: _chain([cost(n, s) for n in ("carried ε", "explore-explore l=8", "l = c(G)",
                                                       "l ≫ m, knots")])))
    lines = ["The thesis's findings (Figure 6.23, §6.3.3), size by size (held: the mean costs are so ordered):",
             "", "| finding | " + " | ".join(f"size {s}" for s in SIZES) + " |", "|---|" + "---|" * len(SIZES)]
    for text, test in claims:
        lines.append(f"| {text} | " + " | ".join(yes(test(s)) for s in SIZES) + " |")
    return lines + [""]


def _lt(x, *others) -> bool | None:
    if x is None or any(o is None for o in others):
        return None
    return all(x < o for o in others)


def _chain(xs: list) -> bool | None:
    if any(x is None for x in xs):
        return None
    return all(a > b for a, b in zip(xs, xs[1:]))


def _knots_lines(gr: dict) -> list[str]:
    """l ≫ m with knots is O(m): under 3m on every world (the target this report tests); each world above it listed."""
    runs = [r for (fam, alg, _, _, _), rs in gr.items() if alg == "thread-knots" for r in rs if _correct(r)]
    if not runs:
        return []
    ratio = [cost_per_m(r) for r in runs]
    above = [r for r, x in zip(runs, ratio) if x >= 3]
    lines = ["## l ≫ m with knots under 3m", "",
             f"{len(runs)} worlds mapped by thread-knots (every family in `runs.csv`): cost/m from {min(ratio):.2f} to "
             f"{max(ratio):.2f}, mean {statistics.fmean(ratio):.2f}; worlds at or above 3m: {len(above)}"
             + (" — held." if not above else "."), ""]
    for r in above:
        lines.append(f"* {r['experiment']} size {r['size']} seed {r['seed']}: cost {r['cost']}, m {r['m']} "
                     f"({cost_per_m(r):.2f}m); new {r.get('new')}, retrace {r.get('retrace')}, "
                     f"validation {r.get('validation')}, other {r.get('other')}")
    return lines + ([""] if above else [])


def _figure624(gr: dict) -> tuple[list[str], dict]:
    s = FIGURE_624_SIZE
    by_l = {n: _stats(gr.get((EDGE_HOLE, "thread-explore", NO_LIGHTHOUSE, f"thread-length={n}", s), []))
            for n in LENGTHS}
    circ = _stats(gr.get((EDGE_HOLE, "thread-circumference", NO_LIGHTHOUSE, "", s), []))
    knots = _stats(gr.get((EDGE_HOLE, "thread-knots", NO_LIGHTHOUSE, "", s), []))
    lines = ["## Figure 6.24 (thesis: caption and text only)", "",
             "Caption: \"Performance of mapping on non-homogeneous lattice (20×20 vertices lattice with 10% edges "
             "removed) using strings of different lengths. Results are averaged over 30 graphs each has randomly "
             "removed edges. Error bars show standard deviations.\" Text: \"The algorithm demonstrates cost reduction "
             "as l increases. Note that when the thread is sufficiently long (l ≥ c(G)), fixed exploration cost is "
             "produced (the algorithm acts as the l = c(G) algorithm).\" The l values are not given; ours: powers of "
             "two up to the first l ≥ n = 400. The algorithm (not stated): explore-explore, Algorithm 6.8 (§6.3.3).", "",
             "| l | worlds | mean cost ± sd | cost/m | vs l = 1 |", "|---:|---:|---:|---:|---:|"]
    first = by_l[LENGTHS[0]]
    for n in LENGTHS:
        st = by_l[n]
        if st:
            lines.append(_l_row(str(n), st, first))
    for name, st in (("l = c(G) (Algorithm 6.7)", circ), ("l ≫ m with knots", knots)):
        if st:
            lines.append(_l_row(name, st, first))
    lines += [""] + _figure624_claims(by_l, circ)
    return lines, {"lengths": [(n, by_l[n]) for n in LENGTHS if by_l[n]], "circ": circ, "knots": knots}


def _l_row(name: str, st: dict, first: dict | None) -> str:
    rel = f"{st['mean'] / first['mean']:.2f}" if first else "—"
    return f"| {name} | {st['ok']}/{st['runs']} | {fmt_pm(st['mean'], st['sd'])} | {st['per_m']:.1f} | {rel} |"


def _figure624_claims(by_l: dict, circ: dict | None) -> list[str]:
    pts = [(n, st["mean"]) for n, st in by_l.items() if st]
    if len(pts) < 2:
        return []
    ups = [(a, b) for (a, x), (b, y) in zip(pts, pts[1:]) if y > x]
    rho = spearman([n for n, _ in pts], [c for _, c in pts])
    lines = ["Whether it held:", "",
             f"* \"cost reduction as l increases\": the mean cost at the longest l is {pts[-1][1] / pts[0][1]:.0%} of "
             f"that at l = {pts[0][0]}; Spearman's rank correlation of l and the mean cost is {rho:.2f}; the mean "
             f"rises from one l to the next {len(ups)} time(s) of {len(pts) - 1}"
             + (f" ({', '.join(f'{a}→{b}' for a, b in ups)})" if ups else "")
             + (" — held as a trend, not step by step." if ups and rho < 0 else " — held." if rho < 0 else " — **not held**.")]
    longest = by_l[LENGTHS[-1]]
    if circ and longest:
        same = [k for k, c in longest["by_seed"].items() if circ["by_seed"].get(k) == c]
        shared = [k for k in longest["by_seed"] if k in circ["by_seed"]]
        lines.append(f"* \"when l ≥ c(G) … acts as the l = c(G) algorithm\": with l = {LENGTHS[-1]} ≥ n, the cost "
                     f"equals Algorithm 6.7's on {len(same)} of {len(shared)} worlds"
                     + (" — held." if shared and len(same) == len(shared) else " — **not held** on every world."))
    return lines + [""]


def _comparison(gr: dict) -> tuple[list[str], dict]:
    stats = {(a, s): _stats(gr.get(("lattice-hole", a, _lighthouse(a), "", s), [])) for a in COMPARED for s in SIZES}
    lines = ["## Every marker on the same worlds (the comparison the thesis never prints)", "",
             "Worlds: lattice-hole (grids with 10% of the vertices removed, the family of Figure 3.10(c) and §6.2). "
             "Kits: dudek — one undirected movable vertex marker (Dudek et al. [24, 26], §2.3.1, O(mn)); "
             "dudek-directional — one directional movable marker (O(mn)); basic and enh3 — Algorithm 3.1 and its "
             "Enhancement-3 with one immovable directional vertex marker (O(m²n)); case-3b, case-dv-sum, extension-2 — "
             "§6.2's immovable markers, Σ k of them (O(m)); thread-knots and thread-circumference — §6.3's threads.", "",
             "| size | n | m | algorithm | worlds | mean cost ± sd | cost/m | cost/(mn) |",
             "|---:|---:|---:|---|---:|---:|---:|---:|"]
    for s in SIZES:
        for a in COMPARED:
            st = stats[(a, s)]
            if st:
                lines.append(f"| {s} | {st['n']:.0f} | {st['m']:.1f} | {a} | {st['ok']}/{st['runs']} | "
                             f"{fmt_pm(st['mean'], st['sd'])} | {st['per_m']:.2f} | {st['per_mn']:.4f} |")
    lines += ["", "### Where a movable marker beats an immovable one, and by how much", "",
              "Ratio of mean costs (movable / immovable; below 1: the movable marker is cheaper) and the worlds on "
              "which the movable marker's run is cheaper than the immovable one's:", "",
              "| size | movable | immovable | cost ratio | worlds cheaper |", "|---:|---|---|---:|---:|"]
    for s in SIZES:
        for mv in MOVABLE:
            for im in IMMOVABLE:
                smv, sim = stats[(mv, s)], stats[(im, s)]
                if smv and sim:
                    shared = [k for k in smv["by_seed"] if k in sim["by_seed"]]
                    wins = sum(smv["by_seed"][k] < sim["by_seed"][k] for k in shared)
                    lines.append(f"| {s} | {mv} | {im} | {smv['mean'] / sim['mean']:.2f} | {wins}/{len(shared)} |")
    return lines + [""], {"lattice-hole": {a: [(s, stats[(a, s)]) for s in SIZES if stats[(a, s)]] for a in COMPARED}}


def _lighthouse(algorithm: str) -> str:
    return "directional-vertex" if algorithm in IMMOVABLE else NO_LIGHTHOUSE


def _plot(plt, experiment: str, figures: dict, out: Path) -> list[Path]:
    """Log-scale cost plots with sd error bars."""
    if experiment == "figure-6.24":
        panels = {"cost-vs-l": {"explore-explore": figures["lengths"]}}
    else:
        panels = figures
    made = []
    for name, series in panels.items():
        if not any(series.values()):
            continue
        fig, ax = new(plt)
        for label, pts in series.items():
            if pts:
                errorbars(ax, [x for x, _ in pts], [st["mean"] for _, st in pts], [st["sd"] for _, st in pts], label)
        if experiment == "figure-6.24":
            for key, style in (("circ", "--"), ("knots", ":")):
                if figures[key]:
                    ax.axhline(figures[key]["mean"], linestyle=style, color="grey",
                               label="l = c(G) (Algorithm 6.7)" if key == "circ" else "l ≫ m, knots")
            ax.set_xscale("log", base=2)
            xlabel = "thread length l (edges)"
        else:
            xlabel = "size (grid label; n of the world in the tables)"
        made.append(finish(plt, fig, ax, out / f"{experiment}-{name}.png", f"{experiment}: {name}", xlabel,
                           "cost (edge traversals)"))
    return made
