"""``worst-case.md``: what the exhaustive and adversarial searches say about the thesis's open question (§7.2).

:func:`summarise` reads the outputs of ``topomark worst-case --out DIR`` (an
exhaustive search, ``worst-case.json``) and ``topomark worst-case --search
--out DIR`` (``worst-case-search.json``) and writes one report: per algorithm
the exact maxima per n beside the thesis's bound, the structure of the worst
worlds (:func:`structure`: what makes them bad), and the adversarial maxima
with their fitted growth.  It states which numbers are proved (exhaustive,
exact for every world of that size) and which are only found (search: a lower
bound on the worst case).  What it reads is checked and recomputed first
(:mod:`~topomark.reference.worstcase.summary_input`): a damaged or edited
directory is bad input (exit 2) naming the file and field, and a cost above
the exact bound, being recomputed, is a negative verdict (exit 1).

Examples
--------
>>> from topomark.reference.worlds.worst_cases import worst_case_world
>>> s = structure(worst_case_world("basic-n5-d4"), "basic")
>>> (s["n"], s["m"], s["cost"], s["max_degree"])
(5, 10, 89, 4)
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import networkx as nx

from topomark.spec.world import World
from topomark.spec.worldfile import world_from_json

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.run.explore import explore
from topomark.reference.bench.reports.plots import curve, drawn, finish, new, points
from topomark.reference.worstcase.fit import fit_exponents
from topomark.reference.worstcase.naming import generator_text
from topomark.reference.worstcase.readback import read_regular
from topomark.reference.worstcase.remake import commands
from topomark.reference.worstcase.report import THESIS
from topomark.reference.worstcase.summary_input import bound_broken, load_runs
from topomark.reference.worstcase.verdicts import best_per_size, one_per_size, verdicts

__all__ = ["structure", "summarise", "summarise_runs", "MIN_FIT_SIZES"]

MIN_FIT_SIZES = 5
"""The fewest sizes a growth fit is made over: three points fit a power law nearly whatever they are."""

QUESTION = ("\"the derived upper cost bound O(m²n) of the basic single directional immovable marker algorithm is "
            "quite loose for some environments … it is worth investigating whether the worst case scenarios exist (at "
            "the same time). If these worst case scenarios can happen together for some environment, then what "
            "classes of graphs are they? … it might be helpful to derive the bound by considering some other factors "
            "such as graph diameter and maximum vertex degrees\" (§7.2).")

def structure(world: World, algorithm: str) -> dict[str, Any]:
    """What the worst run on ``world`` (from its start) looks like: the world's shape and the run's work."""
    g = nx.Graph([(v, w) for v in world.vertices for w in world.rotation[v]])
    start = world.start_state()[0]
    run = explore(world, algorithm)
    spec = algorithm_spec(algorithm)
    bound = spec.bound_for(world.n, world.m)
    ratio = None if bound is None else round(spec.counted_cost(run.cost, run.by_purpose) / bound, 4)
    return {"n": world.n, "ratio_to_bound": ratio, "m": world.m, "diameter": nx.diameter(g), "max_degree": max(dict(g.degree()).values()),
            "genus": world.genus(), "start_degree": world.degree(start),
            "start_eccentricity": nx.eccentricity(g, start), "cost": run.cost, "verified": run.verified,
            "loop_iterations": run.loop_iterations, "hypotheses": run.hypotheses,
            "hypotheses_rejected": run.hypotheses_rejected,
            "degrees": "".join(str(d) for d in sorted((d for _, d in g.degree()), reverse=True))}


def _findings(runs: list[dict], shapes: list[tuple[dict, World]]) -> list[str]:
    """What the exhaustive tables say, computed from them: each ratio from one world, structure counted over
    distinct worlds, and nothing that holds by definition."""
    out = []
    for data in sorted(runs, key=lambda d: (d["algorithm"], d["max_degree"])):
        rows = [r for r in data["per_n"] if r["n"] >= 4 and r["max_ratio_to_bound"] is not None]
        if rows:
            last, top = rows[-1], max(rows, key=lambda r: r["max_ratio_to_bound"])
            exact = max(r["ratio_exact"][0] / r["ratio_exact"][1] for r in rows)  # recomputed by load_runs
            verdict = "the bound holds with room to spare" if exact < 1 else "the bound is reached" if exact == 1 \
                else "the bound does NOT hold (exit 1)"
            out.append(f"- `{data['algorithm']}`, degree ≤ {data['max_degree']}: the largest cost / exact bound at "
                       f"n = {last['n']} is {last['max_ratio_to_bound']}, over 4 ≤ n ≤ {last['n']} "
                       f"{top['max_ratio_to_bound']} (at n = {top['n']}); {verdict}.")
    if shapes:
        out.append(_distinct(shapes))
    return out


def _distinct(shapes: list[tuple[dict, World]]) -> str:
    """The structure of the max-cost worlds counted once per distinct world (start included), leaving out the
    start's eccentricity in worlds of diameter 1, where every start is as far as any two places are."""
    from topomark.proofs.enumerate import canonical_form
    worlds = {canonical_form(w): s for s, w in shapes}
    embedded = {canonical_form(w.with_start(None)) for _, w in shapes}
    wide = [s for s in worlds.values() if s["diameter"] >= 2]
    far = sum(1 for s in wide if s["start_eccentricity"] == s["diameter"])
    full = sum(1 for s in worlds.values() if s["degrees"].count(str(s["max_degree"])) >= s["n"] - 1)
    return (f"- The {len(shapes)} max-cost rows above are {len(worlds)} distinct worlds with their start "
            f"({len(embedded)} distinct embedded worlds). Of the {len(wide)} of diameter ≥ 2, {far} start (where "
            f"the lighthouse is) at eccentricity = diameter; in {full} of the {len(worlds)} all but at most one "
            "place have the largest degree.")


