"""The lighthouses side by side: the report of ``topomark bench lighthouses`` (``DIR/lighthouses.md`` and plots).

The thesis names several ways to establish the *directional lighthouse* its
Chapter 3-4 algorithms need (explicit place and back-link information at v0),
and calls them equivalent for mapping; it never measures what each costs.
The ``lighthouses`` experiment (:mod:`~topomark.reference.bench.plan`) runs
each lighthouse of :data:`~topomark.reference.explorers.lighthouses.LIGHTHOUSES`
with the same algorithms on the same worlds and starts, and this report puts
the costs side by side, per family, size and algorithm:

* mean ± sd of the cost for each lighthouse, on the worlds every lighthouse
  ran, and each lighthouse's ratio of means to the directional vertex marker;
* the mean validation moves and hypotheses of each, which is where a
  difference comes from (findings computed from the rows, not asserted);
* the worlds a lighthouse skipped (a start of degree 1 cannot hold
  ``three-undirected-edge``; :func:`~topomark.reference.bench.plan.fits`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, cast

from topomark.reference.bench.plan import DEFAULT_LIGHTHOUSE, EXPERIMENTS, FAMILIES, Part, fits
from topomark.reference.bench.reports.kit import write
from topomark.reference.bench.reports.plots import Draw, curve, finish, new
from topomark.reference.bench.reports.stats import by_seed, drop_trips, finished, groups, mean, mean_sd, measured, num
from topomark.reference.bench.reports.text import fmt_pm, row
from topomark.reference.explorers.lighthouses import LIGHTHOUSES

__all__ = ["write_report", "by_world"]

NAME = "lighthouses"
SHORT = {"directional-vertex": "dir. vertex", "directional-edge": "dir. edge", "vertex-and-edge": "vertex + edge",
         "three-undirected-edge": "3 undirected edge", "three-undirected-vertex": "3 undirected vertex",
         "undirected-vertex": "undir. vertex (walk)", "undirected-edge": "undir. edge (walk)", "thread": "thread ε",
         "local-pair": "no marker, pair (§5.2.1 A)", "local-degree-list": "no marker, D list (§5.2.1 B)"}

THESIS = [
    "## What the thesis says, and what it does not measure", "",
    "* §3.3 / Algorithm 3.1: one directional vertex marker dropped at v0 gives explicit place and back-link "
    "information there — a *directional lighthouse* (`directional-vertex`, the default).",
    "* §6.1: \"an undirected E-marker is not sufficient …, although again similar to the V-marker case, a "
    "directional E-marker is\"; \"the single directional immovable V-marker algorithm can then be applied, with "
    "the modification that for each hypothesis h′, the expected perceptions P^E include the presence or absence of "
    "the E-marker at the incident edges of each visited vertex\" (`directional-edge`).",
    "* §6.2: \"two markers are sufficient: one marker is dropped at v0 and the other marker is dropped along one "
    "of its edges\" (`vertex-and-edge`); \"three undirected immovable E-markers are also sufficient … one marker "
    "at one of the edges and two markers at one another edge (assume that v0 has degree ≥ 2)\" "
    "(`three-undirected-edge`). \"This approach has O(m²n) cost bound\" — the bound of Algorithm 3.1.",
    "", "The thesis treats these lighthouses as interchangeable and never compares their costs; the tables below "
    "are that comparison.", ""]

MECHANISM = (
    "Why an edge-marker lighthouse can be cheaper: a marker on an edge is sensed at *both* its ends, so the "
    "neighbour w0 of v0 across the marked exit (with `three-undirected-edge`, the neighbours across both marked "
    "exits) perceives a marker too. Under the directional vertex marker w0 looks like any vertex of its degree: "
    "closing a loop at w0 raises a hypothesis for every such vertex of S, and other loop closures hypothesise w0. "
    "Under an edge marker w0's signature is unique in S: the closure at w0 has the one true hypothesis and no "
    "other closure hypothesises w0 (tests/test_bench_lighthouses.py checks that this accounts exactly for the "
    "difference in hypotheses). The same hypotheses are confirmed, so S grows in the same order and travel and "
    "new-edge moves are equal; the saving is validation and retrace moves on hypotheses about one or two of the "
    "n vertices, a small share of the cost that tends to shrink as the worlds grow.")


def by_world(rows: list[dict]) -> dict[tuple, dict[int, dict]]:
    """(world family, algorithm, size, lighthouse) -> {seed: row} over the finished nearest-policy runs."""
    return by_seed(groups(rows, ("family", "algorithm", "size", "lighthouse"),
                          keep=lambda r: finished(r) and (r.get("policy") or "nearest") == "nearest"))


def write_report(out: Path, wall: float | None = None, plots: bool = True) -> Path:
    """Generate ``out/lighthouses.md`` (and plots) from ``out/runs.csv``."""
    parts = EXPERIMENTS[NAME].parts

    def body(rows: list[dict]) -> tuple[list[str], Draw]:
        worlds = by_world(rows)
        lines = list(THESIS)
        for part in parts:
            lines += _cost_table(part, worlds) + _validation_table(part, worlds) + _skipped(part, worlds)
        return lines + ["## What we measured", "", MECHANISM, ""] + _findings(parts, worlds), _draw(parts, worlds, out)
    return write(NAME, out, wall, plots,
                 " (thesis §3.1.2); every lighthouse of a row explores the same worlds from the same start "
                 "(vertex and facing drawn from the world's seed), with the default policies. Means and ratios "
                 "are over the worlds every lighthouse of the row ran; ratio = mean cost ÷ the directional "
                 "vertex marker's mean cost on those worlds.", body)


def _cells(part: Part, worlds: dict, alg: str, size: int) -> tuple[list[dict[int, dict]], list[int]] | None:
    """The runs of each lighthouse of the part for (alg, size), and the worlds all of them ran; None if one has none."""
    got = [worlds.get((part.family, alg, size, lh)) for lh in part.lighthouses]
    if not all(got):
        return None
    runs = cast(list[dict[int, dict]], got)  # every one ran
    return runs, sorted(set.intersection(*(set(g) for g in runs)))


def _on(runs: dict[int, dict], seeds: list[int]) -> list[dict]:
    """The runs on these worlds."""
    return [runs[s] for s in seeds]


def _rows_of(part: Part, worlds: dict):
    """(size, algorithm, runs per lighthouse, shared worlds) for every row of the part with runs of all lighthouses."""
    for size in sorted({k[2] for k in worlds if k[0] == part.family and k[1] in part.algorithms
                        and (part.sizes is None or k[2] in part.sizes)}):
        for alg in part.algorithms:
            cells = _cells(part, worlds, alg, size)
            if cells and cells[1]:
                yield size, alg, cells[0], cells[1]


def _cost_table(part: Part, worlds: dict) -> list[str]:
    names = [SHORT.get(lh, lh) for lh in part.lighthouses]
    others = names[1:]
    lines = [f"## {part.family} ({FAMILIES[part.family].figure} worlds): mean cost ± sd per lighthouse", "",
             "| size | algorithm | worlds | verified | " + " | ".join(names) + " | "
             + " | ".join(f"{o} ÷ dir. vertex" for o in others) + " |",
             "|---:|---|---:|---:|" + "---:|" * (len(names) + len(others))]
    for size, alg, got, seeds in _rows_of(part, worlds):
        stats = [mean_sd([num(r, "cost") for r in _on(runs, seeds)]) for runs in got]
        checked = [runs[s] for runs in got for s in seeds if str(runs[s].get("checked")) == "True"]
        verified = sum(str(r.get("verified")) == "True" for r in checked)
        lines.append(f"| {size} | {alg} | {len(seeds)} | {verified}/{len(checked)} | "
                     + " | ".join(fmt_pm(m, sd) for m, sd in stats) + " | "
                     + " | ".join(f"{m / stats[0][0]:.4f}" for m, _ in stats[1:]) + " |")
    return lines + ["", _trips_line(part, worlds, names), ""]


def _trips_line(part: Part, worlds: dict, names: list[str]) -> str:
    """The lighthouses' drop trips (part of the cost above): the walks made only to drop their markers."""
    cells = []
    for i, name in enumerate(names):
        trips = [drop_trips(r) for _, _, got, seeds in _rows_of(part, worlds) for r in _on(got[i], seeds)]
        cells.append(f"{name} {sum(trips) / len(trips):.1f}" if trips and measured(*trips) else f"{name} not measured")
    return ("Mean drop trips per run (traversals made only to drop markers, part of the cost: Figure 3.21(b)'s walk "
            "to the neighbour and back): " + ", ".join(cells) + ".")


