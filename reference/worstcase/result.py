"""What a worst-case search reports: per size the maxima, their worlds and the cost/m distribution (thesis §7.2).

:func:`rows` turns the merged tallies of a search
(:mod:`~topomark.reference.worstcase.resumable`) into the rows of
``topomark worst-case --json``'s ``per_n``; :func:`argmax_world` rebuilds the
world and start of a witness as a ``topomark/world@1`` object;
:func:`write_outputs` writes them as world files beside the JSON.

Examples
--------
>>> argmax_world(3, 2, (0, 0, "v1", 0))["start"]
{'at': 'v1', 'facing': 'v0'}
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from topomark.proofs.census_map import world_at
from topomark.spec.world import Start, World
from topomark.spec.worldfile import world_to_json

from topomark.reference.algorithms.registry import AlgorithmSpec
from topomark.reference.worstcase.tally import SizeTally, Witness

__all__ = ["QUANTILES", "argmax_world", "histogram", "rows", "write_outputs"]

QUANTILES = (0.0, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0)


def started_world(n: int, max_degree: int, witness: Witness) -> World:
    """The world of ``witness``, started where its run started."""
    gi, rank, v, i = witness
    world = world_at(n, max_degree, gi, rank)
    return world.with_start(Start(v, world.neighbour(v, i)))


def argmax_world(n: int, max_degree: int, witness: Witness) -> dict[str, Any]:
    """The world and start of ``witness`` as a world file's object."""
    return world_to_json(started_world(n, max_degree, witness))


def histogram(tally: SizeTally, width: float = 0.5) -> list[list[float]]:
    """``[low, high, runs]`` bins of cost/m of width ``width``, from 0 to the largest value."""
    bins: dict[int, int] = {}
    for (m, cost), k in tally.pairs.items():
        b = int(cost / m / width)
        bins[b] = bins.get(b, 0) + k
    return [[round(b * width, 3), round((b + 1) * width, 3), bins.get(b, 0)] for b in range(max(bins, default=-1) + 1)]


def _where(witness: Witness | None) -> dict[str, Any] | None:
    return None if witness is None else {"graph": witness[0], "rotation": witness[1], "start": witness[2],
                                         "exit": witness[3]}


def row(tally: SizeTally, max_degree: int, spec: AlgorithmSpec) -> dict[str, Any]:
    """One size's row: the issue's fields, the exact fractions, the witnesses and the distribution."""
    cost_m, ratio = tally.cost_m, tally.ratio
    out: dict[str, Any] = {
        "n": tally.n, "worlds": tally.worlds, "runs": tally.runs, "outcomes": dict(sorted(tally.outcomes.items())),
        "max_cost": tally.max_cost,
        "max_cost_per_m": None if cost_m is None else round(cost_m[0] / cost_m[1], 3),
        "max_ratio_to_bound": None if ratio is None else round(ratio[0] / ratio[1], 4),
        "cost_per_m_exact": cost_m, "ratio_exact": ratio,
        "argmax": None,
        "argmax_at": _where(tally.argmax_cost), "argmax_cost_per_m_at": _where(tally.argmax_cost_m),
        "argmax_ratio_at": _where(tally.argmax_ratio),
        "quantiles_cost_per_m": dict(zip((str(q) for q in QUANTILES), tally.quantiles(QUANTILES))) if tally.pairs
        else {},
        "histogram_cost_per_m": histogram(tally),
    }
    if tally.argmax_cost is not None:
        world = started_world(tally.n, max_degree, tally.argmax_cost)
        out.update(argmax=world_to_json(world), argmax_m=world.m, bound_at_argmax=spec.bound_for(tally.n, world.m))
    return out


def rows(tallies: dict[int, SizeTally], max_degree: int, spec: AlgorithmSpec) -> list[dict[str, Any]]:
    return [row(t, max_degree, spec) for t in tallies.values()]


def write_outputs(out: Path, data: dict[str, Any], max_degree: int, tallies: dict[int, SizeTally]) -> list[Path]:
    """``worst-case.json`` and, per n, the argmax worlds as world files: ``argmax-cost-nN.json``,
    ``argmax-cost-per-m-nN.json`` and ``argmax-ratio-nN.json``."""
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for n, tally in tallies.items():
        for kind, witness in (("cost", tally.argmax_cost), ("cost-per-m", tally.argmax_cost_m),
                              ("ratio", tally.argmax_ratio)):
            if witness is None:
                continue
            path = out / f"argmax-{kind}-n{n}.json"
            path.write_text(json.dumps(argmax_world(n, max_degree, witness), indent=1) + "\n", encoding="utf-8")
            written.append(path)
    path = out / "worst-case.json"
    path.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    return [path, *written]
