"""Benchmark: checked vs unchecked explorations of lattice-hole worlds (the targets: a checked run within a small factor of an unchecked one).

Run ``python -m topomark.reference.bench.measure.checked_cost [--seeds 5] [--repeats 3] [--json]``.
Worlds: 10x10, 17x17 and 20x20 grids with 10% of vertices removed (about 90,
260 and 360 vertices, the thesis's lattice-hole sizes, §3.5.3).  For each size
it reports the median wall time of a fully checked run (incremental and full
check modes) and of an unchecked run, traversals per second, and the ratio of
checked to unchecked time.  Medians over seeds × repeats; machines here are
shared, so read ratios rather than absolute numbers.
"""

from __future__ import annotations

import argparse
import json
import statistics
import time

from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import lattice_hole

SIZES = ((10, 10), (17, 17), (20, 20))


def _time(world, **kw) -> tuple[float, int]:
    t = time.perf_counter()
    out = explore(world, record=False, **kw)
    if kw.get("check", True) and not out.verified:
        raise SystemExit(f"benchmark run not verified: {out.violation}")
    return time.perf_counter() - t, out.cost


def run(seeds: int, repeats: int) -> list[dict]:
    rows = []
    for rows_, cols in SIZES:
        samples: dict[str, list[float]] = {"unchecked": [], "incremental": [], "full": []}
        costs, ns = [], []
        for seed in range(seeds):
            world = lattice_hole(rows_, cols, 0.1, "vertices", seed)
            ns.append(world.n)
            for _ in range(repeats):
                dt, cost = _time(world, check=False)
                samples["unchecked"].append(dt)
                samples["incremental"].append(_time(world, check_mode="incremental")[0])
                samples["full"].append(_time(world, check_mode="full")[0])
            costs.append(cost)
        med = {k: statistics.median(v) for k, v in samples.items()}
        rows.append({
            "grid": f"{rows_}x{cols}", "n": statistics.median(ns), "median_cost": statistics.median(costs),
            "unchecked_s": round(med["unchecked"], 3), "checked_s": round(med["incremental"], 3),
            "checked_full_s": round(med["full"], 3),
            "ratio_checked": round(med["incremental"] / med["unchecked"], 2),
            "ratio_full": round(med["full"] / med["unchecked"], 2),
            "traversals_per_s_checked": int(statistics.median(costs) / med["incremental"]),
            "traversals_per_s_unchecked": int(statistics.median(costs) / med["unchecked"]),
        })
    return rows


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(prog="python -m topomark.reference.bench.measure.checked_cost",
                                 description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=5, help="worlds per size (default 5)")
    ap.add_argument("--repeats", type=int, default=3, help="timed runs per world; the median is kept (default 3)")
    ap.add_argument("--json", action="store_true", help="print the rows as one JSON list")
    args = ap.parse_args(argv)
    rows = run(args.seeds, args.repeats)
    if args.json:
        print(json.dumps(rows, indent=1))
        return
    keys = list(rows[0])
    print(" | ".join(keys))
    for r in rows:
        print(" | ".join(str(r[k]) for k in keys))


if __name__ == "__main__":
    main()