def _validation_table(part: Part, worlds: dict) -> list[str]:
    names = [SHORT.get(lh, lh) for lh in part.lighthouses]
    lines = [f"### {part.family}: mean validation moves and hypotheses per lighthouse", "",
             "| size | algorithm | " + " | ".join(f"validation, {n}" for n in names) + " | "
             + " | ".join(f"hypotheses, {n}" for n in names) + " |",
             "|---:|---|" + "---:|" * (2 * len(names))]
    for size, alg, got, seeds in _rows_of(part, worlds):
        lines.append(row(size, alg, *(f"{mean(_on(r, seeds), column):,.1f}" for column in ("validation", "hypotheses")
                                      for r in got)))
    return lines + [""]


def _skipped(part: Part, worlds: dict) -> list[str]:
    """The worlds the default lighthouse ran that a lighthouse needing a larger start degree skipped."""
    lines = []
    for lh in part.lighthouses:
        if LIGHTHOUSES[lh].min_degree <= 1:
            continue
        skipped = sorted({(size, seed) for (fam, alg, size, light), runs in worlds.items()
                          if fam == part.family and light == DEFAULT_LIGHTHOUSE for seed in runs
                          if not fits(fam, size, seed, lh)})
        lines.append(f"`{lh}` needs a start vertex of degree ≥ {LIGHTHOUSES[lh].min_degree} (§6.2): worlds skipped "
                     f"because the start drawn from their seed has a smaller degree: {len(skipped)}"
                     + (" (" + ", ".join(f"size {s} seed {k}" for s, k in skipped[:20]) + ")" if skipped else "")
                     + ". A skipped world is not re-drawn (that would compare different starts); the other "
                       "lighthouses' means above are over the worlds all four ran.")
    return lines + [""] if lines else []


