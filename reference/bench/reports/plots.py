"""How the bench reports draw their plots: one style for every cost plot, and none at all without matplotlib.

Part of the report kit (:mod:`~topomark.reference.bench.reports.kit`).  A report
hands :func:`drawn` a *draw* function that takes ``matplotlib.pyplot`` and
returns the files it saved; without matplotlib (``pip install topomark[plot]``)
nothing is drawn and the report says so.  Every plot of a cost (or a marker
count, or a ratio) against the size of the world or a thread's length has the
same look: a 6 × 4.2 inch figure at 110 dpi, points marked ``o`` (error bars:
one standard deviation, small caps), a log y axis where costs span decades, a
small legend and a light grid (:func:`new`, :func:`curve`, :func:`errorbars`,
:func:`finish`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

__all__ = ["Draw", "FIGSIZE", "DPI", "pyplot", "drawn", "new", "curve", "errorbars", "finish", "save"]

Draw = Callable[[Any], list[Path]]
"""Given ``matplotlib.pyplot``: draw, save and return the plot files."""
FIGSIZE = (6, 4.2)
DPI = 110


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


def new(plt) -> tuple[Any, Any]:
    """A figure of the shared size and its axes."""
    return plt.subplots(figsize=FIGSIZE)


def curve(ax, xs: list[float], ys: list[float], label: str) -> None:
    """A series of points joined by lines."""
    ax.plot(xs, ys, marker="o", ms=3, label=label)


def errorbars(ax, xs: list[float], means: list[float], sds: list[float], label: str) -> None:
    """A series of means with one standard deviation either side."""
    ax.errorbar(xs, means, yerr=sds, marker="o", ms=3, capsize=2, label=label)


def finish(plt, fig, ax, path: Path, title: str, xlabel: str, ylabel: str, log: bool = True) -> Path:
    """Label the axes (log y axis unless ``log`` is False), add the legend and grid, and :func:`save`."""
    if log:
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    return save(plt, fig, path)


def save(plt, fig, path: Path) -> Path:
    """Lay the figure out, write it to ``path`` and free it."""
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path
