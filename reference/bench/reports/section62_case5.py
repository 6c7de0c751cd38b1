"""§6.2.1 Case 5 measured where phase II does the work: the ``table-6.1`` / ``table-6.2`` rows run with K = 4, 6, 10
markers, and Figure 6.13 for Version-2 (thesis §6.2.1 Case 5,
Algorithms 6.4 and 6.5, and the evaluation that closes §6.2.1; Tables 6.1, 6.2).

With the default kits every Case 5 version marks every place (phase I runs to
the end), so its "unknown k > 3, O(m²n)" row would say nothing of phase II.
The bench therefore also runs each version with K = 4, 6 and 10
(:data:`~topomark.reference.bench.plan.CASE_5_K`; 4 is the least, "k > 3",
§6.2.1 Case 5), and :func:`phase_two_shares` reports, per world family, algorithm, K and
size: the worlds mapped correctly (checked), the mean cost, the mean traversals
phase II made testing its hypotheses (the walks and their retraces, column
``phase_two``) and their share of the cost.  The share is the mean over the
worlds of phase-II traversals ÷ cost; the travel to v_k and the new edge of a
phase-II iteration are not counted in it (every version pays them).

:func:`figure_613_v2` is Figure 6.13 for Version-2 ("Similar results were
observed when we run version-2 ... with different fractions of (homogeneously)
marked vertices", §6.2.1): its cost per fraction beside the single directional
marker algorithm (``basic``) and the m V-E-marker algorithm (``case-1b``), the
upper and lower bounds the thesis names.

Examples
--------
>>> share([{"cost": "10", "phase_two": "4"}, {"cost": "20", "phase_two": "2"}])
0.25
"""

from __future__ import annotations

import math

from topomark.reference.bench.plan import CASE_5_K, FRACTIONS
from topomark.reference.bench.reports.section62_figures import fraction_table, means
from topomark.reference.bench.reports.stats import mean, num
from topomark.reference.bench.reports.text import yes

__all__ = ["phase_two_shares", "figure_613_v2", "share", "CASE_5"]

CASE_5 = ("case-5-v1", "case-5-v2", "case-5-edge", "case-5-directional")


def share(rs: list[dict]) -> float:
    """The mean over the runs of phase II's traversals ÷ cost."""
    return mean(rs, lambda r: num(r, "phase_two") / num(r, "cost") if num(r, "cost") else 0.0)


def phase_two_shares(g: dict, tried: dict, algs: list[str]) -> list[str]:
    """Case 5 with K = 4, 6, 10: correct maps and the share of the cost phase II accounts for."""
    keys = sorted((k for k in tried if k[1] in CASE_5 and k[1] in algs and k[2] in CASE_5_K),
                  key=lambda k: (k[0], k[1], int(k[2].partition("=")[2]), k[3]))
    if not keys:
        return []
    lines = ["## Case 5 with few markers: phase II's share of the cost", "",
             "K = 4, 6, 10 markers (`--markers K`; 4 is the least, \"k > 3\", §6.2.1 Case 5): phase I runs out and phase II "
             "(Algorithm 3.1's hypotheses, Algorithm 6.4 lines 16–35, Algorithm 6.5 lines 14–37) maps the rest. "
             "Phase II = the traversals made testing its hypotheses (walks and retraces); share = mean over the "
             "worlds of phase II ÷ cost.", "",
             "| family | algorithm | K | size | worlds | mapped correctly | cost mean | phase II mean | phase II share "
             "| hypotheses mean |", "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    every_ok = every_share = True
    for k in keys:
        rs, every = g.get(k, []), tried[k]
        every_ok &= len(rs) == len(every)
        if not rs:
            lines.append(f"| {k[0]} | `{k[1]}` | {k[2].partition('=')[2]} | {k[3]} | {len(every)} | 0 |" + " — |" * 4)
            continue
        every_share &= all(num(r, "phase_two") > 0 for r in rs if int(num(r, "n")) > int(k[2].partition("=")[2]))
        lines.append(f"| {k[0]} | `{k[1]}` | {k[2].partition('=')[2]} | {k[3]} | {len(every)} | {len(rs)}/{len(every)} "
                     f"| {mean(rs, 'cost'):,.0f} | {mean(rs, 'phase_two'):,.0f} | {share(rs):.1%} "
                     f"| {mean(rs, 'hypotheses'):,.1f} |")
    return lines + ["", f"Every world mapped correctly: **{yes(every_ok)}**; phase II tested hypotheses on every "
                    f"world larger than K: **{yes(every_share)}**.", ""]


def figure_613_v2(g: dict, families: tuple[str, ...]) -> list[str]:
    """Version-2's mean cost per fraction of marked places, between ``basic`` and ``case-1b``."""
    lines = ["Version-2 (Algorithm 6.5): `marked-fraction=f` gives K = max(4, ⌊f·n⌋ + 3) (two markers at v0, two "
             "on e0, one per other place; loop edges draw from the same pool, so at most ⌊f·n⌋ places are marked) "
             "and 100% the default m + 4 (every place and loop edge marked). Markers used in brackets.", ""]
    for fam in families:
        fr = {f: means(g, fam, "case-5-v2", "cost", f"marked-fraction={f}") for f in FRACTIONS}
        used = {f: means(g, fam, "case-5-v2", "markers_used", f"marked-fraction={f}") for f in FRACTIONS}
        basic, v1b = means(g, fam, "basic", "cost", ""), means(g, fam, "case-1b", "cost", "")
        sizes = sorted(s for s in fr["0"] if s in basic and s in v1b)
        if not sizes:
            continue
        lines += fraction_table(f"## Figure 6.13 for Version-2 ({fam}): mean cost per fraction of marked places",
                                sizes, basic, lambda f, s: f"{fr[f][s]:,.0f} [{used[f][s]:,.0f}]" if s in fr[f] else "—",
                                v1b, "case-1b (m V-E-markers)")
        mono = [all(fr[a][s] >= fr[b][s] for a, b in zip(FRACTIONS, FRACTIONS[1:]) if s in fr[a] and s in fr[b])
                for s in sizes]
        near = [abs(math.log(fr["0"][s] / basic[s])) < abs(math.log(fr["0"][s] / v1b[s])) for s in sizes]
        lines += ["", f"* \"Similar results were observed\" (§6.2.1): cost non-increasing with the fraction at "
                  f"{sum(mono)}/{len(mono)} sizes; at 0% nearer basic than case-1b (log scale) at "
                  f"{sum(near)}/{len(near)} sizes.", ""]
    return lines
