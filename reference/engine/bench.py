"""Runs per second of the reference and of the compiled engine on the exhaustive set (thesis §7.2).

``python -m topomark.reference.engine.bench --max-vertices 7 --max-degree 3
[--algorithm A] [--lighthouse L] [--reference-every K] [--json]`` enumerates every world with n = N vertices
and degrees ≤ D and every start orbit (as ``topomark worst-case`` does; the
enumeration is not timed), then times

* the reference's unchecked runs of the algorithm (``--algorithm``: ``basic``,
  or a footprint search of §6.2.1 the engine runs; as
  :func:`~topomark.reference.worstcase.exhaustive.run_start` runs them)
  on every K-th start (K = 1: all; a fixed sample when the reference is too
  slow to run them all);
* the engine's runs of every start, world by world as the exhaustive search
  makes them (:func:`~topomark.reference.engine.runs.run_starts`, the
  conversion to arrays included), after one warm-up call;
* the engine's first call in a fresh process, with an empty numba cache
  (compilation) and with the cache this installation keeps (loading it): both
  apart from the runs.

Both CPU time (this process's) and wall time are reported, each the least of
``--repeat`` timings: on a shared machine the CPU time is the fairer figure.  The engine's costs are checked to
equal the reference's on the sampled starts.  Nothing is asserted about speed.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from typing import Any

from topomark.proofs.census_map import plan, unit_worlds
from topomark.proofs.start_orbits import start_darts
from topomark.proofs.world_arrays import to_arrays
from topomark.spec.world import Start

from topomark.reference.engine import ENGINE_LIGHTHOUSES, FOOTPRINT_CASES
from topomark.reference.engine.equality import ALGORITHMS
from topomark.reference.engine.runs import run_starts
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.run.explore import explore

__all__ = ["bench", "first_call", "main"]

_FIRST_CALL = ("import time; t = time.perf_counter()\n"
               "from topomark.reference.engine.runs import run_starts\n"
               "from topomark.proofs.world_arrays import to_arrays\n"
               "from topomark.reference.worlds.generators import cycle\n"
               "run_starts(to_arrays(cycle(3)), [(0, 0)], ('nearest', 'fifo', 'shortest'))\n"
               "print(time.perf_counter() - t)\n")


def first_call(cold: bool) -> float:
    """Seconds from import to the end of the engine's first run in a fresh process: with an empty numba cache
    (``cold``: compilation) or with this installation's."""
    env = dict(os.environ)
    with tempfile.TemporaryDirectory() as cache:
        if cold:
            env["NUMBA_CACHE_DIR"] = cache
        out = subprocess.run([sys.executable, "-c", _FIRST_CALL], capture_output=True, text=True, env=env, check=True)
    return float(out.stdout.split()[-1])


def _worlds(n: int, max_degree: int) -> list[tuple[Any, list[tuple[str, int]]]]:
    return [(world, start_darts(world, autos)) for task in plan(n, max_degree, n) for unit, _ in task
            for _, world, autos in unit_worlds(unit, max_degree)]


def _timed(fn) -> tuple[Any, float, float]:
    c, w = time.process_time(), time.perf_counter()
    out = fn()
    return out, time.process_time() - c, time.perf_counter() - w


def _best(fn, repeat: int) -> tuple[Any, float, float]:
    """``fn``'s result and its least CPU and wall time over ``repeat`` runs (the least disturbed by other work)."""
    runs = [_timed(fn) for _ in range(repeat)]
    return runs[0][0], min(r[1] for r in runs), min(r[2] for r in runs)


def bench(n: int, max_degree: int, every: int = 1, policies: tuple[str, str, str] = ("nearest", "fifo", "shortest"),
          repeat: int = 1, algorithm: str = "basic", lighthouse: str | None = None) -> dict[str, Any]:
    """The figures of one benchmark (module docstring) of ``algorithm`` with ``lighthouse`` (None: its default),
    from the starts the lighthouse can start from."""
    least = 0 if algorithm in FOOTPRINT_CASES else LIGHTHOUSES[lighthouse or "directional-vertex"].min_degree
    worlds = [(w, [d for d in ds if w.degree(d[0]) >= least]) for w, ds in _worlds(n, max_degree)]
    starts = sum(len(d) for _, d in worlds)
    sample = [(w, d) for k, (w, d) in enumerate((w, d) for w, ds in worlds for d in ds) if k % every == 0]

    def reference() -> list[int]:
        from topomark.reference.explorers.policies import Policies
        return [explore(w.with_start(Start(d[0], w.neighbour(*d))), algorithm, Policies(*policies), check=False,
                        record=False, lighthouse=lighthouse).cost for w, d in sample]

    def engine() -> list[int]:
        costs = []
        for world, darts in worlds:
            number = {v: k for k, v in enumerate(world.vertices)}
            costs += [r.cost for r in run_starts(to_arrays(world), [(number[v], i) for v, i in darts], policies,
                                                 lighthouse, algorithm)]
        return costs

    run_starts(to_arrays(worlds[0][0]), [(0, 0)], policies, lighthouse, algorithm)  # warm: load the compiled code
    ref_costs, ref_cpu, ref_wall = _best(reference, repeat)
    eng_costs, eng_cpu, eng_wall = _best(engine, repeat)
    agree = ref_costs == [eng_costs[k] for k in range(0, starts, every)]
    ref_rate, eng_rate = len(sample) / ref_cpu, starts / eng_cpu
    return {"algorithm": algorithm, "lighthouse": lighthouse or "directional-vertex", "n": n,
            "max_degree": max_degree, "worlds": len(worlds), "starts": starts, "reference_runs": len(sample),
            "reference_cpu_s": round(ref_cpu, 3), "reference_wall_s": round(ref_wall, 3),
            "reference_runs_per_cpu_s": round(ref_rate, 1), "engine_runs": starts, "engine_cpu_s": round(eng_cpu, 3),
            "engine_wall_s": round(eng_wall, 3), "engine_runs_per_cpu_s": round(eng_rate, 1),
            "speedup_cpu": round(eng_rate / ref_rate, 1), "costs_agree": agree}


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m topomark.reference.engine.bench", description=__doc__.split("\n")[0])
    p.add_argument("--algorithm", choices=ALGORITHMS, default="basic", help="what to run (default basic)")
    p.add_argument("--lighthouse", choices=ENGINE_LIGHTHOUSES, default=None)
    p.add_argument("--max-vertices", type=int, default=7)
    p.add_argument("--max-degree", type=int, default=3)
    p.add_argument("--reference-every", type=int, default=1, help="time the reference on every K-th start")
    p.add_argument("--repeat", type=int, default=3, help="time each side this many times, keep the least")
    p.add_argument("--no-compile", action="store_true", help="skip timing the first call in fresh processes")
    p.add_argument("--json", action="store_true")
    args = p.parse_args(argv)
    if not 2 <= args.max_vertices <= 8 or args.max_degree < 2 or args.reference_every < 1 or args.repeat < 1:
        print("error: --max-vertices 2..8, --max-degree >= 2, --reference-every >= 1, --repeat >= 1", file=sys.stderr)
        return 2
    report = bench(args.max_vertices, args.max_degree, args.reference_every, repeat=args.repeat,
                   algorithm=args.algorithm, lighthouse=args.lighthouse)
    if not args.no_compile:
        report.update(compile_s=round(first_call(True), 2), cache_load_s=round(first_call(False), 2))
    print(json.dumps(report, sort_keys=True) if args.json else "\n".join(f"{k}: {v}" for k, v in report.items()))
    return 0 if report["costs_agree"] else 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