def _deltas(parts: tuple[Part, ...], worlds: dict, lh: str) -> dict:
    """Over every shared world of every row: how ``lh`` compares with the default lighthouse, move by move."""
    d: dict[str, Any] = dict.fromkeys(("worlds", "cheaper", "equal", "dearer", "cost", "validation", "retrace", "travel+new",
                       "hypotheses", "max_excess"), 0.0)
    d["dearer_algs"] = set()
    for part in parts:
        if lh not in part.lighthouses:
            continue
        i = part.lighthouses.index(lh)
        for _size, alg, got, seeds in _rows_of(part, worlds):
            for s in seeds:
                a, b = got[0][s], got[i][s]
                diff = {c: num(a, c) - num(b, c) for c in
                        ("cost", "validation", "retrace", "travel", "new", "hypotheses")}
                d["worlds"] += 1
                d["cheaper" if diff["cost"] > 0 else "equal" if diff["cost"] == 0 else "dearer"] += 1
                if diff["cost"] < 0:
                    d["dearer_algs"].add(alg)
                    d["max_excess"] = max(d["max_excess"], -diff["cost"])
                for c in ("cost", "validation", "retrace", "hypotheses"):
                    d[c] += diff[c]
                d["travel+new"] += abs(diff["travel"]) + abs(diff["new"])
    return d


