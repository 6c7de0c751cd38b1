"""The bench's one plotting style: distinct colour × marker per series, the thesis hollow and dashed beside ours,
ticks at the measured sizes, the policies in one figure and the reductions plot of Tables 4.1-4.8."""

from __future__ import annotations

from topomark.reference.bench import thesis_figures as tf
from topomark.reference.bench.plan import EXPERIMENTS
from topomark.reference.bench.reports import chapter34_plots, plots
from topomark.reference.bench.reports.chapter34 import reduction

plt = plots.pyplot()


def _summary(family: str, algs: tuple[str, ...], sizes: tuple[int, ...], policies=("nearest",)) -> dict:
    """Synthetic per-(family, algorithm, policy, size) summaries: each enhancement costs a fixed share of basic."""
    out = {}
    for pol in policies:
        for k, alg in enumerate(algs):
            for size in sizes:
                cost = 100.0 * size * (1 - 0.1 * k)
                out[(family, alg, pol, size)] = {"mean": cost, "sd": 1.0, "bound": 1e6, "m": 2.0 * size,
                                                 "seeds": {0: cost, 1: cost}}
    return out


def test_fourteen_series_get_fourteen_distinct_styles():
    fig, ax = plots.new(plt)
    for i in range(14):
        plots.curve(ax, [72, 90], [i, i + 1], f"series {i}")
    seen = {(line.get_color(), line.get_marker()) for line in ax.get_lines()}
    plt.close(fig)
    assert len(seen) == 14


def test_thesis_numbers_are_hollow_dashed_in_their_series_colour_and_ticks_are_the_sizes():
    fig, ax = plots.new(plt)
    plots.curve(ax, [72, 90, 108], [1, 2, 3], "enh1")
    plots.thesis(ax, [72, 90], [2, 3], "enh1")
    plots.decorate(ax, "t", "x", "y", log=False)
    ours, theirs = ax.get_lines()
    plt.close(fig)
    assert theirs.get_color() == ours.get_color() and theirs.get_marker() == ours.get_marker()
    assert theirs.get_markerfacecolor() == "none" and theirs.get_linestyle() == "--" and ours.get_linestyle() == "-"
    assert "thesis" in theirs.get_label()
    assert list(ax.get_xticks()) == [72, 90, 108]


def test_policies_draw_one_figure_and_tables_a_reductions_plot(tmp_path):
    exp = EXPERIMENTS["policies"]
    summary = _summary("lattice-hole", ("basic", "enh3"), (90, 260), ("nearest", "fifo", "lifo"))
    made = chapter34_plots.draw(exp, summary, tmp_path, reduction)(plt)
    assert [p.name for p in made] == ["policies-lattice-hole-policies.png"]
    exp = EXPERIMENTS["table-4.1"]
    summary = _summary("lattice-hole", ("basic", "enh1", "enh2", "enh3"), (72, 90))
    made = chapter34_plots.draw(exp, summary, tmp_path, reduction)(plt)
    assert [p.name for p in made] == ["table-4.1-lattice-hole.png", "table-4.1-reductions.png"]
    assert all(p.read_bytes()[:4] == b"\x89PNG" for p in made)


def test_the_reductions_panel_holds_ours_and_the_tables(monkeypatch, tmp_path):
    panels = []
    monkeypatch.setattr(chapter34_plots, "save", lambda plt_, fig, path: panels.append(fig) or path)
    summary = _summary("lattice-hole", ("basic", "enh1"), (72, 90))
    chapter34_plots.draw(EXPERIMENTS["table-4.1"], summary, tmp_path, reduction)(plt)
    ax = panels[-1].axes[0]
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert [round(y, 6) for y in lines["enh1"].get_ydata()] == [10.0, 10.0]  # 90% of basic's cost, every world
    row, _ = tf.REDUCTIONS[("lattice-hole", "enh1")]
    assert list(lines["enh1 (thesis, Table 4.1)"].get_ydata()) == [row[s] for s in sorted(row)]
    plt.close("all")


def _legend(ax) -> list[str]:
    legend = ax.get_legend()
    return [] if legend is None else [t.get_text() for t in legend.get_texts()]


def test_the_legend_lists_only_what_is_drawn():
    """A bound measured at one size is a line of one point without a marker: nothing drawn, so no legend entry;
    at two sizes it is a line, and listed.  A point at y = 0 on a log axis is not drawn either."""
    fig, ax = plots.new(plt)
    plots.reference(ax, [20], [5000], "upper bound (3.3)")
    plots.reference(ax, [20], [40], "lower bound m", dotted=True)
    plots.errorbars(ax, [20], [80], [60], "basic")
    plots.points(ax, [20], [0], "zero")
    plots.decorate(ax, "t", "x", "y")
    assert _legend(ax) == ["basic"]
    fig, ax = plots.new(plt)
    plots.reference(ax, [20, 40], [5000, 9000], "upper bound (3.3)")
    plots.curve(ax, [20], [70], "one point, marked")
    plots.points(ax, [20], [0], "zero")
    plots.decorate(ax, "t", "x", "y", log=False)
    assert _legend(ax) == ["upper bound (3.3)", "one point, marked", "zero"]
    plt.close("all")


def test_a_long_legend_goes_beside_the_panel_and_widens_the_figure_once():
    """Up to LEGEND_INSIDE entries sit over the curves; one more and the legend moves beside the panel."""
    widths = []
    for count in (plots.LEGEND_INSIDE, plots.LEGEND_INSIDE + 1):
        fig, (left, right) = plots.new(plt, panels=2)
        for ax in (left, right):
            for k in range(count):
                plots.curve(ax, [10, 20], [k + 1, k + 2], f"series {k}")
            plots.decorate(ax, "t", "x", "y")
        widths.append(fig.get_figwidth())
        assert len(_legend(left)) == count
        assert (left.get_legend()._ncols == 2) == (count > plots.LEGEND_INSIDE)
    assert widths[1] == 2 * widths[0]
    plt.close("all")


def test_a_one_size_bench_plot_lists_no_bound_it_does_not_draw(monkeypatch, tmp_path):
    """The small Figure 3.11 sweep (one size): its cost plot's legend names the drawn series only."""
    panels = []
    monkeypatch.setattr(chapter34_plots, "save", lambda plt_, fig, path: panels.append(fig) or path)
    part = EXPERIMENTS["figure-3.11"].parts[0]
    summary = _summary(part.family, ("basic",), (20,))
    chapter34_plots.draw(EXPERIMENTS["figure-3.11"], summary, tmp_path, reduction)(plt)
    ax = panels[0].axes[0]
    assert _legend(ax) == ["basic"]
    assert {line.get_label() for line in ax.get_lines()} >= {"upper bound (3.3)", "lower bound m"}  # not drawn
    plt.close("all")
