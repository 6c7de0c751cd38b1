"""Measured: the single movable marker (§2.3.1, Dudek et al. [26] and the directional variant [27]) beside the
single directional immovable marker (Algorithm 3.1, ``basic``) and its best enhancement (``enh3``, §4.1) on the
same worlds (§3.5.3 world families).

For each world family, size and seed, every algorithm maps the same world with the checker on; the table gives, per
algorithm and size, the median n, m, cost, cost/m and cost/(mn) over the seeds, and on how many worlds each
movable marker cost less than ``basic`` / ``enh3``, with the median cost ratio.  World families (:data:`FAMILIES`):
``lattice-hole`` (k × k lattice, 10% of vertices removed; sizes 4, 6, 8 ≈ n 16, 36, 64),
``lattice-hole-edges`` (10% of edges removed: n = 16, 36, 64 exactly),
``complete-hole`` (K_n, 10% of edges removed; n 8, 12, 16) and ``small-world`` (k = 4, p = 20%; n 16, 36,
64).  Run::

    python3 -m topomark.reference.bench.measure.movable                      # lattice-hole, seeds 0-4
    python3 -m topomark.reference.bench.measure.movable complete-hole 3      # seeds 0-2

Examples
--------
>>> rows = measure([3], seeds=[0], algorithms=("dudek", "basic"))
>>> sorted(rows[0])
['algorithm', 'cost', 'm', 'n', 'outcome', 'seed', 'size']
"""

from __future__ import annotations

import argparse
import statistics
import sys

from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import complete_hole, lattice_hole, small_world

__all__ = ["ALGORITHMS", "FAMILIES", "measure", "table"]

ALGORITHMS = ("dudek", "dudek-directional", "basic", "enh3")


FAMILIES = {
    "lattice-hole": ((4, 6, 8), lambda k, seed: lattice_hole(k, k, 0.1, "vertices", seed)),
    "lattice-hole-edges": ((4, 6, 8), lambda k, seed: lattice_hole(k, k, 0.1, "edges", seed)),
    "complete-hole": ((8, 12, 16), lambda n, seed: complete_hole(n, 0.1, seed)),
    "small-world": ((16, 36, 64), lambda n, seed: small_world(n, 4, 0.2, seed)),
}
"""world family ↦ (its sizes, world maker (size, seed) → World)."""


def measure(sizes, seeds, algorithms=ALGORITHMS, family: str = "lattice-hole") -> list[dict]:
    """One row per (size, seed, algorithm): the checked run's outcome and cost."""
    make = FAMILIES[family][1]
    rows = []
    for size in sizes:
        for seed in seeds:
            world = make(size, seed)
            for name in algorithms:
                out = explore(world, name, record=False)
                rows.append({"size": str(size), "seed": seed, "algorithm": name, "n": world.n, "m": world.m,
                             "cost": out.cost, "outcome": out.outcome})
    return rows


def table(rows: list[dict], algorithms=ALGORITHMS) -> str:
    """Medians per size and algorithm, and per-world wins of each movable marker over ``basic`` and ``enh3``."""
    lines = ["size   alg                 n    m   cost  cost/m  cost/(mn)  all correct"]
    by = {}
    for row in rows:
        by.setdefault((row["size"], row["algorithm"]), []).append(row)
    sizes = list(dict.fromkeys(row["size"] for row in rows))
    for size in sizes:
        for name in algorithms:
            runs = by[(size, name)]
            med = lambda key: statistics.median(key(x) for x in runs)  # noqa: E731
            lines.append(f"{size:6} {name:17} {med(lambda x: x['n']):4g} {med(lambda x: x['m']):4g} "
                         f"{med(lambda x: x['cost']):6g} {med(lambda x: x['cost'] / x['m']):7.2f} "
                         f"{med(lambda x: x['cost'] / (x['m'] * x['n'])):10.3f}  "
                         f"{all(x['outcome'] == 'correct' for x in runs)}")
        for mover in ("dudek", "dudek-directional"):
            for fixed in ("basic", "enh3"):
                pairs = list(zip(by[(size, mover)], by[(size, fixed)]))
                wins = [f["cost"] / m["cost"] for m, f in pairs if m["cost"] < f["cost"]]
                ratio = statistics.median(f["cost"] / m["cost"] for m, f in pairs)
                lines.append(f"       {mover} < {fixed}: {len(wins)}/{len(pairs)} worlds; median {fixed}/{mover} "
                             f"cost ratio {ratio:.2f}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m topomark.reference.bench.measure.movable",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("family", nargs="?", default="lattice-hole", choices=sorted(FAMILIES), metavar="FAMILY",
                    help=f"the world family: {', '.join(FAMILIES)} (default lattice-hole)")
    ap.add_argument("seeds", nargs="?", type=int, default=5, metavar="SEEDS",
                    help="worlds per size: seeds 0 to SEEDS-1 (default 5)")
    args = ap.parse_args(argv)
    family, seeds = args.family, range(args.seeds)
    print(f"{family}, seeds {seeds.start}-{seeds.stop - 1}")
    print(table(measure(FAMILIES[family][0], list(seeds), family=family)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