def _exhaustive_section(runs: list[dict]) -> list[str]:
    lines = ["## Proved: the exact worst case for every world up to a size", "",
             "Every embedded world up to extended isomorphism with n vertices and degrees ≤ D, from every start up to "
             "the world's automorphisms; the maxima are exact for those sizes.", "",
             "Each row's max cost, its cost / exact bound and its structure are of one world (the max-cost world, "
             "with its start); the largest cost / exact bound over the same worlds is its own column, with its own "
             "world's size. The largest cost/m is over all worlds.", "",
             "| algorithm | D | n | worlds | runs | max cost | its cost / exact bound | structure of the max-cost "
             "world (m, diameter, degrees, genus, start eccentricity; loop iterations, hypotheses rejected) | "
             "largest cost / exact bound (its world's m) | largest cost/m |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    shapes = []
    for data in sorted(runs, key=lambda d: (d["algorithm"], d["max_degree"])):
        for r in data["per_n"]:
            if r["argmax"] is None or r["n"] < 4:
                continue
            world = world_from_json(r["argmax"])
            s = structure(world, data["algorithm"])
            shapes.append((s, world))
            shape = (f"m={s['m']}, diam {s['diameter']}, degrees {s['degrees']}, genus {s['genus']}, "
                     f"ecc {s['start_eccentricity']}; {s['loop_iterations']} loops, "
                     f"{s['hypotheses_rejected']}/{s['hypotheses']} hypotheses rejected")
            ratio_m = "" if r["ratio_exact"] is None else f" (m={_bound_m(data, r)})"
            lines.append(f"| {data['algorithm']} | {data['max_degree']} | {r['n']} | {r['worlds']} | {r['runs']} | "
                         f"{r['max_cost']} | {s['ratio_to_bound']} | {shape} | {r['max_ratio_to_bound']}{ratio_m} | "
                         f"{r['max_cost_per_m']} |")
    return lines + ["", *_findings(runs, shapes), ""]


def _bound_m(data: dict, r: dict) -> int:
    """The m of the world with the largest cost / exact bound: the m whose exact bound is the ratio's denominator."""
    spec = algorithm_spec(data["algorithm"])
    ms = [m for m in range(r["n"] - 1, r["n"] * data["max_degree"] // 2 + 1)
          if spec.bound_for(r["n"], m) == r["ratio_exact"][1]]
    assert len(ms) == 1, "the exact bound grows with m, so it names its world's m"
    return ms[0]


def _found_texts(runs: list[dict]) -> list[list[str | None]]:
    """For each search run, the generator text of the best world it found at each of its sizes (None: none)."""
    return [[generator_text(world_from_json(r["search"]["best"]["world"]), data["algorithm"])
             if (r["search"].get("best") or {}).get("world") else None for r in data["per_n"]] for data in runs]


def _search_section(runs: list[dict], found: list[list[str | None]]) -> list[str]:
    lines = ["## Found: bad worlds past exhaustive sizes (lower bounds)", "",
             "Seeded local search; the best world found is a lower bound on the worst case, set beside the best of as "
             "many random worlds. Each row's figures are of one world, named by a generator text that "
             "`topomark explore` accepts (none: the world is only in the run's output directory).", "",
             "| algorithm | started from | n | m | diameter | max degree | best found | its world | found / bound "
             "| best random |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    fits = []
    texts = {(id(data), r["n"]): text for data, row in zip(runs, found) for r, text in zip(data["per_n"], row)}
    rows = sorted(((data, r) for data in runs for r in data["per_n"]),
                  key=lambda p: (p[0]["algorithm"], p[0].get("family") or "", p[0].get("restart") or "", p[1]["n"]))
    for data, r in rows:  # by size within an algorithm, whichever run each size came from
        name = f"{data['algorithm']}{' lattice-hole' if data.get('family') else ''}"
        s, b = r["search"].get("best") or {}, r["random"].get("best") or {}
        holes = f" (holes: {', '.join(s['holes']) or 'none'})" if "holes" in s else ""
        text = texts[id(data), r["n"]]
        lines.append(f"| {name} | {data.get('restart') or 'random worlds'} | {r['n']} | {s.get('m')} | "
                     f"{s.get('diameter')} | {s.get('max_degree')} | {s.get('cost')}{holes} | "
                     f"{f'`{text}`' if text else 'none'} | {s.get('ratio_to_bound')} | {b.get('cost')} |")
    by_name: dict[str, list[dict]] = {}
    for data in runs:
        name = f"{data['algorithm']}{' lattice-hole' if data.get('family') else ''}"
        by_name.setdefault(name, []).extend({**r["search"]["best"], "n": r["n"]} for r in data["per_n"]
                                            if r["search"].get("best"))
    for name, rows_found in sorted(by_name.items()):
        best = one_per_size(rows_found)  # a size searched twice is still one point of the fit
        sizes = len(best)
        if sizes >= MIN_FIT_SIZES:  # fitted here, from the rows, so every report fits alike
            fits.append(f"- {name}: {_fit_text(fit_exponents(best))}{_bound_growth(best)}")
        else:
            fits.append(f"- {name}: no fit ({sizes} sizes; a growth fit needs at least {MIN_FIT_SIZES})")
    return lines + ["", "Growth of the cost of the best world found at each size, the one the verdicts below show "
                    "(log-log least squares, 95 % confidence intervals):", "", *fits, ""]


def _names(searched: list[dict], found: list[list[str | None]] | None = None) -> dict[tuple[str, int], str | None]:
    """(algorithm, n) ↦ the generator text of the best world found there (:func:`~.verdicts.best_per_size`), read
    from ``found`` (:func:`_found_texts`, made here when not given), so no world is named twice."""
    found = _found_texts(searched) if found is None else found
    text = {id(r["search"]["best"]): name for data, row in zip(searched, found)
            for r, name in zip(data["per_n"], row) if r["search"].get("best")}
    return {key: text[id(s)] for key, s in best_per_size(searched).items()}


def _bound_growth(best: list[dict[str, Any]]) -> str:
    """How the exact bound grows over the same worlds (the cost each found world would need to reach it)."""
    bounds = [{**b, "cost": b["cost"] / b["ratio_to_bound"]} for b in best if b.get("ratio_to_bound")]
    if len(bounds) < MIN_FIT_SIZES:
        return ""
    fit = fit_exponents(bounds)["n"]
    return f"; the exact bound at those worlds grows as n^{fit['exponent']:.2f}" if fit else ""


def _fit_text(fit: dict[str, Any]) -> str:
    """``cost ∝ m^2.02 (R² 0.984), …`` for the factors that varied."""
    parts = [f"{f}^{fit[f]['exponent']:.2f} (95 % CI {fit[f]['ci95'][0]:.2f} to {fit[f]['ci95'][1]:.2f}, "
             f"R² {fit[f]['r2']})" for f in ("m", "n", "diameter", "max_degree") if fit.get(f) and "ci95" in fit[f]]
    two = fit.get("m_n")
    if two:
        parts.append(f"c·m^{two['a']:.2f}·n^{two['b']:.2f} (R² {two['r2']})")
    return f"cost ∝ {', '.join(parts)} over {fit['rows']} sizes" if parts else "no factor varied"


def _plot(out: Path, exhaustive: list[dict], searched: list[dict]) -> list[Path] | None:
    """The largest cost per n: exact (exhaustive, joined) and found (search, unjoined), log-log."""
    def draw(plt) -> list[Path]:
        fig, ax = new(plt)
        for data in sorted(exhaustive, key=lambda d: (d["algorithm"], d["max_degree"])):
            rows = [r for r in data["per_n"] if r["max_cost"]]
            curve(ax, [r["n"] for r in rows], [r["max_cost"] for r in rows],
                  f"{data['algorithm']}, exact, D ≤ {data['max_degree']}")
        found: dict[str, dict[int, int]] = {}  # one series per algorithm: the best over its runs at each n
        for data in searched:
            series = found.setdefault(f"{data['algorithm']}{' lattice-hole' if data.get('family') else ''}", {})
            for r in data["per_n"]:
                if r["search"].get("best"):
                    series[r["n"]] = max(series.get(r["n"], 0), r["search"]["best"]["cost"])
        for name, series in sorted(found.items()):
            points(ax, sorted(series), [series[n] for n in sorted(series)], f"{name}, found")
        ax.set_xscale("log")
        return [finish(plt, fig, ax, out / "worst-case-summary.png", "The worst cost per n: proved and found",
                       "n (vertices)", "edge traversals")]
    return drawn(draw)


def _distributions(out: Path, exhaustive: list[dict]) -> list[Path]:
    """Each exhaustive search's cost/m distribution plot, copied beside the report under its own name."""
    copied = []
    for data in exhaustive:
        source = Path(data["dir"]) / "worst-case-cost-per-m.png"
        if source.exists() or source.is_symlink():  # read back as a regular file of bounded size, or refused
            # the name is the run's checked algorithm (a registered name) and sizes: never a path of the file's
            target = out / f"worst-case-{data['algorithm']}-n{data['max_vertices']}-d{data['max_degree']}-cost-per-m.png"
            target.write_bytes(read_regular(source, "--summarise"))
            copied.append(target)
    return copied


def summarise(dirs: list[Path], out: Path | None = None) -> str:
    """The report over every output directory in ``dirs``; with ``out``, also its plot, drawn there."""
    return summarise_runs(dirs, out)[0]


def summarise_runs(dirs: list[Path], out: Path | None = None) -> tuple[str, bool]:
    """:func:`summarise`, and whether every summarised exhaustive run stays within its exact bound (the
    directories are read and recomputed by :func:`~topomark.reference.worstcase.summary_input.load_runs`:
    bad input naming the file and field otherwise)."""
    exhaustive, searched = load_runs(dirs)
    found = _found_texts(searched)
    lines = ["# Worst cases: the thesis's open question, measured", "", f"> {QUESTION}", "",
             f"- **Thesis:** {THESIS}"]
    if exhaustive:
        lines.append("- **Proved here** (exhaustive): the largest cost of each algorithm over every world up to the "
                     "sizes below, exactly.")
    if searched:
        lines.append("- **Found here** (search): worlds at least this bad exist at larger sizes; the true worst case "
                     "may be worse.")
    lines.append("")
    if exhaustive:
        lines += _exhaustive_section(exhaustive)
    if searched:
        lines += _search_section(searched, found)
    lines += ["## What this says about §7.2, per algorithm", "", f"- **Thesis:** {THESIS}",
              *verdicts(exhaustive, searched, _names(searched, found)), ""]
    lines += ["## How this page was made", "", "`topomark worst-case --summarise` over the outputs (`-o DIR`) of:", "",
              "A search that goes on from another's world (`--restart-world`) comes after it; `→` names the kept "
              "world a search found.", "", *[f"- {c}" for c in commands(exhaustive, searched, found)], ""]
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        plots = (_plot(out, exhaustive, searched) or []) + _distributions(out, exhaustive)
        lines += [f"![{p.stem}]({p.name})" for p in plots]
    return "\n".join(lines) + "\n", not bound_broken(exhaustive)
