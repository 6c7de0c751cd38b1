"""A measured slice of the census at n = 8 (or 9), max degree 4, on a local Dask cluster (§3.7's census).

Speed is measured here and reported in docs/census.md ("Results past n = 7"), never asserted by a test.

Plans the n = 8 map tasks (``--vertices 9``: n = 9) exactly as ``topomark census`` does (census_map.plan,
task_worlds=2000, min_vertices=n, default shard count for the whole n <= N plan, at most 4,096), picks K tasks at random (seeded: a
uniform sample of tasks ~ a uniform sample of worlds), runs them with census_map.run_map on a
distributed.LocalCluster of 2 single-thread workers, then reduces every shard of the slice with
census_run.reduce_shard; each worker's start-up (the graph list, numba's kernel) is
timed first and apart; per task it records CPU seconds, wall, worlds, placements, records and the
worker's peak RSS, as JSON lines on standard output.

Example (the figures of docs/census.md)::

    python -m topomark.proofs.bench_census directional-vertex 4 14 /tmp/slice-dv --engine reference
    python -m topomark.proofs.bench_census directional-vertex 4 14 /tmp/slice-dv-c --engine compiled
    python -m topomark.proofs.bench_census directional-vertex 4 14 /tmp/slice-dv9 --vertices 9
"""
import argparse
import json
import os
import random
import resource
import sys
import time
from pathlib import Path

from topomark.proofs.census_compiled import resolve_engine, warm_up
from topomark.proofs.census_map import plan, run_map
from topomark.proofs.census_run import default_shards, reduce_shard
from topomark.proofs.census_shards import RECORD, map_path
from topomark.proofs.world_batches import graphs_of

__all__ = ["start_up", "timed_map", "timed_reduce", "main"]


def start_up(n, engine):
    """A worker's start-up, timed apart from its tasks: the graph list of size n (and numba's kernel)."""
    c0 = time.process_time()
    graphs_of(n, 4)
    if engine == "compiled":
        warm_up()
    return time.process_time() - c0


def timed_map(root, t, cls, units, shards, engine="reference"):
    """census_map.run_map of one task, with its CPU time, wall time, sizes and the worker's peak RSS."""
    c0, w0 = time.process_time(), time.perf_counter()
    res = run_map(root, t, cls, 4, units, shards, engine=engine)
    recs = os.path.getsize(map_path(Path(root), t)) // RECORD.itemsize
    return {"task": t, "cpu": time.process_time() - c0, "wall": time.perf_counter() - w0,
            "worlds": sum(w for w, _ in res["sizes"].values()),
            "placements": sum(p for _, p in res["sizes"].values()), "records": recs,
            "rss_gb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6, "offsets": res["offsets"]}


def timed_reduce(root, s, slices, n=8):
    """census_run.reduce_shard of one shard of the slice (worlds of size n), with its CPU time."""
    c0 = time.process_time()
    res = reduce_shard(root, s, slices, n, n, False)
    return {"shard": s, "cpu": time.process_time() - c0, "ambiguous": res["ambiguous_upto"][-1],
            "rss_gb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6}


def main(argv: list[str] | None = None) -> int:
    """Plan, sample K map tasks (seeded), map them and reduce every shard on a 2-worker local Dask cluster."""
    ap = argparse.ArgumentParser(prog="python -m topomark.proofs.bench_census", description=__doc__.split("\n\n")[0])
    ap.add_argument("cls", metavar="CLASS", help="the marker class, e.g. directional-vertex")
    ap.add_argument("k", metavar="K", type=int, help="how many map tasks of size n to sample")
    ap.add_argument("seed", metavar="SEED", type=int, help="seed of the sample")
    ap.add_argument("root", metavar="DIR", help="where the slice's shard files are written")
    ap.add_argument("--engine", default="auto", help="reference, compiled or auto (census_compiled.resolve_engine)")
    ap.add_argument("--vertices", metavar="N", type=int, choices=(8, 9), default=8,
                    help="the world size of the sampled tasks: 8 (default) or 9")
    args = ap.parse_args(argv)
    cls, k, seed, root, n = args.cls, args.k, args.seed, args.root, args.vertices
    engine = resolve_engine(args.engine, cls, lambda line: print(line, file=sys.stderr))
    os.makedirs(root, exist_ok=True)
    t0 = time.perf_counter()
    tasks = plan(n, 4, n, 2000)
    shards = default_shards(sum(e for t in plan(n, 4, 2, 2000) for _, e in t))
    pick = sorted(random.Random(seed).sample(range(len(tasks)), k))
    print(json.dumps({"class": cls, "engine": engine, "n": n, "tasks_n": len(tasks), "shards": shards, "picked": pick,
                      "est_worlds_n": sum(e for t in tasks for _, e in t),
                      "plan_s": round(time.perf_counter() - t0, 1)}), flush=True)
    import distributed
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        startup = client.run(start_up, n, engine)
        print(json.dumps({"start_up_cpu": sorted(round(c, 2) for c in startup.values())}), flush=True)
        futs = [client.submit(timed_map, root, i, cls, [tuple(u) for u, _ in tasks[t]], shards, engine, pure=False)
                for i, t in enumerate(pick)]
        done = [f.result() for f in futs]
        for d, t in zip(done, pick):
            print(json.dumps({"map": {**{k_: v for k_, v in d.items() if k_ != "offsets"}, "plan_task": t}}), flush=True)
        rfuts = [client.submit(timed_reduce, root, s,
                               [(i, d["offsets"][s], d["offsets"][s + 1] - d["offsets"][s]) for i, d in enumerate(done)],
                               n, pure=False) for s in range(shards)]
        red = [f.result() for f in rfuts]
    print(json.dumps({"reduce": {"shards": shards, "cpu": round(sum(r["cpu"] for r in red), 2),
                                 "ambiguous": sum(r["ambiguous"] for r in red),
                                 "max_rss_gb": max(r["rss_gb"] for r in red)},
                      "wall_total_s": round(time.perf_counter() - t0, 1)}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
