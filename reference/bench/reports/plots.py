"""How the bench reports draw their plots: one style for every plot, and none at all without matplotlib.

Part of the report kit (:mod:`~topomark.reference.bench.reports.kit`).  A report
hands :func:`drawn` a *draw* function that takes ``matplotlib.pyplot`` and
returns the files it saved; without matplotlib (:data:`INSTALL_HINT`) nothing is
drawn and the report says so.  Every plot — a cost, a marker count, a ratio or a
reduction against the size of the world or a thread's length — has the same
look (:func:`new`: one panel or several side by side, each 6 × 4.2 inches, at
110 dpi):

* every series its own colour *and* marker: a cycle of 10 colours × 7 markers
  (:data:`COLOURS`, :data:`MARKERS`; 10 and 7 are coprime, so the first 70
  series differ in at least one of the two — the lighthouse plot has 14);
* our measurements filled, joined by solid lines (:func:`curve`, or
  :func:`errorbars` with one standard deviation); the thesis's published
  numbers (:mod:`~topomark.reference.bench.thesis_figures`) in the same colour as
  our series of that algorithm, hollow markers on a dashed line, labelled
  "thesis" (:func:`thesis`); bounds and references black or grey (:func:`reference`);
* x ticks at the sizes measured (:func:`decorate`; never between them, as 72.5),
  a log y axis where costs span decades, a small legend, a light grid;
* the legend lists only what is drawn (:func:`shows`): a bound measured at one
  size is a line of one point, which draws nothing, so it is left out of it.

Examples
--------
>>> [style(i)["marker"] for i in (0, 1, 7, 10)], style(10)["color"] == style(0)["color"]
(['o', 's', 'o', 'D'], True)
>>> len({(style(i)["color"], style(i)["marker"]) for i in range(70)})
70
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable, Sequence

from topomark.proofs.drawing_png import INSTALL_HINT  # how to get matplotlib, the package's ``plot`` extra

__all__ = ["Draw", "FIGSIZE", "DPI", "COLOURS", "MARKERS", "INSTALL_HINT", "style", "pyplot", "drawn", "new",
           "curve", "points", "errorbars", "thesis", "reference", "shows", "decorate", "finish", "save"]

Draw = Callable[[Any], list[Path]]
"""Given ``matplotlib.pyplot``: draw, save and return the plot files."""
FIGSIZE = (6, 4.2)
DPI = 110
COLOURS = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
           "#17becf")
MARKERS = ("o", "s", "^", "D", "v", "P", "X")
MAX_TICKS = 12  # more measured sizes than this: matplotlib's own ticks (they would overlap)
LEGEND_INSIDE = 12
"""More legend entries than this do not fit over the curves: the legend goes beside the panel, in two columns,
and the figure is widened once to make room."""


def style(i: int) -> dict[str, str]:
    """The colour and marker of the ``i``-th series of a panel."""
    return {"color": COLOURS[i % len(COLOURS)], "marker": MARKERS[i % len(MARKERS)]}


def pyplot() -> Any | None:
    """``matplotlib.pyplot`` on the non-interactive Agg backend; None without matplotlib."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    return plt


def drawn(draw: Draw) -> list[Path] | None:
    """The files ``draw`` saved; None without matplotlib (nothing drawn)."""
    plt = pyplot()
    return None if plt is None else draw(plt)


def new(plt, panels: int = 1, sharey: bool = True) -> tuple[Any, Any]:
    """A figure of the shared size (``panels`` side by side, sharing the y axis unless ``sharey`` is False) and its
    axes (a list when ``panels`` > 1)."""
    fig, axes = plt.subplots(1, panels, figsize=(FIGSIZE[0] * panels, FIGSIZE[1]), sharey=sharey and panels > 1,
                             squeeze=False)
    return fig, (axes[0][0] if panels == 1 else list(axes[0]))


def _next(ax, key: str | None) -> dict[str, str]:
    """The style of the panel's next series; a series of a ``key`` already drawn (thesis beside ours) keeps its
    colour and marker."""
    seen: dict = ax.__dict__.setdefault("_topomark_styles", {})
    if key is not None and key in seen:
        return seen[key]
    got = style(len(seen))
    seen[key if key is not None else object()] = got
    return got


def _note_xs(ax, xs) -> None:
    ax.__dict__.setdefault("_topomark_xs", set()).update(xs)


def curve(ax, xs: list[float], ys: list[float], label: str, key: str | None = None) -> None:
    """A series of points joined by lines (``key``, default the label, pairs it with its :func:`thesis` series)."""
    _note_xs(ax, xs)
    ax.plot(xs, ys, ms=4, lw=1.2, label=label, **_next(ax, key or label))