def _findings(parts: tuple[Part, ...], worlds: dict) -> list[str]:
    lines = ["Measured, over every world all four lighthouses ran (cost and validation moves: the tables above):", ""]
    for lh in [lh for lh in LIGHTHOUSES if lh != DEFAULT_LIGHTHOUSE]:
        d = _deltas(parts, worlds, lh)
        if not d["worlds"]:
            continue
        saved = d["cost"]
        share = (f"; validation moves account for {100 * d['validation'] / saved:.0f}% of the moves saved and "
                 f"retrace moves for {100 * d['retrace'] / saved:.0f}%" if saved else "")
        lines.append(f"* `{lh}` against `{DEFAULT_LIGHTHOUSE}`, world by world ({d['worlds']:.0f} runs each): "
                     f"cheaper on {d['cheaper']:.0f}, equal on {d['equal']:.0f}, dearer on {d['dearer']:.0f}"
                     + (f" (only with {', '.join(sorted(d['dearer_algs']))}, by at most {d['max_excess']:,.0f} moves)"
                        if d["dearer"] else "") + "; "
                     f"{saved:+,.0f} moves saved in all ({d['hypotheses']:+,.0f} hypotheses){share}; travel and "
                     f"new-edge moves differ by {d['travel+new']:,.0f} in all.")
    same, total = _identical(parts, worlds, "directional-edge", "vertex-and-edge")
    if total:
        lines.append(f"* `directional-edge` and `vertex-and-edge` cost exactly the same on {same} of {total} "
                     "worlds: both mark v0 and its exit-0 edge, and their perceptions separate the same places "
                     "(the marked edge's direction tells v0 from w0 just as the vertex marker does).")
    if any(_deltas(parts, worlds, lh)["dearer"] for lh in LIGHTHOUSES if lh != DEFAULT_LIGHTHOUSE):
        lines.append(DEARER)
    return lines + [""] if len(lines) > 2 else []


DEARER = (
    "* Where a lighthouse is dearer (the algorithms are named above), our reading, not traced run by run: with "
    "fewer hypotheses an enhancement that rejects hypotheses without motion validates in a different order, and a "
    "walk the directional vertex marker spent on a hypothesis about w0 may have rejected other hypotheses on its "
    "way for free.")


def _identical(parts: tuple[Part, ...], worlds: dict, a: str, b: str) -> tuple[int, int]:
    same = total = 0
    for part in parts:
        if a not in part.lighthouses or b not in part.lighthouses:
            continue
        i, j = part.lighthouses.index(a), part.lighthouses.index(b)
        for _size, _alg, got, seeds in _rows_of(part, worlds):
            total += len(seeds)
            same += sum(got[i][s]["cost"] == got[j][s]["cost"] for s in seeds)
    return same, total


def _draw(parts: tuple[Part, ...], worlds: dict, out: Path) -> Draw:
    """Per family: each lighthouse's ratio of mean cost to the directional vertex marker's, against the size."""
    def draw(plt) -> list[Path]:
        made = [_plot(plt, part, worlds, out) for part in parts]
        return [p for p in made if p]
    return draw


def _plot(plt, part: Part, worlds: dict, out: Path) -> Path | None:
    series: dict[tuple[str, str], list[tuple[int, float]]] = {}
    for size, alg, got, seeds in _rows_of(part, worlds):
        base = mean(_on(got[0], seeds), "cost")
        for lh, runs in zip(part.lighthouses[1:], got[1:]):
            series.setdefault((lh, alg), []).append((size, mean(_on(runs, seeds), "cost") / base))
    if not series:
        return None
    fig, ax = new(plt)
    ax.axhline(1.0, color="k", lw=1, ls="--", label="directional vertex marker")
    for (lh, alg), pts in series.items():
        curve(ax, [p[0] for p in pts], [p[1] for p in pts], f"{SHORT.get(lh, lh)}, {alg}")
    return finish(plt, fig, ax, out / f"{NAME}-{part.family}.png", f"Lighthouses side by side: {part.family}",
                  "size of graph (vertices)", "mean cost ÷ directional vertex marker's", log=False)
