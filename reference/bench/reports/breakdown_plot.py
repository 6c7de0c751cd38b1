"""The plot of one run's cost breakdown: each iteration's motions, stacked by kind of walk (thesis §3.5.2).

``topomark explore --breakdown-plot FILE`` draws it from the run's
:class:`~topomark.reference.run.breakdown.CostBreakdown`: one bar per loop
iteration of Algorithm 3.1 (0 is the start), its height the motions the
iteration made, split by kind (the walk to v_k, the new edge, the validation
walks by outcome case 1/2/3, the retraces, ...); the legend gives each kind's
share of the cost.  A second panel shows the cost accumulated over the
iterations, kind by kind, so where the cost goes as S grows is seen at once.
Only the kinds the run used are drawn.  It needs matplotlib (the ``plot``
extra); :func:`check_plot_file` refuses the file, as bad input naming the
install, before the run.
"""

from __future__ import annotations

from itertools import accumulate
from pathlib import Path
from typing import Any

from topomark.spec.errors import InvalidInput

from topomark.reference.bench.reports.plots import COLOURS, DPI, INSTALL_HINT, pyplot
from topomark.reference.run.breakdown import KINDS, CostBreakdown

__all__ = ["check_plot_file", "save_breakdown_plot", "SUFFIXES"]

SUFFIXES = (".png", ".svg")


def check_plot_file(path: str) -> Any:
    """Bad input unless the plot can be drawn to ``path``: a ``.png`` or ``.svg`` name, and matplotlib; returns
    ``matplotlib.pyplot``."""
    if Path(path).suffix.lower() not in SUFFIXES:
        raise InvalidInput(f"--breakdown-plot {path}: the plot is written as .png or .svg (by the suffix)")
    plt = pyplot()
    if plt is None:
        raise InvalidInput(f"--breakdown-plot {path} needs matplotlib: {INSTALL_HINT}")
    return plt


def save_breakdown_plot(breakdown: CostBreakdown, path: str, title: str) -> Path:
    """Draw ``breakdown`` to ``path`` (:func:`check_plot_file` first) under ``title``; return the path."""
    plt = check_plot_file(path)
    rows = breakdown.rows()
    x = [row[0] for row in rows]
    totals = breakdown.by_kind()
    used = [(i, k) for i, k in enumerate(KINDS) if totals[k]]
    fig, (bars, cumulative) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    bottom = [0] * len(rows)
    cum_bottom = [0] * len(rows)
    for colour, (i, kind) in enumerate(used):
        heights = [row[3 + i] for row in rows]
        share = totals[kind] / max(breakdown.cost, 1)
        style = {"color": COLOURS[colour % len(COLOURS)], "label": f"{kind}: {totals[kind]} ({share:.1%})"}
        bars.bar(x, heights, bottom=bottom, width=1.0, linewidth=0, **style)
        bottom = [b + h for b, h in zip(bottom, heights)]
        top = [c + s for c, s in zip(cum_bottom, accumulate(heights))]
        cumulative.fill_between(x, cum_bottom, top, step="mid", color=style["color"], linewidth=0)
        cum_bottom = top
    bars.set_ylabel("edge traversals in the iteration")
    bars.set_title(title, fontsize=9)
    bars.legend(fontsize=7, loc="upper left")
    cumulative.set_ylabel("cost so far")
    cumulative.set_xlabel("iteration of Algorithm 3.1 (0: the start)")
    for ax in (bars, cumulative):
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return Path(path)