def points(ax, xs: list[float], ys: list[float], label: str) -> None:
    """A series of unjoined points (one per run)."""
    _note_xs(ax, xs)
    ax.plot(xs, ys, ls="none", ms=4, alpha=0.8, label=label, **_next(ax, label))


def errorbars(ax, xs: list[float], means: list[float], sds: list[float], label: str, key: str | None = None) -> None:
    """A series of means with one standard deviation either side."""
    _note_xs(ax, xs)
    ax.errorbar(xs, means, yerr=sds, ms=4, lw=1.2, capsize=2, label=label, **_next(ax, key or label))


def thesis(ax, xs: list[float], ys: list[float], key: str, label: str | None = None) -> None:
    """The thesis's numbers for the series ``key``: its colour and marker, hollow, on a dashed line, labelled
    "thesis"."""
    if not xs:
        return
    _note_xs(ax, xs)
    got = _next(ax, key)
    ax.plot(xs, ys, ls="--", lw=1, ms=6, mfc="none", mew=1.2, label=label or f"{key} (thesis)", **got)


def reference(ax, xs: Sequence[float], ys: Sequence[float], label: str, dotted: bool = False) -> None:
    """A bound or reference curve: black, dashed (``dotted``: dotted), no markers."""
    ax.plot(xs, ys, color="k", ls=":" if dotted else "--", lw=1, label=label)


NO_STYLE = (None, "", " ", "None", "none")


def shows(artist, log_y: bool = False) -> bool:
    """Whether ``artist`` puts anything on the panel: a line needs a marker at one point it can place (finite;
    on a log y axis, y > 0) or a stroke between two distinct ones; a container (error bars) needs one child that
    shows; any other artist shows when visible."""
    import numpy as np
    from matplotlib.container import Container
    from matplotlib.lines import Line2D

    if isinstance(artist, Container):
        return any(shows(child, log_y) for child in artist.get_children())
    if not artist.get_visible():
        return False
    if not isinstance(artist, Line2D):
        return True
    placed = {(x, y) for x, y in np.asarray(artist.get_xydata(), dtype=float).reshape(-1, 2).tolist()
              if math.isfinite(x) and math.isfinite(y) and (y > 0 or not log_y)}
    marked = artist.get_marker() not in NO_STYLE and artist.get_markersize() > 0
    stroked = artist.get_linestyle() not in NO_STYLE and artist.get_linewidth() > 0
    return (marked and len(placed) >= 1) or (stroked and len(placed) >= 2)


def decorate(ax, title: str, xlabel: str, ylabel: str, log: bool = True) -> None:
    """Label a panel (log y axis unless ``log`` is False), tick the sizes it measured, legend (beside the panel
    when it has more than :data:`LEGEND_INSIDE` entries) and grid."""
    if log:
        ax.set_yscale("log")
    xs = sorted(ax.__dict__.get("_topomark_xs", ()))
    if 0 < len(xs) <= MAX_TICKS:
        ax.set_xticks(xs)
        ax.set_xticklabels([f"{x:g}" for x in xs], fontsize=8, rotation=45 if len(xs) > 7 else 0)
        if ax.get_xscale() != "linear":  # the measured values are the ticks: no minor ones between them
            ax.tick_params(axis="x", which="minor", bottom=False, labelbottom=False)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    log_y = ax.get_yscale() == "log"
    entries = [(h, label) for h, label in zip(*ax.get_legend_handles_labels()) if shows(h, log_y)]
    handles, labels = [h for h, _ in entries], [label for _, label in entries]
    if len(entries) > LEGEND_INSIDE:
        ax.legend(handles, labels, fontsize=6, ncol=2, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        fig = ax.figure
        if not getattr(fig, "_topomark_widened", False):
            fig.set_size_inches(fig.get_figwidth() * 2, fig.get_figheight())
            fig._topomark_widened = True
    elif entries:
        ax.legend(handles, labels, fontsize=7)
    ax.grid(True, which="both", alpha=0.3)


def finish(plt, fig, ax, path: Path, title: str, xlabel: str, ylabel: str, log: bool = True) -> Path:
    """:func:`decorate` the one panel and :func:`save`."""
    decorate(ax, title, xlabel, ylabel, log)
    return save(plt, fig, path)


def save(plt, fig, path: Path) -> Path:
    """Lay the figure out, write it to ``path`` and free it."""
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path
