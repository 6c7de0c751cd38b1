"""Cost against the lower bound m for §6.2's O(m) marker algorithms on the Chapter 4 worlds.

``python3 -m topomark.reference.bench.measure.markers_62 [--seeds K] [--family lattice-hole] [ALGORITHM ...]``
explores the bench's worlds (:func:`~topomark.reference.bench.plan.world_for`: the
same worlds and starts as ``topomark bench``) at every size of the world family, checked,
and prints per size the median and max of cost/m, the mean markers used against
Case 3b's Σ_{k=1}^{n−1} k, and the mean share of each purpose: ``new`` (the edges themselves, m in all), ``other`` (trips to drop
markers), ``travel`` (walking S between frontier edges), ``validation`` and
``retrace`` (back-link probes).  The thesis states O(m) only (§6.2.1 Case 3b,
§6.2.2, Table 6.2), so cost/m is what is compared; the target is < 3.

Examples
--------
>>> row = measure("case-3b", "lattice-hole", 72, 1)
>>> row["worlds"], row["max"] < 3
(1, True)
"""

from __future__ import annotations

import argparse
import statistics
import sys

from topomark.reference.bench.plan import FAMILIES, world_for
from topomark.reference.run.explore import explore

__all__ = ["measure", "main", "O_M_ALGORITHMS"]

O_M_ALGORITHMS = ("case-3b", "case-dv-sum")
PURPOSES = ("new", "other", "travel", "validation", "retrace")


def measure(algorithm: str, world_family: str, size: int, seeds: int) -> dict:
    """cost/m over seeds 0..seeds−1 of one size: median, max, the world of the max, mean purpose shares."""
    shares: dict[str, list[float]] = {p: [] for p in PURPOSES}
    ratios, worst, failures, saved = [], None, [], []
    for seed in range(seeds):
        world = world_for(world_family, size, seed)
        out = explore(world, algorithm, record=False)
        if out.outcome != "correct":
            failures.append((seed, out.outcome, out.reason or str(out.violation)))
            continue
        ratio = out.cost / out.m
        if worst is None or ratio > worst[0]:
            worst = (ratio, seed, out.n, out.m, dict(out.by_purpose))
        ratios.append(ratio)
        saved.append(out.explorer.dropped / (out.n * (out.n - 1) // 2))  # markers against Case 3b's Σ_{k=1}^{n−1} k
        for p in PURPOSES:
            shares[p].append(out.by_purpose.get(p, 0) / out.m)
    return {"algorithm": algorithm, "family": world_family, "size": size, "worlds": len(ratios),
            "median": statistics.median(ratios) if ratios else None, "max": max(ratios) if ratios else None,
            "worst": worst, "shares": {p: statistics.mean(v) if v else 0.0 for p, v in shares.items()},
            "failures": failures, "markers": statistics.mean(saved) if saved else None}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m topomark.reference.bench.measure.markers_62",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("algorithms", nargs="*", default=list(O_M_ALGORITHMS), metavar="ALGORITHM",
                        help=f"the algorithms to measure (default: {', '.join(O_M_ALGORITHMS)})")
    parser.add_argument("--seeds", type=int, default=5, help="worlds per size (default 5)")
    parser.add_argument("--family", default="lattice-hole", choices=sorted(FAMILIES), metavar="WORLD_FAMILY",
                        help="the bench's world family (default lattice-hole)")
    parser.add_argument("--sizes", type=int, nargs="*", metavar="SIZE",
                        help="only these sizes (default: the family's sizes)")
    args = parser.parse_args(argv)
    print("algorithm     size  worlds  cost/m median  max    | per m: new  other  travel  valid  retrace | "
          "markers/Σ^{n−1} | worst")
    bad = 0
    for alg in args.algorithms:
        for size in args.sizes or FAMILIES[args.family].sizes:
            r = measure(alg, args.family, size, args.seeds)
            s = r["shares"]
            worst = r["worst"]
            print(f"{alg:12s} {size:5d} {r['worlds']:6d}  {r['median']:12.3f} {r['max']:6.3f} |      "
                  f"{s['new']:.2f}  {s['other']:.2f}   {s['travel']:.2f}    {s['validation']:.2f}  "
                  f"{s['retrace']:.2f}    | {r['markers']:.3f}          | seed {worst[1]} n={worst[2]} m={worst[3]} "
                  f"{worst[4]}")
            for failure in r["failures"]:
                bad += 1
                print(f"  NOT CORRECT: seed {failure[0]}: {failure[1]} {failure[2]}")
            sys.stdout.flush()
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
