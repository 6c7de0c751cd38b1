"""The plots of the Chapter 3-4 reports: cost against size (Figures 3.10-3.12, 4.2-4.8), the edge policies side by
side, and the reductions of Tables 4.1-4.8 — each with the thesis's published numbers beside ours.

Part of :mod:`~topomark.reference.bench.reports.chapter34`, drawn in the one style of
:mod:`~topomark.reference.bench.reports.plots`:

* ``EXPERIMENT-FAMILY.png``: every algorithm's mean cost ± sd against the size, between the bound (3.3) and the
  lower bound m; the costs the thesis prints in §4.1's text (``thesis_figures.ABSOLUTE``: lattice-hole 90 and 260)
  as hollow markers on a dashed line beside the algorithm's own series;
* ``EXPERIMENT-FAMILY-policies.png``: a part run with several edge policies (``bench policies``) draws one figure,
  a panel per policy, sharing the y axis;
* ``EXPERIMENT-reductions.png``: a panel per world family, each enhancement's mean per-world percent reduction
  against basic by size, beside Tables 4.1-4.8's (``thesis_figures.REDUCTIONS``), for an experiment of those tables
  (``tables``, ``table-4.N``, ``all``); the y axis is linear, and logarithmic beyond ±100% where a reduction is
  below −100% (Enhancement-5 with d = 2 costs about 20 times basic on complete-hole worlds, Table 4.6).
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable

from topomark.reference.bench import thesis_figures as tf
from topomark.reference.bench.plan import DEFAULT_LIGHTHOUSE, FAMILIES, Experiment, Part
from topomark.reference.bench.reports.plots import Draw, curve, decorate, errorbars, new, reference, save, thesis

__all__ = ["draw"]

Reduction = Callable[[dict, str, str, int, str], "tuple[float, int] | None"]


def draw(exp: Experiment, summary: dict, out: Path, reduction: Reduction) -> Draw:
    """Per part (Algorithm 3.1's own lighthouse): its cost plot (one panel per edge policy), then the reductions
    plot of the experiment's enhancements, if it has any."""
    def drawing(plt) -> list[Path]:
        made = [_costs(plt, exp, part, summary, out) for part in exp.parts
                if part.lighthouses == (DEFAULT_LIGHTHOUSE,)]
        made.append(_reductions(plt, exp, summary, out, reduction))
        return [p for p in made if p]
    return drawing


def _costs(plt, exp: Experiment, part: Part, summary: dict, out: Path) -> Path | None:
    policies = [pol for pol in part.policies if any(k[0] == part.family and k[2] == pol and k[1] in part.algorithms
                                                     for k in summary)]
    if not policies:
        return None
    fig, axes = new(plt, len(policies))
    figure = "Figures 4.2-4.8" if len(part.algorithms) > 1 else FAMILIES[part.family].figure
    for ax, pol in zip(axes if len(policies) > 1 else [axes], policies):
        _cost_panel(ax, part, pol, summary)
        title = f"{figure}: {part.family}" + (f", edge policy {pol}" if len(policies) > 1 or pol != "nearest" else "")
        decorate(ax, title, "size of graph (vertices)", "cost (edge traversals)", log=FAMILIES[part.family].log)
    suffix = "-policies" if len(policies) > 1 else "" if policies == ["nearest"] else f"-{policies[0]}"
    return save(plt, fig, out / f"{exp.name}-{part.family}{suffix}.png")


def _cost_panel(ax, part: Part, pol: str, summary: dict) -> None:
    every: dict[int, dict] = {}
    for k in summary:
        if k[0] == part.family and k[2] == pol and k[1] in part.algorithms:
            every.setdefault(k[3], summary[k])
    xs = sorted(every)
    reference(ax, xs, [every[x]["bound"] for x in xs], "upper bound (3.3)")
    reference(ax, xs, [every[x]["m"] for x in xs], "lower bound m", dotted=True)
    for alg in part.algorithms:
        keys = sorted(k for k in summary if k[0] == part.family and k[1] == alg and k[2] == pol)
        if not keys:
            continue
        errorbars(ax, [k[3] for k in keys], [summary[k]["mean"] for k in keys], [summary[k]["sd"] for k in keys],
                  alg)
        printed = sorted((size, c[0]) for (fam, a, size), c in tf.ABSOLUTE.items() if fam == part.family and a == alg)
        if pol == "nearest" and printed:  # the thesis's costs are of its own (nearest-first) policy
            thesis(ax, [s for s, _ in printed], [c for _, c in printed], alg)


def _reductions(plt, exp: Experiment, summary: dict, out: Path, reduction: Reduction) -> Path | None:
    families = [p.family for p in exp.parts if p.lighthouses == (DEFAULT_LIGHTHOUSE,)
                and any((p.family, a) in tf.REDUCTIONS for a in p.algorithms)]
    families = list(dict.fromkeys(families))
    if not exp.tables or not families or not any(k[0] in families and k[1] != "basic" for k in summary):
        return None
    from matplotlib.ticker import FuncFormatter  # matplotlib is there: plt is its pyplot

    fig, axes = new(plt, len(families), sharey=False)
    for ax, fam in zip(axes if len(families) > 1 else [axes], families):
        algs = dict.fromkeys(a for p in exp.parts if p.family == fam for a in p.algorithms if a != "basic")
        for alg in algs:
            sizes = sorted({k[3] for k in summary if k[0] == fam and k[1] == alg and k[2] == "nearest"})
            ours = [(s, r[0]) for s in sizes if (r := reduction(summary, fam, alg, s, "nearest")) is not None]
            if ours:
                curve(ax, [s for s, _ in ours], [v for _, v in ours], alg)
            if (fam, alg) in tf.REDUCTIONS:
                row, source = tf.REDUCTIONS[(fam, alg)]
                thesis(ax, sorted(row), [row[s] for s in sorted(row)], alg, f"{alg} (thesis, {source})")
        ax.axhline(0, color="grey", lw=0.8)
        if min(ax.get_ylim()) < -100:  # Enhancement-5, d = 2 on complete-hole worlds (Table 4.6)
            ax.set_yscale("symlog", linthresh=100, linscale=4)
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        decorate(ax, f"Tables 4.1-4.8: {fam}", "size of graph (vertices)", "cost reduction against basic (%)",
                 log=False)
    return save(plt, fig, out / f"{exp.name}-reductions.png")
